//! External clippers: any program that speaks docs/PROTOCOL.md (line-delimited JSON on its
//! stdin and stdout), added to the registry from `--external NAME=COMMAND` or `--clippers FILE`
//! for `verify`, `conformance`, `bench` and `clip`.

mod clipper;
mod process;
pub mod protocol;
pub mod spec;

use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use clip_core::{LineCapabilities, OutputForm, PolygonCapabilities};
use clip_oracle::polygon::GEO_TOLERANCE;

use self::clipper::{ExternalLine, ExternalPolygon, Pool};
use self::process::Worker;
use self::protocol::{Handshake, PROTOCOL_VERSION, parse_fill, parse_op, parse_output, parse_window};
use self::spec::ExternalSpec;
use crate::cli_error::CliError;
use crate::registry::{LineEntry, Origin, PolygonEntry, Registry};

/// The options every command that runs clippers takes for external ones.
#[derive(Debug, Clone, Default, clap::Args)]
pub struct ExternalArgs {
    /// An external clipper speaking docs/PROTOCOL.md: its name and the command that starts it
    /// (split like a shell would), e.g. `shapely='python3 adapters/shapely/clipbench_shapely.py'`.
    /// Repeat for several.
    #[arg(long = "external", value_name = "NAME=COMMAND")]
    pub external: Vec<String>,
    /// External clippers from a TOML file: `[[clipper]]` tables with `name`, `command` and an
    /// optional working directory `dir`.
    #[arg(long = "clippers", value_name = "FILE")]
    pub clippers_file: Option<PathBuf>,
    /// Seconds an external clipper may take to answer one request (or its handshake) before it
    /// is killed, the case failed, and a fresh process started: more than 0, at most a day.
    #[arg(long, value_name = "SECONDS", default_value = DEFAULT_CALL_TIMEOUT, value_parser = parse_call_timeout)]
    pub call_timeout: Duration,
    /// Judge external clippers like this project's own: their failures fail the run.
    #[arg(long)]
    pub strict: bool,
}

/// The registry with every external clipper added: each started once (its handshake read and
/// checked) and kept running for the calls. A clipper that cannot start, dies at the
/// handshake or declares what the harness does not know is a usage error naming it.
pub fn add_external(mut registry: Registry, args: &ExternalArgs) -> Result<Registry, CliError> {
    let mut specs: Vec<ExternalSpec> =
        args.external.iter().map(|text| spec::parse_flag(text)).collect::<Result<_, _>>()?;
    if let Some(path) = &args.clippers_file {
        specs.extend(spec::parse_file(path)?);
    }
    if specs.is_empty() {
        return Ok(registry);
    }
    let timeout = args.call_timeout;
    let origin = if args.strict { Origin::Strict } else { Origin::External };
    for spec in specs {
        let taken = registry.names();
        if taken.contains(&spec.name.as_str()) {
            return Err(CliError::usage(format!(
                "external clipper '{}': the name is taken (registered: {})",
                spec.name,
                taken.join(", ")
            )));
        }
        let blame = |what: String| {
            CliError::usage(format!("external clipper '{}' ({}): {what}", spec.name, spec::shown(&spec.command)))
        };
        let (worker, handshake) = Worker::start(&spec, timeout).map_err(blame)?;
        let mut option = spec.option();
        if parse_call_timeout(DEFAULT_CALL_TIMEOUT).is_ok_and(|default| timeout != default) {
            option.push_str(&format!(" --call-timeout {}", timeout.as_secs_f64()));
        }
        let (polygon, line) = declared(&handshake).map_err(blame)?;
        let handshake_name = handshake.name.clone();
        // The registry hands out `&'static str` names and capability slices: leaked once per
        // external clipper, for a registry that lives as long as the run.
        let name: &'static str = spec.name.clone().leak();
        let pool = Arc::new(Pool::new(name, spec, worker, handshake, timeout));
        if let Some(capabilities) = polygon {
            let clipper = ExternalPolygon { pool: Arc::clone(&pool), capabilities };
            registry.polygon.push(PolygonEntry {
                clipper: Box::new(clipper.clone()),
                origin,
                tolerance: GEO_TOLERANCE,
                own_time: Some(Arc::clone(&pool.own_time)),
                own_memory: Some(Arc::new(clipper)),
                external: Some(option.clone()),
                handshake: Some(handshake_name.clone()),
            });
        }
        if let Some(capabilities) = line {
            registry.line.push(LineEntry {
                clipper: Box::new(ExternalLine { pool: Arc::clone(&pool), capabilities }),
                origin,
                tolerance: GEO_TOLERANCE,
                external: Some(option.clone()),
            });
        }
    }
    Ok(registry)
}

/// `--call-timeout` when none is given, in seconds.
pub const DEFAULT_CALL_TIMEOUT: &str = "20";

/// The longest `--call-timeout`: a day is longer than any call worth waiting for, and far from
/// the largest time a `Duration` holds (about 1.8e19 s), past which the conversion fails.
pub const MAX_CALL_TIMEOUT_SECONDS: f64 = 86_400.0;

/// `--call-timeout`'s value: a number of seconds above 0 and at most [`MAX_CALL_TIMEOUT_SECONDS`].
fn parse_call_timeout(text: &str) -> Result<Duration, String> {
    let seconds: f64 = text.trim().parse().map_err(|_| format!("'{text}' is not a number of seconds"))?;
    if !(seconds > 0.0 && seconds <= MAX_CALL_TIMEOUT_SECONDS) {
        return Err(format!(
            "{text} seconds: the time limit must be above 0 and at most {MAX_CALL_TIMEOUT_SECONDS} (a day)"
        ));
    }
    Ok(Duration::from_secs_f64(seconds))
}

/// The capabilities a handshake declares, or what is wrong with it.
fn declared(h: &Handshake) -> Result<(Option<PolygonCapabilities>, Option<LineCapabilities>), String> {
    if h.protocol != PROTOCOL_VERSION {
        return Err(format!(
            "it speaks protocol version {}; this harness speaks version {PROTOCOL_VERSION} (docs/PROTOCOL.md)",
            h.protocol
        ));
    }
    if h.polygon.is_none() && h.line.is_none() {
        return Err(format!("its handshake (name '{}') declares neither polygon nor line clipping", h.name));
    }
    let polygon = match &h.polygon {
        None => None,
        Some(p) => {
            let ops = p.ops.iter().map(|o| parse_op(o)).collect::<Result<Vec<_>, _>>()?;
            let fills = p.fill_rules.iter().map(|f| parse_fill(f)).collect::<Result<Vec<_>, _>>()?;
            if ops.is_empty() || fills.is_empty() {
                return Err("its polygon capabilities list no operation or no fill rule".into());
            }
            let bridges = parse_output(&p.output)?;
            Some(PolygonCapabilities {
                ops: ops.leak(),
                fill_rules: fills.leak(),
                window: parse_window(&p.window)?,
                trapezoids: false,
                bridges,
                // Bridged output keeps each subject ring in its orientation: read under the input's rule.
                output: if bridges { OutputForm::InputRule } else { OutputForm::Conventional },
            })
        }
    };
    let line = match &h.line {
        None => None,
        Some(l) => Some(LineCapabilities { window: parse_window(&l.window)? }),
    };
    Ok((polygon, line))
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::{BoolOp, FillRule, WindowKind};

    fn handshake(text: &str) -> Handshake {
        serde_json::from_str(text).unwrap()
    }

    #[test]
    fn declarations_become_capabilities() {
        let h = handshake(
            r#"{"protocol":1,"name":"x","polygon":{"ops":["intersection"],"fill_rules":["non-zero","even-odd"],"window":"convex","output":"bridged"},"line":{"window":"rectangle"}}"#,
        );
        let (p, l) = declared(&h).unwrap();
        let p = p.unwrap();
        assert_eq!(p.ops, &[BoolOp::Intersection]);
        assert_eq!(p.fill_rules, &[FillRule::NonZero, FillRule::EvenOdd]);
        assert_eq!((p.window, p.bridges), (WindowKind::Convex, true));
        assert_eq!(l.unwrap().window, WindowKind::Rectangle);
    }

    #[test]
    fn unknown_versions_and_capabilities_are_named() {
        let v2 = handshake(r#"{"protocol":2,"name":"x","line":{"window":"any"}}"#);
        assert!(declared(&v2).unwrap_err().contains("version 2"));
        let none = handshake(r#"{"protocol":1,"name":"x"}"#);
        assert!(declared(&none).unwrap_err().contains("neither"));
        let op = handshake(
            r#"{"protocol":1,"name":"x","polygon":{"ops":["minkowski"],"fill_rules":["even-odd"],"window":"any"}}"#,
        );
        assert!(declared(&op).unwrap_err().contains("'minkowski'"));
        let window = handshake(r#"{"protocol":1,"name":"x","line":{"window":"circle"}}"#);
        assert!(declared(&window).unwrap_err().contains("'circle'"));
    }
}
