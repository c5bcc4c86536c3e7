//! The one colour table: a fixed colour per clipper, and per quantity for the papers' tables.

use plotters::style::RGBColor;

/// Every clipper's colour, so a clipper looks the same in every plot.
const CLIPPERS: [(&str, RGBColor); 19] = [
    ("vatti", RGBColor(31, 119, 180)),
    ("sutherland-hodgman", RGBColor(255, 127, 14)),
    ("rect-four-state", RGBColor(44, 160, 44)),
    ("clipper2", RGBColor(214, 39, 40)),
    ("geo", RGBColor(148, 103, 189)),
    ("liu", RGBColor(140, 86, 75)),
    ("virtual-box", RGBColor(227, 119, 194)),
    ("virtual-box-no45", RGBColor(127, 127, 127)),
    ("cyrus-beck", RGBColor(188, 189, 34)),
    ("indexed", RGBColor(128, 0, 0)),
    ("geos", RGBColor(0, 128, 128)),
    ("i_overlay", RGBColor(0, 0, 0)),
    ("clipper2-rust", RGBColor(255, 152, 150)),
    ("clipper1", RGBColor(140, 140, 60)),
    ("clipper2-open", RGBColor(255, 99, 71)),
    ("curve", RGBColor(31, 158, 137)),
    ("curve-no-tests", RGBColor(64, 64, 64)),
    ("curve-outline", RGBColor(102, 194, 165)),
    ("curve-no-tests-outline", RGBColor(170, 170, 170)),
];

/// Colours for clippers not in the table, in order of first request by name hash.
const SPARE: [RGBColor; 4] =
    [RGBColor(23, 190, 207), RGBColor(255, 187, 120), RGBColor(152, 223, 138), RGBColor(197, 176, 213)];

/// The colour of a clipper's series.
pub fn clipper_colour(name: &str) -> RGBColor {
    CLIPPERS.iter().find(|(n, _)| *n == name).map_or_else(
        || SPARE[name.bytes().fold(0usize, |h, b| h.wrapping_mul(31).wrapping_add(usize::from(b))) % SPARE.len()],
        |(_, c)| *c,
    )
}

/// Colours of the three improvement factors of Table 3: clip, fill, total.
pub const FACTORS: [RGBColor; 3] = [RGBColor(31, 119, 180), RGBColor(255, 127, 14), RGBColor(44, 160, 44)];

/// Colours of Table 4's two size rows.
pub const SIZE_ROWS: [RGBColor; 2] = [RGBColor(31, 119, 180), RGBColor(214, 39, 40)];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_named_clipper_has_its_own_colour() {
        for (i, (_, a)) in CLIPPERS.iter().enumerate() {
            for (_, b) in &CLIPPERS[i + 1..] {
                assert_ne!(a, b);
            }
        }
        assert_eq!(clipper_colour("vatti"), RGBColor(31, 119, 180));
        assert_eq!(clipper_colour("unknown-clipper"), clipper_colour("unknown-clipper"));
    }
}
