//! A directed line segment from `a` to `b`.

use crate::{Point, Rect};

/// A directed segment `P(t) = a + t (b - a)`, `t` in `[0, 1]`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Segment {
    /// Start point, `t = 0`.
    pub a: Point,
    /// End point, `t = 1`.
    pub b: Point,
}

impl Segment {
    /// Makes a segment.
    #[inline]
    pub const fn new(a: Point, b: Point) -> Segment {
        Segment { a, b }
    }

    /// The point at parameter `t`.
    #[inline]
    pub fn at(&self, t: f64) -> Point {
        self.a.lerp(self.b, t)
    }

    /// True when both endpoints coincide.
    #[inline]
    pub fn is_degenerate(&self) -> bool {
        self.a == self.b
    }

    /// Euclidean length.
    #[inline]
    pub fn length(&self) -> f64 {
        self.a.distance(self.b)
    }

    /// The same segment walked the other way.
    #[inline]
    pub fn reversed(&self) -> Segment {
        Segment::new(self.b, self.a)
    }

    /// The axis-aligned bounding box.
    #[inline]
    pub fn bounds(&self) -> Rect {
        Rect::from_points(self.a, self.b)
    }

    /// The parameter of `p` projected onto the segment's line (not clamped).
    /// For a degenerate segment it is 0.
    #[inline]
    pub fn param_of(&self, p: Point) -> f64 {
        let d = self.b - self.a;
        let len2 = d.dot(d);
        if len2 == 0.0 { 0.0 } else { (p - self.a).dot(d) / len2 }
    }
}
