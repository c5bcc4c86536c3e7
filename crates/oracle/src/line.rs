//! The exact oracle for line clipping: closed-set visible intervals of a segment in a window.
//!
//! docs/DESIGN.md's rule: the visible part of `P(t) = a + t (b - a)`, `t` in `[0, 1]`, is the set of
//! maximal intervals `[ta, tb]`, `tb > ta`, on which every point lies in the closed window
//! (interior under even-odd, or boundary). Adjacent intervals are merged and isolated touch
//! points dropped.

use clip_core::predicates::{Orientation, orient, orient2d};
use clip_core::{Point, Polygons, Rect, Segment, SegmentIntersection, VisiblePiece, segment_intersection};
use core::fmt;

use crate::polygon::{SNAP_ROUNDINGS, rounding_distance};

/// The parameter tolerance `verify` compares line clippers' pieces with.
pub const LINE_T_TOLERANCE: f64 = 1e-9;

/// Why a batch of pieces is wrong.
#[derive(Clone, Debug, PartialEq)]
pub enum LineFailure {
    /// A segment's pieces, as parameter intervals, differ from the exact ones.
    WrongPieces {
        /// Index of the segment in the batch.
        segment: usize,
        /// The exact visible intervals.
        expected: Vec<(f64, f64)>,
        /// The clipper's pieces as intervals.
        got: Vec<(f64, f64)>,
    },
    /// A piece breaks the form: off its segment, reversed, zero length, out of order, unmerged.
    BadPiece(String),
}

impl fmt::Display for LineFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LineFailure::WrongPieces { segment, expected, got } => {
                write!(f, "segment {segment}: visible intervals should be {expected:?}, got {got:?}")
            }
            LineFailure::BadPiece(why) => write!(f, "bad piece: {why}"),
        }
    }
}

impl std::error::Error for LineFailure {}

/// The exact closed-set visible parameter intervals of `s` in `window` (even-odd interior,
/// boundary included), sorted by `t`.
///
/// Every `t` where `s` meets an edge comes from the exact classification of the pair
/// ([`segment_intersection`]): proper crossings from the line equations, touching points and
/// collinear overlaps from their exact endpoints. Between consecutive such `t`s the segment is
/// wholly in or wholly out: runs along an overlap are on the boundary (visible); the rest are
/// classified by an exact point location of an interior point. A zero-length segment has no
/// visible interval.
///
/// ```
/// use clip_core::{Point, Polygons, Rect, Segment};
/// use clip_oracle::line::visible_intervals;
///
/// let square = Polygons::from(Rect::new(0.0, 0.0, 10.0, 10.0));
/// let s = Segment::new(Point::new(-5.0, 5.0), Point::new(15.0, 5.0));
/// assert_eq!(visible_intervals(&square, s), vec![(0.25, 0.75)]);
/// // Touching a corner only: nothing visible.
/// let touch = Segment::new(Point::new(5.0, 15.0), Point::new(15.0, 5.0));
/// assert_eq!(visible_intervals(&square, touch), vec![]);
/// ```
pub fn visible_intervals(window: &Polygons, s: Segment) -> Vec<(f64, f64)> {
    visible_intervals_along(window, s, s)
}

/// [`visible_intervals`] as parameters along `frame`, a part of `s` holding every point of it
/// that can be visible: `s` itself, or for a segment reaching far past the window its part near
/// it ([`Segment::part_near`] of the window's bounding box), along which a window's width is
/// still many steps of the parameter (along the whole of a segment with ends at ±1e17, a window
/// 10 wide is less than one). What is visible is decided on `s`, exactly, as for `s` itself;
/// only the parameters are measured along `frame`.
pub fn visible_intervals_along(window: &Polygons, s: Segment, frame: Segment) -> Vec<(f64, f64)> {
    if s.is_degenerate() || !s.a.is_finite() || !s.b.is_finite() {
        return Vec::new();
    }
    let bounds = s.bounds();
    let mut ts = vec![0.0, 1.0];
    let mut overlaps: Vec<(f64, f64)> = Vec::new();
    for e in window.edges() {
        if !bounds.intersects(&e.bounds()) {
            continue;
        }
        match segment_intersection(s, e) {
            SegmentIntersection::None => {}
            SegmentIntersection::Crossing(_) => ts.push(crossing_t((s, frame), e)),
            SegmentIntersection::Touching(p) => ts.push(t_of(frame, p)),
            SegmentIntersection::Overlap(o) => {
                let (ta, tb) = (t_of(frame, o.a), t_of(frame, o.b));
                ts.extend([ta, tb]);
                overlaps.push((ta.min(tb), ta.max(tb)));
            }
        }
    }
    ts.sort_unstable_by(f64::total_cmp);
    ts.dedup();
    let mut out: Vec<(f64, f64)> = Vec::new();
    for w in ts.windows(2) {
        let (ta, tb) = (w[0], w[1]);
        if tb <= ta || !run_is_visible(window, (s, frame), ta, tb, &overlaps) {
            continue;
        }
        match out.last_mut() {
            Some(last) if last.1 == ta => last.1 = tb,
            _ => out.push((ta, tb)),
        }
    }
    out
}

/// `t` of a point known to lie on `s`: exact at the endpoints, else by projection.
fn t_of(s: Segment, p: Point) -> f64 {
    if p == s.a {
        0.0
    } else if p == s.b {
        1.0
    } else {
        s.param_of(p).clamp(0.0, 1.0)
    }
}

/// `t` along `frame` where the interiors of `s` and `e` cross (known to cross), clamped to `frame`.
fn crossing_t((s, frame): (Segment, Segment), e: Segment) -> f64 {
    if frame != s {
        // A part near the window: its ends lie on the line of `s` only to within rounding at the
        // box's magnitude, so the edge's line function at them can put the crossing with an edge
        // nearly parallel to `s` anywhere along it (found by the `line_clippers` fuzz target: an
        // edge of slope 6e-75 under a segment reaching 2e77, whose crossing came out at the
        // part's end). The crossing is placed along the edge instead, at the window's own
        // magnitude, from the exact line of `s`, and measured along `frame`.
        let (fa, fb) = (orient2d(s.a, s.b, e.a), orient2d(s.a, s.b, e.b));
        let u = fa / (fa - fb);
        let at = if u.is_finite() { e.a.lerp(e.b, u.clamp(0.0, 1.0)) } else { e.a.lerp(e.b, 0.5) };
        return t_of(frame, at);
    }
    // From the edge's line function at the ends, each accurate to about an ulp of itself: the
    // plain cross products cancel for a segment nearly parallel to the edge (found by the
    // `line_clippers` fuzz target: segments along sliver windows 1e-16 wide).
    let (ga, gb) = (orient2d(e.a, e.b, s.a), orient2d(e.a, e.b, s.b));
    let t = ga / (ga - gb);
    if t.is_finite() { t.clamp(0.0, 1.0) } else { 0.5 }
}

/// Whether the run of `s` ending at event `tb` (it meets no edge inside) is inside the window,
/// exactly: the parity of the window edges that the segment's line crosses beyond the run, on the
/// ray from the run through `s.b` (the half-open rule: an edge counts when its ends are on
/// opposite sides of the line, a point on the line taken as below it). Where an edge crosses the
/// line comes from exact predicates, or from the same parameters the events were made of. A point
/// placed inside the run and rounded cannot decide this where the window is thinner than an ulp
/// (found by the `line_clippers` fuzz target: a segment running 1e-16 inside a sliver window,
/// whose rounded midpoint fell outside).
fn run_parity(window: &Polygons, (s, frame): (Segment, Segment), tb: f64) -> bool {
    let above = |p: Point| orient(s.a, s.b, p) == Orientation::CounterClockwise;
    let mut inside = false;
    for e in window.edges() {
        if above(e.a) != above(e.b) && crosses_beyond((s, frame), e, tb) {
            inside = !inside;
        }
    }
    inside
}

/// For an edge `e` whose ends are on opposite sides of the line of `s` (a point on it counting as
/// below): whether it meets that line at or beyond parameter `tb` (along `frame`).
fn crosses_beyond((s, frame): (Segment, Segment), e: Segment, tb: f64) -> bool {
    let on_line = [e.a, e.b].into_iter().find(|&p| orient(s.a, s.b, p) == Orientation::Collinear);
    if let Some(v) = on_line {
        return if on_segment(s, v) { t_of(frame, v) >= tb } else { beyond_b(s, v) };
    }
    match segment_intersection(s, e) {
        SegmentIntersection::Crossing(_) => crossing_t((s, frame), e) >= tb,
        SegmentIntersection::Touching(p) => t_of(frame, p) >= tb,
        // Off the segment: `a` and `b` are on one side of the edge's line, and the crossing is
        // beyond `b` when `b` is the nearer (accurate magnitudes; equal ones would be parallel).
        _ => orient2d(e.a, e.b, s.b).abs() < orient2d(e.a, e.b, s.a).abs(),
    }
}

/// For `v` on the line of `s` but off the segment: whether it lies beyond `b` (exact comparisons
/// of coordinates along the line).
fn beyond_b(s: Segment, v: Point) -> bool {
    if s.a.x != s.b.x { (v.x > s.b.x) == (s.b.x > s.a.x) } else { (v.y > s.b.y) == (s.b.y > s.a.y) }
}

/// Whether `p`, on the line of `s`, lies on the segment (ends included).
fn on_segment(s: Segment, p: Point) -> bool {
    s.bounds().contains(p)
}

/// Whether the run `(ta, tb)` of `s` (along `frame`), which meets no edge inside, is in the closed window.
fn run_is_visible(window: &Polygons, s: (Segment, Segment), ta: f64, tb: f64, overlaps: &[(f64, f64)]) -> bool {
    if overlaps.iter().any(|&(oa, ob)| oa <= ta && tb <= ob) {
        return true; // along an edge: boundary
    }
    run_parity(window, s, tb)
}

/// Each segment's pieces as parameter intervals `(t(piece.a), t(piece.b))`, in the order given;
/// one list per segment. The parameters run along each segment's part near the window of
/// bounding box `window` ([`Segment::part_near`]: the segment itself unless it reaches far past
/// the window), as [`visible_intervals_along`] gives them.
pub fn pieces_to_intervals(window: &Rect, segments: &[Segment], pieces: &[VisiblePiece]) -> Vec<Vec<(f64, f64)>> {
    let mut out = vec![Vec::new(); segments.len()];
    for p in pieces {
        if let Some(s) = segments.get(p.segment) {
            let frame = s.part_near(window);
            out[p.segment].push((t_of_piece(&frame, p.piece.a), t_of_piece(&frame, p.piece.b)));
        }
    }
    out
}

fn t_of_piece(s: &Segment, p: Point) -> f64 {
    if p == s.a {
        0.0
    } else if p == s.b {
        1.0
    } else {
        s.param_of(p)
    }
}

/// Checks a clipper's pieces for a batch: segment indices valid and in input order; each piece
/// of positive length, on its segment (within `t_tolerance` of its length; of the length of its
/// part near the window for a segment reaching far past it, as everything measured along such
/// a segment: [`visible_intervals_along`]), running its way,
/// inside `[0, 1]`; a segment's pieces in increasing `t`, apart (pieces that meet exactly should
/// have been merged); and, as `t`-intervals, equal to [`visible_intervals`] within
/// `t_tolerance` (ends may differ by it, and gaps and intervals up to it long may be on one side
/// only, as rounding may make or miss them). Far from the origin the tolerance grows to what
/// rounding moves along a short segment ([`parameter_tolerance`]).
pub fn check_line_batch(
    window: &Polygons,
    segments: &[Segment],
    pieces: &[VisiblePiece],
    t_tolerance: f64,
) -> Result<(), LineFailure> {
    let bad = |why: String| Err(LineFailure::BadPiece(why));
    let window_bounds = window.bounds();
    // Positions along each segment are measured on its part near the window (itself unless it
    // reaches far past the window), where the window's size is many steps of the parameter.
    let frames: Vec<Segment> = segments.iter().map(|s| s.part_near(&window_bounds)).collect();
    let mut last_segment = 0;
    for (k, p) in pieces.iter().enumerate() {
        let Some(s) = frames.get(p.segment) else {
            return bad(format!("piece {k} names segment {} of a batch of {}", p.segment, segments.len()));
        };
        if p.segment < last_segment {
            return bad(format!("piece {k} (segment {}) comes after segment {last_segment}'s", p.segment));
        }
        last_segment = p.segment;
        if !p.piece.a.is_finite() || !p.piece.b.is_finite() || p.piece.is_degenerate() {
            return bad(format!("piece {k} of segment {} is empty or not finite: {:?}", p.segment, p.piece));
        }
        let len = s.length();
        let t_tolerance = parameter_tolerance(&window_bounds, *s, t_tolerance);
        let off = |q: Point| (q - s.a).cross(s.b - s.a).abs() / len;
        if len == 0.0 || off(p.piece.a) > t_tolerance * len || off(p.piece.b) > t_tolerance * len {
            return bad(format!("piece {k} {:?} is not on segment {} {:?}", p.piece, p.segment, s));
        }
        let (ta, tb) = (s.param_of(p.piece.a), s.param_of(p.piece.b));
        if tb <= ta {
            return bad(format!("piece {k} of segment {} runs against it (t {ta} -> {tb})", p.segment));
        }
        if ta < -t_tolerance || tb > 1.0 + t_tolerance {
            return bad(format!("piece {k} of segment {} leaves it (t {ta} -> {tb})", p.segment));
        }
        if k > 0 && pieces[k - 1].segment == p.segment {
            let prev = pieces[k - 1].piece;
            if prev.b == p.piece.a {
                return bad(format!(
                    "pieces {} and {k} of segment {} meet at {:?}: they should be one",
                    k - 1,
                    p.segment,
                    p.piece.a
                ));
            }
            if s.param_of(prev.b) > ta + t_tolerance {
                return bad(format!("pieces {} and {k} of segment {} overlap or are out of order", k - 1, p.segment));
            }
        }
    }
    let got = pieces_to_intervals(&window_bounds, segments, pieces);
    for (i, (s, frame)) in segments.iter().zip(&frames).enumerate() {
        let expected = visible_intervals_along(window, *s, *frame);
        if !same_intervals(&expected, &got[i], parameter_tolerance(&window_bounds, *frame, t_tolerance)) {
            return Err(LineFailure::WrongPieces { segment: i, expected, got: got[i].clone() });
        }
    }
    Ok(())
}

/// The tolerance on `t` for segment `s`: `t_tolerance`, or, where it is larger, what rounding a
/// computed crossing moves along the segment at the magnitude of the case's coordinates
/// ([`SNAP_ROUNDINGS`] times the `rounding_distance` of the window's and the segment's bounds,
/// over the segment's length: a crossing is a few ulps off, as in the polygon oracle's snap). Far
/// from the origin a short segment's pieces cannot end closer to the exact crossings than that
/// (found by the `line_clippers` fuzz target: segments 1e-6 long at 1e9, where an ulp is 1.2e-7).
pub fn parameter_tolerance(window_bounds: &Rect, s: Segment, t_tolerance: f64) -> f64 {
    let len = s.length();
    if len == 0.0 {
        return t_tolerance;
    }
    t_tolerance.max(SNAP_ROUNDINGS * rounding_distance(&window_bounds.union(s.bounds())) / len)
}

/// Equal within `tol`: each side, shrunk by `tol / 2` at every end, lies inside the other grown
/// by `tol / 2`. So ends may differ by `tol`, and an interval or gap up to `tol` long may be on one
/// side only; there is no length at which one side's interval counts and the other's, rounded a
/// little shorter, does not (found by the `line_clippers` fuzz target).
fn same_intervals(a: &[(f64, f64)], b: &[(f64, f64)], tol: f64) -> bool {
    covered_within(a, b, tol / 2.0) && covered_within(b, a, tol / 2.0)
}

/// Every interval of `a` shrunk by `tol` at both ends lies in one interval of `b` grown by `tol`.
fn covered_within(a: &[(f64, f64)], b: &[(f64, f64)], tol: f64) -> bool {
    let mut grown: Vec<(f64, f64)> = b.iter().map(|&(x, y)| (x - tol, y + tol)).collect();
    grown.sort_by(|p, q| p.0.total_cmp(&q.0));
    let mut merged: Vec<(f64, f64)> = Vec::with_capacity(grown.len());
    for (x, y) in grown {
        match merged.last_mut() {
            Some(last) if x <= last.1 => last.1 = last.1.max(y),
            _ => merged.push((x, y)),
        }
    }
    a.iter()
        .map(|&(x, y)| (x + tol, y - tol))
        .filter(|(x, y)| y > x)
        .all(|(x, y)| merged.iter().any(|&(p, q)| p <= x && y <= q))
}
