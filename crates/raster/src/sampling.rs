//! The one sampling rule both fills share: which rows and columns a boundary lights, and how a
//! side's x is walked from row to row.

use clip_core::Point;

/// The first pixel index whose centre is at or beyond `v`: `ceil(v - 0.5)`, clamped to
/// `[0, limit]`. A span from `a` to `b` lights pixels `edge(a)..edge(b)`: a centre exactly on
/// the low side is in, one exactly on the high side is out (the top-left rule, see the crate
/// docs). Rounding `v - 0.5` cannot move `ceil` past an integer, so the rule is exact in `v`.
#[inline]
pub fn pixel_edge(v: f64, limit: usize) -> usize {
    let e = (v - 0.5).ceil();
    if e >= limit as f64 {
        limit
    } else if e > 0.0 {
        e as usize
    } else {
        0 // also NaN
    }
}

/// The rows whose centres lie in `[y_bottom, y_top)`, clipped to `[0, height)`.
#[inline]
pub fn rows(y_bottom: f64, y_top: f64, height: usize) -> core::ops::Range<usize> {
    pixel_edge(y_bottom, height)..pixel_edge(y_top, height)
}

/// The slope of an edge as the fills use it: change of x per unit y, from the lower endpoint
/// (lowest y, then lowest x) to the upper, so it does not depend on the edge's direction.
#[inline]
pub fn edge_dx(a: Point, b: Point) -> f64 {
    let (lo, hi) = lower_first(a, b);
    (hi.x - lo.x) / (hi.y - lo.y)
}

/// The x of a non-horizontal edge at height `y`, from its lower endpoint: where a slab (or a
/// trapezoid) that starts at `y` anchors this edge.
#[inline]
pub fn edge_x_at(a: Point, b: Point, y: f64) -> f64 {
    let (lo, _) = lower_first(a, b);
    if y == lo.y { lo.x } else { lo.x + edge_dx(a, b) * (y - lo.y) }
}

#[inline]
fn lower_first(a: Point, b: Point) -> (Point, Point) {
    if (a.y, a.x) <= (b.y, b.x) { (a, b) } else { (b, a) }
}

/// A side of a trapezoid (or a polygon edge within one slab) walked one row at a time by the
/// paper's incremental loop, `X = X + DX`. Both fills start a walk with the same arithmetic from
/// the same anchor and step it the same number of times, so equal anchors give equal x values,
/// bit for bit, at every row.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SideWalk {
    /// x at the current row's centre.
    pub x: f64,
    /// Change of x per row.
    pub dx: f64,
}

impl SideWalk {
    /// The side through `(x0, y0)` with slope `dx`, placed at the centre of row `row`.
    #[inline]
    pub fn start(x0: f64, y0: f64, dx: f64, row: usize) -> SideWalk {
        SideWalk { x: x0 + dx * ((row as f64 + 0.5) - y0), dx }
    }

    /// Moves to the next row.
    #[inline]
    pub fn step(&mut self) {
        self.x += self.dx;
    }
}
