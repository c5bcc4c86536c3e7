//! The markdown paragraph under each section naming the run behind it, read from the result's sidecar.

use std::path::Path;

use crate::cli_error::CliError;
use crate::measure::provenance::Provenance;

/// A result file's sidecar, and a markdown paragraph giving its provenance and notes.
pub fn provenance_line(meta: &Path) -> Result<(Provenance, String), CliError> {
    let p = Provenance::read(meta)?;
    let file = meta.file_name().map_or_else(String::new, |f| f.to_string_lossy().into_owned());
    let mut text = format!("Run: `clipbench {}`, {} (`{file}`).\n\n", p.command, p.summary());
    for note in &p.notes {
        text.push_str(&format!("- Note: {note}\n"));
    }
    Ok((p, text))
}
