//! A directed line segment from `a` to `b`.

use crate::{Point, Rect};

/// How many times a window's extent a segment may reach before positions along it near the
/// window are measured on its part near the window ([`Segment::part_near`]): below it, a
/// parameter along the whole segment still resolves the window to well under 1e-9 of its size.
pub const FAR_REACH: f64 = 64.0;

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

    /// True when the segment reaches more than [`FAR_REACH`] times `bounds`' extent along either
    /// axis: then positions along it near `bounds` are measured on [`Segment::part_near`].
    #[inline]
    pub fn reaches_far_past(&self, bounds: &Rect) -> bool {
        let reach = (self.b.x - self.a.x).abs().max((self.b.y - self.a.y).abs());
        reach > FAR_REACH * bounds.extent()
    }

    /// The part of the segment that positions near `bounds` are measured along: the segment
    /// itself, unless it [reaches far past](Segment::reaches_far_past) `bounds`; then its part
    /// inside `bounds` grown by its extent on every side, from where its line enters that box
    /// (or from `a`, if `a` is inside) to where it leaves it (or to `b`). Its direction is the
    /// segment's.
    ///
    /// A parameter along a whole segment resolves about 2^-53 of its length (and line clippers
    /// take crossings within [`crate::PARAMETER_SNAP`] of it for one), so with ends at ±1e17 a
    /// window 10 wide is less than one step of it. The ends of this part are where the line
    /// crosses the box's sides, placed from the line function at the box's corners (accurate to
    /// an ulp however far the segment's ends are) along those sides: they lie on the line to
    /// within rounding at the box's own magnitude. A line that misses the box, or a segment that
    /// ends before reaching it, gives the segment itself (it meets nothing there).
    pub fn part_near(&self, bounds: &Rect) -> Segment {
        if !self.reaches_far_past(bounds) || bounds.extent() == 0.0 {
            return *self;
        }
        let e = bounds.extent();
        let (lo, hi) = (Point::new(bounds.min.x - e, bounds.min.y - e), Point::new(bounds.max.x + e, bounds.max.y + e));
        let d = self.b - self.a;
        let crossings: Vec<Point> = if d.y == 0.0 {
            // An axis-parallel line crosses the box at its own y (or x), exactly.
            let on = (lo.y..=hi.y).contains(&self.a.y);
            if on { vec![Point::new(lo.x, self.a.y), Point::new(hi.x, self.a.y)] } else { Vec::new() }
        } else if d.x == 0.0 {
            let on = (lo.x..=hi.x).contains(&self.a.x);
            if on { vec![Point::new(self.a.x, lo.y), Point::new(self.a.x, hi.y)] } else { Vec::new() }
        } else {
            let corners = [lo, Point::new(hi.x, lo.y), hi, Point::new(lo.x, hi.y)];
            let f = corners.map(|c| crate::predicates::orient2d(self.a, self.b, c));
            (0..4)
                .filter_map(|i| {
                    let (c, next, fc, fnext) = (corners[i], corners[(i + 1) % 4], f[i], f[(i + 1) % 4]);
                    if fc == 0.0 {
                        Some(c)
                    } else if fnext != 0.0 && (fc > 0.0) != (fnext > 0.0) {
                        Some(c.lerp(next, fc / (fc - fnext)))
                    } else {
                        None
                    }
                })
                .collect()
        };
        // Ordered along the segment by its major coordinate (monotone along the line).
        let key = |p: &Point| if d.x.abs() >= d.y.abs() { p.x * d.x.signum() } else { p.y * d.y.signum() };
        let by_key = |p: &&Point, q: &&Point| key(p).total_cmp(&key(q));
        let (Some(&enter), Some(&leave)) = (crossings.iter().min_by(by_key), crossings.iter().max_by(by_key)) else {
            return *self;
        };
        let start = if key(&self.a) > key(&enter) { self.a } else { enter };
        let end = if key(&self.b) < key(&leave) { self.b } else { leave };
        if key(&start) >= key(&end) {
            return *self;
        }
        Segment::new(start, end)
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
