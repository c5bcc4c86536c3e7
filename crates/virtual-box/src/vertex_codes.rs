//! Window vertices encoded against the segment's line (+1, -1, 0): by the virtual box first, exactly in the near-zero band.

use clip_core::Point;
use clip_core::predicates::orient2d;

use crate::adaptive_box::{AdaptiveBox, NEAR_ZERO};

/// Encodes every vertex against the directed line `a b`: +1 on its left (the paper's positive
/// region), -1 on its right, 0 on it. Vertices outside the virtual box's band take the code the
/// box gives (Table 2); the rest get the exact sign of the line function. Returns the sum of the
/// codes, the paper's `F`.
#[inline]
pub(crate) fn encode(points: &[Point], vbox: &AdaptiveBox, a: Point, b: Point, codes: &mut Vec<i8>) -> i32 {
    codes.clear();
    if vbox.steep() {
        encode_with::<true>(points, vbox, a, b, codes)
    } else {
        encode_with::<false>(points, vbox, a, b, codes)
    }
}

#[inline(always)]
fn encode_with<const STEEP: bool>(
    points: &[Point],
    vbox: &AdaptiveBox,
    a: Point,
    b: Point,
    codes: &mut Vec<i8>,
) -> i32 {
    let mut sum = 0i32;
    codes.extend(points.iter().map(|&v| {
        let mut code = vbox.code::<STEEP>(v);
        if code == NEAR_ZERO {
            let f = orient2d(a, b, v);
            code = (f > 0.0) as i8 - (f < 0.0) as i8;
        }
        sum += i32::from(code);
        code
    }));
    sum
}
