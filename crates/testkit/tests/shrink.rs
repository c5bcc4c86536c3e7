//! The shrinker: smaller cases that still fail, the same every time, within its budget.

use clip_core::{Point, Polygons, Segment, WindowKind};
use clip_testkit::shrink::*;
use clip_testkit::workload::{line_case, polygon_case};

/// A "bug" that fires whenever some subject vertex lies inside the clip's bounding box and
/// the clip has a vertex left of x = 500.
fn fake_bug(s: &Polygons, c: &Polygons) -> bool {
    let b = c.bounds();
    s.points().any(|&p| b.contains(p)) && c.points().any(|p| p.x < 500.0)
}

#[test]
fn polygon_cases_shrink_and_keep_failing() {
    let mut shrunk_some = false;
    for i in 0..6 {
        let case = polygon_case("multi", 3, i, WindowKind::Any).unwrap();
        if !fake_bug(&case.subject, &case.clip) {
            continue;
        }
        let mut calls = 0;
        let (s, c) = shrink_polygons(&case.subject, &case.clip, |s, c| {
            calls += 1;
            fake_bug(s, c)
        });
        assert!(fake_bug(&s, &c));
        assert!(calls <= MAX_TRIES);
        assert!(s.vertex_count() <= case.subject.vertex_count() && c.vertex_count() <= case.clip.vertex_count());
        // One subject triangle is all this bug needs; the clip may keep a second ring for
        // its bounding box, but every ring is down to a triangle.
        assert_eq!(s.rings.len(), 1, "{s:?}");
        assert!(c.rings.len() <= 2, "{c:?}");
        assert!(s.rings.iter().chain(&c.rings).all(|r| r.len() == 3), "{s:?} {c:?}");
        // Deterministic.
        assert_eq!(shrink_polygons(&case.subject, &case.clip, fake_bug), (s, c));
        shrunk_some = true;
    }
    assert!(shrunk_some);
}

#[test]
fn coordinates_get_snapped() {
    let case = polygon_case("star", 1, 0, WindowKind::Any).unwrap();
    let (s, _) = shrink_polygons(&case.subject, &case.clip, |s, _| s.signed_area() > 1000.0);
    assert!(s.points().all(|p| p.x.fract() == 0.0 && p.y.fract() == 0.0), "{s:?}");
}

#[test]
fn a_case_that_stops_failing_is_returned_whole() {
    let case = polygon_case("star", 1, 0, WindowKind::Any).unwrap();
    let (s, c) = shrink_polygons(&case.subject, &case.clip, |_, _| false);
    assert_eq!((s, c), (case.subject, case.clip));
}

#[test]
fn segment_batches_shrink() {
    let case = line_case("wang-t4", 1, 0, WindowKind::Any, 500).unwrap();
    // A "bug" on any segment crossing the vertical line x = 400 above y = 300.
    let bad = |s: &Segment| (s.a.x - 400.0) * (s.b.x - 400.0) < 0.0 && s.a.y.min(s.b.y) > 300.0;
    assert!(case.segments.iter().any(bad));
    let (w, segs) = shrink_segments(&case.window, &case.segments, |_, s| s.iter().any(bad));
    assert_eq!(segs.len(), 1);
    assert!(bad(&segs[0]));
    assert_eq!(w.vertex_count(), 3);
    let p: Point = segs[0].a;
    assert!(p.x.fract() == 0.0 && p.y.fract() == 0.0);
}

#[test]
fn the_budget_bounds_the_work() {
    let case = polygon_case("scribble", 1, 0, WindowKind::Any).unwrap();
    let mut calls = 0;
    // Fails on every other call: the shrinker must still stop.
    shrink_polygons(&case.subject, &case.clip, |_, _| {
        calls += 1;
        calls % 2 == 0
    });
    assert!(calls <= MAX_TRIES);
}
