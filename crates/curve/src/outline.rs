//! The visible parameter intervals of an arc or a whole ellipse in a window (closed-set rule).

use core::f64::consts::TAU;

use clip_core::{Ellipse, EllipseArc, Location, Point, Rect};

use crate::crossings::{AxisForm, ENDPOINT_SLACK, line_roots, reach};
use crate::preliminary::{Breaks, OCTANT_BREAKS, Piece, Stage, Verdict, box_verdict, circle_octant_points, pieces};
use crate::window::{CurveWindow, PolygonWindow, locate_in_rect};

/// Parameters closer than this (radians) are one point: rounding of crossings computed from
/// different edges stays far below it, and a true piece this short is below the resolution of
/// the parameters.
pub const ANGLE_SNAP: f64 = 1e-12;

/// The visible part of an arc and the stage that settled it.
#[derive(Clone, Debug, PartialEq)]
pub struct Visible {
    /// Maximal closed parameter intervals `(from, to)`, `to > from`, ascending, within the arc's
    /// `[start, end]`. For a whole ellipse a piece through parameter 0 is one interval ending
    /// past 2π, and the whole ellipse is `(0, 2π)`.
    pub intervals: Vec<(f64, f64)>,
    /// Which step settled it.
    pub stage: Stage,
}

/// The visible part of `arc` in `window`; `tests` turns the preliminary tests on.
pub fn visible(window: &CurveWindow, arc: &EllipseArc, tests: bool) -> Visible {
    let mut raw = Vec::new();
    let stage = match window {
        CurveWindow::Rectangle(r) => rectangle(r, arc, tests, &mut raw),
        CurveWindow::Polygon(w) => polygon(w, window, arc, tests, &mut raw),
    };
    Visible { intervals: merged(raw, arc, resolution(arc.ellipse())), stage }
}

/// The lecture's rectangle clipper: the bounding rectangle, quadrants, octants (circles), and
/// the equations only for what is left.
fn rectangle(r: &Rect, arc: &EllipseArc, tests: bool, out: &mut Vec<(f64, f64)>) -> Stage {
    let e = arc.ellipse();
    let range = (arc.start(), arc.end());
    if !tests {
        let whole = Piece { from: range.0, to: range.1, bounds: Rect::EMPTY, verdict: Verdict::Unsettled };
        equations(r, e, &[whole], false, out);
        return Stage::Equations;
    }
    match box_verdict(r, &arc.bounds()) {
        Verdict::Inside => {
            out.push(range);
            return Stage::BoxAccept;
        }
        Verdict::Outside => return Stage::BoxReject,
        Verdict::Unsettled => {}
    }
    let mut left = Vec::with_capacity(8);
    let mut stage = Stage::Quadrants;
    if e.is_circle() {
        let points = circle_octant_points(e);
        let quadrant_points = [points[0], points[2], points[4], points[6]];
        let quarters = [0.0, OCTANT_BREAKS[2], OCTANT_BREAKS[4], OCTANT_BREAKS[6]];
        let mut quadrants = Vec::with_capacity(5);
        pieces(e, range, Breaks { at: &quarters, points: &quadrant_points }, r, &mut quadrants);
        let unsettled = settle(&quadrants, out);
        if !unsettled.is_empty() {
            stage = Stage::Octants;
            let mut octants = Vec::with_capacity(2 * unsettled.len() + 1);
            for p in &unsettled {
                pieces(e, (p.from, p.to), Breaks { at: &OCTANT_BREAKS, points: &points }, r, &mut octants);
            }
            left = settle(&octants, out);
        }
    } else {
        let at = e.extreme_parameters();
        let points = at.map(|t| e.point_at(t));
        let mut quadrants = Vec::with_capacity(5);
        pieces(e, range, Breaks { at: &at, points: &points }, r, &mut quadrants);
        left = settle(&quadrants, out);
    }
    if left.is_empty() {
        return stage;
    }
    equations(r, e, &left, true, out);
    Stage::Equations
}

/// Keeps the pieces found inside, drops those outside, returns the rest.
fn settle(pieces: &[Piece], out: &mut Vec<(f64, f64)>) -> Vec<Piece> {
    let mut left = Vec::new();
    for p in pieces {
        match p.verdict {
            Verdict::Inside => out.push((p.from, p.to)),
            Verdict::Outside => {}
            Verdict::Unsettled => left.push(*p),
        }
    }
    left
}

/// Solves the ellipse against the rectangle's four lines (with `only_near`, only the lines that
/// cross some piece's box: the others cannot meet what is left) and keeps the parts of each
/// piece between crossings that lie in the closed rectangle.
fn equations(r: &Rect, e: &Ellipse, left: &[Piece], only_near: bool, out: &mut Vec<(f64, f64)>) {
    let form = AxisForm::new(e);
    let mut roots = Vec::with_capacity(8);
    let near_x = |k: f64| !only_near || left.iter().any(|p| p.bounds.min.x <= k && k <= p.bounds.max.x);
    let near_y = |k: f64| !only_near || left.iter().any(|p| p.bounds.min.y <= k && k <= p.bounds.max.y);
    for k in [r.min.x, r.max.x] {
        if near_x(k) {
            form.vertical(k, &mut roots);
        }
    }
    for k in [r.min.y, r.max.y] {
        if near_y(k) {
            form.horizontal(k, &mut roots);
        }
    }
    let mut here = Vec::with_capacity(roots.len());
    for p in left {
        here.clear();
        here.extend_from_slice(&roots);
        classify_between(e, (p.from, p.to), &mut here, |q| locate_in_rect(r, q), out);
    }
}

/// A polygon window: the bounding rectangles (the object's against the window's, and each
/// edge's against the object's) with tests on, then every remaining edge's equation.
fn polygon(w: &PolygonWindow, window: &CurveWindow, arc: &EllipseArc, tests: bool, out: &mut Vec<(f64, f64)>) -> Stage {
    let e = arc.ellipse();
    let bounds = arc.bounds();
    if tests && !w.bounds.intersects(&bounds) {
        return Stage::BoxReject;
    }
    let around = reach(e);
    let mut roots = Vec::new();
    for edge in &w.edges {
        if tests && !edge.bounds().intersects(&bounds) {
            continue;
        }
        if let Some(pair) = line_roots(e, &around, *edge) {
            for (t, theta) in pair {
                if (-ENDPOINT_SLACK..=1.0 + ENDPOINT_SLACK).contains(&t) {
                    roots.push(theta);
                }
            }
        }
    }
    classify_between(e, (arc.start(), arc.end()), &mut roots, |p| window.locate(p), out);
    Stage::Equations
}

/// Where in a part between crossings its points are tried, midpoint first: a part lies wholly
/// inside or wholly outside the closed window but for touch points, so the first point not on
/// the boundary decides (a part touching at its midpoint is judged by the next).
const PROBES: [f64; 5] = [0.5, 0.381_966, 0.618_034, 0.25, 0.75];

/// Cuts `[from, to]` at the crossing parameters `roots` (any turn) that fall inside it, and keeps
/// each part found inside the window by exact location of a rounded probe point ([`PROBES`]).
fn classify_between(
    e: &Ellipse,
    (from, to): (f64, f64),
    roots: &mut Vec<f64>,
    locate: impl Fn(Point) -> Location,
    out: &mut Vec<(f64, f64)>,
) {
    let inside = |a: f64, b: f64| {
        PROBES
            .iter()
            .map(|f| locate(e.point_at(a + f * (b - a))))
            .find(|&l| l != Location::Boundary)
            .is_none_or(|l| l == Location::Inside)
    };
    for t in roots.iter_mut() {
        *t = from + (*t - from).rem_euclid(TAU);
    }
    roots.retain(|&t| t < to);
    roots.sort_by(f64::total_cmp);
    let mut a = from;
    for b in roots.iter().copied().chain([to]) {
        if b - a > ANGLE_SNAP && inside(a, b) {
            out.push((a, b));
        }
        a = a.max(b);
    }
}

/// Distance from the window boundary below which a curve's rounded points cannot tell inside
/// from outside: 64 ulps of the ellipse's coordinates.
const RESOLUTION_ULPS: f64 = 64.0;

/// The parameter span below which a gap or a piece is no wider than rounding: a span `δ` of the
/// curve strays at most `a δ² / 8` from its chord (`a` the long radius), so where an edge grazes
/// the curve the two crossings `δ` apart enclose a sliver that deep. Such gaps are joined and such
/// pieces dropped, as touch points are (never below [`ANGLE_SNAP`]).
fn resolution(e: &Ellipse) -> f64 {
    let c = e.center();
    let depth = RESOLUTION_ULPS * f64::EPSILON * (c.x.abs().max(c.y.abs()) + e.max_radius());
    (8.0 * depth / e.max_radius()).sqrt().max(ANGLE_SNAP)
}

/// Sorts and merges the raw intervals: touching ones (and those a gap below `snap` apart) joined,
/// points and pieces below `snap` dropped; for a whole ellipse the piece ending at 2π is joined
/// with the one starting at 0.
fn merged(mut raw: Vec<(f64, f64)>, arc: &EllipseArc, snap: f64) -> Vec<(f64, f64)> {
    raw.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut out: Vec<(f64, f64)> = Vec::with_capacity(raw.len());
    for (a, b) in raw {
        match out.last_mut() {
            Some(last) if a <= last.1 + snap => last.1 = last.1.max(b),
            _ => out.push((a, b)),
        }
    }
    out.retain(|(a, b)| b - a > snap);
    if arc.is_closed() && out.len() > 1 {
        let (first, last) = (out[0], out[out.len() - 1]);
        if first.0 <= arc.start() + snap && last.1 >= arc.end() - snap {
            out.remove(0);
            let n = out.len();
            out[n - 1] = (last.0, first.1 + TAU);
        }
    }
    if arc.is_closed() && out.len() == 1 && out[0].1 - out[0].0 >= TAU - snap {
        out[0] = (0.0, TAU);
    }
    out
}
