//! Circles and ellipses (axis-aligned or rotated) and their arcs, validated once at construction.

use core::f64::consts::{PI, TAU};

use crate::{ClipError, MAX_COORDINATE, Point, Rect};

/// Smallest accepted ratio of the short radius to the long one: below it the ellipse's own frame
/// (coordinates divided by each radius) loses the precision the clippers need.
pub const MIN_AXIS_RATIO: f64 = 1e-12;

/// Smallest accepted ratio of the long radius to the centre's largest coordinate magnitude: a
/// smaller ellipse is below the resolution of its own centre's coordinates.
pub const MIN_RADIUS_TO_CENTRE: f64 = 1e-12;

/// An ellipse with centre `c`, radii `rx` and `ry` along its own axes, and its axes turned by
/// `rotation` radians counter-clockwise. A circle is an ellipse with equal radii and no rotation.
///
/// Its points are `P(θ) = c + R(rotation) (rx cos θ, ry sin θ)`: the parameter `θ` runs
/// counter-clockwise, and for a circle it is the polar angle. Construction refuses radii that are
/// not positive and parameters that are not finite (see [`Ellipse::new`]), so every `Ellipse` is
/// usable.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ellipse {
    center: Point,
    rx: f64,
    ry: f64,
    rotation: f64,
    cos: f64,
    sin: f64,
}

fn invalid(parameter: &'static str, value: f64, reason: &'static str) -> ClipError {
    ClipError::InvalidCurve { parameter, value, reason }
}

fn finite_in_range(parameter: &'static str, value: f64) -> Result<(), ClipError> {
    if !value.is_finite() {
        return Err(invalid(parameter, value, "not finite"));
    }
    if value.abs() > MAX_COORDINATE {
        return Err(invalid(parameter, value, "beyond the supported coordinate range"));
    }
    Ok(())
}

impl Ellipse {
    /// An ellipse, or the error saying which parameter is unusable: a non-finite or out-of-range
    /// centre, radius or rotation, a radius that is not positive, a short radius below
    /// [`MIN_AXIS_RATIO`] of the long one, or a long radius below [`MIN_RADIUS_TO_CENTRE`] of the
    /// centre's coordinates. Equal radii make a circle, whose rotation is dropped.
    pub fn new(center: Point, rx: f64, ry: f64, rotation: f64) -> Result<Ellipse, ClipError> {
        finite_in_range("centre x", center.x)?;
        finite_in_range("centre y", center.y)?;
        for (parameter, r) in [("radius x", rx), ("radius y", ry)] {
            finite_in_range(parameter, r)?;
            if r <= 0.0 {
                return Err(invalid(parameter, r, "a radius must be positive"));
            }
        }
        if !rotation.is_finite() {
            return Err(invalid("rotation", rotation, "not finite"));
        }
        let (long, short) = if rx >= ry { (rx, ry) } else { (ry, rx) };
        if short < long * MIN_AXIS_RATIO {
            return Err(invalid("radius ratio", short / long, "the ellipse is too eccentric (short/long below 1e-12)"));
        }
        if long < center.x.abs().max(center.y.abs()) * MIN_RADIUS_TO_CENTRE {
            return Err(invalid("radius", long, "below the resolution of the centre's coordinates"));
        }
        if center.x.abs().max(center.y.abs()) + long > MAX_COORDINATE {
            return Err(invalid("radius", long, "the ellipse reaches beyond the supported coordinate range"));
        }
        let rotation = if rx == ry { 0.0 } else { rotation.rem_euclid(TAU) };
        let (sin, cos) = if rotation == 0.0 { (0.0, 1.0) } else { rotation.sin_cos() };
        Ok(Ellipse { center, rx, ry, rotation, cos, sin })
    }

    /// A circle of radius `r` about `center`.
    pub fn circle(center: Point, r: f64) -> Result<Ellipse, ClipError> {
        Ellipse::new(center, r, r, 0.0)
    }

    /// The centre.
    #[inline]
    pub fn center(&self) -> Point {
        self.center
    }

    /// The radii along the ellipse's own axes, `(rx, ry)`.
    #[inline]
    pub fn radii(&self) -> (f64, f64) {
        (self.rx, self.ry)
    }

    /// The larger radius.
    #[inline]
    pub fn max_radius(&self) -> f64 {
        self.rx.max(self.ry)
    }

    /// The rotation of the axes, radians in `[0, 2π)` (0 for a circle).
    #[inline]
    pub fn rotation(&self) -> f64 {
        self.rotation
    }

    /// True for equal radii.
    #[inline]
    pub fn is_circle(&self) -> bool {
        self.rx == self.ry
    }

    /// The point at parameter `theta` (rounded).
    #[inline]
    pub fn point_at(&self, theta: f64) -> Point {
        let (s, c) = theta.sin_cos();
        let (u, v) = (self.rx * c, self.ry * s);
        Point::new(self.center.x + u * self.cos - v * self.sin, self.center.y + u * self.sin + v * self.cos)
    }

    /// `p` in the ellipse's own frame, scaled so the ellipse is the unit circle (rounded). The map
    /// keeps orientation, and the parameter of a point of the ellipse is the polar angle of its
    /// image.
    #[inline]
    pub fn to_unit(&self, p: Point) -> Point {
        let d = p - self.center;
        Point::new((d.x * self.cos + d.y * self.sin) / self.rx, (-d.x * self.sin + d.y * self.cos) / self.ry)
    }

    /// The implicit function `|to_unit(p)|² - 1`: negative inside, zero on, positive outside
    /// (rounded; near zero its sign is not reliable, see the curve oracle for the careful test).
    #[inline]
    pub fn implicit(&self, p: Point) -> f64 {
        let q = self.to_unit(p);
        q.x * q.x + q.y * q.y - 1.0
    }

    /// The parameter of the point of the ellipse nearest in the unit frame to `p`, in `[0, 2π)`.
    #[inline]
    pub fn parameter_of(&self, p: Point) -> f64 {
        let q = self.to_unit(p);
        q.y.atan2(q.x).rem_euclid(TAU)
    }

    /// Half the width and half the height of the bounding box.
    pub fn half_extents(&self) -> (f64, f64) {
        let (a, b) = (self.rx * self.cos, self.ry * self.sin);
        let (c, d) = (self.rx * self.sin, self.ry * self.cos);
        (a.hypot(b), c.hypot(d))
    }

    /// The axis-aligned bounding box (rounded outwards by a few ulps, so it holds every point
    /// [`Ellipse::point_at`] returns).
    pub fn bounds(&self) -> Rect {
        let (hx, hy) = self.half_extents();
        let slack = 4.0 * f64::EPSILON * (self.center.x.abs().max(self.center.y.abs()) + self.max_radius());
        Rect::new(self.center.x - hx, self.center.y - hy, self.center.x + hx, self.center.y + hy).inflate(slack)
    }

    /// The parameters of the four points where `x` or `y` is extreme, ascending in `[0, 2π)`:
    /// between two consecutive ones the ellipse is monotone in both coordinates, so the box of
    /// an arc's two ends is its bounding box. For an axis-aligned ellipse they are 0, π/2, π, 3π/2.
    pub fn extreme_parameters(&self) -> [f64; 4] {
        if self.sin == 0.0 || self.cos == 0.0 {
            // Axes along x and y (every circle): no trigonometry needed.
            return [0.0, 0.5 * PI, PI, 1.5 * PI];
        }
        // x'(θ) = 0 and y'(θ) = 0 with x(θ) = cx + rx cos φ cos θ - ry sin φ sin θ, y likewise.
        let tx = (-self.ry * self.sin).atan2(self.rx * self.cos).rem_euclid(TAU);
        let ty = (self.ry * self.cos).atan2(self.rx * self.sin).rem_euclid(TAU);
        let mut t = [tx, ty, (tx + PI).rem_euclid(TAU), (ty + PI).rem_euclid(TAU)];
        t.sort_by(f64::total_cmp);
        t
    }

    /// The ellipse's area, `π rx ry`.
    #[inline]
    pub fn area(&self) -> f64 {
        PI * self.rx * self.ry
    }
}

/// An arc of an ellipse: parameters from `start` to `start + sweep`, counter-clockwise. A sweep of
/// 2π is the whole closed ellipse.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EllipseArc {
    ellipse: Ellipse,
    start: f64,
    sweep: f64,
}

impl EllipseArc {
    /// An arc, or [`ClipError::InvalidCurve`] for a non-finite start or a sweep outside `(0, 2π]`.
    /// The start is reduced to `[0, 2π)`.
    pub fn new(ellipse: Ellipse, start: f64, sweep: f64) -> Result<EllipseArc, ClipError> {
        if !start.is_finite() {
            return Err(invalid("start", start, "not finite"));
        }
        if !sweep.is_finite() {
            return Err(invalid("sweep", sweep, "not finite"));
        }
        if sweep <= 0.0 || sweep > TAU {
            return Err(invalid("sweep", sweep, "an arc's sweep must be in (0, 2π]"));
        }
        let start = if sweep == TAU { 0.0 } else { start.rem_euclid(TAU) };
        Ok(EllipseArc { ellipse, start, sweep })
    }

    /// The whole closed ellipse (start 0, sweep 2π).
    pub fn full(ellipse: Ellipse) -> EllipseArc {
        EllipseArc { ellipse, start: 0.0, sweep: TAU }
    }

    /// The ellipse it lies on.
    #[inline]
    pub fn ellipse(&self) -> &Ellipse {
        &self.ellipse
    }

    /// First parameter, in `[0, 2π)`.
    #[inline]
    pub fn start(&self) -> f64 {
        self.start
    }

    /// Parameter span, in `(0, 2π]`.
    #[inline]
    pub fn sweep(&self) -> f64 {
        self.sweep
    }

    /// Last parameter, `start + sweep` (may exceed 2π).
    #[inline]
    pub fn end(&self) -> f64 {
        self.start + self.sweep
    }

    /// True for the whole closed ellipse.
    #[inline]
    pub fn is_closed(&self) -> bool {
        self.sweep == TAU
    }

    /// The bounding box of the arc (its ends and the extreme points it passes).
    pub fn bounds(&self) -> Rect {
        if self.is_closed() {
            return self.ellipse.bounds();
        }
        let e = &self.ellipse;
        let mut r = Rect::from_points(e.point_at(self.start), e.point_at(self.end()));
        for t in e.extreme_parameters() {
            if self.contains_parameter(t) {
                r = r.including(e.point_at(t));
            }
        }
        let slack = 4.0 * f64::EPSILON * (e.center.x.abs().max(e.center.y.abs()) + e.max_radius());
        r.inflate(slack)
    }

    /// True when parameter `theta` (any turn) lies on the arc.
    #[inline]
    pub fn contains_parameter(&self, theta: f64) -> bool {
        (theta - self.start).rem_euclid(TAU) <= self.sweep
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_parameters_are_typed_errors() {
        let c = Point::new(0.0, 0.0);
        for (rx, ry) in [(0.0, 1.0), (-1.0, 1.0), (1.0, f64::NAN), (f64::INFINITY, 1.0), (1.0, 1e-13)] {
            assert!(matches!(Ellipse::new(c, rx, ry, 0.0), Err(ClipError::InvalidCurve { .. })), "{rx} {ry}");
        }
        assert!(Ellipse::new(Point::new(f64::NAN, 0.0), 1.0, 1.0, 0.0).is_err());
        assert!(Ellipse::new(c, 1.0, 2.0, f64::NAN).is_err());
        assert!(Ellipse::new(Point::new(1e9, 0.0), 1e-4, 1e-4, 0.0).is_err());
        let e = Ellipse::circle(c, 1.0).unwrap();
        for sweep in [0.0, -1.0, 7.0, f64::NAN] {
            assert!(EllipseArc::new(e, 0.0, sweep).is_err(), "{sweep}");
        }
        assert!(EllipseArc::new(e, f64::INFINITY, 1.0).is_err());
    }

    #[test]
    fn points_frames_and_extremes_agree() {
        let e = Ellipse::new(Point::new(3.0, -2.0), 5.0, 2.0, 0.7).unwrap();
        for k in 0..16 {
            let t = f64::from(k) * 0.4;
            let p = e.point_at(t);
            assert!(e.implicit(p).abs() < 1e-14);
            assert!((e.parameter_of(p) - t.rem_euclid(TAU)).abs() < 1e-12);
            assert!(e.bounds().contains(p));
        }
        let b = e.bounds();
        let xs: Vec<f64> = e.extreme_parameters().iter().map(|&t| e.point_at(t).x).collect();
        let (lo, hi) = xs.iter().fold((f64::MAX, f64::MIN), |(l, h), &x| (l.min(x), h.max(x)));
        assert!((lo - b.min.x).abs() < 1e-12 && (hi - b.max.x).abs() < 1e-12);
        let axis = Ellipse::new(Point::ZERO, 2.0, 1.0, 0.0).unwrap();
        assert_eq!(axis.extreme_parameters(), [0.0, PI / 2.0, PI, 1.5 * PI]);
    }

    #[test]
    fn arcs_contain_their_parameters_and_bounds() {
        let e = Ellipse::circle(Point::ZERO, 1.0).unwrap();
        let a = EllipseArc::new(e, 1.5 * PI, PI).unwrap();
        assert!(a.contains_parameter(0.0) && a.contains_parameter(-0.1) && !a.contains_parameter(PI));
        let b = a.bounds();
        assert!((b.max.x - 1.0).abs() < 1e-12 && b.min.x.abs() < 1e-12);
    }
}
