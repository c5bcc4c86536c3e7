//! The beyond-the-paper table from its raw CSVs: ns per segment against window edges for every
//! line clipper, preparation time and memory, the crossover where indexing pays, a log-log plot,
//! and the 10^6-segment point.

use super::derived::{Derived, DerivedFile};
use super::markdown::{duration_ns, header, num, table};
use super::provenance_line::provenance_line;
use super::results_folder::ResultsFolder;
use crate::cli_error::CliError;
use crate::measure::raw::{Measurement, read_csv};
use crate::measure::timing::median;
use crate::plot::chart::{Chart, Series};
use crate::plot::palette::clipper_colour;
use crate::results_files::beyond_paper::{CSV, LARGE_CSV, LargeRecord, META, PREPARE_CSV, PrepareRecord};
use std::collections::BTreeMap;

/// The plots: long segments, then short ones.
pub const PLOTS: [(&str, &str); 2] = [("long", "beyond-paper-long.svg"), ("short", "beyond-paper-short.svg")];

/// The clippers, in column order, with their column titles.
const COLUMNS: [(&str, &str); 7] = [
    ("liu", "Liu"),
    ("virtual-box-no45", "New1"),
    ("virtual-box", "New2"),
    ("indexed", "indexed"),
    ("cyrus-beck", "cyrus-beck"),
    ("geo", "geo"),
    ("clipper2-open", "Clipper2 open"),
];
/// Column of the indexed clipper, and of the linear clippers it is compared with.
const INDEXED: usize = 3;
const LINEAR: [usize; 4] = [0, 1, 2, 4];

/// One window and segment set: the median ns per segment of each of [`COLUMNS`] (NaN where a
/// clipper does not run).
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// `concave` or `convex`.
    pub shape: String,
    /// `long` or `short`.
    pub set: String,
    /// Window edges.
    pub edges: usize,
    /// Median ns per segment per column.
    pub ns: [f64; 7],
}

impl Row {
    /// The fastest linear clipper's ns per segment (Liu, New1, New2, and Cyrus-Beck on convex windows).
    pub fn best_linear(&self) -> f64 {
        LINEAR.iter().map(|&i| self.ns[i]).filter(|v| !v.is_nan()).fold(f64::INFINITY, f64::min)
    }
}

/// Computes the rows from the raw timings, ordered by shape, set and edges.
pub fn rows(measurements: &[Measurement]) -> Vec<Row> {
    let mut times: BTreeMap<(String, usize, String), Vec<f64>> = BTreeMap::new();
    for m in measurements {
        times.entry((m.case.clone(), m.size, m.clipper.clone())).or_default().push(m.time_ns);
    }
    let mut keys: Vec<(String, usize)> = times.keys().map(|(c, e, _)| (c.clone(), *e)).collect();
    keys.dedup();
    keys.into_iter()
        .map(|(case, edges)| {
            let (shape, set) = case.split_once('-').unwrap_or((case.as_str(), ""));
            let ns =
                COLUMNS.map(|(c, _)| times.get(&(case.clone(), edges, c.to_owned())).map_or(f64::NAN, |v| median(v)));
            Row { shape: shape.to_owned(), set: set.to_owned(), edges, ns }
        })
        .collect()
}

/// The smallest edge count from which the indexed clipper beats every linear clipper at that size
/// and at every larger one measured, for one shape and set.
pub fn crossover(rows: &[Row], shape: &str, set: &str) -> Option<usize> {
    let mut these: Vec<&Row> = rows.iter().filter(|r| r.shape == shape && r.set == set).collect();
    these.sort_by_key(|r| r.edges);
    let mut from = None;
    for r in these.iter().rev() {
        if r.ns[INDEXED] < r.best_linear() {
            from = Some(r.edges);
        } else {
            break;
        }
    }
    from
}

/// The ns-per-segment table of one segment set, both shapes.
pub fn markdown_table(rows: &[Row], set: &str) -> String {
    let head = header(&[
        "Window",
        "Edges",
        "Liu",
        "New1",
        "New2",
        "indexed",
        "cyrus-beck",
        "geo",
        "Clipper2 open",
        "indexed / Liu",
        "indexed / best linear",
    ]);
    let body = rows
        .iter()
        .filter(|r| r.set == set)
        .map(|r| {
            let mut cells = vec![r.shape.clone(), r.edges.to_string()];
            cells.extend(r.ns.iter().enumerate().map(|(i, v)| {
                let s = num(*v, 1);
                if i == INDEXED { format!("**{s}**") } else { s }
            }));
            cells.push(num(r.ns[INDEXED] / r.ns[0], 3));
            cells.push(num(r.ns[INDEXED] / r.best_linear(), 2));
            cells
        })
        .collect::<Vec<_>>();
    table(&head, &body)
}

/// Preparation time per clipper against edges (concave windows; Cyrus-Beck on convex ones), and
/// the indexed clipper's memory.
pub fn prepare_table(records: &[PrepareRecord]) -> String {
    let mut edges: Vec<usize> = records.iter().map(|r| r.edges).collect();
    edges.sort_unstable();
    edges.dedup();
    let find =
        |shape: &str, e: usize, c: &str| records.iter().find(|r| r.shape == shape && r.edges == e && r.clipper == c);
    let head = header(&[
        "Edges",
        "Liu",
        "New1",
        "New2",
        "indexed",
        "cyrus-beck (convex)",
        "geo",
        "Clipper2 open",
        "indexed memory (KiB)",
    ]);
    let body = edges
        .iter()
        .map(|&e| {
            let mut cells = vec![e.to_string()];
            for (c, _) in COLUMNS {
                let shape = if c == "cyrus-beck" { "convex" } else { "concave" };
                cells.push(find(shape, e, c).map_or("n/a".to_owned(), |r| duration_ns(r.prepare_ns)));
            }
            let memory = find("concave", e, "indexed").and_then(|r| r.memory_bytes);
            cells.push(memory.map_or("n/a".to_owned(), |m| num(m as f64 / 1024.0, 1)));
            cells
        })
        .collect::<Vec<_>>();
    table(&head, &body)
}

/// The many-segments point: median seconds per configuration and the ratio to Liu.
pub fn large_table(records: &[LargeRecord]) -> (String, Option<(f64, f64)>) {
    let mut groups: BTreeMap<(String, usize), Vec<f64>> = BTreeMap::new();
    let mut cpu: BTreeMap<(String, usize), Vec<f64>> = BTreeMap::new();
    for r in records {
        groups.entry((r.clipper.clone(), r.threads)).or_default().push(r.seconds);
        if let Some(c) = r.cpu_seconds {
            cpu.entry((r.clipper.clone(), r.threads)).or_default().push(c);
        }
    }
    let liu = groups.iter().find(|((c, _), _)| c == "liu").map(|(_, v)| median(v));
    let Some(first) = records.first() else { return (String::new(), None) };
    let head = header(&[
        "Clipper",
        "Threads",
        "Rounds",
        "Seconds (median)",
        "CPU seconds, all threads (median)",
        "Segments per second",
        "Liu / this",
    ]);
    let body = groups
        .iter()
        .map(|((c, t), v)| {
            let s = median(v);
            vec![
                c.clone(),
                t.to_string(),
                v.len().to_string(),
                format!("**{}**", num(s, 3)),
                cpu.get(&(c.clone(), *t)).map_or("n/a".to_owned(), |v| num(median(v), 3)),
                format!("{:.2e}", first.segments as f64 / s),
                liu.map_or("n/a".to_owned(), |l| num(l / s, 1)),
            ]
        })
        .collect::<Vec<_>>();
    let best_indexed =
        groups.iter().filter(|((c, _), _)| c == "indexed").map(|(_, v)| median(v)).fold(f64::INFINITY, f64::min);
    let intro = format!(
        "{} segments against `lines-large` case 3 ({} edges in {} rings: a lobed outer ring with lobed holes), long, \
         short and exactly incident segments mixed (`clip_testkit::workload::lines_large_segments`); several threads \
         means rayon over chunks of 16384 segments, pieces concatenated in chunk order \
         (`harness/src/measure/parallel.rs`). The wall clock counts the time other jobs on this shared machine \
         held the cores; the CPU seconds are what this process's threads ran (`/proc/self/task/*/schedstat`).\n\n",
        first.segments, first.edges, first.rings
    );
    (intro + &table(&head, &body), liu.map(|l| (best_indexed, l)))
}

/// ns per segment against edges on the concave windows (Cyrus-Beck on the convex ones), log-log;
/// the title names the shapes its series were timed on.
pub fn chart(rows: &[Row], set: &str) -> Chart {
    let series = COLUMNS
        .iter()
        .enumerate()
        .filter_map(|(i, (c, title))| {
            let shape = if *c == "cyrus-beck" { "convex" } else { "concave" };
            let points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.set == set && r.shape == shape && !r.ns[i].is_nan())
                .map(|r| (r.edges as f64, r.ns[i]))
                .collect();
            (!points.is_empty()).then(|| Series {
                label: if shape == "convex" { format!("{title} (convex windows)") } else { (*title).to_owned() },
                colour: clipper_colour(c),
                points,
                paper: false,
                spread: Vec::new(),
            })
        })
        .collect::<Vec<Series>>();
    // The title names every window shape the series were timed on.
    let convex = series.iter().any(|s| s.label.ends_with("(convex windows)"));
    let concave = series.iter().any(|s| !s.label.ends_with("(convex windows)"));
    let windows = match (concave, convex) {
        (true, true) => "lobed concave windows (Cyrus-Beck: convex windows of the same size)",
        (false, true) => "convex windows",
        _ => "lobed concave windows",
    };
    Chart {
        title: format!("Line clipping beyond Table 4: ns per {set} segment against window edges, {windows}"),
        x_label: "window edges".to_owned(),
        y_label: "time per segment (ns)".to_owned(),
        log_x: true,
        log_y: true,
        x_ticks: ticks(rows),
        series,
    }
}

/// The measured edge counts, for the log axis.
fn ticks(rows: &[Row]) -> Vec<f64> {
    let mut e: Vec<usize> = rows.iter().map(|r| r.edges).collect();
    e.sort_unstable();
    e.dedup();
    e.into_iter().map(|v| v as f64).collect()
}

/// A short reading, every statement computed from the rows.
pub fn reading(rows: &[Row], large: Option<(f64, f64)>) -> String {
    let mut text = String::new();
    let at = |shape: &str, set: &str, edges: usize| {
        rows.iter().find(|r| r.shape == shape && r.set == set && r.edges == edges)
    };
    for shape in ["concave", "convex"] {
        for set in ["long", "short"] {
            let cross = crossover(rows, shape, set);
            text.push_str(&format!(
                "- {shape} windows, {set} segments: indexing pays {}.",
                cross.map_or("at no measured size".to_owned(), |e| format!(
                    "from {e} edges on (faster than every linear clipper there and at every larger size)"
                ))
            ));
            if let (Some(small), Some(big)) = (at(shape, set, 50), at(shape, set, 10_000)) {
                text.push_str(&format!(
                    " At 10^4 edges the indexed clipper takes {} ns per segment, {}x its own time at 50 edges and 1/{} of Liu's.",
                    num(big.ns[INDEXED], 1),
                    num(big.ns[INDEXED] / small.ns[INDEXED], 2),
                    num(big.ns[0] / big.ns[INDEXED], 0)
                ));
            }
            text.push('\n');
        }
    }
    if let Some((indexed, liu)) = large {
        text.push_str(&format!(
            "- 10^6 segments against the 10^4-edge window with holes: {} s with the indexed clipper, {} s with Liu on the \
             same cores ({}x).\n",
            num(indexed, 3),
            num(liu, 2),
            num(liu / indexed, 0)
        ));
    }
    text
}

/// The section and its plots; `None` when the folder holds no such results.
pub fn derive(folder: &ResultsFolder) -> Result<Option<Derived>, CliError> {
    let csv = folder.join(CSV);
    if !csv.exists() {
        return Ok(None);
    }
    let measurements: Vec<Measurement> = read_csv(&csv)?;
    let prepare: Vec<PrepareRecord> = read_csv(&folder.join(PREPARE_CSV))?;
    let large: Vec<LargeRecord> = read_csv(&folder.join(LARGE_CSV))?;
    let rows = rows(&measurements);
    let (provenance, notes) = provenance_line(&folder.join(META))?;
    let param = |k: &str| provenance.parameters.get(k).and_then(serde_json::Value::as_u64).unwrap_or(0);
    let (large_md, large_times) = large_table(&large);
    let body = format!(
        "Wang et al.'s Table 4 stops at 50 edges, where every clipper above is linear in the window's size. Here the \
         windows grow to 10^4 edges: lobed concave windows (a flower of 7 petals sampled at n vertices, so a line \
         crosses one a bounded number of times whatever n is) and convex ones, their bounding box sized like Table 4's \
         second size row (W1 = 4, W2 = 80) and centred on the 800 x 600 screen. Two batches of {} segments per window: \
         **long** ones as in `wang-t4` (ends uniform on the screen, so most miss the window's box) and **short** ones \
         as in road data (at most 2% of the window's width, midpoints uniform in its bounding box). Times are medians \
         over {} interleaved rounds (geo and Clipper2 open: {} rounds on {} segments), in **ns per segment**. `indexed` \
         is `clip-line-index` (a box tree over runs of 16 edges, walked over the boxes the segment, or its ray, \
         meets); Cyrus-Beck runs on the convex windows only. **Clipper2 open** is Clipper2's general engine clipping \
         open paths (`AddOpenSubject` against the window's rings, even-odd, through `clipper2c-sys`'s C API; the \
         `clipper2` 0.6 crate drops open output), one `Execute` per segment like geo's one call per segment; a peer \
         on an integer grid with its own boundary rules, not exact.\n\n\
         ### Long segments (as in wang-t4)\n\n{}\n![ns per segment against edges, long segments]({})\n\n\
         ### Short segments (at most 2% of the window's width)\n\n{}\n![ns per segment against edges, short segments]({})\n\n{}\n\
         ### Preparation (once per window) and the indexed clipper's memory\n\n{}\n\
         ### 10^6 segments against a 10^4-edge window with holes\n\n{}\n{}",
        param("segments_per_batch"),
        param("repetitions"),
        param("geo_repetitions"),
        param("geo_segments"),
        markdown_table(&rows, "long"),
        PLOTS[0].1,
        markdown_table(&rows, "short"),
        PLOTS[1].1,
        reading(&rows, large_times),
        prepare_table(&prepare),
        large_md,
        notes
    );
    let plots = PLOTS.iter().map(|&(set, file)| (file.to_owned(), DerivedFile::Plot(chart(&rows, set))));
    Ok(Some(Derived { body, files: plots.collect() }))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m(case: &str, clipper: &str, edges: usize, ns: f64) -> Measurement {
        Measurement {
            workload: "beyond-paper".into(),
            case: case.into(),
            clipper: clipper.into(),
            phase: "clip".into(),
            size: edges,
            op: "lines".into(),
            fill_rule: "even-odd".into(),
            repetition: 0,
            iterations: 100,
            time_ns: ns,
            correct: None,
        }
    }

    #[test]
    fn crossover_is_where_indexing_stays_ahead() {
        let mut raw = Vec::new();
        for (edges, liu, new2, indexed) in [
            (6, 10.0, 9.0, 12.0),
            (50, 40.0, 30.0, 25.0),
            (100, 60.0, 50.0, 70.0),
            (1000, 600.0, 400.0, 40.0),
            (10_000, 6000.0, 4000.0, 50.0),
        ] {
            raw.push(m("concave-long", "liu", edges, liu));
            raw.push(m("concave-long", "virtual-box", edges, new2));
            raw.push(m("concave-long", "indexed", edges, indexed));
        }
        let rows = rows(&raw);
        assert_eq!(rows.len(), 5);
        assert_eq!(rows[0].set, "long");
        // Ahead at 50 edges, behind at 100, ahead from 1000 on.
        assert_eq!(crossover(&rows, "concave", "long"), Some(1000));
        assert_eq!(crossover(&rows, "convex", "long"), None);
        let text = reading(&rows, Some((0.5, 20.0)));
        assert!(chart(&rows, "long").title.ends_with(", lobed concave windows"), "{}", chart(&rows, "long").title);
        assert!(text.contains("from 1000 edges on"), "{text}");
        assert!(text.contains("1/120 of Liu's"), "{text}");
        assert!(text.contains("40x"), "{text}");
    }

    #[test]
    fn the_title_names_the_convex_windows_cyrus_beck_ran_on() {
        let raw = vec![
            m("concave-long", "liu", 50, 40.0),
            m("convex-long", "cyrus-beck", 50, 20.0),
            m("convex-long", "liu", 50, 30.0),
        ];
        let rows = rows(&raw);
        let chart = chart(&rows, "long");
        assert!(
            chart.title.contains("concave") && chart.title.contains("Cyrus-Beck: convex windows"),
            "{}",
            chart.title
        );
        assert!(chart.series.iter().any(|s| s.label.ends_with("(convex windows)")));
        let only_convex = chart_of(&[m("convex-long", "cyrus-beck", 50, 20.0)]);
        assert!(only_convex.ends_with(", convex windows"), "{only_convex}");
    }

    fn chart_of(raw: &[Measurement]) -> String {
        chart(&rows(raw), "long").title
    }
}
