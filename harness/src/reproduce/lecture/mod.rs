//! `clipbench reproduce lecture`: the figures of *Computer Graphics, Lecture 17: Polygon
//! Clipping* redrawn from real runs, and measurements of its claims. One module per figure or
//! measurement, so each can be added without touching the others.

mod curve_bench;
mod curve_figure;

use std::path::Path;

use crate::cli_error::CliError;

pub use curve_bench::Settings;

/// Writes the lecture's figures and measures its claims into `out`.
pub fn measure(settings: &Settings, out: &Path) -> Result<(), CliError> {
    curve_figure::write(out)?;
    curve_bench::measure(settings, out)
}
