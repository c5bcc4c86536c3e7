//! Planted faults: each test builds the right answer to a clip, checks that the oracle accepts
//! it, plants one fault of form, and checks that the oracle names that fault and where it is.

use clip_core::{BoolOp, FillRule, Point, Polygons, Rect, Ring};
use clip_oracle::polygon::{
    EdgeAt, FormFailure, OutputRules, PolygonFailure, REGION_TOLERANCE, Visit, check_form, check_polygon_result,
};

fn ring(points: &[(f64, f64)]) -> Ring {
    Ring::from(points)
}

fn square(x0: f64, y0: f64, x1: f64, y1: f64) -> Ring {
    Rect::new(x0, y0, x1, y1).to_ring()
}

/// The oracle's verdict on `output` as the answer to `subject op clip` under non-zero; asserts
/// that it is a form failure and returns it.
fn form_failure(subject: &Polygons, clip: &Polygons, op: BoolOp, output: &Polygons) -> FormFailure {
    let rules = OutputRules::conventional(REGION_TOLERANCE);
    match check_polygon_result(subject, clip, op, FillRule::NonZero, output, &rules) {
        Err(PolygonFailure::Invalid(failure)) => failure,
        other => panic!("expected a form failure, got {other:?}"),
    }
}

fn accepted(subject: &Polygons, clip: &Polygons, op: BoolOp, output: &Polygons) {
    let rules = OutputRules::conventional(REGION_TOLERANCE);
    let verdict = check_polygon_result(subject, clip, op, FillRule::NonZero, output, &rules);
    assert!(verdict.is_ok(), "the right answer is rejected: {verdict:?}");
}

/// [0,2]² ∪ [2,4]×[0,2]: one rectangle. Two squares sharing x = 2 (run both ways) cover the
/// same region, but their edges overlap.
#[test]
fn overlapping_edges_of_two_rings() {
    let (a, b) = (Polygons::from(square(0.0, 0.0, 2.0, 2.0)), Polygons::from(square(2.0, 0.0, 4.0, 2.0)));
    let right = Polygons::from(square(0.0, 0.0, 4.0, 2.0));
    accepted(&a, &b, BoolOp::Union, &right);
    let planted = Polygons::new(vec![a.rings[0].clone(), b.rings[0].clone()]);
    let failure = form_failure(&a, &b, BoolOp::Union, &planted);
    let FormFailure::OverlappingEdges { first, second, from, to } = failure else { panic!("{failure}") };
    // Edge 1 of the first square (x = 2 going up), edge 3 of the second (x = 2 going down).
    let mut pair = [first, second];
    pair.sort();
    assert_eq!(pair, [EdgeAt { ring: 0, edge: 1 }, EdgeAt { ring: 1, edge: 3 }]);
    let mut ends = [from, to];
    ends.sort_by(|p, q| p.y.total_cmp(&q.y));
    assert_eq!(ends, [Point::new(2.0, 0.0), Point::new(2.0, 2.0)]);
}

/// The same union answered by one ring with a zero-width spike: two consecutive edges overlap.
#[test]
fn overlapping_edges_of_one_ring() {
    let (a, b) = (Polygons::from(square(0.0, 0.0, 2.0, 2.0)), Polygons::from(square(2.0, 0.0, 4.0, 2.0)));
    let planted =
        Polygons::from(ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 2.0), (2.0, 2.0), (2.0, 1.0), (2.0, 2.0), (0.0, 2.0)]));
    let failure = form_failure(&a, &b, BoolOp::Union, &planted);
    let FormFailure::OverlappingEdges { first, second, .. } = failure else { panic!("{failure}") };
    assert_eq!((first, second), (EdgeAt { ring: 0, edge: 3 }, EdgeAt { ring: 0, edge: 4 }));
    // Two non-consecutive edges of one ring running along each other: a slit.
    let slit = Polygons::from(ring(&[
        (0.0, 0.0),
        (4.0, 0.0),
        (4.0, 2.0),
        (3.0, 2.0),
        (3.0, 1.0),
        (1.0, 1.0),
        (3.0, 1.0),
        (3.0, 2.0),
        (0.0, 2.0),
    ]));
    let failure = form_failure(&a, &b, BoolOp::Union, &slit);
    assert_eq!(failure.kind(), "overlapping-edges", "{failure}");
}

/// [0,1]² ∪ [1,2]×[1,2]: two squares touching at (1, 1), answered as two rings. One ring
/// walking both squares visits (1, 1) twice.
#[test]
fn a_ring_visiting_a_point_twice() {
    let (a, b) = (Polygons::from(square(0.0, 0.0, 1.0, 1.0)), Polygons::from(square(1.0, 1.0, 2.0, 2.0)));
    let right = Polygons::new(vec![a.rings[0].clone(), b.rings[0].clone()]);
    accepted(&a, &b, BoolOp::Union, &right);
    let planted = Polygons::from(ring(&[
        (0.0, 0.0),
        (1.0, 0.0),
        (1.0, 1.0),
        (2.0, 1.0),
        (2.0, 2.0),
        (1.0, 2.0),
        (1.0, 1.0),
        (0.0, 1.0),
    ]));
    assert_eq!(
        form_failure(&a, &b, BoolOp::Union, &planted),
        FormFailure::RepeatedPoint {
            ring: 0,
            point: Point::new(1.0, 1.0),
            first: Visit::Vertex(2),
            second: Visit::Vertex(6)
        }
    );
    // A vertex of the ring lying inside another of its edges is a second visit too.
    let pinched = Polygons::from(ring(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (1.0, 0.0), (0.0, 2.0)]));
    let failure = check_form(&pinched).unwrap_err();
    assert_eq!(
        failure,
        FormFailure::RepeatedPoint {
            ring: 0,
            point: Point::new(1.0, 0.0),
            first: Visit::Vertex(3),
            second: Visit::Edge(0)
        }
    );
}

/// The answer plus a ring of zero area (the fuzzer's "zero-area hole"): three points on a line.
#[test]
fn a_zero_area_ring() {
    let (a, b) = (Polygons::from(square(0.0, 0.0, 4.0, 4.0)), Polygons::from(square(1.0, 1.0, 5.0, 5.0)));
    let right = Polygons::from(square(1.0, 1.0, 4.0, 4.0));
    accepted(&a, &b, BoolOp::Intersection, &right);
    let mut planted = right.clone();
    planted.rings.push(ring(&[(2.0, 2.0), (3.0, 3.0), (2.5, 2.5)]));
    assert_eq!(form_failure(&a, &b, BoolOp::Intersection, &planted), FormFailure::ZeroArea { ring: 1, vertices: 3 });
}

/// [0,10]² − [3,7]²: an outer with a hole. The outer turned clockwise is a wrong-way outer.
#[test]
fn a_wrong_way_outer() {
    let (a, b) = (Polygons::from(square(0.0, 0.0, 10.0, 10.0)), Polygons::from(square(3.0, 3.0, 7.0, 7.0)));
    let right = Polygons::new(vec![square(0.0, 0.0, 10.0, 10.0), square(3.0, 3.0, 7.0, 7.0).reversed()]);
    accepted(&a, &b, BoolOp::Difference, &right);
    let mut planted = right.clone();
    planted.rings[0] = planted.rings[0].reversed();
    assert_eq!(form_failure(&a, &b, BoolOp::Difference, &planted), FormFailure::WrongWayOuter { ring: 0, depth: 0 });
    // An island inside the hole (depth 2) running clockwise is one too.
    let island = square(4.0, 4.0, 6.0, 6.0);
    let mut islands = right.clone();
    islands.rings.push(island.clone());
    check_form(&islands).unwrap();
    islands.rings[2] = island.reversed();
    assert_eq!(check_form(&islands), Err(FormFailure::WrongWayOuter { ring: 2, depth: 2 }));
}

/// The same difference with its hole turned counter-clockwise.
#[test]
fn a_wrong_way_hole() {
    let (a, b) = (Polygons::from(square(0.0, 0.0, 10.0, 10.0)), Polygons::from(square(3.0, 3.0, 7.0, 7.0)));
    let right = Polygons::new(vec![square(0.0, 0.0, 10.0, 10.0), square(3.0, 3.0, 7.0, 7.0).reversed()]);
    let mut planted = right.clone();
    planted.rings[1] = planted.rings[1].reversed();
    assert_eq!(form_failure(&a, &b, BoolOp::Difference, &planted), FormFailure::WrongWayHole { ring: 1, depth: 1 });
}

/// The same difference with its hole moved outside the outer.
#[test]
fn a_hole_outside_its_outer() {
    let (a, b) = (Polygons::from(square(0.0, 0.0, 10.0, 10.0)), Polygons::from(square(3.0, 3.0, 7.0, 7.0)));
    let right = Polygons::new(vec![square(0.0, 0.0, 10.0, 10.0), square(3.0, 3.0, 7.0, 7.0).reversed()]);
    accepted(&a, &b, BoolOp::Difference, &right);
    let planted = Polygons::new(vec![right.rings[0].clone(), square(13.0, 3.0, 17.0, 7.0).reversed()]);
    assert_eq!(form_failure(&a, &b, BoolOp::Difference, &planted), FormFailure::HoleOutsideOuter { ring: 1 });
    // Touching the outer from outside at a vertex, it is still outside.
    let touching = Polygons::new(vec![right.rings[0].clone(), ring(&[(10.0, 5.0), (12.0, 7.0), (12.0, 3.0)])]);
    assert_eq!(check_form(&touching), Err(FormFailure::HoleOutsideOuter { ring: 1 }));
}

/// [0,2]² ∪ [3,5]×[0,2]: two disjoint squares. Planted: the second slid left over the first, so
/// their edges cross inside both.
#[test]
fn rings_crossing() {
    let (a, b) = (Polygons::from(square(0.0, 0.0, 2.0, 2.0)), Polygons::from(square(3.0, 0.5, 5.0, 1.5)));
    let right = Polygons::new(vec![a.rings[0].clone(), b.rings[0].clone()]);
    accepted(&a, &b, BoolOp::Union, &right);
    let planted = Polygons::new(vec![a.rings[0].clone(), square(1.0, 0.5, 3.0, 1.5)]);
    let failure = form_failure(&a, &b, BoolOp::Union, &planted);
    let FormFailure::Crossing { first, second, near } = failure else { panic!("{failure}") };
    assert_eq!([first.ring, second.ring].iter().filter(|&&r| r == 0).count(), 1, "{failure}");
    assert!(near.x == 2.0 && (near.y == 0.5 || near.y == 1.5), "{failure}");
    // One ring crossing itself: a bow tie.
    let bow = Polygons::from(ring(&[(0.0, 0.0), (2.0, 2.0), (2.0, 0.0), (0.0, 2.0)]));
    let failure = check_form(&bow).unwrap_err();
    assert!(matches!(failure, FormFailure::Crossing { first, second, .. } if first.ring == 0 && second.ring == 0));
}

/// Two rings that meet at shared points and cross there: the second enters the first's inside at
/// its corner (1, 1) and leaves it at its corner (1, 0). Touching there without crossing is fine.
#[test]
fn rings_crossing_at_a_shared_point() {
    let (a, b) = (Polygons::from(square(0.0, 0.0, 1.0, 1.0)), Polygons::from(square(1.0, 1.0, 2.0, 2.0)));
    let right = Polygons::new(vec![a.rings[0].clone(), b.rings[0].clone()]);
    accepted(&a, &b, BoolOp::Union, &right);
    let planted = Polygons::new(vec![a.rings[0].clone(), ring(&[(1.0, 1.0), (0.5, 0.5), (1.0, 0.0), (2.0, 0.5)])]);
    let failure = form_failure(&a, &b, BoolOp::Union, &planted);
    assert!(matches!(failure, FormFailure::Crossing { near, .. } if near == Point::new(1.0, 0.0)), "{failure}");
    // And where the shared points lie inside an edge of the first ring (x = 1).
    let through = Polygons::new(vec![a.rings[0].clone(), ring(&[(1.0, 0.25), (0.5, 0.5), (1.0, 0.75), (1.5, 0.5)])]);
    let failure = check_form(&through).unwrap_err();
    let FormFailure::Crossing { first, second, near } = failure else { panic!("{failure}") };
    assert_eq!(near, Point::new(1.0, 0.25));
    let mut edges = [first, second];
    edges.sort();
    assert_eq!(edges[0], EdgeAt { ring: 0, edge: 1 }, "{failure}");
}

/// What the strict form still allows: rings touching at isolated points (corners, a vertex on
/// another ring's edge, a hole touching its outer), islands in holes, collinear vertices going
/// on straight.
#[test]
fn touching_nested_and_straight_rings_are_valid() {
    let valid: [(&str, Polygons); 5] = [
        ("corners", Polygons::new(vec![square(0.0, 0.0, 1.0, 1.0), square(1.0, 1.0, 2.0, 2.0)])),
        (
            "vertex on an edge",
            Polygons::new(vec![square(0.0, 0.0, 2.0, 2.0), ring(&[(2.0, 1.0), (3.0, 0.0), (3.0, 2.0)])]),
        ),
        (
            "hole touching its outer",
            Polygons::new(vec![square(0.0, 0.0, 10.0, 10.0), ring(&[(5.0, 0.0), (3.0, 5.0), (7.0, 5.0)])]),
        ),
        (
            "island in a hole, touching it",
            Polygons::new(vec![
                square(0.0, 0.0, 10.0, 10.0),
                square(2.0, 2.0, 8.0, 8.0).reversed(),
                ring(&[(2.0, 5.0), (5.0, 3.0), (5.0, 7.0)]),
            ]),
        ),
        ("straight on", Polygons::from(ring(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 2.0)]))),
    ];
    for (what, output) in valid {
        assert_eq!(check_form(&output), Ok(()), "{what}");
    }
}

/// A non-finite vertex is named with its place.
#[test]
fn a_non_finite_vertex() {
    let planted = Polygons::from(ring(&[(0.0, 0.0), (f64::NAN, 0.0), (1.0, 1.0)]));
    assert!(matches!(check_form(&planted), Err(FormFailure::NonFinite { ring: 0, vertex: 1, .. })));
}
