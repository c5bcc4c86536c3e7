//! Named fixtures for the inputs the mature clippers' bug trackers found hard (docs/DESIGN.md,
//! "Hard inputs"), and inputs every clipper must refuse with a typed error.

use clip_core::{Point, Polygons, Rect, Ring};

/// One named fixture: a subject and a clip to run under every operation and fill rule.
#[derive(Clone, Debug, PartialEq)]
pub struct HardCase {
    /// A short kebab-case name, used in file names.
    pub name: &'static str,
    /// What makes it hard.
    pub description: &'static str,
    /// The subject operand.
    pub subject: Polygons,
    /// The clip operand.
    pub clip: Polygons,
}

fn ring(points: &[(f64, f64)]) -> Ring {
    Ring::from(points)
}

fn square(x: f64, y: f64, side: f64) -> Ring {
    Rect::new(x, y, x + side, y + side).to_ring()
}

fn rotated(r: &Ring, center: Point, angle: f64) -> Ring {
    let (s, c) = angle.sin_cos();
    Ring::new(
        r.points
            .iter()
            .map(|&p| {
                let d = p - center;
                Point::new(center.x + d.x * c - d.y * s, center.y + d.x * s + d.y * c)
            })
            .collect(),
    )
}

/// The mirror image of a polygon set in the line `x = 0` (orientation reverses): a clipper's
/// result on mirrored inputs should be the mirrored result.
pub fn mirrored(p: &Polygons) -> Polygons {
    Polygons::new(p.rings.iter().map(|r| Ring::new(r.points.iter().map(|q| Point::new(-q.x, q.y)).collect())).collect())
}

/// The fixtures, valid input all (each passes `validate_polygons`).
pub fn hard_cases() -> Vec<HardCase> {
    let star = ring(&[
        (0.0, 0.0),
        (60.0, 20.0),
        (100.0, 0.0),
        (80.0, 50.0),
        (100.0, 100.0),
        (50.0, 70.0),
        (0.0, 100.0),
        (20.0, 50.0),
    ]);
    let big = 1.0e6;
    let ulp = f64::EPSILON * big;
    vec![
        HardCase {
            name: "thin-triangles-sharing-a-vertex",
            description: "two needle triangles from one apex, almost on top of each other",
            subject: ring(&[(0.0, 0.0), (1000.0, 1.0), (1000.0, 2.0)]).into(),
            clip: ring(&[(0.0, 0.0), (1000.0, 1.5), (1000.0, 3.0)]).into(),
        },
        HardCase {
            name: "near-coincident-edges",
            description: "two squares whose vertical edges are 1e-6 of the extent apart",
            subject: square(0.0, 0.0, 1000.0).into(),
            clip: Rect::new(1.0e-3, -500.0, 1000.0 + 1.0e-3, 500.0).to_ring().into(),
        },
        HardCase {
            name: "vertex-almost-on-edge",
            description: "a triangle's apex one ulp above a square's top edge",
            subject: square(0.0, 0.0, 10.0).into(),
            clip: ring(&[(2.0, 20.0), (5.0, f64::from_bits(10f64.to_bits() + 1)), (8.0, 20.0)]).into(),
        },
        HardCase {
            name: "vertex-exactly-on-edge",
            description: "a triangle's apex exactly on a square's top edge",
            subject: square(0.0, 0.0, 10.0).into(),
            clip: ring(&[(2.0, 20.0), (5.0, 10.0), (8.0, 20.0)]).into(),
        },
        HardCase {
            name: "square-vs-tiny-rotation",
            description: "a square against a copy rotated by 1e-9 radians about its centre",
            subject: square(-50.0, -50.0, 100.0).into(),
            clip: rotated(&square(-50.0, -50.0, 100.0), Point::ZERO, 1.0e-9).into(),
        },
        HardCase {
            name: "utm-coordinates",
            description: "squares near 1e6 (UTM-like) whose corners differ by one ulp",
            subject: square(big, big, 100.0).into(),
            clip: ring(&[
                (big + ulp, big),
                (big + 100.0, big + ulp),
                (big + 100.0 - ulp, big + 100.0),
                (big, big + 100.0 - ulp),
            ])
            .into(),
        },
        HardCase {
            name: "fan-sharing-vertices",
            description: "a fan of triangles sharing the centre and their sides, against a rotated fan",
            subject: fan(8, 0.0).into(),
            clip: fan(8, 0.3).into(),
        },
        HardCase {
            name: "clip-rings-sharing-an-edge",
            description: "two clip squares sharing an edge, a subject across the shared edge",
            subject: Rect::new(5.0, 2.0, 15.0, 8.0).to_ring().into(),
            clip: vec![square(0.0, 0.0, 10.0), square(10.0, 0.0, 10.0)].into(),
        },
        HardCase {
            name: "sliver",
            description: "a clip rectangle 5e-7 high across a square of side 1000",
            subject: square(0.0, 0.0, 1000.0).into(),
            clip: Rect::new(-10.0, 500.0, 1010.0, 500.0 + 5.0e-7).to_ring().into(),
        },
        HardCase {
            name: "mirror-original",
            description: "a concave star against a square; compare with mirror-image",
            subject: star.clone().into(),
            clip: square(30.0, 30.0, 50.0).into(),
        },
        HardCase {
            name: "mirror-image",
            description: "mirror-original mirrored in x = 0: the result should be its mirror",
            subject: mirrored(&star.clone().into()),
            clip: mirrored(&square(30.0, 30.0, 50.0).into()),
        },
        HardCase {
            name: "identical-clip-rings",
            description: "two identical clip rings: empty under even-odd, the square under non-zero",
            subject: Rect::new(5.0, 5.0, 15.0, 15.0).to_ring().into(),
            clip: vec![square(0.0, 0.0, 10.0), square(0.0, 0.0, 10.0)].into(),
        },
        HardCase {
            name: "identical-operands",
            description: "subject and clip the same concave ring",
            subject: star.clone().into(),
            clip: star.clone().into(),
        },
        HardCase {
            name: "bow-tie",
            description: "a self-intersecting bow-tie subject against a square",
            subject: ring(&[(0.0, 0.0), (10.0, 10.0), (10.0, 0.0), (0.0, 10.0)]).into(),
            clip: square(2.0, 2.0, 6.0).into(),
        },
        HardCase {
            name: "hole-touching-outer",
            description: "a hole touching its outer ring at a vertex, against a square over the touch",
            subject: vec![square(0.0, 0.0, 10.0), ring(&[(5.0, 0.0), (3.0, 5.0), (7.0, 5.0)])].into(),
            clip: square(2.0, -2.0, 6.0).into(),
        },
        HardCase {
            name: "checkerboard-corners",
            description: "four squares touching at corners against a square centred on the touch point",
            subject: vec![square(0.0, 0.0, 5.0), square(5.0, 5.0, 5.0), square(10.0, 0.0, 5.0), square(5.0, -5.0, 5.0)]
                .into(),
            clip: square(2.5, -2.5, 10.0).into(),
        },
        HardCase {
            name: "spike",
            description: "a square with a zero-width spike against an overlapping square",
            subject: ring(&[(0.0, 0.0), (10.0, 0.0), (10.0, 5.0), (20.0, 5.0), (10.0, 5.0), (10.0, 10.0), (0.0, 10.0)])
                .into(),
            clip: square(5.0, 2.0, 10.0).into(),
        },
        HardCase {
            name: "offset-1e9",
            description: "mirror-original moved by 1e9 in x and y, where one ulp is 1.2e-7",
            subject: offset(&star.clone().into(), 1.0e9),
            clip: offset(&square(30.0, 30.0, 50.0).into(), 1.0e9),
        },
        HardCase {
            name: "repeated-points",
            description: "a square whose corners are repeated two and three times, against an overlapping square",
            subject: ring(&[
                (0.0, 0.0),
                (0.0, 0.0),
                (10.0, 0.0),
                (10.0, 10.0),
                (10.0, 10.0),
                (10.0, 10.0),
                (0.0, 10.0),
                (0.0, 0.0),
            ])
            .into(),
            clip: square(5.0, 5.0, 10.0).into(),
        },
        HardCase {
            name: "self-touching-ring",
            description: "one ring of two squares touching at a corner it passes twice, against a square over the touch",
            subject: ring(&[
                (0.0, 0.0),
                (5.0, 0.0),
                (5.0, 5.0),
                (10.0, 5.0),
                (10.0, 10.0),
                (5.0, 10.0),
                (5.0, 5.0),
                (0.0, 5.0),
            ])
            .into(),
            clip: square(3.0, 3.0, 4.0).into(),
        },
        HardCase {
            name: "overlapping-collinear-edges",
            description: "rectangles sharing part of their bottom and top lines, one inside the other's span",
            subject: Rect::new(0.0, 0.0, 10.0, 4.0).to_ring().into(),
            clip: Rect::new(4.0, 0.0, 14.0, 4.0).to_ring().into(),
        },
    ]
}

/// A polygon set moved by `d` in x and y.
fn offset(p: &Polygons, d: f64) -> Polygons {
    Polygons::new(
        p.rings.iter().map(|r| Ring::new(r.points.iter().map(|q| Point::new(q.x + d, q.y + d)).collect())).collect(),
    )
}

/// A fan of `n` triangles around the origin, radius 100, starting at angle `phase`.
fn fan(n: usize, phase: f64) -> Vec<Ring> {
    let at = |i: usize| {
        let a = phase + std::f64::consts::TAU * i as f64 / n as f64;
        Point::new((100.0 * a.cos()).round(), (100.0 * a.sin()).round())
    };
    (0..n).map(|i| Ring::new(vec![Point::ZERO, at(i), at(i + 1)])).collect()
}

/// Inputs a clipper must refuse with a typed `ClipError` (never panic): NaN, infinite, beyond
/// the supported range, too few distinct points.
pub fn invalid_inputs() -> Vec<(&'static str, Polygons)> {
    vec![
        ("nan-coordinate", ring(&[(0.0, 0.0), (f64::NAN, 0.0), (1.0, 1.0)]).into()),
        ("infinite-coordinate", ring(&[(0.0, 0.0), (f64::INFINITY, 0.0), (1.0, 1.0)]).into()),
        ("out-of-range", ring(&[(0.0, 0.0), (1.0e200, 0.0), (1.0, 1.0)]).into()),
        ("two-distinct-points", ring(&[(0.0, 0.0), (1.0, 1.0), (0.0, 0.0), (1.0, 1.0)]).into()),
        ("one-point", ring(&[(3.0, 3.0), (3.0, 3.0), (3.0, 3.0)]).into()),
    ]
}
