//! The bench's measuring loop: per group, size and operation, every applicable clipper on every
//! case in interleaved rounds, with a time cap per point and peak memory for large cases.

use std::cell::OnceCell;
use std::collections::BTreeMap;
use std::hint::black_box;
use std::time::Duration;

use clip_core::{BoolOp, FillRule, PolygonClipper, Polygons};
use clip_oracle::polygon::{region_area_work, same_region};
use clip_testkit::workload::{PolygonCase, polygon_case_sized};

use super::checkpoint::{Checkpoint, FinishedGroup};
use super::correctness::{CHECK_WORK, Judge, Verdict};
use super::memory_probe::Probe;
use super::plan::Group;
use crate::cli_error::CliError;
use crate::measure::progress::bar;
use crate::measure::raw::Measurement;
use crate::measure::timing::{iterations_for, per_call_ns, timed};
use crate::registry::{PolygonEntry, Registry};
use crate::results_files::bench::{MemoryRecord, own_time_name};

/// Every case is read under this rule (the papers' parity rule). A clipper that reads only
/// non-zero (Clipper 1) is timed under non-zero where every operand covers the same region under
/// both rules, so it does the same operation as the others.
const FILL: FillRule = FillRule::EvenOdd;

/// A call longer than this many caps is a long one. A clipper whose time, extrapolated from its
/// last sizes ([`predicted_seconds`]), is long is not started at the next size. One found long
/// when it runs (a peer's cost can grow faster than its smaller sizes showed: Clipper 1's joins
/// on a map's shared borders) is not called again at that point: its warm-up call is its one
/// timing, and no child process repeats it for peak memory.
const PREDICTED_CAP_FACTOR: f64 = 15.0;

/// One call's time at `size` extrapolated from the last two sizes timed (`earlier`, `last`): with
/// the growth exponent they show, never below linear, so a clipper quadratic in its input (an
/// O(n·m) window clipper on a large window) is not predicted to grow linearly and started on a
/// call of many minutes. With one size timed, linear.
fn predicted_seconds(earlier: Option<(usize, Duration)>, last: (usize, Duration), size: usize) -> f64 {
    let (last_size, last_time) = last;
    let exponent = earlier
        .filter(|&(n, t)| n < last_size && t > Duration::ZERO && last_time > t)
        .map(|(n, t)| (last_time.as_secs_f64() / t.as_secs_f64()).ln() / (last_size as f64 / n as f64).ln())
        .map_or(1.0, |e| e.max(1.0));
    last_time.as_secs_f64() * (size as f64 / last_size as f64).powf(exponent)
}

/// How much to measure.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Seed of the cases.
    pub seed: u64,
    /// Timed rounds per point.
    pub rounds: usize,
    /// A clipper whose single call exceeds this skips the group's larger sizes.
    pub cap_seconds: f64,
    /// Shorter measurements.
    pub quick: bool,
}

/// What a bench run measured.
pub struct Measured {
    /// Timings.
    pub rows: Vec<Measurement>,
    /// Peak memory of the large groups.
    pub memory: Vec<MemoryRecord>,
    /// Skipped points and why.
    pub notes: Vec<String>,
}

/// Why a clipper stopped early in a group.
struct Stopped {
    size: usize,
    reason: String,
}

/// A clipper's verdicts in one group: results wrong and unchecked, out of those judged, and the
/// first of each with where it happened.
#[derive(Default)]
struct Tally {
    judged: usize,
    wrong: usize,
    first_wrong: Option<String>,
    unchecked: usize,
    first_unchecked: Option<String>,
    sampled: usize,
}

impl Tally {
    fn add(&mut self, verdict: &Verdict, at: impl FnOnce() -> String) {
        self.judged += 1;
        match verdict {
            Verdict::Right => {}
            Verdict::RightAtSamples => self.sampled += 1,
            Verdict::Wrong(why) => {
                self.wrong += 1;
                self.first_wrong.get_or_insert_with(|| format!("{}: {why}", at()));
            }
            Verdict::Unchecked(why) => {
                self.unchecked += 1;
                self.first_unchecked.get_or_insert_with(|| format!("{}: {why}", at()));
            }
        }
    }

    /// The sidecar notes of one clipper in one group.
    fn notes(&self, group: &str, clipper: &str) -> Vec<String> {
        let mut notes = Vec::new();
        if let Some(first) = &self.first_wrong {
            notes.push(format!(
                "{group}: {clipper}: wrong on {} of {} results checked; its times there are left out of the ratios \
                 (first: {first}).",
                self.wrong, self.judged
            ));
        }
        if self.sampled > 0 {
            notes.push(format!(
                "{group}: {clipper}: {} of {} results checked at the oracle's sample points only (the exact area \
                 sweep would visit over {CHECK_WORK} edge-slab pairs).",
                self.sampled, self.judged
            ));
        }
        if let Some(first) = &self.first_unchecked {
            notes.push(format!(
                "{group}: {clipper}: {} of {} results not checked (first: {first}).",
                self.unchecked, self.judged
            ));
        }
        notes
    }
}

/// Runs every group, keeping each in `checkpoint` as it finishes and taking up those an
/// earlier run finished there.
pub fn run(
    groups: &[Group],
    registry: &Registry,
    settings: &Settings,
    checkpoint: &Checkpoint,
) -> Result<Measured, CliError> {
    let points: usize = groups.iter().map(|g| g.sizes.len() * g.ops.len()).sum();
    let mut progress = bar(points, "bench");
    let mut measured = Measured { rows: Vec::new(), memory: Vec::new(), notes: Vec::new() };
    let mut memory_available = true;
    for group in groups {
        if let Some(done) = checkpoint.finished(group)? {
            measured.rows.extend(done.rows);
            measured.memory.extend(done.memory);
            measured.notes.extend(done.notes);
            memory_available &= !done.memory_unavailable;
            (0..group.sizes.len() * group.ops.len()).for_each(|_| progress.inc());
            continue;
        }
        let (rows_before, memory_before, notes_before) =
            (measured.rows.len(), measured.memory.len(), measured.notes.len());
        let mut group_memory_available = true;
        let mut stopped: BTreeMap<&'static str, Stopped> = BTreeMap::new();
        // Last measured single-call time and size per clipper, to predict the next size.
        let mut last: BTreeMap<&'static str, (usize, Duration)> = BTreeMap::new();
        let mut earlier: BTreeMap<&'static str, (usize, Duration)> = BTreeMap::new();
        let mut tallies: BTreeMap<&'static str, Tally> = BTreeMap::new();
        for &size in &group.sizes {
            let cases: Vec<PolygonCase> = group
                .indices
                .iter()
                .map(|&i| polygon_case_sized(group.workload, settings.seed, i, size, group.window))
                .collect::<Result<_, _>>()
                .map_err(|e| CliError::failed(e.to_string()))?;
            let reads_alike = OnceCell::new();
            let mut judge = Judge::default();
            for &op in &group.ops {
                progress.set_message(format!("{} {size} {}", group.label, op.name()));
                let clippers: Vec<(&PolygonEntry, FillRule)> = registry
                    .polygon
                    .iter()
                    .filter(|e| cases.iter().all(|k| e.clipper.capabilities().window.accepts(&k.clip)))
                    .filter_map(|e| {
                        let caps = e.clipper.capabilities();
                        if caps.supports(op, FILL) {
                            Some((e, FILL))
                        } else {
                            if !caps.supports(op, FillRule::NonZero) {
                                return None;
                            }
                            match *reads_alike.get_or_init(|| read_alike(&cases)) {
                                ReadAlike::Yes => Some((e, FillRule::NonZero)),
                                ReadAlike::No => None,
                                ReadAlike::TooCostly(work) => {
                                    let reason = format!(
                                        "it reads non-zero only, and whether these operands read alike under both \
                                         rules was not checked: the exact check would visit {work} edge-slab pairs, \
                                         over the {READ_ALIKE_WORK} allowed"
                                    );
                                    stopped.entry(e.clipper.name()).or_insert(Stopped { size, reason });
                                    None
                                }
                            }
                        }
                    })
                    .collect();
                let mut timed_here = Vec::new();
                for (entry, fill) in clippers {
                    let c = entry.clipper.as_ref();
                    if stopped.contains_key(c.name()) {
                        continue;
                    }
                    if let Some(&(prev_size, prev)) = last.get(c.name()) {
                        let predicted = predicted_seconds(earlier.get(c.name()).copied(), (prev_size, prev), size);
                        if prev_size < size && predicted > PREDICTED_CAP_FACTOR * settings.cap_seconds {
                            let reason = format!(
                                "predicted {predicted:.1} s per call from {prev:.2?} at {prev_size} edges, over {PREDICTED_CAP_FACTOR}x the {} s cap",
                                settings.cap_seconds
                            );
                            stopped.insert(c.name(), Stopped { size, reason });
                            continue;
                        }
                    }
                    let tally = tallies.entry(c.name()).or_default();
                    let mut verdicts = Vec::with_capacity(cases.len());
                    let judged = calibrate(c, &cases, op, fill, |k, output| {
                        let verdict = judge.judge(entry, k, &cases[k], op, fill, output);
                        tally.add(&verdict, || format!("{size} edges, {}, case {}", op.name(), group.indices[k]));
                        verdicts.push(verdict.column());
                    });
                    match judged {
                        Ok(warm_up) => {
                            let single = warm_up.iter().copied().max().unwrap_or_default();
                            // Ops of one size share a size: only a smaller one shows growth.
                            if let Some(previous) = last.insert(c.name(), (size, single))
                                && previous.0 < size
                            {
                                earlier.insert(c.name(), previous);
                            }
                            let over = single.as_secs_f64() > settings.cap_seconds;
                            // An external clipper's own time is read at the timed call only.
                            let long = single.as_secs_f64() > PREDICTED_CAP_FACTOR * settings.cap_seconds
                                && entry.own_time.is_none();
                            let warm_up = long.then_some(warm_up);
                            timed_here.push(Timed { entry, fill, single, over, warm_up, correct: verdicts });
                            if over {
                                let reason = format!(
                                    "one call took {single:.2?} at {size} edges, over the {} s cap",
                                    settings.cap_seconds
                                );
                                stopped.insert(c.name(), Stopped { size: size + 1, reason });
                            }
                        }
                        Err(e) => {
                            stopped.insert(c.name(), Stopped { size, reason: format!("failed: {e}") });
                        }
                    }
                }
                measure_point(group, size, op, &cases, &timed_here, settings, &mut measured.rows);
                if group.measures_memory(size, op) {
                    for Timed { entry: c, fill, single, .. } in &timed_here {
                        if single.as_secs_f64() > PREDICTED_CAP_FACTOR * settings.cap_seconds {
                            measured.notes.push(format!(
                                "{}: {}: peak memory not measured at {size} edges, {}: one call took {single:.2?}, \
                                 over {PREDICTED_CAP_FACTOR}x the {} s cap, and the probe would repeat it.",
                                group.label,
                                c.clipper.name(),
                                op.name(),
                                settings.cap_seconds
                            ));
                            continue;
                        }
                        for (case, index) in cases.iter().zip(&group.indices) {
                            // An external clipper's memory is its own process's; ours is read in a
                            // fresh child of this one.
                            let peak = match &c.own_memory {
                                Some(own) => own.peak_of_call(&case.subject, &case.clip, op, *fill).map_err(Some),
                                None => Probe {
                                    workload: group.workload.to_owned(),
                                    window: group.window,
                                    index: *index,
                                    size,
                                    clipper: c.clipper.name().to_owned(),
                                    op,
                                    fill: *fill,
                                }
                                .run_in_child(settings.seed)
                                .ok_or(None),
                            };
                            match peak {
                                Ok((rss_before_kib, peak_extra_kib)) => measured.memory.push(MemoryRecord {
                                    workload: group.label.to_owned(),
                                    case: index.to_string(),
                                    clipper: c.clipper.name().to_owned(),
                                    size,
                                    op: op.name().to_owned(),
                                    rss_before_kib,
                                    peak_extra_kib,
                                }),
                                Err(Some(why)) => measured.notes.push(format!(
                                    "{}: {}: peak memory not measured at {size} edges, {}, case {index}: {why}",
                                    group.label,
                                    c.clipper.name(),
                                    op.name()
                                )),
                                Err(None) => group_memory_available = false,
                            }
                        }
                    }
                }
                progress.inc();
            }
        }
        for (name, s) in stopped {
            let from = if group.sizes.iter().any(|&z| z >= s.size) {
                format!("sizes from {} on were skipped", group.sizes.iter().find(|&&z| z >= s.size).unwrap_or(&s.size))
            } else {
                "no larger size was planned".to_owned()
            };
            measured.notes.push(format!("{}: {name}: {}; {from}.", group.label, s.reason));
        }
        for (name, tally) in tallies {
            measured.notes.extend(tally.notes(group.label, name));
        }
        memory_available &= group_memory_available;
        checkpoint.finish(
            group,
            FinishedGroup {
                run: checkpoint.run().to_owned(),
                group: group.describe(),
                rows: measured.rows[rows_before..].to_vec(),
                memory: measured.memory[memory_before..].to_vec(),
                notes: measured.notes[notes_before..].to_vec(),
                memory_unavailable: !group_memory_available,
            },
        )?;
    }
    progress.finish();
    if !memory_available {
        measured.notes.push(
            "Peak memory unavailable for some points: /proc/self/clear_refs could not be written (not Linux, or /proc is \
             read-only), or the probe process failed."
                .to_owned(),
        );
    }
    Ok(measured)
}

/// One warm-up call per case, whose result goes to `judge` with the case's position: each
/// case's time for one call.
fn calibrate(
    c: &dyn PolygonClipper,
    cases: &[PolygonCase],
    op: BoolOp,
    fill: FillRule,
    mut judge: impl FnMut(usize, &Polygons),
) -> Result<Vec<Duration>, String> {
    let mut times = Vec::with_capacity(cases.len());
    for (k, case) in cases.iter().enumerate() {
        let (result, took) = timed(|| c.clip(&case.subject, &case.clip, op, fill));
        let output = result.map_err(|e| format!("{} on {}: {e}", c.name(), case.description))?;
        times.push(took);
        judge(k, &output);
    }
    Ok(times)
}

/// A clipper timed at one point: its fill rule, one call's time, whether that is over the cap,
/// each case's warm-up time where that is its timing (a long call, see [`PREDICTED_CAP_FACTOR`]),
/// and each case's verdict (the `correct` column).
struct Timed<'a> {
    entry: &'a PolygonEntry,
    fill: FillRule,
    single: Duration,
    over: bool,
    warm_up: Option<Vec<Duration>>,
    correct: Vec<Option<bool>>,
}

/// Interleaved rounds over cases and clippers; a clipper over the cap is timed once, a long one by
/// its warm-up call. An external clipper that reports its own time gets a second row,
/// `NAME (own time)`, beside the round trip.
fn measure_point(
    group: &Group,
    size: usize,
    op: BoolOp,
    cases: &[PolygonCase],
    clippers: &[Timed],
    settings: &Settings,
    rows: &mut Vec<Measurement>,
) {
    let target = if settings.quick { Duration::from_millis(2) } else { Duration::from_millis(5) };
    for round in 0..settings.rounds {
        for (k, (index, case)) in group.indices.iter().zip(cases).enumerate() {
            let n = clippers.len();
            for j in 0..n {
                let Timed { entry, fill, single, over, ref warm_up, ref correct } =
                    clippers[(j + round + k) % n.max(1)];
                if over && round > 0 {
                    continue;
                }
                let c = entry.clipper.as_ref();
                let (iterations, time_ns) = if let Some(warm_up) = warm_up {
                    (1, warm_up[k].as_secs_f64() * 1e9)
                } else {
                    let iterations = iterations_for(single, target);
                    if let Some(own) = &entry.own_time {
                        own.take();
                    }
                    (iterations, per_call_ns(iterations, || c.clip(black_box(&case.subject), &case.clip, op, fill)))
                };
                let row = |clipper: String, time_ns: f64| Measurement {
                    workload: group.label.to_owned(),
                    case: index.to_string(),
                    clipper,
                    phase: "clip".to_owned(),
                    size,
                    op: op.name().to_owned(),
                    fill_rule: fill.name().to_owned(),
                    repetition: round,
                    iterations,
                    time_ns,
                    correct: correct[k],
                };
                rows.push(row(c.name().to_owned(), time_ns));
                if let Some(own_ns) = entry.own_time.as_ref().and_then(|own| own.take()) {
                    rows.push(row(own_time_name(c.name()), own_ns));
                }
            }
        }
    }
}

/// The most edge-slab pairs [`read_alike`]'s exact check may visit (a second or two). A spiky
/// star of 10^6 edges needs about 10^11 (hours); large smooth blobs and checkerboards stay near
/// linear.
const READ_ALIKE_WORK: u64 = 100_000_000;

/// Whether every case's operands cover exactly the same region under even-odd and non-zero.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum ReadAlike {
    Yes,
    No,
    /// Not checked: the check would visit this many edge-slab pairs, over [`READ_ALIKE_WORK`].
    TooCostly(u64),
}

/// [`ReadAlike`] of `cases`: `Yes` when no point of any operand is wound twice, checked exactly
/// where that is affordable.
fn read_alike(cases: &[PolygonCase]) -> ReadAlike {
    let operands = || cases.iter().flat_map(|c| [&c.subject, &c.clip]);
    let work =
        operands().map(|p| region_area_work(&[(p, FillRule::EvenOdd), (p, FillRule::NonZero)])).max().unwrap_or(0);
    if work > READ_ALIKE_WORK {
        return ReadAlike::TooCostly(work);
    }
    let alike = |p: &Polygons| same_region((p, FillRule::EvenOdd), (p, FillRule::NonZero), 0.0).is_ok();
    if operands().all(alike) { ReadAlike::Yes } else { ReadAlike::No }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_group_an_earlier_run_finished_is_taken_up_not_measured_again() {
        use crate::bench::checkpoint::finished_for_test;
        let dir = std::env::temp_dir().join(format!("clipbench-resume-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let groups = crate::bench::plan::groups(true);
        let star = &groups[0];
        let done = finished_for_test("revision r", star, 4242.0);
        let first = Checkpoint::new(&dir, "revision r".to_owned(), false).unwrap();
        first.finish(star, finished_for_test("revision r", star, 4242.0)).unwrap();
        let resumed = Checkpoint::new(&dir, "revision r".to_owned(), true).unwrap();
        let settings = Settings { seed: 1, rounds: 1, cap_seconds: 0.5, quick: true };
        let measured = run(std::slice::from_ref(star), &crate::registry::registry(), &settings, &resumed).unwrap();
        // Measured again, the group would hold every clipper's rows at every size.
        assert_eq!((measured.rows, measured.notes), (done.rows, done.notes));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_long_call_is_timed_by_its_warm_up_and_not_repeated_for_peak_memory() {
        let dir = std::env::temp_dir().join(format!("clipbench-long-call-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let group = Group {
            label: "star",
            workload: "star",
            window: clip_core::WindowKind::Any,
            indices: vec![0, 1],
            sizes: vec![100],
            ops: vec![BoolOp::Intersection],
            memory_from: Some(100),
        };
        // A cap of a nanosecond makes every call a long one.
        let settings = Settings { seed: 1, rounds: 3, cap_seconds: 1e-9, quick: true };
        let checkpoint = Checkpoint::new(&dir, "revision r".to_owned(), false).unwrap();
        let registry = crate::registry::registry();
        let measured = run(std::slice::from_ref(&group), &registry, &settings, &checkpoint).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        let names: std::collections::BTreeSet<&str> = measured.rows.iter().map(|r| r.clipper.as_str()).collect();
        assert!(names.len() >= 3, "{names:?}");
        // One row per clipper and case (one round, no repetition), each a single call.
        assert_eq!(measured.rows.len(), names.len() * group.indices.len(), "{:?}", measured.rows);
        assert!(measured.rows.iter().all(|r| r.iterations == 1 && r.repetition == 0 && r.time_ns > 0.0));
        assert!(measured.memory.is_empty(), "{:?}", measured.memory);
        for name in names {
            let note = format!("star: {name}: peak memory not measured at 100 edges, intersection: one call took");
            assert!(measured.notes.iter().any(|n| n.starts_with(&note)), "{name}: {:?}", measured.notes);
        }
    }

    fn ms(t: u64) -> Duration {
        Duration::from_millis(t)
    }

    #[test]
    fn operands_read_alike_only_where_no_point_is_wound_twice_and_the_check_is_affordable() {
        use clip_core::{Point, Rect, Ring};
        let case = |subject: Polygons| PolygonCase {
            workload: "test",
            seed: 1,
            index: 0,
            subject,
            clip: Polygons::from(Rect::new(0.0, 0.0, 1.0, 1.0)),
            description: String::new(),
        };
        let square = |x: f64| {
            Ring::new(vec![Point::new(x, 0.0), Point::new(x + 2.0, 0.0), Point::new(x + 2.0, 2.0), Point::new(x, 2.0)])
        };
        assert_eq!(read_alike(&[case(Polygons::new(vec![square(0.0), square(5.0)]))]), ReadAlike::Yes);
        // Two squares overlapping the same way: their overlap is wound twice.
        assert_eq!(read_alike(&[case(Polygons::new(vec![square(0.0), square(1.0)]))]), ReadAlike::No);
        // A comb of 12 000 teeth: a level line crosses every tooth, so the check is quadratic.
        let teeth = 12_000;
        let mut comb: Vec<Point> = (0..teeth)
            .flat_map(|i| [Point::new(2.0 * i as f64, 1.0 + i as f64), Point::new(2.0 * i as f64 + 1.0, 0.0)])
            .collect();
        comb.extend([Point::new(2.0 * teeth as f64, -1.0), Point::new(0.0, -1.0)]);
        let ReadAlike::TooCostly(work) = read_alike(&[case(Polygons::new(vec![Ring::new(comb)]))]) else {
            panic!("the comb's check should be too costly");
        };
        assert!(work > READ_ALIKE_WORK, "{work}");
    }

    #[test]
    fn prediction_follows_the_growth_it_has_seen_and_never_falls_below_linear() {
        // One size timed: linear.
        assert_eq!(predicted_seconds(None, (1000, ms(100)), 10_000), 1.0);
        // Quadratic growth from 10^3 to 10^4 predicts 100x for the next tenfold step.
        let quadratic = predicted_seconds(Some((1000, ms(5))), (10_000, ms(500)), 100_000);
        assert!((quadratic - 50.0).abs() < 1e-6, "{quadratic}");
        // Sub-linear growth (fixed costs) still predicts linear.
        assert_eq!(predicted_seconds(Some((1000, ms(80))), (10_000, ms(100)), 100_000), 1.0);
        // A time that fell, or an earlier size that is not smaller, says nothing of growth.
        assert_eq!(predicted_seconds(Some((1000, ms(200))), (10_000, ms(100)), 100_000), 1.0);
        assert_eq!(predicted_seconds(Some((10_000, ms(5))), (10_000, ms(100)), 100_000), 1.0);
    }
}
