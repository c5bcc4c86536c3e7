//! Sutherland-Hodgman against the exact oracle, by region (its bridges have zero area), on the
//! `vatti-t3`, `star` and `grid` workloads with rectangle and convex windows, all fill rules.

use clip_core::{BoolOp, FillRule, PolygonClipper, WindowKind};
use clip_oracle::polygon::{
    OutputRules, REGION_TOLERANCE, bridge_count as output_bridges, bridge_count_within as output_bridges_within,
    check_polygon_result,
};
use clip_sutherland_hodgman::{ConvexWindow, Form, SutherlandHodgman, bridge_count};
use clip_testkit::workload::polygon_case;

#[test]
fn both_forms_match_the_oracle_by_region() {
    let (mut cases, mut bridges) = (0, 0);
    for workload in ["vatti-t3", "star", "grid"] {
        for window in [WindowKind::Rectangle, WindowKind::Convex] {
            for index in 0..50 {
                let case = polygon_case(workload, 7, index, window).unwrap();
                let fill = FillRule::ALL[index % 4];
                let rules = OutputRules::bridged(fill, REGION_TOLERANCE);
                for form in [Form::List, Form::Pipeline] {
                    let out = SutherlandHodgman::new(form)
                        .clip(&case.subject, &case.clip, BoolOp::Intersection, fill)
                        .unwrap();
                    if let Err(failure) =
                        check_polygon_result(&case.subject, &case.clip, BoolOp::Intersection, fill, &out, &rules)
                    {
                        panic!("{} (seed 7, index {index}, {fill}, {form:?}): {failure}", case.description);
                    }
                }
                let ours = bridge_count(&case.subject, &ConvexWindow::new(&case.clip).unwrap());
                // The testkit's geometric count (opposite overlapping edge pairs, >= 1 per bridge)
                // sees every bridge we count: exactly on axis-aligned sides, within rounding on
                // slanted ones, whose bridge ends are computed separately.
                let out = SutherlandHodgman::default()
                    .clip(&case.subject, &case.clip, BoolOp::Intersection, FillRule::NonZero)
                    .unwrap();
                let snap = case.subject.bounds().union(case.clip.bounds()).extent() * REGION_TOLERANCE;
                let theirs = if window == WindowKind::Rectangle {
                    output_bridges(&out)
                } else {
                    output_bridges_within(&out, snap)
                };
                assert!(theirs >= ours, "{} ({window:?}): ours {ours}, testkit {theirs}", case.description);
                bridges += ours;
                cases += 1;
            }
        }
    }
    assert_eq!(cases, 300);
    assert!(bridges > 0, "the concave workloads should make some bridges");
}
