//! Randomized agreement of the indexed clipper with the exact line oracle and with Liu, on the
//! `wang-t4`, `lines-degenerate` and `lines-large` workloads and on small integer grids.

use clip_core::{LineClipper, Point, Polygons, Ring, Segment, WindowKind};
use clip_cyrus_beck::Liu;
use clip_line_index::{LineIndex, PreparedLineIndex};
use clip_testkit::line_probe::assert_batch_matches_oracle;
use clip_testkit::workload::line_case;
use proptest::prelude::*;

/// The indexed clipper passes the oracle, and shows a piece on exactly the segments Liu does,
/// with the same number of pieces.
fn check(w: &Polygons, segments: &[Segment], what: &str) {
    assert_batch_matches_oracle(&LineIndex, w, segments, what);
    let (mut ours, mut liu) = (Vec::new(), Vec::new());
    LineIndex.prepare(w).unwrap().clip_batch(segments, &mut ours).unwrap();
    Liu.prepare(w).unwrap().clip_batch(segments, &mut liu).unwrap();
    let counts = |v: &[clip_core::VisiblePiece]| v.iter().map(|p| p.segment).collect::<Vec<_>>();
    assert_eq!(counts(&ours), counts(&liu), "{what}: pieces per segment differ from Liu's");
}

#[test]
fn workloads_agree_with_the_oracle_and_liu() {
    // A few cases of each by default; LINE_CASES=n for a longer run.
    let cases = std::env::var("LINE_CASES").ok().and_then(|n| n.parse().ok()).unwrap_or(8);
    for workload in ["lines-degenerate", "wang-t4", "lines-large"] {
        for index in 0..cases {
            for kind in [WindowKind::Any, WindowKind::Convex] {
                let segments = if workload == "lines-large" { 60 } else { 150 };
                let case = line_case(workload, 11, index, kind, segments).unwrap();
                check(&case.window, &case.segments, &case.description);
            }
        }
    }
}

#[test]
fn large_windows_are_walked_not_scanned() {
    let case = line_case("lines-large", 3, 3, WindowKind::Any, 400).unwrap();
    let prepared = PreparedLineIndex::new(&case.window).unwrap();
    let mut out = Vec::new();
    let c = prepared.clip_batch_counted(&case.segments, &mut out).unwrap();
    let walked = c.segments - c.zero_length - c.bounding_box;
    // 10^4 edges in leaves of 8: a scan would classify 1250 leaves per segment.
    assert!(c.leaves_scanned < walked * 60, "{c:?}");
    assert!(c.visible > 0 && c.no_crossing > 0, "{c:?}");
    assert!(prepared.memory_bytes() < case.window_edges * 64, "{}", prepared.memory_bytes());
}

fn grid_point() -> impl Strategy<Value = Point> {
    (0i32..=6, 0i32..=6).prop_map(|(x, y)| Point::new(f64::from(x), f64::from(y)))
}

/// Rings of many vertices on a small grid: several leaves, so degenerate incidences fall on leaf
/// boundaries and the tree's box tests meet lines through box corners and along box sides.
fn long_grid_ring() -> impl Strategy<Value = Vec<Point>> {
    prop::collection::vec(grid_point(), 9..40)
}

// proptest's default: 256 cases, or PROPTEST_CASES=n for a longer run.
proptest! {
    /// Random (often self-intersecting, often degenerate) rings on a 7x7 grid and segments on a
    /// slightly larger one: vertices on segments, collinear edges, shared endpoints everywhere.
    #[test]
    fn grid_cases_agree_with_the_oracle(
        rings in prop::collection::vec(long_grid_ring(), 1..3),
        segments in prop::collection::vec((grid_point(), grid_point()), 1..12),
        shift in (-1i32..=1, -1i32..=1),
    ) {
        let w = Polygons::new(rings.into_iter().map(Ring::new).collect());
        let d = Point::new(f64::from(shift.0), f64::from(shift.1));
        let segments: Vec<Segment> = segments.into_iter().map(|(a, b)| Segment::new(a + d, b + d)).collect();
        if Liu.prepare(&w).is_ok() {
            check(&w, &segments, "grid");
        }
    }
}
