//! `clipbench text`: one string clipped to a window by one of the notes' strategies, drawn as SVG.

use std::path::{Path, PathBuf};

use clip_core::{Operand, Point, PolygonClipper, Polygons};
use clip_sutherland_hodgman::SutherlandHodgman;
use clip_text::{DEFAULT_TOLERANCE, OutlineFont, Strategy, Text, TextError, TextWindow, clip_text};
use clip_vatti::Vatti;

use crate::cli_error::CliError;
use crate::read::{parse_wkt, read_polygons, shapes_of};
use crate::text_svg::text_svg;
use crate::write::write_file;

/// Which strategy, by the names the notes' figures go by.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum TextStrategy {
    /// All-or-none string (Fig. 6-28), outline font.
    String,
    /// All-or-none character (Fig. 6-29), outline font.
    Char,
    /// Per-component (Fig. 6-30), outline glyphs clipped as polygons.
    Outline,
    /// Per-component on the 8x8 bitmap font, pixel by pixel (needs no --font).
    Bitmap,
}

/// Arguments of `clipbench text`.
#[derive(Debug, clap::Args)]
pub struct TextArgs {
    /// The string (one glyph per character, no kerning).
    pub string: String,
    /// Outline font file (TrueType/OpenType), for string, char and outline.
    #[arg(long)]
    pub font: Option<PathBuf>,
    /// Size in pixels per em (the bitmap font draws floor(size / 8) pixels per font pixel).
    #[arg(long, allow_negative_numbers = true)]
    pub size: f64,
    /// The window: WKT text (POLYGON or MULTIPOLYGON, y up), or a WKT/GeoJSON file.
    #[arg(long)]
    pub window: String,
    /// The strategy.
    #[arg(long, value_enum)]
    pub strategy: TextStrategy,
    /// Where the baseline starts, as X,Y.
    #[arg(long, default_value = "0,0", value_parser = parse_point, allow_hyphen_values = true)]
    pub at: Point,
    /// Flattening tolerance of the outline font's curves, in pixels.
    #[arg(long, default_value_t = DEFAULT_TOLERANCE)]
    pub tolerance: f64,
    /// Polygon clipper for outline glyphs the window cuts: vatti (any window) or
    /// sutherland-hodgman-split (convex windows).
    #[arg(long, default_value = "vatti")]
    pub clipper: String,
    /// The SVG picture to write.
    #[arg(short, long)]
    pub out: PathBuf,
}

fn parse_point(s: &str) -> Result<Point, String> {
    let (x, y) = s.split_once(',').ok_or("expected X,Y")?;
    let v = |t: &str| t.trim().parse::<f64>().map_err(|e| format!("{t:?}: {e}"));
    Ok(Point::new(v(x)?, v(y)?))
}

/// Runs the command: prints what was kept and writes the picture.
pub fn run(args: &TextArgs) -> Result<(), CliError> {
    if args.out.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() != Some("svg") {
        return Err(CliError::usage(format!("{}: the picture must be an .svg file", args.out.display())));
    }
    let window = read_window(&args.window)?;
    let clipper: &dyn PolygonClipper = match args.clipper.as_str() {
        "vatti" => &Vatti,
        "sutherland-hodgman-split" => &SutherlandHodgman::SPLIT,
        other => {
            return Err(CliError::usage(format!(
                "unknown outline clipper '{other}' (vatti, sutherland-hodgman-split)"
            )));
        }
    };
    let text = match args.strategy {
        TextStrategy::Bitmap => {
            if let Some(font) = &args.font {
                return Err(CliError::usage(format!(
                    "--font {}: the bitmap strategy draws with the built-in 8x8 font",
                    font.display()
                )));
            }
            Text::bitmap(&args.string, args.size, args.at).map_err(text_error)?
        }
        _ => {
            let path = args
                .font
                .as_ref()
                .ok_or_else(|| CliError::usage("--font FILE is needed for string, char and outline"))?;
            let font = OutlineFont::from_file(path).map_err(text_error)?;
            Text::outline(&font, &args.string, args.size, args.at, args.tolerance).map_err(text_error)?
        }
    };
    let strategy = match args.strategy {
        TextStrategy::String => Strategy::String,
        TextStrategy::Char => Strategy::Character,
        TextStrategy::Outline | TextStrategy::Bitmap => Strategy::Components,
    };
    let prepared = TextWindow::new(&window).map_err(text_error)?;
    let clipped = clip_text(&text, &prepared, strategy, clipper).map_err(text_error)?;
    let title = format!("{:?}, {} strategy", args.string, strategy);
    write_file(&args.out, &text_svg(&text, &window, &clipped, &title, 800.0))?;
    println!(
        "{} of {} glyphs kept whole; {} outline rings and {} pixels drawn; picture in {}",
        clipped.kept.len(),
        text.len(),
        clipped.polygons.rings.len(),
        clipped.pixels.len(),
        args.out.display()
    );
    Ok(())
}

/// The window from a file when a file of that name exists, else from the text as WKT.
fn read_window(arg: &str) -> Result<Polygons, CliError> {
    let window = if Path::new(arg).is_file() {
        read_polygons(Path::new(arg), Operand::Window)?
    } else {
        let shapes = parse_wkt(arg)
            .and_then(|parsed| shapes_of(&parsed.geometries))
            .map_err(|e| CliError::usage(format!("--window '{arg}': no such file, and not WKT: {e}")))?;
        if shapes.line_strings {
            return Err(CliError::usage(format!("--window '{arg}': expected a POLYGON or MULTIPOLYGON")));
        }
        shapes.polygons()
    };
    if window.rings.is_empty() {
        return Err(CliError::usage(format!(
            "--window '{arg}': the window is empty: it encloses no area to clip the text to"
        )));
    }
    Ok(window)
}

/// Bad input (font, string, size, window) is a usage error naming what is wrong; a clipper
/// refusing the window too.
fn text_error(e: TextError) -> CliError {
    CliError::usage(e.to_string())
}
