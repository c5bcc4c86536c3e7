//! The last step of the fallback chain, where the rounding certificate (`rounding_certificate`)
//! fails for the operands and for them routed through their near vertices
//! (`clip_core::snap_edges_to_vertices`): both operands snap rounded (`clip_core::snap_round`,
//! after Hobby 1999), then swept once.
//!
//! Snap-rounded edges meet only at shared vertices or coincide, so the sweep of the rounded
//! operands (which keeps their straight-through vertices: dropping one where another edge
//! passes would make a crossing again) meets no crossing to round: every output vertex is a vertex of the rounded operands,
//! and the output's form rests on exact decisions only. The price is a move of every vertex (and
//! crossing) by at most `s·√2/2`, with `s` the [`pixel_size`], in this fallback only: outputs the
//! certificate holds for are returned as the first sweep made them.

use clip_core::{MIN_COORDINATE, NearEdges, Point, Polygons, Ring, power_of_two_at_least, snap_round_near};

use crate::simplify::simplify_ring;

/// log2 of the pixel in ulps of the largest coordinate (4 ulps, see [`pixel_size`]). Coarser
/// pixels were tried: 64 and 4096 ulps broke more fuzz inputs (more features collapse).
const PIXEL_ULPS_LOG2: i32 = 2;

/// The snap-rounding pixel for `subject` and `clip`: the smallest power of two at least 4 ulps of
/// their largest coordinate magnitude (and at least `clip_core::MIN_COORDINATE`, so rounded
/// coordinates stay in the range the sweep takes). Four ulps, because a pixel's centre and
/// borders (multiples of half a pixel) must be exact in f64 out to the largest coordinate, which
/// takes at least 2 ulps, and because a vertex then moves by at most `s·√2/2`, under 3 ulps of the
/// largest coordinate: a few times the rounding the sweep's crossings have anyway.
pub(crate) fn pixel_size(subject: &Polygons, clip: &Polygons) -> f64 {
    let largest = subject.points().chain(clip.points()).fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
    let floor = power_of_two_at_least(MIN_COORDINATE);
    if largest < f64::MIN_POSITIVE {
        return floor;
    }
    // 2^e <= largest < 2^(e+1): an ulp there is 2^(e-52), four are 2^(e-50).
    let e = ((largest.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    2f64.powi(e - 52 + PIXEL_ULPS_LOG2).max(floor)
}

/// Both operands snap rounded at their [`pixel_size`] `s`, in pixel units from a grid point
/// `origin` at their low corner: every vertex is an integer, exactly (`(p - origin) / s`, a
/// difference of multiples of `s` divided by a power of two). The sweep is run there because its
/// tolerances (where it decides that two rounded x or points coincide) are relative to the
/// coordinates' magnitude: far from the origin (fuzz inputs at 1e15 and 5e5), grid points 4 ulps
/// apart fall within them, and its output from exact, noded operands was broken; near the
/// origin, in units of a pixel, they are far apart.
pub(crate) struct SnappedOperands {
    pub subject: Polygons,
    pub clip: Polygons,
    origin: Point,
    pixel: f64,
}

impl SnappedOperands {
    /// The operands `near` holds (on their [`pixel_size`]) snap rounded.
    pub(crate) fn of(near: &NearEdges) -> SnappedOperands {
        let pixel = near.pixel();
        let (a, b) = snap_round_near(near);
        let low = a.bounds().union(b.bounds()).min;
        let origin = Point::new((low.x / pixel).round() * pixel, (low.y / pixel).round() * pixel);
        let local = |p: &Polygons| map(p, |q| Point::new((q.x - origin.x) / pixel, (q.y - origin.y) / pixel));
        SnappedOperands { subject: local(&a), clip: local(&b), origin, pixel }
    }

    /// `out` (in pixel units) back in the operands' coordinates: exact for the sweep's output of
    /// these operands where its vertices are theirs. Where the sweep still rounded a point (near
    /// `MAX_COORDINATE`, fuzz inputs at 1e150), mapped back it can land on its neighbour: rings
    /// lose such repeats, and rings left without area go.
    pub(crate) fn to_world(&self, out: &Polygons) -> Polygons {
        let world = |q: &Point| Point::new(q.x * self.pixel + self.origin.x, q.y * self.pixel + self.origin.y);
        Polygons::new(
            out.rings
                .iter()
                .map(|r| simplify_ring(&r.points.iter().map(world).collect::<Vec<_>>()))
                .filter(|points| points.len() >= 3)
                .map(Ring::new)
                .collect(),
        )
    }
}

fn map(p: &Polygons, f: impl Fn(Point) -> Point) -> Polygons {
    Polygons::new(p.rings.iter().map(|r| Ring::new(r.points.iter().map(|&q| f(q)).collect())).collect())
}

#[cfg(test)]
mod tests {
    use clip_core::{BoolOp, FillRule};
    use clip_oracle::polygon::{check_valid_output, region_area};

    use super::*;
    use crate::{Sweep, Vatti};

    fn ring(points: &[(f64, f64)]) -> Ring {
        Ring::new(points.iter().map(|&(x, y)| Point::new(x, y)).collect())
    }

    #[test]
    fn pixels_are_four_ulps_of_the_largest_coordinate() {
        let square = |side: f64| Polygons::new(vec![ring(&[(0.0, 0.0), (side, 0.0), (side, side)])]);
        let empty = Polygons::default();
        assert_eq!(pixel_size(&square(1.0), &empty), 4.0 * f64::EPSILON);
        assert_eq!(pixel_size(&square(1.5), &empty), 4.0 * f64::EPSILON);
        assert_eq!(pixel_size(&square(0.75), &square(0.5)), 2.0 * f64::EPSILON);
        assert_eq!(pixel_size(&square(1e15), &empty), 0.5);
        let tiny = pixel_size(&square(1e-99), &empty);
        assert!(tiny >= MIN_COORDINATE && tiny / 2.0 < MIN_COORDINATE, "{tiny:e}");
    }

    /// A square and a copy turned by `angle` about the origin: long edges nearly coincident.
    fn square_and_turned_copy(angle: f64) -> (Polygons, Polygons) {
        let square = [(0.1, 0.2), (0.9, 0.25), (0.95, 0.8), (0.15, 0.7)];
        let (sin, cos) = angle.sin_cos();
        let copy: Vec<(f64, f64)> = square.iter().map(|&(x, y)| (x * cos - y * sin, x * sin + y * cos)).collect();
        (Polygons::new(vec![ring(&square)]), Polygons::new(vec![ring(&copy)]))
    }

    #[test]
    fn a_vertex_an_ulp_inside_a_neighbours_edge_is_routed_through_not_snapped() {
        // The triangle's vertex lies an ulp inside the square's right edge, and its two edges
        // cross that edge within an ulp of it: the certificate fails. Routed through the vertex,
        // the square's edge meets them there exactly, and the routed operands' sweep holds: the
        // fallback chain stops there, before snap rounding.
        let v = Point::new(1.0 - f64::EPSILON / 2.0, 0.5);
        let square = Polygons::new(vec![ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)])]);
        let triangle = Polygons::new(vec![ring(&[(v.x, v.y), (2.0, 0.0), (2.0, 1.0)])]);
        let near = NearEdges::of(&square, &triangle, pixel_size(&square, &triangle)).expect("valid operands");
        let (a, b) = clip_core::snap_edges_to_vertices(&near).expect("the square's edge passes near the vertex");
        assert!(a.rings[0].points.contains(&v) && b == triangle, "{a:?}");
        let mut routed_taken = 0;
        for sweep in [Sweep::Scanbeam, Sweep::Events] {
            for op in [BoolOp::Intersection, BoolOp::Union, BoolOp::Difference, BoolOp::Xor] {
                for fill in [FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive, FillRule::Negative] {
                    let out = Vatti::sweep_polygons(&square, &triangle, op, fill, sweep);
                    check_valid_output(&out).unwrap_or_else(|e| panic!("{op:?} {fill:?}: {e:?}"));
                    // Where the certificate holds as they are (nothing rounded is output: under
                    // the negative rule, nothing at all), the operands are not routed.
                    let float = Vatti::sweep_clean(&square, &triangle, op, fill, sweep, crate::Operands::Float);
                    let routed = Vatti::sweep_clean(&a, &b, op, fill, sweep, crate::Operands::Float);
                    let expected = float.or_else(|| {
                        routed_taken += 1;
                        routed
                    });
                    assert_eq!(Some(out), expected, "{op:?} {fill:?} {sweep:?}");
                }
            }
        }
        assert!(routed_taken >= 12, "the routed sweep taken {routed_taken} times of 32");
    }

    #[test]
    fn snapped_sweeps_of_nearly_coincident_squares_are_valid_and_close() {
        for angle in [1e-16, -3e-16, 1e-12] {
            let (subject, clip) = square_and_turned_copy(angle);
            let near = NearEdges::of(&subject, &clip, pixel_size(&subject, &clip)).expect("valid operands");
            let snapped = SnappedOperands::of(&near);
            let moved = pixel_size(&subject, &clip) * std::f64::consts::SQRT_2 / 2.0;
            for op in [BoolOp::Intersection, BoolOp::Union, BoolOp::Difference, BoolOp::Xor] {
                for fill in [FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive, FillRule::Negative] {
                    for sweep in [Sweep::Scanbeam, Sweep::Events] {
                        let out = Vatti::sweep_polygons_once(&snapped.subject, &snapped.clip, op, fill, sweep);
                        let out = snapped.to_world(&out);
                        check_valid_output(&out).unwrap_or_else(|e| panic!("{angle:e} {op:?} {fill:?}: {e:?}"));
                        // The region differs from the exact one by at most the band each edge
                        // moved through: the perimeters times the largest move, twice.
                        let perimeter: f64 = subject.edges().chain(clip.edges()).map(|e| e.length()).sum();
                        let layers = [(&subject, fill), (&clip, fill), (&out, FillRule::NonZero)];
                        let exact_op = |s: bool, c: bool| match op {
                            BoolOp::Intersection => s && c,
                            BoolOp::Union => s || c,
                            BoolOp::Difference => s && !c,
                            BoolOp::Xor => s != c,
                        };
                        let off = region_area(&layers, |inside| exact_op(inside[0], inside[1]) != inside[2]);
                        assert!(off <= 2.0 * perimeter * moved, "{angle:e} {op:?} {fill:?}: {off:e}");
                    }
                }
            }
        }
    }
}
