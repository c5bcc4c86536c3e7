//! Randomized agreement of New1 and New2 with the exact line oracle and with Liu and Cyrus-Beck,
//! on the `wang-t4` and `lines-degenerate` workloads and on small integer grids.

use clip_core::{LineClipper, Point, Polygons, Ring, Segment, WindowKind};
use clip_cyrus_beck::{CyrusBeck, Liu};
use clip_testkit::line_probe::assert_batch_matches_oracle;
use clip_testkit::workload::line_case;
use clip_virtual_box::VirtualBox;
use proptest::prelude::*;

/// Every clipper that takes `w` passes the exact line oracle on the batch (so they agree with
/// each other within its tolerance).
fn check_all(w: &Polygons, segments: &[Segment], what: &str) {
    let mut clippers: Vec<&dyn LineClipper> = vec![&VirtualBox::NEW2, &VirtualBox::NEW1, &Liu];
    if CyrusBeck.prepare(w).is_ok() {
        clippers.push(&CyrusBeck);
    }
    for c in clippers {
        assert_batch_matches_oracle(c, w, segments, what);
    }
}

#[test]
fn workloads_agree_with_the_oracle() {
    for workload in ["lines-degenerate", "wang-t4"] {
        // 12 cases of each by default; LINE_CASES=n for a longer run.
        let cases = std::env::var("LINE_CASES").ok().and_then(|n| n.parse().ok()).unwrap_or(12);
        for index in 0..cases {
            for kind in [WindowKind::Any, WindowKind::Convex] {
                let case = line_case(workload, 11, index, kind, 150).unwrap();
                check_all(&case.window, &case.segments, &case.description);
            }
        }
    }
}

fn grid_point() -> impl Strategy<Value = Point> {
    (0i32..=6, 0i32..=6).prop_map(|(x, y)| Point::new(f64::from(x), f64::from(y)))
}

// proptest's default: 256 cases, or PROPTEST_CASES=n for a longer run.
proptest! {
    /// Random (often self-intersecting, often degenerate) rings on a 7x7 grid and segments on a
    /// slightly larger one: vertices on segments, collinear edges, shared endpoints everywhere.
    #[test]
    fn grid_cases_agree_with_the_oracle(
        rings in prop::collection::vec(prop::collection::vec(grid_point(), 3..8), 1..3),
        segments in prop::collection::vec((grid_point(), grid_point()), 1..12),
        shift in (-1i32..=1, -1i32..=1),
    ) {
        let w = Polygons::new(rings.into_iter().map(Ring::new).collect());
        let d = Point::new(f64::from(shift.0), f64::from(shift.1));
        let segments: Vec<Segment> = segments.into_iter().map(|(a, b)| Segment::new(a + d, b + d)).collect();
        if Liu.prepare(&w).is_ok() {
            check_all(&w, &segments, "grid");
        }
    }
}
