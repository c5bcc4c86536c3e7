//! An exact check of an output's form, run only where rounding may have broken it.
//!
//! The clean-up sees only rings that share a point. Where an output edge is within a few
//! thousand ulps of the inputs' largest coordinate, rounded crossings can also leave rings that
//! share no point overlapping along an edge, crossing, or one inside another running the same
//! way (found by the `vatti` fuzz target at 1e15 and with edges running to 5e25 and 6e66), and
//! two crossings rounded a few ulps apart can leave edges crossing, overlapping, a ring meeting
//! itself or two rings crossing at a shared vertex between them (at any scale), as can an input
//! vertex a few ulps off an edge (the sweep's near miss). This check looks for exactly those
//! faults, so that `snap_fallback` can replace them: in outputs of at most [`MAX_EDGES`] edges
//! with a pair of near vertices or a near miss, and of at most [`MAX_SCANNED_EDGES`] with a short
//! edge or thin ring (a scan of its own over every output edge, where the near-vertex test rides
//! on the clean-up's order). Larger outputs are not checked (a known limit), except near the
//! sweep's near crossings (several edges through one point, their pairwise crossings rounded to
//! one point or a few ulps apart: a ring can then cross itself with no vertex near another), where
//! [`crossing_near`] tests the edges passing there in outputs of any size.

use clip_core::{
    CellIndex, Point, Polygons, Rect, Ring, Segment, SegmentIntersection, ring_winding, segment_intersection,
};

use crate::cleanup::cross_at_shared_points;
use crate::raw_rings::RawRings;
use crate::sweep::NEAR_CROSSINGS_ULPS;

/// The most output edges checked: the pair test goes through a cell index, near linear on
/// most outputs but quadratic where many long edges share cells.
pub(crate) const MAX_EDGES: usize = 1 << 16;

/// The most output edges scanned for a short edge or thin ring ([`near_rounding`]).
const MAX_SCANNED_EDGES: usize = 1024;

/// Output edges shorter, or rings thinner, than this many ulps of the inputs' largest coordinate
/// make the output worth checking: features that small are where rounding misplaces edges.
const ULPS_NEAR_ROUNDING: f64 = 4096.0;

/// Binary digits up to which integer coordinates, on any power-of-two scale, make the sweep's
/// rounding harmless ([`rounding_is_harmless`]; the bounds there hold up to 9).
const HARMLESS_DIGITS: u32 = 9;

/// True when rounding cannot change the form of the sweep's output, so it needs no check: every
/// coordinate of `subject` and `clip` is an integer below 2^m (m = [`HARMLESS_DIGITS`]) in units
/// of one power of two (`predicates::on_coarse_grid`). In those units:
/// - every product in a crossing's computation is exact, so a crossing is the exact one rounded
///   once, and an edge's x on a scanline twice: under 2^(m-51) off;
/// - a crossing is a fraction with a denominator below 2^(2m+3), so two distinct crossing heights
///   differ by at least 2^-(4m+6), over an ulp: the sweep takes its events in their exact order,
///   and its decisions, which are exact predicates, are those of exact arithmetic;
/// - a crossing or vertex off a segment's line lies at least 2^-(3m+5) from it, and two distinct
///   points at least 2^-(4m+6) apart: rounding moves no point onto, across or within rounding of
///   an edge or point it is not on, so the rounded output meets itself exactly where the exact
///   one does.
///
/// Property used: coordinates of few binary digits (grids, pixel and tile coordinates).
pub(crate) fn rounding_is_harmless(subject: &Polygons, clip: &Polygons) -> bool {
    fn coarse<'a>(points: impl Iterator<Item = &'a Point>) -> bool {
        clip_core::predicates::on_coarse_grid(points.flat_map(|q| [q.x, q.y]), HARMLESS_DIGITS)
    }
    let points = || [subject, clip].into_iter().flat_map(|p| p.rings.iter().flat_map(|r| &r.points));
    // Every 61st point first: an input off the grid, or spanning more digits, mostly shows it
    // there, before a pass over every point (integer spirals reach their far coordinates late).
    coarse(points().step_by(61)) && coarse(points())
}

/// Rings at most this many ulps of their largest coordinate wide are slivers that rounded
/// crossings can turn inside out: the snap fallback's pixel, which would collapse them.
const SLIVER_ULPS: f64 = 4.0;

/// True when `rings` cross, overlap, meet uncleanly at a shared point or nest against their
/// orientation, where they are checked: with `near_vertices` (the sweep's near miss or
/// [`vertices_near_rounding`]) and at most [`MAX_EDGES`] edges, or with an edge or a ring's
/// width within [`ULPS_NEAR_ROUNDING`] ulps of the largest coordinate of `subject` and `clip`
/// and at most [`MAX_SCANNED_EDGES`] edges. False for outputs not checked.
pub(crate) fn broken_near_rounding(subject: &Polygons, clip: &Polygons, rings: &[Ring], near_vertices: bool) -> bool {
    let edges = rings.iter().map(Ring::len).sum::<usize>();
    let gate = if near_vertices {
        edges <= MAX_EDGES
    } else {
        edges <= MAX_SCANNED_EDGES && near_rounding(subject, clip, rings)
    };
    if rings.is_empty() || !gate {
        return false;
    }
    crossing_or_overlapping(rings) || nested_against_orientation(rings) || unclean_at_shared_points(rings)
}

/// Whether the rings cross, or one passes twice, at a point they share
/// (`cleanup::cross_at_shared_points`): rounded crossings a few ulps apart can leave two rings
/// that meet at a vertex and cross there, which no pair of edges shows.
fn unclean_at_shared_points(rings: &[Ring]) -> bool {
    let mut pts: Vec<Point> = rings.iter().flat_map(|r| r.points.iter().copied()).collect();
    pts.sort_unstable_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    pts.dedup();
    let id = |p: &Point| pts.partition_point(|q| q.x.total_cmp(&p.x).then(q.y.total_cmp(&p.y)).is_lt()) as u32;
    let (mut ids, mut ends) = (Vec::new(), Vec::new());
    for r in rings {
        ids.extend(r.points.iter().map(id));
        ends.push(ids.len());
    }
    cross_at_shared_points(&pts, &ids, &ends)
}

/// Whether two distinct points of the sweep's output, of any rings, lie within
/// [`ULPS_NEAR_ROUNDING`] ulps of the inputs' largest coordinate of each other: crossings rounded
/// twice (once per pair of edges), or rounded next to an input vertex, land a few ulps apart, and
/// the edges between them may then cross or overlap although no ring has a short edge. `by_y`
/// holds the distinct points ordered by y, then x (the clean-up's `Touches::distinct_by_y`), so
/// this is one pass: each point against the next of its row, and rows within reach in y (rare)
/// by binary search.
pub(crate) fn vertices_near_rounding(subject: &Polygons, clip: &Polygons, by_y: &[Point]) -> bool {
    if by_y.len() < 2 {
        return false;
    }
    let largest = [subject, clip]
        .iter()
        .flat_map(|p| p.rings.iter().flat_map(|r| &r.points))
        .fold(0.0f64, |m, q| m.max(q.x.abs()).max(q.y.abs()));
    let reach = largest * ULPS_NEAR_ROUNDING * f64::EPSILON;
    // Most rows are one point and most neighbouring rows far apart in y: one pass over
    // neighbours, and the full row by row pass only where two rows are within reach.
    let rows_apart =
        by_y.windows(2).all(|w| if w[0].y == w[1].y { w[1].x - w[0].x > reach } else { w[1].y - w[0].y > reach });
    if rows_apart {
        return false;
    }
    let row_end = |start: usize| start + by_y[start..].iter().take_while(|p| p.y == by_y[start].y).count();
    let mut start = 0;
    while start < by_y.len() {
        let end = row_end(start);
        let row = &by_y[start..end];
        if row.windows(2).any(|w| w[1].x - w[0].x <= reach) {
            return true;
        }
        let mut next = end;
        while next < by_y.len() && by_y[next].y - row[0].y <= reach {
            let next_end = row_end(next);
            let other = &by_y[next..next_end];
            let near = |p: &Point| {
                let k = other.partition_point(|q| q.x < p.x - reach);
                other.get(k).is_some_and(|q| q.x <= p.x + reach)
            };
            if row.iter().any(near) {
                return true;
            }
            next = next_end;
        }
        start = end;
    }
    false
}

/// Whether an output can be checked when its vertices are near: at most [`MAX_EDGES`] edges, and
/// not empty.
pub(crate) fn checked(rings: &[Ring]) -> bool {
    !rings.is_empty() && rings.iter().map(Ring::len).sum::<usize>() <= MAX_EDGES
}

/// Whether an output edge is shorter, or a ring thinner, than [`ULPS_NEAR_ROUNDING`] ulps of the
/// inputs' largest coordinate. Plain loops: this runs on every small clip.
fn near_rounding(subject: &Polygons, clip: &Polygons, rings: &[Ring]) -> bool {
    reaches_rounding(subject, clip, rings.iter().map(|r| r.points.as_slice()))
}

/// [`near_rounding`] of the sweep's raw rings, before the clean-up (the same points).
pub(crate) fn raw_near_rounding(subject: &Polygons, clip: &Polygons, raw: &RawRings) -> bool {
    reaches_rounding(subject, clip, (0..raw.len()).map(|i| raw.ring(i)))
}

fn reaches_rounding<'a>(subject: &Polygons, clip: &Polygons, rings: impl Iterator<Item = &'a [Point]>) -> bool {
    let (mut shortest2, mut thinnest) = (f64::INFINITY, f64::INFINITY);
    for p in rings.filter(|p| !p.is_empty()) {
        // A sliver of long edges (nearly collinear input vertices) is as near rounding as a
        // short edge.
        let (twice_area, perimeter, s2) = ring_measures(p);
        shortest2 = shortest2.min(s2);
        if perimeter > 0.0 {
            thinnest = thinnest.min(twice_area / perimeter);
        }
    }
    // The largest coordinate that leaves the shortest edge and the thinnest ring above the limit.
    let largest_far = shortest2.sqrt().min(thinnest) / (ULPS_NEAR_ROUNDING * f64::EPSILON);
    [subject, clip]
        .iter()
        .flat_map(|p| &p.rings)
        .any(|r| r.points.iter().any(|q| q.x.abs().max(q.y.abs()) >= largest_far))
}

/// A ring's twice area (about its first vertex, so that far coordinates cancel; its absolute
/// value), L1 perimeter and shortest edge squared. The first over the second is at most the
/// ring's width.
fn ring_measures(p: &[Point]) -> (f64, f64, f64) {
    let Some(&o) = p.first() else { return (0.0, 0.0, f64::INFINITY) };
    let (mut a, mut twice_area, mut perimeter, mut shortest2) = (p[p.len() - 1], 0.0, 0.0, f64::INFINITY);
    for &b in p {
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        shortest2 = shortest2.min(dx * dx + dy * dy);
        perimeter += dx.abs() + dy.abs();
        twice_area += (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
        a = b;
    }
    (twice_area.abs(), perimeter, shortest2)
}

/// Removes from an output of more than [`MAX_SCANNED_EDGES`] edges, which
/// [`broken_near_rounding`] checks only with near vertices, the slivers (rings at most
/// [`SLIVER_ULPS`] ulps of their largest coordinate wide) whose orientation disagrees with the
/// number of rings around them: rounded crossings put a vertex across the line of the others, and
/// the ring runs the wrong way round a region narrower than f64 can place a point in. Snap
/// rounding at the fallback's pixel would collapse them; this does so without the fallback's
/// sweep. Smaller outputs with a ring that thin are checked whole. Linear in the output where it
/// holds no sliver.
pub(crate) fn drop_flipped_slivers(rings: &mut Vec<Ring>) {
    if rings.iter().map(Ring::len).sum::<usize>() <= MAX_SCANNED_EDGES {
        return;
    }
    // The first vertex's magnitude plus the perimeter bounds a ring's coordinates.
    let sliver = |r: &Ring| {
        let (twice_area, perimeter, _) = ring_measures(&r.points);
        let largest = r.points.first().map_or(0.0, |o| o.x.abs().max(o.y.abs())) + perimeter;
        twice_area <= SLIVER_ULPS * f64::EPSILON * largest * perimeter
    };
    let slivers: Vec<usize> = (0..rings.len()).filter(|&r| sliver(&rings[r])).collect();
    if slivers.is_empty() {
        return;
    }
    let boxes: Vec<Rect> = rings.iter().map(Ring::bounds).collect();
    let Some(index) = CellIndex::new(&boxes) else { return };
    let flipped: Vec<usize> = slivers.into_iter().filter(|&r| against_orientation(rings, &boxes, &index, r)).collect();
    let mut k = 0;
    rings.retain(|_| {
        k += 1;
        flipped.binary_search(&(k - 1)).is_err()
    });
}

/// Two edges crossing, two edges overlapping (conventional output shares no stretch between
/// rings: two outers would be one, a hole along its outer a notch), or a ring meeting itself away
/// from its own vertices' neighbours (it may visit a point once). Rings may touch at points.
fn crossing_or_overlapping(rings: &[Ring]) -> bool {
    let edges =
        rings.iter().enumerate().flat_map(|(r, ring)| ring.edges().enumerate().map(move |(i, s)| (r, i, s))).collect();
    pair_broken(rings, edges)
}

/// Whether output edges passing within [`NEAR_CROSSINGS_ULPS`] ulps of one of the sweep's
/// `near_crossings` (crossings of several edges through one point, rounded to one point or a few
/// ulps apart) cross, overlap or meet their own ring there, as [`crossing_or_overlapping`] tests
/// every edge. Those points are where the output can break with no near vertices or short edge
/// to show it, and only the edges passing near them are tested: one pass over the output's
/// edges, each edge's x range tested against the points' merged x spans first.
pub(crate) fn crossing_near(rings: &[Ring], near_crossings: &[Point]) -> bool {
    if near_crossings.is_empty() {
        return false;
    }
    let mut pts = near_crossings.to_vec();
    pts.sort_unstable_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    pts.dedup();
    let largest = pts.iter().fold(0.0f64, |m, q| m.max(q.x.abs()).max(q.y.abs()));
    let reach = NEAR_CROSSINGS_ULPS * f64::EPSILON * largest;
    // The points' x ranges within reach, merged: the points come in clusters (several edges
    // through one point), so there are few.
    let mut spans: Vec<(f64, f64)> = Vec::new();
    for q in &pts {
        match spans.last_mut() {
            Some(last) if q.x - reach <= last.1 => last.1 = q.x + reach,
            _ => spans.push((q.x - reach, q.x + reach)),
        }
    }
    let mut edges = Vec::new();
    for (r, ring) in rings.iter().enumerate() {
        let p = &ring.points;
        let Some(&last) = p.last() else { continue };
        // Edge `i - 1` runs from `a` to `b = p[i]`; the first is the ring's last (closing) edge.
        let mut a = last;
        for (i, &b) in p.iter().enumerate() {
            let (ax, bx) = if a.x <= b.x { (a.x, b.x) } else { (b.x, a.x) };
            // Most edges have no point within reach of their x range.
            let hit = if spans.len() <= FEW_SPANS {
                spans.iter().any(|&(lo, hi)| lo <= bx && hi >= ax)
            } else {
                spans.get(spans.partition_point(|s| s.1 < ax)).is_some_and(|s| s.0 <= bx)
            };
            if hit && passes_near(a, b, &pts, reach) {
                edges.push((r, if i == 0 { p.len() - 1 } else { i - 1 }, Segment::new(a, b)));
            }
            a = b;
        }
    }
    edges.len() > 1 && pair_broken(rings, edges)
}

/// Whether one of `pts` (in x order) lies within `reach` of the edge from `a` to `b`: within its
/// box, then within `reach` of its line (generously, in the max norm).
fn passes_near(a: Point, b: Point, pts: &[Point], reach: f64) -> bool {
    let (ax, bx) = (a.x.min(b.x), a.x.max(b.x));
    let (ay, by) = (a.y.min(b.y), a.y.max(b.y));
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let length = dx.abs().max(dy.abs());
    let first = pts.partition_point(|q| q.x < ax - reach);
    pts[first..].iter().take_while(|q| q.x <= bx + reach).any(|q| {
        q.y >= ay - reach && q.y <= by + reach && (dx * (q.y - a.y) - dy * (q.x - a.x)).abs() <= 2.0 * reach * length
    })
}

/// [`crossing_or_overlapping`] over `edges` (ring, index in it, segment) of `rings`. Pairs come
/// from a cell index over the edges' boxes: near linear unless many long edges share cells.
fn pair_broken(rings: &[Ring], edges: Vec<(usize, usize, Segment)>) -> bool {
    let neighbours = |r: usize, i: usize, j: usize| {
        let n = rings[r].len();
        (i + 1) % n == j || (j + 1) % n == i
    };
    let broken = |a: usize, b: usize| {
        let ((r, i, s), (q, j, t)) = (edges[a], edges[b]);
        if r == q && neighbours(r, i, j) {
            return false;
        }
        match segment_intersection(s, t) {
            SegmentIntersection::Crossing(_) | SegmentIntersection::Overlap(_) => true,
            SegmentIntersection::Touching(_) => r == q,
            _ => false,
        }
    };
    // A few edges (those near rounded crossings): every pair, without building an index.
    if edges.len() <= SMALL_PAIR_TEST {
        let meet = |a: usize, b: usize| edges[a].2.bounds().intersects(&edges[b].2.bounds());
        return (0..edges.len()).any(|a| (a + 1..edges.len()).any(|b| meet(a, b) && broken(a, b)));
    }
    let boxes: Vec<Rect> = edges.iter().map(|e| e.2.bounds()).collect();
    let Some(index) = CellIndex::new(&boxes) else { return false };
    index.try_for_each_close_pair(&boxes, |a, b| if broken(a, b) { Err(()) } else { Ok(()) }).is_err()
}

/// Edge lists up to this long are tested pair by pair rather than through a cell index.
const SMALL_PAIR_TEST: usize = 32;

/// Up to this many merged x spans of near crossings, an edge is tested against each in turn
/// rather than by binary search (a few comparisons cost less than the search's branches).
const FEW_SPANS: usize = 4;

/// A ring whose orientation disagrees with the number of other rings around it (outers, at
/// even depth, counter-clockwise; holes clockwise). Each ring is placed by its first vertex off
/// every other ring, else by the first midpoint of an edge off them (a triangle whose corners
/// all touch other rings: its edges cannot lie on them, which would be an overlap); a ring
/// with none such is counted as broken. The rings around a point come from a cell index over
/// the rings' boxes.
fn nested_against_orientation(rings: &[Ring]) -> bool {
    let boxes: Vec<Rect> = rings.iter().map(Ring::bounds).collect();
    let Some(index) = CellIndex::new(&boxes) else { return false };
    (0..rings.len()).any(|r| against_orientation(rings, &boxes, &index, r))
}

/// [`nested_against_orientation`] for ring `r`, with the rings' boxes and their cell index.
fn against_orientation(rings: &[Ring], boxes: &[Rect], index: &CellIndex, r: usize) -> bool {
    let ring = &rings[r];
    let midpoints = ring.edges().map(|e| Point::new(0.5 * e.a.x + 0.5 * e.b.x, 0.5 * e.a.y + 0.5 * e.b.y));
    let depth = ring.points.iter().copied().chain(midpoints).find_map(|p| {
        let (mut depth, mut on_ring) = (0usize, false);
        index.for_each_meeting(boxes, &Rect::new(p.x, p.y, p.x, p.y), |k| {
            if k != r && !on_ring {
                match ring_winding(p, &rings[k]) {
                    Some(w) => depth += usize::from(w != 0),
                    None => on_ring = true,
                }
            }
        });
        (!on_ring).then_some(depth)
    });
    depth.is_none_or(|d| (d % 2 == 0) != ring.runs_counter_clockwise())
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::Point;

    /// A square of side `side` at (`x`, `y`), counter-clockwise or clockwise.
    fn square(x: f64, y: f64, side: f64, ccw: bool) -> Ring {
        let mut p =
            vec![Point::new(x, y), Point::new(x + side, y), Point::new(x + side, y + side), Point::new(x, y + side)];
        if !ccw {
            p.reverse();
        }
        Ring::new(p)
    }

    #[test]
    fn rings_nested_or_crossing_near_rounding_are_broken() {
        let far = Polygons::from(square(1e15, 1e15, 64.0, true));
        let inside_same_way = [square(1e15, 1e15, 64.0, true), square(1e15 + 8.0, 1e15 + 8.0, 8.0, true)];
        assert!(broken_near_rounding(&far, &Polygons::default(), &inside_same_way, false));
        let crossing = [square(1e15, 1e15, 16.0, true), square(1e15 + 8.0, 1e15 + 8.0, 16.0, true)];
        assert!(broken_near_rounding(&far, &Polygons::default(), &crossing, false));
        let hole = [square(1e15, 1e15, 64.0, true), square(1e15 + 8.0, 1e15 + 8.0, 8.0, false)];
        assert!(!broken_near_rounding(&far, &Polygons::default(), &hole, false));
    }

    /// The distinct points of `rings` by y, then x, as the clean-up hands them over.
    fn by_y(rings: &[Ring]) -> Vec<Point> {
        let mut p: Vec<Point> = rings.iter().flat_map(|r| r.points.iter().copied()).collect();
        p.sort_by(|a, b| a.y.total_cmp(&b.y).then(a.x.total_cmp(&b.x)));
        p.dedup();
        p
    }

    /// Found by the `vatti` fuzz target (`fuzz/corpus/vatti/a9146f53…`): a union's two rings hold
    /// the crossings (-1.4, 1.7) and (-1.4000000000000004, 1.7), and the ring with the first has a
    /// vertex just across its own edge; no edge is short and no ring thin.
    #[test]
    fn vertices_a_few_ulps_apart_in_different_rings_are_near_rounding() {
        let input = Polygons::from(square(-8.0, 0.0, 16.0, true));
        let none = Polygons::default();
        let ring = |p: &[(f64, f64)]| Ring::new(p.iter().map(|&(x, y)| Point::new(x, y)).collect());
        let union = [
            ring(&[(-5.9, 4.7), (-1.4, 1.7), (-0.9000000000000004, 1.7), (-2.9000000000000004, 2.7)]),
            ring(&[(-1.4000000000000004, 1.7), (-7.9, 1.7), (0.09999999999999956, 0.7)]),
        ];
        assert!(!near_rounding(&input, &none, &union));
        assert!(vertices_near_rounding(&input, &none, &by_y(&union)));
        assert!(broken_near_rounding(&input, &none, &union, true));
        assert!(!broken_near_rounding(&input, &none, &union, false));
        // The same shapes a unit apart are far from rounding.
        let apart = [union[0].clone(), ring(&[(-0.4, 1.7), (-7.9, 1.7), (0.09999999999999956, 0.7)])];
        assert!(!vertices_near_rounding(&input, &none, &by_y(&apart)));
        // Near in y but in another row and far in x; near in x in the next row.
        let rows = |dx: f64| {
            [ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0)]), ring(&[(1.0 + dx, 1.0 + 1e-15), (5.0, 2.0), (5.0, 1.5)])]
        };
        assert!(!vertices_near_rounding(&input, &none, &by_y(&rows(1.0))));
        assert!(vertices_near_rounding(&input, &none, &by_y(&rows(1e-15))));
    }

    /// Found by the `vatti` fuzz target at 1e149: small triangles whose corners all touch other
    /// rings were counted as broken, and the snap fallback replaced a valid union.
    #[test]
    fn a_ring_whose_corners_all_touch_other_rings_is_placed_by_an_edge() {
        let ring = |p: &[(f64, f64)]| Ring::new(p.iter().map(|&(x, y)| Point::new(x, y)).collect());
        let rings = [
            ring(&[(0.0, 0.0), (2.0, 0.0), (1.0, 2.0)]),
            ring(&[(0.0, 0.0), (-1.0, 0.0), (-1.0, -1.0)]),
            ring(&[(2.0, 0.0), (3.0, -1.0), (3.0, 0.0)]),
            ring(&[(1.0, 2.0), (2.0, 3.0), (0.0, 3.0)]),
        ];
        let input = Polygons::from(square(-8.0, -8.0, 16.0, true));
        assert!(!broken_near_rounding(&input, &Polygons::default(), &rings, true));
        // The middle one turned clockwise, with nothing around it: broken.
        let mut turned = rings.clone();
        turned[0].points.reverse();
        assert!(broken_near_rounding(&input, &Polygons::default(), &turned, true));
    }

    /// From `grid` case 449 of seed 1 (20000 cases), xor, non-zero: three edges pass through
    /// (13⅓, 16⅚), and the ring's edge along one of them passes beside the rounded crossing of
    /// the other two, which is its own vertex: it crosses itself, with no vertex near another.
    #[test]
    fn a_ring_crossing_itself_at_near_crossings_is_found_there() {
        let ring = Ring::new(
            [
                (13.0, 18.0),
                (13.084444444444445, 16.817777777777778),
                (14.0, 16.875),
                (14.0, 17.0),
                (13.333333333333334, 16.833333333333332),
            ]
            .iter()
            .map(|&(x, y)| Point::new(x, y))
            .collect(),
        );
        let rings = [ring];
        let near =
            [Point::new(13.333333333333334, 16.833333333333332), Point::new(13.333333333333332, 16.833333333333332)];
        assert!(crossing_near(&rings, &near));
        // The same ring with the near crossings elsewhere is not looked at.
        let elsewhere = [Point::new(3.0, 3.0), Point::new(3.0000000000000004, 3.0)];
        assert!(!crossing_near(&rings, &elsewhere));
        assert!(!crossing_near(&rings, &[]));
        // A ring through the point without crossing itself passes.
        let square = [square(13.0, 16.0, 1.0, true)];
        assert!(!crossing_near(&square, &near));
    }

    #[test]
    fn outputs_far_above_rounding_are_not_checked() {
        let near = Polygons::from(square(0.0, 0.0, 64.0, true));
        let inside_same_way = [square(0.0, 0.0, 64.0, true), square(8.0, 8.0, 8.0, true)];
        assert!(!broken_near_rounding(&near, &Polygons::default(), &inside_same_way, false));
    }

    /// A ring of `n` vertices round a circle of radius `r` about (`cx`, `cy`), counter-clockwise.
    fn circle(cx: f64, cy: f64, r: f64, n: usize) -> Ring {
        let step = std::f64::consts::TAU / n as f64;
        Ring::new(
            (0..n).map(|i| Point::new(cx + r * (step * i as f64).cos(), cy + r * (step * i as f64).sin())).collect(),
        )
    }

    /// In an output too large for the whole check, a triangle thinner than an ulp (its middle
    /// vertex rounded across the line of the other two) that runs clockwise where it is an outer
    /// goes; such a triangle running counter-clockwise stays, as does a clockwise ring that is
    /// no sliver (a wrong-way ring of width is the whole check's to find, not this one's).
    #[test]
    fn slivers_turned_inside_out_are_dropped_from_large_outputs() {
        let (a, c) = (Point::new(200.0, 0.0), Point::new(248.0, 48.0));
        // The line from a to c passes (224, 24); an ulp above it, the ring runs clockwise.
        let flipped = Ring::new(vec![a, Point::new(224.0, 24.0f64.next_up()), c]);
        assert!(!flipped.runs_counter_clockwise() && flipped.signed_area() != 0.0);
        // Such a sliver running counter-clockwise (an ulp below the line), further right.
        let right = |p: Point| Point::new(p.x + 256.0, p.y);
        let right_way = Ring::new(vec![right(a), right(Point::new(224.0, 24.0f64.next_down())), right(c)]);
        assert!(right_way.runs_counter_clockwise());
        let wide = square(300.0, 0.0, 1.0, false);
        let mut rings = vec![circle(0.0, 0.0, 100.0, 2048), flipped.clone(), right_way.clone(), wide.clone()];
        drop_flipped_slivers(&mut rings);
        assert_eq!(rings.len(), 3);
        assert!(!rings.contains(&flipped));
        assert!(rings.contains(&right_way) && rings.contains(&wide));
        // Too small to skip the whole check: left as it is.
        let mut small = vec![square(0.0, 0.0, 100.0, true), flipped.clone()];
        drop_flipped_slivers(&mut small);
        assert_eq!(small.len(), 2);
    }
}
