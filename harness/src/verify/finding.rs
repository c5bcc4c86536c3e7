//! What one case's runs produce: counts per clipper, and the failures found, as identifiers small
//! enough to keep for every case and regenerate later for shrinking.

use clip_core::{BoolOp, FillRule, WindowKind};

use super::summary::Row;
use crate::checks::{Check, Failing};
use crate::registry::Origin;

/// What a case clips: polygons, lines, curves or text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A polygon boolean operation.
    Polygon,
    /// Line clipping against a window.
    Line,
    /// Circles, ellipses and arcs clipped against a window.
    Curve,
    /// Text clipping (clip-text's strategies).
    Text,
}

impl Kind {
    /// `polygon` or `line`.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Polygon => "polygon",
            Kind::Line => "line",
            Kind::Curve => "curve",
            Kind::Text => "text",
        }
    }
}

/// One failure: enough to regenerate the case (workload, seed, index, window kind) and re-run
/// the check that failed.
#[derive(Clone, Debug, PartialEq)]
pub struct Finding {
    /// Polygon or line.
    pub kind: Kind,
    /// Workload name.
    pub workload: &'static str,
    /// Case index within the workload.
    pub index: usize,
    /// The window kind the case was generated for.
    pub window: WindowKind,
    /// The operation (none for area identities and lines).
    pub op: Option<BoolOp>,
    /// The fill rule (none for lines).
    pub fill: Option<FillRule>,
    /// The clipper the failure is counted under.
    pub clipper: &'static str,
    /// Which check failed.
    pub check: Check,
    /// How it failed: a shrunk case must fail the same way.
    pub how: Failing,
    /// The check's one-line explanation.
    pub message: String,
}

impl Finding {
    /// A folder name that says what failed, unique among runs of any seeds and parts: the
    /// workload, the run's `seed` and the case index first.
    pub fn folder_name(&self, seed: u64) -> String {
        let mut name = format!("{}-s{seed}-{:05}-{}", self.workload, self.index, window_name(self.window));
        if let Some(op) = self.op {
            name.push_str(&format!("-{op}"));
        }
        if let Some(fill) = self.fill {
            name.push_str(&format!("-{fill}"));
        }
        name.push_str(&format!("-{}-{}", self.clipper, self.check.label()));
        name
    }
}

/// `any`, `convex` or `rectangle`.
pub fn window_name(kind: WindowKind) -> &'static str {
    match kind {
        WindowKind::Any => "any",
        WindowKind::Convex => "convex",
        WindowKind::Rectangle => "rectangle",
    }
}

/// The result of one case: a partial row per selected clipper, and the failures.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseOutcome {
    /// One row per selected clipper, in selection order.
    pub rows: Vec<Row>,
    /// Failures, in the order they were found.
    pub findings: Vec<Finding>,
}

impl CaseOutcome {
    /// Empty rows for `clippers` (name, origin, kind) on `workload`.
    pub fn new(clippers: Vec<(&'static str, Origin, &'static str)>, workload: &'static str) -> CaseOutcome {
        CaseOutcome {
            rows: clippers.into_iter().map(|(name, origin, kind)| Row::new(name, origin, kind, workload)).collect(),
            findings: Vec::new(),
        }
    }

    /// Notes that clippers `x` and `y` (row indices) were compared on this case, in the rows of
    /// those `counted` here, and whether they `disagree`. For a disagreement, returns the rows
    /// to record it under: (a counted side, the other), ours before a peer.
    pub fn compared(
        &mut self,
        (x, y): (usize, usize),
        counted: &dyn Fn(usize) -> bool,
        disagree: bool,
    ) -> Option<(usize, usize)> {
        for (me, other) in [(x, y), (y, x)] {
            if counted(me) {
                let name = self.rows[other].clipper;
                *self.rows[me].disagreements.entry(name).or_default() += usize::from(disagree);
            }
        }
        if !disagree {
            return None;
        }
        [(x, y), (y, x)]
            .into_iter()
            .filter(|&(me, _)| counted(me))
            .min_by_key(|&(me, _)| self.rows[me].origin == "peer")
    }
}
