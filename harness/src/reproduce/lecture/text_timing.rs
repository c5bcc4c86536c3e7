//! What the notes' text strategies cost: ns per character for each, as a centred window shrinks over a paragraph from holding all of it to a small part.

use std::path::Path;
use std::time::Duration;

use clip_testkit::workload::{PARAGRAPH_SIZE, PARAGRAPH_WINDOW_SIDES, paragraph_chars};
use clip_text::{DEFAULT_TOLERANCE, OutlineFont, TextWindow};

use crate::cli_error::CliError;
use crate::measure::provenance::Provenance;
use crate::measure::raw::write_csv;
use crate::measure::timing::{iterations_for, median, per_call_ns, timed};
use crate::results_files::lecture_text::{CSV, META, TextTiming};
use crate::text_paragraph::{Paragraph, ROWS};

/// Measures every row at every window size in interleaved rounds (each output checked by the
/// oracle first), and writes the CSV and its sidecar.
pub fn measure(font: &OutlineFont, seed: u64, rounds: usize, out: &Path) -> Result<(), CliError> {
    let fail = |e: String| CliError::failed(format!("lecture text timing: {e}"));
    let p = Paragraph::new(font).map_err(|e| fail(e.to_string()))?;
    let chars = paragraph_chars();
    let mut rows = Vec::new();
    for side in PARAGRAPH_WINDOW_SIDES {
        let w = TextWindow::new(&p.window(side)).map_err(|e| fail(e.to_string()))?;
        // Checked before timed: the oracle on every line for every row.
        for row in ROWS {
            p.check(row, &w).map_err(|e| fail(format!("{row} at window side {side}: {e}")))?;
        }
        // Interleaved rounds: every row once per round, so drift hits them alike.
        let mut samples: Vec<Vec<f64>> = vec![Vec::new(); ROWS.len()];
        for _ in 0..rounds {
            for (k, row) in ROWS.iter().enumerate() {
                let (_, single) = timed(|| p.run(row, &w));
                let n = iterations_for(single, Duration::from_millis(20));
                samples[k].push(per_call_ns(n, || p.run(row, &w)) / chars as f64);
            }
        }
        for (k, row) in ROWS.iter().enumerate() {
            rows.push(TextTiming {
                strategy: (*row).to_owned(),
                window_side: side,
                chars,
                cut_glyphs: p.cut_glyphs(row, &w),
                ns_per_char: median(&samples[k]),
                rounds,
            });
        }
    }
    write_csv(&out.join(CSV), &rows)?;
    let parameters = serde_json::json!({
        "rounds": rounds,
        "chars": chars,
        "size_px": PARAGRAPH_SIZE,
        "window_sides": PARAGRAPH_WINDOW_SIDES,
        "flatten_tolerance_px": DEFAULT_TOLERANCE,
    });
    let mut provenance = Provenance::now("reproduce lecture", seed, parameters);
    provenance.notes.push(
        "The paragraph (six lines of the notes' own text) and the windows are fixed; the seed is not used by the text part."
            .into(),
    );
    provenance.write(&out.join(META))
}
