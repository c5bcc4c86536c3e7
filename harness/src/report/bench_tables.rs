//! The bench from its raw CSV: per group and operation, time per call and the ratio to Clipper2
//! measured in the same run; peak memory of the large cases; one log-log plot per group.

use std::collections::{BTreeMap, BTreeSet};

use super::bench_points::{Point, Points, point_records};
use super::derived::{Derived, DerivedFile};
use super::markdown::{duration_interval_ns, header, num, num_interval, table};
use super::provenance_line::provenance_line;
use super::results_folder::ResultsFolder;
use super::wording::Sides;
use crate::cli_error::CliError;
use crate::measure::interval::Interval;
use crate::measure::raw::{Measurement, csv_text};
use crate::plot::chart::{Chart, Series};
use crate::plot::palette::clipper_colour;
use crate::results_files::bench::{BASELINE, META, MemoryRecord, POINTS_CSV};

/// The plot file of one group.
pub fn plot_file(group: &str) -> String {
    format!("bench-{group}.svg")
}

/// Groups in first-seen order of the raw file, clippers likewise.
fn order(rows: &[&Measurement], pick: impl Fn(&Measurement) -> &str) -> Vec<String> {
    let mut seen = Vec::new();
    for r in rows {
        if !seen.iter().any(|s: &String| s == pick(r)) {
            seen.push(pick(r).to_owned());
        }
    }
    seen
}

/// One table: sizes down, clippers across, "time (ratio to Clipper2)".
fn group_table(points: &Points, group: &str, op: &str, clippers: &[String]) -> Option<String> {
    let sizes: BTreeSet<usize> =
        points.keys().filter(|(g, o, _, _)| g == group && o == op).map(|(_, _, s, _)| *s).collect();
    let present: Vec<&String> =
        clippers.iter().filter(|c| points.keys().any(|(g, o, _, k)| g == group && o == op && k == *c)).collect();
    if sizes.is_empty() {
        return None;
    }
    let mut head = vec!["Edges".to_owned()];
    head.extend(present.iter().map(|c| format!("{c}: time; x {BASELINE}")));
    let body: Vec<Vec<String>> = sizes
        .iter()
        .map(|&s| {
            let mut cells = vec![s.to_string()];
            for c in &present {
                cells.push(match points.get(&(group.to_owned(), op.to_owned(), s, (*c).clone())) {
                    Some(p) if !p.trusted() => format!("wrong on {} of {} cases", p.wrong_cases, p.cases),
                    Some(p) if p.rounds <= 1 => {
                        format!(
                            "{}; x {} ¹",
                            duration_interval_ns(&p.time_interval),
                            num_interval(&p.ratio_interval, 2)
                        )
                    }
                    Some(p) => {
                        format!("{}; x {}", duration_interval_ns(&p.time_interval), num_interval(&p.ratio_interval, 2))
                    }
                    None => "n/a".to_owned(),
                });
            }
            cells
        })
        .collect();
    Some(table(&head, &body))
}

/// The log-log plot of one group's intersection times.
pub fn chart(points: &Points, group: &str, clippers: &[String]) -> Chart {
    let op = "intersection";
    let series = clippers
        .iter()
        .filter_map(|c| {
            let drawn: Vec<(f64, &Point)> = points
                .iter()
                .filter(|((g, o, _, k), p)| g == group && o == op && k == c && p.trusted())
                .map(|((_, _, s, _), p)| (*s as f64, p))
                .collect();
            let pts = drawn.iter().map(|(s, p)| (*s, p.time_ns / 1e3)).collect();
            let spread =
                drawn.iter().map(|(s, p)| (*s, p.time_interval.low / 1e3, p.time_interval.high / 1e3)).collect();
            (!drawn.is_empty()).then(|| Series {
                label: c.clone(),
                colour: clipper_colour(c),
                points: pts,
                paper: false,
                spread,
            })
        })
        .collect();
    Chart {
        title: format!("bench, {group}: intersection time per call against subject size (bars: 95% intervals)"),
        x_label: "subject polygon edges (log scale)".to_owned(),
        y_label: "time per call (µs, log scale)".to_owned(),
        log_x: true,
        log_y: true,
        x_ticks: points
            .keys()
            .filter(|(g, o, _, _)| g == group && o == op)
            .map(|(_, _, s, _)| *s)
            .collect::<BTreeSet<usize>>()
            .into_iter()
            .map(|s| s as f64)
            .collect(),
        series,
    }
}

/// The ratios the issue asks to quote: `vatti` against Clipper2 (with its interval) and geo at 4,
/// 20, 100, 200 edges and the largest size, per group, intersection; then at how many sizes
/// `vatti` is faster than Clipper2, counting only sizes whose interval excludes 1.
pub fn vatti_ratios(points: &Points, groups: &[String]) -> String {
    let op = "intersection";
    let mut text = String::new();
    for g in groups {
        let sizes: BTreeSet<usize> =
            points.keys().filter(|(gg, o, _, c)| gg == g && o == op && c == "vatti").map(|(_, _, s, _)| *s).collect();
        let Some(&largest) = sizes.last() else { continue };
        let mut parts = Vec::new();
        for s in [4, 20, 100, 200, largest].into_iter().filter(|s| sizes.contains(s)).collect::<BTreeSet<_>>() {
            let key = |c: &str| (g.clone(), op.to_owned(), s, c.to_owned());
            let (Some(v), Some(geo)) = (points.get(&key("vatti")), points.get(&key("geo"))) else { continue };
            if !(v.trusted() && geo.trusted()) {
                continue;
            }
            parts.push(format!(
                "{s}: {} x clipper2, {} x geo",
                num_interval(&v.ratio_interval, 2),
                num(v.time_ns / geo.time_ns, 2)
            ));
        }
        let ratios: Vec<&Interval> = points
            .iter()
            .filter(|((gg, o, _, c), p)| gg == g && o == op && c == "vatti" && p.trusted())
            .map(|(_, p)| &p.ratio_interval)
            .collect();
        let sides = Sides::of_time_ratios(ratios);
        if !parts.is_empty() {
            text.push_str(&format!(
                "- {g}: vatti at {}; against clipper2 {}.\n",
                parts.join("; "),
                sides.sentence("sizes")
            ));
        }
    }
    text
}

/// The rectangle-window clippers against Clipper2's dedicated rectangle clipper, per group where
/// it ran, intersection: the ratio of geometric means over cases against the baseline, which is
/// the geometric mean of the per-case ratios between the two.
pub fn rect_clip_ratios(points: &Points, groups: &[String]) -> String {
    const RECT_PEER: &str = "clipper2-rect";
    let op = "intersection";
    let mut text = String::new();
    for g in groups {
        let sizes: BTreeSet<usize> =
            points.keys().filter(|(gg, o, _, c)| gg == g && o == op && c == RECT_PEER).map(|(_, _, s, _)| *s).collect();
        let mut parts = Vec::new();
        for s in sizes {
            let key = |c: &str| (g.clone(), op.to_owned(), s, c.to_owned());
            let Some(peer) = points.get(&key(RECT_PEER)).filter(|p| p.trusted()) else { continue };
            let ours: Vec<String> = ["sutherland-hodgman", "rect-four-state"]
                .iter()
                .filter_map(|c| {
                    points.get(&key(c)).filter(|p| p.trusted()).map(|p| format!("{c} {}", num(p.ratio / peer.ratio, 2)))
                })
                .collect();
            if !ours.is_empty() {
                parts.push(format!("{s}: {}", ours.join(", ")));
            }
        }
        if !parts.is_empty() {
            text.push_str(&format!("- {g}, x {RECT_PEER}: {}.\n", parts.join("; ")));
        }
    }
    text
}

/// Peak memory of one large group, MiB above the resident size before the call (largest over the
/// group's cases): sizes down, every clipper across, with its ratio to Clipper2's in brackets.
fn memory_table(records: &[MemoryRecord], group: &str, clippers: &[String]) -> Option<String> {
    let mut by_size: BTreeMap<usize, BTreeMap<&str, u64>> = BTreeMap::new();
    for r in records.iter().filter(|r| r.workload == group) {
        let cell = by_size.entry(r.size).or_default().entry(r.clipper.as_str()).or_default();
        *cell = (*cell).max(r.peak_extra_kib);
    }
    if by_size.is_empty() {
        return None;
    }
    let present: Vec<&String> =
        clippers.iter().filter(|c| records.iter().any(|r| r.workload == group && &r.clipper == *c)).collect();
    let mut head = header(&["Edges"]);
    head.extend(present.iter().map(|c| format!("{c} MiB (x {BASELINE})")));
    let body: Vec<Vec<String>> = by_size
        .iter()
        .map(|(s, by)| {
            let base = by.get(BASELINE).copied();
            let mut cells = vec![s.to_string()];
            cells.extend(present.iter().map(|c| match (by.get(c.as_str()), base) {
                (Some(&k), Some(b)) if b > 0 => {
                    format!("{} ({})", num(k as f64 / 1024.0, 1), num(k as f64 / b as f64, 2))
                }
                (Some(&k), _) => num(k as f64 / 1024.0, 1),
                (None, _) => "n/a".to_owned(),
            }));
            cells
        })
        .collect();
    Some(table(&head, &body))
}

/// The bench's section, its plots and every point with its intervals (`bench-points.csv`);
/// `None` when the folder holds no polygon bench results (the text group has its own section).
pub fn derive(folder: &ResultsFolder) -> Result<Option<Derived>, CliError> {
    let rows = folder.polygon_bench_rows()?;
    if rows.is_empty() {
        return Ok(None);
    }
    let memory = folder.bench_memory()?;
    let points = folder.bench_points()?;
    let points_csv = csv_text(&point_records(points))
        .map_err(|e| CliError::failed(format!("{}: cannot write ({e})", folder.join(POINTS_CSV).display())))?;
    let mut files = vec![(POINTS_CSV.to_owned(), DerivedFile::Text(points_csv))];
    let groups = order(&rows, |r| r.workload.as_str());
    let clippers = order(&rows, |r| r.clipper.as_str());
    let ops = order(&rows, |r| r.op.as_str());
    let (_, notes) = provenance_line(&folder.join(META))?;
    let mut text = format!(
        "Time per call (mean over the group's cases of the median over interleaved rounds), then `x` the ratio to \
         `{BASELINE}` measured in the same run (geometric mean over cases of the ratio of medians; below 1 is faster \
         than Clipper2). Each figure carries its 95% interval in brackets: a seeded bootstrap over the cases and \
         the rounds, so two figures whose intervals overlap may not differ at all (every point with its \
         interval: `{POINTS_CSV}`; the plots draw the time's interval as a bar). Operands read under even-odd (`clipper1`, which reads only non-zero, is timed where every operand covers the same region under both rules). ¹ marks a point over the time cap, timed once; n/a: not run (the \
         clipper does not take that window, or it was skipped after the cap: see the notes). Every result timed \
         was checked first (the exact oracle, or its area against the exact area where the oracle's sweep is too \
         costly); \"wrong on k of n cases\" stands where a clipper answered wrongly, and its times there count in \
         no ratio.\n\n\
         Ratios of `vatti` at 4, 20, 100, 200 edges and the largest size (intersection):\n\n{}\n\
         Sutherland-Hodgman and four-state on rectangle windows against Clipper2's rectangle clipper \
         (`clipper2-rect`, RectClip64), measured in the same run:\n\n{}\n{notes}\n",
        vatti_ratios(points, &groups),
        rect_clip_ratios(points, &groups)
    );
    for g in &groups {
        files.push((plot_file(g), DerivedFile::Plot(chart(points, g, &clippers))));
        text.push_str(&format!("### {g}\n\n![{g}: time against size]({})\n\n", plot_file(g)));
        for op in &ops {
            if let Some(t) = group_table(points, g, op, &clippers) {
                text.push_str(&format!("{op}:\n\n{t}\n"));
            }
        }
        if let Some(t) = memory_table(memory, g, &clippers) {
            text.push_str(&format!(
                "peak memory of one intersection call (MiB above the resident size before it, measured in a fresh \
                 child process so no memory freed by earlier cases hides it; largest over the cases; ratio to \
                 `{BASELINE}` in brackets):\n\n{t}\n"
            ));
        }
    }
    Ok(Some(Derived { body: text, files }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measure::raw::read_csv;
    use crate::report::bench_points::points;
    use crate::results_files::bench::CSV;

    fn m(clipper: &str, case: &str, rep: usize, ns: f64) -> Measurement {
        Measurement {
            workload: "star".into(),
            case: case.into(),
            clipper: clipper.into(),
            phase: "clip".into(),
            size: 20,
            op: "intersection".into(),
            fill_rule: "even-odd".into(),
            repetition: rep,
            iterations: 1,
            time_ns: ns,
            correct: None,
        }
    }

    #[test]
    fn ratios_are_per_case_against_clipper2() {
        let rows = vec![
            m("clipper2", "0", 0, 100.0),
            m("clipper2", "1", 0, 1000.0),
            m("vatti", "0", 0, 50.0),
            m("vatti", "1", 0, 2000.0),
            m("geo", "0", 0, 400.0),
            m("geo", "1", 0, 4000.0),
        ];
        let p = points(&rows);
        let v = &p[&("star".into(), "intersection".into(), 20, "vatti".into())];
        assert!((v.ratio - 1.0).abs() < 1e-12, "geometric mean of 0.5 and 2");
        assert_eq!(v.time_ns, 1025.0);
        let text = vatti_ratios(&p, &["star".to_owned()]);
        // Two cases at 0.5 and 2: a resample of cases can hold either twice.
        assert!(text.contains("20: 1.00 (0.50-2.00) x clipper2, 0.47 x geo"), "{text}");
    }

    #[test]
    fn faster_at_k_of_n_counts_only_sizes_whose_interval_excludes_one() {
        // A synthetic bench.csv: vatti at half Clipper2's time at 4 edges, twice at 100, and at
        // 20 edges 0.9 on the median but with rounds from 0.6 to 1.4: not a win.
        let mut rows = Vec::new();
        let noisy = [0.6, 0.9, 1.4, 0.7, 1.3, 0.8, 1.2];
        for (size, factors) in [(4, [0.5; 7]), (20, noisy), (100, [2.0; 7])] {
            for case in ["0", "1", "2"] {
                for (rep, f) in factors.iter().enumerate() {
                    let at = |clipper: &str, ns: f64| Measurement { size, ..m(clipper, case, rep, ns) };
                    rows.extend([at("clipper2", 1000.0), at("vatti", 1000.0 * f), at("geo", 3000.0)]);
                }
            }
        }
        let dir = std::env::temp_dir().join(format!("clipbench-wording-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        crate::measure::raw::write_csv(&dir.join(CSV), &rows).unwrap();
        let read: Vec<Measurement> = read_csv(&dir.join(CSV)).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        let p = points(&read);
        let at = |size| p[&("star".to_owned(), "intersection".to_owned(), size, "vatti".to_owned())].ratio_interval;
        assert!(at(4).below(1.0) && at(100).above(1.0), "{:?} {:?}", at(4), at(100));
        assert!(at(20).estimate < 1.0 && at(20).low < 1.0 && at(20).high > 1.0, "{:?}", at(20));
        let text = vatti_ratios(&p, &["star".to_owned()]);
        assert!(
            text.contains("against clipper2 faster at 1 of 3 sizes, slower at 1, indistinguishable at 1"),
            "{text}"
        );
        // The intervals reach bench-points.csv and the plot's bars.
        let records = point_records(&p);
        let vatti_at_4 = records.iter().find(|r| r.clipper == "vatti" && r.size == 4).unwrap();
        assert!(vatti_at_4.ratio_high.is_some_and(|h| h < 1.0), "{vatti_at_4:?}");
        let chart = chart(&p, "star", &["vatti".to_owned()]);
        assert_eq!(chart.series[0].spread.len(), 3);
    }

    #[test]
    fn a_wrong_case_takes_the_point_out_of_the_ratios_and_tables() {
        let wrong = |r: Measurement| Measurement { correct: Some(false), ..r };
        let rows = vec![
            m("clipper2", "0", 0, 100.0),
            m("clipper2", "1", 0, 1000.0),
            m("vatti", "0", 0, 50.0),
            wrong(m("vatti", "1", 0, 20.0)),
            m("geo", "0", 0, 400.0),
            m("geo", "1", 0, 4000.0),
        ];
        let p = points(&rows);
        let v = &p[&("star".into(), "intersection".into(), 20, "vatti".into())];
        assert!(!v.trusted() && v.ratio.is_nan() && v.wrong_cases == 1 && v.cases == 2, "{v:?}");
        assert!(p[&("star".into(), "intersection".into(), 20, "geo".into())].trusted());
        assert_eq!(vatti_ratios(&p, &["star".to_owned()]), "");
        let clippers = ["clipper2", "vatti", "geo"].map(String::from);
        let t = group_table(&p, "star", "intersection", &clippers).unwrap();
        assert!(t.contains("| wrong on 1 of 2 cases |"), "{t}");
        let chart = chart(&p, "star", &clippers);
        assert!(chart.series.iter().all(|s| s.label != "vatti"), "a wrong point is not drawn");
    }

    #[test]
    fn rectangle_clippers_are_compared_with_clipper2_rect_case_by_case() {
        let rows = vec![
            m("clipper2", "0", 0, 100.0),
            m("clipper2", "1", 0, 1000.0),
            m("clipper2-rect", "0", 0, 10.0),
            m("clipper2-rect", "1", 0, 400.0),
            m("sutherland-hodgman", "0", 0, 5.0),
            m("sutherland-hodgman", "1", 0, 800.0),
        ];
        let text = rect_clip_ratios(&points(&rows), &["star".to_owned()]);
        // Per case 0.5 and 2: geometric mean 1.
        assert_eq!(text, "- star, x clipper2-rect: 20: sutherland-hodgman 1.00.\n");
    }

    #[test]
    fn memory_has_a_column_per_clipper_and_a_row_per_size() {
        let rec = |clipper: &str, size, case: &str, kib| MemoryRecord {
            workload: "large-smooth".into(),
            case: case.into(),
            clipper: clipper.into(),
            size,
            op: "intersection".into(),
            rss_before_kib: 6000,
            peak_extra_kib: kib,
        };
        let records = vec![
            rec("vatti", 1000, "0", 512),
            rec("vatti", 1000, "1", 1024),
            rec("clipper2", 1000, "0", 2048),
            rec("geo", 10, "0", 1),
        ];
        let clippers = vec!["vatti".to_owned(), "geo".to_owned(), "clipper2".to_owned()];
        let t = memory_table(&records, "large-smooth", &clippers).unwrap();
        assert!(t.contains("| 1000 | 1.0 (0.50) | n/a | 2.0 (1.00) |"), "{t}");
        assert!(t.contains("| 10 | n/a | 0.0 | n/a |"), "{t}");
        assert!(memory_table(&records, "star", &clippers).is_none());
    }
}
