//! Runs every selected polygon clipper on one generated case: each window kind a clipper needs,
//! each operation and fill rule it supports; checks each result and compares the clippers.

use clip_core::{BoolOp, FillRule, OutputForm, Polygons, WindowKind};
use clip_oracle::polygon::{bridge_count_along, operand_areas, snap_distance};
use clip_testkit::workload::polygon_case;

use super::finding::{CaseOutcome, Finding, Kind};
use crate::checks::{Check, Failure, area_identities, polygon_oracle, polygons_agree, run_polygon};
use crate::registry::PolygonEntry;

/// What to run on every polygon case.
pub struct PolygonPlan<'a> {
    /// The selected polygon clippers.
    pub entries: Vec<&'a PolygonEntry>,
    /// Operations asked for.
    pub ops: Vec<BoolOp>,
    /// Fill rules asked for.
    pub fills: Vec<FillRule>,
    /// The run's seed.
    pub seed: u64,
}

/// True when a clipper taking `own` windows can run on a case generated for `variant`.
pub fn takes(own: WindowKind, variant: WindowKind) -> bool {
    matches!(
        (own, variant),
        (WindowKind::Any, _)
            | (WindowKind::Convex, WindowKind::Convex | WindowKind::Rectangle)
            | (WindowKind::Rectangle, WindowKind::Rectangle)
    )
}

/// The window kinds the selected clippers need, in a fixed order.
pub fn variants(kinds: impl Iterator<Item = WindowKind> + Clone) -> Vec<WindowKind> {
    [WindowKind::Any, WindowKind::Convex, WindowKind::Rectangle]
        .into_iter()
        .filter(|v| kinds.clone().any(|k| k == *v))
        .collect()
}

impl PolygonPlan<'_> {
    /// Runs case `index` of `workload`. Each clipper is counted only on cases generated for its
    /// own window kind; on other kinds it runs so the clippers that need them can be compared.
    pub fn run(&self, workload: &'static str, index: usize) -> Result<CaseOutcome, String> {
        let mut outcome =
            CaseOutcome::new(self.entries.iter().map(|e| (e.clipper.name(), e.origin, "polygon")).collect(), workload);
        let own: Vec<WindowKind> = self.entries.iter().map(|e| e.clipper.capabilities().window).collect();
        for variant in variants(own.iter().copied()) {
            let case = polygon_case(workload, self.seed, index, variant).map_err(|e| e.to_string())?;
            let (subject, clip) = (&case.subject, &case.clip);
            let here: Vec<usize> = (0..self.entries.len()).filter(|&i| takes(own[i], variant)).collect();
            let counted = |i: usize| own[i] == variant;
            for &i in here.iter().filter(|&&i| counted(i)) {
                outcome.rows[i].cases += 1;
            }
            let finding =
                |clipper: &'static str, op: Option<BoolOp>, fill: FillRule, check: Check, failure: Failure| Finding {
                    kind: Kind::Polygon,
                    workload,
                    index,
                    window: variant,
                    op,
                    fill: Some(fill),
                    clipper,
                    check,
                    how: failure.how,
                    message: failure.message,
                };
            for &fill in &self.fills {
                // outputs[i][op] for each clipper here; None when unsupported or refused.
                let mut outputs: Vec<Vec<Option<Polygons>>> = vec![vec![None; BoolOp::ALL.len()]; self.entries.len()];
                for &op in &self.ops {
                    // Per clipper, how far its result is from the exact answer when the oracle passed it.
                    let mut off_exact: Vec<Option<f64>> = vec![None; self.entries.len()];
                    let supports = |i: usize| self.entries[i].clipper.capabilities().supports(op, fill);
                    // A clipper not counted on this case runs only to be compared with one that is.
                    let wanted = here.iter().any(|&j| counted(j) && supports(j));
                    for &i in &here {
                        let e = self.entries[i];
                        if !supports(i) || !(counted(i) || wanted) {
                            continue;
                        }
                        let result = run_polygon(e, subject, clip, op, fill);
                        let verdict = result
                            .as_ref()
                            .map_err(Clone::clone)
                            .and_then(|out| polygon_oracle(e, subject, clip, op, fill, out));
                        if counted(i) {
                            let row = &mut outcome.rows[i];
                            row.runs += 1;
                            if let (Ok(out), true) = (&result, counts_bridges(e)) {
                                // Bridge ends on slanted sides are rounded separately: snap as the oracle does.
                                let snap = snap_distance(&subject.bounds().union(clip.bounds()), e.tolerance);
                                row.bridges = Some(row.bridges.unwrap_or(0) + bridge_count_along(out, clip, snap));
                            }
                            if let Err(failure) = &verdict {
                                let check = failure.run_check();
                                *row.failures(check) += 1;
                                outcome.findings.push(finding(
                                    e.clipper.name(),
                                    Some(op),
                                    fill,
                                    check,
                                    failure.clone(),
                                ));
                            }
                        }
                        off_exact[i] = verdict.ok();
                        outputs[i][op_slot(op)] = result.ok();
                    }
                    self.compare(
                        &mut outcome,
                        &here,
                        &counted,
                        &outputs,
                        &off_exact,
                        op,
                        subject,
                        clip,
                        fill,
                        &finding,
                    );
                }
                // |A| and |B| under this rule, measured once for every clipper that needs them.
                let mut operands = None;
                for &i in here.iter().filter(|&&i| counted(i)) {
                    let four: Vec<(BoolOp, &Polygons)> = BoolOp::ALL
                        .iter()
                        .filter_map(|&op| outputs[i][op_slot(op)].as_ref().map(|o| (op, o)))
                        .collect();
                    if four.len() < BoolOp::ALL.len() {
                        continue;
                    }
                    let operands = *operands.get_or_insert_with(|| operand_areas(subject, clip, fill));
                    if let Err(failure) = area_identities(self.entries[i], subject, clip, fill, operands, &four) {
                        outcome.rows[i].identity_failures += 1;
                        let name = self.entries[i].clipper.name();
                        outcome.findings.push(finding(name, None, fill, Check::AreaIdentities, failure));
                    }
                }
            }
        }
        Ok(outcome)
    }

    /// Counts disagreements between the clippers whose results for `op` both passed the oracle
    /// (`off_exact` is `Some`; otherwise the oracle failure already explains the difference),
    /// and records each as a finding once, under ours when one side is ours.
    #[allow(clippy::too_many_arguments)]
    fn compare(
        &self,
        outcome: &mut CaseOutcome,
        here: &[usize],
        counted: &dyn Fn(usize) -> bool,
        outputs: &[Vec<Option<Polygons>>],
        off_exact: &[Option<f64>],
        op: BoolOp,
        subject: &Polygons,
        clip: &Polygons,
        fill: FillRule,
        finding: &dyn Fn(&'static str, Option<BoolOp>, FillRule, Check, Failure) -> Finding,
    ) {
        let slot = op_slot(op);
        for &x in here {
            for &y in here.iter().filter(|&&y| y > x) {
                let (Some(ox), Some(oy)) = (&outputs[x][slot], &outputs[y][slot]) else { continue };
                let (ex, ey) = (self.entries[x], self.entries[y]);
                // A pair where one result failed the oracle is that result's failure, not a disagreement.
                let verdict = match off_exact[x].zip(off_exact[y]) {
                    Some(both) => polygons_agree((ex, ox), (ey, oy), subject, clip, fill, Some(both)),
                    None => Ok(()),
                };
                if let Some((me, other)) = outcome.compared((x, y), counted, verdict.is_err())
                    && let Err(failure) = verdict
                {
                    let check = Check::Disagreement(self.entries[other].clipper.name());
                    outcome.findings.push(finding(self.entries[me].clipper.name(), Some(op), fill, check, failure));
                }
            }
        }
    }
}

/// True when verify counts the bridges in a clipper's output: it may keep them, or its output is
/// not always conventional (`sutherland-hodgman-split`, which must show none).
fn counts_bridges(entry: &PolygonEntry) -> bool {
    let caps = entry.clipper.capabilities();
    caps.bridges || caps.output != OutputForm::Conventional
}

/// The slot of `op` in [`BoolOp::ALL`].
fn op_slot(op: BoolOp) -> usize {
    BoolOp::ALL.iter().position(|&o| o == op).unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn window_kinds_nest() {
        assert!(takes(WindowKind::Any, WindowKind::Rectangle));
        assert!(takes(WindowKind::Convex, WindowKind::Rectangle));
        assert!(!takes(WindowKind::Convex, WindowKind::Any));
        assert!(!takes(WindowKind::Rectangle, WindowKind::Convex));
        let v = variants([WindowKind::Rectangle, WindowKind::Any].into_iter());
        assert_eq!(v, vec![WindowKind::Any, WindowKind::Rectangle]);
    }
}
