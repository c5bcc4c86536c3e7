//! The report's Fig. 6-24 section: the pictures `reproduce lecture` drew, when present.

use std::path::Path;

use crate::results_files::lecture_sh::FIGURES;

/// The section, or `None` when the pictures are not in `out`.
pub fn section(out: &Path) -> Option<String> {
    if !FIGURES.iter().all(|(file, _)| out.join(file).exists()) {
        return None;
    }
    let mut text = String::from(
        "## Lecture notes: Sutherland-Hodgman on a concave polygon (Fig. 6-24)\n\n\
         *Computer Graphics, Lecture 17: Polygon Clipping*: a concave polygon whose part inside the window falls \
         into two pieces. Sutherland-Hodgman returns one vertex list and joins the pieces by a zero-width bridge \
         along the window; `sutherland-hodgman-split` (the notes' fix: the final list's vertices along each \
         window boundary rejoined in pairs) returns two rings and no bridge. Drawn by `clipbench reproduce \
         lecture`, which checks both bridge counts before drawing; `clipbench verify --clipper \
         sutherland-hodgman-split` checks the split mode on every workload.\n\n",
    );
    for (file, caption) in FIGURES {
        text.push_str(&format!("![{caption}]({file})\n\n"));
    }
    Some(text)
}
