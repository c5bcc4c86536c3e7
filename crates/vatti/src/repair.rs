//! Joins output rings whose insides overlap after rounding, by sweeping the output once more.
//!
//! Where a sliver an ulp wide separates two parts of the result, its crossings can round onto
//! one line, and the clean-up then finds two rings (or two passes of one ring) running the same
//! way along an edge: the region left of it is covered twice. The output's own union under the
//! positive rule covers the same region once. Its vertices are already the output's, and rings
//! that only share edges and vertices meet in no new crossing, so this sweep rounds nothing more
//! in the common case; it is repeated while overlaps remain, at most [`MAX_PASSES`] times. Before
//! each sweep, points left a few ulps apart are merged and edges passing that close are routed
//! through them (`clip_core::snap_clusters`): swept as they are, the crossings of edges an ulp
//! apart round to new points an ulp apart, and rings could be left crossing there every time.

use std::borrow::Cow;

use clip_core::{ClipError, MIN_COORDINATE, Point, Polygons, Ring, snap_clusters};

use crate::cleanup::CleanRings;
use crate::simplify::simplify_ring;

/// Sweeps of the output at most: each one only runs when the last left overlapping rings. Where
/// dozens of rings lie an ulp or two apart each sweep can round new crossings among them, and one
/// fuzz input's xor needed 5 sweeps; 8 leaves room above that.
pub(crate) const MAX_PASSES: usize = 8;

/// The clean rings, joined by `union_positive` (the output's union with nothing under the
/// positive rule, of the rings [`snapped`]) while two of them run the same way along an edge. A
/// sweep that refuses the output (invalid input even after [`flushed_below_min`]) leaves it as
/// it is.
pub(crate) fn join_overlapping(
    mut clean: CleanRings,
    union_positive: impl Fn(&Polygons) -> Result<CleanRings, ClipError>,
) -> Vec<Ring> {
    for _ in 0..MAX_PASSES {
        if !clean.broken_form {
            break;
        }
        let rings = std::mem::take(&mut clean.rings);
        let out = Polygons::new(snapped(&rings).unwrap_or(rings));
        match union_positive(&out) {
            Ok(joined) => clean = joined,
            Err(_) => return out.rings,
        }
    }
    clean.rings
}

/// `rings` snapped by `clip_core::snap_clusters`, simplified, without the rings that this leaves
/// without area; `None` when there was nothing to snap. Out of line: it runs only in a repair.
#[inline(never)]
fn snapped(rings: &[Ring]) -> Option<Vec<Ring>> {
    let snapped = snap_clusters(rings)?;
    Some(snapped.iter().map(|r| simplify_ring(r)).filter(|r| r.len() >= 3).map(Ring::new).collect())
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
    use std::cell::Cell;

    use clip_core::{BoolOp, FillRule};
    use clip_oracle::polygon::{check_valid_output, region_area};

    use super::*;
    use crate::{Vatti, cleanup};

    /// One repair sweep as `Vatti::sweep_polygons` runs it: the rings alone, their union under
    /// non-zero, judged by the clean-up (not strict).
    fn repair_sweep(out: &Polygons) -> Result<CleanRings, ClipError> {
        Ok(Vatti::sweep(
            crate::Sweep::Events,
            out,
            &Polygons::default(),
            BoolOp::Union,
            FillRule::NonZero,
            false,
            |rings, touches, turns, _| cleanup::conventional_rings_checked(rings, touches, turns, false, || true),
        ))
    }

    /// The sweep's broken xor of `fuzz/regressions/vatti/spike-nearly-through-a-vertex-visited-twice`
    /// (rings 1 and 2 share rounded crossings an ulp apart near the input vertex (0.865625,
    /// 7.340624999999999)).
    fn broken_xor_near_a_vertex_visited_twice() -> Polygons {
        Polygons::new(vec![
            ring(&[(0.20507968127490037, 1.6457171314741033), (0.1, 0.7), (0.2090059885290148, 1.6454601045883936)]),
            ring(&[
                (0.8656250000000001, 7.340624999999999),
                (0.2090059885290148, 1.6454601045883936),
                (4.865625, 1.3406249999999993),
            ]),
            ring(&[
                (0.8656250000000001, 7.340624999999998),
                (0.85, 7.449999999999999),
                (0.8364524259609324, 7.3280718336483925),
                (0.8656250000000001, 7.340624999999999),
                (4.6625, 2.7624999999999993),
                (0.6625000000000002, 8.7625),
            ]),
            ring(&[
                (0.1, 12.7),
                (-15.9, 2.7),
                (0.20507968127490037, 1.6457171314741033),
                (0.8364524259609324, 7.3280718336483925),
                (-10.70859375, 2.36015625),
                (0.6625000000000002, 8.7625),
            ]),
        ])
    }

    #[test]
    fn rounded_points_an_ulp_apart_settle_in_one_snapped_sweep() {
        let broken = broken_xor_near_a_vertex_visited_twice();
        // Swept as it is, the union rounds new crossings an ulp from the old ones and leaves two
        // rings crossing there, which the clean-up does not see.
        let unsnapped = repair_sweep(&broken).expect("valid rings");
        assert!(!unsnapped.broken_form);
        assert!(check_valid_output(&Polygons::new(unsnapped.rings)).is_err(), "rings crossing");
        // Snapped first, one sweep gives valid rings covering the same region.
        let sweeps = Cell::new(0);
        let joined = join_overlapping(CleanRings { rings: broken.rings.clone(), broken_form: true }, |out| {
            sweeps.set(sweeps.get() + 1);
            repair_sweep(out)
        });
        assert_eq!(sweeps.get(), 1);
        let joined = Polygons::new(joined);
        check_valid_output(&joined).expect("valid rings");
        let layers = [(&broken, FillRule::NonZero), (&joined, FillRule::NonZero)];
        let moved = region_area(&layers, |inside| inside[0] != inside[1]);
        assert!(moved < 1e-12, "region moved by {moved:e}");
    }

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
