//! The files of `clipbench reproduce lecture`'s Sutherland-Hodgman part: Fig. 6-24 redrawn.

/// Fig. 6-24 redrawn: a concave polygon clipped by plain Sutherland-Hodgman (one list, the pieces
/// joined by a bridge along the window) and by `sutherland-hodgman-split` (two rings).
pub const FIGURES: [(&str, &str); 2] = [
    ("lecture-fig6-24-sh.svg", "Fig. 6-24: sutherland-hodgman, one output list with its bridge along the window"),
    ("lecture-fig6-24-split.svg", "Fig. 6-24 fixed: sutherland-hodgman-split, separate rings, no bridge"),
];
