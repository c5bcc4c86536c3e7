//! Property tests on random float and integer-grid inputs: the exact oracle, the area
//! identities, invariance under translation and mirroring, operand order of symmetric
//! operations, the trapezoid output against the polygon output, and exact output of operands
//! with only horizontal and vertical edges.

use clip_core::{BoolOp, FillRule, Point, PolygonClipper, Polygons, Ring, Trapezoid};
use clip_oracle::polygon::{
    OutputRules, REGION_TOLERANCE, check_area_identities, check_polygon_result, same_region, tolerance,
};
use clip_testkit::workload::mirrored;
use clip_vatti::{Route, Sweep, SweepAxis, Vatti};
use proptest::prelude::*;

/// Rings on a small integer grid: shared vertices, collinear overlaps, horizontals, touching.
fn grid_polygons() -> impl Strategy<Value = Polygons> {
    let ring = prop::collection::vec((0i32..7, 0i32..7), 3..8)
        .prop_map(|v| Ring::new(v.into_iter().map(|(x, y)| Point::new(x as f64, y as f64)).collect()));
    prop::collection::vec(ring, 1..3)
        .prop_map(|rings| Polygons::new(rings.into_iter().filter(|r| r.distinct_points() >= 3).collect()))
}

/// Rings of uniform random float vertices (self-intersecting in general).
fn random_polygons() -> impl Strategy<Value = Polygons> {
    let ring = prop::collection::vec((0.0f64..100.0, 0.0f64..100.0), 3..12)
        .prop_map(|v| Ring::new(v.into_iter().map(Point::from).collect()));
    prop::collection::vec(ring, 1..3)
        .prop_map(|rings| Polygons::new(rings.into_iter().filter(|r| r.distinct_points() >= 3).collect()))
}

fn any_polygons() -> impl Strategy<Value = Polygons> {
    prop_oneof![grid_polygons(), random_polygons()]
}

/// Rings of horizontal and vertical edges, closed walks that turn at every vertex, with
/// coordinates off every grid drawn from five values per axis: shared coordinates, collinear
/// overlaps, touching and crossing walks.
fn rectilinear_polygons() -> impl Strategy<Value = Polygons> {
    let pool = || prop::collection::vec(0.0f64..10.0, 5);
    let walks = prop::collection::vec(prop::collection::vec((0usize..5, 0usize..5), 2..7), 1..3);
    (pool(), pool(), walks).prop_map(|(xs, ys, walks)| {
        let ring = |walk: Vec<(usize, usize)>| {
            let (x0, mut points) = (xs[walk[0].0], Vec::new());
            for (k, &(i, j)) in walk.iter().enumerate() {
                points.push(Point::new(xs[i], ys[j]));
                let x = walk.get(k + 1).map_or(x0, |&(i, _)| xs[i]);
                points.push(Point::new(x, ys[j]));
            }
            Ring::new(points)
        };
        Polygons::new(walks.into_iter().map(ring).filter(|r| r.distinct_points() >= 3).collect())
    })
}

fn op() -> impl Strategy<Value = BoolOp> {
    prop::sample::select(BoolOp::ALL.to_vec())
}

fn fill() -> impl Strategy<Value = FillRule> {
    prop::sample::select(FillRule::ALL.to_vec())
}

fn map(p: &Polygons, f: impl Fn(Point) -> Point) -> Polygons {
    Polygons::new(p.rings.iter().map(|r| Ring::new(r.points.iter().map(|&q| f(q)).collect())).collect())
}

/// Same region, read non-zero, within the inputs' tolerance.
fn same(a: &Polygons, b: &Polygons, tol: f64) -> Result<(), TestCaseError> {
    same_region((a, FillRule::NonZero), (b, FillRule::NonZero), tol)
        .map_err(|area| TestCaseError::fail(format!("regions differ by area {area:e}")))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn output_passes_the_oracle(s in any_polygons(), c in any_polygons(), op in op(), fill in fill()) {
        let out = Vatti.clip(&s, &c, op, fill).unwrap();
        let verdict = check_polygon_result(&s, &c, op, fill, &out, &OutputRules::conventional(REGION_TOLERANCE));
        prop_assert!(verdict.is_ok(), "{}", verdict.unwrap_err());
    }

    #[test]
    fn area_identities_hold(s in any_polygons(), c in any_polygons(), fill in fill()) {
        let outs: Vec<(BoolOp, Polygons)> = BoolOp::ALL.iter().map(|&op| (op, Vatti.clip(&s, &c, op, fill).unwrap())).collect();
        let refs: Vec<(BoolOp, &Polygons)> = outs.iter().map(|(op, p)| (*op, p)).collect();
        let verdict = check_area_identities(&s, &c, fill, &refs, &OutputRules::conventional(REGION_TOLERANCE));
        prop_assert!(verdict.is_ok(), "{}", verdict.unwrap_err());
    }

    #[test]
    fn translation_moves_the_result(s in grid_polygons(), c in grid_polygons(), op in op(), fill in fill(),
                                    dx in -50i32..50, dy in -50i32..50) {
        // Integer shifts of grid input are exact, so the results must match exactly in region.
        let shift = |p: Point| Point::new(p.x + dx as f64, p.y + dy as f64);
        let out = Vatti.clip(&s, &c, op, fill).unwrap();
        let moved = Vatti.clip(&map(&s, shift), &map(&c, shift), op, fill).unwrap();
        same(&map(&out, shift), &moved, tolerance(&s, &c, REGION_TOLERANCE))?;
    }

    #[test]
    fn mirroring_mirrors_the_result(s in any_polygons(), c in any_polygons(), op in op(), fill in fill()) {
        // Mirroring reverses every ring, so the winding numbers change sign: positive and
        // negative fill swap.
        let mirror_fill = match fill {
            FillRule::Positive => FillRule::Negative,
            FillRule::Negative => FillRule::Positive,
            f => f,
        };
        let out = Vatti.clip(&s, &c, op, fill).unwrap();
        let mirrored_out = Vatti.clip(&mirrored(&s), &mirrored(&c), op, mirror_fill).unwrap();
        let back = mirrored(&mirrored_out);
        same(&out, &back, tolerance(&s, &c, REGION_TOLERANCE))?;
    }

    #[test]
    fn symmetric_ops_ignore_operand_order(s in any_polygons(), c in any_polygons(), fill in fill()) {
        for op in [BoolOp::Intersection, BoolOp::Union, BoolOp::Xor] {
            let ab = Vatti.clip(&s, &c, op, fill).unwrap();
            let ba = Vatti.clip(&c, &s, op, fill).unwrap();
            same(&ab, &ba, tolerance(&s, &c, REGION_TOLERANCE))?;
        }
    }

    #[test]
    fn trapezoids_cover_the_result(s in any_polygons(), c in any_polygons(), op in op(), fill in fill()) {
        let out = Vatti.clip(&s, &c, op, fill).unwrap();
        let traps = Vatti.clip_trapezoids(&s, &c, op, fill).unwrap();
        let tol = tolerance(&s, &c, REGION_TOLERANCE).max(1e-12);
        let total: f64 = traps.iter().map(Trapezoid::area).sum();
        prop_assert!((total - out.signed_area()).abs() <= tol, "{total} vs {}", out.signed_area());
        let rings = Polygons::new(traps.iter().map(Trapezoid::to_ring).filter(|r| r.distinct_points() >= 3).collect());
        let verdict = check_polygon_result(&s, &c, op, fill, &rings, &OutputRules::bridged(FillRule::NonZero, REGION_TOLERANCE));
        prop_assert!(verdict.is_ok(), "{}", verdict.unwrap_err());
    }

    /// Nothing is rounded where every edge is horizontal or vertical: every output coordinate is
    /// an input coordinate, under both sweeps and both axes (an x·dy/dy taken along a vertical
    /// edge was an ulp off).
    #[test]
    fn rectilinear_operands_give_input_coordinates(s in rectilinear_polygons(), c in rectilinear_polygons(),
                                                   op in op(), fill in fill()) {
        let coordinates = |f: fn(Point) -> f64| -> Vec<u64> {
            [&s, &c].iter().flat_map(|p| p.rings.iter().flat_map(|r| r.points.iter().map(move |&q| f(q).to_bits()))).collect()
        };
        let (xs, ys) = (coordinates(|q| q.x), coordinates(|q| q.y));
        for sweep in [Sweep::Scanbeam, Sweep::Events] {
            for axis in [SweepAxis::Y, SweepAxis::X] {
                let out = Vatti.clip_along(Route::Whole, Some(sweep), Some(axis), &s, &c, op, fill).unwrap();
                for q in out.rings.iter().flat_map(|r| &r.points) {
                    prop_assert!(xs.contains(&(q.x + 0.0).to_bits()) && ys.contains(&(q.y + 0.0).to_bits()),
                        "{sweep:?} {axis:?}: {q:?} is not at input coordinates");
                }
                let verdict = check_polygon_result(&s, &c, op, fill, &out, &OutputRules::conventional(REGION_TOLERANCE));
                prop_assert!(verdict.is_ok(), "{sweep:?} {axis:?}: {}", verdict.unwrap_err());
            }
        }
    }
}
