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
    /// Operands of at most this many edges in all take the scanbeam sweep: with that few edges
    /// active, its pass over the whole table per scanbeam costs less than the event sweep's
    /// queues and tests. Above it the event sweep's cost does not depend on how many edges
    /// span the sweep line, and the scanbeam sweep's does.
    pub(crate) const SCANBEAM_UP_TO: usize = 64;
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

/// A clip's route and sweep.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct Plan {
    pub route: Route,
    /// The sweep, or `None` to choose by [`Plan::sweep_for`] on what is swept.
    pub sweep: Option<Sweep>,
}

impl Plan {
    /// Both operands swept whole, the sweep chosen by size.
    pub(crate) const WHOLE: Plan = Plan { route: Route::Whole, sweep: None };

    /// The plan for `subject op clip`; `prepared` when the clip was prepared.
    pub(crate) fn of(subject: &Polygons, clip: &Polygons, op: BoolOp, prepared: bool) -> Plan {
        let route = match op {
            BoolOp::Union | BoolOp::Xor if prepared => Route::Splice,
            BoolOp::Union | BoolOp::Xor => Route::Whole,
            _ if prepared || edge_count(subject) + edge_count(clip) > limits::SWEPT_WHOLE_UP_TO => Route::Envelope,
            _ => Route::Whole,
        };
        Plan { route, sweep: None }
    }

    /// The sweep for operands of `edges` edges in all, when the plan fixes none.
    pub(crate) fn sweep_for(&self, edges: usize) -> Sweep {
        self.sweep.unwrap_or(if edges <= limits::SCANBEAM_UP_TO { Sweep::Scanbeam } else { Sweep::Events })
    }
}

/// Edges (vertices) of all rings.
pub(crate) fn edge_count(p: &Polygons) -> usize {
    p.rings.iter().map(|r| r.points.len()).sum()
}
