//! Randomized agreement with the exact line oracle on the `wang-t4` and `lines-degenerate`
//! workloads, and on small integer grids where every incidence is common.

use clip_core::{LineClipper, Point, Polygons, Ring, Segment, WindowKind};
use clip_cyrus_beck::{CyrusBeck, Liu};
use clip_testkit::line_probe::assert_batch_matches_oracle;
use clip_testkit::workload::line_case;
use proptest::prelude::*;

#[test]
fn workloads_agree_with_the_oracle() {
    for workload in ["lines-degenerate", "wang-t4"] {
        // 12 cases of each by default; LINE_CASES=n for a longer run.
        let cases = std::env::var("LINE_CASES").ok().and_then(|n| n.parse().ok()).unwrap_or(12);
        for index in 0..cases {
            let any = line_case(workload, 7, index, WindowKind::Any, 150).unwrap();
            assert_batch_matches_oracle(&Liu, &any.window, &any.segments, &any.description);
            let convex = line_case(workload, 7, index, WindowKind::Convex, 150).unwrap();
            assert_batch_matches_oracle(&Liu, &convex.window, &convex.segments, &convex.description);
            assert_batch_matches_oracle(&CyrusBeck, &convex.window, &convex.segments, &convex.description);
        }
    }
}

fn grid_point() -> impl Strategy<Value = Point> {
    (0i32..=6, 0i32..=6).prop_map(|(x, y)| Point::new(f64::from(x), f64::from(y)))
}

// proptest's default: 256 cases, or PROPTEST_CASES=n for a longer run.
proptest! {
    /// Random (often self-intersecting, often degenerate) rings on a 7x7 grid, segments on the same
    /// grid: vertices on segments, collinear edges and shared endpoints everywhere.
    #[test]
    fn grid_cases_agree_with_the_oracle(
        rings in prop::collection::vec(prop::collection::vec(grid_point(), 3..8), 1..3),
        segments in prop::collection::vec((grid_point(), grid_point()), 1..12),
    ) {
        let w = Polygons::new(rings.into_iter().map(Ring::new).collect());
        let segments: Vec<Segment> = segments.into_iter().map(|(a, b)| Segment::new(a, b)).collect();
        if let Ok(prepared) = Liu.prepare(&w) {
            drop(prepared);
            assert_batch_matches_oracle(&Liu, &w, &segments, "grid");
            if CyrusBeck.prepare(&w).is_ok() {
                assert_batch_matches_oracle(&CyrusBeck, &w, &segments, "grid, convex");
            }
        }
    }
}
