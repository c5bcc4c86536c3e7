//! A segment's line as a parameter axis: `t` of points on it and their exact place relative to the ends.

use crate::predicates::{orient_sign, orient2d_inline as orient2d};
use crate::{Point, Rect, Segment};

/// Where a point of the segment's line lies relative to the segment, decided exactly.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Along {
    /// `t < 0`.
    Before,
    /// `t = 0`: the start point.
    AtStart,
    /// `0 < t < 1`.
    Inside,
    /// `t = 1`: the end point.
    AtEnd,
    /// `t > 1`.
    After,
}

/// The directed line of a segment `a -> b` of positive length, with the parameter positions along
/// it are measured in: `P(t) = o + t (e - o)` over the part `o -> e` of the segment they are
/// wanted on, the segment itself (`t = 0` at `a`, `t = 1` at `b`) unless it reaches far past the
/// window ([`LineFrame::near`]). Places relative to `a` and `b` are always exact.
#[derive(Clone, Copy, Debug)]
pub struct LineFrame {
    /// The segment's start point.
    pub a: Point,
    /// The segment's end point.
    pub b: Point,
    /// Where `t = 0`: `a`, or where the segment's part near the window starts.
    o: Point,
    /// Where `t = 1`: `b`, or where that part ends.
    e: Point,
    d: Point,
    inv_len2: f64,
    /// True when `|dx| >= |dy|`: points on the line are ordered by x, else by y (exact either way).
    x_major: bool,
}

impl LineFrame {
    /// The frame of `s`, `t` along all of it; `s` must have positive length.
    #[inline]
    pub fn new(s: Segment) -> LineFrame {
        let d = s.b - s.a;
        LineFrame { a: s.a, b: s.b, o: s.a, e: s.b, d, inv_len2: 1.0 / d.dot(d), x_major: d.x.abs() >= d.y.abs() }
    }

    /// The frame of `s` for a window of bounding box `window`: `t` along `s`, or, where `s`
    /// reaches far past the window, along its part near it ([`Segment::part_near`]), so that
    /// crossings a window's width apart stay apart in `t` however long the segment is.
    #[inline]
    pub fn near(s: Segment, window: &Rect) -> LineFrame {
        let mut frame = LineFrame::new(s);
        if s.reaches_far_past(window) {
            let part = s.part_near(window);
            let d = part.b - part.a;
            (frame.o, frame.e, frame.d, frame.inv_len2) = (part.a, part.b, d, 1.0 / d.dot(d));
        }
        frame
    }

    /// True when `t` runs over the whole segment (`t = 0` at `a`, `t = 1` at `b`).
    #[inline]
    fn whole(&self) -> bool {
        self.o == self.a && self.e == self.b
    }

    /// The parameter of `p` projected onto the line (rounded; exactness lives in [`Self::place`]).
    #[inline]
    pub fn param(&self, p: Point) -> f64 {
        ((p.x - self.o.x) * self.d.x + (p.y - self.o.y) * self.d.y) * self.inv_len2
    }

    /// The exact place of `p`, a point known to lie on the line, relative to the segment: on the line
    /// one coordinate is monotone in `t`, so comparing coordinates is exact.
    #[inline]
    pub fn place(&self, p: Point) -> Along {
        let (k, ka, kb) = if self.x_major { (p.x, self.a.x, self.b.x) } else { (p.y, self.a.y, self.b.y) };
        let (k, ka, kb) = if kb > ka { (k, ka, kb) } else { (-k, -ka, -kb) };
        if k < ka {
            Along::Before
        } else if k == ka {
            Along::AtStart
        } else if k < kb {
            Along::Inside
        } else if k == kb {
            Along::AtEnd
        } else {
            Along::After
        }
    }

    /// Where the line crosses the edge `p -> q`, whose ends lie strictly on opposite sides of the
    /// line, `fp` and `fq` being the line function there (exact signs). The place is exact: along
    /// the line the edge's own line function grows with the sign of `fp`, so its signs at `a` and
    /// `b` place the crossing. The parameter interpolates the ends' parameters by `fp / (fp - fq)`,
    /// whose rounding does not grow with the distance from `a`, and which tends to the parameter
    /// of `p` (of `q`) as `p` (`q`) nears the line.
    #[inline]
    pub fn edge_crossing(&self, p: Point, q: Point, fp: f64, fq: f64) -> (Along, f64) {
        // Only the signs of the edge's function at the ends place the crossing: the sign-only
        // predicate spares the accurate magnitude's expansion where the ends lie near the edge's
        // line (short edges of large windows, seen from afar).
        let ga = orient_sign(p, q, self.a);
        let ahead_positive = fp > 0.0;
        if ga == 0.0 {
            return (Along::AtStart, 0.0);
        }
        if (ga > 0.0) == ahead_positive {
            return (Along::Before, 0.0);
        }
        let gb = orient_sign(p, q, self.b);
        if gb == 0.0 {
            (Along::AtEnd, 1.0)
        } else if (gb > 0.0) == ahead_positive {
            (Along::Inside, self.crossing_param(p, q, fp, fq))
        } else {
            (Along::After, 1.0)
        }
    }

    /// The parameter of [`Self::edge_crossing`]'s crossing, for a caller that knows it lies inside
    /// the segment: the ends' parameters interpolated by `fp / (fp - fq)`, clamped to `[0, 1]`.
    #[inline]
    pub fn crossing_param(&self, p: Point, q: Point, fp: f64, fq: f64) -> f64 {
        let (tp, tq) = (self.param(p), self.param(q));
        (tp + (tq - tp) * (fp / (fp - fq))).clamp(0.0, 1.0)
    }

    /// As [`Self::edge_crossing`] when the line function at the ends is not at hand (only the side
    /// of `p`): the parameter is then `ga / (ga - gb)` from the edge function at `a` and `b`.
    #[inline]
    pub fn edge_crossing_by_edge(&self, p: Point, q: Point, p_left: bool) -> (Along, f64) {
        let ga = orient2d(p, q, self.a);
        if ga == 0.0 {
            return (Along::AtStart, 0.0);
        }
        if (ga > 0.0) == p_left {
            return (Along::Before, 0.0);
        }
        let gb = orient2d(p, q, self.b);
        if gb == 0.0 {
            (Along::AtEnd, 1.0)
        } else if (gb > 0.0) == p_left {
            if !self.whole() {
                // The part's ends lie on the line only to within rounding at the window's
                // magnitude: the edge's function at them can put the crossing with a nearly
                // parallel edge anywhere along the part. It is placed along the edge instead.
                let (fp, fq) = (orient2d(self.a, self.b, p), orient2d(self.a, self.b, q));
                return (Along::Inside, self.crossing_param(p, q, fp, fq));
            }
            let t = ga / (ga - gb);
            (Along::Inside, if t.is_nan() { 0.5 } else { t.clamp(0.0, 1.0) })
        } else {
            (Along::After, 1.0)
        }
    }

    /// The point at parameter `t`, exactly an endpoint (of the part `t` runs over) at 0 and 1.
    #[inline]
    pub fn at(&self, t: f64) -> Point {
        if t <= 0.0 {
            self.o
        } else if t >= 1.0 {
            self.e
        } else {
            self.o.lerp(self.e, t)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(ax: f64, ay: f64, bx: f64, by: f64) -> LineFrame {
        LineFrame::new(Segment::new(Point::new(ax, ay), Point::new(bx, by)))
    }

    #[test]
    fn places_points_on_the_line_in_either_direction() {
        let f = frame(0.0, 0.0, 4.0, 2.0);
        assert_eq!(f.place(Point::new(-2.0, -1.0)), Along::Before);
        assert_eq!(f.place(Point::new(0.0, 0.0)), Along::AtStart);
        assert_eq!(f.place(Point::new(2.0, 1.0)), Along::Inside);
        assert_eq!(f.place(Point::new(4.0, 2.0)), Along::AtEnd);
        assert_eq!(f.place(Point::new(6.0, 3.0)), Along::After);
        let g = frame(0.0, 5.0, 0.0, 1.0);
        assert_eq!(g.place(Point::new(0.0, 6.0)), Along::Before);
        assert_eq!(g.place(Point::new(0.0, 3.0)), Along::Inside);
        assert_eq!(g.place(Point::new(0.0, 0.0)), Along::After);
        assert_eq!(g.param(Point::new(0.0, 3.0)), 0.5);
    }

    #[test]
    fn places_edge_crossings_exactly() {
        let f = frame(0.0, 0.0, 4.0, 0.0);
        let cross = |x: f64| f.edge_crossing(Point::new(x, 1.0), Point::new(x, -1.0), 4.0, -4.0);
        assert_eq!(cross(-1.0), (Along::Before, 0.0));
        assert_eq!(cross(0.0), (Along::AtStart, 0.0));
        assert_eq!(cross(1.0), (Along::Inside, 0.25));
        assert_eq!(cross(4.0), (Along::AtEnd, 1.0));
        assert_eq!(cross(5.0), (Along::After, 1.0));
        // The same edge walked the other way.
        assert_eq!(f.edge_crossing(Point::new(3.0, -1.0), Point::new(3.0, 1.0), -4.0, 4.0), (Along::Inside, 0.75));
    }
}
