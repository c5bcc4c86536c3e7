//! Vatti bugs the `vatti` fuzz target found (inputs and pictures under `fuzz/regressions/vatti/`),
//! as plain polygons: each operation's output must pass the exact oracle.

use clip_core::{BoolOp, FillRule, Point, PolygonClipper, Polygons, Ring};
use clip_oracle::polygon::{OutputRules, REGION_TOLERANCE, check_polygon_result};
use clip_vatti::Vatti;

fn ring(points: &[(f64, f64)]) -> Polygons {
    Polygons::from(Ring::new(points.iter().map(|&(x, y)| Point::new(x, y)).collect()))
}

fn assert_every_op_passes(subject: &Polygons) {
    for op in BoolOp::ALL {
        let out = Vatti.clip(subject, &Polygons::default(), op, FillRule::EvenOdd).expect("valid input");
        let rules = OutputRules::conventional(REGION_TOLERANCE);
        let verdict = check_polygon_result(subject, &Polygons::default(), op, FillRule::EvenOdd, &out, &rules);
        assert!(verdict.is_ok(), "{op}: {}\noutput: {:?}", verdict.unwrap_err(), out.rings);
    }
}

/// A triangle 7 × 5 at 1e15 (an ulp is 0.125): its lowest vertex went into the other bound's
/// chain, which passes 7 units away but within 64 ulps of the magnitude, and the ring vanished.
#[test]
fn small_triangle_far_from_the_origin_survives() {
    let t = ring(&[(-999999999999993.0, 1e15), (-999999999999997.0, 1000000000000005.0), (-1e15, 1e15)]);
    assert_every_op_passes(&t);
    let union = Vatti.clip(&t, &Polygons::default(), BoolOp::Union, FillRule::EvenOdd).unwrap();
    assert_eq!(union.signed_area(), 17.5);
}

/// A sliver whose bounds leave (-6.9, -6.3) 1e-16 apart in slope: a rounded x at the top of the
/// first bound swapped them, and the triangle came out clockwise.
#[test]
fn sliver_keeps_its_orientation() {
    let sliver =
        ring(&[(0.10000000000000007, 0.7), (0.1000000000000001, 0.7000000000000003), (-6.8999999999999995, -6.3)]);
    assert!(sliver.signed_area() > 0.0);
    assert_every_op_passes(&sliver);
    let union = Vatti.clip(&sliver, &Polygons::default(), BoolOp::Union, FillRule::EvenOdd).unwrap();
    assert!(union.signed_area() > 0.0, "{:?}", union.rings);
}

/// A self-crossing quadrilateral 18 units across at 1e15: rounded crossings went into the chains
/// of edges up to 14 units away, and every result was empty.
#[test]
fn self_crossing_quad_far_from_the_origin_survives() {
    let quad = ring(&[
        (-1e15, 1000000000000003.0),
        (-1e15, 1e15),
        (-999999999999982.0, 1000000000000015.0),
        (-999999999999991.0, 1e15),
    ]);
    assert_every_op_passes(&quad);
}

/// At 1e15 every vertex here is a multiple of an ulp (0.125) and nothing crosses; the same rings
/// at the origin were always right. Input vertices were taken for rounded crossings and joined
/// the chains of edges within 4 ulps, and the xor lost its outer ring.
#[test]
fn input_vertices_far_from_the_origin_are_exact() {
    let (ox, oy, u) = (-1e15, 1e15, 0.125);
    let at = |pts: &[(f64, f64)]| {
        Polygons::from(Ring::new(pts.iter().map(|&(x, y)| Point::new(ox + x * u, oy + y * u)).collect()))
    };
    let subject = at(&[(0.0, 0.0), (1.0, -3.0), (2.0, 0.0)]);
    let clip = at(&[(1.0, -1.0), (1.0, -3.0), (6.0, 2.0), (9.0, 6.0), (-2.0, 0.0), (1.0, -3.0)]);
    for op in BoolOp::ALL {
        let out = Vatti.clip(&subject, &clip, op, FillRule::EvenOdd).expect("valid input");
        let rules = OutputRules::conventional(REGION_TOLERANCE);
        let verdict = check_polygon_result(&subject, &clip, op, FillRule::EvenOdd, &out, &rules);
        assert!(verdict.is_ok(), "{op}: {}\noutput: {:?}", verdict.unwrap_err(), out.rings);
    }
}

/// Two triangles at 1e15 (an ulp is 0.125) whose union pinches to a sliver an ulp wide: its
/// crossings rounded onto one line and the union had two rings running the same way along it,
/// insides overlapping. They are joined now, so no directed edge appears twice.
#[test]
fn rings_overlapping_after_rounding_are_joined() {
    let clip = Polygons::new(vec![
        Ring::new(
            [
                (-999999999999999.9, 1000000000000000.1),
                (-999999999999999.8, 1000000000000000.6),
                (-999999999999999.8, 1000000000000000.5),
            ]
            .iter()
            .map(|&(x, y)| Point::new(x, y))
            .collect(),
        ),
        Ring::new(
            [
                (-999999999999998.4, 1e15),
                (-1000000000000001.5, 1000000000000001.3),
                (-1000000000000000.4, 1000000000000000.4),
            ]
            .iter()
            .map(|&(x, y)| Point::new(x, y))
            .collect(),
        ),
    ]);
    for op in BoolOp::ALL {
        let out = Vatti.clip(&Polygons::default(), &clip, op, FillRule::EvenOdd).expect("valid input");
        let rules = OutputRules::conventional(REGION_TOLERANCE);
        let verdict = check_polygon_result(&Polygons::default(), &clip, op, FillRule::EvenOdd, &out, &rules);
        assert!(verdict.is_ok(), "{op}: {}\noutput: {:?}", verdict.unwrap_err(), out.rings);
        let mut edges: Vec<_> = out.rings.iter().flat_map(Ring::edges).map(|e| (e.a, e.b)).collect();
        let count = edges.len();
        edges.sort_by(|p, q| (p.0.x, p.0.y, p.1.x, p.1.y).partial_cmp(&(q.0.x, q.0.y, q.1.x, q.1.y)).unwrap());
        edges.dedup();
        assert_eq!(edges.len(), count, "{op}: an edge runs twice the same way: {:?}", out.rings);
    }
}

/// A sliver along y = x + 0.6 whose edge from (-2.9, -2.3) crosses a ring's horizontal y = 0.7
/// 3e-16 left of its end (0.1, 0.7): the edge's x there, interpolated from (-2.9, -2.3), came out
/// 8e-17 right of the end, the slide along the horizontal stopped short of it, and the union kept
/// both rings running up (0.1, 0.7)-(0.1, 0.7000000000000003) (a fuzz input's union and every
/// repair sweep of it).
#[test]
fn slide_along_a_horizontal_crosses_an_edge_rounded_past_its_end() {
    let subject = Polygons::new(vec![
        Ring::new(
            [(0.1, 0.7000000000000003), (-2.9, -2.3), (-2.8999999999999995, -2.2999999999999994), (0.1, 0.7)]
                .iter()
                .map(|&(x, y)| Point::new(x, y))
                .collect(),
        ),
        Ring::new(
            [
                (0.20112359550562517, 23.587640449438208),
                (-13.149999999999999, 0.7),
                (0.1, 0.7),
                (0.1, 0.7000000000000003),
                (15.1, 15.7),
                (15.099999999999998, 15.7),
                (3.9048780487804886, 21.62682926829269),
            ]
            .iter()
            .map(|&(x, y)| Point::new(x, y))
            .collect(),
        ),
    ]);
    for fill in [FillRule::NonZero, FillRule::EvenOdd] {
        for op in BoolOp::ALL {
            let out = Vatti.clip(&subject, &Polygons::default(), op, fill).expect("valid input");
            let rules = OutputRules::conventional(REGION_TOLERANCE);
            let verdict = check_polygon_result(&subject, &Polygons::default(), op, fill, &out, &rules);
            assert!(verdict.is_ok(), "{op} {fill}: {}\noutput: {:?}", verdict.unwrap_err(), out.rings);
        }
    }
}
