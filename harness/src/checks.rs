//! The checks applied to one result: the oracle, the area identities, agreement between two
//! clippers; shared by verify (runs, shrinking, `--replay`) and conformance.

use std::cell::Cell;
use std::panic::AssertUnwindSafe;
use std::sync::Once;

use clip_core::{BoolOp, ClipError, FailureKind, FillRule, Polygons, Segment, VisiblePiece};
use clip_oracle::line::{LineFailure, check_line_batch, pieces_to_intervals};
use clip_oracle::polygon::{
    OutputRules, PolygonFailure, check_area_identities_given, check_polygon_result, same_region, tolerance,
};

use crate::registry::{LineEntry, PolygonEntry};

/// What a failure is: which check rejected which result.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Check {
    /// The oracle rejected the result of one operation (or the clipper refused valid input).
    Oracle,
    /// An external clipper gave no answer within the call time-out: not a wrong answer, so
    /// counted apart, but kept with its replay.
    Hung,
    /// The four operations' results break an area identity.
    AreaIdentities,
    /// The result differs by region (or by visible intervals) from another clipper's.
    Disagreement(&'static str),
}

impl Check {
    /// The name used in file names and case files.
    pub fn label(self) -> String {
        match self {
            Check::Oracle => "oracle".into(),
            Check::Hung => "hung".into(),
            Check::AreaIdentities => "area-identities".into(),
            Check::Disagreement(other) => format!("vs-{other}"),
        }
    }
}

/// How a check failed: a shrunk case must fail the same way as the case found, not just fail
/// (a hang must not shrink to a crash, nor a wrong answer to a refusal).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Failing {
    /// The clipper refused valid, supported input.
    Refused,
    /// The clipper panicked.
    Panicked,
    /// The clipper gave no answer, in this way.
    NoAnswer(FailureKind),
    /// The output breaks the output conventions (crossing rings, a piece off its segment).
    Invalid,
    /// The output is well formed but wrong: a wrong region, wrong visible pieces.
    Wrong,
    /// The four operations' results break an area identity.
    AreaIdentity,
    /// Two clippers' results differ.
    Disagrees,
}

/// A failed check: how, and the one-line explanation.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Failure {
    /// How it failed.
    pub how: Failing,
    /// What failed, in words.
    pub message: String,
}

impl Failure {
    fn new(how: Failing, message: String) -> Failure {
        Failure { how, message }
    }

    /// The check a failed run is recorded under: [`Check::Hung`] when the clipper gave no
    /// answer in time, else [`Check::Oracle`].
    pub fn run_check(&self) -> Check {
        if self.how == Failing::NoAnswer(FailureKind::Hung) { Check::Hung } else { Check::Oracle }
    }
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl From<Failure> for String {
    fn from(f: Failure) -> String {
        f.message
    }
}

/// How the oracle reads a polygon clipper's output on `subject` under input fill rule `fill`.
pub fn output_rules(entry: &PolygonEntry, subject: &Polygons, fill: FillRule) -> OutputRules {
    OutputRules::for_form(entry.clipper.capabilities().output, subject, fill, entry.tolerance)
}

thread_local! {
    /// True while this thread runs a clipper under [`guarded`].
    static INSIDE_CLIPPER: Cell<bool> = const { Cell::new(false) };
}

/// Installs, once, a panic hook that stays quiet for panics [`guarded`] catches around a clipper
/// call (they become failure messages) and reports every other panic as before.
pub fn quiet_clipper_panics() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if !INSIDE_CLIPPER.with(Cell::get) {
                previous(info);
            }
        }));
    });
}

/// Runs a clipper call; a panic (a peer library's bug, or ours) becomes a failure message, so one
/// bad case does not end a whole run.
pub(crate) fn guarded<T>(call: impl FnOnce() -> Result<T, String>) -> Result<T, String> {
    guarded_as(|| call().map_err(|m| Failure::new(Failing::Wrong, m))).map_err(String::from)
}

/// [`guarded`] for calls that say how they failed: a panic is [`Failing::Panicked`].
fn guarded_as<T>(call: impl FnOnce() -> Result<T, Failure>) -> Result<T, Failure> {
    INSIDE_CLIPPER.with(|c| c.set(true));
    let result = std::panic::catch_unwind(AssertUnwindSafe(call));
    INSIDE_CLIPPER.with(|c| c.set(false));
    result.unwrap_or_else(|payload| {
        let message = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a non-text payload".into());
        Err(Failure::new(Failing::Panicked, format!("panicked: {message}")))
    })
}

/// Runs a polygon clipper; a refusal of (valid, supported) input is a failure message.
pub fn run_polygon(
    entry: &PolygonEntry,
    subject: &Polygons,
    clip: &Polygons,
    op: BoolOp,
    fill: FillRule,
) -> Result<Polygons, Failure> {
    guarded_as(|| entry.clipper.clip(subject, clip, op, fill).map_err(|e| failure(e, "")))
}

/// The oracle's verdict on one polygon result; when it passes, the area by which it differs from
/// the exact answer.
pub fn polygon_oracle(
    entry: &PolygonEntry,
    subject: &Polygons,
    clip: &Polygons,
    op: BoolOp,
    fill: FillRule,
    output: &Polygons,
) -> Result<f64, Failure> {
    polygon_oracle_under(&output_rules(entry, subject, fill), subject, clip, op, fill, output)
}

/// [`polygon_oracle`] with the output read under `rules` (the caller's [`output_rules`]).
pub fn polygon_oracle_under(
    rules: &OutputRules,
    subject: &Polygons,
    clip: &Polygons,
    op: BoolOp,
    fill: FillRule,
    output: &Polygons,
) -> Result<f64, Failure> {
    check_polygon_result(subject, clip, op, fill, output, rules).map_err(|f| {
        let how = match f {
            PolygonFailure::Invalid(_) => Failing::Invalid,
            PolygonFailure::WrongPoint { .. } | PolygonFailure::WrongRegion { .. } => Failing::Wrong,
            PolygonFailure::AreaIdentity(_) => Failing::AreaIdentity,
        };
        Failure::new(how, f.to_string())
    })
}

/// The area identities on the four operations' results; `operands` are |A| and |B| under `fill`
/// (`clip_oracle::polygon::operand_areas`), measured once per case.
pub fn area_identities(
    entry: &PolygonEntry,
    subject: &Polygons,
    clip: &Polygons,
    fill: FillRule,
    operands: (f64, f64),
    outputs: &[(BoolOp, &Polygons)],
) -> Result<(), Failure> {
    let rules = output_rules(entry, subject, fill);
    let tol = tolerance(subject, clip, rules.relative_tolerance);
    check_area_identities_given(operands, tol, outputs, &rules)
        .map_err(|f| Failure::new(Failing::AreaIdentity, f.to_string()))
}

/// Whether two clippers' results cover the same region, within the looser of their tolerances.
///
/// `off_exact` is, when the oracle passed both, how far each is from the exact answer (area of
/// the symmetric difference): the two differ by at most the sum, so when that is within the
/// tolerance they agree without another sweep.
pub fn polygons_agree(
    x: (&PolygonEntry, &Polygons),
    y: (&PolygonEntry, &Polygons),
    subject: &Polygons,
    clip: &Polygons,
    fill: FillRule,
    off_exact: Option<(f64, f64)>,
) -> Result<(), Failure> {
    let relative = x.0.tolerance.max(y.0.tolerance);
    let allowed = tolerance(subject, clip, relative);
    if off_exact.is_some_and(|(a, b)| a + b <= allowed) {
        return Ok(());
    }
    let read = |e: &PolygonEntry| output_rules(e, subject, fill).output_fill;
    same_region((x.1, read(x.0)), (y.1, read(y.0)), allowed).map_err(|area| {
        Failure::new(
            Failing::Disagrees,
            format!(
                "{} and {} differ by region: symmetric difference area {area:e} > tolerance {allowed:e}",
                x.0.clipper.name(),
                y.0.clipper.name()
            ),
        )
    })
}

/// A clipper's error as a failure: a refusal of input (of `what`, when said), or a failure to
/// answer (a library's internal error, an external process that crashed, hung or answered
/// garbage).
fn failure(e: ClipError, what: &str) -> Failure {
    match e {
        ClipError::Failed { kind, .. } => Failure::new(Failing::NoAnswer(kind), e.to_string()),
        _ => Failure::new(Failing::Refused, format!("refused{what}: {e}")),
    }
}

/// Runs a line clipper on a batch; a refusal of a valid window is a failure.
pub fn run_line(entry: &LineEntry, window: &Polygons, segments: &[Segment]) -> Result<Vec<VisiblePiece>, Failure> {
    guarded_as(|| {
        let prepared = entry.clipper.prepare(window).map_err(|e| failure(e, " the window"))?;
        let mut pieces = Vec::new();
        prepared.clip_batch(segments, &mut pieces).map_err(|e| failure(e, " the segments"))?;
        Ok(pieces)
    })
}

/// The line oracle's verdict on a batch.
pub fn line_oracle(
    entry: &LineEntry,
    window: &Polygons,
    segments: &[Segment],
    pieces: &[VisiblePiece],
) -> Result<(), Failure> {
    check_line_batch(window, segments, pieces, entry.tolerance).map_err(|f| {
        let how = match f {
            LineFailure::WrongPieces { .. } => Failing::Wrong,
            LineFailure::BadPiece(_) => Failing::Invalid,
        };
        Failure::new(how, f.to_string())
    })
}

/// Whether two line clippers see the same visible intervals in `window`, within the looser
/// tolerance.
pub fn lines_agree(
    x: (&LineEntry, &[VisiblePiece]),
    y: (&LineEntry, &[VisiblePiece]),
    window: &Polygons,
    segments: &[Segment],
) -> Result<(), Failure> {
    let allowed = x.0.tolerance.max(y.0.tolerance);
    let bounds = window.bounds();
    let (a, b) = (pieces_to_intervals(&bounds, segments, x.1), pieces_to_intervals(&bounds, segments, y.1));
    for (i, (ia, ib)) in a.iter().zip(&b).enumerate() {
        let close = ia.len() == ib.len()
            && ia.iter().zip(ib).all(|(p, q)| (p.0 - q.0).abs() <= allowed && (p.1 - q.1).abs() <= allowed);
        if !close {
            let message =
                format!("segment {i}: {} sees {ia:?}, {} sees {ib:?}", x.0.clipper.name(), y.0.clipper.name());
            return Err(Failure::new(Failing::Disagrees, message));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::registry;
    use clip_core::Rect;

    #[test]
    fn agreement_follows_from_two_oracle_passes_only_within_the_tolerance() {
        let registry = registry();
        let vatti = registry.find_polygon("vatti").expect("registered");
        let (a, b) = (Polygons::from(Rect::new(0.0, 0.0, 2.0, 2.0)), Polygons::from(Rect::new(1.0, 1.0, 3.0, 3.0)));
        let exact = vatti.clipper.clip(&a, &b, BoolOp::Intersection, FillRule::NonZero).expect("valid input");
        let off = polygon_oracle(vatti, &a, &b, BoolOp::Intersection, FillRule::NonZero, &exact).expect("passes");
        assert!(off <= tolerance(&a, &b, vatti.tolerance), "{off}");
        // A different result is caught by the sweep, and by the bound when it does not prove agreement.
        let shifted = Polygons::from(Rect::new(1.0, 1.0, 2.0, 2.5));
        assert!(polygons_agree((vatti, &exact), (vatti, &shifted), &a, &b, FillRule::NonZero, None).is_err());
        assert!(
            polygons_agree((vatti, &exact), (vatti, &shifted), &a, &b, FillRule::NonZero, Some((off, 0.5))).is_err()
        );
        assert!(polygons_agree((vatti, &exact), (vatti, &exact), &a, &b, FillRule::NonZero, Some((off, off))).is_ok());
    }
}
