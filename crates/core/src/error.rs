//! Typed errors for bad input, and the validation that produces them.

use core::fmt;

use crate::predicates::Orientation;
use crate::{FillRule, Point, Polygons, Rect, Ring, Segment};

/// Largest coordinate magnitude accepted. Below it every product of two coordinate differences,
/// and sums of a few such products, stay finite, so the exact predicates stay exact.
pub const MAX_COORDINATE: f64 = 1.0e150;

/// Smallest non-zero coordinate magnitude accepted. Above it every non-zero coordinate
/// difference is at least an ulp of 1e-100 (about 1e-116), so products of two differences, and of
/// their rounding errors, stay normal numbers: the exact predicates stay exact, and lengths and
/// parameters along segments do not underflow. Zero is always accepted.
pub const MIN_COORDINATE: f64 = 1.0e-100;

/// Which input a problem was found in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Operand {
    /// The subject polygons.
    Subject,
    /// The clip polygons.
    Clip,
    /// A clipping window.
    Window,
    /// A batch of segments (the part index is the segment index).
    Segments,
}

impl fmt::Display for Operand {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Operand::Subject => "subject",
            Operand::Clip => "clip",
            Operand::Window => "window",
            Operand::Segments => "segment",
        })
    }
}

/// Why a clipper refused its input. Bad input gets one of these; it never panics or loops.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ClipError {
    /// A coordinate is NaN or infinite.
    #[error("{operand} {part}, vertex {vertex}: coordinate is not finite ({x}, {y})")]
    NonFinite {
        /// Which input.
        operand: Operand,
        /// Ring (or segment) index.
        part: usize,
        /// Vertex index within it.
        vertex: usize,
        /// The x found.
        x: f64,
        /// The y found.
        y: f64,
    },
    /// A coordinate's magnitude exceeds [`MAX_COORDINATE`], or is below [`MIN_COORDINATE`] but
    /// not zero.
    #[error(
        "{operand} {part}, vertex {vertex}: coordinate {value:e} is outside the supported range (magnitudes \
         {MIN_COORDINATE:e} to {MAX_COORDINATE:e}, or zero)"
    )]
    OutOfRange {
        /// Which input.
        operand: Operand,
        /// Ring (or segment) index.
        part: usize,
        /// Vertex index within it.
        vertex: usize,
        /// The offending value.
        value: f64,
    },
    /// A ring has fewer than three distinct points.
    #[error("{operand} ring {part} has {distinct} distinct point(s); a ring needs at least 3")]
    TooFewPoints {
        /// Which input.
        operand: Operand,
        /// Ring index.
        part: usize,
        /// Number of distinct points found.
        distinct: usize,
    },
    /// A window that must enclose area encloses none (no ring, zero width or height, all collinear).
    #[error("the window is degenerate: {reason}")]
    DegenerateWindow {
        /// What is wrong with it.
        reason: &'static str,
    },
    /// The clipper needs a single convex ring as its window.
    #[error("{clipper} needs a convex window: {reason}")]
    WindowNotConvex {
        /// The clipper's name.
        clipper: &'static str,
        /// What is wrong with the window.
        reason: &'static str,
    },
    /// The clipper needs an axis-aligned rectangle as its window.
    #[error("{clipper} needs an axis-aligned rectangle as its window")]
    WindowNotRectangle {
        /// The clipper's name.
        clipper: &'static str,
    },
    /// A curve (circle, ellipse, arc) or a flattening tolerance with an unusable parameter: a
    /// radius that is not positive, a non-finite centre, radius, angle or tolerance, a sweep
    /// outside `(0, 2π]`, an ellipse too eccentric or too small for its coordinates.
    #[error("curve {parameter} = {value:e}: {reason}")]
    InvalidCurve {
        /// Which parameter (`radius`, `centre x`, `rotation`, `sweep`, `tolerance`, ...).
        parameter: &'static str,
        /// The value given.
        value: f64,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A snap-rounding pixel size that is not a positive, normal power of two.
    #[error("snap-rounding pixel size {value:e} is not a positive normal power of two")]
    InvalidPixel {
        /// The size given.
        value: f64,
    },
    /// A coordinate too far from the origin for the snap-rounding grid: its pixel centre and
    /// borders must be exact in f64, so it must be within 2^51 pixels of the origin.
    #[error("{operand} {part}, vertex {vertex}: coordinate {value:e} is beyond 2^51 snap-rounding pixels of {pixel:e}")]
    BeyondGrid {
        /// Which input.
        operand: Operand,
        /// Ring index.
        part: usize,
        /// Vertex index within it.
        vertex: usize,
        /// The offending value.
        value: f64,
        /// The pixel size.
        pixel: f64,
    },
    /// The clipper does not do this operation, fill rule or output form.
    #[error("{clipper} does not support {what}")]
    Unsupported {
        /// The clipper's name.
        clipper: &'static str,
        /// What was asked for.
        what: String,
    },
    /// The clipper did not produce a result for valid, supported input: a library reported an
    /// internal error, or an external clipper process crashed, hung or answered garbage.
    #[error("{clipper} failed: {reason}")]
    Failed {
        /// The clipper's name.
        clipper: &'static str,
        /// How it failed: a shrunk failure case must fail the same way as the one found.
        kind: FailureKind,
        /// What went wrong, in the clipper's or the harness's words.
        reason: String,
    },
}

/// How a clipper failed to answer ([`ClipError::Failed`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FailureKind {
    /// A library reported an internal error.
    Internal,
    /// A clipper process exited or closed its output.
    Crashed,
    /// A clipper process gave no answer within its time limit.
    Hung,
    /// A clipper process broke its protocol: a line that is not a reply, a wrong id, a time
    /// that cannot be.
    Garbled,
    /// A clipper process answered with an error of its own.
    Declined,
}

/// True when `v` is finite and in the valid range (NaN fails `<=`), without branches.
#[inline]
fn in_range(v: f64) -> bool {
    (v.abs() <= MAX_COORDINATE) & ((v == 0.0) | (v.abs() >= MIN_COORDINATE))
}

fn check_point(p: Point, operand: Operand, part: usize, vertex: usize) -> Result<(), ClipError> {
    if !p.is_finite() {
        return Err(ClipError::NonFinite { operand, part, vertex, x: p.x, y: p.y });
    }
    for value in [p.x, p.y] {
        if value.abs() > MAX_COORDINATE || (value != 0.0 && value.abs() < MIN_COORDINATE) {
            return Err(ClipError::OutOfRange { operand, part, vertex, value });
        }
    }
    Ok(())
}

/// Checks one ring: finite, in range, at least three distinct points.
pub fn validate_ring(ring: &Ring, operand: Operand, part: usize) -> Result<(), ClipError> {
    // One branch-free pass for the common case, as in `validate_segments`; a ring that fails it
    // is walked again to name the first bad vertex.
    let all_good = ring.points.iter().fold(true, |ok, p| ok & in_range(p.x) & in_range(p.y));
    if !all_good {
        for (vertex, &p) in ring.points.iter().enumerate() {
            check_point(p, operand, part, vertex)?;
        }
    }
    let distinct = ring.distinct_points_up_to(3);
    if distinct < 3 {
        return Err(ClipError::TooFewPoints { operand, part, distinct });
    }
    Ok(())
}

/// Checks every ring of a polygon operand. No rings at all is valid: the empty region.
pub fn validate_polygons(polygons: &Polygons, operand: Operand) -> Result<(), ClipError> {
    polygons.rings.iter().enumerate().try_for_each(|(i, r)| validate_ring(r, operand, i))
}

/// Checks a batch of segments: every endpoint finite and in range. Zero-length segments are
/// valid (they clip to nothing).
pub fn validate_segments(segments: &[Segment]) -> Result<(), ClipError> {
    // The common case in one branch-free pass the compiler vectorises; only a batch that fails
    // it is walked again to name the first bad endpoint.
    let all_good =
        segments.iter().fold(true, |ok, s| ok & in_range(s.a.x) & in_range(s.a.y) & in_range(s.b.x) & in_range(s.b.y));
    if all_good {
        return Ok(());
    }
    for (i, s) in segments.iter().enumerate() {
        check_point(s.a, Operand::Segments, i, 0)?;
        check_point(s.b, Operand::Segments, i, 1)?;
    }
    Ok(())
}

/// Checks a window: valid rings, at least one, enclosing positive area.
pub fn validate_window(window: &Polygons) -> Result<(), ClipError> {
    if window.rings.is_empty() {
        return Err(ClipError::DegenerateWindow { reason: "it has no ring" });
    }
    validate_polygons(window, Operand::Window)?;
    let b = window.bounds();
    if b.width() == 0.0 || b.height() == 0.0 {
        return Err(ClipError::DegenerateWindow { reason: "zero width or height" });
    }
    let all_collinear = window.rings.iter().all(|r| {
        let p = &r.points;
        p.iter().all(|&q| crate::predicates::orient(p[0], p[1], q) == Orientation::Collinear)
            && p.iter().all(|&q| q == p[0] || crate::predicates::orient(p[0], q, p[1]) == Orientation::Collinear)
    });
    if all_collinear {
        return Err(ClipError::DegenerateWindow { reason: "every ring is collinear" });
    }
    Ok(())
}

/// The window as one convex ring (repeated vertices removed) with its orientation, or the error
/// a clipper that needs a convex window should return.
pub fn convex_window(window: &Polygons, clipper: &'static str) -> Result<(Ring, Orientation), ClipError> {
    validate_window(window)?;
    if window.rings.len() != 1 {
        return Err(ClipError::WindowNotConvex { clipper, reason: "it has more than one ring" });
    }
    let ring = window.rings[0].without_repeats();
    match ring.convex_orientation() {
        Some(o) => Ok((ring, o)),
        None => Err(ClipError::WindowNotConvex { clipper, reason: "it turns both ways, folds back or winds twice" }),
    }
}

/// Whether a one-ring convex window (as [`convex_window`] or [`rect_window`] accepted it) covers
/// its interior under `fill`: under positive (negative) a clockwise (counter-clockwise) window
/// winds -1 (+1) inside and so covers nothing; under non-zero and even-odd it always does.
/// Window clippers return the empty result when it does not.
pub fn window_covers(window: &Polygons, fill: FillRule) -> bool {
    window.rings.first().and_then(Ring::convex_orientation).is_some_and(|o| fill.is_inside(o.sign()))
}

/// The window as an axis-aligned rectangle, or the error a rectangle clipper should return.
pub fn rect_window(window: &Polygons, clipper: &'static str) -> Result<Rect, ClipError> {
    validate_window(window)?;
    match window.rings.as_slice() {
        [ring] => ring.as_rect().ok_or(ClipError::WindowNotRectangle { clipper }),
        _ => Err(ClipError::WindowNotRectangle { clipper }),
    }
}
