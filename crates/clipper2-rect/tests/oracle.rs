//! Clipper2's rectangle clipper against the exact oracle, by region under the input's fill rule.

use clip_clipper2_rect::Clipper2RectClipper;
use clip_core::{BoolOp, FillRule, PolygonClipper, WindowKind};
use clip_oracle::polygon::{GEO_TOLERANCE, OutputRules, check_polygon_result};
use clip_testkit::workload::polygon_case;

#[test]
fn matches_the_oracle_by_region() {
    let mut cases = 0;
    for workload in ["vatti-t3", "star", "grid"] {
        for index in 0..100 {
            let case = polygon_case(workload, 11, index, WindowKind::Rectangle).unwrap();
            let fill = FillRule::ALL[index % 4];
            let out = Clipper2RectClipper.clip(&case.subject, &case.clip, BoolOp::Intersection, fill).unwrap();
            let rules = OutputRules::bridged(fill, GEO_TOLERANCE);
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
