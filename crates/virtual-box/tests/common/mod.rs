//! Test support: running a line clipper on one segment, and an interim exact oracle (to be
//! replaced by clip-testkit's `visible_intervals` when it lands).

#![allow(dead_code)]

use clip_core::{
    FillRule, LineClipper, Location, Point, Polygons, Ring, Segment, SegmentIntersection, VisiblePiece, locate,
    segment_intersection,
};

/// A ring from coordinate pairs.
pub fn ring(points: &[(f64, f64)]) -> Ring {
    Ring::from(points)
}

/// A window of one ring.
pub fn window(points: &[(f64, f64)]) -> Polygons {
    Polygons::from(ring(points))
}

/// The same window with every ring walked the other way.
pub fn reversed(w: &Polygons) -> Polygons {
    Polygons::new(w.rings.iter().map(Ring::reversed).collect())
}

/// A segment from coordinates.
pub fn seg(ax: f64, ay: f64, bx: f64, by: f64) -> Segment {
    Segment::new(Point::new(ax, ay), Point::new(bx, by))
}

/// The pieces of every segment as parameter intervals, checking that each piece lies on its
/// segment's line and runs in its direction.
pub fn intervals(segments: &[Segment], pieces: &[VisiblePiece]) -> Vec<Vec<(f64, f64)>> {
    let mut all = vec![Vec::new(); segments.len()];
    for p in pieces {
        let s = segments[p.segment];
        let (ta, tb) = (s.param_of(p.piece.a), s.param_of(p.piece.b));
        assert!(ta < tb, "piece {p:?} of {s:?} is reversed or empty");
        all[p.segment].push((ta, tb));
    }
    all
}

/// Clips one segment and returns its visible parameter intervals.
pub fn clip(clipper: &dyn LineClipper, w: &Polygons, s: Segment) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    clipper.prepare(w).expect("window accepted").clip_batch(&[s], &mut out).expect("finite segment");
    intervals(&[s], &out).pop().unwrap_or_default()
}

/// Asserts two interval lists are equal within `tol`.
pub fn assert_intervals(got: &[(f64, f64)], expected: &[(f64, f64)], tol: f64, what: &str) {
    let close = got.len() == expected.len()
        && got.iter().zip(expected).all(|(g, e)| (g.0 - e.0).abs() <= tol && (g.1 - e.1).abs() <= tol);
    assert!(close, "{what}: got {got:?}, expected {expected:?}");
}

/// Exact closed-set visible intervals of `s` in `w` (even-odd): the cut parameters of every
/// segment/edge incidence, each sub-interval inside when it lies along an edge or its midpoint
/// is not outside; then merged, zero-length ones dropped.
pub fn oracle(w: &Polygons, s: Segment) -> Vec<(f64, f64)> {
    if s.is_degenerate() {
        return Vec::new();
    }
    let mut cuts = vec![0.0, 1.0];
    let mut along = Vec::new();
    for e in w.edges() {
        match segment_intersection(s, e) {
            SegmentIntersection::Crossing(p) | SegmentIntersection::Touching(p) => cuts.push(s.param_of(p)),
            SegmentIntersection::Overlap(o) => {
                let (t0, t1) = (s.param_of(o.a), s.param_of(o.b));
                cuts.extend([t0, t1]);
                along.push((t0.min(t1), t0.max(t1)));
            }
            SegmentIntersection::None => {}
        }
    }
    let mut cuts: Vec<f64> = cuts.into_iter().map(|t| t.clamp(0.0, 1.0)).collect();
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let mut result: Vec<(f64, f64)> = Vec::new();
    for pair in cuts.windows(2) {
        let (t0, t1) = (pair[0], pair[1]);
        let mid = 0.5 * (t0 + t1);
        let on_edge = along.iter().any(|&(a, b)| a <= mid && mid <= b);
        if on_edge || locate(s.at(mid), w, FillRule::EvenOdd) != Location::Outside {
            match result.last_mut() {
                Some(last) if last.1 == t0 => last.1 = t1,
                _ => result.push((t0, t1)),
            }
        }
    }
    result
}
