//! Shrunk `grid` workload failures from `clipbench verify` (positive fill), kept as named
//! regression tests: each runs the recorded operation and the exact oracle on conventional output.

use clip_core::{BoolOp, FillRule, Point, PolygonClipper, Polygons, Ring, WindowKind};
use clip_oracle::polygon::{OutputRules, REGION_TOLERANCE, check_polygon_result};
use clip_testkit::workload::polygon_case;
use clip_vatti::{Vatti, VattiPrepared};

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

/// Every operation and fill rule through [`Vatti`] and a prepared clip.
fn assert_passes_both(subject: &Polygons, clip: &Polygons) {
    let rules = OutputRules::conventional(REGION_TOLERANCE);
    let clippers: [(&str, &dyn PolygonClipper); 2] = [("vatti", &Vatti), ("vatti-prepared", &VattiPrepared)];
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
/// (13⅓, 16⅚), which f64 cannot hold. All three pairwise crossings round to one point, off the
/// edge that passes it without a vertex there, and a ring crossed itself at it; no near
/// vertices, short edge or near miss showed it. The sweep now notes crossings taken one after
/// another at or near one rounded point, and the edges passing there are checked
/// (`form_check::crossing_near`).
#[test]
fn a_ring_crossing_itself_where_three_edges_meet_off_the_grid_is_caught() {
    let subject = polygons(&[&[(18.0, 17.0), (16.0, 17.0), (0.0, 16.0)]]);
    let clip = polygons(&[&[(10.0, 16.0), (14.0, 17.0), (14.0, 4.0), (13.0, 18.0), (15.0, 11.0)]]);
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
