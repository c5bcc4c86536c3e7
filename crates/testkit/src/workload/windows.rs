//! Clip operands constrained to a window kind: a random convex polygon or an axis-aligned
//! rectangle that overlaps the subject.

use super::shapes::{convex, convex_hull};
use clip_core::{Point, Polygons, Rect, Ring};
use rand::Rng;
use rand_pcg::Pcg64;

/// Centre and half-sizes of a box overlapping `subject`: the centre inside the middle half of
/// the subject's bounding box, the half-sizes 15%-60% of its width and height.
fn overlapping_box(rng: &mut Pcg64, subject: &Rect) -> (Point, f64, f64) {
    let (w, h) = (subject.width().max(1.0), subject.height().max(1.0));
    let c =
        Point::new(subject.min.x + w * rng.random_range(0.25..0.75), subject.min.y + h * rng.random_range(0.25..0.75));
    (c, w * rng.random_range(0.15..0.6), h * rng.random_range(0.15..0.6))
}

/// An axis-aligned rectangle overlapping `subject`; on integer corners when `integer`.
pub(crate) fn rectangle_over(rng: &mut Pcg64, subject: &Rect, integer: bool) -> Polygons {
    let (c, hw, hh) = overlapping_box(rng, subject);
    let mut r = Rect::new(c.x - hw, c.y - hh, c.x + hw, c.y + hh);
    if integer {
        r = Rect::new(r.min.x.floor(), r.min.y.floor(), r.max.x.ceil(), r.max.y.ceil());
    }
    Polygons::from(r)
}

/// A strictly convex polygon of 4-16 vertices overlapping `subject`; with `integer`, the convex
/// hull of its vertices rounded to integers (a rectangle if that hull collapses).
pub(crate) fn convex_over(rng: &mut Pcg64, subject: &Rect, integer: bool) -> Polygons {
    let (c, hw, hh) = overlapping_box(rng, subject);
    let n = rng.random_range(4..=16);
    let ring = convex(rng, n, c, hw, hh);
    if !integer {
        return Polygons::from(ring);
    }
    let rounded: Vec<Point> = ring.points.iter().map(|p| Point::new(p.x.round(), p.y.round())).collect();
    let hull = convex_hull(&rounded);
    if hull.len() >= 3 { Polygons::from(Ring::new(hull)) } else { rectangle_over(rng, subject, true) }
}
