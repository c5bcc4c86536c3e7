//! External clippers end to end: a deliberately broken one (crash, hang, garbage, wrong id) fails
//! only those cases and every other case is judged; its line clipping is judged by the line
//! oracle; bad commands, handshakes and files are refused with the clipper's name and what it said.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn clipbench(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_clipbench")).args(args).output().expect("the clipbench binary runs")
}

/// A fresh folder for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("external").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[test]
fn a_broken_clipper_fails_its_broken_cases_and_every_other_case_is_judged() {
    let dir = scratch("broken");
    // Requests 5, 9, 13 and 17 crash, hang, answer garbage and answer the wrong id; one thread
    // keeps the order fixed.
    let external = broken_clipper(&dir, [5, 9, 13, 17]);
    let json = dir.join("summary.json");
    let o = clipbench(&[
        "verify",
        "--external",
        &external,
        "--clipper",
        "broken",
        "--workload",
        "star",
        "--cases",
        "6",
        "--threads",
        "1",
        "--call-timeout",
        "2",
        "--max-records",
        "0",
        "--out",
        dir.join("failures").to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ]);
    // A peer: its failures are reported, the run succeeds.
    assert!(o.status.success(), "{}\n{}", text(&o.stdout), text(&o.stderr));
    let summary: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let rows = summary["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 1, "{rows:?}");
    assert_eq!(rows[0]["origin"], "external");
    // 6 cases x intersection x 4 fill rules, every one judged; only the four broken ones fail,
    // the hang counted apart from the oracle failures.
    assert_eq!(rows[0]["runs"], 24);
    assert_eq!(rows[0]["oracle_failures"], 3, "{}", text(&o.stdout));
    assert_eq!(rows[0]["hung"], 1, "{}", text(&o.stdout));
    let found: Vec<String> = summary["cases"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            let case: serde_json::Value = serde_json::from_str(
                &std::fs::read_to_string(dir.join("failures").join(c["folder"].as_str().unwrap()).join("case.json"))
                    .unwrap(),
            )
            .unwrap();
            // The case also opens in a GIS: subject and clip as GeoJSON features.
            let folder = dir.join("failures").join(c["folder"].as_str().unwrap());
            let geojson: serde_json::Value =
                serde_json::from_str(&std::fs::read_to_string(folder.join("case.geojson")).unwrap()).unwrap();
            let roles: Vec<&str> = geojson["features"]
                .as_array()
                .unwrap()
                .iter()
                .map(|f| f["properties"]["role"].as_str().unwrap())
                .collect();
            assert!(roles.starts_with(&["subject", "clip"]), "{roles:?}");
            case["found"].as_str().unwrap().to_owned()
        })
        .collect();
    assert_eq!(found.len(), 4, "{found:?}");
    assert!(found[0].contains("exited") && found[0].contains("crashing on purpose"), "{}", found[0]);
    assert!(found[1].contains("no answer within 2.0 s"), "{}", found[1]);
    assert!(found[2].contains("not a reply") && found[2].contains("this is not a reply"), "{}", found[2]);
    assert!(found[3].contains("answered id") && found[3].contains("to request"), "{}", found[3]);
    assert!(found.iter().all(|f| f.starts_with("broken failed: ")), "{found:?}");
}

/// `--external broken=...` running tests/broken_clipper.py with the given faults (0: none).
fn broken_clipper(dir: &Path, faults: [u32; 4]) -> String {
    broken_clipper_with(dir, faults, [0, 0])
}

/// [`broken_clipper`] with the faults after the first four: an impossible time on the request
/// given, and lies from the request given on.
fn broken_clipper_with(dir: &Path, faults: [u32; 4], [bad_time, lie]: [u32; 2]) -> String {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests").join("broken_clipper.py");
    let state = dir.join("requests");
    let [crash, hang, garbage, wrong_id] = faults;
    format!(
        "broken=python3 '{}' '{}' {crash} {hang} {garbage} {wrong_id} {bad_time} {lie}",
        script.display(),
        state.display()
    )
}

/// Runs `verify` of the broken clipper on `star` (one thread, every failure written) and returns
/// the output and the JSON summary.
fn verify_broken(dir: &Path, external: &str, cases: &str, more: &[&str]) -> (Output, serde_json::Value) {
    let json = dir.join("summary.json");
    let failures = dir.join("failures");
    let mut args = vec![
        "verify",
        "--external",
        external,
        "--clipper",
        "broken",
        "--workload",
        "star",
        "--cases",
        cases,
        "--threads",
        "1",
        "--max-records",
        "0",
        "--out",
        failures.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ];
    args.extend_from_slice(more);
    let o = clipbench(&args);
    let summary = serde_json::from_str(
        &std::fs::read_to_string(&json)
            .unwrap_or_else(|e| panic!("no summary ({e}): {}{}", text(&o.stdout), text(&o.stderr))),
    )
    .unwrap();
    (o, summary)
}

/// The `found` of every failure case the summary lists.
fn found(dir: &Path, summary: &serde_json::Value) -> Vec<serde_json::Value> {
    summary["cases"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            let path = dir.join("failures").join(c["folder"].as_str().unwrap()).join("case.json");
            serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
        })
        .collect()
}

/// On a starved machine, adapters that gave no answer within --call-timeout were counted as
/// oracle failures (issue 31). A hang is counted apart, in `hung`, and still recorded with its
/// replay, under the check `hung`.
#[test]
fn a_hang_is_counted_as_hung_not_as_an_oracle_failure() {
    let dir = scratch("hung");
    // Request 3 of 8 never gets an answer.
    let external = broken_clipper(&dir, [0, 3, 0, 0]);
    let (o, summary) = verify_broken(&dir, &external, "2", &["--call-timeout", "2"]);
    assert!(o.status.success(), "{}\n{}", text(&o.stdout), text(&o.stderr));
    let row = &summary["rows"][0];
    let counts = (row["runs"].as_u64(), row["oracle_failures"].as_u64(), row["hung"].as_u64());
    assert_eq!(counts, (Some(8), Some(0), Some(1)), "{row}");
    // The text summary: a `hung` column beside `oracle fail`.
    let table = text(&o.stdout);
    let mut lines = table.lines();
    let head: Vec<&str> = lines.next().unwrap().split("  ").map(str::trim).filter(|c| !c.is_empty()).collect();
    let broken = lines.find(|l| l.starts_with("broken")).unwrap_or_else(|| panic!("{table}"));
    let cells: Vec<&str> = broken.split_whitespace().collect();
    let cell = |name: &str| cells[head.iter().position(|h| *h == name).unwrap_or_else(|| panic!("{name}: {table}"))];
    assert_eq!((cell("oracle fail"), cell("hung")), ("0", "1"), "{table}");
    // Recorded under `hung`, with a replay that runs (the hang was on request 3 only: it passes).
    let cases = found(&dir, &summary);
    assert_eq!(cases.len(), 1, "{cases:?}");
    assert_eq!(cases[0]["check"], "hung");
    let message = cases[0]["found"].as_str().unwrap();
    assert!(message.contains("no answer within 2.0 s"), "{message}");
    let folder = summary["cases"][0]["folder"].as_str().unwrap();
    assert!(folder.ends_with("-broken-hung"), "{folder}");
    let words = shlex::split(cases[0]["replay"].as_str().unwrap()).unwrap();
    let args: Vec<&str> = words[1..].iter().map(String::as_str).collect();
    let again = clipbench(&args);
    assert_eq!(again.status.code(), Some(0), "{}\n{}", text(&again.stdout), text(&again.stderr));
    assert!(text(&again.stdout).starts_with("passes now: polygon broken hung"), "{}", text(&again.stdout));
}

/// A reply's own time of -5 ns was dropped without a word; it is a protocol error now, which
/// fails that case and names the time (issue 28).
#[test]
fn a_reply_with_an_impossible_time_fails_its_case_naming_the_time() {
    let dir = scratch("bad-time");
    let (o, summary) = verify_broken(&dir, &broken_clipper_with(&dir, [0, 0, 0, 0], [3, 0]), "2", &[]);
    assert!(o.status.success(), "{}\n{}", text(&o.stdout), text(&o.stderr));
    let row = &summary["rows"][0];
    assert_eq!((row["runs"].as_u64(), row["oracle_failures"].as_u64()), (Some(8), Some(1)), "{row}");
    let cases = found(&dir, &summary);
    let message = cases[0]["found"].as_str().unwrap();
    assert!(message.contains("time_ns -5") && message.contains("round trip"), "{message}");
}

/// The replay command written for an external clipper's failure lacked its `--external`
/// option, so it failed with "unknown clipper" (issue 28); it runs now.
#[test]
fn the_replay_command_of_an_external_clippers_failure_runs_as_printed() {
    let dir = scratch("replay-external");
    let external = broken_clipper(&dir, [2, 0, 0, 0]);
    let (o, summary) = verify_broken(&dir, &external, "1", &["--call-timeout", "30"]);
    assert!(o.status.success(), "{}\n{}", text(&o.stdout), text(&o.stderr));
    let cases = found(&dir, &summary);
    let replay = cases[0]["replay"].as_str().unwrap();
    assert!(replay.contains("--external") && replay.contains("--call-timeout 30"), "{replay}");
    assert!(text(&o.stdout).contains(replay), "the printed line gives the same command: {}", text(&o.stdout));
    let words = shlex::split(replay).unwrap();
    assert_eq!(words[0], "clipbench");
    let args: Vec<&str> = words[1..].iter().map(String::as_str).collect();
    let again = clipbench(&args);
    // The crash was on request 2 only: replayed, it passes.
    assert_eq!(again.status.code(), Some(0), "{}\n{}", text(&again.stdout), text(&again.stderr));
    assert!(text(&again.stdout).starts_with("passes now: polygon broken oracle"), "{}", text(&again.stdout));
}

/// A lying clipper's summary read "48 runs, 60 oracle failures": failed area identities were
/// counted in the oracle column, though they are no run (issue 28). They have their own now.
#[test]
fn area_identity_failures_are_counted_apart_from_the_runs_oracle_failures() {
    let dir = scratch("identities");
    let (o, summary) = verify_broken(&dir, &broken_clipper_with(&dir, [0, 0, 0, 0], [0, 1]), "3", &[]);
    assert!(o.status.success(), "{}\n{}", text(&o.stdout), text(&o.stderr));
    let row = &summary["rows"][0];
    let (runs, oracle, identities) =
        (row["runs"].as_u64().unwrap(), row["oracle_failures"].as_u64().unwrap(), row["identity_failures"].as_u64());
    assert_eq!(runs, 3 * 4 * 4, "{row}");
    assert!(oracle > 0 && oracle <= runs, "{row}");
    assert!(identities.is_some_and(|i| i > 0 && i <= 3 * 4), "{row}");
    let table = text(&o.stdout);
    assert!(table.lines().next().unwrap().contains("identity fail"), "{table}");
}

/// An external clipper that answers polygon requests with the subject unclipped (a wrong
/// region) while the subject has at least `WRONG_FROM` vertices, and declines smaller ones with
/// an error reply (its process kept, so shrinking stays quick).
const WRONG_THEN_DECLINING: &str = r#"import json, sys
WRONG_FROM = int(sys.argv[1])
print(json.dumps({"protocol": 1, "name": "wrong, then declining", "polygon": {"ops": ["intersection"],
    "fill_rules": ["even-odd", "non-zero", "positive", "negative"], "window": "rectangle", "output": "bridged"}}), flush=True)
for line in sys.stdin:
    request = json.loads(line)
    if sum(len(ring) for ring in request["subject"]) >= WRONG_FROM:
        print(json.dumps({"id": request["id"], "rings": request["subject"]}), flush=True)
    else:
        print(json.dumps({"id": request["id"], "error": "declined on purpose"}), flush=True)
"#;

/// A wrong answer found on a large case shrank to whatever smaller case failed at all: here the
/// clipper's refusal of small inputs (issue 28). The shrunk case fails as the case found does, by
/// the oracle's verdict on a wrong region, on the smallest subject still answered wrong.
#[test]
fn a_wrong_answer_shrinks_to_a_smaller_wrong_answer_not_to_a_refusal() {
    let dir = scratch("shrink-same-way");
    let script = dir.join("wrong_then_declining.py");
    std::fs::write(&script, WRONG_THEN_DECLINING).unwrap();
    let external = format!("liar=python3 '{}' 8", script.display());
    let json = dir.join("summary.json");
    let o = clipbench(&[
        "verify",
        "--external",
        &external,
        "--clipper",
        "liar",
        "--workload",
        "star",
        "--cases",
        "1",
        "--fill",
        "even-odd",
        "--threads",
        "1",
        "--out",
        dir.join("failures").to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}\n{}", text(&o.stdout), text(&o.stderr));
    let summary: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let cases = found(&dir, &summary);
    assert_eq!(cases.len(), 1, "{summary}");
    let case = &cases[0];
    let (generated, shrunk) =
        (case["generated_vertices"][0].as_u64().unwrap(), case["shrunk_vertices"][0].as_u64().unwrap());
    let message = case["shrunk"].as_str().unwrap();
    assert!(!message.contains("declined on purpose"), "shrunk to the refusal: {message}");
    assert_eq!(case["check"], "oracle");
    assert!((8..generated).contains(&shrunk), "{shrunk} of {generated} vertices: {message}");
}

#[test]
fn an_external_line_clipper_is_judged_by_the_line_oracle() {
    let dir = scratch("lines");
    let json = dir.join("summary.json");
    let o = clipbench(&[
        "verify",
        "--external",
        &broken_clipper(&dir, [0, 0, 0, 0]),
        "--clipper",
        "broken",
        "--workload",
        "lines-degenerate",
        "--workload",
        "wang-t4",
        "--cases",
        "10",
        "--segments",
        "30",
        "--out",
        dir.join("failures").to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}\n{}", text(&o.stdout), text(&o.stderr));
    let summary: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let lines: Vec<&serde_json::Value> =
        summary["rows"].as_array().unwrap().iter().filter(|r| r["kind"] == "line").collect();
    assert_eq!(lines.len(), 2, "{}", text(&o.stdout));
    for row in lines {
        assert_eq!((row["runs"].as_u64(), row["oracle_failures"].as_u64()), (Some(10), Some(0)), "{row}");
    }
}

/// Runs `verify` with one external clipper and returns its exit code and error line.
fn refused(external: &str) -> (Option<i32>, String) {
    let o = clipbench(&["verify", "--external", external, "--workload", "star", "--cases", "1"]);
    (o.status.code(), text(&o.stderr))
}

#[test]
fn bad_commands_and_handshakes_name_the_clipper_and_what_it_said() {
    let (code, e) = refused("gone=./no-such-clipper --json");
    assert_eq!(code, Some(2), "{e}");
    assert!(e.contains("external clipper 'gone'") && e.contains("cannot start ./no-such-clipper --json"), "{e}");

    let (code, e) = refused("dies=sh -c 'echo missing licence file >&2; exit 4'");
    assert_eq!(code, Some(2), "{e}");
    assert!(e.contains("'dies'") && e.contains("at the handshake") && e.contains("missing licence file"), "{e}");

    let (code, e) = refused(r#"talks=sh -c 'echo hello; sleep 1'"#);
    assert_eq!(code, Some(2), "{e}");
    assert!(e.contains("'talks'") && e.contains("not a protocol handshake") && e.contains("'hello'"), "{e}");

    let curve = r#"{"protocol":1,"name":"c","polygon":{"ops":["union"],"fill_rules":["even-odd"],"window":"circle"}}"#;
    let (code, e) = refused(&format!("curvy=sh -c 'echo {}; cat >/dev/null'", curve.replace('"', "\\\"")));
    assert_eq!(code, Some(2), "{e}");
    assert!(e.contains("'curvy'") && e.contains("unknown window kind 'circle'"), "{e}");

    let (code, e) = refused("vatti=sh -c 'exit 0'");
    assert_eq!(code, Some(2), "{e}");
    assert!(e.contains("'vatti': the name is taken"), "{e}");
}

#[test]
fn a_clippers_file_with_an_unknown_key_is_refused_with_its_line() {
    let dir = scratch("toml");
    let file = dir.join("clippers.toml");
    std::fs::write(&file, "[[clipper]]\nname = \"mine\"\ncommand = \"./mine\"\nretries = 3\n").unwrap();
    let o = clipbench(&["verify", "--clippers", file.to_str().unwrap(), "--cases", "1"]);
    let e = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.contains("clippers.toml: line 4") && e.contains("retries"), "{e}");
}

/// `--external NAME=...` running tests/lying_clipper.py in `mode` (`square` or `empty`).
fn lying_clipper(name: &str, mode: &str) -> String {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests").join("lying_clipper.py");
    format!("{name}=python3 '{}' {mode}", script.display())
}

#[test]
fn a_lying_clipper_and_an_empty_one_are_timed_marked_wrong_and_not_ranked() {
    let dir = scratch("lying");
    let out = dir.join("results");
    let o = clipbench(&[
        "bench",
        "--quick",
        "--workload",
        "star",
        "--op",
        "intersection",
        "--rounds",
        "1",
        "--external",
        &lying_clipper("square", "square"),
        "--external",
        &lying_clipper("empty", "empty"),
        "--clipper",
        "square",
        "--clipper",
        "empty",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}\n{}", text(&o.stdout), text(&o.stderr));
    let mut reader = csv::Reader::from_path(out.join("bench.csv")).unwrap();
    let header = reader.headers().unwrap().clone();
    let column = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (clipper, correct) = (column("clipper"), column("correct"));
    let rows: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    for name in ["square", "empty", "clipper2"] {
        let verdicts: Vec<&str> = rows.iter().filter(|r| &r[clipper] == name).map(|r| &r[correct]).collect();
        assert!(!verdicts.is_empty(), "{name} was timed");
        let expected = if name == "clipper2" { "true" } else { "false" };
        assert!(verdicts.iter().all(|v| *v == expected), "{name}: {verdicts:?}");
    }
    let md = std::fs::read_to_string(out.join("bench.md")).unwrap();
    let table = md.lines().find(|l| l.starts_with("| 20 |")).expect("a row at 20 edges");
    // Columns in first-seen order; both liars' cells say so, and no ratio stands beside them.
    assert_eq!(table.matches("wrong on 2 of 2 cases").count(), 2, "{table}");
    // REPORT.md opens with the summary: every bench point of both liars wrong, no speed given.
    let report = std::fs::read_to_string(out.join("REPORT.md")).unwrap();
    let first_section = report.lines().find(|l| l.starts_with("## ")).unwrap();
    assert!(first_section.starts_with("## Summary"), "{first_section}");
    for liar in ["square", "empty"] {
        let row = report.lines().find(|l| l.starts_with(&format!("| `{liar}` | external"))).unwrap();
        assert!(row.ends_with("| **4 / 4** | – | – | – |"), "{row}");
    }
    let notes = std::fs::read_to_string(out.join("bench.meta.json")).unwrap();
    assert!(notes.contains("square: wrong on") && notes.contains("empty: wrong on"), "{notes}");
}

/// The atlas names each external clipper's library and version as its handshake gave them:
/// `hostile --json` and `conformance --json` record it beside the counts, and only for external
/// clippers.
#[test]
fn hostile_and_conformance_files_record_what_the_handshake_named() {
    let dir = scratch("handshake-recorded");
    let external = lying_clipper("square", "square");
    // The command before its clippers, and the list of tallies its file holds.
    for (command, list) in [(&["hostile"][..], "tallies"), (&["conformance", "geo-booleanop"][..], "clippers")] {
        let json = dir.join(format!("{}.json", command[0]));
        let mut args = command.to_vec();
        args.extend(["--external", &external, "--clipper", "square", "--clipper", "vatti"]);
        args.extend(["--json", json.to_str().unwrap()]);
        let o = clipbench(&args);
        assert!(o.status.success(), "{}", text(&o.stderr));
        let file: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
        let tallies = file[list].as_array().unwrap();
        let of = |name: &str| tallies.iter().find(|t| t["clipper"] == name).unwrap_or_else(|| panic!("{name}: {file}"));
        assert_eq!(of("square")["handshake"], "lying test clipper (square)", "{file}");
        assert!(of("vatti").get("handshake").is_none(), "{file}");
    }
}
