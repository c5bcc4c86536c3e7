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

/// Every operation under every fill rule of `subject` and `clip` passes the exact oracle.
fn assert_every_op_and_fill_passes(subject: &Polygons, clip: &Polygons) {
    for fill in [FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive, FillRule::Negative] {
        for op in BoolOp::ALL {
            let out = Vatti.clip(subject, clip, op, fill).expect("valid input");
            let rules = OutputRules::conventional(REGION_TOLERANCE);
            let verdict = check_polygon_result(subject, clip, op, fill, &out, &rules);
            assert!(verdict.is_ok(), "{op} {fill}: {}\noutput: {:?}", verdict.unwrap_err(), out.rings);
        }
    }
}

fn rings(rings: &[&[(f64, f64)]]) -> Polygons {
    Polygons::new(rings.iter().map(|r| Ring::new(r.iter().map(|&(x, y)| Point::new(x, y)).collect())).collect())
}

/// Two fans of edges from a cluster of vertices a few ulps apart along a line through
/// (-15.9, 2.7) (fuzz corpus input d1e175a5): rounded crossings broke ∩, − and ⊕ (two rings
/// running the same way along an edge an ulp long), and so did the snap-rounded operands' sweep
/// that replaces such output. Their extent is their magnitude, so in pixel units they reach
/// 1.7e15 and an ulp is a quarter of a pixel. An edge sliding along a horizontal passed another
/// edge that was itself sliding, at that edge's exact x, but took the point for a rounded
/// crossing, which edges a pixel away (within the 4 ε × 1.7e15 a rounded point may be off) then
/// took into their chains.
#[test]
fn fans_from_a_cluster_of_vertices_a_few_ulps_apart() {
    let subject = rings(&[&[
        (-15.90000000000001, 2.699999999999999),
        (-15.900000000000073, 2.699999999999988),
        (-15.900000000000137, 2.6999999999999775),
        (-5.884375, 2.0906249999999993),
        (1.115625, 9.090625),
        (-15.900000000000052, 2.6999999999999917),
        (-15.900000000000126, 2.6999999999999793),
        (0.865625, 7.340624999999999),
        (0.88125, 7.231249999999999),
        (-15.90000000000015, 2.6999999999999753),
        (-15.900000000000139, 2.699999999999977),
        (-15.900000000000128, 2.699999999999979),
        (-15.900000000000118, 2.6999999999999806),
        (-15.900000000000107, 2.6999999999999824),
        (-15.900000000000096, 2.699999999999984),
        (-15.900000000000086, 2.699999999999986),
        (-15.900000000000075, 2.6999999999999877),
        (-15.900000000000064, 2.6999999999999895),
        (-15.900000000000054, 2.6999999999999913),
        (-15.900000000000043, 2.699999999999993),
        (-15.900000000000032, 2.699999999999995),
        (-15.900000000000022, 2.6999999999999966),
        (-15.900000000000011, 2.6999999999999984),
        (-15.9, 2.7),
        (1.740625, 13.465625),
        (0.865625, 7.340624999999999),
        (1.865625, 14.340625),
        (0.865625, 7.340624999999999),
        (0.85, 7.449999999999999),
        (0.9125, 7.012499999999999),
        (0.85, 7.449999999999999),
        (1.1, 5.699999999999999),
        (0.1, 12.7),
    ]]);
    let clip = rings(&[&[
        (-15.90000000000009, 2.699999999999985),
        (-3.3140625000000377, 6.098437499999993),
        (-3.138281250000013, 7.4929687499999975),
        (-15.900000000000025, 2.699999999999996),
        (-9.9, -9.3),
        (-11.900000000000073, -3.300000000000012),
        (-15.900000000000073, 2.699999999999988),
        (-14.900000000000073, 9.699999999999989),
        (-15.900000000000073, 2.699999999999988),
        (-15.900000000000126, 2.6999999999999793),
        (-11.708593750000096, 3.8601562499999846),
        (-15.90000000000009, 2.6999999999999855),
        (-9.9, -9.3),
    ]]);
    assert_every_op_and_fill_passes(&subject, &clip);
}

/// Three clip rings with vertices an ulp or a few apart near (-1e15, 1e15) (an ulp is 0.125) and
/// one vertex at the origin (fuzz corpus input e7e17b93): the union and the xor had two rings
/// running the same way along (-999999999999999, 1000000000000000.5) -
/// (-999999999999999.5, 1000000000000000.5), and so did the paper's sweep of the snap-rounded
/// operands that replaces such output (pixel 0.5; in pixel units they reach 2e15). Where bounds
/// met at a local maximum, the edges between them were crossed on the scanline at exact points
/// (the edge's own vertex, or its x clamped to the maximum's) taken for rounded crossings, which
/// edges up to 4 ε × 2e15 (two pixels) away then took into their chains.
#[test]
fn clusters_of_vertices_an_ulp_apart_at_1e15_with_a_vertex_at_the_origin() {
    let clip = rings(&[
        &[
            (-1000000000000001.0, 1000000000000000.1),
            (-1000000000000000.0, 1000000000000000.0),
            (-999999999999999.0, 1000000000000001.0),
            (-1000000000000000.0, 1000000000000000.0),
            (-999999999999999.5, 1000000000000001.0),
            (-999999999999998.5, 1000000000000002.0),
            (-999999999999997.5, 1000000000000003.0),
            (-999999999999996.5, 1000000000000004.0),
            (-999999999999995.5, 1000000000000005.0),
            (-999999999999994.5, 1000000000000006.0),
            (-1000000000000000.0, 1000000000000002.0),
            (-999999999999999.6, 1000000000000000.4),
            (-999999999999998.6, 1000000000000001.4),
            (-1000000000000001.9, 999999999999998.5),
            (-999999999999999.3, 1000000000000000.3),
            (-999999999999998.3, 1000000000000000.3),
            (-1000000000000001.5, 999999999999998.4),
        ],
        &[
            (-999999999999996.8, 1000000000000002.9),
            (-999999999999996.5, 1000000000000003.1),
            (-999999999999997.5, 1000000000000002.1),
            (-999999999999998.5, 1000000000000001.1),
            (-999999999999999.5, 1000000000000000.1),
            (-1000000000000000.0, 1000000000000000.0),
            (-999999999999999.6, 1000000000000000.4),
            (-1000000000000001.5, 999999999999998.4),
            (-999999999999996.5, 1000000000000004.0),
            (-1000000000000001.5, 999999999999998.4),
            (-999999999999996.5, 1000000000000004.0),
            (-999999999999999.3, 999999999999999.6),
        ],
        &[
            (-1000000000000000.3, 999999999999999.8),
            (-1000000000000000.5, 999999999999999.5),
            (-1000000000000000.8, 999999999999999.3),
            (-1000000000000000.5, 999999999999998.8),
            (-1000000000000001.1, 999999999999998.8),
            (-1000000000000001.1, 999999999999997.8),
            (-1000000000000000.1, 999999999999998.8),
            (2.2141812330543942e-52, 2.0351519284918095e-96),
            (-999999999999999.0, 1000000000000001.1),
            (-999999999999999.3, 999999999999999.6),
            (-1000000000000000.8, 999999999999999.3),
            (-999999999999996.5, 1000000000000003.1),
            (-1000000000000000.0, 1000000000000000.0),
            (-1000000000000001.5, 999999999999998.4),
            (-999999999999998.3, 1000000000000000.3),
            (-999999999999999.6, 1000000000000000.4),
            (-999999999999999.5, 1000000000000000.1),
            (-1000000000000000.0, 1000000000000000.0),
            (-999999999999999.4, 1000000000000000.6),
            (-999999999999999.9, 1000000000000000.6),
            (-999999999999999.3, 1000000000000000.4),
        ],
    ]);
    assert_every_op_and_fill_passes(&Polygons::default(), &clip);
}
