//! `Clipper2RectClipper` behind clip-core's `PolygonClipper` trait.

use clip_core::{
    BoolOp, ClipError, FillRule, Operand, Point, PolygonCapabilities, PolygonClipper, Polygons, Rect, Ring, WindowKind,
    rect_window, validate_polygons, window_covers,
};

use crate::NAME;
use crate::ffi::{GridPoint, GridRect, rect_clip};
use crate::grid::IntegerGrid;

/// Clipper2's `RectClip`, registered as `clipper2-rect`: intersection of any subject with an
/// axis-aligned rectangle, each subject ring clipped on its own.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Clipper2RectClipper;

impl Clipper2RectClipper {
    /// Clips every ring of `subject` to `rect` on the integer grid fitted to both: one call to
    /// Clipper2's `RectClip` for the whole ring list. Output vertices on the rectangle's sides
    /// get the side's exact coordinate back.
    pub fn clip_to_rect(&self, subject: &Polygons, rect: &Rect) -> Result<Polygons, ClipError> {
        let grid = IntegerGrid::fitting(subject.bounds().union(*rect));
        let window = GridRect { min: grid.to_grid(rect.min), max: grid.to_grid(rect.max) };
        let paths: Vec<Vec<GridPoint>> =
            subject.rings.iter().map(|r| r.points.iter().map(|&p| grid.to_grid(p)).collect()).collect();
        let clipped = rect_clip(window, &paths).ok_or_else(|| ClipError::Unsupported {
            clipper: NAME,
            what: "an output with more than i32::MAX paths or points per path".into(),
        })?;
        let back = |q: GridPoint| on_sides(grid.to_point(q), q, window, rect);
        Ok(Polygons::new(clipped.into_iter().map(|path| Ring::new(path.into_iter().map(back).collect())).collect()))
    }
}

/// `p` (grid point `q` mapped back) with each coordinate that lies on a side of the grid window
/// replaced by that side's exact coordinate, so cut points land on the rectangle itself.
fn on_sides(p: Point, q: GridPoint, window: GridRect, rect: &Rect) -> Point {
    let snap = |v: f64, i: i64, lo: i64, hi: i64, exact_lo: f64, exact_hi: f64| {
        if i == lo {
            exact_lo
        } else if i == hi {
            exact_hi
        } else {
            v
        }
    };
    Point::new(
        snap(p.x, q[0], window.min[0], window.max[0], rect.min.x, rect.max.x),
        snap(p.y, q[1], window.min[1], window.max[1], rect.min.y, rect.max.y),
    )
}

impl PolygonClipper for Clipper2RectClipper {
    fn name(&self) -> &'static str {
        NAME
    }

    fn capabilities(&self) -> PolygonCapabilities {
        PolygonCapabilities::window_clipper(WindowKind::Rectangle)
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        self.capabilities().check(NAME, op, fill)?;
        validate_polygons(subject, Operand::Subject)?;
        let rect = rect_window(clip, NAME)?;
        // RectClip itself ignores the window's orientation.
        if !window_covers(clip, fill) {
            return Ok(Polygons::empty());
        }
        self.clip_to_rect(subject, &rect)
    }
}
