//! The curve oracle: visible arcs and clipped filled ellipses checked by point sampling against
//! exact window predicates and a careful point-in-ellipse test, plus the identities they obey.

use core::f64::consts::TAU;
use core::fmt;

use clip_core::{
    ArcFill, BoundaryPiece, CurveRegion, Ellipse, EllipseArc, FillRule, FilledArc, Location, Point, Polygons, Rect,
    Segment, locate,
};

use crate::polygon::rounding_distance;
use crate::polygon::sampling::sample_points;

/// Tolerance on interval ends and on the parameter identity, in radians.
pub const CURVE_T_TOLERANCE: f64 = 1e-9;

/// Tolerance on a parameter computed two ways (the split identity, two clippers compared), in
/// radians per interval end. Where the curve is tangent to an edge the crossing's parameter is
/// determined only to about the square root of rounding (about 1e-8 at unit scale; the crossing's
/// position still to rounding, which [`check_visible`] checks), so this is looser than
/// [`CURVE_T_TOLERANCE`].
pub const TANGENT_T_TOLERANCE: f64 = 1e-7;

/// Relative distance (of the case's extent) within which a sample is too near a boundary to
/// judge, and within which an interval end must lie on the window's boundary.
pub const CURVE_MARGIN: f64 = 1e-7;

/// Relative area tolerance (of the ellipse's bounding-box area) for the area identity.
pub const CURVE_AREA_TOLERANCE: f64 = 1e-9;

/// Samples along an arc: evenly spaced, then as many again at seeded random parameters.
const ARC_SAMPLES: usize = 200;

/// Why a curve result is wrong.
#[derive(Clone, Debug, PartialEq)]
pub enum CurveFailure {
    /// An interval is malformed, out of order, outside the arc, or not merged.
    BadIntervals(String),
    /// An interval end that is not an end of the arc lies off the window's boundary.
    EndOffBoundary {
        /// The parameter.
        theta: f64,
        /// Its distance from the window's boundary.
        distance: f64,
    },
    /// A sample of the curve is reported visible when it is outside the window, or not visible
    /// when inside.
    WrongSample {
        /// The parameter.
        theta: f64,
        /// True when the sample is in the window.
        expected: bool,
    },
    /// A region's boundary loop does not close, or a piece is malformed.
    BadLoop(String),
    /// A sample point of the plane is in the region when it should not be, or the reverse (or
    /// is covered twice).
    WrongPoint {
        /// The sample.
        point: Point,
        /// True when the point is in the ellipse and the window.
        expected: bool,
        /// The region's winding number there.
        winding: i32,
    },
    /// An identity between results does not hold.
    Identity(String),
}

impl fmt::Display for CurveFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CurveFailure::BadIntervals(why) => write!(f, "bad intervals: {why}"),
            CurveFailure::EndOffBoundary { theta, distance } => {
                write!(f, "interval end θ = {theta} is {distance:e} from the window's boundary")
            }
            CurveFailure::WrongSample { theta, expected } => write!(
                f,
                "the curve at θ = {theta} is {} the window but reported {}",
                if *expected { "in" } else { "outside" },
                if *expected { "hidden" } else { "visible" }
            ),
            CurveFailure::BadLoop(why) => write!(f, "bad boundary loop: {why}"),
            CurveFailure::WrongPoint { point, expected, winding } => write!(
                f,
                "point ({}, {}) is {} the clipped region but the result winds {winding} around it",
                point.x,
                point.y,
                if *expected { "in" } else { "outside" }
            ),
            CurveFailure::Identity(why) => write!(f, "identity fails: {why}"),
        }
    }
}

impl std::error::Error for CurveFailure {}

/// The distance within which samples are skipped for a case of this ellipse and window.
pub fn curve_margin(e: &Ellipse, window: &Polygons) -> f64 {
    let b = e.bounds().union(window.bounds());
    (b.extent() * CURVE_MARGIN).max(1e3 * rounding_distance(&b))
}

/// Whether `p` is in the closed ellipse, judged only when that is certain: `None` when `p` may
/// lie within `margin` of the curve. The unit frame's radius `|q|` is off by a few ulps at most,
/// and a unit-frame distance `d` from the circle is at least `d` times the short radius in the
/// plane, so `|q|` beyond `1 ± margin / short radius` (plus rounding) decides.
pub fn ellipse_side(e: &Ellipse, p: Point, margin: f64) -> Option<bool> {
    let q = e.to_unit(p);
    let r = q.x.hypot(q.y);
    let (rx, ry) = e.radii();
    let band = margin / rx.min(ry) + 8.0 * f64::EPSILON * (1.0 + r);
    if r < 1.0 - band {
        Some(true)
    } else if r > 1.0 + band {
        Some(false)
    } else {
        None
    }
}

/// Whether `p` is in the closed filled arc (ellipse and closing half-plane or wedge), judged only
/// when that is certain: `None` when `p` may lie within `margin` of the curve or of the line of a
/// closing side (the whole line, so some certain points are skipped too).
pub fn filled_arc_side(f: &FilledArc, p: Point, margin: f64) -> Option<bool> {
    let in_ellipse = ellipse_side(f.ellipse(), p, margin)?;
    if f.is_whole() {
        return Some(in_ellipse);
    }
    let e = f.ellipse();
    let (s, t, c) = (e.point_at(f.arc().start()), e.point_at(f.arc().end()), e.center());
    // Signed distance of p from the line through a and b, positive on its left.
    let left_of = |a: Point, b: Point| {
        let d = (b - a).cross(p - a) / a.distance(b);
        (d.abs() > margin).then_some(d > 0.0)
    };
    let in_closing = match f.fill() {
        ArcFill::Chord => left_of(t, s)?,
        ArcFill::Sector => {
            let (a, b) = (left_of(c, s)?, left_of(t, c)?);
            if f.arc().sweep() <= core::f64::consts::PI { a && b } else { a || b }
        }
    };
    Some(in_ellipse && in_closing)
}

fn distance_to_segment(p: Point, s: Segment) -> f64 {
    let d = s.b - s.a;
    let len2 = d.dot(d);
    let t = if len2 > 0.0 { ((p - s.a).dot(d) / len2).clamp(0.0, 1.0) } else { 0.0 };
    p.distance(s.at(t))
}

fn distance_to_boundary(p: Point, window: &Polygons) -> f64 {
    window.edges().map(|e| distance_to_segment(p, e)).fold(f64::INFINITY, f64::min)
}

/// True when `theta` (any turn) lies in one of the intervals (closed).
fn covered(intervals: &[(f64, f64)], theta: f64) -> bool {
    intervals.iter().any(|&(a, b)| b - a >= TAU || (theta - a).rem_euclid(TAU) <= b - a)
}

/// Checks the visible intervals of `arc` in `window` (even-odd, closed): their form (ascending,
/// positive length, apart, inside the arc, for a whole ellipse one piece at most running past
/// 2π), that every end other than the arc's own lies on the window's boundary, and that samples
/// of the curve away from the boundary are visible exactly when they are in the window (exact
/// point location of the rounded sample).
pub fn check_visible(window: &Polygons, arc: &EllipseArc, intervals: &[(f64, f64)]) -> Result<(), CurveFailure> {
    let e = arc.ellipse();
    let tol = CURVE_T_TOLERANCE;
    let bad = |why: String| Err(CurveFailure::BadIntervals(why));
    for (i, &(a, b)) in intervals.iter().enumerate() {
        if !(a.is_finite() && b.is_finite() && b > a) {
            return bad(format!("interval {i} = ({a}, {b}) is not a positive span"));
        }
        if arc.is_closed() {
            if !(0.0..TAU).contains(&a) || b > a + TAU + tol {
                return bad(format!("interval {i} = ({a}, {b}) of a closed ellipse must start in [0, 2π)"));
            }
        } else if a < arc.start() - tol || b > arc.end() + tol {
            return bad(format!("interval {i} = ({a}, {b}) leaves the arc [{}, {}]", arc.start(), arc.end()));
        }
        if i > 0 && a <= intervals[i - 1].1 {
            return bad(format!("interval {i} starts at {a}, not after the previous end {}", intervals[i - 1].1));
        }
    }
    if arc.is_closed()
        && let (Some(first), Some(last)) = (intervals.first(), intervals.last())
        && intervals.len() > 1
        && last.1 - TAU >= first.0
    {
        return bad(format!("the last interval wraps past the first: {last:?} over {first:?}"));
    }
    let margin = curve_margin(e, window);
    let whole = arc.is_closed() && intervals == [(0.0, TAU)];
    for &(a, b) in intervals {
        for theta in [a, b] {
            let own_end = !arc.is_closed() && ((theta - arc.start()).abs() <= tol || (theta - arc.end()).abs() <= tol);
            if whole || own_end {
                continue;
            }
            let distance = distance_to_boundary(e.point_at(theta), window);
            if distance > margin {
                return Err(CurveFailure::EndOffBoundary { theta, distance });
            }
        }
    }
    let mut rng = 0x0c0f_fee0_u64;
    let mut thetas: Vec<f64> =
        (0..ARC_SAMPLES).map(|k| arc.start() + arc.sweep() * (k as f64 + 0.5) / ARC_SAMPLES as f64).collect();
    thetas.extend((0..ARC_SAMPLES).map(|_| arc.start() + arc.sweep() * unit(&mut rng)));
    for theta in thetas {
        let p = e.point_at(theta);
        if distance_to_boundary(p, window) <= margin {
            continue;
        }
        let expected = locate(p, window, FillRule::EvenOdd) == Location::Inside;
        if covered(intervals, theta) != expected {
            return Err(CurveFailure::WrongSample { theta, expected });
        }
    }
    Ok(())
}

/// A uniform f64 in [0, 1) (SplitMix64).
fn unit(state: &mut u64) -> f64 {
    *state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
}

/// The winding number of the region's boundary around `p`, from a ray towards +x in the
/// ellipse's unit frame (an orientation-keeping affine map, so winding numbers are unchanged):
/// arcs of the unit circle cross it where `sin θ = y`, segments by the usual half-open rule.
/// Meant for points away from the boundary: `None` when `p` is within `1e-9` (unit frame) of the
/// height of a piece's end, where rounded ends of adjoining pieces could miscount.
pub fn region_winding(region: &CurveRegion, p: Point) -> Option<i32> {
    let e = &region.ellipse;
    let q = e.to_unit(p);
    let mut w = 0;
    for piece in region.pieces() {
        match *piece {
            BoundaryPiece::Arc { from, to } => {
                for end in [from, to] {
                    if (end.sin() - q.y).abs() < 1e-9 {
                        return None;
                    }
                }
                if q.y.abs() >= 1.0 {
                    continue;
                }
                let s = q.y.asin();
                for theta in [s, core::f64::consts::PI - s] {
                    let on_arc = to - from >= TAU || (theta - from).rem_euclid(TAU) <= to - from;
                    if on_arc && theta.cos() > q.x {
                        w += if theta.cos() > 0.0 { 1 } else { -1 };
                    }
                }
            }
            BoundaryPiece::Segment(s) => {
                let (a, b) = (e.to_unit(s.a), e.to_unit(s.b));
                if (a.y - q.y).abs() < 1e-9 || (b.y - q.y).abs() < 1e-9 {
                    return None;
                }
                if (a.y > q.y) != (b.y > q.y) {
                    let x = a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y);
                    if x > q.x {
                        w += if b.y > a.y { 1 } else { -1 };
                    }
                }
            }
        }
    }
    Some(w)
}

/// Checks a clipped filled ellipse: every loop closes (each piece starts within the margin of
/// where the previous ends), arcs run forwards, and at sample points over the region's
/// surroundings away from every boundary the result winds once around points in both the
/// ellipse ([`ellipse_side`]) and the window (exact even-odd location) and zero times elsewhere.
pub fn check_region(window: &Polygons, region: &CurveRegion) -> Result<(), CurveFailure> {
    check_filled_region(window, &FilledArc::whole(region.ellipse), region)
}

/// [`check_region`] for a clipped filled arc (sector or chord region; a whole ellipse too):
/// sample points are judged by [`filled_arc_side`].
pub fn check_filled_region(window: &Polygons, filled: &FilledArc, region: &CurveRegion) -> Result<(), CurveFailure> {
    let e = &region.ellipse;
    if e != filled.ellipse() {
        return Err(CurveFailure::BadLoop("the region is of another ellipse than the filled arc's".into()));
    }
    let margin = curve_margin(e, window);
    for (i, lp) in region.loops.iter().enumerate() {
        for (j, piece) in lp.iter().enumerate() {
            if let BoundaryPiece::Arc { from, to } = *piece
                && !(from.is_finite() && to.is_finite() && to > from && to - from <= TAU + CURVE_T_TOLERANCE)
            {
                return Err(CurveFailure::BadLoop(format!("loop {i} piece {j}: arc ({from}, {to})")));
            }
            let next = &lp[(j + 1) % lp.len()];
            let gap = piece.end(e).distance(next.start(e));
            if gap > margin {
                return Err(CurveFailure::BadLoop(format!(
                    "loop {i}: piece {j} ends {gap:e} from where the next starts"
                )));
            }
        }
    }
    let around = e.bounds().union(window.bounds());
    let b = filled.bounds();
    let w = window.bounds();
    let overlap = Rect::new(b.min.x.max(w.min.x), b.min.y.max(w.min.y), b.max.x.min(w.max.x), b.max.y.min(w.max.y));
    let look = if overlap.is_empty() { around } else { overlap.inflate(0.05 * overlap.extent()) };
    for p in sample_points(&look) {
        let Some(in_shape) = filled_arc_side(filled, p, margin) else { continue };
        if distance_to_boundary(p, window) <= margin {
            continue;
        }
        let expected = in_shape && locate(p, window, FillRule::EvenOdd) == Location::Inside;
        let Some(winding) = region_winding(region, p) else { continue };
        if winding != i32::from(expected) {
            return Err(CurveFailure::WrongPoint { point: p, expected, winding });
        }
    }
    Ok(())
}

/// The window's complement around `around` (a box holding the curves to clip): the window's
/// rings plus a rectangle holding both, read even-odd. Clipping against it and against the
/// window splits a curve between the two, so visible spans add up to the arc's sweep and clipped
/// areas to the ellipse's.
pub fn complement_window(window: &Polygons, around: &Rect) -> Polygons {
    let b = window.bounds().union(*around);
    let mut rings = window.rings.clone();
    rings.push(b.inflate(0.1 * b.extent() + 1.0).to_ring());
    Polygons::new(rings)
}

/// The total parameter span of some intervals.
pub fn span(intervals: &[(f64, f64)]) -> f64 {
    intervals.iter().map(|(a, b)| b - a).sum()
}

/// Checks the split identities: spans in the window and in its complement add up to the arc's
/// sweep (within [`TANGENT_T_TOLERANCE`] per interval end), and, when given, the clipped areas of
/// a filled arc (or whole ellipse) in both to its exact area, [`FilledArc::area`] (within
/// [`CURVE_AREA_TOLERANCE`] of the ellipse's bounding box's area).
pub fn check_identities(
    arc: &EllipseArc,
    inside: &[(f64, f64)],
    outside: &[(f64, f64)],
    areas: Option<(&FilledArc, f64, f64)>,
) -> Result<(), CurveFailure> {
    let sum = span(inside) + span(outside);
    let ends = 2 * (inside.len() + outside.len()) + 2;
    if (sum - arc.sweep()).abs() > TANGENT_T_TOLERANCE * ends as f64 {
        return Err(CurveFailure::Identity(format!(
            "visible spans in the window and its complement add to {sum}, not the sweep {}",
            arc.sweep()
        )));
    }
    if let Some((filled, a, b)) = areas {
        let tolerance = CURVE_AREA_TOLERANCE * filled.ellipse().bounds().area();
        if (a + b - filled.area()).abs() > tolerance {
            return Err(CurveFailure::Identity(format!(
                "clipped areas in the window ({a}) and its complement ({b}) add to {}, not the {} area {}",
                a + b,
                if filled.is_whole() { "ellipse's" } else { filled.fill().name() },
                filled.area()
            )));
        }
    }
    Ok(())
}
