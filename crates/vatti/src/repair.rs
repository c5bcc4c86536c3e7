//! Joins output rings whose insides overlap after rounding, by sweeping the output once more.
//!
//! Where a sliver an ulp wide separates two parts of the result, its crossings can round onto
//! one line, and the clean-up then finds two rings (or two passes of one ring) running the same
//! way along an edge: the region left of it is covered twice. The output's own union under the
//! positive rule covers the same region once. Its vertices are already the output's, and rings
//! that only share edges and vertices meet in no new crossing, so this sweep rounds nothing more
//! in the common case; it is repeated while overlaps remain, at most [`MAX_PASSES`] times.

use clip_core::{ClipError, Polygons, Ring};

use crate::cleanup::CleanRings;

/// Sweeps of the output at most: each one only runs when the last left overlapping rings. Where
/// dozens of rings lie an ulp or two apart each sweep can round new crossings among them, and one
/// fuzz input's xor needed 5 sweeps; 8 leaves room above that.
pub(crate) const MAX_PASSES: usize = 8;

/// The clean rings, joined by `union_positive` (the output's union with nothing under the
/// positive rule) while two of them run the same way along an edge. A sweep that refuses the
/// output (a rounded crossing below `clip_core::MIN_COORDINATE`) leaves it as it is.
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
