//! `clipbench reproduce lecture`: the figures of *Computer Graphics, Lecture 17: Polygon
//! Clipping* redrawn from real runs, and measurements of its claims (curve clipping's preliminary
//! tests, what the text strategies cost). One module per figure or measurement, so each can be
//! added without touching the others.

mod curve_bench;
mod curve_figure;
mod sh_split_figure;
mod text_figures;
mod text_timing;

use std::path::Path;

use clip_text::{DEJAVU_SANS, OutlineFont};

use crate::cli_error::CliError;

/// How much the lecture's measurements run: the curve bench's settings, and the text timings'
/// interleaved rounds.
pub struct Settings {
    /// The curve bench.
    pub curves: curve_bench::Settings,
    /// Rounds of the text timings.
    pub text_rounds: usize,
}

impl Settings {
    /// Quick by default, `full` for the long runs; `repetitions` overrides both measurements'
    /// rounds.
    pub fn new(seed: u64, full: bool, repetitions: Option<usize>) -> Settings {
        Settings {
            curves: curve_bench::Settings::new(seed, full, repetitions),
            text_rounds: repetitions.unwrap_or(if full { 31 } else { 7 }),
        }
    }
}

/// Writes the lecture's figures and measures its claims into `out`.
pub fn measure(settings: &Settings, out: &Path) -> Result<(), CliError> {
    curve_figure::write(out)?;
    curve_bench::measure(&settings.curves, out)?;
    sh_split_figure::write(out)?;
    let font = OutlineFont::from_file(Path::new(DEJAVU_SANS)).map_err(|e| {
        CliError::failed(format!("the lecture's text figures need DejaVu Sans (Debian package fonts-dejavu-core): {e}"))
    })?;
    text_figures::write(&font, out)?;
    text_timing::measure(&font, settings.curves.seed, settings.text_rounds, out)
}
