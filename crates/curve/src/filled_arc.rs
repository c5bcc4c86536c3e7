//! A filled arc (sector or chord region) clipped to a window: the visible part of its arc, the
//! parts of its closing sides inside the window, and the window's edges inside it, linked into
//! boundary loops.

use clip_core::predicates::{Orientation, on_segment, orient};
use clip_core::{
    BoundaryPiece, CurveRegion, FilledArc, Location, Point, Rect, Segment, SegmentIntersection, segment_intersection,
};

use crate::crossings::{line_roots, reach};
use crate::outline::{ANGLE_SNAP, visible};
use crate::preliminary::{Stage, Verdict, box_verdict};
use crate::region::{Clipped, clip_filled, link};
use crate::window::CurveWindow;

/// The part of the filled arc `f` inside `window`; `tests` turns the preliminary tests on.
///
/// With the tests, the filled arc's bounding box (the arc's, with the centre for a sector) is
/// tried first against the window (a polygon window: its bounding box, reject only); then the
/// arc goes through the outline clipper's tests (quadrants, octants), and `stage` says which
/// step settled the arc. The closing sides are clipped to the window as segments, and each
/// window edge is cut to the ellipse (its curve-line equation) and then to the closing sides'
/// half-plane or wedge. A whole ellipse is [`clip_filled`]'s.
pub fn clip_filled_arc(window: &CurveWindow, f: &FilledArc, tests: bool) -> Clipped {
    let e = f.ellipse();
    if f.is_whole() {
        return clip_filled(window, e, tests);
    }
    if tests {
        let verdict = match window {
            CurveWindow::Rectangle(r) => box_verdict(r, &f.bounds()),
            CurveWindow::Polygon(w) if !w.bounds.intersects(&f.bounds()) => Verdict::Outside,
            CurveWindow::Polygon(_) => Verdict::Unsettled,
        };
        match verdict {
            Verdict::Inside => return Clipped { region: f.region(), stage: Stage::BoxAccept },
            Verdict::Outside => return Clipped { region: CurveRegion::empty(*e), stage: Stage::BoxReject },
            Verdict::Unsettled => {}
        }
    }
    let seen = visible(window, f.arc(), tests);
    let mut pieces: Vec<BoundaryPiece> =
        seen.intervals.iter().map(|&(from, to)| BoundaryPiece::Arc { from, to }).collect();
    let boundary = window.oriented_boundary();
    let near = f.bounds();
    let closing = f.closing_segments();
    for &side in &closing {
        pieces.extend(side_inside(window, &boundary, side, tests).into_iter().map(BoundaryPiece::Segment));
    }
    let around = reach(e);
    for &s in &boundary {
        if tests && !s.bounds().intersects(&near) {
            continue;
        }
        let Some([(t1, _), (t2, _)]) = line_roots(e, &around, s) else { continue };
        let (a, b) = (t1.max(0.0), t2.min(1.0));
        if b - a <= ANGLE_SNAP {
            continue;
        }
        let inside_ellipse = s.piece(a, b);
        pieces.extend(
            cut_by(inside_ellipse, &closing, |p| f.locate_closing(p) == Location::Inside)
                .into_iter()
                .map(BoundaryPiece::Segment),
        );
    }
    let region =
        if pieces.is_empty() { CurveRegion::empty(*e) } else { CurveRegion { ellipse: *e, loops: link(pieces, e) } };
    Clipped { region, stage: seen.stage }
}

/// The parts of closing side `side` in the closed window. A part along the window's boundary is
/// kept only where the window lies on its left too (the region's side), so a side shared with a
/// window edge appears once, and not at all where the window lies beyond it.
fn side_inside(window: &CurveWindow, boundary: &[Segment], side: Segment, tests: bool) -> Vec<Segment> {
    let rectangle: [Segment; 4];
    let all: &[Segment] = match window {
        CurveWindow::Rectangle(r) => {
            rectangle = rect_edges(r);
            &rectangle
        }
        CurveWindow::Polygon(w) => &w.edges,
    };
    let edges: Vec<Segment> = all.iter().copied().filter(|e| !tests || e.bounds().intersects(&side.bounds())).collect();
    let along = |b: &Segment| {
        orient(side.a, side.b, b.a) == Orientation::Collinear && orient(side.a, side.b, b.b) == Orientation::Collinear
    };
    cut_by(side, &edges, |m| match window.locate(m) {
        Location::Inside => true,
        Location::Outside => false,
        // On the boundary: kept where a boundary piece through it runs the same way (the window
        // on the side's left too).
        Location::Boundary => {
            boundary.iter().any(|b| on_segment(m, *b) && along(b) && (b.b - b.a).dot(side.b - side.a) > 0.0)
        }
    })
}

/// The four edges of a rectangle, counter-clockwise.
fn rect_edges(r: &Rect) -> [Segment; 4] {
    let [a, b, c, d] = [r.min, Point::new(r.max.x, r.min.y), r.max, Point::new(r.min.x, r.max.y)];
    [Segment::new(a, b), Segment::new(b, c), Segment::new(c, d), Segment::new(d, a)]
}

/// `s` cut wherever one of `cutters` meets it, keeping the pieces whose midpoint `keep` accepts.
fn cut_by(s: Segment, cutters: &[Segment], keep: impl Fn(Point) -> bool) -> Vec<Segment> {
    let mut ts = vec![0.0, 1.0];
    for &c in cutters {
        match segment_intersection(s, c) {
            SegmentIntersection::None => {}
            SegmentIntersection::Crossing(p) | SegmentIntersection::Touching(p) => ts.push(s.param_of(p)),
            SegmentIntersection::Overlap(o) => ts.extend([s.param_of(o.a), s.param_of(o.b)]),
        }
    }
    ts.retain(|t| (0.0..=1.0).contains(t));
    ts.sort_by(f64::total_cmp);
    ts.dedup();
    let mut out = Vec::new();
    for w in ts.windows(2) {
        let (a, b) = (w[0], w[1]);
        if b - a <= ANGLE_SNAP {
            continue;
        }
        let piece = s.piece(a, b);
        if piece.a != piece.b && keep(piece.a.lerp(piece.b, 0.5)) {
            out.push(piece);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::{ArcFill, Ellipse, EllipseArc, Polygons};
    use core::f64::consts::{FRAC_PI_2, PI};

    fn clip(window: Rect, f: &FilledArc, tests: bool) -> Clipped {
        clip_filled_arc(&CurveWindow::new(&Polygons::from(window)).unwrap(), f, tests)
    }

    #[test]
    fn a_quarter_disc_cut_by_a_window_edge() {
        // The quarter x, y >= 0 of the circle of radius 2, the window's right side at x = 1.
        let e = Ellipse::circle(Point::ZERO, 2.0).unwrap();
        let f = FilledArc::new(EllipseArc::new(e, 0.0, FRAC_PI_2).unwrap(), ArcFill::Sector);
        let w = Rect::new(-5.0, -5.0, 1.0, 5.0);
        // Area of the quarter disc left of x = 1: the strip 0..1 under sqrt(4 - x²).
        let exact = 0.5 * (3f64.sqrt() + 4.0 * (0.5f64).asin());
        for tests in [true, false] {
            let c = clip(w, &f, tests);
            assert_eq!(c.region.loops.len(), 1);
            assert!((c.region.area() - exact).abs() < 1e-12, "{tests}: {}", c.region.area());
        }
        // The chord region of the same arc: that part less the triangle (0,0), (2,0), (0,2)
        // left of x = 1, whose area is 1.5.
        let g = FilledArc::new(*f.arc(), ArcFill::Chord);
        for tests in [true, false] {
            let c = clip(w, &g, tests);
            assert!((c.region.area() - (exact - 1.5)).abs() < 1e-12, "{tests}: {}", c.region.area());
        }
    }

    #[test]
    fn settled_by_the_box_and_windows_inside_the_shape() {
        let e = Ellipse::circle(Point::new(50.0, 50.0), 10.0).unwrap();
        let f = FilledArc::new(EllipseArc::new(e, 0.3, 2.0).unwrap(), ArcFill::Chord);
        let inside = clip(Rect::new(0.0, 0.0, 100.0, 100.0), &f, true);
        assert_eq!(inside.stage, Stage::BoxAccept);
        assert!((inside.region.area() - f.area()).abs() < 1e-12);
        let away = clip(Rect::new(200.0, 200.0, 300.0, 300.0), &f, true);
        assert_eq!(away.stage, Stage::BoxReject);
        assert!(away.region.is_empty());
        // A small window wholly inside a reflex sector: the window itself.
        let big = FilledArc::new(EllipseArc::new(e, 0.0, 1.5 * PI).unwrap(), ArcFill::Sector);
        let small = clip(Rect::new(41.0, 51.0, 43.0, 53.0), &big, true);
        assert!((small.region.area() - 4.0).abs() < 1e-12, "{}", small.region.area());
        // ... and one in the missing quarter: nothing.
        let none = clip(Rect::new(51.0, 41.0, 53.0, 43.0), &big, false);
        assert!(none.region.is_empty());
    }

    #[test]
    fn a_side_along_a_window_edge_appears_once() {
        // The upper half disc, its chord (a diameter) on the window's bottom edge.
        let e = Ellipse::circle(Point::ZERO, 1.0).unwrap();
        let half = FilledArc::new(EllipseArc::new(e, 0.0, PI).unwrap(), ArcFill::Chord);
        let c = clip(Rect::new(-0.5, 0.0, 3.0, 3.0), &half, false);
        let exact = 0.5 * (0.5 * 0.75f64.sqrt() + (0.5f64).asin()) + 0.5 * FRAC_PI_2;
        assert!((c.region.area() - exact).abs() < 1e-12, "{} vs {exact}", c.region.area());
        // The window below the chord: nothing of the region.
        let below = clip(Rect::new(-0.5, -3.0, 3.0, 0.0), &half, false);
        assert!(below.region.area().abs() < 1e-12, "{}", below.region.area());
    }
}
