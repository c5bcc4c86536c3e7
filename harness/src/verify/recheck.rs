//! Re-runs the one check a failure was found by, on any inputs: the shrinker's predicate and the
//! heart of `--replay`.

use clip_core::{BoolOp, FillRule, Operand, Polygons, Segment, validate_polygons, validate_segments, validate_window};
use clip_oracle::polygon::operand_areas;

use crate::checks::{
    Check, Failure, area_identities, line_oracle, lines_agree, polygon_oracle, polygons_agree, run_line, run_polygon,
};
use crate::registry::Registry;

/// The check to re-run: whose result, which check, which operation and fill rule.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Target<'a> {
    /// The clipper the failure is counted under.
    pub clipper: &'a str,
    /// The check that failed.
    pub check: Check,
    /// The operation (polygons, except for area identities).
    pub op: Option<BoolOp>,
    /// The fill rule (polygons).
    pub fill: Option<FillRule>,
}

/// Why the polygon check still fails on these inputs, or `None` when it passes or the inputs
/// are not ones the clippers must accept (invalid, or a window of the wrong kind): the shrinker
/// must not turn a wrong answer into a correct refusal.
pub fn polygon_failure(registry: &Registry, target: Target, subject: &Polygons, clip: &Polygons) -> Option<Failure> {
    let entry = registry.find_polygon(target.clipper)?;
    let fill = target.fill?;
    let acceptable = |e: &crate::registry::PolygonEntry| e.clipper.capabilities().window.accepts(clip);
    if validate_polygons(subject, Operand::Subject).is_err() || validate_polygons(clip, Operand::Clip).is_err() {
        return None;
    }
    if !acceptable(entry) {
        return None;
    }
    let checked = |e, op| {
        let out = run_polygon(e, subject, clip, op, fill)?;
        polygon_oracle(e, subject, clip, op, fill, &out).map(|_| out)
    };
    match target.check {
        Check::Oracle | Check::Hung => checked(entry, target.op?).err(),
        Check::AreaIdentities => {
            let mut outputs = Vec::new();
            for op in BoolOp::ALL {
                outputs.push((op, run_polygon(entry, subject, clip, op, fill).ok()?));
            }
            let four: Vec<(BoolOp, &Polygons)> = outputs.iter().map(|(op, o)| (*op, o)).collect();
            area_identities(entry, subject, clip, fill, operand_areas(subject, clip, fill), &four).err()
        }
        Check::Disagreement(other) => {
            let other = registry.find_polygon(other)?;
            if !acceptable(other) {
                return None;
            }
            let op = target.op?;
            let (a, b) = (checked(entry, op).ok()?, checked(other, op).ok()?);
            polygons_agree((entry, &a), (other, &b), subject, clip, fill, None).err()
        }
    }
}

/// Why the line check still fails on these inputs, or `None` (see [`polygon_failure`]).
pub fn line_failure(registry: &Registry, target: Target, window: &Polygons, segments: &[Segment]) -> Option<Failure> {
    let entry = registry.find_line(target.clipper)?;
    if validate_window(window).is_err() || validate_segments(segments).is_err() {
        return None;
    }
    let acceptable = |e: &crate::registry::LineEntry| e.clipper.capabilities().window.accepts(window);
    if !acceptable(entry) {
        return None;
    }
    let checked = |e| {
        let pieces = run_line(e, window, segments)?;
        line_oracle(e, window, segments, &pieces).map(|()| pieces)
    };
    match target.check {
        Check::Oracle | Check::Hung => checked(entry).err(),
        Check::AreaIdentities => None,
        Check::Disagreement(other) => {
            let other = registry.find_line(other)?;
            if !acceptable(other) {
                return None;
            }
            let (a, b) = (checked(entry).ok()?, checked(other).ok()?);
            lines_agree((entry, &a), (other, &b), window, segments).err()
        }
    }
}
