//! Arcs and clipped regions turned into polylines and rings within a requested tolerance.

use clip_core::{BoundaryPiece, ClipError, CurveRegion, Ellipse, FilledArc, Point, Polygons, Ring};

/// Most vertices a flattening may make before the tolerance is refused as too fine.
pub const MAX_FLATTEN_VERTICES: usize = 10_000_000;

/// The largest parameter step whose chord stays within `tolerance` of the ellipse: the ellipse
/// is the unit circle stretched by at most its long radius `a`, so a chord over `Δθ` is off by at
/// most `a (1 - cos(Δθ / 2))`. At most a quarter turn, so every piece has a few vertices.
fn max_step(e: &Ellipse, tolerance: f64) -> f64 {
    let a = e.max_radius();
    let ratio = (1.0 - tolerance / a).max(-1.0);
    (2.0 * ratio.acos()).clamp(f64::MIN_POSITIVE, core::f64::consts::FRAC_PI_2)
}

/// Checks a tolerance: positive and finite.
pub fn check_tolerance(tolerance: f64) -> Result<(), ClipError> {
    if !tolerance.is_finite() || tolerance <= 0.0 {
        return Err(ClipError::InvalidCurve {
            parameter: "tolerance",
            value: tolerance,
            reason: "a flattening tolerance must be positive and finite",
        });
    }
    Ok(())
}

fn too_fine(tolerance: f64) -> ClipError {
    ClipError::InvalidCurve {
        parameter: "tolerance",
        value: tolerance,
        reason: "too fine: the flattening would exceed 10^7 vertices",
    }
}

/// Points of the ellipse from parameter `from` to `to` with chords within `tolerance`, both
/// ends included, appended to `out`; the number of chords is returned.
pub fn flatten_arc(
    e: &Ellipse,
    (from, to): (f64, f64),
    tolerance: f64,
    out: &mut Vec<Point>,
) -> Result<usize, ClipError> {
    check_tolerance(tolerance)?;
    let chords = ((to - from) / max_step(e, tolerance)).ceil().max(1.0);
    if chords > MAX_FLATTEN_VERTICES as f64 || out.len() + chords as usize > MAX_FLATTEN_VERTICES {
        return Err(too_fine(tolerance));
    }
    let n = chords as usize;
    let step = (to - from) / chords;
    out.extend((0..n).map(|k| e.point_at(from + step * k as f64)));
    out.push(e.point_at(to));
    Ok(n)
}

/// The visible arcs as polylines within `tolerance` of the curve.
pub fn flatten_intervals(e: &Ellipse, intervals: &[(f64, f64)], tolerance: f64) -> Result<Vec<Vec<Point>>, ClipError> {
    intervals
        .iter()
        .map(|&iv| {
            let mut line = Vec::new();
            flatten_arc(e, iv, tolerance, &mut line)?;
            Ok(line)
        })
        .collect()
}

/// The region as rings: each loop's arcs replaced by chords within `tolerance` of the curve
/// (inscribed, so the rings lie inside the ellipse), its window pieces kept. Outer rings are
/// counter-clockwise and holes clockwise, as the loops run; repeated vertices are dropped and
/// loops left with fewer than three points (rounding slivers) are dropped. The area differs
/// from [`CurveRegion::area`] by at most `tolerance` times the arcs' length.
pub fn flatten_region(region: &CurveRegion, tolerance: f64) -> Result<Polygons, ClipError> {
    check_tolerance(tolerance)?;
    let e = &region.ellipse;
    let mut rings = Vec::with_capacity(region.loops.len());
    let mut total = 0;
    for lp in &region.loops {
        let mut pts: Vec<Point> = Vec::new();
        for piece in lp {
            match *piece {
                BoundaryPiece::Arc { from, to } => {
                    flatten_arc(e, (from, to), tolerance, &mut pts)?;
                    pts.pop();
                }
                BoundaryPiece::Segment(s) => pts.push(s.a),
            }
            if total + pts.len() > MAX_FLATTEN_VERTICES {
                return Err(too_fine(tolerance));
            }
        }
        pts.dedup();
        while pts.len() > 1 && pts.first() == pts.last() {
            pts.pop();
        }
        total += pts.len();
        let ring = Ring::new(pts);
        if ring.distinct_points_up_to(3) >= 3 {
            rings.push(ring);
        }
    }
    Ok(Polygons::new(rings))
}

/// The whole filled ellipse as one counter-clockwise inscribed ring within `tolerance`: the
/// polygon route's input.
pub fn flatten_ellipse(e: &Ellipse, tolerance: f64) -> Result<Polygons, ClipError> {
    flatten_region(&CurveRegion::whole(*e), tolerance)
}

/// The whole filled arc (sector or chord region) as one counter-clockwise ring within
/// `tolerance`: the polygon route's input for filled arcs.
pub fn flatten_filled_arc(filled: &FilledArc, tolerance: f64) -> Result<Polygons, ClipError> {
    flatten_region(&filled.region(), tolerance)
}

/// The bound on `|flattened area - exact area|`: `tolerance` times the arcs' length, the arc
/// length taken as at most the long radius times the parameter span.
pub fn flattening_area_bound(region: &CurveRegion, tolerance: f64) -> f64 {
    tolerance * region.ellipse.max_radius() * region.arc_span()
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::TAU;

    #[test]
    fn chords_stay_within_tolerance_and_area_within_its_bound() {
        let e = Ellipse::new(Point::new(1.0, 2.0), 5.0, 3.0, 0.3).unwrap();
        for tol in [1.0, 0.1, 1e-3, 1e-6] {
            let p = flatten_ellipse(&e, tol).unwrap();
            let exact = e.area();
            let got = p.signed_area();
            assert!(got <= exact && exact - got <= flattening_area_bound(&CurveRegion::whole(e), tol), "{tol}");
            // Chord midpoints are within tolerance of the curve (the unit-frame radius).
            let r = &p.rings[0];
            for w in r.points.windows(2) {
                let m = w[0].lerp(w[1], 0.5);
                let q = e.to_unit(m);
                assert!((1.0 - q.x.hypot(q.y)) * 5.0 <= tol * 1.0001, "{tol}");
            }
        }
    }

    #[test]
    fn bad_tolerances_are_typed_errors() {
        let e = Ellipse::circle(Point::ZERO, 1.0).unwrap();
        for tol in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(matches!(flatten_ellipse(&e, tol), Err(ClipError::InvalidCurve { .. })));
        }
        assert!(matches!(flatten_ellipse(&e, 1e-300), Err(ClipError::InvalidCurve { .. })));
        assert_eq!(flatten_intervals(&e, &[(0.0, TAU)], 10.0).unwrap()[0].len(), 5);
    }
}
