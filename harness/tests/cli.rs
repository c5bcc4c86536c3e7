//! The clipbench binary end to end: `clip` on files, bad input, `verify` and its JSON summary,
//! determinism across thread counts, and `--replay`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::str::FromStr;

use clip_testkit::workload::{LINE_WORKLOADS, POLYGON_WORKLOADS, TEXT_WORKLOADS};

fn clipbench(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_clipbench")).args(args).output().expect("the clipbench binary runs")
}

/// A fresh folder for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("cli").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_owned()
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The area of a MULTIPOLYGON/POLYGON WKT text (outer rings positive, holes negative).
fn wkt_area(text: &str) -> f64 {
    let wkt = wkt::Wkt::<f64>::from_str(text.trim()).unwrap_or_else(|e| panic!("not WKT ({e}): {text}"));
    let mp: geo::MultiPolygon<f64> = match geo::Geometry::try_from(wkt).unwrap() {
        geo::Geometry::MultiPolygon(mp) => mp,
        geo::Geometry::Polygon(p) => geo::MultiPolygon(vec![p]),
        other => panic!("not polygons: {other:?}"),
    };
    use geo::Area;
    mp.signed_area()
}

#[test]
fn clip_round_trips_a_wkt_case_with_each_peer() {
    let dir = scratch("clip");
    // An L shape with a hole against a square that cuts through the hole.
    let subject =
        write(&dir, "subject.wkt", "POLYGON((0 0,6 0,6 2,2 2,2 6,0 6,0 0),(0.5 0.5,0.5 1.5,1.5 1.5,1.5 0.5,0.5 0.5))");
    let clip = write(&dir, "clip.wkt", "POLYGON((1 1,5 1,5 5,1 5,1 1))");
    // |L| = 20 - 1 (hole) ; L ∩ square = [1,5]x[1,2] ∪ [1,2]x[2,5] minus the hole's [1,1.5]^2 = 4 + 3 - 0.25.
    let expected = 6.75;
    for peer in ["geo", "clipper2"] {
        let o = clipbench(&["clip", "--clipper", peer, "--op", "intersection", "--fill", "non-zero", &subject, &clip]);
        assert!(o.status.success(), "{peer}: {}", stderr(&o));
        let first = stdout(&o);
        assert!((wkt_area(&first) - expected).abs() < 1e-6, "{peer}: {first}");
        // Written to a file and read back: clipping the result again changes nothing.
        let out = dir.join(format!("{peer}.wkt"));
        let o = clipbench(&["clip", "--clipper", peer, "--op", "and", &subject, &clip, "-o", out.to_str().unwrap()]);
        assert!(o.status.success(), "{peer}: {}", stderr(&o));
        let o = clipbench(&["clip", "--clipper", peer, out.to_str().unwrap(), &clip]);
        assert!(o.status.success(), "{peer}: {}", stderr(&o));
        assert!((wkt_area(&stdout(&o)) - expected).abs() < 1e-6, "{peer}: {}", stdout(&o));
        // GeoJSON and SVG outputs by extension.
        for ext in ["geojson", "svg"] {
            let out = dir.join(format!("{peer}.{ext}"));
            let o = clipbench(&["clip", "--clipper", peer, &subject, &clip, "-o", out.to_str().unwrap()]);
            assert!(o.status.success(), "{peer} {ext}: {}", stderr(&o));
            let text = std::fs::read_to_string(&out).unwrap();
            assert!(text.contains(if ext == "svg" { "<svg" } else { "MultiPolygon" }), "{text}");
        }
    }
}

#[test]
fn clip_reads_geojson_and_clips_line_strings_with_geo() {
    let dir = scratch("clip-lines");
    let lines = write(&dir, "lines.wkt", "MULTILINESTRING((-1 1,3 1),(0.5 -1,0.5 3))");
    let window = write(&dir, "window.geojson", r#"{"type":"Polygon","coordinates":[[[0,0],[2,0],[2,2],[0,2],[0,0]]]}"#);
    let o = clipbench(&["clip", "--clipper", "geo", &lines, &window]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(text.starts_with("MULTILINESTRING"), "{text}");
    let Ok(geo::Geometry::MultiLineString(mls)) =
        geo::Geometry::try_from(wkt::Wkt::<f64>::from_str(text.trim()).unwrap())
    else {
        panic!("{text}")
    };
    use geo::Length;
    let total: f64 = mls.0.iter().map(|l| geo::Euclidean.length(l)).sum();
    assert!((total - 4.0).abs() < 1e-6, "{text}");
    // Clipper2 has no line clipper: the message says which do.
    let o = clipbench(&["clip", "--clipper", "clipper2", &lines, &window]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("line clippers:") && stderr(&o).contains("geo"), "{}", stderr(&o));
}

#[test]
fn broken_or_missing_files_exit_2_with_a_one_line_message_naming_the_file() {
    let dir = scratch("broken");
    let good = write(&dir, "good.wkt", "POLYGON((0 0,1 0,1 1,0 0))");
    let cases = [
        (write(&dir, "cut.wkt", "POLYGON((0 0,1 0,1 1"), "not valid WKT"),
        (write(&dir, "two.wkt", "POLYGON((0 0,1 0,0 0))"), "distinct point"),
        (write(&dir, "nan.wkt", "POLYGON((0 0,1e999 0,1 1,0 0))"), "not finite"),
        (write(&dir, "bad.geojson", "{\"type\": \"Polygon\", \"coordinates\": 5}"), "GeoJSON"),
        (write(&dir, "point.wkt", "POINT(1 2)"), "points"),
        (dir.join("missing.wkt").to_str().unwrap().to_owned(), "cannot read"),
    ];
    for (file, problem) in &cases {
        let o = clipbench(&["clip", "--clipper", "geo", file, &good]);
        assert_eq!(o.status.code(), Some(2), "{file}: {}", stderr(&o));
        let err = stderr(&o);
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains(file.as_str()) && err.contains(problem), "{file}: {err}");
    }
}

#[test]
fn unknown_names_list_the_valid_ones() {
    let o = clipbench(&["verify", "--clipper", "nope", "--cases", "1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("geo, clipper2"), "{}", stderr(&o));
    let o = clipbench(&["verify", "--workload", "nope", "--cases", "1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("star") && stderr(&o).contains("wang-t4"), "{}", stderr(&o));
}

fn verify_json(dir: &Path, threads: &str) -> (Output, serde_json::Value) {
    let json = dir.join(format!("summary-{threads}.json"));
    let out = dir.join(format!("failures-{threads}"));
    let o = clipbench(&[
        "verify",
        "--clipper",
        "geo",
        "--clipper",
        "clipper2",
        "--workload",
        "star",
        "--workload",
        "grid",
        "--workload",
        "lines-degenerate",
        "--cases",
        "12",
        "--fill",
        "even-odd",
        "--fill",
        "non-zero",
        "--segments",
        "20",
        "--max-records",
        "1",
        "--threads",
        threads,
        "--out",
        out.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&json).unwrap_or_else(|e| panic!("no JSON summary ({e}): {}", stderr(&o)));
    (o, serde_json::from_str(&text).expect("the summary is JSON"))
}

#[test]
fn verify_prints_a_table_writes_json_and_does_not_depend_on_the_thread_count() {
    let dir = scratch("verify");
    let (one, summary_one) = verify_json(&dir, "1");
    // Peers only: their failures are reported and do not fail the run.
    assert!(one.status.success(), "{}", stderr(&one));
    let table = stdout(&one);
    assert!(table.lines().next().unwrap().contains("oracle fail"), "{table}");
    assert!(table.lines().any(|l| l.starts_with("geo") && l.contains("star")), "{table}");
    assert!(table.lines().any(|l| l.starts_with("clipper2") && l.contains("grid")), "{table}");
    assert!(table.lines().any(|l| l.starts_with("geo") && l.contains("lines-degenerate")), "{table}");
    let rows = summary_one["rows"].as_array().unwrap();
    let star_geo = rows.iter().find(|r| r["clipper"] == "geo" && r["workload"] == "star").unwrap();
    assert_eq!(star_geo["cases"], 12);
    assert_eq!(star_geo["runs"], 12 * 4 * 2, "every op under both fill rules");
    assert_eq!(summary_one["ours_failed"], false);

    let (_, summary_two) = verify_json(&dir, "2");
    assert_eq!(summary_one, summary_two);
}

/// Every clipper of this project on every workload it takes, every op and fill rule, against
/// the oracle: a regression in any of them fails CI here (peers are left out: their failures
/// are reported, not failed on).
#[test]
fn verify_passes_every_clipper_of_ours_on_every_workload() {
    let dir = scratch("verify-ours");
    let ours = [
        "vatti",
        "sutherland-hodgman",
        "sutherland-hodgman-split",
        "rect-four-state",
        "cyrus-beck",
        "liu",
        "virtual-box",
        "virtual-box-no45",
        "text-string",
        "text-char",
        "text-outline",
        "text-bitmap",
    ];
    // Every workload the testkit names, so a new one is verified here from the day it exists.
    let small: Vec<&str> = POLYGON_WORKLOADS
        .iter()
        .chain(LINE_WORKLOADS)
        .chain(TEXT_WORKLOADS)
        .copied()
        .filter(|&w| w != "large")
        .collect();
    for (workloads, cases) in [(&small[..], 120), (&["large"][..], 4)] {
        let json = dir.join(format!("{}.json", workloads[0]));
        let mut args = vec!["verify".to_owned(), "--cases".to_owned(), cases.to_string()];
        args.extend(workloads.iter().flat_map(|w| ["--workload".to_owned(), (*w).to_owned()]));
        args.extend(ours.iter().flat_map(|c| ["--clipper".to_owned(), (*c).to_owned()]));
        args.extend(["--json".to_owned(), json.to_str().unwrap().to_owned()]);
        args.extend(["--out".to_owned(), dir.join(workloads[0]).to_str().unwrap().to_owned()]);
        let o = clipbench(&args.iter().map(String::as_str).collect::<Vec<_>>());
        assert!(o.status.success(), "{}{}", stdout(&o), stderr(&o));
        let summary: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
        let rows = summary["rows"].as_array().unwrap();
        for w in workloads {
            let here: Vec<&serde_json::Value> = rows.iter().filter(|r| r["workload"] == *w).collect();
            assert!(!here.is_empty(), "no clipper ran {w}");
            for r in here {
                assert_eq!(r["cases"], cases, "{r}");
                assert_eq!(r["oracle_failures"], 0, "{r}");
            }
        }
    }
}

#[test]
fn replay_reruns_a_saved_case() {
    let dir = scratch("replay");
    write(&dir, "subject.wkt", "MULTIPOLYGON(((0 0,2 0,2 2,0 2,0 0)))");
    write(&dir, "clip.wkt", "MULTIPOLYGON(((1 1,3 1,3 3,1 3,1 1)))");
    let case = serde_json::json!({
        "kind": "polygon", "clipper": "clipper2", "check": "disagreement", "other": "geo",
        "workload": "star", "seed": 1, "index": 0, "window": "any", "op": "union", "fill": "even-odd",
        "found": "", "shrunk": "", "generated_vertices": [4, 4], "shrunk_vertices": [4, 4],
        "inputs": ["subject.wkt", "clip.wkt"], "replay": ""
    });
    let file = write(&dir, "case.json", &case.to_string());
    let o = clipbench(&["verify", "--replay", &file]);
    assert!(o.status.success(), "{}{}", stdout(&o), stderr(&o));
    assert!(stdout(&o).starts_with("passes now"), "{}", stdout(&o));
    let broken = write(&dir, "broken.json", "{\"kind\": 3}");
    let o = clipbench(&["verify", "--replay", &broken]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("broken.json"), "{}", stderr(&o));
}

#[test]
fn conformance_suites_run_and_print_a_closing_line_per_clipper() {
    let dir = scratch("conformance");
    let o = clipbench(&["conformance", "clipper2-polygons", "--clipper", "vatti", "--clipper", "clipper2"]);
    assert!(o.status.success(), "{}", stderr(&o));
    for line in ["vatti: 195 passed, 0 failed", "clipper2: 195 passed, 0 failed"] {
        assert!(stdout(&o).lines().any(|l| l == line), "{line}\n{}", stdout(&o));
    }
    // Case 44's stored area is off (Clipper2 rounds crossings to integers); vatti has the exact one.
    assert!(stdout(&o).contains("(vatti: of its passes, 1 by the exact area"), "{}", stdout(&o));
    let o = clipbench(&[
        "conformance",
        "clipper2-lines",
        "--clipper",
        "liu",
        "--clipper",
        "virtual-box",
        "--clipper",
        "geo",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    for name in ["liu", "virtual-box", "geo"] {
        let closing = format!("{name}: 15 passed, 0 failed");
        assert!(stdout(&o).lines().any(|l| l.starts_with(&closing)), "{closing}\n{}", stdout(&o));
    }
    let o = clipbench(&["conformance", "geo-booleanop", "--clipper", "vatti", "--clipper", "geo"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).lines().any(|l| l.starts_with("vatti: ") && l.contains(" passed, 0 failed")), "{}", stdout(&o));
    assert!(stdout(&o).lines().any(|l| l.starts_with("geo: ") && l.contains(" passed, ")), "{}", stdout(&o));
    // One case by name, with a picture.
    let svg = dir.join("168.svg");
    let o = clipbench(&[
        "conformance",
        "clipper2-polygons",
        "--clipper",
        "clipper2",
        "--case",
        "168",
        "--svg",
        svg.to_str().unwrap(),
    ]);
    assert!(stdout(&o).contains("clipper2: 1 passed, 0 failed"), "{}", stdout(&o));
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
    // A malformed record is that case's failure; a missing file is an error naming it.
    std::fs::create_dir_all(dir.join("clipper2")).unwrap();
    write(
        &dir.join("clipper2"),
        "Polygons.txt",
        "CAPTION: 1.\nCLIPTYPE: UNION\nFILLRULE: EVENODD\nSUBJECTS\n0,0, 4,0, 4\n",
    );
    let data = dir.to_str().unwrap();
    let o = clipbench(&["conformance", "clipper2-polygons", "--clipper", "clipper2", "--testdata", data]);
    assert!(stdout(&o).contains("Polygons.txt:5: odd number of coordinates"), "{}", stdout(&o));
    assert!(stdout(&o).contains("clipper2: 0 passed, 1 failed"), "{}", stdout(&o));
    let o = clipbench(&["conformance", "clipper2-lines", "--testdata", data]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("Lines.txt") && stderr(&o).contains("cannot read"), "{}", stderr(&o));
}

#[test]
fn an_empty_operand_is_the_empty_region() {
    let dir = scratch("empty");
    let subject = write(&dir, "subject.wkt", "POLYGON((0 0,2 0,2 2,0 2,0 0))");
    let empty = write(&dir, "empty.wkt", "MULTIPOLYGON EMPTY");
    for peer in ["geo", "clipper2"] {
        let o = clipbench(&["clip", "--clipper", peer, "--op", "union", &subject, &empty]);
        assert!(o.status.success(), "{peer}: {}", stderr(&o));
        assert!((wkt_area(&stdout(&o)) - 4.0).abs() < 1e-9, "{peer}: {}", stdout(&o));
    }
}

/// `clipbench text`: each strategy writes a picture; bad input exits 2 with a one-line message.
#[test]
fn text_draws_each_strategy_and_refuses_bad_input() {
    let dir = scratch("text");
    let font = clip_text::DEJAVU_SANS;
    let window = "POLYGON((30 0, 150 0, 150 60, 30 60, 30 0))";
    for (strategy, kept) in [("string", "0 of 8"), ("char", "6 of 8"), ("outline", "6 of 8"), ("bitmap", "2 of 8")] {
        let svg = dir.join(format!("{strategy}.svg"));
        let mut args = vec!["text", "Clipping", "--size", "40", "--at", "10,20", "--window", window];
        args.extend(["--strategy", strategy, "-o", svg.to_str().unwrap()]);
        if strategy != "bitmap" {
            args.extend(["--font", font]);
        }
        let o = clipbench(&args);
        assert!(o.status.success(), "{strategy}: {}", stderr(&o));
        assert!(stdout(&o).starts_with(kept), "{strategy}: {}", stdout(&o));
        assert!(std::fs::read_to_string(&svg).unwrap().starts_with("<svg"), "{strategy}");
    }
    let out = dir.join("bad.svg");
    let out = out.to_str().unwrap();
    let bad: [(&[&str], &str); 7] = [
        (&["text", "", "--font", font, "--size", "20", "--window", window, "--strategy", "char", "-o", out], "empty"),
        (
            &[
                "text",
                "a",
                "--font",
                "no-such.ttf",
                "--size",
                "20",
                "--window",
                window,
                "--strategy",
                "char",
                "-o",
                out,
            ],
            "no-such.ttf",
        ),
        (&["text", "a", "--font", font, "--size", "inf", "--window", window, "--strategy", "char", "-o", out], "size"),
        (
            &["text", "a", "--font", font, "--size", "-2", "--window", window, "--strategy", "outline", "-o", out],
            "size",
        ),
        (
            &["text", "a\u{E000}", "--font", font, "--size", "20", "--window", window, "--strategy", "char", "-o", out],
            "no glyph",
        ),
        (&["text", "é", "--size", "20", "--window", window, "--strategy", "bitmap", "-o", out], "no glyph"),
        (
            &[
                "text",
                "a",
                "--font",
                font,
                "--size",
                "20",
                "--window",
                "POLYGON((0 0, 1 1, 2 2, 0 0))",
                "--strategy",
                "char",
                "-o",
                out,
            ],
            "degenerate",
        ),
    ];
    for (args, says) in bad {
        let o = clipbench(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(says) && stderr(&o).lines().count() == 1, "{args:?}: {}", stderr(&o));
    }
}
