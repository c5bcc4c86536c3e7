//! Which edges contribute, and what a crossing does to the output: the paper's rules 1-6 (and
//! its union and difference rule sets, and xor) derived from winding counts under a fill rule.
//!
//! Every active edge carries the winding numbers of both operands just left of it; the region
//! right of it differs by the edge's own winding step. A region is in the result when
//! `op(fill(w_subject), fill(w_clip))` holds, so an edge *contributes* exactly when the result
//! differs on its two sides, and it is a *left* edge of the output (the paper's L side) when the
//! result lies to its right.
//!
//! When two adjacent edges `a` (left) and `b` (right) cross, the regions left of `a` and right
//! of `b` stay; only the thin region between them changes, from `i1` below the crossing to `j1`
//! above. With `i0`, `i2` the outer regions:
//!
//! - `i0 != i2`: exactly one edge contributes below and one above. If it is the same edge it
//!   just continues; otherwise the output chain passes from one edge to the other — the paper's
//!   left and right intermediate vertices (rules 1 and 2: `LC×LS`, `RC×RS`).
//! - `i0 == i2` and the result is in neither thin region: nothing happens.
//! - contributing only above: a local minimum (rule 4, `RS×LC`): a new output polygon starts.
//! - contributing only below: a local maximum (rule 3, `LS×RC`): the two chains join.
//! - contributing below and above: both sides meet at the point and swap (rules 5 and 6, like
//!   edges, "LI and RI").
//!
//! For even-odd intersection this reproduces the paper's table; the union and difference sets
//! of its Extensions section come out of the same classification with another `op`. Xor, which
//! the paper does not give, is `fill(w_s) != fill(w_c)`: under even-odd every edge of either
//! operand flips exactly one parity, so every edge contributes, unlike crossings between
//! contributing edges are pinches (like rules 5/6), and no crossing ever starts or ends a
//! polygon; under the other fill rules the same table applies to the edges that change a
//! membership. Non-zero, positive and negative (which the paper does not cover) only change
//! `fill`.

use clip_core::{BoolOp, FillRule};

/// The operation and fill rule: which winding pairs are in the result.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Rules {
    fill: FillRule,
    /// `op` as a truth table: bit `a + 2b` is `op.apply(a, b)`, so every crossing's four
    /// membership tests do not match on the operation.
    op_table: u8,
}

impl Rules {
    pub(crate) fn new(op: BoolOp, fill: FillRule) -> Rules {
        let mut op_table = 0;
        for (a, b) in [(false, false), (true, false), (false, true), (true, true)] {
            if op.apply(a, b) {
                op_table |= 1 << (a as u8 | (b as u8) << 1);
            }
        }
        Rules { fill, op_table }
    }

    /// True when a region with winding numbers `w` (subject, clip) is in the result.
    #[inline]
    pub(crate) fn inside(&self, w: [i32; 2]) -> bool {
        let (a, b) = (self.fill.is_inside(w[0]), self.fill.is_inside(w[1]));
        (self.op_table >> (a as u8 | (b as u8) << 1)) & 1 != 0
    }
}

/// What the crossing of adjacent edges `a` (left before) and `b` (right before) does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Crossing {
    /// No contribution changes.
    Nothing,
    /// `a`'s output chain continues on `b` (an intermediate vertex).
    AToB,
    /// `b`'s output chain continues on `a` (an intermediate vertex).
    BToA,
    /// A new output polygon starts; `b_is_left` says whether `b` (now on the left) is its left side.
    LocalMin { b_is_left: bool },
    /// The two chains meet and end here.
    LocalMax,
    /// Both contribute before and after: the chains touch here and swap edges.
    Pinch { b_is_left: bool },
}

/// Classifies a crossing from the result membership of the region left of `a` (`i0`), between
/// the edges below the crossing (`i1`), right of `b` (`i2`) and between them above (`j1`).
#[inline]
pub(crate) fn classify(i0: bool, i1: bool, i2: bool, j1: bool) -> Crossing {
    let a_before = i0 != i1;
    let b_before = i1 != i2;
    let b_after = i0 != j1;
    let a_after = j1 != i2;
    if i0 != i2 {
        match (a_before, b_after, b_before, a_after) {
            (true, true, _, _) => Crossing::AToB,
            (_, _, true, true) => Crossing::BToA,
            _ => Crossing::Nothing,
        }
    } else {
        match (a_before, b_after) {
            (false, false) => Crossing::Nothing,
            (false, true) => Crossing::LocalMin { b_is_left: j1 },
            (true, false) => Crossing::LocalMax,
            (true, true) => Crossing::Pinch { b_is_left: j1 },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Classifies the crossing of `a` then `b` (each `(operand, winding step)`) when the region
    /// left of both winds `wl`, for even-odd intersection.
    fn intersection_crossing(wl: [i32; 2], a: (usize, i32), b: (usize, i32)) -> Crossing {
        let r = Rules::new(BoolOp::Intersection, FillRule::EvenOdd);
        let mut mid = wl;
        mid[a.0] += a.1;
        let mut right = mid;
        right[b.0] += b.1;
        let mut mid_after = wl;
        mid_after[b.0] += b.1;
        classify(r.inside(wl), r.inside(mid), r.inside(right), r.inside(mid_after))
    }

    // The paper's intersection rules (subject is operand 0, clip operand 1; a left edge steps
    // into its polygon, a right edge out of it).
    #[test]
    fn paper_rules_for_intersection() {
        // Rule 1, LS x LC = LI: the left side of the result passes from the clip to the subject edge.
        assert_eq!(intersection_crossing([0, 0], (0, 1), (1, 1)), Crossing::BToA);
        // Rule 2, RC x RS = RI: the right side passes from the clip edge to the subject edge.
        assert_eq!(intersection_crossing([1, 1], (1, -1), (0, -1)), Crossing::AToB);
        // Rule 3, LS x RC = MX.
        assert_eq!(intersection_crossing([0, 1], (0, 1), (1, -1)), Crossing::LocalMax);
        // Rule 4, RS x LC = MN, the edge now on the left is the new polygon's left side.
        assert_eq!(intersection_crossing([1, 0], (0, -1), (1, 1)), Crossing::LocalMin { b_is_left: true });
        // Rule 6, LS x RS inside the clip: a self-crossing subject pinches (LI and RI).
        assert_eq!(intersection_crossing([0, 1], (0, 1), (0, -1)), Crossing::Pinch { b_is_left: true });
        // Unlike edges outside the other polygon do nothing.
        assert_eq!(intersection_crossing([0, 0], (0, 1), (0, -1)), Crossing::Nothing);
    }

    // Xor under even-odd: every crossing of two edges is a pinch or a hand-over, never a start or end.
    #[test]
    fn xor_never_starts_or_ends_at_crossings() {
        let r = Rules::new(BoolOp::Xor, FillRule::EvenOdd);
        for wl in [[0, 0], [1, 0], [0, 1], [1, 1]] {
            for a in [(0, 1), (0, -1), (1, 1), (1, -1)] {
                for b in [(0, 1), (0, -1), (1, 1), (1, -1)] {
                    let mut mid = wl;
                    mid[a.0] += a.1;
                    let mut right = mid;
                    right[b.0] += b.1;
                    let mut mid_after = wl;
                    mid_after[b.0] += b.1;
                    let c = classify(r.inside(wl), r.inside(mid), r.inside(right), r.inside(mid_after));
                    assert!(matches!(c, Crossing::Pinch { .. }), "{wl:?} {a:?} {b:?}: {c:?}");
                }
            }
        }
    }
}
