//! Vatti's trapezoid: a horizontal slab of the clipped region, ready for a fill loop.

use crate::{Point, Ring};

/// A trapezoid with horizontal top and bottom, in the paper's form
/// `(x_left, x_right, y_bottom, dx_left, dx_right, y_top)`: `x_left` and `x_right` are the side
/// edges' x at `y_bottom`; `dx_left` and `dx_right` their change in x per unit of y.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Trapezoid {
    /// x of the left side at `y_bottom`.
    pub x_left: f64,
    /// x of the right side at `y_bottom`.
    pub x_right: f64,
    /// Bottom y.
    pub y_bottom: f64,
    /// Change of the left side's x per unit y.
    pub dx_left: f64,
    /// Change of the right side's x per unit y.
    pub dx_right: f64,
    /// Top y.
    pub y_top: f64,
}

impl Trapezoid {
    /// Height.
    #[inline]
    pub fn height(&self) -> f64 {
        self.y_top - self.y_bottom
    }

    /// x of the left side at height `y`.
    #[inline]
    pub fn x_left_at(&self, y: f64) -> f64 {
        self.x_left + self.dx_left * (y - self.y_bottom)
    }

    /// x of the right side at height `y`.
    #[inline]
    pub fn x_right_at(&self, y: f64) -> f64 {
        self.x_right + self.dx_right * (y - self.y_bottom)
    }

    /// Area: height times the mean of the bottom and top widths.
    #[inline]
    pub fn area(&self) -> f64 {
        let h = self.height();
        let bottom = self.x_right - self.x_left;
        let top = self.x_right_at(self.y_top) - self.x_left_at(self.y_top);
        0.5 * h * (bottom + top)
    }

    /// The trapezoid as a counter-clockwise ring (three vertices when a side has zero length).
    pub fn to_ring(&self) -> Ring {
        let corners = [
            Point::new(self.x_left, self.y_bottom),
            Point::new(self.x_right, self.y_bottom),
            Point::new(self.x_right_at(self.y_top), self.y_top),
            Point::new(self.x_left_at(self.y_top), self.y_top),
        ];
        Ring::new(corners.to_vec()).without_repeats()
    }
}
