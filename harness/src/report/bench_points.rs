//! The bench's points from its raw rows: per group, operation, size and clipper, the time per
//! call and the ratio to Clipper2, each with a seeded bootstrap interval. Shared by the bench's
//! tables, the summary and `compare`, so the bootstrap is written (and, per report, run) once.

use std::collections::BTreeMap;

use crate::measure::interval::{CaseSamples, Interval, bootstrap, geometric_mean_ratio, mean_time, seed_of};
use crate::measure::raw::Measurement;
use crate::results_files::bench::{BASELINE, PointRecord};

/// One point: a clipper on a group's size and operation.
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// Time per call in ns: mean over cases of the median over rounds.
    pub time_ns: f64,
    /// Geometric mean over cases of (this clipper's median / Clipper2's median on the same case);
    /// NaN where Clipper2 has no time.
    pub ratio: f64,
    /// [`Point::time_ns`] with its 95% bootstrap interval (over cases and rounds).
    pub time_interval: Interval,
    /// [`Point::ratio`] with its 95% bootstrap interval (over cases and both clippers' rounds).
    pub ratio_interval: Interval,
    /// Rounds behind the medians (1 for a point over the cap).
    pub rounds: usize,
    /// Cases behind the point.
    pub cases: usize,
    /// Cases whose result the bench's check found wrong (bench.csv's `correct` column): a point
    /// with any is shown as "wrong on k of n cases", with no time or ratio.
    pub wrong_cases: usize,
}

impl Point {
    /// Whether its time and ratio count: no case was found wrong.
    pub fn trusted(&self) -> bool {
        self.wrong_cases == 0
    }
}

/// Points keyed by (group, op, size, clipper).
pub type Points = BTreeMap<(String, String, usize, String), Point>;

/// Computes every point from raw rows, with seeded bootstrap intervals over cases and rounds.
pub fn points<'a>(rows: impl IntoIterator<Item = &'a Measurement>) -> Points {
    // Per point, per case: the rounds' times and whether the result was found wrong.
    type Cases = BTreeMap<String, (Vec<f64>, bool)>;
    let mut grouped: BTreeMap<(String, String, usize, String), Cases> = BTreeMap::new();
    for r in rows {
        let point = grouped.entry((r.workload.clone(), r.op.clone(), r.size, r.clipper.clone())).or_default();
        let case = point.entry(r.case.clone()).or_default();
        case.0.push(r.time_ns);
        case.1 |= r.correct == Some(false);
    }
    let none = Cases::new();
    grouped
        .iter()
        .map(|((g, op, size, clipper), cases)| {
            let baseline = grouped.get(&(g.clone(), op.clone(), *size, BASELINE.to_owned())).unwrap_or(&none);
            // A ratio needs a right answer on both sides of the case.
            let samples: Vec<CaseSamples> = cases
                .iter()
                .map(|(case, (times, wrong))| CaseSamples {
                    times,
                    baseline: baseline
                        .get(case)
                        .filter(|(_, base_wrong)| !*wrong && !*base_wrong)
                        .map(|(b, _)| b.as_slice()),
                })
                .collect();
            let seed = seed_of(&format!("{g}/{op}/{size}/{clipper}"));
            let nan = Interval::exact(f64::NAN);
            let time_interval = bootstrap(&samples, seed, mean_time).unwrap_or(nan);
            let ratio_interval = bootstrap(&samples, seed, geometric_mean_ratio).unwrap_or(nan);
            let point = Point {
                time_ns: time_interval.estimate,
                ratio: ratio_interval.estimate,
                time_interval,
                ratio_interval,
                rounds: cases.values().map(|c| c.0.len()).min().unwrap_or(0),
                cases: cases.len(),
                wrong_cases: cases.values().filter(|c| c.1).count(),
            };
            ((g.clone(), op.clone(), *size, clipper.clone()), point)
        })
        .collect()
}

/// The rows of [`POINTS_CSV`]: every point with its intervals.
pub fn point_records(points: &Points) -> Vec<PointRecord> {
    let finite = |v: f64| v.is_finite().then_some(v);
    points
        .iter()
        .map(|((workload, op, size, clipper), p)| PointRecord {
            workload: workload.clone(),
            op: op.clone(),
            size: *size,
            clipper: clipper.clone(),
            cases: p.cases,
            wrong_cases: p.wrong_cases,
            rounds: p.rounds,
            time_ns: p.time_interval.estimate,
            time_low_ns: p.time_interval.low,
            time_high_ns: p.time_interval.high,
            ratio: finite(p.ratio_interval.estimate),
            ratio_low: finite(p.ratio_interval.low),
            ratio_high: finite(p.ratio_interval.high),
        })
        .collect()
}
