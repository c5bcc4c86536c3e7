//! Double-double numbers: an unevaluated sum `hi + lo` of two doubles with `|lo| <= ulp(hi)/2`,
//! about 106 bits of significand. For filters in front of exact predicates: a quantity computed
//! here errs by a few units in 2^-104 of its size per operation (Dekker 1971; the algorithms of
//! Hida, Li and Bailey's QD library, with a fused multiply-add for the exact products), where a
//! double's rounding is 2^-53.

/// `hi + lo`, normalized: `hi` is the sum rounded to a double.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct DoubleDouble {
    pub hi: f64,
    pub lo: f64,
}

impl DoubleDouble {
    /// `a - b` exactly.
    #[inline]
    pub fn difference(a: f64, b: f64) -> DoubleDouble {
        let (hi, lo) = two_diff(a, b);
        DoubleDouble { hi, lo }
    }

    /// `hi + lo` normalized.
    #[inline]
    pub fn sum_of(hi: f64, lo: f64) -> DoubleDouble {
        let (hi, lo) = two_sum(hi, lo);
        DoubleDouble { hi, lo }
    }

    /// `self + other`, to within a few units of 2^-106 of the operands' size (QD's accurate
    /// addition).
    #[inline]
    pub fn add(self, other: DoubleDouble) -> DoubleDouble {
        let (s, e) = two_sum(self.hi, other.hi);
        let (t, f) = two_sum(self.lo, other.lo);
        let (s, e) = quick_two_sum(s, e + t);
        let (hi, lo) = quick_two_sum(s, e + f);
        DoubleDouble { hi, lo }
    }

    /// `self - other`, as [`DoubleDouble::add`].
    #[inline]
    pub fn sub(self, other: DoubleDouble) -> DoubleDouble {
        self.add(DoubleDouble { hi: -other.hi, lo: -other.lo })
    }

    /// `self · other`, to within about 8·2^-106 of the product's size.
    #[inline]
    pub fn mul(self, other: DoubleDouble) -> DoubleDouble {
        let (p, e) = two_product(self.hi, other.hi);
        let e = e + (self.hi * other.lo + self.lo * other.hi);
        let (hi, lo) = quick_two_sum(p, e);
        DoubleDouble { hi, lo }
    }

    /// `self / other` (`other` not zero), to within about 16·2^-106 of the quotient's size: three
    /// quotient digits, each from the remainder left by the ones before.
    #[inline]
    pub fn div(self, other: DoubleDouble) -> DoubleDouble {
        let q1 = self.hi / other.hi;
        let r = self.sub(other.mul_f64(q1));
        let q2 = r.hi / other.hi;
        let r = r.sub(other.mul_f64(q2));
        let q3 = r.hi / other.hi;
        let (hi, lo) = quick_two_sum(q1, q2);
        DoubleDouble { hi, lo }.add(DoubleDouble { hi: q3, lo: 0.0 })
    }

    /// `self · b` for a double `b`.
    #[inline]
    fn mul_f64(self, b: f64) -> DoubleDouble {
        let (p, e) = two_product(self.hi, b);
        let (hi, lo) = quick_two_sum(p, e + self.lo * b);
        DoubleDouble { hi, lo }
    }

    /// True when both parts are finite.
    #[inline]
    pub fn is_finite(self) -> bool {
        self.hi.is_finite() && self.lo.is_finite()
    }
}

/// `a + b` exactly, as a rounded sum and its error (Knuth).
#[inline]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let x = a + b;
    let bv = x - a;
    let av = x - bv;
    (x, (a - av) + (b - bv))
}

/// `a + b` exactly where `|a| >= |b|` (or `a` is zero), as a rounded sum and its error (Dekker).
#[inline]
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// `a - b` exactly, as a rounded difference and its error.
#[inline]
pub(crate) fn two_diff(a: f64, b: f64) -> (f64, f64) {
    let x = a - b;
    let bv = a - x;
    let av = x + bv;
    (x, (a - av) + (bv - b))
}

/// `a * b` exactly, as a rounded product and its error (a fused multiply-add).
#[inline]
pub(crate) fn two_product(a: f64, b: f64) -> (f64, f64) {
    let x = a * b;
    (x, a.mul_add(b, -x))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// True when `a` lies within `rel` of `hi + lo`'s size of it.
    fn close(a: DoubleDouble, hi: f64, lo: f64, rel: f64) -> bool {
        let d = DoubleDouble::sum_of(hi, lo).sub(a);
        (d.hi + d.lo).abs() <= rel * hi.abs()
    }

    #[test]
    fn differences_and_sums_are_exact() {
        let d = DoubleDouble::difference(1.0, 1e-20);
        assert_eq!((d.hi, d.lo), (1.0, -1e-20));
        let s = DoubleDouble::sum_of(1.0, 2f64.powi(-60));
        assert_eq!((s.hi, s.lo), (1.0, 2f64.powi(-60)));
    }

    #[test]
    fn a_third_times_three_is_one_to_double_double_precision() {
        let third = DoubleDouble::sum_of(1.0, 0.0).div(DoubleDouble::sum_of(3.0, 0.0));
        let one = third.mul(DoubleDouble::sum_of(3.0, 0.0));
        assert!(close(one, 1.0, 0.0, 2f64.powi(-100)), "{one:?}");
        // The double quotient alone is off by about 2^-55: double-double holds far more.
        assert!((third.lo).abs() > 0.0);
    }

    #[test]
    fn products_keep_what_doubles_round_away() {
        let a = DoubleDouble::sum_of(1.0 + 2f64.powi(-52), 0.0);
        let p = a.mul(a);
        // (1 + 2^-52)^2 = 1 + 2^-51 + 2^-104: the last term is what a double loses.
        assert_eq!(p.hi, 1.0 + 2f64.powi(-51));
        assert_eq!(p.lo, 2f64.powi(-104));
    }
}
