//! The form conventional output must have (docs/DESIGN.md): finite, no repeated consecutive vertex,
//! no zero-area ring, no crossings, outers counter-clockwise and holes clockwise by nesting
//! depth; and the count of zero-width bridges in bridged output.

use super::PolygonFailure;
use clip_core::predicates::{Orientation, on_segment, orient};
use clip_core::{
    CellIndex, Point, Polygons, Rect, Ring, Segment, SegmentIntersection, ring_winding, segment_intersection,
};

/// One edge of an output ring, with where it comes from.
#[derive(Clone, Copy, Debug)]
struct RingEdge {
    ring: usize,
    index: usize,
    segment: Segment,
    bounds: Rect,
}

fn ring_edges(p: &Polygons) -> Vec<RingEdge> {
    p.rings
        .iter()
        .enumerate()
        .flat_map(|(ring, r)| {
            r.edges().enumerate().map(move |(index, segment)| RingEdge {
                ring,
                index,
                segment,
                bounds: segment.bounds(),
            })
        })
        .collect()
}

/// Calls `visit` once on every pair of edges whose bounding boxes meet, each pair in the one
/// cell of a [`CellIndex`] that holds the lower-left corner of the overlap of their boxes. So
/// output whose edges crowd along a curve (10^4-gons) or across a checkerboard costs about
/// linear time rather than quadratic.
fn for_each_close_pair(
    edges: &[RingEdge],
    mut visit: impl FnMut(&RingEdge, &RingEdge) -> Result<(), PolygonFailure>,
) -> Result<(), PolygonFailure> {
    let boxes: Vec<Rect> = edges.iter().map(|e| e.bounds).collect();
    let Some(index) = CellIndex::new(&boxes) else { return Ok(()) };
    index.try_for_each_close_pair(&boxes, |i, j| visit(&edges[i], &edges[j]))
}

/// What [`check_valid_output`] would visit on `output`: the edge pairs it tests (pairs sharing a
/// cell of the [`CellIndex`]) plus the edges the nesting count files and meets (one entry per
/// edge and height bucket it spans, and each ring's bucket). Near linear for output whose edges
/// are short beside its extent; quadratic where many long edges share cells or heights (nested
/// squares, combs), which is why a caller with a time budget asks first. Counted without testing
/// a pair, in O(n log n).
pub fn check_valid_work(output: &Polygons) -> u64 {
    let edges = ring_edges(output);
    let boxes: Vec<Rect> = edges.iter().map(|e| e.bounds).collect();
    let Some(index) = CellIndex::new(&boxes) else { return 0 };
    let pairs: u64 = index.entries().chunk_by(|a, b| a.0 == b.0).map(|c| (c.len() as u64).pow(2) / 2).sum();
    let heights = HeightBuckets::new(output, edges.len());
    // Edges per bucket, from +1 where each edge's span starts and -1 past where it ends.
    let mut steps = vec![0i64; heights.count + 1];
    let mut filed = 0u64;
    for e in &edges {
        let (lo, hi) = (heights.bucket(e.bounds.min.y), heights.bucket(e.bounds.max.y));
        steps[lo] += 1;
        steps[hi + 1] -= 1;
        filed += (hi - lo + 1) as u64;
    }
    let per_bucket: Vec<u64> = steps
        .iter()
        .scan(0i64, |running, step| {
            *running += step;
            Some(*running as u64)
        })
        .collect();
    let met: u64 = output.rings.iter().filter_map(|r| r.points.first()).map(|p| per_bucket[heights.bucket(p.y)]).sum();
    pairs + filed + met
}

/// The nesting count's height buckets: about √edges (at most 1024) bands of equal height.
struct HeightBuckets {
    min_y: f64,
    height: f64,
    count: usize,
}

impl HeightBuckets {
    fn new(output: &Polygons, edges: usize) -> HeightBuckets {
        let b = output.bounds();
        let count = ((edges as f64).sqrt() as usize).clamp(1, 1024);
        let height = if b.height() > 0.0 { b.height() / count as f64 } else { 1.0 };
        HeightBuckets { min_y: b.min.y, height, count }
    }

    /// The bucket holding height `y` (clamped).
    fn bucket(&self, y: f64) -> usize {
        let k = ((y - self.min_y) / self.height).floor();
        if k > 0.0 { (k as usize).min(self.count - 1) } else { 0 }
    }
}

/// Checks conventional output: every coordinate finite; every ring of at least 3 vertices, no
/// repeated consecutive vertex, not all on one line, no zero-width spike (an edge folding back
/// over the previous one); no two edges crossing, none overlapping another of its own ring, and
/// no two rings (or two passes of one ring) crossing at a shared point; outer rings
/// counter-clockwise and holes clockwise by nesting depth (the number of rings around them).
///
/// Rings may touch at points without crossing, and different rings may share an edge, running it
/// in opposite directions (the same direction would overlap their insides). Exact:
/// see [`check_valid_output_within`] for output whose vertices were rounded.
pub fn check_valid_output(output: &Polygons) -> Result<(), PolygonFailure> {
    check_valid_output_within(output, 0.0)
}

/// [`check_valid_output`], except that two edges crossing within `snap` of an end point of
/// either count as touching there: a vertex rounded (or snapped to a peer's integer grid) onto
/// the wrong side of an edge it should touch. [`super::check_polygon_result`] uses the case's
/// relative tolerance times its extent.
pub fn check_valid_output_within(output: &Polygons, snap: f64) -> Result<(), PolygonFailure> {
    check_valid(output, snap, None)
}

/// [`check_valid_output_within`] for a result computed from `inputs`, which
/// [`super::check_polygon_result`] uses: a ring that rounding made (one with a vertex in neither
/// input, or an edge along no input edge) and whose area is within `snap` times its perimeter may
/// run either way. Rounding its vertices can turn such a ring inside out, and its area is within
/// the region tolerance anyway. (Found by the `vatti` fuzz target: a self-crossing quadrilateral
/// of area 0.008 at 1e15, where an ulp is 0.125, gave a triangle of rounded crossings running
/// clockwise; at 1e9 crossings rounded onto input vertices made a clockwise triangle with an edge
/// along no input edge.) A ring made of input vertices and edges must turn the right way, however
/// thin.
pub fn check_valid_result_within(output: &Polygons, snap: f64, inputs: [&Polygons; 2]) -> Result<(), PolygonFailure> {
    check_valid(output, snap, Some(inputs))
}

fn check_valid(output: &Polygons, snap: f64, inputs: Option<[&Polygons; 2]>) -> Result<(), PolygonFailure> {
    for (r, ring) in output.rings.iter().enumerate() {
        check_ring_form(r, ring)?;
    }
    let edges = ring_edges(output);
    for_each_close_pair(&edges, |e, f| check_pair(output, e, f, snap))?;
    check_orientation(output, snap, inputs)
}

/// True when `ring` has a vertex in neither input or an edge along no input edge, and an area
/// within `snap` times its perimeter.
fn rounding_may_invert(ring: &Ring, snap: f64, inputs: [&Polygons; 2], input_points: &mut Vec<(u64, u64)>) -> bool {
    let perimeter: f64 = ring.edges().map(|e| e.a.distance(e.b)).sum();
    if ring.signed_area().abs() > snap * perimeter {
        return false;
    }
    let key = |p: &Point| ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits());
    if input_points.is_empty() {
        input_points.extend(inputs.iter().flat_map(|p| p.points()).map(key));
        input_points.sort_unstable();
    }
    let along_input = |e: Segment| {
        inputs.iter().flat_map(|p| p.edges()).any(|f| {
            orient(f.a, f.b, e.a) == Orientation::Collinear
                && orient(f.a, f.b, e.b) == Orientation::Collinear
                && f.bounds().contains(e.a)
                && f.bounds().contains(e.b)
        })
    };
    ring.points.iter().any(|p| input_points.binary_search(&key(p)).is_err()) || !ring.edges().all(along_input)
}

fn invalid(message: String) -> Result<(), PolygonFailure> {
    Err(PolygonFailure::Invalid(message))
}

fn check_ring_form(r: usize, ring: &Ring) -> Result<(), PolygonFailure> {
    let p = &ring.points;
    if let Some(v) = p.iter().position(|q| !q.is_finite()) {
        return invalid(format!("ring {r} vertex {v} is not finite ({:?})", p[v]));
    }
    if p.len() < 3 {
        return invalid(format!("ring {r} has {} vertices", p.len()));
    }
    let first_other = p.iter().find(|&&q| q != p[0]).copied().unwrap_or(p[0]);
    if p.iter().all(|&q| orient(p[0], first_other, q) == Orientation::Collinear) {
        return invalid(format!("ring {r} has zero area (all its vertices are collinear)"));
    }
    let n = p.len();
    for i in 0..n {
        let (a, b, c) = (p[i], p[(i + 1) % n], p[(i + 2) % n]);
        if a == b {
            return invalid(format!("ring {r} repeats vertex {i} ({}, {})", a.x, a.y));
        }
        if orient(a, b, c) == Orientation::Collinear && folds_back(a, b, c) {
            return invalid(format!("ring {r} has a zero-width spike at vertex {} ({}, {})", (i + 1) % n, b.x, b.y));
        }
    }
    Ok(())
}

/// For collinear `a, b, c`: true when `c` lies on the same side of `b` as `a` (the path turns
/// back at `b`). Exact: compares coordinates.
fn folds_back(a: Point, b: Point, c: Point) -> bool {
    let side = |q: Point| if q.x != b.x { (q.x > b.x) as i8 * 2 - 1 } else { (q.y > b.y) as i8 * 2 - 1 };
    c != b && side(a) == side(c)
}

fn adjacent(output: &Polygons, e: &RingEdge, f: &RingEdge) -> bool {
    if e.ring != f.ring {
        return false;
    }
    let n = output.rings[e.ring].len();
    let (i, j) = (e.index.min(f.index), e.index.max(f.index));
    j == i + 1 || (i == 0 && j == n - 1)
}

fn check_pair(output: &Polygons, e: &RingEdge, f: &RingEdge, snap: f64) -> Result<(), PolygonFailure> {
    if adjacent(output, e, f) {
        return Ok(());
    }
    let at = |p: Point| format!("({}, {})", p.x, p.y);
    match segment_intersection(e.segment, f.segment) {
        SegmentIntersection::None => Ok(()),
        SegmentIntersection::Crossing(p) if near_an_end(p, e.segment, f.segment, snap) => Ok(()),
        SegmentIntersection::Crossing(p) => {
            invalid(format!("ring {} edge {} crosses ring {} edge {} near {}", e.ring, e.index, f.ring, f.index, at(p)))
        }
        // An overlap no longer than `snap` is a rounded vertex an ulp past where it belongs.
        SegmentIntersection::Overlap(s) if e.ring == f.ring && s.a.distance(s.b) > snap => invalid(format!(
            "ring {} overlaps itself along {} - {} (edges {} and {})",
            e.ring,
            at(s.a),
            at(s.b),
            e.index,
            f.index
        )),
        // Rings sharing an edge run it both ways; running it the same way puts their insides on
        // one side (winding 2, or a hole outside its outer).
        SegmentIntersection::Overlap(s) if !opposite_overlap(e.segment, f.segment) => invalid(format!(
            "rings {} and {} run the same way along {} - {} (edges {} and {}): their insides overlap",
            e.ring,
            f.ring,
            at(s.a),
            at(s.b),
            e.index,
            f.index
        )),
        SegmentIntersection::Overlap(_) => Ok(()),
        SegmentIntersection::Touching(p) => {
            let (pe, pf) = (passage(output, e, p), passage(output, f, p));
            match (side(p, pe, pf.0, snap), side(p, pe, pf.1, snap)) {
                (Some(x), Some(y)) if x != y => invalid(format!(
                    "ring {} (edge {}) crosses ring {} (edge {}) at the shared point {}",
                    e.ring,
                    e.index,
                    f.ring,
                    f.index,
                    at(p)
                )),
                _ => Ok(()),
            }
        }
    }
}

/// Whether the crossing at `p` of `e` and `f` goes away when an end point moves by at most
/// `snap`: an end within `snap` of the crossing, or of the other edge. (At a shallow angle a
/// rounded end a snap away from the other edge crosses it farther than a snap from the end: found
/// by the `vatti` fuzz target at 1e15.)
fn near_an_end(p: Point, e: Segment, f: Segment, snap: f64) -> bool {
    snap > 0.0
        && ([e.a, e.b, f.a, f.b].iter().any(|&q| p.distance(q) <= snap)
            || [e.a, e.b].iter().any(|&q| distance_to_segment(q, f) <= snap)
            || [f.a, f.b].iter().any(|&q| distance_to_segment(q, e) <= snap))
}

fn distance_to_segment(q: Point, s: Segment) -> f64 {
    let d = s.b - s.a;
    let len2 = d.dot(d);
    if len2 == 0.0 {
        return q.distance(s.a);
    }
    let t = ((q - s.a).dot(d) / len2).clamp(0.0, 1.0);
    q.distance(s.a.lerp(s.b, t))
}

/// The ring's way through `p` on edge `e`: the points it comes from and goes to.
fn passage(output: &Polygons, e: &RingEdge, p: Point) -> (Point, Point) {
    let pts = &output.rings[e.ring].points;
    let n = pts.len();
    if p == e.segment.a {
        (pts[(e.index + n - 1) % n], e.segment.b)
    } else if p == e.segment.b {
        (e.segment.a, pts[(e.index + 2) % n])
    } else {
        (e.segment.a, e.segment.b)
    }
}

/// Which side of the path `u -> p -> v` the ray from `p` towards `q` leaves on: `Some(true)`
/// inside the counter-clockwise turn from ray `pu` to ray `pv`, `Some(false)` outside, `None`
/// when it runs along either ray (exactly, or within `snap`: `p` may be a rounded point) or the
/// path folds back on itself.
fn side(p: Point, (u, v): (Point, Point), q: Point, snap: f64) -> Option<bool> {
    if q == p || runs_along(p, u, q, snap) || runs_along(p, v, q, snap) {
        return None;
    }
    let ccw = |a: Point, b: Point| orient(p, a, b) == Orientation::CounterClockwise;
    match orient(p, u, v) {
        Orientation::CounterClockwise => Some(ccw(u, q) && ccw(q, v)),
        Orientation::Clockwise => Some(!(ccw(v, q) && ccw(q, u))),
        Orientation::Collinear if on_segment(p, Segment::new(u, v)) => Some(ccw(u, q)),
        Orientation::Collinear => None,
    }
}

/// True when the rays from `p` towards `r` and towards `q` run the same way: exactly, or with
/// the nearer of the two points within `snap` of the line to the farther.
fn runs_along(p: Point, r: Point, q: Point, snap: f64) -> bool {
    if snap == 0.0 {
        return orient(p, r, q) == Orientation::Collinear && !on_segment(p, Segment::new(r, q));
    }
    let (a, b) = (r - p, q - p);
    if a.dot(b) <= 0.0 {
        return false;
    }
    let (near, far) = if a.dot(a) <= b.dot(b) { (a, b) } else { (b, a) };
    let cross = far.x * near.y - far.y * near.x;
    cross.abs() <= snap * far.dot(far).sqrt()
}

/// Outer rings (even depth) counter-clockwise, holes (odd depth) clockwise.
fn check_orientation(output: &Polygons, snap: f64, inputs: Option<[&Polygons; 2]>) -> Result<(), PolygonFailure> {
    let mut input_points = Vec::new();
    for (r, depth) in nesting_depths(output, snap).into_iter().enumerate() {
        let ring = &output.rings[r];
        let area = ring.signed_area();
        let want_ccw = depth % 2 == 0;
        let ccw = ring.runs_counter_clockwise();
        if ccw != want_ccw && !inputs.is_some_and(|i| rounding_may_invert(ring, snap, i, &mut input_points)) {
            let role = if want_ccw { "an outer ring (depth" } else { "a hole (depth" };
            let turn = if ccw { "counter-clockwise" } else { "clockwise" };
            return invalid(format!("ring {r} is {role} {depth}) but runs {turn} (signed area {area})"));
        }
    }
    Ok(())
}

/// For each ring, how many other rings hold it (rings that do not cross). One exact winding
/// count per ring, at its first vertex, against every other ring at once: the edges are
/// bucketed by height, so the vertex meets only the edges at its height. Where the vertex lies
/// on another ring, or within `snap` of it (they touch there, up to a rounded vertex), that pair
/// is decided by [`ring_inside`].
fn nesting_depths(output: &Polygons, snap: f64) -> Vec<usize> {
    let rings = &output.rings;
    let edges: Vec<(Point, Point, usize)> =
        rings.iter().enumerate().flat_map(|(r, ring)| ring.edges().map(move |e| (e.a, e.b, r))).collect();
    let heights = HeightBuckets::new(output, edges.len());
    let bucket_of = |y: f64| heights.bucket(y);
    let mut buckets: Vec<Vec<u32>> = vec![Vec::new(); heights.count];
    for (i, &(p, q, _)) in edges.iter().enumerate() {
        for bucket in &mut buckets[bucket_of(p.y.min(q.y))..=bucket_of(p.y.max(q.y))] {
            bucket.push(i as u32);
        }
    }
    let mut winding = vec![0i32; rings.len()];
    let mut touching = vec![false; rings.len()];
    let mut met: Vec<usize> = Vec::new();
    let mut near: Vec<u32> = Vec::new();
    // A ring can lie only inside rings whose box (grown by `snap`) holds its own box: rings that
    // have none (every square of a checkerboard) are outers without a ray cast.
    let grown: Vec<Rect> = rings.iter().map(|r| r.bounds().expanded(snap)).collect();
    let boxes = CellIndex::new(&grown);
    let may_hold = |r: usize, p: Point| {
        let own = rings[r].bounds();
        boxes.as_ref().is_some_and(|index| index.at(p).any(|s| s != r && grown[s].contains_rect(&own)))
    };
    let mut depths = Vec::with_capacity(rings.len());
    for (r, ring) in rings.iter().enumerate() {
        let Some(&p) = ring.points.first() else {
            depths.push(0);
            continue;
        };
        if !may_hold(r, p) {
            depths.push(0);
            continue;
        }
        // The edges at the vertex's height, and within `snap` of it (one bucket but rarely).
        let (lo, hi) = (bucket_of(p.y - snap), bucket_of(p.y + snap));
        let candidates: &[u32] = if lo == hi {
            &buckets[lo]
        } else {
            near.clear();
            near.extend(buckets[lo..=hi].iter().flatten());
            near.sort_unstable();
            near.dedup();
            &near
        };
        for &i in candidates {
            let (a, c, s) = edges[i as usize];
            let (bottom, top) = (a.y.min(c.y), a.y.max(c.y));
            if s == r || p.y < bottom - snap || p.y > top + snap || p.x > a.x.max(c.x) + snap {
                continue;
            }
            met.push(s);
            if within(p, Segment::new(a, c), snap) {
                touching[s] = true;
            } else if p.y < bottom || p.y > top || p.x > a.x.max(c.x) {
                continue;
            } else if a.y <= p.y {
                if c.y > p.y && orient(a, c, p) == Orientation::CounterClockwise {
                    winding[s] += 1;
                }
            } else if c.y <= p.y && orient(a, c, p) == Orientation::Clockwise {
                winding[s] -= 1;
            }
        }
        met.sort_unstable();
        met.dedup();
        let depth = met
            .iter()
            .filter(|&&s| if touching[s] { ring_inside(ring, &rings[s], snap) } else { winding[s] != 0 })
            .count();
        depths.push(depth);
        for &s in &met {
            winding[s] = 0;
            touching[s] = false;
        }
        met.clear();
    }
    depths
}

/// True when `p` is on `e` (exactly, when `snap` is 0) or within `snap` of it.
fn within(p: Point, e: Segment, snap: f64) -> bool {
    if snap == 0.0 {
        return on_segment(p, e);
    }
    let (dx, dy) = (e.b.x - e.a.x, e.b.y - e.a.y);
    if p.x < e.a.x.min(e.b.x) - snap || p.x > e.a.x.max(e.b.x) + snap {
        return false;
    }
    let length2 = dx * dx + dy * dy;
    let t = if length2 > 0.0 { (((p.x - e.a.x) * dx + (p.y - e.a.y) * dy) / length2).clamp(0.0, 1.0) } else { 0.0 };
    let (ex, ey) = (p.x - (e.a.x + t * dx), p.y - (e.a.y + t * dy));
    ex * ex + ey * ey <= snap * snap
}

/// True when ring `r` lies inside ring `s` (rings that do not cross): decided at the first
/// vertex or edge midpoint of `r` that is neither on `s` nor within `snap` of it; for a ring
/// that lies wholly within `snap` of `s` (a rounding sliver), at the first one not exactly on it.
fn ring_inside(r: &Ring, s: &Ring, snap: f64) -> bool {
    let probes = || r.points.iter().copied().chain(r.edges().map(|e| e.at(0.5)));
    let clear = probes().filter(|&p| snap == 0.0 || !s.edges().any(|e| within(p, e, snap)));
    clear.chain(probes()).find_map(|p| ring_winding(p, s)).is_some_and(|w| w != 0)
}

/// The number of zero-width bridges in an output: pairs of edges (of any rings) that overlap
/// along a positive length while running in opposite directions. Such pairs enclose no area;
/// Sutherland-Hodgman leaves them along the window when a concave result falls apart.
pub fn bridge_count(output: &Polygons) -> usize {
    bridge_count_within(output, 0.0)
}

/// [`bridge_count`], where edges within `snap` of each other's line count as overlapping: on a
/// slanted window side, the two edges of a bridge end at points rounded separately, so they are
/// collinear only to within rounding. With `snap` 0 the overlap is exact.
pub fn bridge_count_within(output: &Polygons, snap: f64) -> usize {
    count_opposite_pairs(&ring_edges(output), snap)
}

/// How many pairs of `edges` overlap running in opposite directions (within `snap` when positive).
fn count_opposite_pairs(edges: &[RingEdge], snap: f64) -> usize {
    let mut count = 0;
    let _ = for_each_close_pair(edges, |e, f| {
        count += usize::from(if snap > 0.0 {
            opposite_within(e.segment, f.segment, snap)
        } else {
            opposite_overlap(e.segment, f.segment)
        });
        Ok(())
    });
    count
}

/// The bridges of docs/DESIGN.md: [`bridge_count_within`] counted only among the output edges
/// that run along a side of `window` (both ends on it, or within `snap` of it). Zero-width spikes
/// and edges running both ways that a subject brings inside the window are its own, not the
/// clipper's, and are not counted.
pub fn bridge_count_along(output: &Polygons, window: &Polygons, snap: f64) -> usize {
    let on_a_side = |e: &RingEdge| window.edges().any(|w| within(e.segment.a, w, snap) && within(e.segment.b, w, snap));
    let edges: Vec<RingEdge> = ring_edges(output).into_iter().filter(on_a_side).collect();
    count_opposite_pairs(&edges, snap)
}

/// Exactly collinear, overlapping along a positive length, in opposite directions.
fn opposite_overlap(e: Segment, f: Segment) -> bool {
    if let SegmentIntersection::Overlap(_) = segment_intersection(e, f) {
        let (d, g) = (e.b - e.a, f.b - f.a);
        // Collinear, so the signs along either axis agree; use the larger component.
        if d.x.abs() >= d.y.abs() { (d.x > 0.0) != (g.x > 0.0) } else { (d.y > 0.0) != (g.y > 0.0) }
    } else {
        false
    }
}

/// Opposite directions, `f` within `snap` of `e`'s line, and overlapping along it by more than
/// `snap`.
fn opposite_within(e: Segment, f: Segment, snap: f64) -> bool {
    let d = e.b - e.a;
    let length = (d.x * d.x + d.y * d.y).sqrt();
    if length <= snap {
        return false;
    }
    let (ux, uy) = (d.x / length, d.y / length);
    let along = |p: Point| (p.x - e.a.x) * ux + (p.y - e.a.y) * uy;
    let across = |p: Point| ((p.x - e.a.x) * uy - (p.y - e.a.y) * ux).abs();
    let (fa, fb) = (along(f.a), along(f.b));
    let overlap = fa.max(fb).min(length) - fa.min(fb).max(0.0);
    fb < fa && overlap > snap && across(f.a) <= snap && across(f.b) <= snap
}
