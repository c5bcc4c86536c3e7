//! The count of zero-width bridges in bridged output (docs/DESIGN.md): pairs of edges running
//! both ways along one stretch.

use core::convert::Infallible;

use clip_core::predicates::on_segment;
use clip_core::{CellIndex, Point, Polygons, Rect, Segment, SegmentIntersection, segment_intersection};

/// One edge of an output ring, with its box.
#[derive(Clone, Copy, Debug)]
struct RingEdge {
    segment: Segment,
    bounds: Rect,
}

fn ring_edges(p: &Polygons) -> Vec<RingEdge> {
    p.edges().map(|segment| RingEdge { segment, bounds: segment.bounds() }).collect()
}

/// Calls `visit` once on every pair of edges whose bounding boxes meet ([`CellIndex`]'s close
/// pairs). So output whose edges crowd along a curve (10^4-gons) or across a checkerboard costs
/// about linear time rather than quadratic.
fn for_each_close_pair(edges: &[RingEdge], mut visit: impl FnMut(&RingEdge, &RingEdge)) {
    let boxes: Vec<Rect> = edges.iter().map(|e| e.bounds).collect();
    let Some(index) = CellIndex::new(&boxes) else { return };
    let Ok(()) = index.try_for_each_close_pair(&boxes, |i, j| -> Result<(), Infallible> {
        visit(&edges[i], &edges[j]);
        Ok(())
    });
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
    for_each_close_pair(edges, |e, f| {
        count += usize::from(if snap > 0.0 {
            opposite_within(e.segment, f.segment, snap)
        } else {
            opposite_overlap(e.segment, f.segment)
        });
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
