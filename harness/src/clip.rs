//! `clipbench clip`: one operation on files with any registered clipper, to try a case by hand.

use std::path::PathBuf;

use clip_core::{BoolOp, FillRule, Operand, validate_polygons, validate_segments};

use crate::cli_error::{CliError, InputError};
use crate::clip_curves::clip_curves;
use crate::clip_features::{FeatureClipper, clip_features};
use crate::console;
use crate::curve_input::read_curves;
use crate::read::{is_geojson, read_features, read_polygons, read_shapes};
use crate::registry::{Registry, unknown_clipper};
use crate::write::{OutputFormat, line_result, polygon_result, write_file};

/// How `clip` reads its files, for `clipbench clip --help`.
const READING: &str = "\
Files: WKT, one geometry per file (several go in a GEOMETRYCOLLECTION), or GeoJSON (a geometry, a \
Feature or a FeatureCollection), holding polygons or line strings, not both. Rings must be closed (the last point the first); coordinates must \
be finite numbers; WKT nests at most 256 parentheses deep, GeoJSON at most 128 levels. Z and M \
values are dropped, and rings of fewer than 3 distinct points (which enclose nothing) are dropped, \
each with a note on standard error. Errors say where: `feature 1, ring 0, position 2`, or a WKT \
line and column (indices count from 0). A GeoJSON Feature or FeatureCollection subject is clipped \
feature by feature, and written back as GeoJSON features with their ids and properties (WKT and SVG \
output get the geometries only); a feature with a null geometry is written back as it is.";

/// Arguments of `clipbench clip`.
#[derive(Debug, clap::Args)]
#[command(after_help = READING)]
pub struct ClipArgs {
    /// Registered clipper to run (`clipbench verify --help` lists them).
    #[arg(long)]
    pub clipper: String,
    /// Operation: intersection, union, difference or xor.
    #[arg(long, default_value = "intersection")]
    pub op: BoolOp,
    /// Fill rule both operands are read under: even-odd, non-zero, positive or negative.
    #[arg(long, default_value = "even-odd")]
    pub fill: FillRule,
    /// Subject file (WKT, or GeoJSON when named .geojson/.json). Polygons, or line strings to
    /// clip with a line clipper (intersection only; the window is read under even-odd), or
    /// circles, ellipses and arcs for a curve clipper (the curve text format, or GeoJSON Point
    /// features with a `circle` or `ellipse` property; see the README).
    pub subject: PathBuf,
    /// Clip file (WKT or GeoJSON): polygons, every ring kept with its orientation.
    pub clip: PathBuf,
    /// Write here instead of printing WKT: .wkt, .geojson/.json, or .svg for a picture.
    #[arg(short, long)]
    pub out: Option<PathBuf>,
    /// External clippers (docs/PROTOCOL.md).
    #[command(flatten)]
    pub external: crate::external::ExternalArgs,
    /// Curves only: the flattening tolerance of WKT and GeoJSON output (default: 1e-4 of the
    /// window's extent); SVG draws exact arcs.
    #[arg(long)]
    pub tolerance: Option<f64>,
}

/// Runs the command.
pub fn run(args: &ClipArgs, registry: &Registry) -> Result<(), CliError> {
    let format = match &args.out {
        Some(path) => OutputFormat::of(path)?,
        None => OutputFormat::Wkt,
    };
    if let Some(objects) = read_curves(&args.subject)? {
        if args.op != BoolOp::Intersection {
            return Err(CliError::usage(format!("curves can only be clipped by intersection, not {}", args.op)));
        }
        let text = clip_curves(registry, &args.clipper, &objects, &args.clip, args.tolerance, format)?;
        return emit(args, &text);
    }
    if is_geojson(&args.subject)
        && let Some(features) = read_features(&args.subject)?
    {
        let clip = read_polygons(&args.clip, Operand::Clip)?;
        let clipper = if features.line_strings {
            FeatureClipper::Line(line_entry(args, registry)?)
        } else {
            FeatureClipper::Polygon(polygon_entry(args, registry)?, args.op, args.fill)
        };
        // Features are written back as features: GeoJSON unless another format is asked for.
        let format = if args.out.is_none() { OutputFormat::GeoJson } else { format };
        let text = clip_features(clipper, &args.subject, &features, &clip, format)?;
        return emit(args, &text);
    }
    let subject = read_shapes(&args.subject)?;
    let clip = read_polygons(&args.clip, Operand::Clip)?;
    let text = if subject.line_strings {
        // Line strings: a line clipper's visible pieces.
        let entry = line_entry(args, registry)?;
        let segments = subject.segments.clone();
        validate_segments(&segments).map_err(|e| InputError::new(&args.subject, e.to_string()))?;
        let window =
            entry.clipper.prepare(&clip).map_err(|e| CliError::usage(format!("{}: {e}", args.clip.display())))?;
        let mut pieces = Vec::new();
        window.clip_batch(&segments, &mut pieces).map_err(|e| CliError::usage(e.to_string()))?;
        line_result(format, entry.clipper.name(), &clip, &segments, &pieces)
    } else {
        let entry = polygon_entry(args, registry)?;
        let subject = subject.polygons();
        validate_polygons(&subject, Operand::Subject).map_err(|e| InputError::new(&args.subject, e.to_string()))?;
        let result =
            entry.clipper.clip(&subject, &clip, args.op, args.fill).map_err(|e| CliError::usage(e.to_string()))?;
        polygon_result(format, entry.clipper.name(), &subject, &clip, &result)
    };
    emit(args, &text)
}

/// Writes the output file, or prints the text.
fn emit(args: &ClipArgs, text: &str) -> Result<(), CliError> {
    match &args.out {
        Some(path) => write_file(path, text),
        None => console::print(text),
    }
}

/// The polygon clipper `--clipper` names, or a usage error saying what it is and which clip polygons.
fn polygon_entry<'a>(args: &ClipArgs, registry: &'a Registry) -> Result<&'a crate::registry::PolygonEntry, CliError> {
    registry.find_polygon(&args.clipper).ok_or_else(|| wrong_kind(&args.clipper, registry, "polygons"))
}

/// The line clipper `--clipper` names (for intersection only), or a usage error as for polygons.
fn line_entry<'a>(args: &ClipArgs, registry: &'a Registry) -> Result<&'a crate::registry::LineEntry, CliError> {
    let entry = registry.find_line(&args.clipper).ok_or_else(|| wrong_kind(&args.clipper, registry, "line strings"))?;
    if args.op != BoolOp::Intersection {
        return Err(CliError::usage(format!("line strings can only be clipped by intersection, not {}", args.op)));
    }
    Ok(entry)
}

/// Why `given` cannot clip a subject that `holds` (`polygons` or `line strings`): what kind of
/// clipper it is, if any, and which clippers take what the subject holds.
fn wrong_kind(given: &str, registry: &Registry, holds: &str) -> CliError {
    let names = |kind: &str| -> Vec<&'static str> {
        match kind {
            "polygons" => registry.polygon.iter().map(|e| e.clipper.name()).collect(),
            "line strings" => registry.line.iter().map(|e| e.clipper.name()).collect(),
            _ => registry.curve.iter().map(|e| e.clipper.name()).collect(),
        }
    };
    let takes = if holds == "polygons" { "polygon clippers" } else { "line clippers" };
    let is = ["polygons", "line strings", "curves"].into_iter().find(|k| names(k).contains(&given));
    match is {
        Some(kind) => {
            let what = match kind {
                "polygons" => "a polygon clipper",
                "line strings" => "a line clipper",
                _ => {
                    "a curve clipper (circles, ellipses and arcs, from the curve text format or GeoJSON curve features)"
                }
            };
            CliError::usage(format!(
                "'{given}' is {what}, and the subject holds {holds} ({takes}: {})",
                names(holds).join(", ")
            ))
        }
        None => unknown_clipper(given, &registry.names()),
    }
}
