//! `clipbench verify --replay FILE`: re-runs the check of a saved failure on its saved inputs.

use std::path::Path;
use std::process::ExitCode;

use clip_core::{Operand, validate_window};

use super::curve_runs::curve_failure;
use super::finding::Kind;
use super::recheck::{line_failure, polygon_failure};
use super::record::CaseFile;
use super::replay_case::{self, Replay};
use super::text_runs::TextPlan;
use crate::cli_error::{CliError, InputError};
use crate::console;
use crate::curve_input::read_curves;
use crate::read::{read_polygons, read_segments};
use crate::registry::Registry;

/// Replays the case file at `path`: exit 1 when the failure is still there, 0 when it is gone.
pub fn replay(path: &Path, registry: &Registry) -> Result<ExitCode, CliError> {
    let text = crate::read::read_text(path)?;
    let (case, replay) = read_case(&text, path, registry)?;
    let dir = path.parent().unwrap_or(Path::new("."));
    let (first, second) = (dir.join(&case.inputs[0]), dir.join(&case.inputs[1]));
    let failure = match replay.kind {
        // Regenerated from its seed and index rather than read from files.
        Kind::Text => return replay_text(&case, replay.target.clipper),
        Kind::Curve => {
            let window = read_polygons(&first, Operand::Window)?;
            validate_window(&window).map_err(|e| InputError::new(&first, e.to_string()))?;
            let objects = read_curves(&second)?
                .ok_or_else(|| InputError::new(&second, "holds no circle, ellipse or arc".into()))?;
            curve_failure(&registry.curve, replay.target.clipper, replay.target.check, &window, &objects)
        }
        Kind::Line => {
            let window = read_polygons(&first, Operand::Window)?;
            validate_window(&window).map_err(|e| InputError::new(&first, e.to_string()))?;
            replay.takes_window(&window, &first)?;
            let segments = read_segments(&second)?;
            line_failure(registry, replay.target, &window, &segments).map(String::from)
        }
        Kind::Polygon => {
            let subject = read_polygons(&first, Operand::Subject)?;
            let clip = read_polygons(&second, Operand::Clip)?;
            replay.takes_window(&clip, &second)?;
            polygon_failure(registry, replay.target, &subject, &clip).map(String::from)
        }
    };
    let what = format!(
        "{} {} {} ({} case {} of seed {}{}{})",
        case.kind,
        case.clipper,
        case.check,
        case.workload,
        case.index,
        case.seed,
        case.op.map(|o| format!(", {o}")).unwrap_or_default(),
        case.fill.map(|f| format!(", {f}")).unwrap_or_default(),
    );
    match failure {
        Some(message) => {
            console::print_line(format_args!("still fails: {what}: {message}"))?;
            Ok(ExitCode::FAILURE)
        }
        None => {
            console::print_line(format_args!("passes now: {what}"))?;
            Ok(ExitCode::SUCCESS)
        }
    }
}

/// A case file's text (read from `path`) parsed and checked against itself and the registry:
/// what `--replay` runs, or the one-line error saying what does not hang together. The `readers`
/// fuzz target calls this with any text.
pub fn read_case(text: &str, path: &Path, registry: &Registry) -> Result<(CaseFile, Replay), CliError> {
    let bad = |problem: String| CliError::from(InputError::new(path, problem));
    let value: serde_json::Value =
        serde_json::from_str(text).map_err(|e| bad(format!("not a verify case file (not JSON: {e})")))?;
    if let Some(inputs) = value.get("inputs").and_then(serde_json::Value::as_array)
        && inputs.len() != 2
    {
        return Err(bad(format!(
            "'inputs' lists {} file(s); a case has two: subject and clip, or the window and the segments or curves",
            inputs.len()
        )));
    }
    let case: CaseFile = serde_json::from_value(value).map_err(|e| bad(format!("not a verify case file: {e}")))?;
    let replay = replay_case::checked(&case, registry, path)?;
    Ok((case, replay))
}

/// Replays a text failure: the case regenerated from its seed and index, the strategy rerun.
fn replay_text(case: &CaseFile, name: &'static str) -> Result<ExitCode, CliError> {
    let font = clip_text::OutlineFont::from_file(Path::new(clip_text::DEJAVU_SANS))
        .map_err(|e| CliError::failed(e.to_string()))?;
    let plan = TextPlan { font: Some(font), names: vec![name], seed: case.seed };
    let what = format!("text {} ({} case {} of seed {})", case.clipper, case.workload, case.index, case.seed);
    match plan.failures(name, case.index).into_iter().flatten().next() {
        Some(message) => {
            console::print_line(format_args!("still fails: {what}: {message}"))?;
            Ok(ExitCode::FAILURE)
        }
        None => {
            console::print_line(format_args!("passes now: {what}"))?;
            Ok(ExitCode::SUCCESS)
        }
    }
}
