//! Axis-aligned rectangles, used as windows and as bounding boxes.

use crate::{Point, Ring};

/// An axis-aligned rectangle `[min.x, max.x] x [min.y, max.y]`. An empty box has `min > max`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    /// Lower-left corner.
    pub min: Point,
    /// Upper-right corner.
    pub max: Point,
}

impl Rect {
    /// The empty box: the identity of [`Rect::union`].
    pub const EMPTY: Rect =
        Rect { min: Point::new(f64::INFINITY, f64::INFINITY), max: Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY) };

    /// Makes the box spanned by two corners, in any order.
    #[inline]
    pub fn from_points(p: Point, q: Point) -> Rect {
        Rect { min: Point::new(p.x.min(q.x), p.y.min(q.y)), max: Point::new(p.x.max(q.x), p.y.max(q.y)) }
    }

    /// Makes a box from its bounds.
    #[inline]
    pub const fn new(min_x: f64, min_y: f64, max_x: f64, max_y: f64) -> Rect {
        Rect { min: Point::new(min_x, min_y), max: Point::new(max_x, max_y) }
    }

    /// The bounding box of some points ([`Rect::EMPTY`] for none).
    pub fn bounding<'a>(points: impl IntoIterator<Item = &'a Point>) -> Rect {
        points.into_iter().fold(Rect::EMPTY, |r, &p| r.including(p))
    }

    /// True when the box holds no point.
    #[inline]
    pub fn is_empty(&self) -> bool {
        !(self.min.x <= self.max.x && self.min.y <= self.max.y)
    }

    /// Width (0 for an empty box).
    #[inline]
    pub fn width(&self) -> f64 {
        if self.is_empty() { 0.0 } else { self.max.x - self.min.x }
    }

    /// Height (0 for an empty box).
    #[inline]
    pub fn height(&self) -> f64 {
        if self.is_empty() { 0.0 } else { self.max.y - self.min.y }
    }

    /// Area (0 for an empty box).
    #[inline]
    pub fn area(&self) -> f64 {
        self.width() * self.height()
    }

    /// The larger of width and height.
    #[inline]
    pub fn extent(&self) -> f64 {
        self.width().max(self.height())
    }

    /// The smallest box holding this one and `p`.
    #[inline]
    pub fn including(self, p: Point) -> Rect {
        Rect {
            min: Point::new(self.min.x.min(p.x), self.min.y.min(p.y)),
            max: Point::new(self.max.x.max(p.x), self.max.y.max(p.y)),
        }
    }

    /// The smallest box holding both.
    #[inline]
    pub fn union(self, other: Rect) -> Rect {
        Rect {
            min: Point::new(self.min.x.min(other.min.x), self.min.y.min(other.min.y)),
            max: Point::new(self.max.x.max(other.max.x), self.max.y.max(other.max.y)),
        }
    }

    /// True when `p` lies in the closed box.
    #[inline]
    pub fn contains(&self, p: Point) -> bool {
        p.x >= self.min.x && p.x <= self.max.x && p.y >= self.min.y && p.y <= self.max.y
    }

    /// True when `other` lies in the closed box (an empty `other` lies in any box).
    #[inline]
    pub fn contains_rect(&self, other: &Rect) -> bool {
        other.is_empty() || (self.contains(other.min) && self.contains(other.max))
    }

    /// The box grown by `by` on every side (an empty box stays empty).
    #[inline]
    pub fn expanded(&self, by: f64) -> Rect {
        if self.is_empty() {
            return *self;
        }
        Rect { min: Point::new(self.min.x - by, self.min.y - by), max: Point::new(self.max.x + by, self.max.y + by) }
    }

    /// True when the closed boxes share a point.
    #[inline]
    pub fn intersects(&self, other: &Rect) -> bool {
        self.min.x <= other.max.x && other.min.x <= self.max.x && self.min.y <= other.max.y && other.min.y <= self.max.y
    }

    /// Cohen-Sutherland's four-bit code of `p` against the closed box: 0 inside or on it, one bit
    /// per side it lies strictly beyond (left, right, below, above).
    #[inline]
    pub fn outcode(&self, p: Point) -> u8 {
        (p.x < self.min.x) as u8
            | ((p.x > self.max.x) as u8) << 1
            | ((p.y < self.min.y) as u8) << 2
            | ((p.y > self.max.y) as u8) << 3
    }

    /// Cohen-Sutherland's trivial reject: both ends of the segment `a b` lie strictly beyond the
    /// same side, so it cannot touch the box. Exact (comparisons of input coordinates).
    ///
    /// The outcodes' common bit, read side by side: both ends beyond a side is the nearer end
    /// beyond it. Eight comparisons and shifts become four min/max and four comparisons, with
    /// no branch (ends are finite, as validated).
    #[inline]
    pub fn rejects_segment(&self, a: Point, b: Point) -> bool {
        (a.x.max(b.x) < self.min.x)
            | (a.x.min(b.x) > self.max.x)
            | (a.y.max(b.y) < self.min.y)
            | (a.y.min(b.y) > self.max.y)
    }

    /// The indices of the segments of positive length that [`Rect::rejects_segment`] keeps, in
    /// order, into `kept` (cleared first). The line clippers run it over a whole batch before any
    /// other work: with no branch on a segment's fate (the index is always written, the length
    /// grows by the test's outcome), randomly placed segments cost no mispredicted branch here,
    /// where a per-segment early out mispredicts on about a third of them.
    pub fn keep_meeting(&self, segments: &[crate::Segment], kept: &mut Vec<usize>) {
        kept.clear();
        kept.resize(segments.len() + 1, 0);
        let mut n = 0;
        for (i, s) in segments.iter().enumerate() {
            kept[n] = i;
            let zero_length = (s.a.x == s.b.x) & (s.a.y == s.b.y);
            n += usize::from(!(self.rejects_segment(s.a, s.b) | zero_length));
        }
        kept.truncate(n);
    }

    /// The box grown by `d` on every side.
    #[inline]
    pub fn inflate(&self, d: f64) -> Rect {
        Rect::new(self.min.x - d, self.min.y - d, self.max.x + d, self.max.y + d)
    }

    /// The box as a counter-clockwise ring starting at the lower-left corner.
    pub fn to_ring(&self) -> Ring {
        Ring::new(vec![self.min, Point::new(self.max.x, self.min.y), self.max, Point::new(self.min.x, self.max.y)])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Segment;

    #[test]
    fn keep_meeting_keeps_touching_segments_in_order_and_drops_points() {
        let r = Rect::new(0.0, 0.0, 1.0, 1.0);
        let s = |ax, ay, bx, by| Segment::new(Point::new(ax, ay), Point::new(bx, by));
        let segments = [
            s(-2.0, 0.5, -1.0, 0.5), // left of the box
            s(-1.0, 1.0, 0.0, 2.0),  // past the corner, beyond no single side
            s(0.5, 0.5, 0.5, 0.5),   // a point inside
            s(1.0, -1.0, 1.0, 2.0),  // along the right side
            s(0.0, 2.0, 1.0, 1.5),   // above
            s(-1.0, -1.0, 2.0, 2.0), // through
        ];
        let mut kept = vec![7];
        r.keep_meeting(&segments, &mut kept);
        assert_eq!(kept, vec![1, 3, 5]);
        r.keep_meeting(&[], &mut kept);
        assert!(kept.is_empty());
    }
}
