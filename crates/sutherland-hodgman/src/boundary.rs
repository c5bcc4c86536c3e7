//! One window edge as a clip boundary: the closed half-plane to its left, decided exactly.

use clip_core::Point;
use clip_core::predicates::orient2d;

/// A directed edge of a counter-clockwise convex window. Its inside is the closed half-plane to
/// the left of `from -> to`; points on the line count as inside ("inside or on", as the notes say).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Boundary {
    /// Start of the window edge.
    pub from: Point,
    /// End of the window edge.
    pub to: Point,
}

/// Where a point lies relative to a boundary, with the exact signed value it was decided from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Side {
    /// `orient2d(from, to, p)`: its sign is exact (positive inside, zero on the line, negative
    /// outside); its magnitude (twice a triangle's area) places a crossing along an edge.
    pub value: f64,
}

impl Side {
    /// Strictly inside: off the line, on the window's side.
    #[inline]
    pub fn strictly_inside(self) -> bool {
        self.value > 0.0
    }

    /// Exactly on the boundary line.
    #[inline]
    pub fn on_line(self) -> bool {
        self.value == 0.0
    }

    /// Strictly outside.
    #[inline]
    pub fn outside(self) -> bool {
        self.value < 0.0
    }
}

impl Boundary {
    /// Which side of the boundary `p` is on (exact sign).
    #[inline]
    pub fn side(&self, p: Point) -> Side {
        Side { value: orient2d(self.from, self.to, p) }
    }

    /// Where the edge between `p` and `q` crosses the boundary line, given their sides, which must
    /// be strictly opposite. The endpoints are put in a canonical order first, so the edge gives
    /// the same point whichever way it is walked. The point is clamped into the edge's bounding
    /// box; on an axis-aligned boundary its coordinate across the boundary is the boundary's own.
    pub fn crossing(&self, p: Point, p_side: Side, q: Point, q_side: Side) -> Point {
        let ((u, du), (v, dv)) = if (p.x, p.y) <= (q.x, q.y) {
            ((p, p_side.value), (q, q_side.value))
        } else {
            ((q, q_side.value), (p, p_side.value))
        };
        // du and dv have exact, opposite, non-zero signs, so t lies in (0, 1) up to rounding.
        let t = (du / (du - dv)).clamp(0.0, 1.0);
        let mut x = u.x + (v.x - u.x) * t;
        let mut y = u.y + (v.y - u.y) * t;
        if self.from.x == self.to.x {
            x = self.from.x;
        }
        if self.from.y == self.to.y {
            y = self.from.y;
        }
        Point::new(x.clamp(u.x.min(v.x), u.x.max(v.x)), y.clamp(u.y.min(v.y), u.y.max(v.y)))
    }
}
