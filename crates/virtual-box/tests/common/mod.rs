//! Test support: windows and segments from coordinates, and one segment's pieces as intervals.

#![allow(dead_code)]

use clip_core::{LineClipper, Point, Polygons, Ring, Segment, VisiblePiece};

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
