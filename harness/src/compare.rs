//! `clipbench compare OLD NEW`: did a change make a clipper faster or slower? Per bench point,
//! the change of each clipper's ratio to Clipper2 from one results folder to another, with an
//! interval; changes beyond the noise are flagged, and a regression beyond a threshold exits
//! non-zero so a CI job can gate on it.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use crate::cli_error::CliError;
use crate::measure::interval::Interval;
use crate::measure::raw::{Measurement, read_csv};
use crate::report::bench_points::{Point, Points, points};
use crate::report::markdown::{header, num_interval, table};
use crate::results_files::bench::{BASELINE, CSV, TEXT_GROUP};

/// Arguments of `clipbench compare`.
#[derive(Debug, clap::Args)]
pub struct CompareArgs {
    /// The earlier results folder (its bench.csv).
    pub old: PathBuf,
    /// The later results folder (its bench.csv).
    pub new: PathBuf,
    /// Exit with status 1 when some clipper's ratio to Clipper2 grew by more than this fraction
    /// (0.10: 10% slower) with its whole interval above no change, or when a point that was right
    /// became wrong.
    #[arg(long, default_value_t = 0.10, value_name = "FRACTION")]
    pub max_regression: f64,
    /// List every point compared, not only those that moved beyond the noise.
    #[arg(long)]
    pub all: bool,
}

/// How a point moved.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// The ratio's change interval lies wholly above 1.
    Regression,
    /// Wholly below 1.
    Improvement,
    /// It crosses 1.
    WithinNoise,
    /// Right before, wrong now.
    NowWrong,
    /// Wrong before, right now.
    NowRight,
}

/// One point in both runs.
#[derive(Clone, Debug, PartialEq)]
pub struct Change {
    /// (group, op, size, clipper).
    pub key: (String, String, usize, String),
    /// The old ratio to Clipper2.
    pub old: Interval,
    /// The new one.
    pub new: Interval,
    /// new / old, from the two intervals' ends (wide: the two runs are independent).
    pub change: Interval,
    /// How it moved.
    pub verdict: Verdict,
}

/// Every clipper's point present in both runs, Clipper2's own excepted (its ratio is 1 by
/// definition), with its change.
pub fn changes(old: &Points, new: &Points) -> Vec<Change> {
    old.iter()
        .filter(|((_, _, _, clipper), _)| clipper != BASELINE)
        .filter_map(|(key, o)| new.get(key).map(|n| (key, o, n)))
        .filter_map(|(key, o, n)| {
            let verdict = match (o.trusted(), n.trusted()) {
                (true, false) => Some(Verdict::NowWrong),
                (false, true) => Some(Verdict::NowRight),
                (false, false) => None,
                (true, true) => Some(Verdict::WithinNoise),
            }?;
            let change = ratio_change(o, n);
            if verdict == Verdict::WithinNoise && !change.is_finite() {
                return None;
            }
            let verdict = match verdict {
                Verdict::WithinNoise if change.above(1.0) => Verdict::Regression,
                Verdict::WithinNoise if change.below(1.0) => Verdict::Improvement,
                v => v,
            };
            Some(Change { key: key.clone(), old: o.ratio_interval, new: n.ratio_interval, change, verdict })
        })
        .collect()
}

/// new / old with the interval from the ends: the lowest new over the highest old, and back.
fn ratio_change(old: &Point, new: &Point) -> Interval {
    let (o, n) = (old.ratio_interval, new.ratio_interval);
    Interval { estimate: n.estimate / o.estimate, low: n.low / o.high, high: n.high / o.low }
}

/// Whether `c` fails the gate: a regression beyond `max_regression`, or a right point gone wrong.
pub fn fails_gate(c: &Change, max_regression: f64) -> bool {
    match c.verdict {
        Verdict::Regression => c.change.estimate > 1.0 + max_regression,
        Verdict::NowWrong => true,
        _ => false,
    }
}

/// The markdown report: a summary line, then the table of points.
pub fn markdown(changes: &[Change], max_regression: f64, all: bool) -> String {
    let count = |v: Verdict| changes.iter().filter(|c| c.verdict == v).count();
    let gated = changes.iter().filter(|c| fails_gate(c, max_regression)).count();
    let mut text = format!(
        "{} points compared (ratio to `{BASELINE}`, 95% intervals): {} regressions, {} improvements, {} within the \
         noise, {} now wrong, {} now right; {gated} beyond the gate (slower by over {:.0}%, or now wrong).\n\n",
        changes.len(),
        count(Verdict::Regression),
        count(Verdict::Improvement),
        count(Verdict::WithinNoise),
        count(Verdict::NowWrong),
        count(Verdict::NowRight),
        max_regression * 100.0
    );
    let shown: Vec<&Change> = changes.iter().filter(|c| all || c.verdict != Verdict::WithinNoise).collect();
    if shown.is_empty() {
        text.push_str("No change beyond the noise.\n");
        return text;
    }
    let head = header(&["Group", "Op", "Edges", "Clipper", "Old x clipper2", "New x clipper2", "Change", "Verdict"]);
    let body: Vec<Vec<String>> = shown
        .iter()
        .map(|c| {
            let (g, op, size, clipper) = &c.key;
            let verdict = match c.verdict {
                Verdict::Regression if fails_gate(c, max_regression) => "**regression**",
                Verdict::Regression => "regression (under the gate)",
                Verdict::Improvement => "improvement",
                Verdict::WithinNoise => "within the noise",
                Verdict::NowWrong => "**now wrong**",
                Verdict::NowRight => "now right",
            };
            vec![
                g.clone(),
                op.clone(),
                size.to_string(),
                clipper.clone(),
                num_interval(&c.old, 2),
                num_interval(&c.new, 2),
                num_interval(&c.change, 2),
                verdict.to_owned(),
            ]
        })
        .collect();
    text.push_str(&table(&head, &body));
    text
}

/// The bench points of one results folder (the text group aside: it has no Clipper2 ratio).
fn read_points(dir: &Path) -> Result<Points, CliError> {
    let csv = dir.join(CSV);
    if !csv.exists() {
        return Err(CliError::usage(format!(
            "{}: no {CSV} (run `clipbench bench --out {}`)",
            dir.display(),
            dir.display()
        )));
    }
    let rows: Vec<Measurement> =
        read_csv(&csv)?.into_iter().filter(|r: &Measurement| r.workload != TEXT_GROUP).collect();
    Ok(points(&rows))
}

/// Prints the comparison; exit status 1 when the gate fails.
pub fn run(args: &CompareArgs) -> Result<ExitCode, CliError> {
    if !(args.max_regression.is_finite() && args.max_regression >= 0.0) {
        return Err(CliError::usage("--max-regression must be a fraction of at least 0 (0.10 for 10%)"));
    }
    let changes = changes(&read_points(&args.old)?, &read_points(&args.new)?);
    if changes.is_empty() {
        return Err(CliError::failed(format!(
            "{} and {} share no bench point to compare (same groups, sizes, operations and clippers needed)",
            args.old.display(),
            args.new.display()
        )));
    }
    crate::console::print(&markdown(&changes, args.max_regression, args.all))?;
    let failed = changes.iter().any(|c| fails_gate(c, args.max_regression));
    Ok(if failed { ExitCode::FAILURE } else { ExitCode::SUCCESS })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(low: f64, estimate: f64, high: f64, wrong_cases: usize) -> Point {
        let ratio_interval = Interval { estimate, low, high };
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
    fn changes_beyond_both_intervals_are_flagged_and_only_big_regressions_fail_the_gate() {
        let key = |size: usize, clipper: &str| ("star".to_owned(), "intersection".to_owned(), size, clipper.to_owned());
        let old: Points = [
            (key(4, "vatti"), point(0.9, 1.0, 1.1, 0)),
            (key(20, "vatti"), point(0.9, 1.0, 1.1, 0)),
            (key(40, "vatti"), point(0.9, 1.0, 1.1, 0)),
            (key(100, "vatti"), point(0.9, 1.0, 1.1, 0)),
            (key(200, "vatti"), point(0.9, 1.0, 1.1, 0)),
            (key(4, "clipper2"), point(1.0, 1.0, 1.0, 0)),
        ]
        .into_iter()
        .collect();
        let new: Points = [
            (key(4, "vatti"), point(0.95, 1.05, 1.15, 0)),
            (key(20, "vatti"), point(1.5, 1.6, 1.7, 0)),
            (key(40, "vatti"), point(1.13, 1.15, 1.2, 0)),
            (key(100, "vatti"), point(0.5, 0.6, 0.7, 0)),
            (key(200, "vatti"), point(0.9, 1.0, 1.1, 1)),
            (key(4, "clipper2"), point(1.0, 1.0, 1.0, 0)),
        ]
        .into_iter()
        .collect();
        let c = changes(&old, &new);
        let verdicts: Vec<(usize, Verdict)> = c.iter().map(|c| (c.key.2, c.verdict)).collect();
        assert_eq!(
            verdicts,
            [
                (4, Verdict::WithinNoise),
                (20, Verdict::Regression),
                (40, Verdict::Regression),
                (100, Verdict::Improvement),
                (200, Verdict::NowWrong)
            ]
        );
        let gated: Vec<usize> = c.iter().filter(|c| fails_gate(c, 0.10)).map(|c| c.key.2).collect();
        assert_eq!(gated, [20, 40, 200]);
        let gated: Vec<usize> = c.iter().filter(|c| fails_gate(c, 0.5)).map(|c| c.key.2).collect();
        assert_eq!(gated, [20, 200]);
        let text = markdown(&c, 0.5, false);
        assert!(text.starts_with("5 points compared"), "{text}");
        assert!(text.contains("| star | intersection | 20 | vatti | 1.00 (0.90-1.10) | 1.60 (1.50-1.70) |"), "{text}");
        assert!(!text.contains("| 4 | vatti"), "a change within the noise is listed only with --all: {text}");
        let same = changes(&old, &old);
        assert!(same.iter().all(|c| c.verdict == Verdict::WithinNoise), "{same:?}");
        assert!(markdown(&same, 0.1, false).contains("No change beyond the noise."));
    }
}
