//! The lecture's preliminary tests: bounding rectangle, then quadrant and octant extents.

use core::f64::consts::{FRAC_PI_4, TAU};

use clip_core::{Ellipse, Point, Rect};

/// Which step settled an object: the first that decided all of it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Stage {
    /// Its bounding rectangle lies inside the window: kept whole.
    BoxAccept,
    /// Its bounding rectangle misses the window (a polygon window: the window's bounding
    /// rectangle): dropped whole.
    BoxReject,
    /// Every quadrant's extents lie inside or outside the window (rectangle windows).
    Quadrants,
    /// Every octant's extents lie inside or outside the window (circles, rectangle windows).
    Octants,
    /// Something was left for the curve-line equations.
    Equations,
}

impl Stage {
    /// Every stage, in order.
    pub const ALL: [Stage; 5] =
        [Stage::BoxAccept, Stage::BoxReject, Stage::Quadrants, Stage::Octants, Stage::Equations];

    /// A short name for tables and files.
    pub fn name(self) -> &'static str {
        match self {
            Stage::BoxAccept => "box-accept",
            Stage::BoxReject => "box-reject",
            Stage::Quadrants => "quadrants",
            Stage::Octants => "octants",
            Stage::Equations => "equations",
        }
    }
}

/// What a box test says about a piece of curve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Wholly inside the closed window.
    Inside,
    /// Disjoint from the closed window.
    Outside,
    /// Neither: the equations must decide.
    Unsettled,
}

/// The verdict of a box against a rectangle window.
#[inline]
pub fn box_verdict(window: &Rect, b: &Rect) -> Verdict {
    if window.contains_rect(b) {
        Verdict::Inside
    } else if !window.intersects(b) {
        Verdict::Outside
    } else {
        Verdict::Unsettled
    }
}

/// A parameter range `[from, to]` of an arc with its bounding box and the box test's verdict.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Piece {
    /// First parameter.
    pub from: f64,
    /// Last parameter.
    pub to: f64,
    /// The box of its two ends (its bounding box: pieces are monotone).
    pub bounds: Rect,
    /// What the box test said.
    pub verdict: Verdict,
}

/// Where an ellipse is cut into pieces: parameters in `[0, 2π)`, ascending, with their points
/// (computed once per object; for a circle from constants, with no trigonometry).
#[derive(Clone, Copy, Debug)]
pub struct Breaks<'a> {
    /// The parameters.
    pub at: &'a [f64],
    /// The ellipse's points there.
    pub points: &'a [Point],
}

/// The part `[start, end]` of ellipse `e`'s parameters cut at `breaks`, each piece tested by the
/// box of its two ends. Between consecutive breaks at the ellipse's extreme points (and any finer
/// cut of such a piece) the curve is monotone in x and y, so that box is the piece's bounding box.
pub fn pieces(e: &Ellipse, (start, end): (f64, f64), breaks: Breaks<'_>, window: &Rect, out: &mut Vec<Piece>) {
    let slack = 4.0 * f64::EPSILON * (e.center().x.abs().max(e.center().y.abs()) + e.max_radius());
    let mut cut = |from: (f64, Point), to: (f64, Point)| {
        let bounds = Rect::from_points(from.1, to.1).inflate(slack);
        out.push(Piece { from: from.0, to: to.0, bounds, verdict: box_verdict(window, &bounds) });
    };
    // Breaks are found in the turn `start` lies in, then the next turns.
    let n = breaks.at.len();
    let base = start - start.rem_euclid(TAU);
    let first = breaks.at.iter().position(|&b| base + b > start).unwrap_or(n);
    let mut from = (start, e.point_at(start));
    for k in first..first + 2 * n {
        let b = base + breaks.at[k % n] + TAU * (k / n) as f64;
        if b >= end {
            break;
        }
        if b > from.0 {
            let here = (b, breaks.points[k % n]);
            cut(from, here);
            from = here;
        }
    }
    cut(from, (end, e.point_at(end)));
}

/// The points of a circle at multiples of π/4 (its octant ends), as offsets of unit radius.
const UNIT_OCTANT_POINTS: [(f64, f64); 8] = [
    (1.0, 0.0),
    (core::f64::consts::FRAC_1_SQRT_2, core::f64::consts::FRAC_1_SQRT_2),
    (0.0, 1.0),
    (-core::f64::consts::FRAC_1_SQRT_2, core::f64::consts::FRAC_1_SQRT_2),
    (-1.0, 0.0),
    (-core::f64::consts::FRAC_1_SQRT_2, -core::f64::consts::FRAC_1_SQRT_2),
    (0.0, -1.0),
    (core::f64::consts::FRAC_1_SQRT_2, -core::f64::consts::FRAC_1_SQRT_2),
];

/// A circle's points at its octant ends (`OCTANT_BREAKS`), from constants; every other one is a
/// quadrant end.
pub fn circle_octant_points(e: &Ellipse) -> [Point; 8] {
    let (c, (r, _)) = (e.center(), e.radii());
    UNIT_OCTANT_POINTS.map(|(x, y)| Point::new(c.x + r * x, c.y + r * y))
}

/// The parameters of a circle's octant ends: every multiple of π/4 (a circle has no rotation).
pub const OCTANT_BREAKS: [f64; 8] = [
    0.0,
    FRAC_PI_4,
    2.0 * FRAC_PI_4,
    3.0 * FRAC_PI_4,
    4.0 * FRAC_PI_4,
    5.0 * FRAC_PI_4,
    6.0 * FRAC_PI_4,
    7.0 * FRAC_PI_4,
];

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::{Ellipse, EllipseArc};

    #[test]
    fn a_full_circle_has_four_quadrants_and_eight_octants() {
        let e = Ellipse::circle(Point::ZERO, 1.0).unwrap();
        let arc = EllipseArc::full(e);
        let far = Rect::new(10.0, 10.0, 11.0, 11.0);
        let mut out = Vec::new();
        let q = e.extreme_parameters();
        let qp = q.map(|t| e.point_at(t));
        pieces(&e, (arc.start(), arc.end()), Breaks { at: &q, points: &qp }, &far, &mut out);
        assert_eq!(out.len(), 4);
        assert!(out.iter().all(|p| p.verdict == Verdict::Outside));
        out.clear();
        let op = circle_octant_points(&e);
        for (t, p) in OCTANT_BREAKS.iter().zip(op) {
            assert!(e.point_at(*t).distance(p) < 1e-15);
        }
        pieces(&e, (arc.start(), arc.end()), Breaks { at: &OCTANT_BREAKS, points: &op }, &far, &mut out);
        assert_eq!(out.len(), 8);
        assert!((out[7].to - TAU).abs() < 1e-15 && out[0].from == 0.0);
    }

    #[test]
    fn an_arc_across_zero_is_cut_at_the_breaks_it_passes() {
        let e = Ellipse::circle(Point::ZERO, 1.0).unwrap();
        let arc = EllipseArc::new(e, 1.5 * core::f64::consts::PI + 0.1, 2.0).unwrap();
        let mut out = Vec::new();
        let q = e.extreme_parameters();
        let qp = q.map(|t| e.point_at(t));
        let breaks = Breaks { at: &q, points: &qp };
        pieces(&e, (arc.start(), arc.end()), breaks, &Rect::new(-2.0, -2.0, 2.0, 2.0), &mut out);
        assert_eq!(out.len(), 2);
        assert!((out[0].to - TAU).abs() < 1e-15);
        assert!(out.iter().all(|p| p.verdict == Verdict::Inside));
    }
}
