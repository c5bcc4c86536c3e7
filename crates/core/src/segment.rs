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

    /// The piece between parameters `ta` and `tb`, ending exactly at `a` where a parameter is 0
    /// and at `b` where it is 1 (so a piece reaching an end point keeps it bit for bit).
    pub fn piece(&self, ta: f64, tb: f64) -> Segment {
        let point = |t: f64| {
            if t == 0.0 {
                self.a
            } else if t == 1.0 {
                self.b
            } else {
                self.at(t)
            }
        };
        Segment::new(point(ta), point(tb))
    }

    /// The parameter intervals of this segment that `pieces` cover, where the pieces lie on it up
    /// to rounding (another library's clipped output): each piece's ends projected onto the
    /// segment and clamped to [0, 1], sorted, overlapping or touching intervals merged, and
    /// zero-length ones dropped.
    pub fn covered_intervals(&self, pieces: impl IntoIterator<Item = Segment>) -> Vec<(f64, f64)> {
        let mut intervals: Vec<(f64, f64)> = pieces
            .into_iter()
            .map(|p| {
                let (t0, t1) = (self.param_of(p.a).clamp(0.0, 1.0), self.param_of(p.b).clamp(0.0, 1.0));
                (t0.min(t1), t0.max(t1))
            })
            .filter(|(ta, tb)| tb > ta)
            .collect();
        intervals.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut merged: Vec<(f64, f64)> = Vec::with_capacity(intervals.len());
        for (ta, tb) in intervals {
            match merged.last_mut() {
                Some(last) if ta <= last.1 => last.1 = last.1.max(tb),
                _ => merged.push((ta, tb)),
            }
        }
        merged
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
