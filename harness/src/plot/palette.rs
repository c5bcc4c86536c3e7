//! The one colour table: a fixed colour per clipper, and per quantity for the papers' tables.

use plotters::style::RGBColor;

/// Every clipper's colour, so a clipper looks the same in every plot: every registered clipper,
/// the text strategies, and the external adapters of adapters/clippers.toml.
const CLIPPERS: [(&str, RGBColor); 41] = [
    ("vatti", RGBColor(31, 119, 180)),
    ("vatti-prepared", RGBColor(174, 199, 232)),
    ("vatti-scanbeam", RGBColor(23, 190, 207)),
    ("sutherland-hodgman", RGBColor(255, 127, 14)),
    ("sutherland-hodgman-split", RGBColor(255, 187, 120)),
    ("rect-four-state", RGBColor(44, 160, 44)),
    ("clipper2", RGBColor(214, 39, 40)),
    ("clipper2-rect", RGBColor(153, 0, 76)),
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
    ("text-string", RGBColor(0, 100, 0)),
    ("text-char", RGBColor(218, 165, 32)),
    ("text-outline-vatti", RGBColor(70, 130, 180)),
    ("text-outline-sh-split", RGBColor(210, 105, 30)),
    ("text-bitmap", RGBColor(112, 128, 144)),
    ("martinez", RGBColor(128, 0, 128)),
    ("polygon-clipping", RGBColor(0, 0, 205)),
    ("polyclip-ts", RGBColor(0, 191, 255)),
    ("polybooljs", RGBColor(154, 205, 50)),
    ("jsts", RGBColor(139, 69, 19)),
    ("clipper-lib", RGBColor(199, 199, 199)),
    ("jts-ng", RGBColor(85, 107, 47)),
    ("jts-ng-robust", RGBColor(189, 183, 107)),
    ("boost", RGBColor(220, 20, 60)),
    ("cgal", RGBColor(75, 0, 130)),
    ("pyclipper", RGBColor(255, 20, 147)),
    ("pyclipr", RGBColor(32, 178, 170)),
    ("shapely", RGBColor(205, 133, 63)),
];

/// Colours for clippers not in the table (picked by name hash), and for a plot to give a series
/// whose colour another series there already has (see [`distinct`]).
const SPARE: [RGBColor; 8] = [
    RGBColor(152, 223, 138),
    RGBColor(197, 176, 213),
    RGBColor(196, 156, 148),
    RGBColor(247, 182, 210),
    RGBColor(219, 219, 141),
    RGBColor(158, 218, 229),
    RGBColor(255, 215, 0),
    RGBColor(106, 90, 205),
];

/// The colour of a clipper's series.
pub fn clipper_colour(name: &str) -> RGBColor {
    CLIPPERS.iter().find(|(n, _)| *n == name).map_or_else(
        || SPARE[name.bytes().fold(0usize, |h, b| h.wrapping_mul(31).wrapping_add(usize::from(b))) % SPARE.len()],
        |(_, c)| *c,
    )
}

/// A paper's series beside ours: the same hue, halfway to white, so the pair reads as one
/// quantity and the two series still differ in colour.
pub fn paper_tint(c: RGBColor) -> RGBColor {
    let half = |v: u8| v + (255 - v) / 2;
    RGBColor(half(c.0), half(c.1), half(c.2))
}

/// `wanted` with every repeat replaced by the first colour no earlier entry has (the spares,
/// then the clipper table), so no two series of one plot share a colour.
pub fn distinct(wanted: &[RGBColor]) -> Vec<RGBColor> {
    let mut taken: Vec<RGBColor> = Vec::with_capacity(wanted.len());
    for &c in wanted {
        let free = |c: &RGBColor| !taken.contains(c) && !wanted.contains(c);
        let chosen = if taken.contains(&c) {
            SPARE.iter().chain(CLIPPERS.iter().map(|(_, c)| c)).copied().find(free).unwrap_or(c)
        } else {
            c
        };
        taken.push(chosen);
    }
    taken
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
        for (_, c) in &CLIPPERS {
            assert!(!SPARE.contains(c), "a spare is a clipper's colour");
        }
    }

    #[test]
    fn repeated_colours_are_replaced_by_unused_ones() {
        let red = clipper_colour("clipper2");
        let blue = clipper_colour("vatti");
        let got = distinct(&[red, blue, red, red]);
        assert_eq!(&got[..2], &[red, blue]);
        assert!(got[2] != got[3] && ![red, blue].contains(&got[2]) && ![red, blue].contains(&got[3]), "{got:?}");
        assert_ne!(paper_tint(blue), blue);
    }
}
