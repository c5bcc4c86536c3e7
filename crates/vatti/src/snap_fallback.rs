//! The one fallback where rounding broke the sweep's output: both operands snap rounded
//! (`clip_core::snap_round`, after Hobby 1999), then swept once.
//!
//! Snap-rounded edges meet only at shared vertices or coincide, so the sweep of the rounded
//! operands meets no crossing to round: every output vertex is a vertex of the rounded operands,
//! and the output's form rests on exact decisions only. The price is a move of every vertex (and
//! crossing) by at most `s·√2/2`, with `s` the [`pixel_size`], in this fallback only: outputs the
//! sweep leaves valid are returned as they are.

use clip_core::{MIN_COORDINATE, Polygons, snap_round};

/// The snap-rounding pixel for `subject` and `clip`: the smallest power of two at least 4 ulps of
/// their largest coordinate magnitude (and at least `clip_core::MIN_COORDINATE`, so rounded
/// coordinates stay in the range the sweep takes). Four ulps, because a pixel's centre and
/// borders (multiples of half a pixel) must be exact in f64 out to the largest coordinate, which
/// takes at least 2 ulps, and because a vertex then moves by at most `s·√2/2`, under 3 ulps of the
/// largest coordinate: a few times the rounding the sweep's crossings have anyway.
pub(crate) fn pixel_size(subject: &Polygons, clip: &Polygons) -> f64 {
    let largest = subject.points().chain(clip.points()).fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
    let floor = smallest_power_of_two_from(MIN_COORDINATE);
    if largest < f64::MIN_POSITIVE {
        return floor;
    }
    // 2^e <= largest < 2^(e+1): an ulp there is 2^(e-52), four are 2^(e-50).
    let e = ((largest.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    2f64.powi(e - 50).max(floor)
}

/// The smallest power of two at least `v` (positive, normal).
fn smallest_power_of_two_from(v: f64) -> f64 {
    let e = ((v.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    let p = 2f64.powi(e);
    if p < v { p * 2.0 } else { p }
}

/// Both valid operands snap rounded at their [`pixel_size`]; `None` when the grid refuses them
/// (it cannot for valid operands: the pixel is chosen for their largest coordinate).
pub(crate) fn snapped_operands(subject: &Polygons, clip: &Polygons) -> Option<(Polygons, Polygons)> {
    snap_round(subject, clip, pixel_size(subject, clip)).ok()
}

#[cfg(test)]
mod tests {
    use clip_core::{BoolOp, FillRule, Point, Ring};
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
    fn snapped_sweeps_of_nearly_coincident_squares_are_valid_and_close() {
        for angle in [1e-16, -3e-16, 1e-12] {
            let (subject, clip) = square_and_turned_copy(angle);
            let (a, b) = snapped_operands(&subject, &clip).expect("valid operands");
            let moved = pixel_size(&subject, &clip) * std::f64::consts::SQRT_2 / 2.0;
            for op in [BoolOp::Intersection, BoolOp::Union, BoolOp::Difference, BoolOp::Xor] {
                for fill in [FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive, FillRule::Negative] {
                    for sweep in [Sweep::Scanbeam, Sweep::Events] {
                        let out = Vatti::sweep_polygons_once(&a, &b, op, fill, sweep);
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
