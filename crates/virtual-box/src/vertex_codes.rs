//! Window vertices encoded against the segment's line (+1, -1, 0): by the virtual box first, exactly in the near-zero band.

use clip_core::{LineSide, Point};

use crate::adaptive_box::AdaptiveBox;

/// The code of a vertex in the near-zero band whose exact sign was +1 or -1: the magnitude 2 says
/// its line function is stored in the sides array (the sign is what the paper's code is).
pub(crate) const EXACT: i8 = 2;

/// Windows with at most this many stored vertices are encoded in one fused loop; larger ones in
/// two passes, the first branch-free and vectorised. Measured on `wang-t4`: the fused loop is
/// faster at 6 edges (7 stored vertices), the two passes from 10 edges on.
pub(crate) const FUSED_UP_TO: usize = 8;

/// Encodes every vertex against the directed line `a b` (the paper's `f_i`): positive on its left,
/// negative on its right, 0 on it. Returns the paper's `F = Σ f_i` (over the signs).
///
/// Each vertex is first placed by the virtual box alone (Table 2): one coordinate (`minor`: x
/// for a steep line, y for a flat one) compared with the band gives ±1, or 0 for a vertex in the
/// near-zero band. A band vertex then gets the exact sign of the line function, stored as
/// ±[`EXACT`] with the function's value in `sides` (reused for the intersections), or 0 when it
/// lies on the line.
#[inline]
pub(crate) fn encode(
    minor: &[f64],
    points: &[Point],
    vbox: &AdaptiveBox,
    a: Point,
    b: Point,
    codes: &mut [i8],
    sides: &mut [f64],
) -> i32 {
    let (lo, hi, beyond_hi) = vbox.band();
    let line = LineSide::new(a, b);
    let exact = |v: Point, side: &mut f64| {
        let f = line.side(v);
        *side = f;
        EXACT * ((f > 0.0) as i8 - (f < 0.0) as i8)
    };
    if points.len() <= FUSED_UP_TO {
        let mut sum = 0;
        for (((code, side), &k), &v) in codes.iter_mut().zip(sides.iter_mut()).zip(minor).zip(points) {
            let mut c = beyond_hi * ((k > hi) as i8 - (k < lo) as i8);
            if c == 0 {
                c = exact(v, side);
            }
            *code = c;
            sum += i32::from(c.signum());
        }
        return sum;
    }
    for (code, &k) in codes.iter_mut().zip(minor) {
        *code = beyond_hi * ((k > hi) as i8 - (k < lo) as i8);
    }
    for ((code, side), &v) in codes.iter_mut().zip(sides.iter_mut()).zip(points) {
        if *code == 0 {
            *code = exact(v, side);
        }
    }
    codes.iter().map(|&c| i32::from(c.signum())).sum()
}
