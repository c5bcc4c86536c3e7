//! Runs every selected line clipper on one generated case (a window and a batch of segments) for
//! each window kind a clipper needs; checks each batch and compares the clippers.

use clip_core::{VisiblePiece, WindowKind};
use clip_testkit::workload::line_case;

use super::finding::{CaseOutcome, Finding, Kind};
use super::polygon_runs::{takes, variants};
use crate::checks::{Check, Failure, line_oracle, lines_agree, run_line};
use crate::registry::LineEntry;

/// What to run on every line case.
pub struct LinePlan<'a> {
    /// The selected line clippers.
    pub entries: Vec<&'a LineEntry>,
    /// Segments per case.
    pub segments: usize,
    /// The run's seed.
    pub seed: u64,
}

impl LinePlan<'_> {
    /// Runs case `index` of `workload`; as for polygons, a clipper is counted only on cases
    /// generated for its own window kind.
    pub fn run(&self, workload: &'static str, index: usize) -> Result<CaseOutcome, String> {
        let mut outcome =
            CaseOutcome::new(self.entries.iter().map(|e| (e.clipper.name(), e.origin, "line")).collect(), workload);
        let own: Vec<WindowKind> = self.entries.iter().map(|e| e.clipper.capabilities().window).collect();
        for variant in variants(own.iter().copied()) {
            let case = line_case(workload, self.seed, index, variant, self.segments).map_err(|e| e.to_string())?;
            let here: Vec<usize> = (0..self.entries.len()).filter(|&i| takes(own[i], variant)).collect();
            let counted = |i: usize| own[i] == variant;
            let finding = |clipper: &'static str, check: Check, failure: Failure| Finding {
                kind: Kind::Line,
                workload,
                index,
                window: variant,
                op: None,
                fill: None,
                clipper,
                check,
                how: failure.how,
                message: failure.message,
            };
            let mut outputs: Vec<Option<Vec<VisiblePiece>>> = vec![None; self.entries.len()];
            let mut passed = vec![false; self.entries.len()];
            for &i in &here {
                let e = self.entries[i];
                let result = run_line(e, &case.window, &case.segments);
                let verdict = result
                    .as_ref()
                    .map_err(Clone::clone)
                    .and_then(|pieces| line_oracle(e, &case.window, &case.segments, pieces));
                if counted(i) {
                    let row = &mut outcome.rows[i];
                    row.cases += 1;
                    row.runs += 1;
                    if let Err(failure) = &verdict {
                        let check = failure.run_check();
                        *row.failures(check) += 1;
                        outcome.findings.push(finding(e.clipper.name(), check, failure.clone()));
                    }
                }
                passed[i] = verdict.is_ok();
                outputs[i] = result.ok();
            }
            for &x in &here {
                for &y in here.iter().filter(|&&y| y > x) {
                    let (Some(px), Some(py)) = (&outputs[x], &outputs[y]) else { continue };
                    // A pair where one result failed the oracle is that result's failure.
                    let verdict = if passed[x] && passed[y] {
                        lines_agree((self.entries[x], px), (self.entries[y], py), &case.window, &case.segments)
                    } else {
                        Ok(())
                    };
                    if let Some((me, other)) = outcome.compared((x, y), &counted, verdict.is_err())
                        && let Err(failure) = verdict
                    {
                        let check = Check::Disagreement(self.entries[other].clipper.name());
                        outcome.findings.push(finding(self.entries[me].clipper.name(), check, failure));
                    }
                }
            }
        }
        Ok(outcome)
    }
}
