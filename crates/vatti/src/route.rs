//! The route plan: what a clip does with valid operands around the sweep, and which sweep, as
//! explicit values chosen by one function from one block of limits.

use clip_core::{BoolOp, Polygons};

use crate::sweep::Sweep;

/// Every limit the plan reads.
pub(crate) mod limits {
    /// Operands of at most this many edges in all are swept whole, not cut to each other's
    /// boxes first: the cut's own work and the border paths it adds cost more than the few
    /// edges it could remove.
    pub(crate) const SWEPT_WHOLE_UP_TO: usize = 64;
    /// Operands of at most this many edges in all take the scanbeam sweep. Its pass over the
    /// whole table per scanbeam is quadratic only in the edges that span the sweep line, which
    /// this bounds (at most 512 in at most 1,024 scanbeams), and each crossing costs it less than
    /// the event sweep's queue: inputs dense in crossings are cheaper on it at this size. Above
    /// it the event sweep's cost no longer depends on how many edges span the sweep line.
    /// (PERFORMANCE.md has both sweeps' counts on either side of the limit.)
    pub(crate) const SCANBEAM_UP_TO: usize = 512;
    /// The sweep runs along x instead of y when the edges spanning a vertical line, on average,
    /// are fewer than this fraction of those spanning a horizontal one ([`SweepAxis::of`]). Below
    /// a factor of two the choice hardly matters, and keeping y there keeps the output of inputs
    /// about as tall as wide the same as the paper's sweep gives.
    pub(crate) const ALONG_X_BELOW: f64 = 0.5;
    /// Operands of at most this many edges in all are swept along y without counting: so few
    /// edges span any line that the count and the mirrored copies would cost more than they save.
    pub(crate) const ALONG_Y_UP_TO: usize = 64;
}

/// What a clip does with its (valid) operands around the sweep.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Route {
    /// Both operands swept as they are.
    Whole,
    /// For ∩ and −, what cannot reach the result is cut away first (the envelope pre-filter,
    /// after GEOS's overlay: outside the clip's box a subject's ∩ is empty, outside the
    /// subject's box the clip takes nothing away): each operand's edges that miss the other's
    /// box are replaced by paths around it, exactly, keeping every winding number inside it.
    /// When no edge of one operand reaches the box, that operand is all or nothing there and
    /// the other is swept alone, or nothing is. Property used: edges outside the other
    /// operand's box cannot reach the result. Other operations sweep whole.
    Envelope,
    /// For ∪ and ⊕ with a prepared clip: outside the subject's box the result is the clip's
    /// region itself, which preparing resolved into conventional rings; only the subject with
    /// the clip's part inside its box is swept, and the clip's rings outside are joined back
    /// where they cross the box's border. Property used: the far operand is in conventional
    /// form (it is this clipper's own output). Degenerate borders sweep whole; for an operand
    /// that is not prepared, and for other operations, it is [`Route::Envelope`].
    Splice,
}

/// The direction the sweep line moves in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SweepAxis {
    /// Upwards, a horizontal sweep line: the paper's sweep.
    Y,
    /// Rightwards, a vertical sweep line: the operands are swept mirrored across y = x
    /// ([`Polygons::transposed`], exact, every winding number kept) and the output mirrored back.
    /// Polygon output only: trapezoids are horizontal bands, swept along y.
    X,
}

impl SweepAxis {
    /// The axis along which fewer edges span the sweep line. A sweep's work at each event grows
    /// with the edges spanning its line (the order's depth, and the memory its records take),
    /// and on average a horizontal line crosses `Σ|Δy| / height` edges, a vertical one
    /// `Σ|Δx| / width`. Property used: an input whose edges run mostly one way (teeth of a comb,
    /// hatching, a column of text lines, tall blocks side by side) spans few edges across that
    /// way. Y unless x's count is below [`limits::ALONG_X_BELOW`] of y's.
    pub(crate) fn of(a: &Polygons, b: &Polygons) -> SweepAxis {
        let (mut x_lo, mut x_hi, mut y_lo, mut y_hi) =
            (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
        let (mut span_x, mut span_y) = (0.0, 0.0);
        for ring in a.rings.iter().chain(&b.rings) {
            let Some(&last) = ring.points.last() else { continue };
            let mut prev = last;
            for &p in &ring.points {
                span_x += (p.x - prev.x).abs();
                span_y += (p.y - prev.y).abs();
                // Valid operands hold no NaN: plain comparisons, not `f64::min`'s NaN handling.
                x_lo = if p.x < x_lo { p.x } else { x_lo };
                x_hi = if p.x > x_hi { p.x } else { x_hi };
                y_lo = if p.y < y_lo { p.y } else { y_lo };
                y_hi = if p.y > y_hi { p.y } else { y_hi };
                prev = p;
            }
        }
        let (width, height) = (x_hi - x_lo, y_hi - y_lo);
        // Compared as products, so a flat extent (an operand on one line) needs no division.
        if width > 0.0 && span_x * height < limits::ALONG_X_BELOW * span_y * width {
            SweepAxis::X
        } else {
            SweepAxis::Y
        }
    }
}

/// A clip's route, sweep and axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct Plan {
    pub route: Route,
    /// The sweep, or `None` to choose by [`Plan::sweep_for`] on what is swept.
    pub sweep: Option<Sweep>,
    /// The axis, or `None` to choose by [`SweepAxis::of`] on what is swept.
    pub axis: Option<SweepAxis>,
}

impl Plan {
    /// Both operands swept whole, the sweep and axis chosen on them.
    pub(crate) const WHOLE: Plan = Plan { route: Route::Whole, sweep: None, axis: None };

    /// The plan for `subject op clip`; `prepared` when the clip was prepared.
    pub(crate) fn of(subject: &Polygons, clip: &Polygons, op: BoolOp, prepared: bool) -> Plan {
        let route = match op {
            BoolOp::Union | BoolOp::Xor if prepared => Route::Splice,
            BoolOp::Union | BoolOp::Xor => Route::Whole,
            _ if prepared || edge_count(subject) + edge_count(clip) > limits::SWEPT_WHOLE_UP_TO => Route::Envelope,
            _ => Route::Whole,
        };
        Plan { route, sweep: None, axis: None }
    }

    /// The sweep for operands of `edges` edges in all, when the plan fixes none.
    pub(crate) fn sweep_for(&self, edges: usize) -> Sweep {
        self.sweep.unwrap_or(if edges <= limits::SCANBEAM_UP_TO { Sweep::Scanbeam } else { Sweep::Events })
    }

    /// The axis for sweeping `a` and `b` (of `edges` edges in all), when the plan fixes none:
    /// y for at most [`limits::ALONG_Y_UP_TO`] edges.
    pub(crate) fn axis_for(&self, a: &Polygons, b: &Polygons, edges: usize) -> SweepAxis {
        self.axis.unwrap_or_else(|| if edges <= limits::ALONG_Y_UP_TO { SweepAxis::Y } else { SweepAxis::of(a, b) })
    }
}

/// Edges (vertices) of all rings.
pub(crate) fn edge_count(p: &Polygons) -> usize {
    p.rings.iter().map(|r| r.points.len()).sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::{Point, Rect, Ring};

    /// A comb of `teeth` teeth 1 wide and 100 tall along x, on a spine 1 tall.
    fn comb(teeth: usize) -> Polygons {
        let mut pts = vec![Point::new(0.0, -1.0), Point::new(2.0 * teeth as f64, -1.0)];
        for i in (0..teeth).rev() {
            let x = 2.0 * i as f64;
            pts.extend([
                Point::new(x + 1.0, 0.0),
                Point::new(x + 1.0, 100.0),
                Point::new(x, 100.0),
                Point::new(x, 0.0),
            ]);
        }
        Polygons::from(Ring::new(pts))
    }

    #[test]
    fn the_sweep_runs_across_the_way_most_edges_run() {
        let square = Polygons::from(Rect::new(0.0, 0.0, 10.0, 10.0));
        assert_eq!(SweepAxis::of(&square, &square), SweepAxis::Y, "as tall as wide: the paper's way");
        assert_eq!(SweepAxis::of(&comb(50), &square), SweepAxis::X, "teeth upright: a vertical line spans few");
        assert_eq!(SweepAxis::of(&comb(50).transposed(), &square), SweepAxis::Y, "teeth lying down");
        assert_eq!(SweepAxis::of(&Polygons::empty(), &Polygons::empty()), SweepAxis::Y);
        let fixed = Plan { axis: Some(SweepAxis::Y), ..Plan::WHOLE };
        assert_eq!(fixed.axis_for(&comb(50), &square, 204), SweepAxis::Y, "a plan's axis is kept");
        assert_eq!(Plan::WHOLE.axis_for(&comb(50), &square, 204), SweepAxis::X);
        assert_eq!(Plan::WHOLE.axis_for(&comb(10), &square, 44), SweepAxis::Y, "a few edges");
    }
}
