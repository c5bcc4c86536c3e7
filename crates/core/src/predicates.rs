//! The one place orientation and incidence are decided, exactly, with Shewchuk's adaptive
//! predicates (the `robust` crate). No clipper computes a raw cross product for a decision.

use crate::double_double::{DoubleDouble, two_diff, two_product, two_sum};
use crate::{Point, Rect, Segment};

/// Which way three points turn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Orientation {
    /// Counter-clockwise (left turn, y up).
    CounterClockwise,
    /// Clockwise (right turn).
    Clockwise,
    /// On one line.
    Collinear,
}

impl Orientation {
    /// +1, -1 or 0.
    #[inline]
    pub fn sign(self) -> i32 {
        match self {
            Orientation::CounterClockwise => 1,
            Orientation::Clockwise => -1,
            Orientation::Collinear => 0,
        }
    }

    /// The opposite turn.
    #[inline]
    pub fn reversed(self) -> Orientation {
        match self {
            Orientation::CounterClockwise => Orientation::Clockwise,
            Orientation::Clockwise => Orientation::CounterClockwise,
            Orientation::Collinear => Orientation::Collinear,
        }
    }
}

#[inline]
fn coord(p: Point) -> robust::Coord<f64> {
    robust::Coord { x: p.x, y: p.y }
}

/// Below this fraction of its terms' size, the plain determinant's magnitude is not trusted.
const TRUSTED_FRACTION: f64 = 1e-4;

/// Twice the signed area of triangle `abc`, with an exactly right sign and a magnitude accurate to
/// a few parts in 10^12 (the plain determinant, where it is above 1e-4 of its terms) or to about
/// an ulp (otherwise). Positive when `c` lies left of the directed line `a -> b`.
///
/// Callers place crossings by these magnitudes (`t = ga / (ga - gb)`), so the magnitude matters
/// too. Shewchuk's adaptive `orient2d` stops refining as soon as the sign is certain, with the
/// magnitude then off by up to its whole size (found by the `window_clippers` fuzz target: a
/// window edge 2.2e-16 long put a Sutherland-Hodgman crossing 0.003 off, and by the
/// `line_clippers` one: the line oracle misplaced crossings with sliver windows and far segment
/// ends). So where the plain determinant is not clearly above its rounding, the magnitude is summed
/// exactly from the exact products of the exact coordinate differences, and the sign still comes
/// from the exact predicate.
#[inline]
pub fn orient2d(a: Point, b: Point, c: Point) -> f64 {
    let (left, right) = ((a.x - c.x) * (b.y - c.y), (a.y - c.y) * (b.x - c.x));
    let det = left - right;
    if det.abs() > TRUSTED_FRACTION * (left.abs() + right.abs()) {
        return det;
    }
    let exact = robust::orient2d(coord(a), coord(b), coord(c));
    let accurate = accurate_determinant(a, b, c);
    if (accurate > 0.0 && exact > 0.0) || (accurate < 0.0 && exact < 0.0) { accurate } else { exact }
}

/// `(a.x - c.x)(b.y - c.y) - (a.y - c.y)(b.x - c.x)` to about an ulp: every difference split
/// exactly into two doubles, every product of the parts exactly into two (fused multiply-add), and
/// the sixteen terms summed exactly into an expansion (Shewchuk's grow-expansion), whose
/// components are then added smallest first. A compensated sum is not enough: terms of 1e51 that
/// cancel to 1e25 (a window edge near the origin, a segment end at 6e25) leave it 1e-4 off. The
/// coordinate range (`MIN_COORDINATE` to `MAX_COORDINATE`) keeps every term a normal number.
fn accurate_determinant(a: Point, b: Point, c: Point) -> f64 {
    let mut expansion = [0.0; 32];
    let len = determinant_into(a, b, c, &mut expansion);
    expansion[..len].iter().sum()
}

/// [`accurate_determinant`]'s exact expansion, into `expansion`: its length.
fn determinant_into(a: Point, b: Point, c: Point, expansion: &mut [f64; 32]) -> usize {
    let (ax, ay, bx, by) = (two_diff(a.x, c.x), two_diff(a.y, c.y), two_diff(b.x, c.x), two_diff(b.y, c.y));
    let mut len = 0;
    for (u, v, sign) in [(ax, by, 1.0), (ay, bx, -1.0)] {
        for x in [u.0, u.1] {
            for y in [v.0, v.1] {
                let (p, e) = two_product(x, y);
                for term in [sign * e, sign * p] {
                    len = grow_expansion(expansion, len, term);
                }
            }
        }
    }
    len
}

/// [`accurate_determinant`] in double-double, and a bound on its error: the expansion's sum, the
/// sum of what is left of it after that, and the magnitudes of what is left after both, summed
/// and rounded up (every step exact but the sums).
fn double_double_determinant(a: Point, b: Point, c: Point) -> (DoubleDouble, f64) {
    // Sixteen terms leave at most seventeen components, and each step below one more.
    let mut expansion = [0.0; 32];
    let len = determinant_into(a, b, c, &mut expansion);
    let hi: f64 = expansion[..len].iter().sum();
    let len = grow_expansion(&mut expansion, len, -hi);
    let lo: f64 = expansion[..len].iter().sum();
    let len = grow_expansion(&mut expansion, len, -lo);
    // A sum of at most nineteen magnitudes errs by under 2^-47 of itself.
    let left: f64 = expansion[..len].iter().map(|c| c.abs()).sum();
    (DoubleDouble::sum_of(hi, lo), left * (1.0 + 2f64.powi(-40)))
}

/// The crossing point of two segments whose interiors cross, as its offset from `s.a` along each
/// axis in double-double, and a bound on the offsets' error relative to their size; `None` where
/// something is not finite or the determinants are not known to 2^-60. With `D(p)` the
/// determinant of `t`'s line at `p`, the offset is `D(s.a) / (D(s.a) - D(s.b)) · (s.b - s.a)`. The
/// two determinants have opposite signs, so their difference does not cancel: with each within
/// a fraction `r` of its value, the quotient is within `2r/(1 - r)` of its own, and the division,
/// the difference and the product add a few units of 2^-104 each (bounded by 2^-96 here). For
/// filtering the exact [`crossing_coordinate_cmp`]: against a line farther from the estimate
/// than its error, the estimate decides. Limit: as the expansions', coordinates well above
/// 1e-100 apart.
pub(crate) fn double_double_crossing_offset(s: Segment, t: Segment) -> Option<([DoubleDouble; 2], f64)> {
    let (d0, e0) = double_double_determinant(t.a, t.b, s.a);
    let (d1, e1) = double_double_determinant(t.a, t.b, s.b);
    // Interiors that cross put the ends of `s` strictly either side of `t`'s line.
    if d0.hi == 0.0 || d1.hi == 0.0 || (d0.hi > 0.0) == (d1.hi > 0.0) {
        return None;
    }
    // Relative to the determinants' values, which lie within 2^-52 of their leading parts.
    let r = (e0 / d0.hi.abs()).max(e1 / d1.hi.abs()) * (1.0 + 2f64.powi(-50));
    let known = r < 2f64.powi(-60);
    if !known {
        return None;
    }
    let u = d0.div(d0.sub(d1));
    let along = |a: f64, b: f64| u.mul(DoubleDouble::difference(b, a));
    let offset = [along(s.a.x, s.b.x), along(s.a.y, s.b.y)];
    let relative = (2.0 * r / (1.0 - r) + 2f64.powi(-96)) * (1.0 + 2f64.powi(-50));
    offset.iter().all(|o| o.is_finite()).then_some((offset, relative))
}

/// `(a.x - c.x)(b.y - c.y) - (a.y - c.y)(b.x - c.x)` as an exact expansion (non-overlapping
/// components, smallest first), for predicates of higher degree built on it.
fn determinant_expansion(a: Point, b: Point, c: Point) -> Vec<f64> {
    let (ax, ay, bx, by) = (two_diff(a.x, c.x), two_diff(a.y, c.y), two_diff(b.x, c.x), two_diff(b.y, c.y));
    let mut e = Vec::with_capacity(16);
    for (u, v, sign) in [(ax, by, 1.0), (ay, bx, -1.0)] {
        for x in [u.0, u.1] {
            for y in [v.0, v.1] {
                let (p, err) = two_product(x, y);
                grow_vec(&mut e, sign * err);
                grow_vec(&mut e, sign * p);
            }
        }
    }
    e
}

/// Adds `b` exactly to the expansion `e` (non-overlapping components, smallest first), dropping
/// zero components.
fn grow_vec(e: &mut Vec<f64>, b: f64) {
    let mut q = b;
    let mut out = 0;
    for i in 0..e.len() {
        let (sum, err) = two_sum(q, e[i]);
        if err != 0.0 {
            e[out] = err;
            out += 1;
        }
        q = sum;
    }
    e.truncate(out);
    if q != 0.0 {
        e.push(q);
    }
}

/// Where the crossing point of two segments whose interiors cross lies against the line
/// `x = m` (or `y = m` when `along_y`): `Less` when its coordinate is below `m`. Exact: with
/// `D(p)` the determinant of `t`'s line at `p` (exact expansions), the crossing's coordinate
/// minus `m` has the sign of `D(s.a) · (D(s.a)(s.b - m) - D(s.b)(s.a - m))`, a polynomial of degree
/// three in the coordinates. Hot pixels of snap rounding must hold the exact crossing, and a
/// rounded crossing of nearly parallel edges can lie pixels away from it. Limit: exact while no
/// product of three coordinate differences underflows (coordinates well above 1e-100 apart).
pub fn crossing_coordinate_cmp(s: Segment, t: Segment, along_y: bool, m: f64) -> core::cmp::Ordering {
    if let Some(order) = exact_quotient_cmp(s, t, along_y, m) {
        return order;
    }
    let (d0, v) = weighted_determinants(s, t, along_y, m);
    (expansion_sign(&d0) * expansion_sign(&v)).cmp(&0)
}

/// How the x of segment `s` at height `y` compares with the x of segment `t` there: `Less` when
/// `s` passes left of `t`. Both segments rise (`a.y < b.y`) and span `y`. Exact: with `D` the
/// determinant of `s`'s line, `(t.b.y - y)·D(t.a) + (y - t.a.y)·D(t.b)` is
/// `(s.b.y - s.a.y)(t.b.y - t.a.y)(x_s(y) - x_t(y))`. An end at `y` decides by one orientation;
/// else the two x where both are computed exactly; else, where `t`'s ends lie on one side of
/// `s`'s line, that side; else the sum in exact expansions (degree three,
/// [`crossing_coordinate_cmp`]'s limit). A sweep that orders
/// edges by their x computed at a height (rounded, ulps off) can swap two edges that pass a pixel
/// apart far from the origin and invent a crossing of segments that meet only at vertices.
pub fn x_at_height_cmp(s: Segment, t: Segment, y: f64) -> core::cmp::Ordering {
    use core::cmp::Ordering;
    debug_assert!(s.a.y < s.b.y && t.a.y < t.b.y, "rising segments");
    // An end at height y is the segment's point there: one orientation decides (a sweep meets
    // this most, edges ending or starting on its scanlines).
    let end_at = |e: Segment| {
        if y == e.a.y {
            Some(e.a)
        } else if y == e.b.y {
            Some(e.b)
        } else {
            None
        }
    };
    match (end_at(s), end_at(t)) {
        (Some(p), Some(q)) => return p.x.partial_cmp(&q.x).unwrap_or(Ordering::Equal),
        (Some(p), None) => return (-orient(t.a, t.b, p).sign()).cmp(&0),
        (None, Some(q)) => return orient(s.a, s.b, q).sign().cmp(&0),
        (None, None) => {}
    }
    // On integer grids both x are computed exactly, also where the segments cross or overlap
    // (where the orientations below are zero or disagree, and cost most).
    if let (Some(xs), Some(xt)) = (exact_x_at(s, y), exact_x_at(t, y)) {
        return xs.partial_cmp(&xt).unwrap_or(Ordering::Equal);
    }
    let (below, above) = (orient(s.a, s.b, t.a).sign(), orient(s.a, s.b, t.b).sign());
    if below * above >= 0 {
        // D > 0: t's point lies left of s, so s's x is the greater.
        return (below + above).signum().cmp(&0);
    }
    expansion_sign(&weighted_determinants(t, s, true, y).1).cmp(&0)
}

/// The x of rising segment `s` at height `y`, `a.x + (y - a.y)(b.x - a.x) / (b.y - a.y)`, when
/// every step of that computation is exact (each step's rounding error, found by `two_diff`,
/// `two_sum` or a fused multiply-add, is zero); else `None`.
fn exact_x_at(s: Segment, y: f64) -> Option<f64> {
    let rise = two_diff(y, s.a.y);
    let (dx, dy) = (two_diff(s.b.x, s.a.x), two_diff(s.b.y, s.a.y));
    if rise.1 != 0.0 || dx.1 != 0.0 || dy.1 != 0.0 {
        return None;
    }
    let (product, product_error) = two_product(rise.0, dx.0);
    let quotient = product / dy.0;
    let x = two_sum(s.a.x, quotient);
    (product_error == 0.0 && quotient.mul_add(dy.0, -product) == 0.0 && x.1 == 0.0).then_some(x.0)
}

/// [`crossing_coordinate_cmp`] without expansions where every quantity is exact in f64: by
/// [`exact_crossing_quotients`] and [`quotient_cmp`] against `w = m - c(s.a)`.
fn exact_quotient_cmp(s: Segment, t: Segment, along_y: bool, m: f64) -> Option<core::cmp::Ordering> {
    let (nx, ny, d) = exact_crossing_quotients(s, t)?;
    if along_y { quotient_cmp(ny, d, s.a.y, m) } else { quotient_cmp(nx, d, s.a.x, m) }
}

/// The crossing point of two segments whose interiors cross as offsets from `s.a`, `(nx / d,
/// ny / d)`, where `nx`, `ny` and `d` are exact in f64 (every difference and product checked by
/// its error term: integer coordinates up to about 2^17 apart, and their multiples by powers of
/// two, as on grids); `None` elsewhere. With `D(p)` the determinant of `t`'s line at `p`,
/// `d = D(s.a) - D(s.b)` and `n = D(s.a)·(s.b - s.a)` per coordinate. Limit: products that
/// underflow are not caught (coordinates well above 1e-100 apart, as for the expansions).
pub fn exact_crossing_quotients(s: Segment, t: Segment) -> Option<(f64, f64, f64)> {
    let (d0, d1) = (exact_determinant(t, s.a)?, exact_determinant(t, s.b)?);
    let nx = exact_product(d0, exact_difference(s.b.x, s.a.x)?)?;
    let ny = exact_product(d0, exact_difference(s.b.y, s.a.y)?)?;
    let d = exact_difference(d0, d1)?;
    (d != 0.0 && (nx / d).is_finite() && (ny / d).is_finite()).then_some((nx, ny, d))
}

/// True when every one of `coordinates` is an integer multiple of one power of two `2^e` and
/// below `2^(e + digits)` in magnitude: integers of at most `digits` binary digits on some
/// power-of-two scale (zero fits every scale). Such inputs have small exact arithmetic: the
/// crossing of two of their segments is a fraction whose denominator has at most `2·digits + 3`
/// digits, so distinct crossings, and a crossing and a line not through it, lie a bounded
/// distance apart, which rounding to f64 cannot bridge when `digits` is small. Stops at the first
/// coordinate that widens the span past `digits` (at once for coordinates with decimals).
pub fn on_coarse_grid(coordinates: impl IntoIterator<Item = f64>, digits: u32) -> bool {
    // Lowest and highest binary digit used: every coordinate is a multiple of 2^lo below 2^hi.
    let (mut lo, mut hi) = (i32::MAX, i32::MIN);
    for v in coordinates {
        let bits = v.abs().to_bits();
        if bits == 0 {
            continue;
        }
        if !v.is_finite() {
            return false;
        }
        let (biased, fraction) = ((bits >> 52) as i32, bits & ((1 << 52) - 1));
        // v = mantissa · 2^exponent, the mantissa an integer (subnormals have no hidden bit).
        let (mantissa, exponent) = if biased == 0 { (fraction, -1074) } else { (fraction | 1 << 52, biased - 1075) };
        lo = lo.min(exponent + mantissa.trailing_zeros() as i32);
        hi = hi.max(exponent + 64 - mantissa.leading_zeros() as i32);
        if hi - lo > digits as i32 {
            return false;
        }
    }
    true
}

/// `a - b` when f64 holds it exactly.
fn exact_difference(a: f64, b: f64) -> Option<f64> {
    let (x, e) = two_diff(a, b);
    (e == 0.0).then_some(x)
}

/// `a · b` when f64 holds it exactly.
fn exact_product(a: f64, b: f64) -> Option<f64> {
    let (x, e) = two_product(a, b);
    (e == 0.0).then_some(x)
}

/// The determinant of `t`'s line at `c`, `(t.a - c) × (t.b - c)`, when every step is exact in f64.
fn exact_determinant(t: Segment, c: Point) -> Option<f64> {
    let (ax, ay) = (exact_difference(t.a.x, c.x)?, exact_difference(t.a.y, c.y)?);
    let (bx, by) = (exact_difference(t.b.x, c.x)?, exact_difference(t.b.y, c.y)?);
    exact_difference(exact_product(ax, by)?, exact_product(ay, bx)?)
}

/// Whether the line of `k` passes exactly through the crossing point of the lines of `s` and `t`
/// (three lines through one point), when every quantity is exact in f64 (integer coordinates up
/// to about 2^12 apart, and their multiples by powers of two); `None` elsewhere, and for parallel
/// `s` and `t`. With `D` the determinants of `t`'s and `k`'s lines, the crossing is
/// `s.a + (s.b - s.a)·Dt(s.a) / (Dt(s.a) - Dt(s.b))`, and `Dk` there is zero exactly when
/// `Dt(s.a)·Dk(s.b) = Dt(s.b)·Dk(s.a)`. A sweep rounds such a point, and an edge through it at a
/// small angle to the sweep line then passes ulps off the rounded point.
pub fn through_crossing(k: Segment, s: Segment, t: Segment) -> Option<bool> {
    let (t0, t1) = (exact_determinant(t, s.a)?, exact_determinant(t, s.b)?);
    if t0 == t1 {
        return None;
    }
    let (k0, k1) = (exact_determinant(k, s.a)?, exact_determinant(k, s.b)?);
    Some(exact_product(t0, k1)? == exact_product(t1, k0)?)
}

/// How `base + n / d` compares with `m`, for `n` and `d` (not zero) exact, without expansions:
/// with `w = m - base` exact (else `None`), `q = n / d` is one correctly rounded division, and
/// rounding is monotone, so `q < w` implies `n / d < w` and `q > w` implies `n / d > w`. A tie
/// `q == w` is settled by the sign of `w·d - n`, rounded once (fused multiply-add), exact unless
/// it underflows to zero: `None` then.
pub fn quotient_cmp(n: f64, d: f64, base: f64, m: f64) -> Option<core::cmp::Ordering> {
    use core::cmp::Ordering;
    let (w, error) = two_diff(m, base);
    if error != 0.0 {
        return None;
    }
    let q = n / d;
    if q != w {
        return Some(if q < w { Ordering::Less } else { Ordering::Greater });
    }
    // n / d - w = (n - w·d) / d.
    let r = w.mul_add(d, -n);
    if r == 0.0 {
        return None;
    }
    Some(if (r > 0.0) == (d > 0.0) { Ordering::Less } else { Ordering::Greater })
}

/// `D(s.a)` and `D(s.a)·(c(s.b) - m) - D(s.b)·(c(s.a) - m)` as exact expansions, with `D` the
/// determinant of `t`'s line and `c` the y (`along_y`) or x coordinate.
fn weighted_determinants(s: Segment, t: Segment, along_y: bool, m: f64) -> (Vec<f64>, Vec<f64>) {
    let coord = |p: Point| if along_y { p.y } else { p.x };
    let d0 = determinant_expansion(t.a, t.b, s.a);
    let d1 = determinant_expansion(t.a, t.b, s.b);
    let mut v = Vec::with_capacity(2 * (d0.len() + d1.len()));
    for (d, w, sign) in [(&d0, two_diff(coord(s.b), m), 1.0), (&d1, two_diff(coord(s.a), m), -1.0)] {
        for &c in d {
            for part in [w.0, w.1] {
                let (p, err) = two_product(c, part);
                grow_vec(&mut v, sign * err);
                grow_vec(&mut v, sign * p);
            }
        }
    }
    (d0, v)
}

/// The sign of an expansion (non-overlapping components, smallest first, none zero): its largest
/// component's, 0 when empty.
fn expansion_sign(e: &[f64]) -> i32 {
    e.last().map_or(0, |&v| if v > 0.0 { 1 } else { -1 })
}

/// The crossing point of two segments whose interiors cross, from determinants accurate to
/// about an ulp: its error is at most about 8 ulps of `s`'s extent along each axis plus an ulp of
/// the point (the plain [`crossing_point`] can be far off for nearly parallel segments).
pub fn accurate_crossing_point(s: Segment, t: Segment) -> Point {
    let (dx, dy) = accurate_crossing_offset(s, t);
    Point::new(s.a.x + dx, s.a.y + dy)
}

/// [`accurate_crossing_point`] as its offset from `s.a`: at most about 8 ulps of `s`'s extent
/// off along each axis, with no ulp of the point's magnitude added (an exact predicate filtered
/// by this error stays cheap far from the origin).
pub fn accurate_crossing_offset(s: Segment, t: Segment) -> (f64, f64) {
    let d0 = accurate_determinant(t.a, t.b, s.a);
    let d1 = accurate_determinant(t.a, t.b, s.b);
    let u = d0 / (d0 - d1);
    let u = if u.is_finite() { u.clamp(0.0, 1.0) } else { 0.0 };
    (u * (s.b.x - s.a.x), u * (s.b.y - s.a.y))
}

/// Adds `b` exactly to the expansion `e[..len]` (non-overlapping components, smallest first) and
/// returns its new length, dropping zero components.
fn grow_expansion(e: &mut [f64; 32], len: usize, b: f64) -> usize {
    let mut q = b;
    let mut out = 0;
    for i in 0..len {
        let (sum, err) = two_sum(q, e[i]);
        if err != 0.0 {
            e[out] = err;
            out += 1;
        }
        q = sum;
    }
    if q != 0.0 {
        e[out] = q;
        out += 1;
    }
    out
}

/// The largest error [`LineSide::crossing_values`] lets into a crossing's parameter (of the
/// segment's length) from rounded line-function values, well below the 1e-12 within which the
/// line clippers merge crossings ([`crate::PARAMETER_SNAP`]).
pub const CROSSING_PARAMETER_ERROR: f64 = 1e-14;

/// Shewchuk's first error bound of `orient2d` (`ccwerrboundA = (3 + 16ε)ε`, ε = 2^-53): a
/// determinant computed in plain f64 whose magnitude exceeds this times the sum of its two
/// products' magnitudes has the right sign.
pub const ORIENT_ERROR_BOUND: f64 = (3.0 + 16.0 * (f64::EPSILON / 2.0)) * (f64::EPSILON / 2.0);

/// The line function of a directed segment `a -> b`, `f(v) = (b - a) × (v - a)` (positive left of
/// it), with `b - a` formed once for many vertices: the loops of the line clippers evaluate it at
/// every window vertex they look at.
///
/// [`LineSide::side`] has [`orient2d`]'s exact sign and accurate magnitude: the rounded determinant
/// (`orient2d(b, v, a)` in Shewchuk's operand order) where its magnitude is trusted, `orient2d`
/// otherwise; [`LineSide::estimate`] gives the rounded value with the bound above which it is
/// trusted, for loops that filter first and call the predicate for the few left. Inlined into the caller's loop, the filter costs a few flops and vectorises.
#[derive(Clone, Copy, Debug)]
pub struct LineSide {
    a: Point,
    b: Point,
    d: Point,
}

impl LineSide {
    /// The line function of `a -> b`.
    #[inline]
    pub fn new(a: Point, b: Point) -> LineSide {
        LineSide { a, b, d: Point::new(b.x - a.x, b.y - a.y) }
    }

    /// The rounded `f(v)` and the bound above which it is trusted: when `|f| > bound`, the sign
    /// of `f` is exact and its magnitude as accurate as [`orient2d`]'s (the clippers place
    /// crossings by it), so a caller can take it as it is; otherwise it calls [`LineSide::side`].
    #[inline(always)]
    pub fn estimate(&self, vx: f64, vy: f64) -> (f64, f64) {
        let l = self.d.x * (vy - self.a.y);
        let r = self.d.y * (vx - self.a.x);
        (l - r, TRUSTED_FRACTION * (l.abs() + r.abs()))
    }

    /// `f(v)` with an exact sign and a magnitude as accurate as [`orient2d`]'s (crossings are
    /// placed by it): the rounded value where it is clearly above its rounding, `orient2d`
    /// otherwise.
    #[inline(always)]
    pub fn side(&self, v: Point) -> f64 {
        let l = self.d.x * (v.y - self.a.y);
        let r = self.d.y * (v.x - self.a.x);
        let f = l - r;
        if f.abs() > TRUSTED_FRACTION * (l.abs() + r.abs()) { f } else { orient2d(self.a, self.b, v) }
    }

    /// The rounded `f(v)`, for loops that test it against [`LineSide::sign_bound`].
    #[inline(always)]
    pub fn value(&self, vx: f64, vy: f64) -> f64 {
        self.d.x * (vy - self.a.y) - self.d.y * (vx - self.a.x)
    }

    /// One error bound for every point of `within`: a [`LineSide::value`] at such a point whose
    /// magnitude exceeds it has the exact sign. Shewchuk's first bound of `orient2d` taken with the
    /// largest products any point of the box can give (rounding is monotone, so the rounded
    /// products at a point never exceed the rounded products at the box's farthest sides), so a
    /// per-point loop pays one comparison instead of forming the bound at each point.
    #[inline]
    pub fn sign_bound(&self, within: &Rect) -> f64 {
        let far_x = (within.max.x - self.a.x).abs().max((within.min.x - self.a.x).abs());
        let far_y = (within.max.y - self.a.y).abs().max((within.min.y - self.a.y).abs());
        ORIENT_ERROR_BOUND * (self.d.x.abs() * far_y + self.d.y.abs() * far_x)
    }

    /// A gap `|fp - fq|` above which [`LineSide::crossing_values`] keeps the rounded pair for any
    /// edge with both ends in `within`: its trust fraction of the largest four products a box
    /// point can give. A loop tests it first and calls `crossing_values` only below it.
    #[inline]
    pub fn crossing_gap_bound(&self, within: &Rect) -> f64 {
        2.0 * (TRUSTED_FRACTION / ORIENT_ERROR_BOUND) * self.sign_bound(within)
    }

    /// The line function at the ends of an edge `p -> q` that crosses the line, `fp` and `fq`
    /// being its rounded values there ([`LineSide::value`]) with exact, opposite signs, made
    /// accurate enough to place the crossing by `fp / (fp - fq)`. That ratio's error is at most
    /// the two values' error bounds over `|fp| + |fq|`, and the crossing's parameter moves by it
    /// times the edge's span of parameters. The rounded pair is kept when either the ratio is as
    /// accurate as two values above [`orient2d`]'s trust fraction would make it, or the parameter's
    /// error is below [`CROSSING_PARAMETER_ERROR`]; [`orient2d`]'s accurate pair is taken
    /// otherwise. So a short edge whose ends lie close to the line (a finely sampled boundary,
    /// seen from afar) costs no exact expansion unless it runs nearly along the line.
    #[inline]
    pub fn crossing_values(&self, p: Point, q: Point, fp: f64, fq: f64) -> (f64, f64) {
        let terms = |v: Point| (self.d.x * (v.y - self.a.y)).abs() + (self.d.y * (v.x - self.a.x)).abs();
        let (terms, gap) = (terms(p) + terms(q), (fp - fq).abs());
        // |t_q - t_p| times |d|^2, and the values' error bound.
        let span = (self.d.x * (q.x - p.x) + self.d.y * (q.y - p.y)).abs();
        let error = ORIENT_ERROR_BOUND * terms;
        let len2 = self.d.x * self.d.x + self.d.y * self.d.y;
        if gap > TRUSTED_FRACTION * terms || span * error <= CROSSING_PARAMETER_ERROR * gap * len2 {
            (fp, fq)
        } else {
            (orient2d(self.a, self.b, p), orient2d(self.a, self.b, q))
        }
    }
}

/// [`orient2d`] with its first stage inlined: the plain f64 determinant when its magnitude is
/// trusted (the same test as `orient2d`'s), `orient2d` otherwise. The same value as [`orient2d`]
/// bit for bit; for per-segment loops, where the call is the larger part of the cost.
#[inline(always)]
pub fn orient2d_inline(a: Point, b: Point, c: Point) -> f64 {
    let l = (a.x - c.x) * (b.y - c.y);
    let r = (a.y - c.y) * (b.x - c.x);
    let det = l - r;
    if det.abs() > TRUSTED_FRACTION * (l.abs() + r.abs()) { det } else { orient2d(a, b, c) }
}

/// The exact turn of `a -> b -> c`.
#[inline]
pub fn orient(a: Point, b: Point, c: Point) -> Orientation {
    let d = orient_sign(a, b, c);
    if d > 0.0 {
        Orientation::CounterClockwise
    } else if d < 0.0 {
        Orientation::Clockwise
    } else {
        Orientation::Collinear
    }
}

/// A value with the exact sign of `orient2d(a, b, c)` and no promise about its magnitude: the
/// plain determinant where it clears Shewchuk's error bound, else his adaptive predicate, which
/// stops as soon as the sign is certain. The accurate magnitude of [`orient2d`] costs an exact
/// expansion near collinearity, which smooth inputs meet at every vertex (it had doubled vatti's
/// time on large-smooth; it was a fifth of the indexed line clipper's instructions against a
/// 10^4-edge window).
#[inline(always)]
pub fn orient_sign(a: Point, b: Point, c: Point) -> f64 {
    let (left, right) = ((a.x - c.x) * (b.y - c.y), (a.y - c.y) * (b.x - c.x));
    let det = left - right;
    if det.abs() > ORIENT_ERROR_BOUND * (left.abs() + right.abs()) {
        det
    } else {
        robust::orient2d(coord(a), coord(b), coord(c))
    }
}

/// True when `p` lies on the line through `s`'s ends (exactly), for points computed to lie near
/// it. Where the four coordinate differences are exact (integer coordinates below 2^53, nearby
/// floats), the two products of the determinant are compared as exact pairs (fused
/// multiply-add); else by [`orient`], whose adaptive stage every point within rounding of the
/// line takes.
#[inline]
pub fn on_line(s: Segment, p: Point) -> bool {
    let (ux, uy) = (two_diff(s.b.x, s.a.x), two_diff(s.b.y, s.a.y));
    let (vx, vy) = (two_diff(p.x, s.a.x), two_diff(p.y, s.a.y));
    if ux.1 == 0.0 && uy.1 == 0.0 && vx.1 == 0.0 && vy.1 == 0.0 {
        // A product's rounded value and error are unique to it, so equal pairs are equal products.
        return two_product(ux.0, vy.0) == two_product(uy.0, vx.0);
    }
    orient(s.a, s.b, p) == Orientation::Collinear
}

/// True when `p` lies on the closed segment `s` (exactly).
#[inline]
pub fn on_segment(p: Point, s: Segment) -> bool {
    s.bounds().contains(p) && orient(s.a, s.b, p) == Orientation::Collinear
}

/// How two closed segments meet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SegmentIntersection {
    /// No common point.
    None,
    /// The interiors cross at one point. The point is rounded, then clamped into both
    /// segments' bounding boxes.
    Crossing(Point),
    /// One common point that is an endpoint of at least one segment (exact: the endpoint).
    Touching(Point),
    /// Collinear overlap of positive length, directed like the first segment.
    Overlap(Segment),
}

/// Classifies how segments `s` and `t` meet, with exact predicates.
pub fn segment_intersection(s: Segment, t: Segment) -> SegmentIntersection {
    if !s.bounds().intersects(&t.bounds()) {
        return SegmentIntersection::None;
    }
    if s.is_degenerate() || t.is_degenerate() {
        let (p, other) = if s.is_degenerate() { (s.a, t) } else { (t.a, s) };
        return if on_segment(p, other) { SegmentIntersection::Touching(p) } else { SegmentIntersection::None };
    }
    let o1 = orient(s.a, s.b, t.a);
    let o2 = orient(s.a, s.b, t.b);
    if o1 == o2 && o1 != Orientation::Collinear {
        return SegmentIntersection::None;
    }
    if o1 == Orientation::Collinear && o2 == Orientation::Collinear {
        return collinear_overlap(s, t);
    }
    let o3 = orient(t.a, t.b, s.a);
    let o4 = orient(t.a, t.b, s.b);
    if o3 == o4 {
        // Both same side (o3 == o4 == Collinear would make the segments collinear, handled above).
        return SegmentIntersection::None;
    }
    match (o1, o2, o3, o4) {
        (Orientation::Collinear, ..) => SegmentIntersection::Touching(t.a),
        (_, Orientation::Collinear, ..) => SegmentIntersection::Touching(t.b),
        (_, _, Orientation::Collinear, _) => SegmentIntersection::Touching(s.a),
        (_, _, _, Orientation::Collinear) => SegmentIntersection::Touching(s.b),
        _ => SegmentIntersection::Crossing(crossing_point(s, t)),
    }
}

/// The crossing point of two segments whose interiors are known to cross, rounded and clamped
/// into the intersection of their bounding boxes (so it never leaves either segment's box).
pub fn crossing_point(s: Segment, t: Segment) -> Point {
    let d1 = s.b - s.a;
    let d2 = t.b - t.a;
    let denom = d1.cross(d2);
    let u = (t.a - s.a).cross(d2) / denom;
    let p = if u.is_finite() { s.at(u.clamp(0.0, 1.0)) } else { s.a };
    let b = s.bounds();
    let c = t.bounds();
    let lo = Point::new(b.min.x.max(c.min.x), b.min.y.max(c.min.y));
    let hi = Point::new(b.max.x.min(c.max.x), b.max.y.min(c.max.y));
    Point::new(p.x.clamp(lo.x.min(hi.x), hi.x.max(lo.x)), p.y.clamp(lo.y.min(hi.y), hi.y.max(lo.y)))
}

fn collinear_overlap(s: Segment, t: Segment) -> SegmentIntersection {
    // Order along s's dominant axis; exact, because the points are collinear.
    let key = |p: Point| if (s.b.x - s.a.x).abs() >= (s.b.y - s.a.y).abs() { p.x } else { p.y };
    let forward = key(s.b) > key(s.a);
    let along = |p: Point| if forward { key(p) } else { -key(p) };
    let (t_lo, t_hi) = if along(t.a) <= along(t.b) { (t.a, t.b) } else { (t.b, t.a) };
    let start = if along(t_lo) > along(s.a) { t_lo } else { s.a };
    let end = if along(t_hi) < along(s.b) { t_hi } else { s.b };
    let (ks, ke) = (along(start), along(end));
    if ks < ke {
        SegmentIntersection::Overlap(Segment::new(start, end))
    } else if ks == ke {
        SegmentIntersection::Touching(start)
    } else {
        SegmentIntersection::None
    }
}

/// True when `p` is strictly inside the box `r` (not on its boundary).
#[inline]
pub fn strictly_inside_rect(p: Point, r: &Rect) -> bool {
    p.x > r.min.x && p.x < r.max.x && p.y > r.min.y && p.y < r.max.y
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn three_lines_through_one_crossing_f64_cannot_hold() {
        let seg = |a: (f64, f64), b: (f64, f64)| Segment::new(Point::new(a.0, a.1), Point::new(b.0, b.1));
        // Through (40/3, 101/6): a grid case where the sweep rounded the crossing.
        let (s, t) = (seg((10.0, 16.0), (14.0, 17.0)), seg((13.0, 18.0), (15.0, 11.0)));
        let k = seg((0.0, 16.0), (16.0, 17.0));
        assert_eq!(through_crossing(k, s, t), Some(true));
        assert_eq!(through_crossing(s, k, t), Some(true));
        assert_eq!(through_crossing(seg((0.0, 16.0), (18.0, 17.0)), s, t), Some(false));
        assert_eq!(through_crossing(k, s, seg((0.0, 0.0), (4.0, 1.0))), None, "parallel");
        assert_eq!(through_crossing(k, s, seg((0.1, 0.0), (13.0, 18.0))), None, "not exact in f64");
    }

    #[test]
    fn coarse_grids_are_integers_of_few_binary_digits_on_any_power_of_two_scale() {
        let grid = |c: &[f64], digits| on_coarse_grid(c.iter().copied(), digits);
        assert!(grid(&[0.0, 1.0, 24.0, -24.0, 7.0], 5), "integers below 32");
        assert!(!grid(&[0.0, 1.0, 32.0], 5), "32 needs six digits");
        assert!(grid(&[0.5, 12.0], 5) && !grid(&[0.25, 12.0], 5), "0.5 to 12 is 1 to 24 in halves");
        assert!(grid(&[3.0 * 2f64.powi(-40), 2f64.powi(-36)], 5), "the scale can be any power of two");
        assert!(!grid(&[0.1], 9) && !grid(&[1.0, 1e-3], 9), "decimals span the whole mantissa");
        assert!(grid(&[], 0) && grid(&[0.0, -0.0], 0), "no digits for zeros");
        assert!(grid(&[5e-324, 1e-323], 2) && !grid(&[5e-324, 1.0], 60), "subnormals");
        assert!(!grid(&[f64::INFINITY], 60) && !grid(&[f64::NAN], 60));
    }

    #[test]
    fn exact_quotients_order_crossings_as_the_expansions_do() {
        // Integer segments that cross (on a grid of quarter units, and of 2^20 units, where the
        // products are no longer exact), against the pixel borders and centres of snap rounding
        // (pixels of 4 ulps of the largest coordinate) around the rounded crossing: the quotient
        // path, where it answers, agrees with the exact expansions, and on the small grid it
        // answers all but ties.
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = |range: i64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % (2 * range as u64 + 1)) as i64 - range
        };
        for (unit, range, pixel) in [(0.25, 400, 2f64.powi(-44)), (1.0, 1 << 20, 2f64.powi(-30))] {
            let (mut answered, mut asked) = (0, 0);
            for _ in 0..400 {
                let mut point = || Point::new(next(range) as f64 * unit, next(range) as f64 * unit);
                let (s, t) = (Segment::new(point(), point()), Segment::new(point(), point()));
                let SegmentIntersection::Crossing(_) = segment_intersection(s, t) else { continue };
                for along_y in [false, true] {
                    let p = accurate_crossing_point(s, t);
                    let at = if along_y { p.y } else { p.x };
                    for k in -3..=3 {
                        let m = ((at / pixel).round() + f64::from(k) / 2.0) * pixel;
                        let (d0, v) = weighted_determinants(s, t, along_y, m);
                        let expected = (expansion_sign(&d0) * expansion_sign(&v)).cmp(&0);
                        asked += 1;
                        if let Some(order) = exact_quotient_cmp(s, t, along_y, m) {
                            answered += 1;
                            assert_eq!(order, expected, "{s:?} {t:?} along_y {along_y} at {m}");
                        }
                    }
                }
            }
            if unit < 1.0 {
                assert!(answered * 10 > asked * 9, "{answered} of {asked} answered on the small grid");
            } else {
                assert!(answered < asked, "products beyond 2^53 must not be taken as exact");
            }
        }
    }

    #[test]
    fn line_side_has_orient2d_signs_where_rounding_lies() {
        // Points within an ulp of the line y = x through far-apart ends: the plain determinant is
        // wrong or zero for some, the filtered one never.
        let (a, b) = (Point::new(0.5, 0.5), Point::new(12.0, 12.0));
        let line = LineSide::new(a, b);
        for k in -40..40 {
            let c = Point::new(24.0, 24.0 + f64::from(k) * 2f64.powi(-48));
            assert_eq!(line.side(c).signum(), orient2d(a, b, c).signum(), "{c:?}");
            assert_eq!(line.side(c) == 0.0, orient2d(a, b, c) == 0.0, "{c:?}");
        }
        assert!(line.side(Point::new(0.0, 1.0)) > 0.0);
        assert!(line.side(Point::new(1.0, 0.0)) < 0.0);
        assert_eq!(line.side(Point::new(3.0, 3.0)), 0.0);
        for k in -40..40 {
            let c = Point::new(24.0, 24.0 + f64::from(k) * 2f64.powi(-48));
            assert_eq!(orient2d_inline(a, b, c), orient2d(a, b, c), "{c:?}");
        }
    }

    #[test]
    fn sign_bound_keeps_only_exact_signs_over_its_box() {
        // The same near-line points, inside a box around them: a value beyond the bound has the
        // exact sign, and points within an ulp of the line are never beyond it.
        let (a, b) = (Point::new(0.5, 0.5), Point::new(12.0, 12.0));
        let line = LineSide::new(a, b);
        let bound = line.sign_bound(&Rect::new(20.0, 20.0, 30.0, 30.0));
        for k in -40_i32..40 {
            let c = Point::new(24.0, 24.0 + f64::from(k) * 2f64.powi(-48));
            let v = line.value(c.x, c.y);
            if v.abs() > bound {
                assert_eq!(v.signum(), orient2d(a, b, c).signum(), "{c:?}");
            }
            assert!(v.abs() <= bound || k.abs() > 4, "{c:?}: {v} against {bound}");
        }
        assert!(line.value(20.0, 30.0) > bound && line.value(30.0, 20.0) < -bound);
        // Above the gap bound, crossing_values keeps any pair from the box as it is.
        let gap = line.crossing_gap_bound(&Rect::new(20.0, 20.0, 30.0, 30.0));
        let (p, q) = (Point::new(20.0, 30.0), Point::new(30.0, 20.0));
        let (fp, fq) = (line.value(p.x, p.y), line.value(q.x, q.y));
        assert!((fp - fq).abs() > gap && line.crossing_values(p, q, fp, fq) == (fp, fq));
    }

    #[test]
    fn crossing_values_place_crossings_of_edges_near_the_line() {
        // A long diagonal line and a short edge across it near its start, its ends about 1e-10 of
        // the products from the line: neither value is trusted alone, yet the parameter they give
        // is within the promised error of the one from exact magnitudes.
        let (a, b) = (Point::new(-1000.0, -1000.0), Point::new(1000.0, 1000.0));
        let line = LineSide::new(a, b);
        let (p, q) = (Point::new(3.0, 3.0 + 1e-7), Point::new(3.001, 3.001 - 3e-7));
        let (fp, fq) = (line.value(p.x, p.y), line.value(q.x, q.y));
        let (gp, gq) = line.crossing_values(p, q, fp, fq);
        let (ep, eq) = (orient2d(a, b, p), orient2d(a, b, q));
        assert!(fp.abs() < 1e-4 * 4e6 && fq.abs() < 1e-4 * 4e6);
        let span = 0.001 / 2000.0;
        assert!(span * (gp / (gp - gq) - ep / (ep - eq)).abs() < CROSSING_PARAMETER_ERROR);
        // An edge running along the line within rounding: the exact magnitudes are taken.
        let (p, q) = (Point::new(3.0, 3.0 + 1e-13), Point::new(300.0, 300.0 - 1e-13));
        let (gp, gq) = line.crossing_values(p, q, line.value(p.x, p.y), line.value(q.x, q.y));
        assert_eq!((gp, gq), (orient2d(a, b, p), orient2d(a, b, q)));
    }

    /// The sign of `x_s(y) - x_t(y)` for integer coordinates, in exact integers.
    fn x_at_height_reference(s: Segment, t: Segment, y: f64) -> core::cmp::Ordering {
        let i = |v: f64| v as i128;
        let (ds, dt) = (s.b - s.a, t.b - t.a);
        // x_s(y)·ds.y·dt.y and x_t(y)·ds.y·dt.y, the positive factors cleared.
        let xs = (i(s.a.x) * i(ds.y) + (i(y) - i(s.a.y)) * i(ds.x)) * i(dt.y);
        let xt = (i(t.a.x) * i(dt.y) + (i(y) - i(t.a.y)) * i(dt.x)) * i(ds.y);
        xs.cmp(&xt)
    }

    #[test]
    fn x_at_height_cmp_orders_nearly_parallel_segments_exactly() {
        // Pairs of long segments on a grid of 2^37, the second's ends a unit or two off the
        // first's: at a height between, their x differ by far less than the rounding of x at that
        // height, which orders many of them wrongly.
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = |range: i64| {
            state = state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            ((state >> 33) as i64).rem_euclid(range)
        };
        let big = 1i64 << 37;
        let computed_x = |s: Segment, y: f64| s.a.x + ((y - s.a.y) * (s.b.x - s.a.x)) / (s.b.y - s.a.y);
        let mut rounding_wrong = 0;
        for _ in 0..20_000 {
            let (x0, y0) = (next(big) - big / 2, next(big) - big / 2);
            let (x1, y1) = (next(big) - big / 2, y0 + 1 + next(big));
            let s = Segment::new(Point::new(x0 as f64, y0 as f64), Point::new(x1 as f64, y1 as f64));
            let d: [i64; 4] = std::array::from_fn(|_| next(5) - 2);
            let t = Segment::new(
                Point::new((x0 + d[0]) as f64, (y0 + d[1]) as f64),
                Point::new((x1 + d[2]) as f64, (y1 + d[3]) as f64),
            );
            if t.a.y >= t.b.y {
                continue;
            }
            let (lo, hi) = (s.a.y.max(t.a.y), s.b.y.min(t.b.y));
            for y in [lo, hi, lo + ((hi - lo) / 2.0).floor(), lo + ((hi - lo) / 3.0).floor()] {
                let want = x_at_height_reference(s, t, y);
                assert_eq!(x_at_height_cmp(s, t, y), want, "{s:?} {t:?} at {y}");
                assert_eq!(x_at_height_cmp(t, s, y), want.reverse(), "{t:?} {s:?} at {y}");
                rounding_wrong += usize::from(computed_x(s, y).partial_cmp(&computed_x(t, y)) != Some(want));
            }
        }
        // The cases are hard: rounded x orders hundreds of them wrongly.
        assert!(rounding_wrong > 100, "{rounding_wrong}");
    }

    #[test]
    fn x_at_height_cmp_of_segments_from_one_point_and_to_one_point() {
        let (p, q) = (Point::new(0.0, 0.0), Point::new(1.0, 3.0));
        let (left, right) = (Segment::new(p, Point::new(-1.0, 4.0)), Segment::new(p, q));
        assert_eq!(x_at_height_cmp(left, right, 2.0), core::cmp::Ordering::Less);
        assert_eq!(x_at_height_cmp(left, right, 0.0), core::cmp::Ordering::Equal);
        assert_eq!(x_at_height_cmp(right, right, 1.5), core::cmp::Ordering::Equal);
        // Segments crossing at height 2: right of each other below, left above.
        let (a, b) = (
            Segment::new(Point::new(0.0, 0.0), Point::new(4.0, 4.0)),
            Segment::new(Point::new(4.0, 0.0), Point::new(0.0, 4.0)),
        );
        assert_eq!(x_at_height_cmp(a, b, 1.0), core::cmp::Ordering::Less);
        assert_eq!(x_at_height_cmp(a, b, 2.0), core::cmp::Ordering::Equal);
        assert_eq!(x_at_height_cmp(a, b, 3.0), core::cmp::Ordering::Greater);
    }

    #[test]
    fn on_line_agrees_with_orient_at_points_computed_on_lines() {
        // Lines between integer points up to 2^52 (differences exact) and between arbitrary
        // floats (differences rounded), with x computed at integer heights: on the line exactly
        // for some, an ulp or so off for most.
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            state = state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            state >> 12
        };
        let (mut on, mut off) = (0, 0);
        for k in 0..20_000 {
            let scale = if k % 2 == 0 { 1.0 } else { 1.0 + 1.0 / 3.0 };
            let mut coordinate = || (next() as f64) * scale;
            let (a, b) = (Point::new(coordinate(), coordinate()), Point::new(coordinate(), coordinate()));
            if a.y == b.y {
                continue;
            }
            let y = a.y + ((b.y - a.y) * 0.25).round();
            let p = Point::new(a.x + ((y - a.y) * (b.x - a.x)) / (b.y - a.y), y);
            let s = Segment::new(a, b);
            let collinear = orient(a, b, p) == Orientation::Collinear;
            assert_eq!(on_line(s, p), collinear, "{s:?} {p:?}");
            if collinear { on += 1 } else { off += 1 }
        }
        assert!(on > 100 && off > 100, "{on} on, {off} off");
    }
}
