//! `clipbench verify --replay FILE`: re-runs the check of a saved failure on its saved inputs.

use std::path::Path;
use std::process::ExitCode;

use clip_core::{BoolOp, FillRule, Operand};

use super::recheck::{Target, line_failure, polygon_failure};
use super::record::CaseFile;
use super::text_runs::{TEXT_STRATEGIES, TextPlan};
use crate::checks::Check;
use crate::cli_error::{CliError, InputError};
use crate::read::{read_polygons, read_segments};
use crate::registry::{Registry, unknown_clipper};

/// Replays the case file at `path`: exit 1 when the failure is still there, 0 when it is gone.
pub fn replay(path: &Path, registry: &Registry) -> Result<ExitCode, CliError> {
    let text = std::fs::read_to_string(path).map_err(|e| InputError::new(path, format!("cannot read it: {e}")))?;
    let case: CaseFile =
        serde_json::from_str(&text).map_err(|e| InputError::new(path, format!("not a verify case file: {e}")))?;
    let dir = path.parent().unwrap_or(Path::new("."));
    if case.kind == "text" {
        return replay_text(&case);
    }
    let known = |name: &str| {
        registry.names().into_iter().find(|n| *n == name).ok_or_else(|| unknown_clipper(name, &registry.names()))
    };
    let clipper = known(&case.clipper)?;
    let check = match (case.check.as_str(), &case.other) {
        ("oracle", _) => Check::Oracle,
        ("area-identities", _) => Check::AreaIdentities,
        ("disagreement", Some(other)) => Check::Disagreement(known(other)?),
        (other, _) => return Err(InputError::new(path, format!("unknown check '{other}'")).into()),
    };
    let parse_op = |s: &String| s.parse::<BoolOp>().map_err(|e| CliError::from(InputError::new(path, e.to_string())));
    let parse_fill =
        |s: &String| s.parse::<FillRule>().map_err(|e| CliError::from(InputError::new(path, e.to_string())));
    let target = Target {
        clipper,
        check,
        op: case.op.as_ref().map(parse_op).transpose()?,
        fill: case.fill.as_ref().map(parse_fill).transpose()?,
    };
    let (first, second) = (dir.join(&case.inputs[0]), dir.join(&case.inputs[1]));
    let failure = if case.kind == "line" {
        let window = read_polygons(&first, Operand::Window)?;
        let segments = read_segments(&second)?;
        line_failure(registry, target, &window, &segments)
    } else {
        let subject = read_polygons(&first, Operand::Subject)?;
        let clip = read_polygons(&second, Operand::Clip)?;
        polygon_failure(registry, target, &subject, &clip)
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
            println!("still fails: {what}: {message}");
            Ok(ExitCode::FAILURE)
        }
        None => {
            println!("passes now: {what}");
            Ok(ExitCode::SUCCESS)
        }
    }
}

/// Replays a text failure: the case regenerated from its seed and index, the strategy rerun.
fn replay_text(case: &CaseFile) -> Result<ExitCode, CliError> {
    let name = TEXT_STRATEGIES.into_iter().find(|n| *n == case.clipper).ok_or_else(|| {
        CliError::usage(format!("unknown text row '{}' ({})", case.clipper, TEXT_STRATEGIES.join(", ")))
    })?;
    let font = clip_text::OutlineFont::from_file(Path::new(clip_text::DEJAVU_SANS))
        .map_err(|e| CliError::failed(e.to_string()))?;
    let plan = TextPlan { font: Some(font), names: vec![name], seed: case.seed };
    let what = format!("text {} ({} case {} of seed {})", case.clipper, case.workload, case.index, case.seed);
    match plan.failures(name, case.index).into_iter().flatten().next() {
        Some(message) => {
            println!("still fails: {what}: {message}");
            Ok(ExitCode::FAILURE)
        }
        None => {
            println!("passes now: {what}");
            Ok(ExitCode::SUCCESS)
        }
    }
}
