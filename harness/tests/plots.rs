//! The plots a run writes: every series of one plot in its own colour (the legend's swatches,
//! one per series, are the lines drawn 3 px wide).

use std::path::{Path, PathBuf};
use std::process::Command;

/// The colours of the legend swatches of one SVG, in order.
fn swatch_colours(svg: &str) -> Vec<String> {
    svg.split("<polyline")
        .skip(1)
        .filter_map(|element| {
            let element = &element[..element.find('>').unwrap_or(element.len())];
            element.contains("stroke-width=\"3\"").then(|| {
                let stroke = element.split("stroke=\"").nth(1).unwrap_or("");
                stroke[..stroke.find('"').unwrap_or(0)].to_owned()
            })
        })
        .collect()
}

#[test]
fn no_two_series_of_a_plot_share_a_colour() {
    let out: PathBuf = Path::new(env!("CARGO_TARGET_TMPDIR")).join("plots");
    let _ = std::fs::remove_dir_all(&out);
    // Every clipper that takes a rectangle window, and the five text strategies.
    let o = Command::new(env!("CARGO_BIN_EXE_clipbench"))
        .args(["bench", "--quick", "--workload", "star-rect", "--workload", "text", "--rounds", "1", "--out"])
        .arg(&out)
        .output()
        .expect("the clipbench binary runs");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut plots = 0;
    for entry in std::fs::read_dir(&out).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "svg") {
            continue;
        }
        let colours = swatch_colours(&std::fs::read_to_string(&path).unwrap());
        assert!(colours.len() >= 5, "{}: {colours:?}", path.display());
        for (i, c) in colours.iter().enumerate() {
            assert!(!colours[..i].contains(c), "{}: two series in {c}: {colours:?}", path.display());
        }
        plots += 1;
    }
    // bench-star-rect.svg and lecture-text.svg.
    assert_eq!(plots, 2);
}
