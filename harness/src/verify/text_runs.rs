//! Runs clip-text's strategies on one `text` case, each checked by clip-text's raster oracle.

use std::panic::AssertUnwindSafe;

use clip_core::{PolygonClipper, WindowKind};
use clip_sutherland_hodgman::SutherlandHodgman;
use clip_testkit::workload::text_case;
use clip_text::oracle::check_clipped_text;
use clip_text::{DEFAULT_TOLERANCE, OutlineFont, Strategy, Text, TextWindow, clip_text};
use clip_vatti::Vatti;

use super::finding::{CaseOutcome, Finding, Kind};
use crate::checks::{Check, Failing};
use crate::registry::Origin;

/// The rows verify shows for text: the notes' strategies on DejaVu Sans (string, character,
/// per-component outline) and per-component on the 8x8 bitmap font.
pub const TEXT_STRATEGIES: [&str; 4] = ["text-string", "text-char", "text-outline", "text-bitmap"];

/// What to run on every text case.
pub struct TextPlan {
    /// The outline font (DejaVu Sans).
    pub font: Option<OutlineFont>,
    /// The selected rows, from [`TEXT_STRATEGIES`].
    pub names: Vec<&'static str>,
    /// The run's seed.
    pub seed: u64,
}

impl TextPlan {
    /// Runs case `index` of the `text` workload under every selected strategy.
    pub fn run(&self, workload: &'static str, index: usize) -> Result<CaseOutcome, String> {
        let mut outcome =
            CaseOutcome::new(self.names.iter().map(|&n| (n, Origin::Ours, Kind::Text.name())).collect(), workload);
        for (row, &name) in self.names.iter().enumerate() {
            outcome.rows[row].cases += 1;
            for message in self.failures(name, index) {
                outcome.rows[row].runs += 1;
                if let Some(message) = message {
                    outcome.rows[row].oracle_failures += 1;
                    outcome.findings.push(Finding {
                        kind: Kind::Text,
                        workload,
                        index,
                        window: WindowKind::Any,
                        op: None,
                        fill: None,
                        clipper: name,
                        check: Check::Oracle,
                        how: Failing::Wrong,
                        message,
                    });
                }
            }
        }
        Ok(outcome)
    }

    /// One entry per run of `name` on case `index`: `None` when it passed, else why it failed. The
    /// per-component outline row runs Vatti, and Sutherland-Hodgman (split) too when the window
    /// is convex.
    pub fn failures(&self, name: &str, index: usize) -> Vec<Option<String>> {
        let case = text_case(self.seed, index);
        let run = |bitmap: bool, strategy: Strategy, clipper: &dyn PolygonClipper| -> Option<String> {
            let attempt = std::panic::catch_unwind(AssertUnwindSafe(|| -> Result<(), String> {
                let window = TextWindow::new(&case.window).map_err(|e| format!("refused the window: {e}"))?;
                let text = if bitmap {
                    Text::bitmap(&case.string, case.size, case.origin)
                } else {
                    let font = self.font.as_ref().ok_or("no outline font loaded")?;
                    Text::outline(font, &case.string, case.size, case.origin, DEFAULT_TOLERANCE)
                }
                .map_err(|e| format!("refused the text: {e}"))?;
                let clipped = clip_text(&text, &window, strategy, clipper).map_err(|e| format!("refused: {e}"))?;
                check_clipped_text(&text, &window, strategy, &clipped).map(|_| ())
            }));
            match attempt {
                Ok(Ok(())) => None,
                Ok(Err(why)) => Some(format!("{} ({}): {why}", case.description, clipper.name())),
                Err(_) => Some(format!("{} ({}): panicked", case.description, clipper.name())),
            }
        };
        match name {
            "text-string" => vec![run(false, Strategy::String, &Vatti)],
            "text-char" => vec![run(false, Strategy::Character, &Vatti)],
            "text-outline" => {
                let mut runs = vec![run(false, Strategy::Components, &Vatti)];
                if WindowKind::Convex.accepts(&case.window) {
                    runs.push(run(false, Strategy::Components, &SutherlandHodgman::SPLIT));
                }
                runs
            }
            _ => vec![run(true, Strategy::Components, &Vatti)],
        }
    }
}
