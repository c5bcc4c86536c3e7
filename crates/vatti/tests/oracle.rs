//! The exact oracle (clip-testkit) on the named hard cases and on every polygon workload, for
//! all four operations and fill rules: valid output, sampled points, the symmetric-difference
//! area, the area identities, and the same for the trapezoid output.

use clip_core::{BoolOp, FillRule, PolygonClipper, Polygons, Ring, Trapezoid, WindowKind};
use clip_oracle::polygon::{
    OutputRules, PolygonFailure, REGION_TOLERANCE, check_area_identities, check_polygon_result, same_region, tolerance,
};
use clip_testkit::workload::{hard_cases, polygon_case_sized};
use clip_vatti::Vatti;

/// Trapezoids as rings; their union read under non-zero is the region (they do not overlap).
fn trapezoid_rings(traps: &[Trapezoid]) -> Polygons {
    Polygons::new(traps.iter().map(Trapezoid::to_ring).filter(|r: &Ring| r.distinct_points() >= 3).collect())
}

/// Runs all four operations under `fill` on one case and checks everything; returns the
/// failures with `label`.
fn check_case(label: &str, subject: &Polygons, clip: &Polygons, fill: FillRule) -> Vec<String> {
    let rules = OutputRules::conventional(REGION_TOLERANCE);
    let mut failures = Vec::new();
    let mut outputs = Vec::new();
    for op in BoolOp::ALL {
        let out = Vatti.clip(subject, clip, op, fill).expect("valid input");
        if let Err(e) = check_polygon_result(subject, clip, op, fill, &out, &rules) {
            failures.push(format!("{label} {op} {fill}: {e}"));
        }
        let traps = Vatti.clip_trapezoids(subject, clip, op, fill).expect("valid input");
        let total: f64 = traps.iter().map(Trapezoid::area).sum();
        let tol = tolerance(subject, clip, REGION_TOLERANCE);
        if (total - out.signed_area()).abs() > tol.max(1e-12) {
            failures.push(format!("{label} {op} {fill}: trapezoid area {total} vs polygon area {}", out.signed_area()));
        }
        // The top corners come from dx times the height: allow their rounding.
        let slack = 1e-9 * subject.bounds().union(clip.bounds()).extent();
        if let Some(t) = traps.iter().find(|t| {
            t.y_top <= t.y_bottom || t.x_right < t.x_left || t.x_right_at(t.y_top) < t.x_left_at(t.y_top) - slack
        }) {
            failures.push(format!("{label} {op} {fill}: trapezoid upside down or inside out: {t:?}"));
        }
        if let Err(area) = same_region((&trapezoid_rings(&traps), FillRule::NonZero), (&out, FillRule::NonZero), tol) {
            failures.push(format!("{label} {op} {fill}: trapezoids differ from the polygons by {area:e}"));
        }
        outputs.push((op, out));
    }
    let refs: Vec<(BoolOp, &Polygons)> = outputs.iter().map(|(op, p)| (*op, p)).collect();
    if let Err(e @ PolygonFailure::AreaIdentity(_)) = check_area_identities(subject, clip, fill, &refs, &rules) {
        failures.push(format!("{label} {fill}: {e}"));
    }
    failures
}

#[test]
fn hard_cases_pass_the_oracle() {
    let mut failures = Vec::new();
    for case in hard_cases() {
        for fill in FillRule::ALL {
            failures.extend(check_case(case.name, &case.subject, &case.clip, fill));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A few small cases of every workload but `large` (the harness's verify runs the full sizes;
/// debug-build test time stays short).
#[test]
fn workloads_pass_the_oracle() {
    let mut failures = Vec::new();
    for workload in ["vatti-t3", "star", "scribble", "holes", "multi", "grid"] {
        for (index, edges) in [(0, 8), (1, 24), (2, 40)] {
            for window in [WindowKind::Any, WindowKind::Convex, WindowKind::Rectangle] {
                let case = polygon_case_sized(workload, 2026, index, edges, window).expect("workload");
                for fill in FillRule::ALL {
                    failures.extend(check_case(&case.description, &case.subject, &case.clip, fill));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// One large case per kind (smooth blobs, checkerboard): the oracle on intersection only.
#[test]
fn large_cases_pass_the_oracle() {
    let rules = OutputRules::conventional(REGION_TOLERANCE);
    for index in 0..2 {
        let case = polygon_case_sized("large", 2026, index, 1000, WindowKind::Any).unwrap();
        let out = Vatti.clip(&case.subject, &case.clip, BoolOp::Intersection, FillRule::NonZero).unwrap();
        let verdict =
            check_polygon_result(&case.subject, &case.clip, BoolOp::Intersection, FillRule::NonZero, &out, &rules);
        assert!(verdict.is_ok(), "{}: {}", case.description, verdict.unwrap_err());
    }
}
