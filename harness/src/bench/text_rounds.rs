//! The bench's `text` group: clip-text's strategies on the paragraph as a centred window shrinks
//! over it, timed in interleaved rounds into `bench.csv` rows like the polygon groups' (workload
//! `text`, case the window side, size the paragraph's characters, time per paragraph).

use std::path::Path;
use std::time::Duration;

use clip_testkit::workload::{PARAGRAPH_SIZE, PARAGRAPH_WINDOW_SIDES, paragraph_chars};
use clip_text::{DEFAULT_TOLERANCE, DEJAVU_SANS, OutlineFont, TextWindow};
use serde_json::json;

use super::rounds::Settings;
use crate::cli_error::CliError;
use crate::measure::raw::Measurement;
use crate::measure::timing::{iterations_for, per_call_ns, timed};
use crate::results_files::bench::TEXT_GROUP;
use crate::text_paragraph::{Paragraph, ROWS, bench_name, row_of_bench_name};

/// The rows to time: those named (as in `bench.csv`: `text-string`, `text-char`, `text-outline`,
/// `text-outline-sh-split`, `text-bitmap`), or every row when none is named. Unknown `text-`
/// names are usage errors.
pub fn select_rows(names: &[String]) -> Result<Vec<&'static str>, CliError> {
    if names.is_empty() {
        return Ok(ROWS.to_vec());
    }
    names
        .iter()
        .map(|n| {
            row_of_bench_name(n).ok_or_else(|| {
                let valid: Vec<&str> = ROWS.iter().map(|r| bench_name(r)).collect();
                CliError::usage(format!("--clipper {n}: not a text row (text rows: {})", valid.join(", ")))
            })
        })
        .collect()
}

/// What the text group measured: the rows for `bench.csv`, and its parameters for the sidecar
/// (the glyphs each window cuts, which `report` shows beside the times).
pub struct TextMeasured {
    /// Timings, one per row, window side and round.
    pub rows: Vec<Measurement>,
    /// The group's parameters.
    pub parameters: serde_json::Value,
}

/// Times `rows` at every window side: each output first checked by clip-text's raster oracle,
/// then the rows interleaved within each round so drift hits them alike.
pub fn run(rows: &[&'static str], settings: &Settings) -> Result<TextMeasured, CliError> {
    let font = OutlineFont::from_file(Path::new(DEJAVU_SANS)).map_err(|e| {
        CliError::failed(format!("bench text: needs DejaVu Sans (Debian package fonts-dejavu-core): {e}"))
    })?;
    let fail = |e: String| CliError::failed(format!("bench text: {e}"));
    let p = Paragraph::new(&font).map_err(|e| fail(e.to_string()))?;
    let chars = paragraph_chars();
    let target = if settings.quick { Duration::from_millis(2) } else { Duration::from_millis(5) };
    let mut out = Vec::new();
    let mut cut = Vec::new();
    for side in PARAGRAPH_WINDOW_SIDES {
        let w = TextWindow::new(&p.window(side)).map_err(|e| fail(e.to_string()))?;
        let mut single = Vec::with_capacity(rows.len());
        for row in rows {
            p.check(row, &w).map_err(|e| fail(format!("{row} at window side {side}: {e}")))?;
            let (_, took) = timed(|| p.run(row, &w));
            single.push(took);
        }
        cut.push(json!({
            "window_side": side,
            "outline_glyphs_cut": p.cut_glyphs("outline-vatti", &w),
            "bitmap_glyphs_cut": p.cut_glyphs("bitmap", &w),
        }));
        for round in 0..settings.rounds {
            for j in 0..rows.len() {
                let k = (j + round) % rows.len();
                let iterations = iterations_for(single[k], target);
                let time_ns = per_call_ns(iterations, || p.run(rows[k], &w));
                out.push(Measurement {
                    workload: TEXT_GROUP.to_owned(),
                    case: side.to_string(),
                    clipper: bench_name(rows[k]).to_owned(),
                    phase: "clip".to_owned(),
                    size: chars,
                    op: "intersection".to_owned(),
                    fill_rule: "even-odd".to_owned(),
                    repetition: round,
                    iterations,
                    time_ns,
                    correct: Some(true),
                });
            }
        }
    }
    let parameters = json!({
        "chars": chars,
        "size_px": PARAGRAPH_SIZE,
        "flatten_tolerance_px": DEFAULT_TOLERANCE,
        "rows": rows.iter().map(|r| bench_name(r)).collect::<Vec<_>>(),
        "windows": cut,
    });
    Ok(TextMeasured { rows: out, parameters })
}
