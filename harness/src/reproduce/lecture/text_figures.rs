//! Figs. 6-28 to 6-30 redrawn: one string under each text strategy, each output checked by clip-text's oracle before it is drawn.

use std::path::Path;

use clip_core::{Point, Polygons, Rect};
use clip_text::oracle::check_clipped_text;
use clip_text::{DEFAULT_TOLERANCE, OutlineFont, Strategy, Text, TextWindow, clip_text};
use clip_vatti::Vatti;

use crate::cli_error::CliError;
use crate::results_files::lecture_text::FIGURES;
use crate::text_svg::text_svg;
use crate::write::write_file;

/// The string of the figures and where it sits: 48 px from (20, 30).
const STRING: &str = "Text Clipping";
const SIZE: f64 = 48.0;
const ORIGIN: Point = Point::new(20.0, 30.0);

/// The window: cuts the first and last letters and the descender of the 'p's.
fn window() -> Polygons {
    Polygons::from(Rect::new(40.0, 26.0, 300.0, 90.0))
}

/// Writes the four figures.
pub fn write(font: &OutlineFont, out: &Path) -> Result<(), CliError> {
    let fail = |e: String| CliError::failed(format!("lecture text figures: {e}"));
    let window = window();
    let prepared = TextWindow::new(&window).map_err(|e| fail(e.to_string()))?;
    let outline = Text::outline(font, STRING, SIZE, ORIGIN, DEFAULT_TOLERANCE).map_err(|e| fail(e.to_string()))?;
    let bitmap = Text::bitmap(STRING, SIZE / 2.0, ORIGIN).map_err(|e| fail(e.to_string()))?;
    let runs = [
        (&outline, Strategy::String),
        (&outline, Strategy::Character),
        (&outline, Strategy::Components),
        (&bitmap, Strategy::Components),
    ];
    for ((file, caption), (text, strategy)) in FIGURES.iter().zip(runs) {
        let clipped = clip_text(text, &prepared, strategy, &Vatti).map_err(|e| fail(e.to_string()))?;
        check_clipped_text(text, &prepared, strategy, &clipped).map_err(fail)?;
        write_file(&out.join(file), &text_svg(text, &window, &clipped, caption, 720.0))?;
    }
    Ok(())
}
