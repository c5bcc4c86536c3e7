//! The report's Fig. 6-24 section: the pictures `reproduce lecture` drew, when present.

use super::derived::Derived;
use super::results_folder::ResultsFolder;
use crate::cli_error::CliError;
use crate::results_files::lecture_sh::FIGURES;

/// The section (it draws nothing: `reproduce lecture` drew the pictures), or `None` when the
/// pictures are not in the folder.
pub fn derive(folder: &ResultsFolder) -> Result<Option<Derived>, CliError> {
    if !FIGURES.iter().all(|(file, _)| folder.join(file).exists()) {
        return Ok(None);
    }
    let mut text = String::from(
        "*Computer Graphics, Lecture 17: Polygon Clipping*: a concave polygon whose part inside the window falls \
         into two pieces. Sutherland-Hodgman returns one vertex list and joins the pieces by a zero-width bridge \
         along the window; `sutherland-hodgman-split` (the notes' fix: the final list's vertices along each \
         window boundary rejoined in pairs) returns two rings and no bridge. Drawn by `clipbench reproduce \
         lecture`, which checks both bridge counts before drawing; `clipbench verify --clipper \
         sutherland-hodgman-split` checks the split mode on every workload.\n\n",
    );
    for (file, caption) in FIGURES {
        text.push_str(&format!("![{caption}]({file})\n\n"));
    }
    Ok(Some(Derived::new(text)))
}
