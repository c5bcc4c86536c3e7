//! A window prepared once for clipping many curves: a rectangle, or any polygons read even-odd.

use clip_core::{ClipError, FillRule, Location, Point, Polygons, Rect, Segment, locate, rect_window, validate_window};

use crate::boundary_edges::oriented_boundary;

/// The name the clipper gives in its errors.
pub const CLIPPER: &str = "curve";

/// A prepared window.
#[derive(Clone, Debug)]
pub enum CurveWindow {
    /// One axis-aligned rectangle: the lecture's window, with the quadrant and octant tests.
    Rectangle(Rect),
    /// Any polygons read under even-odd (concave, holes, several parts).
    Polygon(PolygonWindow),
}

/// A general window: its rings for exact point location, its edges for the curve-line equations,
/// and its even-odd boundary with the interior on the left for the filled region.
#[derive(Clone, Debug)]
pub struct PolygonWindow {
    /// The rings as given.
    pub rings: Polygons,
    /// The bounding box.
    pub bounds: Rect,
    /// Every edge of positive length, as given.
    pub edges: Vec<Segment>,
    /// The even-odd boundary, each piece with the window on its left.
    pub boundary: Vec<Segment>,
}

impl CurveWindow {
    /// The window as a rectangle when it is one axis-aligned rectangle, otherwise as polygons.
    /// A degenerate window (no ring, zero width or height, all collinear) or bad coordinates are
    /// a [`ClipError`].
    pub fn new(window: &Polygons) -> Result<CurveWindow, ClipError> {
        match rect_window(window, CLIPPER) {
            Ok(r) => Ok(CurveWindow::Rectangle(r)),
            Err(ClipError::WindowNotRectangle { .. }) => CurveWindow::polygon(window),
            Err(e) => Err(e),
        }
    }

    /// The window as polygons even when it is a rectangle (no quadrant or octant tests).
    pub fn polygon(window: &Polygons) -> Result<CurveWindow, ClipError> {
        validate_window(window)?;
        let edges: Vec<Segment> = window.edges().filter(|e| !e.is_degenerate()).collect();
        Ok(CurveWindow::Polygon(PolygonWindow {
            rings: window.clone(),
            bounds: window.bounds(),
            boundary: oriented_boundary(window),
            edges,
        }))
    }

    /// The bounding box.
    pub fn bounds(&self) -> Rect {
        match self {
            CurveWindow::Rectangle(r) => *r,
            CurveWindow::Polygon(p) => p.bounds,
        }
    }

    /// Where `p` lies: inside, on the boundary or outside (exact for the given point).
    #[inline]
    pub fn locate(&self, p: Point) -> Location {
        match self {
            CurveWindow::Rectangle(r) => locate_in_rect(r, p),
            CurveWindow::Polygon(w) if !w.bounds.contains(p) => Location::Outside,
            CurveWindow::Polygon(w) => locate(p, &w.rings, FillRule::EvenOdd),
        }
    }

    /// The boundary with the window on the left (a rectangle counter-clockwise).
    pub fn oriented_boundary(&self) -> Vec<Segment> {
        match self {
            CurveWindow::Rectangle(r) => r.to_ring().edges().collect(),
            CurveWindow::Polygon(w) => w.boundary.clone(),
        }
    }
}

/// Where `p` lies in the closed rectangle `r` (exact comparisons).
#[inline]
pub fn locate_in_rect(r: &Rect, p: Point) -> Location {
    if clip_core::predicates::strictly_inside_rect(p, r) {
        Location::Inside
    } else if r.contains(p) {
        Location::Boundary
    } else {
        Location::Outside
    }
}
