//! The four-state clipper against the exact oracle, by region (its bridges have zero area), on
//! the `vatti-t3`, `star` and `grid` workloads with rectangle windows, all fill rules.

use clip_core::{BoolOp, FillRule, PolygonClipper, WindowKind};
use clip_oracle::polygon::{OutputRules, REGION_TOLERANCE, check_polygon_result};
use clip_rect_four_state::FourState;
use clip_testkit::workload::polygon_case;

#[test]
fn matches_the_oracle_by_region() {
    let mut cases = 0;
    for workload in ["vatti-t3", "star", "grid", "scribble", "holes"] {
        for index in 0..60 {
            let case = polygon_case(workload, 11, index, WindowKind::Rectangle).unwrap();
            let fill = FillRule::ALL[index % 4];
            let out = FourState.clip(&case.subject, &case.clip, BoolOp::Intersection, fill).unwrap();
            let rules = OutputRules::bridged(fill, REGION_TOLERANCE);
            if let Err(failure) =
                check_polygon_result(&case.subject, &case.clip, BoolOp::Intersection, fill, &out, &rules)
            {
                panic!("{} (seed 11, index {index}, {fill}): {failure}", case.description);
            }
            cases += 1;
        }
    }
    assert_eq!(cases, 300);
}
