//! `clipbench clip`: one operation on files with any registered clipper, to try a case by hand.

use std::path::PathBuf;

use clip_core::{BoolOp, FillRule, Operand, validate_polygons, validate_segments};

use crate::cli_error::{CliError, InputError};
use crate::clip_curves::clip_curves;
use crate::console;
use crate::curve_input::read_curves;
use crate::read::{read_polygons, read_shapes};
use crate::registry::{Registry, unknown_clipper};
use crate::write::{OutputFormat, line_result, polygon_result, write_file};

/// How `clip` reads its files, for `clipbench clip --help`.
const READING: &str = "\
Files: WKT, one geometry per file (several go in a GEOMETRYCOLLECTION), or GeoJSON (a geometry, a \
Feature or a FeatureCollection), holding polygons or line strings, not both. Rings must be closed (the last point the first); coordinates must \
be finite numbers; WKT nests at most 256 parentheses deep, GeoJSON at most 128 levels. Z and M \
values are dropped, with a note on standard error. Errors say where: `feature 1, ring 0, position \
2`, or a WKT line and column (indices count from 0).";

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
    let subject = read_shapes(&args.subject)?;
    let clip = read_polygons(&args.clip, Operand::Clip)?;
    let text = if subject.rings.is_empty() && !subject.segments.is_empty() {
        // Line strings: a line clipper's visible pieces.
        let entry = registry.find_line(&args.clipper).ok_or_else(|| unknown_line_clipper(&args.clipper, registry))?;
        if args.op != BoolOp::Intersection {
            return Err(CliError::usage(format!("line strings can only be clipped by intersection, not {}", args.op)));
        }
        let segments = subject.segments.clone();
        validate_segments(&segments).map_err(|e| InputError::new(&args.subject, e.to_string()))?;
        let window =
            entry.clipper.prepare(&clip).map_err(|e| CliError::usage(format!("{}: {e}", args.clip.display())))?;
        let mut pieces = Vec::new();
        window.clip_batch(&segments, &mut pieces).map_err(|e| CliError::usage(e.to_string()))?;
        line_result(format, entry.clipper.name(), &clip, &segments, &pieces)
    } else {
        let entry = registry
            .find_polygon(&args.clipper)
            .ok_or_else(|| unknown_clipper(&args.clipper, &polygon_names(registry)))?;
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

fn polygon_names(registry: &Registry) -> Vec<&'static str> {
    registry.polygon.iter().map(|e| e.clipper.name()).collect()
}

fn unknown_line_clipper(given: &str, registry: &Registry) -> CliError {
    let valid: Vec<&str> = registry.line.iter().map(|e| e.clipper.name()).collect();
    CliError::usage(format!("'{given}' is not a registered line clipper (line clippers: {})", valid.join(", ")))
}
