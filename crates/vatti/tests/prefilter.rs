//! Every route and both sweeps, and the prepared clip, against the plain sweep and the exact
//! oracle: operands that overlap partly, rectangles, far-apart operands, big rings.

mod common;

use clip_core::{BoolOp, FillRule, Point, PolygonClipper, Polygons, Rect, Ring};
use clip_oracle::polygon::{OutputRules, REGION_TOLERANCE, check_polygon_result, same_region, tolerance};
use clip_testkit::workload::polygon_case_sized;
use clip_vatti::{Route, Sweep, SweepAxis, Vatti};
use proptest::prelude::*;

/// Rings of random float vertices in a box placed at `(ox, oy)` of side `size` (self-crossing).
fn rings_in(ox: f64, oy: f64, size: f64) -> impl Strategy<Value = Polygons> {
    let ring = prop::collection::vec((0.0f64..1.0, 0.0f64..1.0), 3..16)
        .prop_map(move |v| Ring::new(v.into_iter().map(|(x, y)| Point::new(ox + size * x, oy + size * y)).collect()));
    prop::collection::vec(ring, 1..4)
        .prop_map(|rings| Polygons::new(rings.into_iter().filter(|r| r.distinct_points() >= 3).collect()))
}

/// Integer-grid rings: shared vertices and edges along the other operand's box.
fn grid_rings() -> impl Strategy<Value = Polygons> {
    let ring = prop::collection::vec((0i32..12, 0i32..12), 3..10)
        .prop_map(|v| Ring::new(v.into_iter().map(|(x, y)| Point::new(f64::from(x), f64::from(y))).collect()));
    prop::collection::vec(ring, 1..3)
        .prop_map(|rings| Polygons::new(rings.into_iter().filter(|r| r.distinct_points() >= 3).collect()))
}

/// A star-shaped ring of 64-300 vertices about (50, 50) (radii 5-50, either way round): above
/// the size where `clip` cuts operands to each other's boxes.
fn big_star() -> impl Strategy<Value = Polygons> {
    (prop::collection::vec(5.0f64..50.0, 64..300), any::<bool>()).prop_map(|(radii, cw)| {
        let n = radii.len() as f64;
        let pts = radii
            .iter()
            .enumerate()
            .map(|(i, r)| {
                let a = i as f64 * std::f64::consts::TAU / n;
                Point::new(50.0 + r * a.cos(), 50.0 + r * a.sin())
            })
            .collect();
        let ring = Ring::new(pts);
        Polygons::from(if cw { ring.reversed() } else { ring })
    })
}

/// A comb on the integer grid: a spine below y = 0 and 17-60 unit-wide teeth of random heights
/// above it, shifted by `shift`. Every gap between two teeth is a local minimum at y = 0, so more
/// than 32 edges start at one height (the event sweep sorts their tops into a run), and two combs
/// share edges along the spine and wherever teeth line up.
fn comb() -> impl Strategy<Value = Polygons> {
    (prop::collection::vec(1i32..40, 17..60), 0i32..3).prop_map(|(heights, shift)| {
        let n = heights.len() as i32;
        let mut pts = vec![(shift, -1), (shift + 2 * n, -1), (shift + 2 * n, 0)];
        for (i, &h) in heights.iter().enumerate().rev() {
            let x = shift + 2 * i as i32;
            pts.extend([(x + 1, 0), (x + 1, h), (x, h), (x, 0)]);
        }
        Polygons::from(Ring::new(pts.into_iter().map(|(x, y)| Point::new(f64::from(x), f64::from(y))).collect()))
    })
}

/// A big subject and a smaller operand somewhere over it, beside it or inside it.
fn operands() -> impl Strategy<Value = (Polygons, Polygons)> {
    prop_oneof![
        (big_star(), (0.0f64..100.0, 0.0f64..100.0, 1.0f64..20.0))
            .prop_flat_map(|(s, (x, y, k))| (Just(s), rings_in(x - k, y - k, k))),
        (rings_in(0.0, 0.0, 100.0), (-20.0f64..100.0, -20.0f64..100.0, 1.0f64..40.0))
            .prop_flat_map(|(s, (x, y, k))| (Just(s), rings_in(x, y, k))),
        (grid_rings(), grid_rings()),
        (comb(), comb()),
        // One rectangle, either way round.
        (rings_in(0.0, 0.0, 100.0), (-10i32..12, -10i32..12, 1i32..12), any::<bool>()).prop_map(
            |(s, (x, y, k), cw)| {
                let r =
                    Rect::new(f64::from(x) * 8.0, f64::from(y) * 8.0, f64::from(x + k) * 8.0, f64::from(y + k) * 8.0);
                let ring = Polygons::from(r).rings.remove(0);
                (s, Polygons::from(if cw { ring.reversed() } else { ring }))
            }
        ),
    ]
}

fn op() -> impl Strategy<Value = BoolOp> {
    prop::sample::select(BoolOp::ALL.to_vec())
}

fn fill() -> impl Strategy<Value = FillRule> {
    prop::sample::select(FillRule::ALL.to_vec())
}

/// Every route by both sweeps along both axes, `clip` and the prepared clip's routes: oracle-exact, valid,
/// and the region of the whole sweep by the paper's scanbeam sweep.
fn check_all_paths(s: &Polygons, c: &Polygons, op: BoolOp, fill: FillRule) -> Result<(), TestCaseError> {
    let plain = Vatti.clip_along(Route::Whole, Some(Sweep::Scanbeam), Some(SweepAxis::Y), s, c, op, fill).unwrap();
    let prepared = Vatti::prepare(c, fill).unwrap();
    let mut outs = vec![("clip", Vatti.clip(s, c, op, fill).unwrap()), ("prepared", prepared.clip(s, op).unwrap())];
    for route in [Route::Whole, Route::Envelope, Route::Splice] {
        for sweep in [Sweep::Scanbeam, Sweep::Events] {
            for axis in [SweepAxis::Y, SweepAxis::X] {
                outs.push(("route", Vatti.clip_along(route, Some(sweep), Some(axis), s, c, op, fill).unwrap()));
                outs.push(("prepared route", prepared.clip_along(route, Some(sweep), Some(axis), s, op).unwrap()));
            }
        }
    }
    let tol = tolerance(s, c, REGION_TOLERANCE);
    for (i, (name, out)) in outs.iter().enumerate() {
        let verdict = check_polygon_result(s, c, op, fill, out, &OutputRules::conventional(REGION_TOLERANCE));
        prop_assert!(verdict.is_ok(), "{name} {i}: {}", verdict.unwrap_err());
        prop_assert!(common::check_valid(out).is_ok(), "{name} {i}: {}", common::check_valid(out).unwrap_err());
        let same = same_region((out, FillRule::NonZero), (&plain, FillRule::NonZero), tol);
        prop_assert!(same.is_ok(), "{name} {i} differs from the plain sweep by area {:e}", same.unwrap_err());
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    #[test]
    fn prefiltered_and_prepared_match_the_plain_sweep((s, c) in operands(), op in op(), fill in fill()) {
        check_all_paths(&s, &c, op, fill)?;
        // The other way round: the small operand as the subject.
        check_all_paths(&c, &s, op, fill)?;
    }

    #[test]
    fn prepared_trapezoids_cover_the_result((s, c) in operands(), op in op(), fill in fill()) {
        let out = Vatti.clip(&s, &c, op, fill).unwrap();
        let traps = Vatti::prepare(&c, fill).unwrap().clip_trapezoids(&s, op).unwrap();
        let area: f64 = traps.iter().map(|t| t.area()).sum();
        prop_assert!((area - out.signed_area()).abs() <= tolerance(&s, &c, REGION_TOLERANCE), "{area} vs {}", out.signed_area());
    }
}

#[test]
fn spiky_stars_cut_to_a_box_inside_them_match_the_plain_sweep() {
    for (index, edges) in [(0, 2_000), (1, 6_000)] {
        let case = polygon_case_sized("spiky-box", 7, index, edges, clip_core::WindowKind::Any).unwrap();
        for op in BoolOp::ALL {
            for fill in [FillRule::EvenOdd, FillRule::Positive] {
                check_all_paths(&case.subject, &case.clip, op, fill).unwrap();
            }
        }
    }
}

#[test]
fn many_subjects_cases_match_the_plain_sweep_on_every_path() {
    // Small subjects over a 1000-edge clip: the prepared clip splices ∪ and ⊕ into its resolved
    // region, cutting it at the subject's box.
    for index in 0..48 {
        let case = clip_testkit::workload::polygon_case("many-subjects", 5, index, clip_core::WindowKind::Any).unwrap();
        for op in BoolOp::ALL {
            for fill in FillRule::ALL {
                check_all_paths(&case.subject, &case.clip, op, fill).unwrap();
            }
        }
    }
}

#[test]
fn a_prepared_clip_refuses_bad_subjects_and_clips() {
    let good = Polygons::from(Rect::new(0.0, 0.0, 1.0, 1.0));
    let bad = Polygons::from(Ring::new(vec![Point::new(0.0, 0.0), Point::new(f64::NAN, 1.0), Point::new(1.0, 0.0)]));
    assert!(Vatti::prepare(&bad, FillRule::NonZero).is_err());
    let prepared = Vatti::prepare(&good, FillRule::NonZero).unwrap();
    assert!(prepared.clip(&bad, BoolOp::Intersection).is_err());
    assert!(prepared.clip_trapezoids(&bad, BoolOp::Union).is_err());
}

/// Found by the property test above in CI: a prepared xor under the positive rule whose clip's
/// second ring shares the subject's edge (2, 1)-(4, 6) reversed.
#[test]
fn prepared_xor_of_a_triangle_sharing_a_clip_edge_reversed() {
    let ring = |pts: &[(f64, f64)]| Ring::new(pts.iter().map(|&(x, y)| Point::new(x, y)).collect());
    let s = Polygons::from(ring(&[(0.0, 0.0), (2.0, 1.0), (4.0, 6.0)]));
    let c = Polygons::new(vec![
        ring(&[(0.0, 3.0), (2.0, 4.0), (9.0, 9.0)]),
        ring(&[(4.0, 6.0), (2.0, 1.0), (2.0, 5.0), (5.0, 3.0)]),
    ]);
    for op in BoolOp::ALL {
        for fill in FillRule::ALL {
            if let Err(e) = check_all_paths(&s, &c, op, fill) {
                panic!("{op:?} {fill:?}: {e}");
            }
        }
    }
}
