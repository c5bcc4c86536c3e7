//! A region bounded by arcs of one ellipse and straight segments: a clipped filled curve.

use crate::{Ellipse, Point, Segment};

/// One piece of a [`CurveRegion`]'s boundary, walked with the region on its left.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BoundaryPiece {
    /// The region's ellipse from parameter `from` to `to` (`to > from`, counter-clockwise).
    Arc {
        /// First parameter.
        from: f64,
        /// Last parameter.
        to: f64,
    },
    /// A straight piece (part of a window edge).
    Segment(Segment),
}

impl BoundaryPiece {
    /// Where the piece starts.
    pub fn start(&self, ellipse: &Ellipse) -> Point {
        match *self {
            BoundaryPiece::Arc { from, .. } => ellipse.point_at(from),
            BoundaryPiece::Segment(s) => s.a,
        }
    }

    /// Where the piece ends.
    pub fn end(&self, ellipse: &Ellipse) -> Point {
        match *self {
            BoundaryPiece::Arc { to, .. } => ellipse.point_at(to),
            BoundaryPiece::Segment(s) => s.b,
        }
    }

    /// Twice the piece's contribution to the region's area, `∫ (x dy - y dx)` with coordinates
    /// relative to the ellipse's centre: `rx ry (to - from)` for an arc (Green's theorem on the
    /// parameterisation), `a × b` for a segment.
    pub fn twice_area_term(&self, ellipse: &Ellipse) -> f64 {
        match *self {
            BoundaryPiece::Arc { from, to } => {
                let (rx, ry) = ellipse.radii();
                rx * ry * (to - from)
            }
            BoundaryPiece::Segment(s) => {
                let c = ellipse.center();
                (s.a - c).cross(s.b - c)
            }
        }
    }
}

/// The part of a filled ellipse inside a window: closed boundary loops of arcs of the ellipse and
/// pieces of window edges, each loop with the region on its left (outer loops counter-clockwise,
/// holes clockwise). Its area is exact up to rounding: each arc adds its elliptic sector and each
/// segment its triangle with the centre, so circular and elliptic segments come out exactly.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveRegion {
    /// The clipped ellipse.
    pub ellipse: Ellipse,
    /// The boundary loops; none for the empty region.
    pub loops: Vec<Vec<BoundaryPiece>>,
}

impl CurveRegion {
    /// The empty region of `ellipse`.
    pub fn empty(ellipse: Ellipse) -> CurveRegion {
        CurveRegion { ellipse, loops: Vec::new() }
    }

    /// The whole filled ellipse: one loop, one arc of 2π.
    pub fn whole(ellipse: Ellipse) -> CurveRegion {
        CurveRegion { ellipse, loops: vec![vec![BoundaryPiece::Arc { from: 0.0, to: core::f64::consts::TAU }]] }
    }

    /// True when there is no loop.
    pub fn is_empty(&self) -> bool {
        self.loops.is_empty()
    }

    /// Every piece of every loop.
    pub fn pieces(&self) -> impl Iterator<Item = &BoundaryPiece> {
        self.loops.iter().flatten()
    }

    /// The area, by Green's theorem over the boundary (sectors plus triangles, relative to the
    /// ellipse's centre). Each loop is closed first: where a piece ends a rounding away from
    /// where the next starts (a crossing computed for the arc and for the edge), the gap's chord
    /// counts too, so the area is that of closed loops and a gap costs only the sliver it spans,
    /// not the gap times the distance to the centre.
    pub fn area(&self) -> f64 {
        let e = &self.ellipse;
        let c = e.center();
        let mut twice = 0.0;
        for lp in &self.loops {
            for (i, p) in lp.iter().enumerate() {
                twice += p.twice_area_term(e);
                let next = &lp[(i + 1) % lp.len()];
                twice += (p.end(e) - c).cross(next.start(e) - c);
            }
        }
        0.5 * twice
    }

    /// The total parameter span of the arcs on the boundary.
    pub fn arc_span(&self) -> f64 {
        self.pieces()
            .map(|p| match *p {
                BoundaryPiece::Arc { from, to } => to - from,
                BoundaryPiece::Segment(_) => 0.0,
            })
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::PI;

    #[test]
    fn area_of_a_half_disc_and_a_whole_ellipse() {
        let e = Ellipse::circle(Point::new(5.0, 5.0), 2.0).unwrap();
        let half = CurveRegion {
            ellipse: e,
            loops: vec![vec![
                BoundaryPiece::Arc { from: 0.0, to: PI },
                BoundaryPiece::Segment(Segment::new(Point::new(3.0, 5.0), Point::new(7.0, 5.0))),
            ]],
        };
        assert!((half.area() - 2.0 * PI).abs() < 1e-12);
        let ell = Ellipse::new(Point::new(-1.0, 2.0), 3.0, 1.0, 0.3).unwrap();
        assert!((CurveRegion::whole(ell).area() - 3.0 * PI).abs() < 1e-12);
        // A circular segment: the part of the unit circle above y = 0.5.
        let unit = Ellipse::circle(Point::ZERO, 1.0).unwrap();
        let (a, b) = (PI / 6.0, 5.0 * PI / 6.0);
        let cap = CurveRegion {
            ellipse: unit,
            loops: vec![vec![
                BoundaryPiece::Arc { from: a, to: b },
                BoundaryPiece::Segment(Segment::new(unit.point_at(b), unit.point_at(a))),
            ]],
        };
        let exact = PI / 3.0 - 3f64.sqrt() / 4.0;
        assert!((cap.area() - exact).abs() < 1e-14, "{}", cap.area());
    }
}
