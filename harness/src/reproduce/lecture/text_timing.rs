//! What the notes' text strategies cost: ns per character for each, as a centred window shrinks over a paragraph from holding all of it to a small part.

use std::path::Path;
use std::time::Duration;

use clip_core::{Point, PolygonClipper, Polygons, Rect};
use clip_sutherland_hodgman::SutherlandHodgman;
use clip_text::oracle::check_clipped_text;
use clip_text::{DEFAULT_TOLERANCE, OutlineFont, Strategy, Text, TextWindow, clip_text};
use clip_vatti::Vatti;

use crate::cli_error::CliError;
use crate::measure::provenance::Provenance;
use crate::measure::raw::write_csv;
use crate::measure::timing::{iterations_for, median, per_call_ns, timed};
use crate::results_files::lecture_text::{CSV, META, TextTiming};

/// The paragraph: six lines at 24 px, 30 px apart.
const LINES: [&str; 6] = [
    "There are several techniques that can be used",
    "to provide text clipping in a graphics package.",
    "The simplest method is all-or-none string",
    "clipping; an alternative is all-or-none",
    "character clipping; a final method clips the",
    "components of individual characters (6-30).",
];
const SIZE: f64 = 24.0;
const LEADING: f64 = 30.0;

/// The window sides as fractions of the paragraph box's, largest first: 1.05 holds it all.
pub const WINDOW_SIDES: [f64; 7] = [1.05, 0.9, 0.75, 0.6, 0.45, 0.3, 0.15];

/// The rows timed: a strategy on a font with a clipper.
const ROWS: [&str; 5] = ["string", "char", "outline-vatti", "outline-sh-split", "bitmap"];

/// One paragraph, laid out once per font.
struct Paragraph {
    outline: Vec<Text>,
    bitmap: Vec<Text>,
    bounds: Rect,
}

fn paragraph(font: &OutlineFont) -> Result<Paragraph, CliError> {
    let fail = |e: clip_text::TextError| CliError::failed(format!("lecture text timing: {e}"));
    let origin = |k: usize| Point::new(20.0, 20.0 + LEADING * (LINES.len() - k) as f64);
    let outline: Vec<Text> = LINES
        .iter()
        .enumerate()
        .map(|(k, l)| Text::outline(font, l, SIZE, origin(k), DEFAULT_TOLERANCE))
        .collect::<Result<_, _>>()
        .map_err(fail)?;
    let bitmap: Vec<Text> = LINES
        .iter()
        .enumerate()
        .map(|(k, l)| Text::bitmap(l, SIZE, origin(k)))
        .collect::<Result<_, _>>()
        .map_err(fail)?;
    let bounds = outline.iter().chain(&bitmap).fold(Rect::EMPTY, |b, t| b.union(t.bounds));
    Ok(Paragraph { outline, bitmap, bounds })
}

/// The centred window with sides `side` times the paragraph box's.
fn window(p: &Paragraph, side: f64) -> Polygons {
    let (c, hw, hh) = (
        Point::new(0.5 * (p.bounds.min.x + p.bounds.max.x), 0.5 * (p.bounds.min.y + p.bounds.max.y)),
        0.5 * side * p.bounds.width(),
        0.5 * side * p.bounds.height(),
    );
    Polygons::from(Rect::new(c.x - hw, c.y - hh, c.x + hw, c.y + hh))
}

/// The lines, strategy and outline clipper of a row.
fn pick<'a>(row: &str, p: &'a Paragraph) -> (&'a [Text], Strategy, &'static dyn PolygonClipper) {
    match row {
        "string" => (&p.outline, Strategy::String, &Vatti),
        "char" => (&p.outline, Strategy::Character, &Vatti),
        "outline-vatti" => (&p.outline, Strategy::Components, &Vatti),
        "outline-sh-split" => (&p.outline, Strategy::Components, &SutherlandHodgman::SPLIT),
        _ => (&p.bitmap, Strategy::Components, &Vatti),
    }
}

/// Clips every line of the paragraph with `row`'s strategy.
fn run(row: &str, p: &Paragraph, window: &TextWindow) -> Result<usize, clip_text::TextError> {
    let (texts, strategy, clipper) = pick(row, p);
    let mut drawn = 0;
    for t in texts {
        let c = clip_text(t, window, strategy, clipper)?;
        drawn += c.polygons.rings.len() + c.pixels.len();
    }
    Ok(drawn)
}

/// Measures every row at every window size in interleaved rounds (each output checked by the
/// oracle first), and writes the CSV and its sidecar.
pub fn measure(font: &OutlineFont, seed: u64, rounds: usize, out: &Path) -> Result<(), CliError> {
    let p = paragraph(font)?;
    let chars: usize = LINES.iter().map(|l| l.chars().count()).sum();
    let fail = |e: String| CliError::failed(format!("lecture text timing: {e}"));
    let mut rows = Vec::new();
    for side in WINDOW_SIDES {
        let polygons = window(&p, side);
        let w = TextWindow::new(&polygons).map_err(|e| fail(e.to_string()))?;
        // Checked before timed: the oracle on every line for every row.
        for row in ROWS {
            let (texts, strategy, clipper) = pick(row, &p);
            for t in texts {
                let c = clip_text(t, &w, strategy, clipper).map_err(|e| fail(e.to_string()))?;
                check_clipped_text(t, &w, strategy, &c)
                    .map_err(|e| fail(format!("{row} at window side {side}: {e}")))?;
            }
        }
        let cut = |texts: &[Text]| {
            texts
                .iter()
                .flat_map(|t| &t.glyphs)
                .filter(|g| !g.bounds.is_empty() && g.bounds.intersects(&w.bounds()) && !w.contains_box(g.bounds))
                .count()
        };
        // Interleaved rounds: every row once per round, so drift hits them alike.
        let mut samples: Vec<Vec<f64>> = vec![Vec::new(); ROWS.len()];
        for _ in 0..rounds {
            for (k, row) in ROWS.iter().enumerate() {
                let (_, single) = timed(|| run(row, &p, &w));
                let n = iterations_for(single, Duration::from_millis(20));
                samples[k].push(per_call_ns(n, || run(row, &p, &w)) / chars as f64);
            }
        }
        for (k, row) in ROWS.iter().enumerate() {
            rows.push(TextTiming {
                strategy: (*row).to_owned(),
                window_side: side,
                chars,
                cut_glyphs: if *row == "bitmap" { cut(&p.bitmap) } else { cut(&p.outline) },
                ns_per_char: median(&samples[k]),
                rounds,
            });
        }
    }
    write_csv(&out.join(CSV), &rows)?;
    let parameters = serde_json::json!({
        "rounds": rounds,
        "chars": chars,
        "size_px": SIZE,
        "window_sides": WINDOW_SIDES,
        "flatten_tolerance_px": DEFAULT_TOLERANCE,
    });
    let mut provenance = Provenance::now("reproduce lecture", seed, parameters);
    provenance.notes.push(
        "The paragraph (six lines of the notes' own text) and the windows are fixed; the seed is not used by the text part."
            .into(),
    );
    provenance.write(&out.join(META))
}
