//! A case file read back for `--replay`, its fields checked against each other and the registry
//! before anything runs. The re-check passes on inputs it does not apply to (a line clipper on a
//! polygon case, an operation the clipper does not do, a window it cannot take), which is right
//! for the shrinker but would make a case file that does not hang together say "passes now".

use std::path::Path;

use clip_core::{BoolOp, FillRule, Polygons, WindowKind};

use super::finding::{Kind, window_name};
use super::polygon_runs::takes;
use super::recheck::Target;
use super::record::CaseFile;
use super::text_runs::TEXT_STRATEGIES;
use crate::checks::Check;
use crate::cli_error::{CliError, InputError};
use crate::registry::{Registry, unknown_clipper};

/// What a case file asks to re-run, checked.
pub struct Replay {
    /// Polygon, line, curve or text case.
    pub kind: Kind,
    /// The clipper, check, operation and fill rule.
    pub target: Target<'static>,
    /// The clippers that run (the one counted, and the other of a disagreement) and the windows
    /// each takes.
    clippers: Vec<(&'static str, WindowKind)>,
}

impl Replay {
    /// `Ok` when every clipper that runs takes `window` (the clip operand, or the line window)
    /// read from `path`; else the check would pass without running.
    pub fn takes_window(&self, window: &Polygons, path: &Path) -> Result<(), CliError> {
        match self.clippers.iter().find(|(_, own)| !own.accepts(window)) {
            None => Ok(()),
            Some((name, own)) => Err(InputError::new(
                path,
                format!("{name} takes {} windows only, and this is not one", window_name(*own)),
            )
            .into()),
        }
    }
}

/// Checks `case`, read from `path`, into what to re-run: a one-line error naming the field
/// otherwise.
pub fn checked(case: &CaseFile, registry: &Registry, path: &Path) -> Result<Replay, CliError> {
    let bad = |problem: String| CliError::from(InputError::new(path, problem));
    let kind = match case.kind.as_str() {
        "polygon" => Kind::Polygon,
        "line" => Kind::Line,
        "curve" => Kind::Curve,
        "text" => return text_replay(case, path),
        other => return Err(bad(format!("unknown kind '{other}' (a case is a polygon, line, curve or text case)"))),
    };
    let clipper = clipper_of(kind, &case.clipper, registry, path)?;
    let mut clippers = vec![clipper];
    let check = match (case.check.as_str(), &case.other) {
        ("disagreement", None) => {
            return Err(bad(
                "a disagreement case needs 'other', the clipper it disagreed with, and it is missing".into()
            ));
        }
        ("disagreement", Some(other)) if *other == case.clipper => {
            return Err(bad(format!("'other' is {other}, the clipper itself: a disagreement is between two")));
        }
        ("disagreement", Some(other)) => {
            let other = clipper_of(kind, other, registry, path)?;
            clippers.push(other);
            Check::Disagreement(other.0)
        }
        (check @ ("oracle" | "hung" | "area-identities"), Some(other)) => {
            return Err(bad(format!("'other' ({other}) is for a disagreement, and the check here is {check}")));
        }
        ("oracle", None) => Check::Oracle,
        ("hung", None) => Check::Hung,
        ("area-identities", None) if kind == Kind::Polygon => Check::AreaIdentities,
        ("area-identities", None) => {
            return Err(bad(format!("area identities are a polygon check, and this is a {} case", kind.name())));
        }
        (other, _) => {
            return Err(bad(format!("unknown check '{other}' (oracle, hung, area-identities or disagreement)")));
        }
    };
    let op = case.op.as_deref().map(|s| s.parse::<BoolOp>().map_err(|e| bad(e.to_string()))).transpose()?;
    let fill = case.fill.as_deref().map(|s| s.parse::<FillRule>().map_err(|e| bad(e.to_string()))).transpose()?;
    match kind {
        Kind::Line | Kind::Curve | Kind::Text => {
            if let Some(op) = op {
                return Err(bad(format!("a {} case has no 'op', and this one says {op}", kind.name())));
            }
            if let Some(fill) = fill {
                return Err(bad(format!("a {} case has no 'fill', and this one says {fill}", kind.name())));
            }
        }
        Kind::Polygon => {
            let fill =
                fill.ok_or_else(|| bad("a polygon case needs 'fill', the fill rule, and it is missing".into()))?;
            let ops = match (check, op) {
                (Check::AreaIdentities, None) => BoolOp::ALL.to_vec(),
                (Check::AreaIdentities, Some(op)) => {
                    return Err(bad(format!("area identities run all four operations, and this case names {op}")));
                }
                (_, None) => {
                    return Err(bad(format!(
                        "a polygon {} case needs 'op', the operation, and it is missing",
                        case.check
                    )));
                }
                (_, Some(op)) => vec![op],
            };
            for &(name, _) in &clippers {
                let Some(e) = registry.find_polygon(name) else { continue };
                if let Some(op) = ops.iter().find(|&&op| !e.clipper.capabilities().supports(op, fill)) {
                    return Err(bad(format!("{name} does not do {op} under {fill}, so verify never ran it")));
                }
            }
        }
    }
    let window = [WindowKind::Any, WindowKind::Convex, WindowKind::Rectangle]
        .into_iter()
        .find(|&w| window_name(w) == case.window)
        .ok_or_else(|| bad(format!("unknown window '{}' (any, convex or rectangle)", case.window)))?;
    if let Some((name, own)) = clippers.iter().find(|(_, own)| !takes(*own, window)) {
        return Err(bad(format!(
            "{name} takes {} windows only, and this case was generated for {} windows",
            window_name(*own),
            case.window
        )));
    }
    Ok(Replay { kind, target: Target { clipper: clipper.0, check, op, fill }, clippers })
}

/// A text case: one of the text rows, checked by the raster oracle, regenerated from its seed and
/// index (no operation, fill rule or other clipper).
fn text_replay(case: &CaseFile, path: &Path) -> Result<Replay, CliError> {
    let bad = |problem: String| CliError::from(InputError::new(path, problem));
    let Some(&row) = TEXT_STRATEGIES.iter().find(|&&n| n == case.clipper) else {
        return Err(bad(format!("unknown text row '{}' ({})", case.clipper, TEXT_STRATEGIES.join(", "))));
    };
    if case.check != "oracle" || case.other.is_some() || case.op.is_some() || case.fill.is_some() {
        return Err(bad("a text case is an oracle check with no 'other', 'op' or 'fill'".into()));
    }
    let target = Target { clipper: row, check: Check::Oracle, op: None, fill: None };
    Ok(Replay { kind: Kind::Text, target, clippers: Vec::new() })
}

/// The registered clipper `name` of `kind` and the windows it takes.
fn clipper_of(
    kind: Kind,
    name: &str,
    registry: &Registry,
    path: &Path,
) -> Result<(&'static str, WindowKind), CliError> {
    let polygon = registry.find_polygon(name).map(|e| (e.clipper.name(), e.clipper.capabilities().window));
    let line = registry.find_line(name).map(|e| (e.clipper.name(), e.clipper.capabilities().window));
    // Curve clippers take rectangle and polygon windows alike.
    let curve = registry.curve.iter().find(|e| e.clipper.name() == name).map(|e| (e.clipper.name(), WindowKind::Any));
    let kind_of = |found: Option<_>, k: Kind| found.map(|_: (&str, WindowKind)| k);
    let (wanted, other_kind) = match kind {
        Kind::Polygon => (polygon, kind_of(line, Kind::Line).or(kind_of(curve, Kind::Curve))),
        Kind::Line => (line, kind_of(polygon, Kind::Polygon).or(kind_of(curve, Kind::Curve))),
        Kind::Curve => (curve, kind_of(polygon, Kind::Polygon).or(kind_of(line, Kind::Line))),
        Kind::Text => (None, None),
    };
    match (wanted, other_kind) {
        (Some(found), _) => Ok(found),
        (None, Some(other_kind)) => Err(InputError::new(
            path,
            format!("{name} is a {} clipper, and this is a {} case", other_kind.name(), kind.name()),
        )
        .into()),
        (None, None) => Err(InputError::new(path, unknown_clipper(name, &registry.names()).message).into()),
    }
}
