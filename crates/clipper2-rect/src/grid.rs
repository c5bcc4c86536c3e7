//! The integer grid Clipper2 works on, fitted to the inputs' extent.

use clip_core::{Point, Rect};

use crate::ffi::GridPoint;

/// Where the integer grid sits: `integer = round((coordinate - origin) * scale)`.
///
/// Clipper2 computes on 64-bit integers. [`IntegerGrid::fitting`] moves the inputs' bounding-box
/// centre to the origin and picks the power of two that maps the largest distance from it to
/// just under 2^[`IntegerGrid::BITS`]: the rounding step is then about extent x 2^-30 wherever
/// the inputs sit (the same grid as clip-testkit's Clipper2 peer), and a power of two makes the
/// scaling itself exact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IntegerGrid {
    /// The point that maps to integer (0, 0).
    pub origin: Point,
    /// Integer units per coordinate unit, a power of two.
    pub scale: f64,
}

impl IntegerGrid {
    /// Bits the inputs' extent is scaled to.
    pub const BITS: i32 = 30;

    /// The grid for inputs whose bounding box is `bounds` (any grid for an empty box).
    pub fn fitting(bounds: Rect) -> IntegerGrid {
        if bounds.is_empty() {
            return IntegerGrid { origin: Point::ZERO, scale: 1.0 };
        }
        let origin = bounds.min.lerp(bounds.max, 0.5);
        let extent =
            [bounds.min.x - origin.x, bounds.max.x - origin.x, bounds.min.y - origin.y, bounds.max.y - origin.y]
                .into_iter()
                .fold(0.0f64, |m, d| m.max(d.abs()));
        IntegerGrid { origin, scale: grid_scale(extent) }
    }

    /// The grid point nearest `p`.
    pub fn to_grid(&self, p: Point) -> GridPoint {
        [((p.x - self.origin.x) * self.scale).round() as i64, ((p.y - self.origin.y) * self.scale).round() as i64]
    }

    /// The coordinates of grid point `q`.
    pub fn to_point(&self, q: GridPoint) -> Point {
        Point::new(q[0] as f64 / self.scale + self.origin.x, q[1] as f64 / self.scale + self.origin.y)
    }
}

/// The power of two that maps magnitudes up to `extent` below 2^BITS. For extents so small that
/// this power would overflow, the largest finite power of two (such inputs round to few points).
fn grid_scale(extent: f64) -> f64 {
    if extent == 0.0 {
        return 1.0;
    }
    // extent < 2^(e+1) when e = floor(log2(extent)).
    let exponent = extent.log2().floor() as i32 + 1;
    2f64.powi((IntegerGrid::BITS - exponent).min(f64::MAX_EXP - 1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_extent_fills_the_grid_without_overflowing_it() {
        for extent in [1e-7, 0.3, 1.0, 1280.0, 1e6, 1e140] {
            let scaled = extent * grid_scale(extent);
            assert!(scaled < 2f64.powi(IntegerGrid::BITS), "{extent}: {scaled}");
            assert!(scaled >= 2f64.powi(IntegerGrid::BITS - 1), "{extent}: {scaled}");
        }
        for extent in [1e-300, f64::MIN_POSITIVE, 5e-324] {
            assert!(grid_scale(extent).is_finite(), "{extent}");
        }
    }

    #[test]
    fn points_round_trip_and_the_box_centre_is_the_origin() {
        let grid = IntegerGrid::fitting(Rect::new(500_000.0, 4_000_000.0, 500_000.004, 4_000_000.002));
        assert_eq!(grid.to_grid(Point::new(500_000.002, 4_000_000.001)), [0, 0]);
        for p in [Point::new(500_000.0, 4_000_000.0), Point::new(500_000.004, 4_000_000.002)] {
            let back = grid.to_point(grid.to_grid(p));
            assert!((back.x - p.x).abs() < 1e-11 && (back.y - p.y).abs() < 1e-11, "{p:?} -> {back:?}");
        }
        assert_eq!(IntegerGrid::fitting(Rect::EMPTY).scale, 1.0);
    }
}
