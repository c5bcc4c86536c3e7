//! Joins output rings whose insides overlap after rounding, by sweeping the output once more.
//!
//! Where a sliver an ulp wide separates two parts of the result, its crossings can round onto
//! one line, and the clean-up then finds two rings (or two passes of one ring) running the same
//! way along an edge: the region left of it is covered twice. The output's own union under the
//! positive rule covers the same region once. Its vertices are already the output's, and rings
//! that only share edges and vertices meet in no new crossing, so this sweep rounds nothing more
//! in the common case; it is repeated while overlaps remain, at most [`MAX_PASSES`] times.

use std::borrow::Cow;

use clip_core::{ClipError, MIN_COORDINATE, Point, Polygons, Ring};

use crate::cleanup::CleanRings;
use crate::simplify::simplify_ring;

/// Sweeps of the output at most: each one only runs when the last left overlapping rings. Where
/// dozens of rings lie an ulp or two apart each sweep can round new crossings among them, and one
/// fuzz input's xor needed 5 sweeps; 8 leaves room above that.
pub(crate) const MAX_PASSES: usize = 8;

/// The clean rings, joined by `union_positive` (the output's union with nothing under the
/// positive rule) while two of them run the same way along an edge. A sweep that refuses the
/// output (invalid input even after [`flushed_below_min`]) leaves it as it is.
pub(crate) fn join_overlapping(
    mut clean: CleanRings,
    union_positive: impl Fn(&Polygons) -> Result<CleanRings, ClipError>,
) -> Vec<Ring> {
    for _ in 0..MAX_PASSES {
        if !clean.broken_form {
            break;
        }
        let out = Polygons::new(std::mem::take(&mut clean.rings));
        match union_positive(&out) {
            Ok(joined) => clean = joined,
            Err(_) => return out.rings,
        }
    }
    clean.rings
}

/// `rings` with every coordinate below `clip_core::MIN_COORDINATE` in magnitude (a rounded
/// crossing of edges near 1e-90, which the sweep refuses as input) made 0: the output's other
/// coordinates are rounded by far more than that move wherever they are larger. Rings that this
/// leaves without area (repeated or collinear points only) go.
pub(crate) fn flushed_below_min(rings: &Polygons) -> Cow<'_, Polygons> {
    let tiny = |v: f64| v != 0.0 && v.abs() < MIN_COORDINATE;
    if !rings.rings.iter().flat_map(|r| &r.points).any(|p| tiny(p.x) || tiny(p.y)) {
        return Cow::Borrowed(rings);
    }
    let flush = |v: f64| if tiny(v) { 0.0 } else { v };
    Cow::Owned(Polygons::new(
        rings
            .rings
            .iter()
            .map(|r| simplify_ring(&r.points.iter().map(|p| Point::new(flush(p.x), flush(p.y))).collect::<Vec<_>>()))
            .filter(|points| points.len() >= 3)
            .map(Ring::new)
            .collect(),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(points: &[(f64, f64)]) -> Ring {
        Ring::new(points.iter().map(|&(x, y)| Point::new(x, y)).collect())
    }

    #[test]
    fn coordinates_below_the_minimum_become_zero_and_flat_rings_go() {
        let kept = ring(&[(1e-90, 1e-105), (2e-90, 0.0), (2e-90, 1e-90)]);
        // Flushed, this one has only (0, 0) and (1e-90, 0) left.
        let flat = ring(&[(-1e-104, 0.0), (1e-90, 0.0), (1e-106, 1e-104)]);
        let output = Polygons::new(vec![kept, flat]);
        let flushed = flushed_below_min(&output);
        assert!(matches!(flushed, Cow::Owned(_)));
        assert_eq!(flushed.rings.len(), 1);
        assert_eq!(flushed.rings[0].points[0], Point::new(1e-90, 0.0));
        let fine = Polygons::new(vec![ring(&[(0.0, 0.0), (1e-90, 0.0), (0.0, 1e-90)])]);
        assert!(matches!(flushed_below_min(&fine), Cow::Borrowed(_)));
    }
}
