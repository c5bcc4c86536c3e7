//! A filled ellipse clipped to a window: the visible arcs and the window's edges inside the
//! ellipse, linked into boundary loops.

use core::f64::consts::TAU;

use clip_core::{BoundaryPiece, CurveRegion, Ellipse, EllipseArc, Point, Segment};

use crate::crossings::{line_roots, reach};
use crate::outline::{ANGLE_SNAP, visible};
use crate::preliminary::Stage;
use crate::window::CurveWindow;

/// The region and the stage that settled it.
#[derive(Clone, Debug, PartialEq)]
pub struct Clipped {
    /// The part of the filled ellipse inside the window.
    pub region: CurveRegion,
    /// Which step settled it.
    pub stage: Stage,
}

/// The part of the filled ellipse `e` inside `window`; `tests` turns the preliminary tests on.
///
/// Its boundary is the ellipse's visible arcs (the outline clipper's answer) plus each window
/// boundary piece inside the ellipse, walked with the window on its left; a convex ellipse meets
/// a straight piece in one interval, between the two roots of its equation.
pub fn clip_filled(window: &CurveWindow, e: &Ellipse, tests: bool) -> Clipped {
    let arc = EllipseArc::full(*e);
    let seen = visible(window, &arc, tests);
    let done = |region| Clipped { region, stage: seen.stage };
    match seen.stage {
        Stage::BoxAccept => return done(CurveRegion::whole(*e)),
        Stage::BoxReject => return done(CurveRegion::empty(*e)),
        _ => {}
    }
    let whole_outline = seen.intervals == [(0.0, TAU)];
    let mut pieces: Vec<BoundaryPiece> =
        seen.intervals.iter().map(|&(from, to)| BoundaryPiece::Arc { from, to }).collect();
    match window {
        // A rectangle holding the whole outline holds the ellipse; when the tests settled the
        // outline with nothing visible, the rectangle is wholly inside or wholly outside.
        CurveWindow::Rectangle(_) if whole_outline => return done(CurveRegion::whole(*e)),
        CurveWindow::Rectangle(r) if seen.stage != Stage::Equations && seen.intervals.is_empty() => {
            let region = if e.implicit(r.min) <= 0.0 {
                CurveRegion { ellipse: *e, loops: vec![edges_inside(window, e, tests)] }
            } else {
                CurveRegion::empty(*e)
            };
            return done(region);
        }
        _ => pieces.extend(edges_inside(window, e, tests)),
    }
    done(CurveRegion { ellipse: *e, loops: link(pieces, e) })
}

/// The window's boundary pieces inside the closed ellipse, window on the left.
fn edges_inside(window: &CurveWindow, e: &Ellipse, tests: bool) -> Vec<BoundaryPiece> {
    let around = reach(e);
    let bounds = e.bounds();
    let mut out = Vec::new();
    let rectangle: [Segment; 4];
    let boundary: &[Segment] = match window {
        CurveWindow::Rectangle(r) => {
            let [a, b, c, d] = [r.min, Point::new(r.max.x, r.min.y), r.max, Point::new(r.min.x, r.max.y)];
            rectangle = [Segment::new(a, b), Segment::new(b, c), Segment::new(c, d), Segment::new(d, a)];
            &rectangle
        }
        CurveWindow::Polygon(w) => &w.boundary,
    };
    for &s in boundary {
        if tests && !s.bounds().intersects(&bounds) {
            continue;
        }
        if let Some([(t1, _), (t2, _)]) = line_roots(e, &around, s) {
            let (a, b) = (t1.max(0.0), t2.min(1.0));
            if b - a > ANGLE_SNAP {
                let piece: Segment = s.piece(a, b);
                if piece.a != piece.b {
                    out.push(BoundaryPiece::Segment(piece));
                }
            }
        }
    }
    out
}

/// Links pieces into closed loops: each piece is followed by the unused piece starting nearest
/// to its end, and a loop closes when its own start is at least as near. Exact ends are not
/// needed: the ends of an arc and of the window piece it meets are the same crossing computed
/// two ways, equal to rounding.
pub(crate) fn link(mut pieces: Vec<BoundaryPiece>, e: &Ellipse) -> Vec<Vec<BoundaryPiece>> {
    let mut loops = Vec::new();
    while let Some(first) = pieces.pop() {
        let start = first.start(e);
        let mut end = first.end(e);
        let mut lp = vec![first];
        loop {
            let nearest = pieces
                .iter()
                .enumerate()
                .map(|(i, p)| (i, p.start(e).distance(end)))
                .min_by(|a, b| a.1.total_cmp(&b.1));
            match nearest {
                Some((i, d)) if d < start.distance(end) => {
                    let next = pieces.swap_remove(i);
                    end = next.end(e);
                    lp.push(next);
                }
                _ => break,
            }
        }
        loops.push(lp);
    }
    loops
}
