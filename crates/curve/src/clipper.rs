//! The clipper: a window prepared once, then curves clipped one by one, with the lecture's
//! preliminary tests on or off.

use clip_core::{ClipError, Ellipse, EllipseArc, FilledArc, Polygons};

use crate::filled_arc::clip_filled_arc;

use crate::outline::{Visible, visible};
use crate::region::{Clipped, clip_filled};
use crate::window::CurveWindow;

/// The curve clipper. `preliminary_tests` turns on the lecture's tests (bounding rectangle, then
/// quadrant and octant extents on rectangle windows); off, every curve goes straight to the
/// curve-line equations. Both give the same answers up to rounding.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CurveClipper {
    /// Run the preliminary tests before the equations.
    pub preliminary_tests: bool,
}

impl CurveClipper {
    /// With the preliminary tests (the lecture's method).
    pub const WITH_TESTS: CurveClipper = CurveClipper { preliminary_tests: true };
    /// Equations only, for measuring what the tests save.
    pub const WITHOUT_TESTS: CurveClipper = CurveClipper { preliminary_tests: false };

    /// The registry name: `curve`, or `curve-no-tests`.
    pub fn name(&self) -> &'static str {
        if self.preliminary_tests { "curve" } else { "curve-no-tests" }
    }

    /// Prepares `window`: an axis-aligned rectangle gets the rectangle clipper, anything else is
    /// read as polygons under even-odd. A degenerate window or bad coordinates are an error.
    pub fn prepare(&self, window: &Polygons) -> Result<PreparedCurveWindow, ClipError> {
        Ok(PreparedCurveWindow { window: CurveWindow::new(window)?, tests: self.preliminary_tests })
    }

    /// Prepares `window` as polygons even when it is a rectangle.
    pub fn prepare_polygon(&self, window: &Polygons) -> Result<PreparedCurveWindow, ClipError> {
        Ok(PreparedCurveWindow { window: CurveWindow::polygon(window)?, tests: self.preliminary_tests })
    }
}

/// A window ready to clip curves.
#[derive(Clone, Debug)]
pub struct PreparedCurveWindow {
    window: CurveWindow,
    tests: bool,
}

impl PreparedCurveWindow {
    /// The prepared window.
    pub fn window(&self) -> &CurveWindow {
        &self.window
    }

    /// The visible parameter intervals of an arc (or a whole ellipse), and the stage that
    /// settled it.
    pub fn visible(&self, arc: &EllipseArc) -> Visible {
        visible(&self.window, arc, self.tests)
    }

    /// The part of the filled ellipse inside the window, and the stage that settled it.
    pub fn clip_filled(&self, ellipse: &Ellipse) -> Clipped {
        clip_filled(&self.window, ellipse, self.tests)
    }

    /// The part of the filled arc (sector or chord region; a whole ellipse when its sweep is 2π)
    /// inside the window, and the stage that settled it (its own box, then its arc's tests).
    pub fn clip_filled_arc(&self, filled: &FilledArc) -> Clipped {
        clip_filled_arc(&self.window, filled, self.tests)
    }
}
