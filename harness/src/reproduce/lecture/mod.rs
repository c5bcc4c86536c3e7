//! `clipbench reproduce lecture`: the lecture notes' figures redrawn from real runs, and what the text strategies cost. One module per figure group.

mod sh_split_figure;
mod text_figures;
mod text_timing;

use std::path::Path;

use clip_text::{DEJAVU_SANS, OutlineFont};

use crate::cli_error::CliError;

/// How many interleaved rounds the text timings take (quick, --full).
pub fn rounds(full: bool, repetitions: Option<usize>) -> usize {
    repetitions.unwrap_or(if full { 31 } else { 7 })
}

/// Draws the figures and measures the text strategies into `out`.
pub fn measure(seed: u64, rounds: usize, out: &Path) -> Result<(), CliError> {
    sh_split_figure::write(out)?;
    let font = OutlineFont::from_file(Path::new(DEJAVU_SANS)).map_err(|e| {
        CliError::failed(format!("the lecture's text figures need DejaVu Sans (Debian package fonts-dejavu-core): {e}"))
    })?;
    text_figures::write(&font, out)?;
    text_timing::measure(&font, seed, rounds, out)
}
