//! The report's text-clipping section: ns per character per strategy as the window shrinks, a plot, and the figures.

use super::derived::Derived;
use super::results_folder::ResultsFolder;
use crate::cli_error::CliError;
use crate::measure::raw::{Measurement, read_csv};
use crate::measure::timing::median;
use crate::plot::chart::{Chart, Series};
use crate::plot::palette::clipper_colour;
use crate::report::markdown::{num, table};
use crate::report::provenance_line::provenance_line;
use crate::results_files::bench;
use crate::results_files::lecture_text::{CSV, FIGURES, META, TextTiming};
use crate::text_paragraph::row_of_bench_name;

/// The rows in the order the notes give the strategies.
const ORDER: [&str; 5] = ["string", "char", "outline-vatti", "outline-sh-split", "bitmap"];

/// The plot: ns per character against the window's side.
pub const PLOT: &str = "lecture-text.svg";

/// ns per character against window side, one line per strategy.
pub fn chart(rows: &[TextTiming]) -> Chart {
    let series = ORDER
        .iter()
        .map(|&s| {
            let mut points: Vec<(f64, f64)> =
                rows.iter().filter(|r| r.strategy == s).map(|r| (r.window_side, r.ns_per_char)).collect();
            points.sort_by(|a, b| a.0.total_cmp(&b.0));
            Series {
                label: s.to_owned(),
                colour: clipper_colour(&format!("text-{s}")),
                points,
                paper: false,
                spread: Vec::new(),
            }
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

/// The text timings from the bench's raw results (`bench.csv`'s `text` group): per row and
/// window side, the median over rounds of the time per paragraph divided by its characters, with
/// the glyphs cut from the bench's sidecar. `None` when the bench did not time text.
pub fn from_bench(rows: &[Measurement], parameters: &serde_json::Value) -> Option<Vec<TextTiming>> {
    let text: Vec<&Measurement> = rows.iter().filter(|r| r.workload == bench::TEXT_GROUP).collect();
    if text.is_empty() {
        return None;
    }
    let windows = parameters.get(bench::TEXT_GROUP).and_then(|t| t.get("windows")).and_then(|w| w.as_array());
    let cut = |side: f64, key: &str| {
        windows
            .into_iter()
            .flatten()
            .find(|w| w.get("window_side").and_then(serde_json::Value::as_f64) == Some(side))
            .and_then(|w| w.get(key)?.as_u64())
            .map_or(0, |n| n as usize)
    };
    let mut keys: Vec<(&str, &str)> = text.iter().map(|r| (r.clipper.as_str(), r.case.as_str())).collect();
    keys.sort_unstable();
    keys.dedup();
    let timings = keys
        .into_iter()
        .filter_map(|(clipper, case)| {
            let strategy = row_of_bench_name(clipper)?;
            let window_side: f64 = case.parse().ok()?;
            let of: Vec<&&Measurement> = text.iter().filter(|r| r.clipper == clipper && r.case == case).collect();
            let chars = of.first()?.size;
            let per_char: Vec<f64> = of.iter().map(|r| r.time_ns / chars.max(1) as f64).collect();
            let key = if strategy == "bitmap" { "bitmap_glyphs_cut" } else { "outline_glyphs_cut" };
            Some(TextTiming {
                strategy: strategy.to_owned(),
                window_side,
                chars,
                cut_glyphs: cut(window_side, key),
                ns_per_char: median(&per_char),
                rounds: of.len(),
            })
        })
        .collect();
    Some(timings)
}

/// The text timings and where they came from: the bench's raw results when it timed text, else
/// `reproduce lecture`'s; `None` when neither is in the folder.
fn timings(folder: &ResultsFolder) -> Result<Option<(Vec<TextTiming>, String, String)>, CliError> {
    if let Some(rows) = folder.bench_rows()? {
        let (provenance, line) = provenance_line(&folder.join(bench::META))?;
        if let Some(timings) = from_bench(rows, &provenance.parameters) {
            return Ok(Some((timings, format!("`{}`'s `text` group", bench::CSV), line)));
        }
    }
    let csv = folder.join(CSV);
    if !csv.exists() {
        return Ok(None);
    }
    let (_, line) = provenance_line(&folder.join(META))?;
    Ok(Some((read_csv(&csv)?, format!("`{CSV}` (`clipbench reproduce lecture`)"), line)))
}

/// The section and its plot; `None` when the folder holds no text timings.
pub fn derive(folder: &ResultsFolder) -> Result<Option<Derived>, CliError> {
    let Some((rows, source, provenance)) = timings(folder)? else { return Ok(None) };
    let figures: String = FIGURES
        .iter()
        .filter(|(file, _)| folder.join(file).exists())
        .map(|(file, caption)| format!("![{caption}]({file})\n\n"))
        .collect();
    let body = format!(
        "*Computer Graphics, Lecture 17: Polygon Clipping*, \"Text Clipping\": all-or-none string (the string's box \
         against the window), all-or-none character (each glyph's box), and per-component clipping (outline \
         glyphs of DejaVu Sans, flattened within 0.05 px, clipped as polygons by Vatti or by \
         `sutherland-hodgman-split`; glyphs of the 8x8 bitmap font `font8x8` pixel by pixel). A paragraph of six \
         24 px lines is clipped to a centred rectangle whose sides shrink from beyond the paragraph's box to 15% \
         of it; each output is checked by clip-text's raster oracle before it is timed. Times are medians over \
         interleaved rounds, per character of the paragraph, from {source}; they are this machine's, so compare \
         them with each other.\n\n{}\n![ns per character against window size]({PLOT})\n\n{}\n{figures}{provenance}",
        markdown_table(&rows),
        reading(&rows),
    );
    Ok(Some(Derived::new(body).with_plot(PLOT, chart(&rows))))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m(clipper: &str, case: &str, rep: usize, ns: f64) -> Measurement {
        Measurement {
            workload: bench::TEXT_GROUP.into(),
            case: case.into(),
            clipper: clipper.into(),
            phase: "clip".into(),
            size: 100,
            op: "intersection".into(),
            fill_rule: "even-odd".into(),
            repetition: rep,
            iterations: 1,
            time_ns: ns,
            correct: None,
        }
    }

    #[test]
    fn bench_rows_become_medians_per_character_with_the_glyphs_cut() {
        let mut rows = vec![
            m("text-char", "0.45", 0, 1000.0),
            m("text-char", "0.45", 1, 3000.0),
            m("text-char", "0.45", 2, 2000.0),
            m("text-bitmap", "0.45", 0, 50_000.0),
            m("text-unknown", "0.45", 0, 1.0),
        ];
        rows.push(Measurement { workload: "star".into(), ..m("vatti", "0", 0, 5.0) });
        let parameters = serde_json::json!({ "text": { "windows": [
            { "window_side": 0.45, "outline_glyphs_cut": 31, "bitmap_glyphs_cut": 29 }
        ]}});
        let mut got = from_bench(&rows, &parameters).unwrap();
        got.sort_by(|a, b| a.strategy.cmp(&b.strategy));
        assert_eq!(got.len(), 2);
        assert_eq!((got[0].strategy.as_str(), got[0].cut_glyphs, got[0].ns_per_char), ("bitmap", 29, 500.0));
        assert_eq!((got[1].strategy.as_str(), got[1].cut_glyphs, got[1].rounds), ("char", 31, 3));
        assert_eq!(got[1].ns_per_char, 20.0);
        assert_eq!(got[1].window_side, 0.45);
        assert!(from_bench(&rows[5..], &parameters).is_none());
    }
}
