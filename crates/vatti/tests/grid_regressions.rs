//! Shrunk `grid` workload failures from `clipbench verify` (positive fill), kept as named
//! regression tests: each runs the recorded operation and the exact oracle on conventional output.

use clip_core::{BoolOp, FillRule, Point, PolygonClipper, Polygons, Ring, WindowKind};
use clip_oracle::polygon::{OutputRules, REGION_TOLERANCE, check_polygon_result};
use clip_testkit::workload::polygon_case;
use clip_vatti::{FixedSweep, Sweep, Vatti, VattiPrepared};

/// Rings from coordinate lists (closing point omitted).
fn polygons(rings: &[&[(f64, f64)]]) -> Polygons {
    Polygons::new(rings.iter().map(|r| Ring::new(r.iter().map(|&(x, y)| Point::new(x, y)).collect())).collect())
}

/// Runs `op` under `fill` and checks the output with the exact oracle.
fn assert_oracle(subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) {
    let out = Vatti.clip(subject, clip, op, fill).expect("valid input");
    let verdict = check_polygon_result(subject, clip, op, fill, &out, &OutputRules::conventional(REGION_TOLERANCE));
    assert!(verdict.is_ok(), "{op} {fill}: {}\noutput: {:?}", verdict.unwrap_err(), out.rings);
}

/// Grid seed 1 index 3, shrunk: a triangle whose apex (4, 20) is a vertex of a clip triangle
/// and whose edge passes through another clip vertex (2, 16); the difference has a hole
/// touching the outer ring at (2, 16). The hole's other corners are rounded crossings of two
/// clip edges; each must go into both edges' chains although one passes it only within rounding
/// (at 5d54aba it did not, and the hole crossed the outer ring at (2, 16)).
fn grid_3() -> (Polygons, Polygons) {
    let subject = polygons(&[&[(4.0, 20.0), (0.0, 12.0), (4.0, 6.0)]]);
    let clip = polygons(&[&[(2.0, 12.0), (4.0, 22.0), (10.0, 4.0)], &[(4.0, 20.0), (2.0, 16.0), (8.0, 8.0)]]);
    (subject, clip)
}

/// Grid seed 1 index 97, shrunk: a subject edge collinear with and overlapping a clip edge of a
/// self-intersecting clip, a third clip edge crossing both where the overlap ends. The rounded
/// crossing (17.33.., 15.33..) must go into both coincident edges' chains so that their opposite
/// output edges share end points and cancel (at 5d54aba they overlapped in two rings).
fn grid_97() -> (Polygons, Polygons) {
    let subject = polygons(&[&[(19.0, 17.0), (17.0, 21.0), (17.0, 15.0)]]);
    let clip = polygons(&[&[(20.0, 18.0), (17.0, 15.0), (22.0, 18.0), (15.0, 14.0)]]);
    (subject, clip)
}

#[test]
fn grid_3_difference_positive() {
    let (subject, clip) = grid_3();
    assert_oracle(&subject, &clip, BoolOp::Difference, FillRule::Positive);
}

#[test]
fn grid_3_xor_positive() {
    let (subject, clip) = grid_3();
    assert_oracle(&subject, &clip, BoolOp::Xor, FillRule::Positive);
}

#[test]
fn grid_97_union_positive() {
    let (subject, clip) = grid_97();
    assert_oracle(&subject, &clip, BoolOp::Union, FillRule::Positive);
}

#[test]
fn grid_97_xor_positive() {
    let (subject, clip) = grid_97();
    assert_oracle(&subject, &clip, BoolOp::Xor, FillRule::Positive);
}

/// Every operation and fill rule on both cases.
#[test]
fn grid_3_and_97_all_ops_and_fills() {
    for (subject, clip) in [grid_3(), grid_97()] {
        for op in BoolOp::ALL {
            for fill in FillRule::ALL {
                assert_oracle(&subject, &clip, op, fill);
            }
        }
    }
}

/// The unshrunk cases as the harness generated them (grid seed 1, indices 3 and 97), every
/// operation under positive and negative fill.
#[test]
fn grid_seed_1_cases_3_and_97_unshrunk() {
    for index in [3, 97] {
        let case = polygon_case("grid", 1, index, WindowKind::Any).expect("workload");
        for op in BoolOp::ALL {
            for fill in [FillRule::Positive, FillRule::Negative] {
                assert_oracle(&case.subject, &case.clip, op, fill);
            }
        }
    }
}

/// Every operation and fill rule through [`Vatti`], a prepared clip and either sweep.
fn assert_passes_both(subject: &Polygons, clip: &Polygons) {
    let rules = OutputRules::conventional(REGION_TOLERANCE);
    let clippers: [(&str, &dyn PolygonClipper); 4] = [
        ("vatti", &Vatti),
        ("vatti-prepared", &VattiPrepared),
        ("scanbeam", &FixedSweep(Sweep::Scanbeam)),
        ("events", &FixedSweep(Sweep::Events)),
    ];
    for (name, clipper) in clippers {
        for op in BoolOp::ALL {
            for fill in FillRule::ALL {
                let out = clipper.clip(subject, clip, op, fill).expect("valid input");
                let verdict = check_polygon_result(subject, clip, op, fill, &out, &rules);
                assert!(verdict.is_ok(), "{name} {op} {fill}: {}", verdict.unwrap_err());
            }
        }
    }
}

/// `verify --cases 20000`, case 449, xor, non-zero, shrunk: three edges pass through
/// (13⅓, 16⅚), which f64 cannot hold. All three pairwise crossings round to one point, 3e-14 off
/// the flattest edge in x (twice the rounding allowance), which passed it without a vertex there,
/// and a ring crossed itself at it. On floating-point inputs such crossings fail the rounding
/// certificate (events within its box); on a grid as coarse as this rounding is proven harmless
/// (`rounding_certificate::rounding_is_harmless`), and the sweep gives the point to every edge
/// through the exact crossing (`predicates::through_crossing`).
#[test]
fn three_edges_through_a_crossing_f64_cannot_hold_all_take_its_point() {
    let subject = polygons(&[&[(18.0, 17.0), (16.0, 17.0), (0.0, 16.0)]]);
    let clip = polygons(&[&[(10.0, 16.0), (14.0, 17.0), (14.0, 4.0), (13.0, 18.0), (15.0, 11.0)]]);
    assert_passes_both(&subject, &clip);
}

/// Random integer rings on a 7 x 7 grid, intersection, non-zero, found by a stress of such
/// grids: a subject edge and a clip edge cross at (⅓, -2), on the row of a clip horizontal. The
/// slide along that horizontal computed the subject edge's x there as 0.33333333333333326 (the
/// quotient rounded, then the sum), the edges' crossing as 0.3333333333333333 (rounded once), and
/// a ring crossed itself between the two. `Edge::x_at` now divides last, so on a grid both are
/// the exact value rounded once: one point.
#[test]
fn a_slide_and_a_crossing_on_its_row_take_one_point() {
    let subject = polygons(&[&[
        (1.0, 2.0),
        (1.0, -2.0),
        (-3.0, 0.0),
        (2.0, -3.0),
        (0.0, -3.0),
        (-1.0, -3.0),
        (0.0, -3.0),
        (0.0, 1.0),
    ]]);
    let clip = polygons(&[
        &[(-3.0, 3.0), (-3.0, 2.0), (-1.0, 2.0), (1.0, -3.0)],
        &[(2.0, -2.0), (0.0, -2.0), (1.0, 1.0), (-1.0, -1.0), (2.0, 0.0), (0.0, 3.0), (1.0, -2.0), (0.0, -3.0)],
    ]);
    assert_passes_both(&subject, &clip);
}

/// `verify --cases 20000`, case 13087, union, even-odd (vatti-prepared), shrunk: the prepared
/// clip's splice joined two swept rings that touch where a vertex of one lies inside an edge of
/// the other into one ring.
#[test]
fn swept_rings_touching_inside_an_edge_stay_apart_through_the_splice() {
    let subject = polygons(&[&[(2.0, 0.0), (3.0, 4.0), (2.0, 4.0)]]);
    let clip = polygons(&[
        &[(0.0, 2.0), (5.0, 2.0), (2.0, 4.0), (2.0, 5.0)],
        &[(2.0, 5.0), (2.0, 4.0), (1.0, 3.0), (2.0, 2.0), (6.0, 2.0)],
    ]);
    assert_passes_both(&subject, &clip);
}

/// `verify --cases 20000`, case 17339, union, even-odd (vatti-prepared), shrunk: the splice cut
/// the clip's edge (1, 1)-(2, 4) at a rounded point of the box's border, the local sweep crossed
/// that cut edge with the subject's y = 2 at (1.3333333333333335, 2), an ulp right of the restored
/// edge, which then crossed the edge ending there. A joining edge crossing an edge left inside
/// the box now sends the call to the plain sweep.
#[test]
fn a_crossing_computed_on_a_cut_edge_does_not_cross_the_restored_edge() {
    let subject = polygons(&[&[(0.0, 2.0), (4.0, 0.0), (0.0, 3.0), (0.0, 0.0), (3.0, 2.0)]]);
    let clip = polygons(&[&[(1.0, 1.0), (2.0, 4.0), (1.0, 0.0)]]);
    assert_passes_both(&subject, &clip);
}
