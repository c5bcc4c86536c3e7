//! REPORT.md's opening summary: per kind of clipper (polygon, line, curve, text), each clipper's
//! origin, its oracle failures across every workload verified, its wrong answers in the bench,
//! its speed against Clipper2 with an interval at small and large sizes, and its peak memory;
//! then one picture of trust against speed.

use std::collections::BTreeMap;

use super::bench_points::{Point, Points};
use super::derived::Derived;
use super::markdown::{num, num_interval, table};
use super::results_folder::ResultsFolder;
use crate::cli_error::CliError;
use crate::measure::interval::Interval;
use crate::measure::timing::geometric_mean;
use crate::plot::chart::{Chart, Series};
use crate::plot::palette::clipper_colour;
use crate::registry::Registry;
use crate::results_files::bench::{BASELINE, MemoryRecord};
use crate::results_files::verify::VerifyRow;

/// The trust-against-speed plot.
pub const PLOT: &str = "summary-trust-speed.svg";

/// Sizes from this one on count as large in the speed columns.
pub const LARGE_FROM: usize = 1000;

/// The kinds, in the order of their tables.
const KINDS: [&str; 4] = ["polygon", "line", "curve", "text"];

/// The language of this project's clippers and of the registered peers (external clippers say
/// theirs in adapters/).
pub fn language(clipper: &str, origin: &str) -> &'static str {
    match clipper {
        "clipper2" | "clipper2-rect" | "clipper2-open" | "clipper1" => "C++",
        "geos" => "C++, GEOS",
        _ if origin == "ours" || origin == "peer" => "Rust",
        _ => "see adapters/",
    }
}

/// One clipper's line of the summary.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SummaryRow {
    /// Clipper name.
    pub clipper: String,
    /// `ours`, `peer`, `external` or `strict`.
    pub origin: String,
    /// Oracle failures and checked results, summed over the workloads verified.
    pub verified: Option<(usize, usize)>,
    /// Of those results, the ones an external clipper gave no answer to in time (not oracle failures).
    pub hung: usize,
    /// Bench points with a wrong case, and points timed.
    pub bench_wrong: Option<(usize, usize)>,
    /// Geometric mean of its ratios to Clipper2 below [`LARGE_FROM`] edges, with the geometric
    /// means of the points' interval ends.
    pub speed_small: Option<Interval>,
    /// Likewise from [`LARGE_FROM`] edges on.
    pub speed_large: Option<Interval>,
    /// Geometric mean over groups and sizes of its peak memory over Clipper2's.
    pub memory: Option<f64>,
}

/// The geometric mean of the points' ratio estimates, and of their lower and upper ends.
fn speed(points: &[&Interval]) -> Option<Interval> {
    let kept: Vec<&&Interval> = points.iter().filter(|i| i.is_finite() && i.low > 0.0).collect();
    if kept.is_empty() {
        return None;
    }
    let of = |f: fn(&Interval) -> f64| geometric_mean(&kept.iter().map(|i| f(i)).collect::<Vec<_>>());
    Some(Interval { estimate: of(|i| i.estimate), low: of(|i| i.low), high: of(|i| i.high) })
}

/// Every clipper's row, per kind: verify's rows first in their order, then clippers only benched.
pub fn rows(verify: &[VerifyRow], bench: &Points, memory: &[MemoryRecord]) -> BTreeMap<&'static str, Vec<SummaryRow>> {
    let mut by_kind: BTreeMap<&'static str, Vec<SummaryRow>> = BTreeMap::new();
    let kind_of = |k: &str| KINDS.iter().copied().find(|&x| x == k);
    for r in verify {
        let Some(kind) = kind_of(&r.kind) else { continue };
        let rows = by_kind.entry(kind).or_default();
        let row = match rows.iter_mut().position(|x| x.clipper == r.clipper) {
            Some(i) => &mut rows[i],
            None => {
                rows.push(SummaryRow { clipper: r.clipper.clone(), origin: r.origin.clone(), ..SummaryRow::default() });
                rows.last_mut().expect("just pushed")
            }
        };
        let (failures, runs) = row.verified.unwrap_or((0, 0));
        row.verified = Some((failures + r.oracle_failures, runs + r.runs));
        row.hung += r.hung;
    }
    let registry = crate::registry::registry();
    let mut benched: Vec<&str> = Vec::new();
    for (_, _, _, clipper) in bench.keys() {
        if !benched.contains(&clipper.as_str()) {
            benched.push(clipper);
        }
    }
    for clipper in benched {
        let rows = by_kind.entry("polygon").or_default();
        let row = match rows.iter_mut().position(|x| x.clipper == clipper) {
            Some(i) => &mut rows[i],
            None => {
                let origin = registered_origin(&registry, clipper).to_owned();
                rows.push(SummaryRow { clipper: clipper.to_owned(), origin, ..SummaryRow::default() });
                rows.last_mut().expect("just pushed")
            }
        };
        let mine: Vec<(usize, &Point)> = bench.iter().filter(|(k, _)| k.3 == clipper).map(|(k, p)| (k.2, p)).collect();
        row.bench_wrong = Some((mine.iter().filter(|(_, p)| !p.trusted()).count(), mine.len()));
        let ratios = |large: bool| -> Vec<&Interval> {
            mine.iter()
                .filter(|(size, p)| p.trusted() && (*size >= LARGE_FROM) == large)
                .map(|(_, p)| &p.ratio_interval)
                .collect()
        };
        // The baseline is 1 by definition wherever it was timed.
        let speed_of = |large: bool| {
            let r = ratios(large);
            if clipper == BASELINE { (!r.is_empty()).then(|| Interval::exact(1.0)) } else { speed(&r) }
        };
        row.speed_small = speed_of(false);
        row.speed_large = speed_of(true);
        row.memory = memory_ratio(memory, clipper);
    }
    by_kind
}

/// Geometric mean over (group, size) of the clipper's peak (largest over cases) over Clipper2's.
fn memory_ratio(records: &[MemoryRecord], clipper: &str) -> Option<f64> {
    let mut peaks: BTreeMap<(&str, usize, &str), u64> = BTreeMap::new();
    for r in records {
        let peak = peaks.entry((r.workload.as_str(), r.size, r.clipper.as_str())).or_default();
        *peak = (*peak).max(r.peak_extra_kib);
    }
    let ratios: Vec<f64> = peaks
        .iter()
        .filter(|((_, _, c), _)| *c == clipper)
        .filter_map(|((g, s, _), &k)| {
            peaks.get(&(*g, *s, BASELINE)).filter(|&&b| b > 0 && k > 0).map(|&b| k as f64 / b as f64)
        })
        .collect();
    (!ratios.is_empty()).then(|| geometric_mean(&ratios))
}

/// The origin label of a registered clipper; `external` for any other name (bench and verify
/// know no other kind).
fn registered_origin(registry: &Registry, name: &str) -> &'static str {
    let polygon = registry.find_polygon(name).map(|e| e.origin);
    let line = registry.find_line(name).map(|e| e.origin);
    let curve = registry.curve.iter().find(|e| e.clipper.name() == name).map(|e| e.origin);
    polygon.or(line).or(curve).map_or("external", |o| o.label())
}

/// The markdown table of one kind.
fn kind_table(rows: &[SummaryRow]) -> String {
    let head: Vec<String> = [
        "Clipper",
        "Origin (language)",
        "Oracle failures / results checked",
        "Bench points wrong / timed",
        &format!("Speed x {BASELINE}, < {LARGE_FROM} edges"),
        &format!("Speed x {BASELINE}, >= {LARGE_FROM} edges"),
        &format!("Peak memory x {BASELINE}"),
    ]
    .iter()
    .map(|s| (*s).to_owned())
    .collect();
    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            let pair = |p: Option<(usize, usize)>| {
                p.map_or("–".to_owned(), |(k, n)| if k > 0 { format!("**{k} / {n}**") } else { format!("{k} / {n}") })
            };
            vec![
                format!("`{}`", r.clipper),
                format!("{} ({})", r.origin, language(&r.clipper, &r.origin)),
                with_hung(pair(r.verified), r.hung),
                pair(r.bench_wrong),
                r.speed_small.map_or("–".to_owned(), |i| num_interval(&i, 2)),
                r.speed_large.map_or("–".to_owned(), |i| num_interval(&i, 2)),
                r.memory.map_or("–".to_owned(), |m| num(m, 2)),
            ]
        })
        .collect();
    table(&head, &body)
}

/// A count cell with its hangs beside it ("12 / 3200, 3 hung"), shown only when there are some.
pub fn with_hung(cell: String, hung: usize) -> String {
    if hung > 0 { format!("{cell}, {hung} hung") } else { cell }
}

/// Trust (share of checked results the oracle accepted) against speed (the overall geometric
/// mean ratio to Clipper2, small and large sizes together), one point per polygon clipper with
/// both.
pub fn chart(rows: &[SummaryRow]) -> Chart {
    let series = rows
        .iter()
        .filter_map(|r| {
            // Trust is over the results answered in time: a hang is not a wrong answer.
            let (failures, runs) = r.verified.map(|(f, n)| (f, n - r.hung.min(n))).filter(|v| v.1 > 0)?;
            let speeds: Vec<f64> = [r.speed_small, r.speed_large].iter().flatten().map(|i| i.estimate).collect();
            let speed = (!speeds.is_empty()).then(|| geometric_mean(&speeds))?;
            let trust = 100.0 * (1.0 - failures as f64 / runs as f64);
            Some(Series {
                label: r.clipper.clone(),
                colour: clipper_colour(&r.clipper),
                points: vec![(speed, trust)],
                paper: false,
                spread: Vec::new(),
            })
        })
        .collect();
    Chart {
        title: format!("Polygon clippers: results the oracle accepted against time relative to {BASELINE}"),
        x_label: format!("time per call x {BASELINE} (geometric mean over bench points; log scale; left is faster)"),
        y_label: "results the oracle accepted (% of those answered in time)".to_owned(),
        log_x: true,
        log_y: false,
        x_ticks: Vec::new(),
        series,
    }
}

/// The summary section and its plot; `None` when the folder holds neither verify nor bench
/// results.
pub fn derive(folder: &ResultsFolder) -> Result<Option<Derived>, CliError> {
    let verify = folder.verify()?.map_or(&[][..], |v| v.rows.as_slice());
    if verify.is_empty() && folder.polygon_bench_rows()?.is_empty() {
        return Ok(None);
    }
    let by_kind = rows(verify, folder.bench_points()?, folder.bench_memory()?);
    let mut text = format!(
        "Per kind of clipper: where it comes from; the results the exact oracle rejected out of those it checked, \
         over every workload `verify` ran (section \"Where the clippers disagree with the oracle\"); the bench points \
         where it answered wrongly (those count in no ratio); its time relative to `{BASELINE}` as the geometric mean \
         of its bench ratios below and from {LARGE_FROM} edges, with the geometric means of the points' 95% interval \
         ends in brackets; and its peak memory relative to `{BASELINE}` on the large cases. – : not measured.\n\n"
    );
    for kind in KINDS {
        if let Some(rows) = by_kind.get(kind).filter(|r| !r.is_empty()) {
            text.push_str(&format!("{kind} clippers:\n\n{}\n", kind_table(rows)));
        }
    }
    let chart = by_kind.get("polygon").map(|polygon| chart(polygon)).filter(|c| !c.series.is_empty());
    if chart.is_some() {
        text.push_str(&format!("![trust against speed]({PLOT})\n\n"));
    }
    let derived = Derived::new(text);
    Ok(Some(match chart {
        Some(chart) => derived.with_plot(PLOT, chart),
        None => derived,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn verify_row(clipper: &str, origin: &str, kind: &str, failures: usize, runs: usize) -> VerifyRow {
        VerifyRow {
            clipper: clipper.into(),
            origin: origin.into(),
            kind: kind.into(),
            workload: "star".into(),
            runs,
            oracle_failures: failures,
            ..VerifyRow::default()
        }
    }

    fn point(estimate: f64, wrong_cases: usize) -> Point {
        let ratio_interval = Interval { estimate, low: estimate * 0.9, high: estimate * 1.1 };
        Point {
            time_ns: 1.0,
            ratio: estimate,
            time_interval: Interval::exact(1.0),
            ratio_interval,
            rounds: 7,
            cases: 3,
            wrong_cases,
        }
    }

    #[test]
    fn one_row_per_clipper_and_kind_with_failures_wrong_points_and_speeds() {
        let verify = vec![
            verify_row("vatti", "ours", "polygon", 0, 100),
            verify_row("vatti", "ours", "polygon", 2, 50),
            verify_row("clipper2", "peer", "polygon", 1, 150),
            verify_row("liu", "ours", "line", 0, 30),
        ];
        let key = |size: usize, c: &str| ("star".to_owned(), "intersection".to_owned(), size, c.to_owned());
        let bench: Points = [
            (key(20, "vatti"), point(0.5, 0)),
            (key(200, "vatti"), point(2.0, 0)),
            (key(1000, "vatti"), point(4.0, 0)),
            (key(20, "liar"), point(0.1, 3)),
            (key(20, "clipper2"), point(1.0, 0)),
        ]
        .into_iter()
        .collect();
        let rows = rows(&verify, &bench, &[]);
        let polygon = &rows["polygon"];
        let vatti = polygon.iter().find(|r| r.clipper == "vatti").unwrap();
        assert_eq!(vatti.verified, Some((2, 150)));
        assert_eq!(vatti.bench_wrong, Some((0, 3)));
        assert!((vatti.speed_small.unwrap().estimate - 1.0).abs() < 1e-12, "geometric mean of 0.5 and 2");
        assert!((vatti.speed_large.unwrap().estimate - 4.0).abs() < 1e-12);
        let liar = polygon.iter().find(|r| r.clipper == "liar").unwrap();
        assert_eq!((liar.bench_wrong, liar.speed_small, liar.verified), (Some((1, 1)), None, None));
        assert_eq!(liar.origin, "external", "a name the registry does not know");
        assert_eq!(rows["line"].len(), 1);
        let table = kind_table(polygon);
        assert!(
            table.contains("| `vatti` | ours (Rust) | **2 / 150** | 0 / 3 | 1.00 (0.90-1.10) | 4.00 (3.60-4.40) | – |"),
            "{table}"
        );
        // The liar is not placed on the trust-against-speed picture: it has no speed.
        let labels: Vec<String> = chart(polygon).series.into_iter().map(|s| s.label).collect();
        assert_eq!(labels, ["vatti", "clipper2"]);
    }

    #[test]
    fn hangs_are_shown_beside_the_failures_and_left_out_of_trust() {
        let mut slow = verify_row("slow", "external", "polygon", 1, 100);
        slow.hung = 50;
        let bench: Points = [(("star".to_owned(), "intersection".to_owned(), 20, "slow".to_owned()), point(2.0, 0))]
            .into_iter()
            .collect();
        let rows = rows(&[slow], &bench, &[]);
        let polygon = &rows["polygon"];
        assert_eq!((polygon[0].verified, polygon[0].hung), (Some((1, 100)), 50));
        let table = kind_table(polygon);
        assert!(table.contains("| `slow` | external (see adapters/) | **1 / 100**, 50 hung |"), "{table}");
        // 1 wrong of the 50 answered: 98%, not 99% of 100 nor 49% as if the hangs were wrong.
        let trust = chart(polygon).series[0].points[0].1;
        assert!((trust - 98.0).abs() < 1e-9, "{trust}");
    }
}
