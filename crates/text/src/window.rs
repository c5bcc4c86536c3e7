//! The clip window as text clipping reads it: any valid polygons under non-zero, closed, with exact point and box tests.

use clip_core::predicates::on_segment;
use clip_core::{
    Point, Polygons, Rect, Segment, SegmentIntersection, segment_intersection, validate_window, winding_number,
};

use crate::error::TextError;

/// A checked window. Its region is read under non-zero (the glyphs' rule), closed: a point on an
/// edge is inside.
#[derive(Clone, Debug, PartialEq)]
pub struct TextWindow {
    polygons: Polygons,
    bounds: Rect,
}

impl TextWindow {
    /// Checks `window` ([`clip_core::validate_window`]: at least one ring, finite, positive extent).
    pub fn new(window: &Polygons) -> Result<TextWindow, TextError> {
        validate_window(window)?;
        Ok(TextWindow { polygons: window.clone(), bounds: window.bounds() })
    }

    /// The window's rings.
    pub fn polygons(&self) -> &Polygons {
        &self.polygons
    }

    /// The window's bounding box.
    pub fn bounds(&self) -> Rect {
        self.bounds
    }

    /// True when `p` is in the closed window (exact winding number; on an edge counts as in).
    pub fn covers(&self, p: Point) -> bool {
        self.bounds.contains(p) && winding_number(p, &self.polygons).is_none_or(|w| w != 0)
    }

    /// True when the closed box `b` lies in the closed window: no window edge meets the open box
    /// (no vertex strictly inside, no edge crossing a side, no edge touching two sides that do
    /// not share a line: it would run through the inside), so the open box is wholly in or out,
    /// which its centre decides; and its corners are in. Exact, for windows whose edges bound
    /// their region (rings that do not overlap). An empty box (a glyph that draws nothing) is in.
    pub fn contains_box(&self, b: Rect) -> bool {
        if b.is_empty() {
            return true;
        }
        if !self.bounds.contains_rect(&b) {
            return false;
        }
        let corners = [b.min, Point::new(b.max.x, b.min.y), b.max, Point::new(b.min.x, b.max.y)];
        if !corners.iter().all(|&c| self.covers(c)) {
            return false;
        }
        let strictly_inside = |p: Point| b.min.x < p.x && p.x < b.max.x && b.min.y < p.y && p.y < b.max.y;
        if self.polygons.points().any(|&p| strictly_inside(p)) {
            return false;
        }
        let sides: Vec<Segment> = (0..4).map(|k| Segment::new(corners[k], corners[(k + 1) % 4])).collect();
        let on_box = |p: Point| {
            (p.x == b.min.x || p.x == b.max.x) && b.min.y <= p.y && p.y <= b.max.y
                || (p.y == b.min.y || p.y == b.max.y) && b.min.x <= p.x && p.x <= b.max.x
        };
        let share_a_side = |p: Point, q: Point| {
            (p.x == q.x && (p.x == b.min.x || p.x == b.max.x)) || (p.y == q.y && (p.y == b.min.y || p.y == b.max.y))
        };
        let meets_open_box = |e: Segment| {
            if !e.bounds().intersects(&b) {
                return false;
            }
            if sides.iter().any(|&s| matches!(segment_intersection(e, s), SegmentIntersection::Crossing(_))) {
                return true;
            }
            let contacts: Vec<Point> = [e.a, e.b]
                .into_iter()
                .filter(|&p| on_box(p))
                .chain(corners.iter().copied().filter(|&c| on_segment(c, e)))
                .collect();
            contacts.iter().enumerate().any(|(i, &p)| contacts[i + 1..].iter().any(|&q| p != q && !share_a_side(p, q)))
        };
        if self.polygons.edges().any(meets_open_box) {
            return false;
        }
        let centre = Point::new(0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y));
        winding_number(centre, &self.polygons).is_some_and(|w| w != 0)
    }
}
