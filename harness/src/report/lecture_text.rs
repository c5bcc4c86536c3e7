//! The report's text-clipping section: ns per character per strategy as the window shrinks, a plot, and the figures.

use std::path::Path;

use crate::cli_error::CliError;
use crate::measure::raw::read_csv;
use crate::plot::chart::{Chart, Series};
use crate::plot::palette::clipper_colour;
use crate::report::markdown::{num, table};
use crate::report::provenance_line::provenance_line;
use crate::results_files::lecture_text::{CSV, FIGURES, MD, META, PLOT, TextTiming};

/// The rows in the order the notes give the strategies.
const ORDER: [&str; 5] = ["string", "char", "outline-vatti", "outline-sh-split", "bitmap"];

/// Recomputes the section from `out`'s CSV and writes its markdown and plot.
pub fn write(out: &Path) -> Result<(), CliError> {
    super::write_markdown(out, MD, section(out)?)
}

/// ns per character against window side, one line per strategy.
pub fn chart(rows: &[TextTiming]) -> Chart {
    let series = ORDER
        .iter()
        .map(|&s| {
            let mut points: Vec<(f64, f64)> =
                rows.iter().filter(|r| r.strategy == s).map(|r| (r.window_side, r.ns_per_char)).collect();
            points.sort_by(|a, b| a.0.total_cmp(&b.0));
            Series { label: s.to_owned(), colour: clipper_colour(s), points, paper: false }
        })
        .collect();
    Chart {
        title: "Text clipping: ns per character as a centred window shrinks over a paragraph".to_owned(),
        x_label: "window side / paragraph box side (above 1: the window holds it all)".to_owned(),
        y_label: "ns per character (median)".to_owned(),
        log_x: false,
        log_y: true,
        x_ticks: Vec::new(),
        series,
    }
}

/// The table: one row per window size, one column per strategy, and the glyphs cut.
pub fn markdown_table(rows: &[TextTiming]) -> String {
    let mut sides: Vec<f64> = rows.iter().map(|r| r.window_side).collect();
    sides.sort_by(|a, b| b.total_cmp(a));
    sides.dedup();
    let mut head = vec!["window side".to_owned(), "outline glyphs cut".to_owned()];
    head.extend(ORDER.iter().map(|s| format!("{s} (ns/char)")));
    let body: Vec<Vec<String>> = sides
        .iter()
        .map(|&side| {
            let at = |s: &str| rows.iter().find(|r| r.window_side == side && r.strategy == s);
            let mut line = vec![num(side, 2), at("outline-vatti").map_or("-".into(), |r| r.cut_glyphs.to_string())];
            line.extend(ORDER.iter().map(|s| at(s).map_or("-".into(), |r| num(r.ns_per_char, 0))));
            line
        })
        .collect();
    table(&head, &body)
}

/// A reading computed from the rows: how much more per-component clipping costs than the
/// all-or-none strategies, where the window cuts most.
pub fn reading(rows: &[TextTiming]) -> String {
    let at = |s: &str, side: f64| rows.iter().find(|r| r.strategy == s && r.window_side == side).map(|r| r.ns_per_char);
    let mut text = String::new();
    let mut sides: Vec<f64> = rows.iter().map(|r| r.window_side).collect();
    sides.sort_by(f64::total_cmp);
    sides.dedup();
    let cut_most = rows.iter().filter(|r| r.strategy == "outline-vatti").max_by_key(|r| r.cut_glyphs);
    if let Some(worst) = cut_most {
        let side = worst.window_side;
        if let (Some(s), Some(c), Some(v), Some(h), Some(b)) = (
            at("string", side),
            at("char", side),
            at("outline-vatti", side),
            at("outline-sh-split", side),
            at("bitmap", side),
        ) {
            text.push_str(&format!(
                "- Where the window cuts most outline glyphs ({} of {}, window side {}): all-or-none string {} ns per \
                 character, all-or-none character {} ns, per-component outlines {} ns with Vatti and {} ns with \
                 Sutherland-Hodgman split ({}x and {}x the character strategy), bitmap per pixel {} ns.\n",
                worst.cut_glyphs,
                worst.chars,
                num(side, 2),
                num(s, 0),
                num(c, 0),
                num(v, 0),
                num(h, 0),
                num(v / c, 1),
                num(h / c, 1),
                num(b, 0)
            ));
        }
    }
    if let (Some(&big), Some(&small)) = (sides.last(), sides.first()) {
        for s in ["string", "char", "outline-vatti"] {
            if let (Some(a), Some(b)) = (at(s, big), at(s, small)) {
                text.push_str(&format!(
                    "- {s}: {} ns per character with the window holding everything (side {}), {} ns at side {}.\n",
                    num(a, 0),
                    num(big, 2),
                    num(b, 0),
                    num(small, 2)
                ));
            }
        }
    }
    text
}

/// The section after writing its plot; `None` when `out` holds no text timings.
pub fn section(out: &Path) -> Result<Option<String>, CliError> {
    let csv = out.join(CSV);
    if !csv.exists() {
        return Ok(None);
    }
    let rows: Vec<TextTiming> = read_csv(&csv)?;
    chart(&rows).write_svg(&out.join(PLOT))?;
    let (_, provenance) = provenance_line(&out.join(META))?;
    let figures: String = FIGURES
        .iter()
        .filter(|(file, _)| out.join(file).exists())
        .map(|(file, caption)| format!("![{caption}]({file})\n\n"))
        .collect();
    Ok(Some(format!(
        "## Lecture notes: text clipping (Figs. 6-28 to 6-30)\n\n\
         *Computer Graphics, Lecture 17: Polygon Clipping*, \"Text Clipping\": all-or-none string (the string's box \
         against the window), all-or-none character (each glyph's box), and per-component clipping (outline \
         glyphs of DejaVu Sans, flattened within 0.05 px, clipped as polygons by Vatti or by \
         `sutherland-hodgman-split`; glyphs of the 8x8 bitmap font `font8x8` pixel by pixel). A paragraph of six \
         24 px lines is clipped to a centred rectangle whose sides shrink from beyond the paragraph's box to 15% \
         of it; each output is checked by clip-text's raster oracle before it is timed. Times are medians over \
         interleaved rounds, per character of the paragraph; they are this machine's, so compare them with each \
         other.\n\n{}\n![ns per character against window size]({PLOT})\n\n{}\n{figures}{provenance}",
        markdown_table(&rows),
        reading(&rows),
    )))
}
