//! Wang et al.'s Table 4 from its raw CSV: per window, each line clipper's time per batch, the
//! gain of New2 over Liu beside the paper's, the rejection stages' shares, a plot and a reading.

use super::derived::Derived;
use super::markdown::{header, num, num_interval, table};
use super::provenance_line::provenance_line;
use super::results_folder::ResultsFolder;
use super::wording::{self, Sides};
use crate::cli_error::CliError;
use crate::measure::interval::{CaseSamples, Interval, bootstrap, mean_ratio, seed_of};
use crate::measure::raw::{Measurement, read_csv};
use crate::measure::timing::median;
use crate::papers::{WANG_TABLE4, wang_row};
use crate::plot::chart::{Chart, Series};
use crate::plot::palette::SIZE_ROWS;
use crate::results_files::wang_table4::{
    CSV, META, STAGE_TIMES_CSV, STAGES_CSV, StageRecord, StageTimeRecord, WINDOWS_CSV, WindowRecord,
};
use std::collections::BTreeMap;

/// The gain plot.
pub const PLOT: &str = "wang-table4-gain.svg";

/// The clippers of the table, in column order, with their column titles.
const COLUMNS: [(&str, &str); 6] = [
    ("liu", "Liu"),
    ("virtual-box-no45", "New1"),
    ("virtual-box", "New2"),
    ("cyrus-beck", "cyrus-beck"),
    ("geo", "geo"),
    ("indexed", "indexed"),
];
/// Columns of this project's clippers (not geo).
const OURS: [usize; 5] = [0, 1, 2, 3, 5];

/// The size rows, in the table's order: name in the files, and a label.
const SIZE_ROWS_NAMES: [(&str, &str); 2] = [("W1", "row 1 (paper's polygon)"), ("W2", "row 2 (W1 = 4, W2 = 80)")];

/// One window of the table.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// `concave` or `convex`.
    pub shape: String,
    /// Window edges.
    pub edges: usize,
    /// 0 or 1: the paper's size row.
    pub size_row: usize,
    /// Our window's measured W1 and W2.
    pub w1_w2: (f64, f64),
    /// Median ms per batch for each of [`COLUMNS`] (NaN where the clipper does not run).
    pub ms: [f64; 6],
    /// Repetitions behind each median.
    pub repetitions: [usize; 6],
    /// Liu's time over New2's with its 95% bootstrap interval over the repetitions: above 1 where
    /// New2 is faster.
    pub speedup: Interval,
}

impl Row {
    /// The fastest of this project's clippers on this window: its column and ms per batch.
    pub fn best_ours(&self) -> (usize, f64) {
        OURS.iter()
            .map(|&i| (i, self.ms[i]))
            .filter(|(_, v)| !v.is_nan())
            .fold((0, f64::INFINITY), |best, c| if c.1 < best.1 { c } else { best })
    }

    /// (Liu - New2) x 100% / New2.
    pub fn gain(&self) -> f64 {
        (self.ms[0] - self.ms[2]) * 100.0 / self.ms[2]
    }

    /// [`Row::gain`] with its 95% interval.
    pub fn gain_interval(&self) -> Interval {
        let percent = |r: f64| (r - 1.0) * 100.0;
        let s = self.speedup;
        Interval { estimate: self.gain(), low: percent(s.low), high: percent(s.high) }
    }
}

/// Computes the rows from raw timings and the window records.
pub fn rows(measurements: &[Measurement], windows: &[WindowRecord]) -> Vec<Row> {
    let mut times: BTreeMap<(String, usize, String), Vec<f64>> = BTreeMap::new();
    for m in measurements {
        times.entry((m.case.clone(), m.size, m.clipper.clone())).or_default().push(m.time_ns / 1e6);
    }
    windows
        .iter()
        .filter_map(|w| {
            let size_row = SIZE_ROWS_NAMES.iter().position(|(n, _)| *n == w.size_row)?;
            let case = format!("{}-{}", w.shape, w.size_row);
            let series = COLUMNS.map(|(c, _)| times.get(&(case.clone(), w.edges, c.to_owned())));
            let speedup = match (series[0], series[2]) {
                (Some(liu), Some(new2)) => bootstrap(
                    &[CaseSamples { times: liu, baseline: Some(new2) }],
                    seed_of(&format!("wang-t4/{case}/{}", w.edges)),
                    mean_ratio,
                ),
                _ => None,
            };
            Some(Row {
                shape: w.shape.clone(),
                edges: w.edges,
                size_row,
                w1_w2: (w.w1, w.w2),
                ms: series.map(|s| s.map_or(f64::NAN, |v| median(v))),
                repetitions: series.map(|s| s.map_or(0, Vec::len)),
                speedup: speedup.unwrap_or(Interval::exact(f64::NAN)),
            })
        })
        .collect()
}

/// The concave-window table, beside the paper's.
pub fn markdown_table(rows: &[Row]) -> String {
    let head = header(&[
        "Edges",
        "Size row",
        "W1, W2 (ours)",
        "W1, W2 (paper)",
        "Liu ms",
        "New1 ms",
        "New2 ms",
        "Gain %",
        "paper Liu",
        "paper New1",
        "paper New2",
        "paper Gain %",
        "indexed ms",
        "cyrus-beck ms",
        "geo ms",
    ]);
    let body = rows
        .iter()
        .filter(|r| r.shape == "concave")
        .map(|r| {
            let p = wang_row(r.edges, r.size_row);
            let pv = |f: fn(&crate::papers::WangRow) -> f64| p.map_or("n/a".to_owned(), |p| num(f(p), 2));
            vec![
                r.edges.to_string(),
                SIZE_ROWS_NAMES[r.size_row].1.to_owned(),
                format!("{}, {}", num(r.w1_w2.0, 2), num(r.w1_w2.1, 1)),
                p.map_or("n/a".to_owned(), |p| format!("{}, {}", p.w1_w2.0, p.w1_w2.1)),
                num(r.ms[0], 3),
                num(r.ms[1], 3),
                num(r.ms[2], 3),
                format!("**{}**", num_interval(&r.gain_interval(), 1)),
                pv(|p| p.liu),
                pv(|p| p.new1),
                pv(|p| p.new2),
                pv(|p| p.gain),
                num(r.ms[5], 3),
                "n/a (concave)".to_owned(),
                num(r.ms[4], 2),
            ]
        })
        .collect::<Vec<_>>();
    table(&head, &body)
}

/// The same clippers on convex windows of the same sizes, where Cyrus-Beck applies.
pub fn convex_table(rows: &[Row]) -> String {
    let head = header(&[
        "Edges",
        "Size row",
        "Liu ms",
        "New1 ms",
        "New2 ms",
        "Gain %",
        "indexed ms",
        "cyrus-beck ms",
        "geo ms",
    ]);
    let body = rows
        .iter()
        .filter(|r| r.shape == "convex")
        .map(|r| {
            vec![
                r.edges.to_string(),
                SIZE_ROWS_NAMES[r.size_row].1.to_owned(),
                num(r.ms[0], 3),
                num(r.ms[1], 3),
                num(r.ms[2], 3),
                num_interval(&r.gain_interval(), 1),
                num(r.ms[5], 3),
                num(r.ms[3], 3),
                num(r.ms[4], 2),
            ]
        })
        .collect::<Vec<_>>();
    table(&head, &body)
}

/// Share of the batch each stage settled, for New2 and Liu on the concave windows.
pub fn stages_table(stages: &[StageRecord]) -> String {
    let share = |shape: &str, row: &str, edges: usize, clipper: &str, stage: &str| {
        stages
            .iter()
            .find(|s| {
                s.shape == shape && s.size_row == row && s.edges == edges && s.clipper == clipper && s.stage == stage
            })
            .map_or(f64::NAN, |s| s.segments as f64 * 100.0 / s.of as f64)
    };
    let head = header(&[
        "Edges",
        "Size row",
        "MEB %",
        "45° box %",
        "virtual box %",
        "code sum %",
        "intersected %",
        "visible %",
        "Liu: MEB %",
        "Liu: no crossing %",
        "New1: adaptive box + code sum %",
    ]);
    let mut body = Vec::new();
    for (name, label) in SIZE_ROWS_NAMES {
        let mut edges: Vec<usize> = stages.iter().filter(|s| s.size_row == name).map(|s| s.edges).collect();
        edges.sort_unstable();
        edges.dedup();
        for e in edges {
            let s = |stage: &str| share("concave", name, e, "virtual-box", stage);
            let n1 = share("concave", name, e, "virtual-box-no45", "virtual-box")
                + share("concave", name, e, "virtual-box-no45", "code-sum");
            body.push(vec![
                e.to_string(),
                label.to_owned(),
                num(s("meb"), 1),
                num(s("rotated-box"), 1),
                num(s("virtual-box"), 1),
                num(s("code-sum"), 1),
                num(s("intersected"), 1),
                num(s("visible"), 1),
                num(share("concave", name, e, "liu", "meb"), 1),
                num(share("concave", name, e, "liu", "no-crossing"), 1),
                num(n1, 1),
            ]);
        }
    }
    table(&head, &body)
}

/// New2's stages in pipeline order, with their column titles.
const STAGE_COLUMNS: [(&str, &str); 5] = [
    ("meb", "MEB"),
    ("rotated-box", "45° box"),
    ("virtual-box", "virtual box"),
    ("code-sum", "code sum"),
    ("intersected", "intersected"),
];

/// One window's stage sums: size-row label, edges, the summed gain (ns per segment of the batch)
/// and each stage's part of it.
pub struct StageSum {
    /// The size row's label.
    pub label: String,
    /// Window edges.
    pub edges: usize,
    /// Σ share x (Liu - New2), ns per segment of the batch.
    pub total: f64,
    /// Each stage's title and share x (Liu - New2).
    pub parts: Vec<(String, f64)>,
    /// Σ share x ns over the stages, New2's and Liu's: each clipper's time per segment of the
    /// batch as it would be with the batch sorted by New2's stage.
    pub sorted: (f64, f64),
    /// Σ share x (Liu - New2) over the 45° box and the virtual box: what New2's two boxes save.
    pub boxes: f64,
}

/// Per window, for the segments New2 settles at each stage: their share, New2's and Liu's ns per
/// segment on them, and the sum over stages of share x (Liu - New2), which is where the gain
/// comes from (or goes).
pub fn stage_times_table(records: &[StageTimeRecord]) -> (String, Vec<StageSum>) {
    let mut head = vec!["Edges".to_owned(), "Size row".to_owned()];
    head.extend(STAGE_COLUMNS.iter().map(|(_, t)| format!("{t}: share, New2 / Liu ns")));
    head.push("Σ share x (Liu - New2) ns".to_owned());
    let mut windows: Vec<(String, usize)> = records.iter().map(|r| (r.size_row.clone(), r.edges)).collect();
    windows.sort();
    windows.dedup();
    let mut body = Vec::new();
    let mut sums = Vec::new();
    for (row, edges) in windows {
        let find = |stage: &str, clipper: &str| {
            records.iter().find(|r| r.size_row == row && r.edges == edges && r.stage == stage && r.clipper == clipper)
        };
        let label = SIZE_ROWS_NAMES.iter().find(|(n, _)| *n == row).map_or(row.clone(), |(_, l)| (*l).to_owned());
        let mut cells = vec![edges.to_string(), label.clone()];
        let mut total = 0.0;
        let mut parts = Vec::new();
        let (mut sorted, mut boxes) = ((0.0, 0.0), 0.0);
        for (stage, title) in STAGE_COLUMNS {
            match (find(stage, "virtual-box"), find(stage, "liu")) {
                (Some(n), Some(l)) => {
                    let share = n.segments as f64 / n.of as f64;
                    let part = share * (l.ns_per_segment - n.ns_per_segment);
                    total += part;
                    sorted = (sorted.0 + share * n.ns_per_segment, sorted.1 + share * l.ns_per_segment);
                    if stage == "rotated-box" || stage == "virtual-box" {
                        boxes += part;
                    }
                    parts.push((title.to_owned(), part));
                    cells.push(format!(
                        "{}%, {} / {}",
                        num(share * 100.0, 1),
                        num(n.ns_per_segment, 1),
                        num(l.ns_per_segment, 1)
                    ));
                }
                _ => cells.push("-".to_owned()),
            }
        }
        cells.push(format!("**{}**", num(total, 1)));
        body.push(cells);
        sums.push(StageSum { label, edges, total, parts, sorted, boxes });
    }
    (table(&head, &body), sums)
}

/// What the stage timings say, computed from them: per window, where New2 gains and loses
/// against Liu on the batch sorted by stage, what the mixed order of the real batch costs each
/// clipper, and whether New2's boxes could pay for that.
pub fn stage_reading(sums: &[StageSum], rows: &[Row]) -> String {
    let mut text = String::new();
    for StageSum { label, edges, total, parts, sorted, boxes } in sums {
        // The same window's whole-batch medians, Liu's and New2's, in ns per segment (batches of
        // 10000).
        let whole = rows
            .iter()
            .find(|r| r.shape == "concave" && r.edges == *edges && SIZE_ROWS_NAMES[r.size_row].1 == label.as_str())
            .map(|r| (r.ms[0] * 1e6 / 10_000.0, r.ms[2] * 1e6 / 10_000.0));
        let (gain, loss): (Vec<_>, Vec<_>) = parts.iter().partition(|(_, v)| *v >= 0.0);
        let list = |v: &[&(String, f64)]| {
            v.iter().map(|(t, ns)| format!("{t} {}", num(ns.abs(), 1))).collect::<Vec<_>>().join(", ")
        };
        text.push_str(&format!(
            "- {label}, {edges} edges: New2 {} {} ns per segment of the batch against Liu; gained at {}; lost at {}.\n",
            if *total >= 0.0 { "saves" } else { "loses" },
            num(total.abs(), 1),
            if gain.is_empty() { "no stage".to_owned() } else { list(&gain) },
            if loss.is_empty() { "no stage".to_owned() } else { list(&loss) },
        ));
        if let Some((liu, new2)) = whole {
            let saved = liu - new2;
            // What the mixed order costs each clipper over its stage sum, and New2's excess.
            let (order_new2, order_liu) = (new2 - sorted.0, liu - sorted.1);
            let excess = order_new2 - order_liu;
            text.push_str(&format!(
                "  In the mixed batch of the table above New2 {} {} ns per segment; the {} ns between the two is what the \
                 order of the batch costs: sorted by stage, every early out is predicted, while in the mixed batch the \
                 stage a segment stops at is random, and each of New2's extra early outs (45° box, virtual box, code \
                 sum) can be a mispredicted branch.\n",
                if saved >= 0.0 { "saves" } else { "loses" },
                num(saved.abs(), 1),
                num((total - saved).abs(), 1)
            ));
            text.push_str(&format!(
                "  Split by clipper: New2's stages sum to {} ns per segment against its {} in the mixed batch ({} ns \
                 for the order), Liu's to {} against {} ({} ns). New2's two boxes save {} ns per segment of the batch; \
                 {}\n",
                num(sorted.0, 1),
                num(new2, 1),
                num(order_new2, 1),
                num(sorted.1, 1),
                num(liu, 1),
                num(order_liu, 1),
                num(*boxes, 1),
                if *boxes > excess {
                    format!(
                        "that is more than the {} ns more that the mixed order costs New2 than Liu, so the boxes pay \
                         for themselves here.",
                        num(excess, 1)
                    )
                } else {
                    format!(
                        "even were New2's code-sum and intersected segments no dearer than Liu's, that is less than \
                         the {} ns more that the mixed order costs New2 than Liu: at this size New2 cannot be faster \
                         than Liu on a random batch unless that order cost falls below what its boxes save.",
                        num(excess, 1)
                    )
                }
            ));
        }
    }
    text
}

/// Gain against edges for both size rows, ours and the paper's.
pub fn chart(rows: &[Row]) -> Chart {
    let mut series = Vec::new();
    for (i, (_, label)) in SIZE_ROWS_NAMES.iter().enumerate() {
        let mut ours: Vec<(f64, f64)> = rows
            .iter()
            .filter(|r| r.shape == "concave" && r.size_row == i)
            .map(|r| (r.edges as f64, r.gain()))
            .collect();
        ours.sort_by(|a, b| a.0.total_cmp(&b.0));
        series.push(Series {
            label: format!("{label}, measured here"),
            colour: SIZE_ROWS[i],
            points: ours,
            paper: false,
            spread: Vec::new(),
        });
    }
    for (i, (_, label)) in SIZE_ROWS_NAMES.iter().enumerate() {
        let paper = WANG_TABLE4.iter().filter(|r| r.size_row == i).map(|r| (r.edges as f64, r.gain)).collect();
        series.push(Series {
            label: format!("{label}, Wang et al. 2005 (Pentium IV)"),
            colour: SIZE_ROWS[i],
            points: paper,
            paper: true,
            spread: Vec::new(),
        });
    }
    Chart {
        title: "Wang et al. Table 4: gain of New2 (virtual boxes + 45° box) over Liu, concave windows".to_owned(),
        x_label: "window polygon edges".to_owned(),
        y_label: "gain = (Liu - New2) / New2 (%)".to_owned(),
        log_x: false,
        log_y: false,
        x_ticks: Vec::new(),
        series,
    }
}

/// A short reading, every statement computed from the rows; a claim counts only the windows whose
/// interval supports it.
pub fn reading(rows: &[Row]) -> String {
    let mut text = String::new();
    for (i, (_, label)) in SIZE_ROWS_NAMES.iter().enumerate() {
        let ours: Vec<&Row> = rows.iter().filter(|r| r.shape == "concave" && r.size_row == i).collect();
        let (Some(a), Some(b)) = (ours.first(), ours.last()) else { continue };
        let pa = wang_row(a.edges, i).map_or(f64::NAN, |p| p.gain);
        let pb = wang_row(b.edges, i).map_or(f64::NAN, |p| p.gain);
        text.push_str(&format!(
            "- {label}: our gain (%) {} from {} at {} edges to {} at {}; the paper's from {}% to {}%.\n",
            wording::trend(&a.gain_interval(), &b.gain_interval()),
            num_interval(&a.gain_interval(), 1),
            a.edges,
            num_interval(&b.gain_interval(), 1),
            b.edges,
            num(pa, 1),
            num(pb, 1)
        ));
    }
    let concave: Vec<&Row> = rows.iter().filter(|r| r.shape == "concave").collect();
    let sides = Sides::of_speedups(concave.iter().map(|r| &r.speedup));
    text.push_str(&format!(
        "- Against Liu, New2 is {} (the paper: faster at 12 of 12).\n",
        sides.sentence("concave windows")
    ));
    let box45: Vec<f64> = concave.iter().map(|r| (r.ms[1] - r.ms[2]) * 100.0 / r.ms[2]).collect();
    let paper45: Vec<f64> = WANG_TABLE4.iter().map(|r| (r.new1 - r.new2) * 100.0 / r.new2).collect();
    let range = |v: &[f64]| {
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        format!("{}% to {}%", num(lo, 1), num(hi, 1))
    };
    if !box45.is_empty() {
        text.push_str(&format!(
            "- The 45° box (New1 against New2) saves {} of New2's time here; {} in the paper.\n",
            range(&box45),
            range(&paper45)
        ));
    }
    let geo: Vec<f64> = concave.iter().filter(|r| !r.ms[4].is_nan()).map(|r| r.ms[4] / r.ms[2]).collect();
    if !geo.is_empty() {
        text.push_str(&format!(
            "- geo's line clip (one call per segment) takes {} times New2's time.\n",
            range(&geo).replace('%', "")
        ));
    }
    for (i, (_, label)) in SIZE_ROWS_NAMES.iter().enumerate() {
        let best: Vec<String> = concave
            .iter()
            .filter(|r| r.size_row == i)
            .map(|r| {
                let (c, ms) = r.best_ours();
                format!("{} edges: {} {} ns", r.edges, COLUMNS[c].1, num(ms * 1e6 / 10_000.0, 1))
            })
            .collect();
        if !best.is_empty() {
            text.push_str(&format!("- The fastest of our clippers per segment, {label}: {}.\n", best.join("; ")));
        }
    }
    let convex: Vec<&Row> = rows.iter().filter(|r| r.shape == "convex" && !r.ms[3].is_nan()).collect();
    if !convex.is_empty() {
        let cb: Vec<f64> = convex.iter().map(|r| r.ms[3] / r.ms[2]).collect();
        text.push_str(&format!(
            "- On convex windows Cyrus-Beck takes {} times New2's time.\n",
            range(&cb).replace('%', "")
        ));
    }
    text
}

/// The table's section and its plot; `None` when the folder holds no Table 4 results.
pub fn derive(folder: &ResultsFolder) -> Result<Option<Derived>, CliError> {
    let csv = folder.join(CSV);
    if !csv.exists() {
        return Ok(None);
    }
    let measurements: Vec<Measurement> = read_csv(&csv)?;
    let windows: Vec<WindowRecord> = read_csv(&folder.join(WINDOWS_CSV))?;
    let stages: Vec<StageRecord> = read_csv(&folder.join(STAGES_CSV))?;
    let rows = rows(&measurements, &windows);
    let stage_times_path = folder.join(STAGE_TIMES_CSV);
    let stage_times = if stage_times_path.exists() {
        let records: Vec<StageTimeRecord> = read_csv(&stage_times_path)?;
        let (md, sums) = stage_times_table(&records);
        format!(
            "### Where New2 gains and loses time against Liu, stage by stage (concave windows)\n\n\
             The batch split by the stage at which New2 settles each segment; New2 and Liu timed on each part \
             (medians of 31 interleaved rounds, ns per segment of the part). A segment New2 rejects early still costs \
             Liu its MEB test and, past it, a pass over every vertex; a segment New2 intersects costs New2 its three \
             boxes and the vertex codes on top of what Liu does. share x (Liu - New2), summed, is New2's gain per \
             segment of the whole batch.\n\n{md}\n{}\n",
            stage_reading(&sums, &rows)
        )
    } else {
        String::new()
    };
    let (provenance, notes) = provenance_line(&folder.join(META))?;
    let param = |k: &str| provenance.parameters.get(k).and_then(serde_json::Value::as_u64).unwrap_or(0);
    let body = format!(
        "Workload `wang-t4`: {} random segments (endpoints uniform in 800 x 600) clipped against star-shaped concave \
         windows of 6 to 50 edges at the paper's two size rows; W1 = 600 / L and W2 = 600 x 800 / MEB area are \
         measured on our windows (L read as MEB width + height, see `clip_testkit::workload::wang`). Times are \
         medians over {} interleaved repetitions (geo: {}) of one batch, in ms per batch of 10000 segments, which is \
         numerically the paper's seconds for 1000 batches. Gain = (Liu - New2) x 100% / New2. Cyrus-Beck needs a \
         convex window (n/a here; see the convex table).\n\n{}\n![gain against edges]({PLOT})\n\n{}\n\
         ### The same sizes with convex windows\n\n{}\n\
         ### Share of the batch settled by each stage (concave windows; New2's pipeline, and Liu's)\n\n{}\n{}{}\n",
        param("segments_per_batch"),
        param("repetitions"),
        param("geo_repetitions"),
        markdown_table(&rows),
        reading(&rows),
        convex_table(&rows),
        stages_table(&stages),
        stage_times,
        notes
    );
    Ok(Some(Derived::new(body).with_plot(PLOT, chart(&rows))))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m(clipper: &str, rep: usize, ms: f64) -> Measurement {
        Measurement {
            workload: "wang-t4".into(),
            case: "concave-W1".into(),
            clipper: clipper.into(),
            phase: "clip".into(),
            size: 6,
            op: "lines".into(),
            fill_rule: "even-odd".into(),
            repetition: rep,
            iterations: 1,
            time_ns: ms * 1e6,
            correct: None,
        }
    }

    #[test]
    fn stage_reading_splits_the_order_cost_and_weighs_the_boxes_against_it() {
        let record = |stage: &str, clipper: &str, segments: usize, ns: f64| StageTimeRecord {
            size_row: "W1".into(),
            edges: 6,
            stage: stage.into(),
            segments,
            of: 100,
            clipper: clipper.into(),
            ns_per_segment: ns,
        };
        // Half the batch rejected by the MEB (2 ns each), a quarter by the 45° box (New2 4 ns,
        // Liu 20), a quarter intersected (New2 50, Liu 40): sorted sums New2 1 + 1 + 12.5 = 14.5,
        // Liu 1 + 5 + 10 = 16; the boxes save 0.25 x 16 = 4 ns.
        let records = vec![
            record("meb", "virtual-box", 50, 2.0),
            record("meb", "liu", 50, 2.0),
            record("rotated-box", "virtual-box", 25, 4.0),
            record("rotated-box", "liu", 25, 20.0),
            record("intersected", "virtual-box", 25, 50.0),
            record("intersected", "liu", 25, 40.0),
        ];
        let (_, sums) = stage_times_table(&records);
        assert_eq!((sums[0].sorted, sums[0].boxes), ((14.5, 16.0), 4.0));
        let row = |new2_ms: f64| Row {
            shape: "concave".into(),
            edges: 6,
            size_row: 0,
            w1_w2: (2.7, 41.0),
            ms: [0.18, f64::NAN, new2_ms, f64::NAN, f64::NAN, f64::NAN],
            repetitions: [1; 6],
            speedup: Interval::exact(0.18 / new2_ms),
        };
        // Mixed batch: Liu 18 ns (order 2), New2 21.5 (order 7): the excess 5 exceeds the boxes' 4.
        let text = stage_reading(&sums, &[row(0.215)]);
        assert!(text.contains("New2's stages sum to 14.5 ns per segment against its 21.5"), "{text}");
        assert!(text.contains("the 5.0 ns more that the mixed order costs New2 than Liu: at this size New2 cannot"));
        // New2 at 19 ns (order 4.5): the excess 2.5 is below the boxes' 4.
        assert!(stage_reading(&sums, &[row(0.19)]).contains("so the boxes pay for themselves here"));
    }

    #[test]
    fn gain_comes_from_the_medians() {
        let raw = vec![
            m("liu", 0, 3.0),
            m("liu", 1, 3.0),
            m("liu", 2, 90.0),
            m("virtual-box", 0, 2.0),
            m("virtual-box", 1, 2.0),
        ];
        let windows = vec![WindowRecord {
            shape: "concave".into(),
            size_row: "W1".into(),
            edges: 6,
            w1: 2.7,
            w2: 41.0,
            paper_w1: 2.76,
            paper_w2: 40.0,
        }];
        let rows = rows(&raw, &windows);
        assert_eq!(rows.len(), 1);
        assert_eq!(rows[0].gain(), 50.0);
        assert_eq!(rows[0].repetitions, [3, 0, 2, 0, 0, 0]);
        assert!(rows[0].ms[3].is_nan());
        assert!(reading(&rows).contains("from 50.0 (50.0-4400.0) at 6 edges"), "{}", reading(&rows));
    }

    #[test]
    fn a_window_whose_interval_crosses_one_is_not_counted_faster() {
        let reps = |c: &str, times: &[f64], edges: usize| {
            times.iter().map(|&t| Measurement { size: edges, ..m(c, 0, t) }).collect::<Vec<_>>()
        };
        let mut raw = reps("liu", &[3.0, 3.1, 2.9, 3.0, 3.05], 6);
        raw.extend(reps("virtual-box", &[2.0, 2.1, 1.9, 2.0, 2.05], 6));
        raw.extend(reps("liu", &[1.0, 1.2, 0.8, 1.1, 0.9], 8));
        raw.extend(reps("virtual-box", &[1.0, 0.9, 1.1, 1.2, 0.8], 8));
        let window = |edges| WindowRecord {
            shape: "concave".into(),
            size_row: "W1".into(),
            edges,
            w1: 2.7,
            w2: 41.0,
            paper_w1: 2.76,
            paper_w2: 40.0,
        };
        let rows = rows(&raw, &[window(6), window(8)]);
        assert!(rows[0].speedup.above(1.0), "{:?}", rows[0].speedup);
        assert!(!rows[1].speedup.above(1.0) && !rows[1].speedup.below(1.0), "{:?}", rows[1].speedup);
        let text = reading(&rows);
        assert!(
            text.contains("New2 is faster at 1 of 2 concave windows, slower at 0, indistinguishable at 1"),
            "{text}"
        );
        assert!(text.contains("our gain (%) falls from 50.0"), "{text}");
    }
}
