//! The slope-adaptive virtual box of one segment (Fig. 4): its reject test (Table 1) and box codes (Table 2).

use clip_core::{Point, Rect};

/// In the tests, the code of a vertex inside the near-zero band.
#[cfg(test)]
const NEAR_ZERO: i8 = 2;

/// Bound on the rounding of a line ordinate computed as `a_k + (m - a_j) (d_k / d_j)`, relative
/// to `|a_k| + |m - a_j|` (with `|d_k / d_j| <= 1`): about nine units of roundoff, against about
/// six that the four roundings can produce.
const RELATIVE_ERROR: f64 = 1e-15;

/// The slope-adaptive virtual box of a segment's line: the box whose diagonal corners `P1`, `P2`
/// are where the line meets the MEB's left and right sides (`|k| <= 1`, Figs. 4a, 4b) or its
/// bottom and top (`|k| > 1`, Figs. 4c, 4d). Over the MEB the line stays within the box's band
/// `[lo, hi]` of the minor coordinate (y for a flat line, x for a steep one).
///
/// The paper's four slope cases differ only in which of `P1`, `P2` is lower; taking `lo` and `hi`
/// as the smaller and larger coordinate covers them all, and Tables 1 and 2 become one comparison
/// each. `lo` and `hi` are widened by a bound on their rounding, so a vertex outside the band is
/// certainly on the side the comparison says, and a rejected line certainly misses the MEB.
#[derive(Clone, Copy, Debug)]
pub(crate) struct AdaptiveBox {
    /// True for `|k| > 1` (steep): the band is in x.
    steep: bool,
    lo: f64,
    hi: f64,
    /// The code of a vertex beyond `hi` (+1 when it lies left of the directed segment).
    beyond_hi: i8,
}

impl AdaptiveBox {
    /// The virtual box of segment `a b` over `meb`, or `None` when Table 1 rejects the segment: the
    /// box lies above or below the MEB (flat line) or left or right of it (steep line), so the
    /// line misses the MEB.
    #[inline]
    pub fn new(a: Point, b: Point, meb: &Rect) -> Option<AdaptiveBox> {
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let steep = dy.abs() > dx.abs();
        // Major axis j (the line's parameter), minor axis k (the band's coordinate).
        let (aj, ak, dj, dk, min_j, max_j, min_k, max_k) = if steep {
            (a.y, a.x, dy, dx, meb.min.y, meb.max.y, meb.min.x, meb.max.x)
        } else {
            (a.x, a.y, dx, dy, meb.min.x, meb.max.x, meb.min.y, meb.max.y)
        };
        let slope = dk / dj;
        let (h1, h2) = (min_j - aj, max_j - aj);
        let (k1, k2) = (ak + h1 * slope, ak + h2 * slope);
        let err = RELATIVE_ERROR * (ak.abs() + h1.abs().max(h2.abs())) + f64::MIN_POSITIVE;
        let (lo, hi) = (k1.min(k2) - err, k1.max(k2) + err);
        if lo > max_k || hi < min_k {
            return None;
        }
        // Flat line: above it is left of it when it runs rightwards. Steep line: right of it is
        // left of it when it runs downwards.
        let beyond_hi = if steep {
            if dy > 0.0 { -1 } else { 1 }
        } else if dx > 0.0 {
            1
        } else {
            -1
        };
        Some(AdaptiveBox { steep, lo, hi, beyond_hi })
    }

    /// True when the band is in x (steep line).
    #[inline]
    pub fn steep(&self) -> bool {
        self.steep
    }

    /// Table 2 as numbers: a vertex whose minor coordinate exceeds `hi` has code `beyond_hi`, one
    /// below `lo` has `-beyond_hi`, one in `[lo, hi]` (the near-zero band) needs the exact sign.
    #[inline]
    pub fn band(&self) -> (f64, f64, i8) {
        (self.lo, self.hi, self.beyond_hi)
    }
}

#[cfg(test)]
mod tests {
    use clip_core::predicates::orient2d;

    use super::*;

    const MEB: Rect = Rect::new(0.0, 0.0, 10.0, 6.0);

    #[test]
    fn rejects_lines_passing_the_box() {
        // Flat lines above and below (Figs. 5a, 5b), steep lines left and right (Figs. 5c, 5d).
        assert!(AdaptiveBox::new(Point::new(-2.0, 5.0), Point::new(2.0, 9.0), &MEB).is_none());
        assert!(AdaptiveBox::new(Point::new(4.0, -1.0), Point::new(12.0, -2.0), &MEB).is_none());
        assert!(AdaptiveBox::new(Point::new(-3.0, 1.0), Point::new(-1.0, 5.0), &MEB).is_none());
        assert!(AdaptiveBox::new(Point::new(11.0, 7.0), Point::new(12.0, 4.0), &MEB).is_none());
        // Through the corner (0,6) exactly: touching, so kept for the exact stages.
        assert!(AdaptiveBox::new(Point::new(-2.0, 4.0), Point::new(2.0, 8.0), &MEB).is_some());
        assert!(AdaptiveBox::new(Point::new(-1.0, -1.0), Point::new(11.0, 5.0), &MEB).is_some());
    }

    #[test]
    fn box_codes_agree_with_the_line_function() {
        let segments = [
            (Point::new(-1.0, 1.0), Point::new(11.0, 4.0)),
            (Point::new(11.0, 4.0), Point::new(-1.0, 1.0)),
            (Point::new(3.0, -1.0), Point::new(5.0, 7.0)),
            (Point::new(5.0, 7.0), Point::new(3.0, -1.0)),
            (Point::new(2.0, -1.0), Point::new(2.0, 7.0)),
            (Point::new(-1.0, 3.0), Point::new(11.0, 3.0)),
        ];
        for (a, b) in segments {
            let vb = AdaptiveBox::new(a, b, &MEB).unwrap();
            for x in 0..=10 {
                for y in 0..=6 {
                    let v = Point::new(f64::from(x), f64::from(y));
                    let (lo, hi, beyond_hi) = vb.band();
                    let k = if vb.steep() { v.x } else { v.y };
                    let code = if k > hi {
                        beyond_hi
                    } else if k < lo {
                        -beyond_hi
                    } else {
                        NEAR_ZERO
                    };
                    let o = orient2d(a, b, v);
                    let exact = (o > 0.0) as i8 - (o < 0.0) as i8;
                    assert!(code == NEAR_ZERO || code == exact, "{a:?}->{b:?} at {v:?}: box {code}, exact {exact}");
                }
            }
        }
    }
}
