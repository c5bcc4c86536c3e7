//! REPORT.md's atlas: every external clipper of adapters/clippers.toml, beside vatti and Clipper2,
//! judged and timed from the raw files of `<results>/atlas/` (scripts/atlas.sh): oracle failures
//! per workload, conformance, the hostile cases, speed against Clipper2 by own time, peak memory,
//! and CGAL as a referee of the oracle's areas.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use clip_testkit::workload::POLYGON_WORKLOADS;

use super::bench_points::points;
use super::derived::Derived;
use super::markdown::{num, num_interval, table};
use super::results_folder::ResultsFolder;
use super::summary::{self, LARGE_FROM, SummaryRow};
use super::wording::Sides;
use crate::cli_error::CliError;
use crate::external::spec::{ExternalSpec, parse_file, shown};
use crate::measure::interval::Interval;
use crate::measure::raw::{Measurement, read_csv};
use crate::results_files::atlas::{
    BENCH_FOLDER, CONFORMANCE_SUITES, ConformanceResults, ConformanceTally, FOLDER, HOSTILE_JSON, HostileResults,
    HostileTally, REFEREE_PREFIX, RefereeResults, RefereeTally, VERIFY_PREFIX, conformance_file, read_json,
};
use crate::results_files::bench::{BASELINE, CSV, TEXT_GROUP, own_time_name, read_memory};
use crate::results_files::verify::{CaseEntry, VerifyResults, VerifyRow};

/// The clippers the atlas shows beside the external ones, for reference.
const REFERENCE: [&str; 2] = ["vatti", BASELINE];

/// What a cell says for a clipper a stage that ran did not run.
const ABSENT: &str = "-";

/// What a cell says for a stage or workload with no file.
const NOT_RUN: &str = "not run";

/// The repository's list of external clippers, read when the atlas folder holds no copy.
fn repository_clippers() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("adapters").join("clippers.toml")
}

/// The section, or `None` when the folder has no `atlas/`.
pub fn derive(folder: &ResultsFolder) -> Result<Option<Derived>, CliError> {
    let atlas = folder.join(FOLDER);
    if !atlas.is_dir() {
        return Ok(None);
    }
    let copy = atlas.join("clippers.toml");
    let list = if copy.exists() { copy } else { repository_clippers() };
    let described = if list.exists() { parse_file(&list)? } else { Vec::new() };
    Ok(Some(Derived::new(Atlas::read(&atlas, described)?.text())))
}

/// Everything the atlas's files hold, read once.
struct Atlas {
    /// The external clippers as adapters/clippers.toml describes them.
    described: Vec<ExternalSpec>,
    /// Per workload: the largest case count run and its polygon rows.
    verify: BTreeMap<String, (usize, Vec<VerifyRow>)>,
    /// Per clipper: its shrunk oracle failures recorded by those runs, counted by kind.
    recorded: BTreeMap<String, BTreeMap<&'static str, usize>>,
    /// Per conformance suite: each clipper's tally, `None` when the suite has no file.
    conformance: Vec<(&'static str, Option<Vec<ConformanceTally>>)>,
    /// The hostile tallies, `None` without the file.
    hostile: Option<Vec<HostileTally>>,
    /// The bench's summary rows (speed and memory against Clipper2), `None` without the bench.
    speed: Option<Vec<SummaryRow>>,
    /// The bench's ratio points per clipper name as timed (own time for external clippers).
    speed_points: BTreeMap<String, Vec<Interval>>,
    /// Per workload: the referee's largest case count run, its name and its tally.
    referee: BTreeMap<String, (usize, String, RefereeTally)>,
}

/// The case count `N` of a folder named `PREFIX-N`.
fn cases_of(name: &str, prefix: &str) -> Option<usize> {
    name.strip_prefix(prefix)?.parse().ok()
}

/// The `*.json` files of every folder `PREFIX-N` in `atlas`, with N, in name order.
fn json_files(atlas: &Path, prefix: &str) -> Result<Vec<(usize, PathBuf)>, CliError> {
    let list = |dir: &Path| -> Result<Vec<PathBuf>, CliError> {
        let entries =
            std::fs::read_dir(dir).map_err(|e| CliError::failed(format!("{}: cannot list ({e})", dir.display())))?;
        let mut paths: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
        paths.sort();
        Ok(paths)
    };
    let mut files = Vec::new();
    for dir in list(atlas)? {
        let Some(n) = dir.file_name().and_then(|n| n.to_str()).and_then(|n| cases_of(n, prefix)) else { continue };
        if !dir.is_dir() {
            continue;
        }
        files.extend(list(&dir)?.into_iter().filter(|p| p.extension().is_some_and(|e| e == "json")).map(|p| (n, p)));
    }
    Ok(files)
}

/// What a shrunk oracle failure of `clipper` is, from its message (clip-oracle's
/// `PolygonFailure` and the external clipper's own words): a result that is not a valid polygon
/// (the region may still be right), a wrong region, an error the clipper answered with, or no
/// answer in time.
fn failure_kind(message: &str, clipper: &str) -> &'static str {
    if message.starts_with("invalid output") {
        "invalid output"
    } else if message.starts_with("point (") || message.starts_with("result differs from the exact region") {
        "wrong region"
    } else if message.contains("no answer within") {
        "no answer"
    } else if message.starts_with(&format!("{clipper} failed")) {
        "error"
    } else {
        "other"
    }
}

/// The order workloads are shown in: clip-testkit's, then any other by name.
fn workload_rank(workload: &str) -> (usize, String) {
    (POLYGON_WORKLOADS.iter().position(|w| *w == workload).unwrap_or(usize::MAX), workload.to_owned())
}

/// The parts of one verify run on one workload, as they are read.
#[derive(Default)]
struct VerifyParts {
    /// The parts' K.
    seen: Vec<usize>,
    /// One row per clipper, the parts' counts added up.
    rows: Vec<VerifyRow>,
    /// The oracle failures the parts recorded.
    cases: Vec<CaseEntry>,
}

impl VerifyParts {
    /// Adds part `k`, unless it was read already.
    fn join(&mut self, k: usize, rows: Vec<VerifyRow>, cases: Vec<CaseEntry>) {
        if self.seen.contains(&k) {
            return;
        }
        self.seen.push(k);
        for row in rows {
            match self.rows.iter_mut().find(|r| r.clipper == row.clipper) {
                Some(r) => r.add(&row),
                None => self.rows.push(row),
            }
        }
        self.cases.extend(cases);
    }
}

impl Atlas {
    fn read(atlas: &Path, described: Vec<ExternalSpec>) -> Result<Atlas, CliError> {
        // Rows and recorded oracle failures by the run's case count: whole runs as read, and the
        // parts of one (`verify --partition K/N`) joined per workload once all N are there.
        let mut rows: Vec<(usize, VerifyRow)> = Vec::new();
        let mut cases: Vec<(usize, CaseEntry)> = Vec::new();
        let mut parts: BTreeMap<(usize, String, usize), VerifyParts> = BTreeMap::new();
        for (n, path) in json_files(atlas, VERIFY_PREFIX)? {
            let results: VerifyResults = read_json(&path, "a verify summary")?;
            let polygon_rows = results.rows.into_iter().filter(|r| r.kind == "polygon");
            let failures = results.cases.into_iter().filter(|c| c.kind == "polygon" && c.check == "oracle");
            let Some(p) = results.partition else {
                rows.extend(polygon_rows.map(|r| (n, r)));
                cases.extend(failures.map(|c| (n, c)));
                continue;
            };
            let failures: Vec<CaseEntry> = failures.collect();
            let mut by_workload: BTreeMap<String, Vec<VerifyRow>> = BTreeMap::new();
            for row in polygon_rows {
                by_workload.entry(row.workload.clone()).or_default().push(row);
            }
            for (workload, workload_rows) in by_workload {
                let recorded: Vec<CaseEntry> = failures.iter().filter(|c| c.workload == workload).cloned().collect();
                parts.entry((n, workload, p.n)).or_default().join(p.k, workload_rows, recorded);
            }
        }
        for ((n, _, count), joined) in parts {
            if joined.seen.len() == count {
                rows.extend(joined.rows.into_iter().map(|r| (n, r)));
                cases.extend(joined.cases.into_iter().map(|c| (n, c)));
            }
        }
        let mut verify: BTreeMap<String, (usize, Vec<VerifyRow>)> = BTreeMap::new();
        for (n, row) in rows {
            let kept = verify.entry(row.workload.clone()).or_insert((n, Vec::new()));
            if n > kept.0 {
                *kept = (n, Vec::new());
            }
            if n == kept.0 {
                kept.1.push(row);
            }
        }
        let mut recorded: BTreeMap<String, BTreeMap<&'static str, usize>> = BTreeMap::new();
        for (n, case) in cases {
            if verify.get(&case.workload).is_some_and(|(kept, _)| *kept == n) {
                let kind = failure_kind(&case.shrunk, &case.clipper);
                *recorded.entry(case.clipper).or_default().entry(kind).or_default() += 1;
            }
        }
        let mut conformance = Vec::new();
        for suite in CONFORMANCE_SUITES {
            let json = atlas.join(conformance_file(suite, "json"));
            let text = atlas.join(conformance_file(suite, "txt"));
            let tallies = if json.exists() {
                Some(read_json::<ConformanceResults>(&json, "a conformance summary")?.clippers)
            } else if text.exists() {
                let lines = std::fs::read_to_string(&text)
                    .map_err(|e| CliError::failed(format!("{}: cannot read ({e})", text.display())))?;
                Some(lines.lines().filter_map(ConformanceTally::from_line).collect())
            } else {
                None
            };
            conformance.push((suite, tallies));
        }
        let hostile_path = atlas.join(HOSTILE_JSON);
        let hostile = if hostile_path.exists() {
            Some(read_json::<HostileResults>(&hostile_path, "a hostile summary")?.tallies)
        } else {
            None
        };
        let bench = atlas.join(BENCH_FOLDER);
        let (speed, speed_points) = if bench.join(CSV).exists() {
            let rows: Vec<Measurement> = read_csv(&bench.join(CSV))?;
            // The same points and summary speeds as the bench and summary sections.
            let points = points(rows.iter().filter(|r| r.workload != TEXT_GROUP));
            let memory = read_memory(&bench)?;
            let mut by_clipper: BTreeMap<String, Vec<_>> = BTreeMap::new();
            for ((_, _, _, clipper), p) in points.iter().filter(|(_, p)| p.trusted()) {
                by_clipper.entry(clipper.clone()).or_default().push(p.ratio_interval);
            }
            let rows = summary::rows(&[], &points, &memory).remove("polygon").unwrap_or_default();
            (Some(rows), by_clipper)
        } else {
            (None, BTreeMap::new())
        };
        let mut referee: BTreeMap<String, (usize, String, RefereeTally)> = BTreeMap::new();
        let mut keep = |n: usize, name: &str, t: RefereeTally| {
            if referee.get(&t.workload).is_none_or(|kept| n > kept.0) {
                referee.insert(t.workload.clone(), (n, name.to_owned(), t));
            }
        };
        // Parts of one run (`referee --partition K/N`), joined once all N are there: by cases,
        // referee, workload and N, the parts seen and the tally so far.
        type PartKey = (usize, String, String, usize);
        let mut parts: BTreeMap<PartKey, (Vec<usize>, RefereeTally)> = BTreeMap::new();
        for (n, path) in json_files(atlas, REFEREE_PREFIX)? {
            let results: RefereeResults = read_json(&path, "a referee summary")?;
            for t in results.workloads {
                match results.partition {
                    None => keep(n, &results.referee, t),
                    Some(p) => {
                        let key = (n, results.referee.clone(), t.workload.clone(), p.n);
                        let (seen, joined) = parts.entry(key).or_insert_with(|| {
                            (Vec::new(), RefereeTally { workload: t.workload.clone(), ..RefereeTally::default() })
                        });
                        if !seen.contains(&p.k) {
                            seen.push(p.k);
                            joined.join(&t);
                        }
                    }
                }
            }
        }
        for ((n, name, _, count), (seen, joined)) in parts {
            if seen.len() == count {
                keep(n, &name, joined);
            }
        }
        Ok(Atlas { described, verify, recorded, conformance, hostile, speed, speed_points, referee })
    }

    /// Vatti and Clipper2, then the external clippers in adapters/clippers.toml's order, then
    /// any other clipper a stage ran, in the order first met.
    fn clippers(&self) -> Vec<String> {
        let mut names: Vec<String> = REFERENCE.iter().map(|c| (*c).to_owned()).collect();
        let mut add = |name: &str| {
            if !names.iter().any(|n| n == name) {
                names.push(name.to_owned());
            }
        };
        self.described.iter().for_each(|s| add(&s.name));
        for (_, rows) in self.verify.values() {
            rows.iter().for_each(|r| add(&r.clipper));
        }
        for (_, tallies) in &self.conformance {
            tallies.iter().flatten().for_each(|t| add(&t.clipper));
        }
        self.hostile.iter().flatten().for_each(|t| add(&t.clipper));
        names
    }

    /// The workloads of the verify and referee tables: every one a stage ran.
    fn workloads(&self) -> Vec<String> {
        let mut all: Vec<String> = self.verify.keys().chain(self.referee.keys()).cloned().collect();
        all.sort_by_key(|w| workload_rank(w));
        all.dedup();
        all
    }

    /// The name a clipper's speed is read under: its own time when it reports one.
    fn timed_name(&self, clipper: &str) -> Option<String> {
        let own = own_time_name(clipper);
        [own, clipper.to_owned()].into_iter().find(|n| self.speed_points.contains_key(n))
    }

    fn speed_row(&self, clipper: &str) -> Option<&SummaryRow> {
        let name = self.timed_name(clipper)?;
        self.speed.as_ref()?.iter().find(|r| r.clipper == name)
    }

    /// Oracle failures, hangs and results checked over every verified workload, `None` when it
    /// ran on none.
    fn verified(&self, clipper: &str) -> Option<(usize, usize, usize)> {
        let rows: Vec<&VerifyRow> =
            self.verify.values().flat_map(|(_, rows)| rows).filter(|r| r.clipper == clipper).collect();
        (!rows.is_empty())
            .then(|| rows.iter().fold((0, 0, 0), |(f, h, n), r| (f + r.oracle_failures, h + r.hung, n + r.runs)))
    }

    /// The name an external clipper's handshake gave (library and version), from the first
    /// file that recorded it.
    fn handshake(&self, clipper: &str) -> Option<&str> {
        let conformance =
            self.conformance.iter().flat_map(|(_, t)| t.iter().flatten()).filter(|t| t.clipper == clipper);
        let hostile = self.hostile.iter().flatten().filter(|t| t.clipper == clipper);
        conformance.filter_map(|t| t.handshake.as_deref()).chain(hostile.filter_map(|t| t.handshake.as_deref())).next()
    }

    fn hostile_of(&self, clipper: &str) -> Option<&HostileTally> {
        self.hostile.as_ref()?.iter().find(|t| t.clipper == clipper)
    }

    /// The short notes of a row, from its counts: what it got wrong, refused, crashed or hung on.
    fn notes(&self, clipper: &str) -> String {
        let mut notes = Vec::new();
        if let Some((failures, hung, runs)) = self.verified(clipper) {
            if failures > 0 {
                let kinds = self.recorded.get(clipper).map(|kinds| {
                    let counts: Vec<String> = kinds.iter().map(|(kind, n)| format!("{n} {kind}")).collect();
                    format!(" (its shrunk cases: {})", counts.join(", "))
                });
                notes.push(format!(
                    "fails the oracle on {failures} of {runs} verify results{}",
                    kinds.unwrap_or_default()
                ));
            }
            if hung > 0 {
                notes.push(format!("gave no answer in time on {hung} of {runs} verify results"));
            }
        }
        for (suite, tallies) in &self.conformance {
            if let Some(t) = tallies.iter().flatten().find(|t| t.clipper == clipper && t.failed > 0) {
                notes.push(format!("fails {} of {} {}", t.failed, t.passed + t.failed, suite_label(suite)));
            }
        }
        if let Some(t) = self.hostile_of(clipper) {
            for (count, what) in
                [(t.wrong, "wrong or invalid output"), (t.refused, "refused"), (t.crashed, "crashed"), (t.hung, "hung")]
            {
                if count > 0 {
                    notes.push(format!("{what} on {count} of {} hostile calls", t.runs));
                }
            }
        }
        let ran = self.verified(clipper).is_some()
            || self.hostile_of(clipper).is_some()
            || self.conformance.iter().any(|(_, t)| t.iter().flatten().any(|t| t.clipper == clipper));
        if notes.is_empty() && ran {
            notes.push("no failure found".to_owned());
        }
        notes.join("; ")
    }

    fn text(&self) -> String {
        let clippers = self.clippers();
        let workloads = self.workloads();
        let mut text = format!(
            "The clippers people use in JavaScript, Java, C++ and Python, run as external clippers \
             (docs/PROTOCOL.md) from `adapters/clippers.toml`, beside `vatti` and `{BASELINE}` for reference; every \
             figure is read from the raw files of `atlas/` (scripts/atlas.sh; atlas/COMMANDS.md lists the command \
             behind each file). {ABSENT} : the stage ran without this clipper; {NOT_RUN}: the stage or workload has \
             no file.\n\n"
        );
        text.push_str(&self.identity_table(&clippers));
        text.push_str(&self.verify_table(&clippers, &workloads));
        text.push_str(&self.judged_table(&clippers));
        text.push_str(&self.speed_table(&clippers));
        text.push_str(&self.referee_table(&workloads));
        text
    }

    fn identity_table(&self, clippers: &[String]) -> String {
        let head =
            ["clipper", "library", "language", "version (its handshake)", "called as", "notes"].map(str::to_owned);
        let body: Vec<Vec<String>> = clippers
            .iter()
            .map(|c| {
                let spec = self.described.iter().find(|s| &s.name == c);
                let (library, language, called) = match spec {
                    Some(s) => (
                        s.library.clone().unwrap_or_else(|| ABSENT.to_owned()),
                        s.language.clone().unwrap_or_else(|| ABSENT.to_owned()),
                        format!("own process: `{}`", shown(&s.command)),
                    ),
                    None if REFERENCE.contains(&c.as_str()) => {
                        let origin = if c == "vatti" { "ours" } else { "peer" };
                        (
                            if c == "vatti" { "this repository (clip-vatti)" } else { "Clipper2 (clip-peers)" }
                                .to_owned(),
                            summary::language(c, origin).to_owned(),
                            "in process".to_owned(),
                        )
                    }
                    None => (ABSENT.to_owned(), ABSENT.to_owned(), ABSENT.to_owned()),
                };
                let version = match self.handshake(c) {
                    Some(name) => name.to_owned(),
                    None if spec.is_some() => "not recorded".to_owned(),
                    None => ABSENT.to_owned(),
                };
                vec![format!("`{c}`"), library, language, version, called, self.notes(c)]
            })
            .collect();
        format!(
            "Who they are: library and language as adapters/clippers.toml describes them; the version is what each \
             adapter's handshake said it runs, as `conformance --json` and `hostile --json` record it (\"not recorded\" \
             in files from before they did: adapters/node/package.json and adapters/python/requirements.txt pin the \
             npm and PyPI versions, Debian's packages the rest). The notes come from the counts below.\n\n{}\n",
            table(&head, &body)
        )
    }

    fn verify_table(&self, clippers: &[String], workloads: &[String]) -> String {
        let mut head = vec!["clipper".to_owned()];
        head.extend(workloads.iter().map(|w| match self.verify.get(w) {
            Some((n, _)) => format!("`{w}` ({n} cases)"),
            None => format!("`{w}`"),
        }));
        let body: Vec<Vec<String>> = clippers
            .iter()
            .map(|c| {
                let mut line = vec![format!("`{c}`")];
                line.extend(workloads.iter().map(|w| match self.verify.get(w) {
                    None => NOT_RUN.to_owned(),
                    Some((_, rows)) => rows.iter().find(|r| &r.clipper == c).map_or(ABSENT.to_owned(), |r| {
                        let cell = format!("{} / {}", r.oracle_failures, r.runs);
                        let cell = if r.oracle_failures > 0 { format!("**{cell}**") } else { cell };
                        summary::with_hung(cell, r.hung)
                    }),
                }));
                line
            })
            .collect();
        format!(
            "Oracle failures per workload (`clipbench verify`, the largest case count run per workload): results the \
             exact oracle rejected / results checked, refusals of valid input and failed area identities included; \
             beside them, the results an external clipper gave no answer to within the call time-out (\"3 hung\"), \
             which are not wrong answers and not in the failures. A clipper declaring fewer fill rules has fewer \
             results checked.\n\n{}\n",
            table(&head, &body)
        )
    }

    fn judged_table(&self, clippers: &[String]) -> String {
        let mut head = vec!["clipper".to_owned()];
        head.extend(
            self.conformance.iter().map(|(suite, _)| format!("{} passed / failed / skipped", suite_label(suite))),
        );
        head.push("hostile: right / wrong / refused / crashed / hung of calls".to_owned());
        let body: Vec<Vec<String>> = clippers
            .iter()
            .map(|c| {
                let mut line = vec![format!("`{c}`")];
                line.extend(self.conformance.iter().map(|(_, tallies)| match tallies {
                    None => NOT_RUN.to_owned(),
                    Some(tallies) => tallies.iter().find(|t| &t.clipper == c).map_or(ABSENT.to_owned(), |t| {
                        let cell = format!("{} / {} / {}", t.passed, t.failed, t.skipped);
                        if t.failed > 0 { format!("**{cell}**") } else { cell }
                    }),
                }));
                line.push(match &self.hostile {
                    None => NOT_RUN.to_owned(),
                    Some(_) => self.hostile_of(c).map_or(ABSENT.to_owned(), |t| {
                        let cell = format!(
                            "{} / {} / {} / {} / {} of {}",
                            t.right, t.wrong, t.refused, t.crashed, t.hung, t.runs
                        );
                        if t.right < t.runs { format!("**{cell}**") } else { cell }
                    }),
                });
                line
            })
            .collect();
        format!(
            "Conformance (`clipbench conformance`: skipped cases are those a clipper does not declare) and the fixed \
             hostile and degenerate cases (`clipbench hostile`, every operation and fill rule each clipper \
             declares).\n\n{}\n",
            table(&head, &body)
        )
    }

    fn speed_table(&self, clippers: &[String]) -> String {
        if self.speed.is_none() {
            return format!("Speed: {NOT_RUN} (no atlas/bench/bench.csv).\n\n");
        }
        let head = [
            "clipper".to_owned(),
            format!("time x {BASELINE}, < {LARGE_FROM} edges"),
            format!("time x {BASELINE}, >= {LARGE_FROM} edges"),
            format!("points against {BASELINE}"),
            format!("peak memory x {BASELINE}"),
        ];
        let body: Vec<Vec<String>> = clippers
            .iter()
            .map(|c| {
                let row = self.speed_row(c);
                let interval = |i: Option<Interval>| i.map_or(ABSENT.to_owned(), |i| num_interval(&i, 2));
                let sides = match self.timed_name(c) {
                    Some(_) if c == BASELINE => "the reference".to_owned(),
                    Some(name) => Sides::of_time_ratios(&self.speed_points[&name]).sentence("points"),
                    None => ABSENT.to_owned(),
                };
                // Memory is recorded under the clipper's name, not its own time's.
                let memory = match self.speed.as_ref().and_then(|rows| rows.iter().find(|r| r.clipper == *c)) {
                    None => ABSENT.to_owned(),
                    Some(r) => r.memory.map_or("not measured".to_owned(), |m| num(m, 2)),
                };
                vec![
                    format!("`{c}`"),
                    interval(row.and_then(|r| r.speed_small)),
                    interval(row.and_then(|r| r.speed_large)),
                    sides,
                    memory,
                ]
            })
            .collect();
        format!(
            "Speed (`clipbench bench`): time per call relative to `{BASELINE}`, external clippers by the time they \
             report for themselves (no process, pipe or JSON), as the geometric mean of the bench's ratios below and \
             from {LARGE_FROM} edges, with the geometric means of the points' 95% interval ends in brackets (the \
             summary's figures, from the same points). Peak memory is the geometric mean, over the large groups, \
             of the peak resident memory of one call above that before it, over `{BASELINE}`'s; an external \
             clipper's is its own process's, in a process started for the call, and includes reading the request, \
             writing the answer and its runtime's own heap.\n\n{}\n",
            table(&head, &body)
        )
    }

    fn referee_table(&self, workloads: &[String]) -> String {
        if self.referee.is_empty() {
            return format!("The exact referee: {NOT_RUN}.\n\n");
        }
        let referees: Vec<&str> = {
            let mut r: Vec<&str> = self.referee.values().map(|(_, name, _)| name.as_str()).collect();
            r.sort_unstable();
            r.dedup();
            r
        };
        let head = [
            "workload",
            "cases",
            "results compared",
            "no result",
            "largest relative area difference",
            "largest / rounding bound",
            "beyond rounding",
        ]
        .map(str::to_owned);
        let body: Vec<Vec<String>> = workloads
            .iter()
            .map(|w| match self.referee.get(w) {
                None => {
                    let mut line = vec![format!("`{w}`"), NOT_RUN.to_owned()];
                    line.extend(std::iter::repeat_n(ABSENT.to_owned(), 5));
                    line
                }
                Some((n, _, t)) => vec![
                    format!("`{w}`"),
                    format!("{} of {n}", t.cases),
                    t.compared.to_string(),
                    t.failed.to_string(),
                    format!("{:.3e}", t.largest_relative),
                    format!("{:.3e}", t.largest_of_bound),
                    if t.beyond_rounding > 0 { format!("**{}**", t.beyond_rounding) } else { "0".to_owned() },
                ],
            })
            .collect();
        format!(
            "The exact referee (`clipbench referee`): {}'s exact result areas against clip-oracle's region areas, \
             the largest case count run per workload. A difference beyond the rounding of the output to f64 would be \
             a bug in one of the two.\n\n{}\n",
            referees.join(", "),
            table(&head, &body)
        )
    }
}

/// A conformance suite as a reader knows it.
fn suite_label(suite: &str) -> &str {
    match suite {
        "clipper2-polygons" => "Clipper2's Polygons.txt",
        "geo-booleanop" => "geo's fixtures",
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fresh folder for one test.
    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("clipbench-atlas-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn write(path: &Path, text: &str) {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
    }

    /// Rows of (clipper, workload, oracle failures, hung, runs), and recorded oracle failures
    /// (clipper, workload, message).
    fn verify_file(
        path: &Path,
        cases: usize,
        rows: &[(&str, &str, usize, usize, usize)],
        shrunk: &[(&str, &str, &str)],
    ) {
        let results = VerifyResults {
            seed: 1,
            cases_per_workload: cases,
            rows: rows
                .iter()
                .map(|&(clipper, workload, failures, hung, runs)| VerifyRow {
                    clipper: clipper.into(),
                    origin: "external".into(),
                    kind: "polygon".into(),
                    workload: workload.into(),
                    cases,
                    runs,
                    oracle_failures: failures,
                    hung,
                    ..VerifyRow::default()
                })
                .collect(),
            failures_recorded: 0,
            failures_not_recorded: 0,
            ours_failed: false,
            cases: shrunk
                .iter()
                .map(|&(clipper, workload, message)| CaseEntry {
                    folder: format!("{workload}-{clipper}"),
                    seed: 1,
                    index: 0,
                    kind: "polygon".into(),
                    clipper: clipper.into(),
                    workload: workload.into(),
                    check: "oracle".into(),
                    other: None,
                    op: Some("union".into()),
                    fill: Some("even-odd".into()),
                    shrunk_vertices: [3, 3],
                    shrunk: message.into(),
                })
                .collect(),
            partition: None,
        };
        write(path, &serde_json::to_string(&results).unwrap());
    }

    /// The row of `clipper` in a markdown table, split into cells.
    fn row(table: &str, clipper: &str) -> Vec<String> {
        let start = format!("| `{clipper}` |");
        let line = table.lines().find(|l| l.starts_with(&start)).unwrap_or_else(|| panic!("no {clipper}\n{table}"));
        line.trim_matches('|').split(" | ").map(|c| c.trim().to_owned()).collect()
    }

    /// An atlas of two clippers: `ext` (described in the folder's clippers.toml) and vatti.
    fn synthetic(name: &str) -> PathBuf {
        let results = scratch(name);
        let atlas = results.join(FOLDER);
        write(
            &atlas.join("clippers.toml"),
            "[[clipper]]\nname = \"ext\"\ncommand = \"ext --serve\"\nlibrary = \"Ext 1\"\nlanguage = \"Go\"\n",
        );
        // A smaller run of `star` is superseded by the larger one; `holes` ran only small.
        let star_20 = [("vatti", "star", 0, 0, 320), ("ext", "star", 9, 0, 80)];
        // The smaller run's shrunk cases count for nothing either.
        let stale = [("ext", "star", "result differs from the exact region by area 1e0 (tolerance 1e-6)")];
        verify_file(&atlas.join("verify-20/star.json"), 20, &star_20, &stale);
        let star_200 = [("vatti", "star", 0, 0, 3200), ("ext", "star", 7, 3, 800)];
        let star_cases = [
            ("ext", "star", "invalid output: ring 0 visits (2, -2) twice (at vertex 1 and vertex 4)"),
            ("ext", "star", "ext failed: it answered with an error: TypeError"),
        ];
        verify_file(&atlas.join("verify-200/star.json"), 200, &star_200, &star_cases);
        let holes_20 = [("vatti", "holes", 0, 0, 320), ("ext", "holes", 2, 0, 80)];
        let holes_cases = [("ext", "holes", "point (1, 2) should be inside the result but is outside")];
        verify_file(&atlas.join("verify-20/holes.json"), 20, &holes_20, &holes_cases);
        write(
            &atlas.join(HOSTILE_JSON),
            r#"{"tallies": [{"clipper": "ext", "runs": 10, "right": 5, "wrong": 2, "refused": 1, "crashed": 1, "hung": 1,
                 "handshake": "ext 1.2.3 (rings as given)"}],
               "incidents": [], "handshake": "ignored"}"#,
        );
        write(
            &atlas.join(conformance_file("clipper2-polygons", "txt")),
            "clipper2-polygons 2 ext: expected a result, got no\next: 4 passed, 1 failed, 2 skipped\n",
        );
        let geo = ConformanceResults {
            suite: "geo-booleanop".into(),
            clippers: vec![ConformanceTally {
                clipper: "vatti".into(),
                passed: 80,
                failed: 0,
                skipped: 3,
                handshake: None,
            }],
        };
        write(&atlas.join(conformance_file("geo-booleanop", "json")), &serde_json::to_string(&geo).unwrap());
        // The referee ran `grid`, which verify did not.
        write(
            &atlas.join("referee-50/grid.json"),
            r#"{"referee": "cgal", "seed": 1, "cases_per_workload": 50, "workloads": [{"workload": "grid", "cases": 50,
               "compared": 800, "failed": 0, "largest_relative": 1.5e-13, "largest_of_bound": 0.25, "beyond_rounding": 0}],
               "beyond_rounding": [], "failures": []}"#,
        );
        results
    }

    fn read_synthetic(results: &Path) -> Atlas {
        let atlas = results.join(FOLDER);
        Atlas::read(&atlas, parse_file(&atlas.join("clippers.toml")).unwrap()).unwrap()
    }

    #[test]
    fn a_workload_without_a_file_is_not_run_and_a_clipper_a_stage_left_out_is_a_dash() {
        let results = synthetic("cells");
        let atlas = read_synthetic(&results);
        let clippers = atlas.clippers();
        assert_eq!(clippers, ["vatti", "clipper2", "ext"]);
        let workloads = atlas.workloads();
        assert_eq!(workloads, ["star", "holes", "grid"], "clip-testkit's order");
        let verify = atlas.verify_table(&clippers, &workloads);
        assert!(verify.contains("| clipper | `star` (200 cases) | `holes` (20 cases) | `grid` |"), "{verify}");
        assert_eq!(row(&verify, "ext"), ["`ext`", "**7 / 800**, 3 hung", "**2 / 80**", "not run"]);
        assert_eq!(row(&verify, "vatti"), ["`vatti`", "0 / 3200", "0 / 320", "not run"]);
        assert_eq!(row(&verify, "clipper2"), ["`clipper2`", "-", "-", "not run"], "in no verify file: not 0");
        let judged = atlas.judged_table(&clippers);
        // Polygons.txt read from its printed lines; geo's fixtures from --json.
        assert_eq!(row(&judged, "ext"), ["`ext`", "**4 / 1 / 2**", "-", "**5 / 2 / 1 / 1 / 1 of 10**"]);
        assert_eq!(row(&judged, "vatti"), ["`vatti`", "-", "80 / 0 / 3", "-"]);
        let speed = atlas.speed_table(&clippers);
        assert!(speed.starts_with("Speed: not run"), "{speed}");
        let referee = atlas.referee_table(&workloads);
        assert!(referee.contains("| `grid` | 50 of 50 | 800 | 0 | 1.500e-13 | 2.500e-1 | 0 |"), "{referee}");
        assert!(referee.contains("| `star` | not run | - |"), "{referee}");
        let identity = atlas.identity_table(&clippers);
        assert_eq!(
            &row(&identity, "ext")[..5],
            ["`ext`", "Ext 1", "Go", "ext 1.2.3 (rings as given)", "own process: `ext --serve`"]
        );
        assert_eq!(row(&identity, "vatti")[3], "-");
    }

    #[test]
    fn the_notes_add_the_counts_up_and_name_every_kind_of_failure() {
        let results = synthetic("notes");
        let atlas = read_synthetic(&results);
        assert_eq!(atlas.verified("ext"), Some((7 + 2, 3, 800 + 80)), "the largest run of each workload, summed");
        let notes = atlas.notes("ext");
        for part in [
            "fails the oracle on 9 of 880 verify results (its shrunk cases: 1 error, 1 invalid output, 1 wrong region)",
            "gave no answer in time on 3 of 880 verify results",
            "fails 1 of 5 Clipper2's Polygons.txt",
            "wrong or invalid output on 2 of 10 hostile calls",
            "refused on 1 of 10 hostile calls",
            "crashed on 1 of 10 hostile calls",
            "hung on 1 of 10 hostile calls",
        ] {
            assert!(notes.contains(part), "{part}: {notes}");
        }
        assert_eq!(atlas.notes("vatti"), "no failure found");
        assert_eq!(atlas.notes("clipper2"), "", "it ran nowhere: nothing to say");
    }

    #[test]
    fn a_shrunk_failure_is_classed_by_what_its_message_says() {
        for (message, kind) in [
            ("invalid output: ring 0 has zero area (all its vertices are collinear)", "invalid output"),
            ("point (8.25, 15.25) should be outside the result but is inside", "wrong region"),
            ("result differs from the exact region by area 1.5e-1 (tolerance 2.8e-4)", "wrong region"),
            ("jsts failed: it answered with an error: TopologyException: found non-noded intersection", "error"),
            ("jsts failed: no answer within 20.0 s (killed)", "no answer"),
            ("something else", "other"),
        ] {
            assert_eq!(failure_kind(message, "jsts"), kind, "{message}");
        }
    }

    /// `verify --partition K/N` parts: a workload's rows and recorded failures are joined once all
    /// N parts are in the folder, a part read twice counts once, and a run missing a part counts
    /// for nothing.
    #[test]
    fn verify_parts_are_joined_only_when_all_are_there() {
        let results = synthetic("verify-parts");
        let atlas_dir = results.join(FOLDER);
        let part = |file: &str, k: usize, n: usize, rows: &[(&str, &str, usize, usize, usize)], shrunk| {
            let path = atlas_dir.join(file);
            verify_file(&path, 80, rows, shrunk);
            let mut parsed: VerifyResults = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
            parsed.partition = Some(crate::partition::Partition { k, n });
            write(&path, &serde_json::to_string(&parsed).unwrap());
        };
        let wrong = [("ext", "scribble", "point (1, 2) should be inside the result but is outside")];
        part(
            "verify-80/scribble.part-1.json",
            1,
            2,
            &[("ext", "scribble", 2, 1, 640), ("vatti", "scribble", 0, 0, 640)],
            &wrong,
        );
        part(
            "verify-80/scribble.part-2.json",
            2,
            2,
            &[("ext", "scribble", 3, 0, 640), ("vatti", "scribble", 0, 0, 640)],
            &[],
        );
        // The same part again, under another name: read once.
        part("verify-80/scribble.part-2-again.json", 2, 2, &[("ext", "scribble", 3, 0, 640)], &[]);
        part("verify-80/large.part-1.json", 1, 3, &[("ext", "large", 5, 0, 640)], &[]);
        let atlas = read_synthetic(&results);
        let scribble = &atlas.verify["scribble"];
        assert_eq!(scribble.0, 80);
        let ext = scribble.1.iter().find(|r| r.clipper == "ext").unwrap();
        assert_eq!((ext.oracle_failures, ext.hung, ext.runs), (5, 1, 1280));
        let before = read_synthetic(&synthetic("verify-parts-none")).recorded["ext"]["wrong region"];
        assert_eq!(atlas.recorded["ext"]["wrong region"], before + 1, "the parts' recorded failure, once");
        assert!(!atlas.verify.contains_key("large"), "one part of three is not a run");
    }

    /// `referee --partition K/N` parts: joined once all N are in the folder, and a run missing a
    /// part counts for nothing.
    #[test]
    fn referee_parts_are_joined_only_when_all_are_there() {
        let results = synthetic("parts");
        let atlas_dir = results.join(FOLDER);
        let part = |file: &str, k: usize, n: usize, cases: usize, largest: f64, beyond: usize| {
            write(
                &atlas_dir.join(file),
                &format!(
                    r#"{{"referee": "cgal", "seed": 1, "cases_per_workload": 80, "partition": {{"k": {k}, "n": {n}}},
                       "workloads": [{{"workload": "WORKLOAD", "cases": {cases}, "compared": {}, "failed": 1,
                       "largest_relative": {largest}, "largest_of_bound": 0.5, "beyond_rounding": {beyond}}}],
                       "beyond_rounding": [], "failures": []}}"#,
                    cases * 16
                ),
            )
        };
        // star: both parts of two; holes: one part of two only.
        part("referee-80/star.part-1.json", 1, 2, 40, 1e-13, 0);
        part("referee-80/star.part-2.json", 2, 2, 40, 3e-13, 1);
        part("referee-80/holes.part-1.json", 1, 2, 40, 1e-13, 0);
        for file in ["referee-80/star.part-1.json", "referee-80/star.part-2.json", "referee-80/holes.part-1.json"] {
            let path = atlas_dir.join(file);
            let text = std::fs::read_to_string(&path).unwrap();
            let workload = if file.contains("star") { "star" } else { "holes" };
            write(&path, &text.replace("WORKLOAD", workload));
        }
        let atlas = read_synthetic(&results);
        let joined = &atlas.referee["star"].2;
        assert_eq!((joined.cases, joined.compared, joined.failed, joined.beyond_rounding), (80, 1280, 2, 1));
        assert_eq!(joined.largest_relative, 3e-13);
        assert!(!atlas.referee.contains_key("holes"), "one part of two is not a run");
    }

    #[test]
    fn no_atlas_folder_no_section() {
        let results = scratch("none");
        assert!(derive(&ResultsFolder::new(&results)).unwrap().is_none());
        let results = synthetic("some");
        let derived = derive(&ResultsFolder::new(&results)).unwrap().unwrap();
        assert!(derived.body.contains("| `ext` |"), "{}", derived.body);
    }

    /// The committed atlas: a few rows of the section against the raw JSON, read here apart.
    #[test]
    fn the_committed_atlas_matches_its_raw_files() {
        let results = Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("results");
        let atlas_dir = results.join(FOLDER);
        assert!(atlas_dir.is_dir(), "{} is committed", atlas_dir.display());
        let atlas = Atlas::read(&atlas_dir, parse_file(&repository_clippers()).unwrap()).unwrap();
        let clippers = atlas.clippers();
        let workloads = atlas.workloads();
        let json = |path: &Path| -> serde_json::Value {
            serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
        };
        // Hostile: every tally of the file, cell by cell.
        let hostile = json(&atlas_dir.join(HOSTILE_JSON));
        let judged = atlas.judged_table(&clippers);
        let tallies = hostile["tallies"].as_array().unwrap();
        assert!(!tallies.is_empty());
        for t in tallies {
            let n = |k: &str| t[k].as_u64().unwrap();
            assert_eq!(n("right") + n("wrong") + n("refused") + n("crashed") + n("hung"), n("runs"));
            let cell = format!(
                "{} / {} / {} / {} / {} of {}",
                n("right"),
                n("wrong"),
                n("refused"),
                n("crashed"),
                n("hung"),
                n("runs")
            );
            let cells = row(&judged, t["clipper"].as_str().unwrap());
            assert_eq!(cells.last().unwrap().trim_matches('*'), cell);
        }
        // Verify: the largest run of one workload, every clipper's cell.
        let mut largest: Option<(usize, PathBuf)> = None;
        for entry in std::fs::read_dir(&atlas_dir).unwrap() {
            let path = entry.unwrap().path();
            let name = path.file_name().unwrap().to_str().unwrap().to_owned();
            if let Some(n) = name.strip_prefix("verify-").and_then(|n| n.parse::<usize>().ok()) {
                let file = path.join("star.json");
                if file.exists() && largest.as_ref().is_none_or(|l| n > l.0) {
                    largest = Some((n, file));
                }
            }
        }
        let (n, file) = largest.expect("a verify run of star");
        let star = json(&file);
        let verify = atlas.verify_table(&clippers, &workloads);
        let column = 1 + workloads.iter().position(|w| w == "star").unwrap();
        assert!(verify.contains(&format!("`star` ({n} cases)")), "{verify}");
        for r in star["rows"].as_array().unwrap() {
            let cell = format!("{} / {}", r["oracle_failures"], r["runs"]);
            let cell = match r["hung"].as_u64() {
                Some(hung) if hung > 0 => format!("{cell}, {hung} hung"),
                _ => cell,
            };
            assert_eq!(row(&verify, r["clipper"].as_str().unwrap())[column].replace('*', ""), cell);
        }
        // Every external clipper of adapters/clippers.toml has a row, with its library, and its
        // version where the hostile file recorded the handshake.
        let identity = atlas.identity_table(&clippers);
        for spec in parse_file(&repository_clippers()).unwrap() {
            let cells = row(&identity, &spec.name);
            assert_eq!(cells[1], spec.library.unwrap());
            let recorded =
                tallies.iter().find(|t| t["clipper"] == spec.name.as_str()).and_then(|t| t["handshake"].as_str());
            if let Some(handshake) = recorded {
                assert_eq!(cells[3], handshake);
            }
        }
    }
}
