//! Snap rounding: two operands' rings noded on a grid, so that their edges meet only at shared
//! vertices.
//!
//! J. D. Hobby, *Practical segment intersection with finite precision output*, Computational
//! Geometry: Theory and Applications 13(4):199-214, 1999 (GEOS OverlayNG's `SnapRoundingNoder`
//! and `HotPixel` are built the same way). The plane is tiled by pixels of side `s`, a power of
//! two; the pixel of centre `c` is the half-open square `[c.x - s/2, c.x + s/2) × [c.y - s/2,
//! c.y + s/2)`. A pixel is hot when it holds an input vertex or the exact crossing point of two
//! input edges. Every edge is then replaced by the path through the centres of the hot pixels it
//! meets, in order along it. Hobby's theorem: no two of the resulting edges cross, and (since a
//! pixel between two hot pixels along an output edge is met by the input edge too) no output
//! vertex lies inside an output edge: output edges meet only at shared end points, or coincide.
//! Every output vertex is the centre of a pixel its input edge meets, so it lies within `s·√2/2`
//! of that edge (and of its input vertex, for a vertex's own pixel).
//!
//! Every decision is exact: whether an edge meets a pixel (the box test and the orientation of
//! the pixel's corners against the edge, with the open sides moved in by a symbolic ε), which
//! pixel holds a crossing ([`predicates::crossing_coordinate_cmp`], after a filtered estimate),
//! and the order of the pixels along an edge (by column in the edge's x direction, then row in
//! its y direction: no float projection, which would tie on nearly vertical edges). Grid points
//! are multiples of `s`, exact in f64 within 2^51 pixels of the origin (farther coordinates
//! are refused).
//!
//! Limits. The topology can change by up to a pixel: features narrower than a pixel collapse
//! (rings can become spikes or touch themselves; rings left with fewer than three distinct points
//! or all on one line are dropped), and a vertex can end up within `s·√2/2` of an edge it was not
//! near. The pairs of edges within a pixel of each other come from [`NearEdges`] (then their
//! crossings, and each edge's hot pixels tested against the other): near linear when edges are
//! short beside the extent, quadratic when many long edges lie close to each other (bundles of
//! nearly coincident edges) or share the index's cells (stars). That is acceptable for a fallback
//! run only where rounding could not be proven harmless, which is what it is for.

use crate::double_double::DoubleDouble;
use crate::near_edges::{NearEdges, shared_end};
#[cfg(test)]
use crate::near_edges::{apart, near_pairs};
use crate::predicates::{self, Orientation, accurate_crossing_offset, crossing_coordinate_cmp, orient};
use crate::{ClipError, Point, Polygons, Ring, Segment, SegmentIntersection};

/// A pixel, as its column and row: its centre is `(column·s, row·s)`.
type Pixel = (i64, i64);

/// Both operands' rings snap rounded to pixels of side `pixel` (a power of two): the subject's
/// rings, then the clip's, each without the rings the rounding leaves with fewer than three
/// distinct points or all on one line. Edges of the result (of both operands together) meet only
/// at shared end points or coincide; every vertex is a multiple of `pixel`, within `pixel·√2/2`
/// of the input edge it comes from. Refuses what [`NearEdges::of`] refuses.
pub fn snap_round(subject: &Polygons, clip: &Polygons, pixel: f64) -> Result<(Polygons, Polygons), ClipError> {
    Ok(snap_round_near(&NearEdges::of(subject, clip, pixel)?))
}

/// [`snap_round`] of the operands `near` was made of, on its pixel, from its near pairs.
pub fn snap_round_near(near: &NearEdges) -> (Polygons, Polygons) {
    // Grid points times the pixel are exact again.
    let rings: Vec<&Ring> = near.rings.iter().collect();
    near.in_world(snap_rings_of(&rings, &near.segments, &near.pairs, 1.0))
}

/// The snap-rounded points of each ring (finite, on the grid's range), `None` for a ring left
/// with fewer than three distinct points or all on one line.
#[cfg(test)]
fn snap_rings(rings: &[&Ring], s: f64) -> Vec<Option<Vec<Point>>> {
    let segments: Vec<Segment> = rings.iter().flat_map(|r| r.edges()).collect();
    snap_rings_of(rings, &segments, &near_pairs(rings.iter().map(|r| r.len()), &segments, s), s)
}

/// [`snap_rings`] of `rings`, whose edges are `segments` with the near `pairs` among them.
fn snap_rings_of(rings: &[&Ring], segments: &[Segment], pairs: &[(u32, u32)], s: f64) -> Vec<Option<Vec<Point>>> {
    let met = met_pixels(segments, pairs, s);
    let mut pixels = Vec::new();
    let mut next = 0;
    rings
        .iter()
        .map(|ring| {
            let mut out: Vec<Point> = Vec::with_capacity(ring.len());
            for (k, segment) in segments[next..next + ring.len()].iter().enumerate() {
                pixels.clear();
                pixels.extend_from_slice(met.of(next + k));
                order_along(&mut pixels, *segment);
                for &p in &pixels {
                    let c = centre(p, s);
                    if out.last() != Some(&c) {
                        out.push(c);
                    }
                }
            }
            next += ring.len();
            while out.len() > 1 && out.first() == out.last() {
                out.pop();
            }
            has_area(&out).then_some(out)
        })
        .collect()
}

/// Pixels per segment, in one buffer: segment `i`'s are `pixels[starts[i]..starts[i + 1]]`.
struct PixelLists {
    starts: Vec<usize>,
    pixels: Vec<Pixel>,
}

impl PixelLists {
    /// The lists of `(segment, pixel)` entries over `n` segments, by a counting sort.
    fn of_entries(n: usize, entries: &[(u32, Pixel)]) -> PixelLists {
        let mut starts = vec![0usize; n + 1];
        for &(i, _) in entries {
            starts[i as usize + 1] += 1;
        }
        for i in 0..n {
            starts[i + 1] += starts[i];
        }
        let mut fill = starts.clone();
        let mut pixels = vec![(0, 0); entries.len()];
        for &(i, p) in entries {
            pixels[fill[i as usize]] = p;
            fill[i as usize] += 1;
        }
        PixelLists { starts, pixels }
    }

    fn of(&self, i: usize) -> &[Pixel] {
        &self.pixels[self.starts[i]..self.starts[i + 1]]
    }
}

/// The hot pixels each segment meets. A pixel is hot when it holds an input vertex or the exact
/// crossing of two segments; each segment meets its own (its ends' and its crossings' pixels),
/// and another segment's where it passes through them. A segment meets another's hot pixel only
/// where the two come within a pixel of each other, so both are found from one pass over the
/// near `pairs` ([`near_pairs`]): first the crossings, then each segment's pixels tested against
/// the other's.
fn met_pixels(segments: &[Segment], pairs: &[(u32, u32)], s: f64) -> PixelLists {
    let mut own: Vec<(u32, Pixel)> = Vec::with_capacity(2 * segments.len());
    for (i, e) in segments.iter().enumerate() {
        own.extend([(i as u32, pixel_of(e.a, s)), (i as u32, pixel_of(e.b, s))]);
    }
    // A segment with both ends in one pixel lies in it (pixels are convex): so do its crossings,
    // and that pixel is hot already.
    let in_one_pixel: Vec<bool> = own.chunks_exact(2).map(|ends| ends[0].1 == ends[1].1).collect();
    let inside_one_pixel = |i: u32| in_one_pixel[i as usize];
    for &(i, j) in pairs {
        let (e, f) = (segments[i as usize], segments[j as usize]);
        // Touching points and overlaps end at input vertices, whose pixels are hot already; two
        // segments with an end in common (most close pairs: a ring's consecutive edges) cannot
        // cross.
        if shared_end(e, f).is_some() || inside_one_pixel(i) || inside_one_pixel(j) {
            continue;
        }
        if let SegmentIntersection::Crossing(_) = predicates::segment_intersection(e, f) {
            let p = crossing_pixel(e, f, s);
            own.extend([(i, p), (j, p)]);
        }
    }
    let own = PixelLists::of_entries(segments.len(), &own);
    let mut met: Vec<(u32, Pixel)> = Vec::with_capacity(2 * own.pixels.len());
    for i in 0..segments.len() {
        met.extend(own.of(i).iter().map(|&p| (i as u32, p)));
    }
    for &(i, j) in pairs {
        // The pixel of an end both share (a ring's consecutive edges) is on both own lists.
        let (e, f) = (segments[i as usize], segments[j as usize]);
        let shared = match shared_end(e, f) {
            Some(v) => pixel_of(v, s),
            None => (i64::MIN, i64::MIN),
        };
        for (a, b) in [(i, j), (j, i)] {
            let e = segments[a as usize];
            // Each own list starts with its segment's ends' pixels (the counting sort is stable).
            let (ends, crossings) = own.of(b as usize).split_at(2);
            // An end's pixel on `a`'s own list is there already: where many segments share a few
            // pixels (a cluster a pixel wide), the list stays as long as their pixels, not pairs.
            let a_ends = &own.of(a as usize)[..2];
            for &p in ends {
                if p != shared && !a_ends.contains(&p) && meets_pixel(e, p, s) {
                    met.push((a, p));
                }
            }
            for &p in crossings {
                if meets_pixel(e, p, s) {
                    met.push((a, p));
                }
            }
        }
    }
    PixelLists::of_entries(segments.len(), &met)
}

/// The pixel holding `p`: half-open, so a point on a border belongs to the pixel above or right.
/// Exact: `p / s` is exact (a power of two), and adding a half is exact below 2^52.
fn pixel_of(p: Point, s: f64) -> Pixel {
    // The floor by truncation (exact below 2^63; coordinates here are within 2^51 pixels):
    // `f64::floor` is a library call on targets without SSE4.1.
    let floor = |v: f64| {
        let t = v as i64;
        t - i64::from((t as f64) > v)
    };
    (floor(p.x / s + 0.5), floor(p.y / s + 0.5))
}

fn centre(p: Pixel, s: f64) -> Point {
    Point::new(p.0 as f64 * s, p.1 as f64 * s)
}

/// The pixel holding the exact crossing point of `e` and `f` (whose interiors cross): the pixel
/// of an estimate, moved a pixel at a time while the exact crossing lies beyond one of its
/// borders. Where the crossing's quotients are exact in f64 (grids), each border is decided by
/// one division ([`predicates::quotient_cmp`]); else borders farther from the estimate than its
/// error bound are decided by the estimate, those within it by one in double-double (made once,
/// for the first such border: within about 2^-90 of the offset's size), and the rest exactly.
fn crossing_pixel(e: Segment, f: Segment, s: f64) -> Pixel {
    // An estimate errs by ulps of the extent of the segment it runs along: the shorter one
    // leaves the fewest borders to the exact test.
    let extent = |g: Segment| (g.b.x - g.a.x).abs().max((g.b.y - g.a.y).abs());
    let (e, f) = if extent(f) < extent(e) { (f, e) } else { (e, f) };
    let quotients = predicates::exact_crossing_quotients(e, f);
    // The estimate as an offset from `e.a`: its error scales with the segment's extent, not the
    // coordinates' magnitude, so far from the origin the filter below still decides (with the
    // point's ulp in the bound, a pixel of 4 ulps left nearly every border to the expansions).
    let offset = match quotients {
        Some((nx, ny, d)) => (nx / d, ny / d),
        None => accurate_crossing_offset(e, f),
    };
    // The double-double estimate, made for the first border the f64 one cannot decide.
    let mut finer = None;
    let mut pixel = pixel_of(Point::new(e.a.x + offset.0, e.a.y + offset.1), s);
    for along_y in [false, true] {
        let (off, span, base) =
            if along_y { (offset.1, e.b.y - e.a.y, e.a.y) } else { (offset.0, e.b.x - e.a.x, e.a.x) };
        let mut below = |m: f64| {
            if let Some((nx, ny, d)) = quotients
                && let Some(order) = predicates::quotient_cmp(if along_y { ny } else { nx }, d, base, m)
            {
                return order.is_lt();
            }
            // `m - base` is rounded by at most half an ulp of itself; the offset errs by at
            // most about 8 ulps of the span (twice that allowed).
            let w = m - base;
            let error = 16.0 * f64::EPSILON * span.abs() + f64::EPSILON * w.abs() + f64::MIN_POSITIVE;
            if off - w > error {
                return false;
            }
            if w - off > error {
                return true;
            }
            let finer = finer.get_or_insert_with(|| predicates::double_double_crossing_offset(e, f));
            finer
                .and_then(|(o, relative)| below_by_estimate(o[usize::from(along_y)], relative, base, m))
                .unwrap_or_else(|| crossing_coordinate_cmp(e, f, along_y, m).is_lt())
        };
        let k = if along_y { &mut pixel.1 } else { &mut pixel.0 };
        // The exact crossing lies in the segment's box, within 2^51 pixels: this ends.
        loop {
            if below((*k as f64 - 0.5) * s) {
                *k -= 1;
            } else if !below((*k as f64 + 0.5) * s) {
                *k += 1;
            } else {
                break;
            }
        }
    }
    pixel
}

/// Whether the exact crossing's coordinate `base + offset` lies below `m`, decided by an estimate
/// `o` of the offset within `relative` of its size; `None` where it lies too near to tell. The
/// estimate less `w = m - base` (exact as a double-double) is off by the estimate's error and
/// the difference's rounding (a few units of 2^-104 of its operands); beyond twice that, its
/// leading part has the exact difference's sign.
fn below_by_estimate(o: DoubleDouble, relative: f64, base: f64, m: f64) -> Option<bool> {
    let w = DoubleDouble::difference(m, base);
    let d = o.sub(w);
    let error = relative * o.hi.abs() + 2f64.powi(-100) * (o.hi.abs() + w.hi.abs()) + f64::MIN_POSITIVE;
    if d.hi > 2.0 * error {
        Some(false)
    } else if d.hi < -2.0 * error {
        Some(true)
    } else {
        None
    }
}

/// Whether the closed segment `e` meets the half-open pixel `p`, exactly: their boxes meet (the
/// open sides strictly), and the pixel's corners are not all on one side of `e`'s line. The
/// corners on the open sides are moved in by infinitesimals (x's far larger than y's), so a
/// line through such a corner is judged by the side the corner moves to. The side is linear
/// over the (shrunk) square, so its two corners farthest either way along the line's normal
/// decide: the other two lie between them.
#[inline(always)]
fn meets_pixel(e: Segment, p: Pixel, s: f64) -> bool {
    let (x, y) = (p.0 as f64, p.1 as f64);
    let (x0, x1, y0, y1) = ((x - 0.5) * s, (x + 0.5) * s, (y - 0.5) * s, (y + 0.5) * s);
    let b = e.bounds();
    if b.max.x < x0 || b.min.x >= x1 || b.max.y < y0 || b.min.y >= y1 {
        return false;
    }
    // Both ends inside the (convex) pixel, a point edge among them: no corner need be asked.
    // Where one pixel holds a whole cluster of edges beside a far vertex (the pixel is ulps of
    // that vertex), the corners lie far from every edge and the orientation filter cannot
    // decide them.
    if b.min.x >= x0 && b.max.x < x1 && b.min.y >= y0 && b.max.y < y1 {
        return true;
    }
    let (dx, dy) = (e.b.x - e.a.x, e.b.y - e.a.y);
    // The sign of orient(a, b, c - (εx, εy)): the exact sign, else εx·dy - εy·dx's.
    let side = |c: Point, moved_x: bool, moved_y: bool| -> i32 {
        let o = orient(e.a, e.b, c);
        if o != Orientation::Collinear {
            return o.sign();
        }
        if moved_x && dy != 0.0 {
            return if dy > 0.0 { 1 } else { -1 };
        }
        if moved_y && dx != 0.0 {
            return if dx > 0.0 { -1 } else { 1 };
        }
        0
    };
    // orient(a, b, c) = dx·(c.y - a.y) - dy·(c.x - a.x): largest at this corner, least at the
    // opposite one.
    let (high_x, high_y) = (dy <= 0.0, dx > 0.0);
    let corner =
        |right: bool, top: bool| side(Point::new(if right { x1 } else { x0 }, if top { y1 } else { y0 }), right, top);
    let (most, least) = (corner(high_x, high_y), corner(!high_x, !high_y));
    !((most > 0 && least > 0) || (most < 0 && least < 0))
}

/// Sorts the pixels an edge meets into their order along it: by column in its x direction, then
/// by row in its y direction (along an edge both are monotone), and drops repeats.
fn order_along(pixels: &mut Vec<Pixel>, e: Segment) {
    let sx = if e.b.x >= e.a.x { 1 } else { -1 };
    let sy = if e.b.y >= e.a.y { 1 } else { -1 };
    pixels.sort_unstable_by_key(|p| (sx * p.0, sy * p.1));
    pixels.dedup();
}

/// At least three distinct points, not all on one line.
fn has_area(points: &[Point]) -> bool {
    let Some(&a) = points.first() else { return false };
    let Some(&b) = points.iter().find(|&&p| p != a) else { return false };
    points.iter().any(|&c| orient(a, b, c) != Orientation::Collinear)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Operand;

    /// A small xorshift generator: seeded, so every failure reproduces.
    struct Rng(u64);

    impl Rng {
        fn next(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    fn ring(points: &[(f64, f64)]) -> Ring {
        Ring::new(points.iter().map(|&(x, y)| Point::new(x, y)).collect())
    }

    fn random_ring(rng: &mut Rng, n: usize, scale: f64) -> Ring {
        Ring::new((0..n).map(|_| Point::new(rng.next() * scale, rng.next() * scale)).collect())
    }

    /// (a): no two output edges cross, and no output vertex lies inside an output edge (they
    /// meet only at shared end points, or coincide). Brute force, exact.
    fn assert_noded(out: &[&Polygons]) {
        let edges: Vec<Segment> = out.iter().flat_map(|p| p.edges()).filter(|e| e.a != e.b).collect();
        for (i, &e) in edges.iter().enumerate() {
            for &f in &edges[i + 1..] {
                match predicates::segment_intersection(e, f) {
                    SegmentIntersection::Crossing(p) => panic!("{e:?} crosses {f:?} near {p:?}"),
                    SegmentIntersection::Touching(p) => {
                        let ends = [e.a, e.b, f.a, f.b];
                        assert!(
                            (p == e.a || p == e.b) && (p == f.a || p == f.b),
                            "{e:?} and {f:?} touch at {p:?}, inside one of them ({ends:?})"
                        );
                    }
                    SegmentIntersection::Overlap(_) => {
                        let same = (e.a == f.a && e.b == f.b) || (e.a == f.b && e.b == f.a);
                        assert!(same, "{e:?} and {f:?} overlap without coinciding");
                    }
                    SegmentIntersection::None => {}
                }
            }
        }
    }

    /// (b) and (c): every output vertex a multiple of `s`, within s·√2/2 of an edge of the input
    /// ring it came from (`snap_rings` keeps ring order).
    fn assert_near_inputs(rings: &[&Ring], snapped: &[Option<Vec<Point>>], s: f64) {
        let reach = s * std::f64::consts::SQRT_2 / 2.0 * (1.0 + 1e-12);
        for (ring, out) in rings.iter().zip(snapped) {
            for &p in out.iter().flatten() {
                assert!(p.x % s == 0.0 && p.y % s == 0.0, "{p:?} off the grid of {s:e}");
                let near = ring.edges().any(|e| distance_to_segment(p, e) <= reach);
                assert!(near, "{p:?} farther than s·√2/2 from its ring");
            }
        }
    }

    fn distance_to_segment(p: Point, e: Segment) -> f64 {
        let d = e.b - e.a;
        let len2 = d.dot(d);
        let t = if len2 > 0.0 { ((p - e.a).dot(d) / len2).clamp(0.0, 1.0) } else { 0.0 };
        p.distance(e.at(t))
    }

    /// Snap rounds both operands and checks (a), (b) and (c).
    fn check(subject: &Polygons, clip: &Polygons, s: f64) -> (Polygons, Polygons) {
        let rings: Vec<&Ring> = subject.rings.iter().chain(&clip.rings).collect();
        assert_near_inputs(&rings, &snap_rings(&rings, s), s);
        let (a, b) = snap_round(subject, clip, s).expect("valid input");
        assert_noded(&[&a, &b]);
        (a, b)
    }

    /// Found by the `vatti` fuzz target (unions at 1e114-1e141, whose snap fallback's output
    /// crossed itself): in world units the crossing predicates' degree-three terms overflow
    /// beyond about 1e100, and crossings went into the wrong pixels.
    #[test]
    fn rings_far_beyond_1e100_are_noded() {
        for seed in 1..=20u64 {
            let mut rng = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
            let scale = 1e141;
            let subject = Polygons::new(vec![random_ring(&mut rng, 12, scale)]);
            let clip = Polygons::new(vec![random_ring(&mut rng, 12, scale)]);
            let s = 2f64.powi(((scale.log2().ceil()) as i32) - 50);
            let (a, b) = snap_round(&subject, &clip, s).expect("valid input");
            assert_noded(&[&a, &b]);
        }
    }

    /// The pixel of a crossing holds the exact crossing, checked against its borders exactly:
    /// far from the origin (where the filter works on offsets from the segment's start), for
    /// short and long segments, and for nearly parallel pairs (lenses).
    #[test]
    fn crossing_pixels_hold_the_exact_crossing_far_from_the_origin() {
        let mut rng = Rng(0x2545_F491_4F6C_DD1D);
        let mut checked = 0;
        for (origin, span) in [(1e6f64, 1e3f64), (1e6, 1.0), (3.7e9, 1e5), (1.0, 1.0), (-2e7, 10.0)] {
            // 4 ulps of the largest coordinate, as the vatti fallback's pixel.
            let top = origin.abs() + span;
            let s = 2f64.powi(((top.to_bits() >> 52) & 0x7ff) as i32 - 1023 - 50);
            let at = |rng: &mut Rng| Point::new(origin + rng.next() * span, origin + rng.next() * span);
            for k in 0..800 {
                let a = Segment::new(at(&mut rng), at(&mut rng));
                let (e, f) = match k % 3 {
                    0 => (a, Segment::new(at(&mut rng), at(&mut rng))),
                    1 => {
                        // Both through a pixel corner near a's middle: the crossing lies within
                        // rounding of two pixel borders.
                        let m = a.at(0.5);
                        let corner = Point::new(((m.x / s).floor() + 0.5) * s, ((m.y / s).floor() + 0.5) * s);
                        let d = Point::new(rng.next() - 0.5, rng.next() - 0.5) * span;
                        let half = (a.b - a.a) * 0.5;
                        (Segment::new(corner - half, corner + half), Segment::new(corner - d, corner + d))
                    }
                    _ => {
                        // a's ends moved by a few ulps: crossing at a small angle, if at all.
                        let nudge = |p: Point, rng: &mut Rng| {
                            Point::new(p.x + (rng.next() - 0.5) * 8.0 * s, p.y + (rng.next() - 0.5) * 8.0 * s)
                        };
                        (a, Segment::new(nudge(a.b, &mut rng), nudge(a.a, &mut rng)))
                    }
                };
                if !matches!(predicates::segment_intersection(e, f), SegmentIntersection::Crossing(_)) {
                    continue;
                }
                let (i, j) = crossing_pixel(e, f, s);
                for (along_y, c) in [(false, i), (true, j)] {
                    let (low, high) = ((c as f64 - 0.5) * s, (c as f64 + 0.5) * s);
                    assert!(crossing_coordinate_cmp(e, f, along_y, low).is_ge(), "{e:?} {f:?} below its pixel");
                    assert!(crossing_coordinate_cmp(e, f, along_y, high).is_lt(), "{e:?} {f:?} above its pixel");
                }
                checked += 1;
            }
        }
        assert!(checked > 1000, "{checked} crossings checked");
    }

    #[test]
    fn the_double_double_estimate_decides_only_as_the_exact_comparison_does() {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        let (mut decided, mut ulp_away) = (0, 0);
        for (origin, span) in [(1e6f64, 1e3f64), (3.7e9, 1e5), (1.0, 1.0), (-2e7, 10.0)] {
            let at = |rng: &mut Rng| Point::new(origin + rng.next() * span, origin + rng.next() * span);
            for k in 0..400 {
                let e = Segment::new(at(&mut rng), at(&mut rng));
                // Every other pair nearly parallel: `e` turned by up to 1e-12 about its middle.
                let f = if k % 2 == 0 {
                    Segment::new(at(&mut rng), at(&mut rng))
                } else {
                    let (m, half) = (e.at(0.5), (e.b - e.a) * 0.5);
                    let turn = Point::new(-half.y, half.x) * ((rng.next() - 0.5) * 2e-12);
                    Segment::new(m + half + turn, m - half - turn)
                };
                if !matches!(predicates::segment_intersection(e, f), SegmentIntersection::Crossing(_)) {
                    continue;
                }
                let Some((offset, relative)) = predicates::double_double_crossing_offset(e, f) else { continue };
                for along_y in [false, true] {
                    let (o, base) = if along_y { (offset[1], e.a.y) } else { (offset[0], e.a.x) };
                    let estimate = base + o.hi;
                    // Lines from within the estimate's error to a few ulps of the coordinate away.
                    for steps in [-64i32, -3, -1, 0, 1, 3, 64] {
                        for (scale, ulps) in [(relative * o.hi.abs(), false), (f64::EPSILON * estimate.abs(), true)] {
                            let m = estimate + f64::from(steps) * scale;
                            let exact = crossing_coordinate_cmp(e, f, along_y, m).is_lt();
                            let by_estimate = below_by_estimate(o, relative, base, m);
                            if let Some(below) = by_estimate {
                                assert_eq!(below, exact, "{e:?} {f:?} against {m} (y: {along_y})");
                                decided += 1;
                            }
                            // A line an ulp of the coordinate or more away: the estimate decides.
                            if ulps && steps != 0 && m != estimate {
                                assert!(by_estimate.is_some(), "{e:?} {f:?} against {m}, {steps} ulps away");
                                ulp_away += 1;
                            }
                        }
                    }
                }
            }
        }
        assert!(ulp_away > 1000 && decided > ulp_away, "{decided} decided, {ulp_away} lines an ulp or more away");
    }

    #[test]
    fn random_rings_are_noded_on_the_grid_near_their_inputs() {
        for seed in 1..=60u64 {
            let mut rng = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
            let n = 3 + seed as usize % 9;
            let subject = Polygons::new(vec![random_ring(&mut rng, n, 1.0), random_ring(&mut rng, 4, 1.0)]);
            let clip = Polygons::new(vec![random_ring(&mut rng, n + 2, 1.0)]);
            // A coarse grid collapses and reroutes a lot; a fine one is the vatti fallback's.
            for s in [2f64.powi(-3), 2f64.powi(-6), 2f64.powi(-50)] {
                check(&subject, &clip, s);
            }
        }
    }

    #[test]
    fn an_edge_and_a_copy_turned_by_1e_16_are_noded() {
        let turned = |x: f64, y: f64, angle: f64| {
            let (sin, cos) = angle.sin_cos();
            (x * cos - y * sin, x * sin + y * cos)
        };
        for angle in [1e-16, -1e-16, 3e-16, 1e-15] {
            let square = [(0.1, 0.2), (0.9, 0.25), (0.95, 0.8), (0.15, 0.7)];
            let copy: Vec<(f64, f64)> = square.iter().map(|&(x, y)| turned(x, y, angle)).collect();
            let subject = Polygons::new(vec![ring(&square)]);
            let clip = Polygons::new(vec![ring(&copy)]);
            // Nearly coincident edges cross somewhere along them: the crossings must be hot.
            let crossings = subject
                .edges()
                .flat_map(|e| clip.edges().map(move |f| (e, f)))
                .filter(|&(e, f)| matches!(predicates::segment_intersection(e, f), SegmentIntersection::Crossing(_)))
                .count();
            assert!(crossings > 0, "angle {angle:e}: the copy does not cross the square");
            let s = 2f64.powi(-51);
            let (a, b) = check(&subject, &clip, s);
            assert_eq!((a.rings.len(), b.rings.len()), (1, 1));
        }
    }

    #[test]
    fn a_vertex_2_ulps_off_an_edge_is_noded() {
        let ulp = f64::EPSILON / 2.0;
        for offset in [2.0 * ulp, -2.0 * ulp, ulp] {
            let subject = Polygons::new(vec![ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0)])]);
            // A triangle whose apex is `offset` off the diagonal's middle.
            let clip = Polygons::new(vec![ring(&[(0.75, 0.25), (0.5 + offset, 0.5), (0.25, 0.75), (0.2, 0.2)])]);
            for s in [2f64.powi(-50), 2f64.powi(-48)] {
                check(&subject, &clip, s);
            }
        }
    }

    #[test]
    fn grid_input_without_crossings_comes_back_unchanged() {
        let s = 0.25;
        let subject = Polygons::new(vec![
            ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0)]),
            ring(&[(1.0, 1.0), (1.0, 2.0), (2.0, 1.0)]),
        ]);
        // Touching the subject along an edge and at a vertex, crossing nothing.
        let clip = Polygons::new(vec![ring(&[(4.0, 0.0), (6.0, 0.0), (5.0, 2.0), (4.0, 3.0)])]);
        let (a, b) = snap_round(&subject, &clip, s).expect("valid input");
        assert_eq!((a, b), (subject.clone(), clip.clone()));
        // Crossing edges do change: the crossing becomes a vertex of both.
        let crossing = Polygons::new(vec![ring(&[(-1.0, 1.5), (1.0, 1.5), (0.0, 5.0)])]);
        let (a, b) = snap_round(&subject, &crossing, s).expect("valid input");
        assert_noded(&[&a, &b]);
        assert_ne!(a, subject);
        assert_eq!(a.rings[0].distinct_points(), 6);
    }

    #[test]
    fn bad_pixels_and_far_coordinates_are_refused() {
        let square = Polygons::new(vec![ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0)])]);
        for pixel in [0.0, -0.5, 0.3, f64::NAN, f64::INFINITY, f64::MIN_POSITIVE / 4.0] {
            assert!(matches!(snap_round(&square, &square, pixel), Err(ClipError::InvalidPixel { .. })), "{pixel}");
        }
        let far = Polygons::new(vec![ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 2f64.powi(60))])]);
        let e = snap_round(&square, &far, 2f64.powi(-4)).unwrap_err();
        assert!(matches!(e, ClipError::BeyondGrid { operand: Operand::Clip, part: 0, vertex: 2, .. }), "{e}");
        let nan = Polygons::new(vec![ring(&[(0.0, 0.0), (f64::NAN, 0.0), (1.0, 1.0)])]);
        let e = snap_round(&nan, &square, 1.0).unwrap_err();
        assert!(matches!(e, ClipError::NonFinite { operand: Operand::Subject, vertex: 1, .. }), "{e}");
    }

    #[test]
    fn pairs_set_apart_meet_no_pixel_of_each_other() {
        let mut rng = Rng(0x5DEE_CE66_D1CE_4E5B);
        let (mut apart_pairs, mut close_kept) = (0, 0);
        for scale in [1.0, 1e3, 1e9] {
            let s = 2f64.powi(((scale * 2.0f64).log2().ceil()) as i32 - 50);
            let at = |rng: &mut Rng| Point::new(rng.next() * scale, rng.next() * scale);
            for _ in 0..3000 {
                let e = Segment::new(at(&mut rng), at(&mut rng));
                let f = Segment::new(at(&mut rng), at(&mut rng));
                if apart(e, f, s) {
                    apart_pairs += 1;
                    assert!(matches!(predicates::segment_intersection(e, f), SegmentIntersection::None));
                    for (g, h) in [(e, f), (f, e)] {
                        for v in [h.a, h.b] {
                            assert!(!meets_pixel(g, pixel_of(v, s), s), "{g:?} meets the pixel of {v:?}");
                        }
                    }
                }
                // A copy moved by up to a pixel, and one through a point of `e`: within reach.
                let d = Point::new((rng.next() - 0.5) * s, (rng.next() - 0.5) * s);
                let moved = Segment::new(e.a + d, e.b + d);
                let through = Segment::new(e.at(rng.next()), at(&mut rng));
                for g in [moved, through] {
                    assert!(!apart(e, g, s) && !apart(g, e, s), "{e:?} and {g:?} set apart");
                    close_kept += 1;
                }
            }
        }
        assert!(apart_pairs > 1000 && close_kept > 1000, "{apart_pairs} apart, {close_kept} close");
    }

    /// Every segment's met pixels are every hot pixel it meets, as found by testing each segment
    /// against every hot pixel: on random rings at coarse pixels (many edges inside one pixel),
    /// and on a cluster of edges inside one pixel beside a far vertex, whose pixel is ulps of that
    /// vertex (the fuzz target's slow units: every pair of the cluster is a near pair).
    #[test]
    fn met_pixels_are_the_hot_pixels_each_segment_meets() {
        let mut cases = Vec::new();
        for seed in 1..=30u64 {
            let mut rng = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
            let rings = vec![random_ring(&mut rng, 5 + seed as usize % 7, 1.0), random_ring(&mut rng, 6, 1.0)];
            cases.push((rings, 2f64.powi(-2 - (seed % 3) as i32)));
        }
        let mut rng = Rng(0x2545_F491_4F6C_DD1D);
        let mut cluster = random_ring(&mut rng, 40, 1e6);
        cluster.points.push(Point::new(-6.3e66, 5e5));
        cases.push((vec![cluster, random_ring(&mut rng, 30, 1e6)], 2f64.powi(222 - 50)));
        for (rings, s) in cases {
            let refs: Vec<&Ring> = rings.iter().collect();
            let segments: Vec<Segment> = refs.iter().flat_map(|r| r.edges()).collect();
            let pairs = near_pairs(refs.iter().map(|r| r.len()), &segments, s);
            let met = met_pixels(&segments, &pairs, s);
            let mut hot: Vec<Pixel> = segments.iter().flat_map(|e| [pixel_of(e.a, s), pixel_of(e.b, s)]).collect();
            for (i, &e) in segments.iter().enumerate() {
                for &f in &segments[i + 1..] {
                    if shared_end(e, f).is_none()
                        && let SegmentIntersection::Crossing(_) = predicates::segment_intersection(e, f)
                    {
                        hot.push(crossing_pixel(e, f, s));
                    }
                }
            }
            hot.sort_unstable();
            hot.dedup();
            for (i, &e) in segments.iter().enumerate() {
                let mut expected: Vec<Pixel> = hot.iter().copied().filter(|&p| meets_pixel(e, p, s)).collect();
                let mut found = met.of(i).to_vec();
                expected.sort_unstable();
                found.sort_unstable();
                found.dedup();
                assert_eq!(found, expected, "segment {i} {e:?} at s = {s:e}");
            }
        }
    }

    #[test]
    fn pixel_membership_is_half_open() {
        let s = 1.0;
        // A horizontal edge along the top border belongs to the pixel above only.
        let top = Segment::new(Point::new(-3.0, 0.5), Point::new(3.0, 0.5));
        assert!(!meets_pixel(top, (0, 0), s) && meets_pixel(top, (0, 1), s));
        // A diagonal through the pixel's top-right corner only meets it there: not in it.
        let corner = Segment::new(Point::new(0.0, 1.0), Point::new(1.0, 0.0));
        assert!(!meets_pixel(corner, (0, 0), s) && meets_pixel(corner, (1, 1), s));
        let through = Segment::new(Point::new(-1.0, 2.0), Point::new(2.0, -1.0));
        assert!(!meets_pixel(through, (0, 0), s));
        assert!(meets_pixel(through, (1, 0), s) && meets_pixel(through, (0, 1), s));
        // The bottom-left corner belongs to it.
        let low = Segment::new(Point::new(-2.0, 1.0), Point::new(1.0, -2.0));
        assert!(meets_pixel(low, (0, 0), s));
    }
}
