//! The shrinker: smaller cases that still fail, the same every time, within its budget.

use clip_core::{Point, Polygons, Segment, WindowKind};
use clip_testkit::shrink::*;
use clip_testkit::workload::{line_case, polygon_case};

/// A "bug" that fires whenever some subject vertex lies inside the clip's bounding box and
/// the clip has a vertex left of x = 500.
fn fake_bug(s: &Polygons, c: &Polygons) -> Option<()> {
    let b = c.bounds();
    (s.points().any(|&p| b.contains(p)) && c.points().any(|p| p.x < 500.0)).then_some(())
}

#[test]
fn polygon_cases_shrink_and_keep_failing() {
    let mut shrunk_some = false;
    for i in 0..6 {
        let case = polygon_case("multi", 3, i, WindowKind::Any).unwrap();
        if fake_bug(&case.subject, &case.clip).is_none() {
            continue;
        }
        let mut calls = 0;
        let (s, c) = shrink_polygons(&case.subject, &case.clip, |s, c| {
            calls += 1;
            fake_bug(s, c)
        });
        assert!(fake_bug(&s, &c).is_some());
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
    let (s, _) = shrink_polygons(&case.subject, &case.clip, |s, _| (s.signed_area() > 1000.0).then_some(()));
    assert!(s.points().all(|p| p.x.fract() == 0.0 && p.y.fract() == 0.0), "{s:?}");
}

#[test]
fn a_case_that_stops_failing_is_returned_whole() {
    let case = polygon_case("star", 1, 0, WindowKind::Any).unwrap();
    let (s, c) = shrink_polygons(&case.subject, &case.clip, |_, _| None::<()>);
    assert_eq!((s, c), (case.subject, case.clip));
}

#[test]
fn segment_batches_shrink() {
    let case = line_case("wang-t4", 1, 0, WindowKind::Any, 500).unwrap();
    // A "bug" on any segment crossing the vertical line x = 400 above y = 300.
    let bad = |s: &Segment| (s.a.x - 400.0) * (s.b.x - 400.0) < 0.0 && s.a.y.min(s.b.y) > 300.0;
    assert!(case.segments.iter().any(bad));
    let (w, segs) = shrink_segments(&case.window, &case.segments, |_, s| s.iter().any(bad).then_some(()));
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
        (calls % 2 == 1).then_some(())
    });
    assert!(calls <= MAX_TRIES);
}

/// A hang found on a large case must not "shrink" to a crash that a smaller case shows instead:
/// the shrunk case fails the way the original did (issue 28).
#[test]
fn a_shrunk_case_fails_the_same_way_as_the_original() {
    #[derive(Debug, PartialEq)]
    enum How {
        Hang,
        Crash,
    }
    let case = polygon_case("multi", 3, 0, WindowKind::Any).unwrap();
    // Hangs while the subject has more than 8 vertices, crashes below: every step down from the
    // original that keeps failing somehow ends in the crash.
    let how = |s: &Polygons, _: &Polygons| Some(if s.vertex_count() > 8 { How::Hang } else { How::Crash });
    assert_eq!(how(&case.subject, &case.clip), Some(How::Hang), "{}", case.subject.vertex_count());
    let (s, c) = shrink_polygons(&case.subject, &case.clip, how);
    assert_eq!(how(&s, &c), Some(How::Hang), "{} vertices", s.vertex_count());
    assert!(s.vertex_count() < case.subject.vertex_count(), "it still shrinks");
}

/// A predicate as slow as an external clipper's time-out: once the time limit has passed, no
/// call is begun, and the result says it stopped early (a failing case, smaller or whole).
#[test]
fn the_time_limit_stops_calls_and_says_so() {
    use std::time::Duration;
    let case = polygon_case("multi", 3, 0, WindowKind::Any).unwrap();
    let mut calls = 0;
    let limit = ShrinkLimit { tries: MAX_TRIES, time: Some(Duration::from_millis(30)) };
    let ((s, c), end) = shrink_polygons_within(&case.subject, &case.clip, limit, |_, _| {
        calls += 1;
        std::thread::sleep(Duration::from_millis(20));
        Some(())
    });
    assert_eq!(end, ShrinkEnd::OutOfTime);
    // Each call takes at least 20 ms and none begins after 30 ms: the first, and a second only if
    // the first's sleep ended in time.
    assert!((1..=2).contains(&calls), "{calls} calls");
    assert!(s.vertex_count() <= case.subject.vertex_count() && c.vertex_count() <= case.clip.vertex_count());

    let mut calls = 0;
    let limit = ShrinkLimit { tries: 5, time: None };
    let (_, end) = shrink_polygons_within(&case.subject, &case.clip, limit, |_, _| {
        calls += 1;
        Some(())
    });
    assert_eq!((end, calls), (ShrinkEnd::OutOfTries, 5));
    let (_, end) = shrink_polygons_within(&case.subject, &case.clip, ShrinkLimit::default(), fake_bug);
    assert_eq!(end, ShrinkEnd::Smallest);
}
