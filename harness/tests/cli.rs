//! The clipbench binary end to end: `clip` on files, bad input, `verify` and its JSON summary,
//! determinism across thread counts, and `--replay`.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::str::FromStr;

use clip_testkit::workload::{CURVE_WORKLOADS, LINE_WORKLOADS, POLYGON_WORKLOADS, TEXT_WORKLOADS};

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

/// A polygon of `n` vertices on a circle of radius 100: clipped by a larger square it comes back
/// whole, so the result printed is far larger than a pipe's buffer.
fn circle_wkt(n: usize) -> String {
    let points: Vec<String> = (0..=n)
        .map(|i| {
            let a = std::f64::consts::TAU * (i % n) as f64 / n as f64;
            format!("{} {}", 100.0 * a.cos(), 100.0 * a.sin())
        })
        .collect();
    format!("POLYGON(({}))", points.join(","))
}

#[test]
fn stdout_closed_early_ends_quietly_with_exit_0() {
    let dir = scratch("closed-pipe");
    let subject = write(&dir, "circle.wkt", &circle_wkt(5000));
    let clip = write(&dir, "square.wkt", "POLYGON((-200 -200,200 -200,200 200,-200 200,-200 -200))");
    let mut child = Command::new(env!("CARGO_BIN_EXE_clipbench"))
        .args(["clip", "--clipper", "geo", &subject, &clip])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the clipbench binary runs");
    // Like `| head -c 10`: read a little, then close the pipe while clipbench is still writing.
    let mut start = [0u8; 10];
    child.stdout.take().unwrap().read_exact(&mut start).unwrap();
    assert_eq!(&start, b"MULTIPOLYG");
    let o = child.wait_with_output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stderr(&o), "", "a reader that stops early is not an error");
}

#[cfg(target_os = "linux")]
#[test]
fn stdout_that_cannot_be_written_is_an_error_exit_not_a_panic() {
    let dir = scratch("full");
    let square = write(&dir, "square.wkt", "POLYGON((0 0,1 0,1 1,0 1,0 0))");
    let o = Command::new(env!("CARGO_BIN_EXE_clipbench"))
        .args(["clip", "--clipper", "geo", &square, &square])
        .stdout(std::fs::File::create("/dev/full").unwrap())
        .output()
        .expect("the clipbench binary runs");
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let err = stderr(&o);
    assert_eq!(err.trim_end(), "clipbench: cannot write to standard output: No space left on device (os error 28)");
}

#[test]
fn broken_or_missing_files_exit_2_with_a_one_line_message_naming_the_file() {
    let dir = scratch("broken");
    let good = write(&dir, "good.wkt", "POLYGON((0 0,1 0,1 1,0 0))");
    let cases = [
        (write(&dir, "cut.wkt", "POLYGON((0 0,1 0,1 1"), "is never closed"),
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

/// Runs `clip` on `subject` against a unit square and returns the output; the square is `clip.wkt` in `dir`.
fn clip_on(dir: &Path, subject: &str) -> Output {
    let square = write(dir, "clip.wkt", "POLYGON((0 0,1 0,1 1,0 1,0 0))");
    clipbench(&["clip", "--clipper", "geo", subject, &square])
}

/// Exit 2 and one line on standard error, which says `problem`.
fn assert_input_error(o: &Output, problem: &str) {
    assert_eq!(o.status.code(), Some(2), "{}{}", stdout(o), stderr(o));
    let err = stderr(o);
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains(problem), "expected '{problem}' in: {err}");
}

#[test]
fn clip_with_a_geojson_position_of_one_number_exits_2_naming_it() {
    let dir = scratch("geojson-position");
    let subject = write(
        &dir,
        "subject.geojson",
        r#"{"type":"FeatureCollection","features":[
            {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[2,0],[2,2],[0,0]]]}},
            {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1],[1,1],[0,0]]]}}]}"#,
    );
    let o = clip_on(&dir, &subject);
    assert_input_error(
        &o,
        "subject.geojson: feature 1, ring 0, position 1 is [1]: a position needs two numbers, x and y",
    );
}

#[test]
fn wkt_nested_thousands_deep_exits_2_instead_of_overflowing_the_stack() {
    let dir = scratch("wkt-deep");
    let nested = |n: usize| format!("{}POLYGON((0 0,1 0,1 1,0 0)){}", "GEOMETRYCOLLECTION(".repeat(n), ")".repeat(n));
    let deep = write(&dir, "deep.wkt", &nested(8000));
    assert_input_error(&clip_on(&dir, &deep), "deep.wkt: parentheses nested deeper than 256 levels (line 1, column");
    // At the limit (254 collections around a polygon's 2 levels) it still reads, stack and all.
    let at_limit = write(&dir, "at-limit.wkt", &nested(254));
    let o = clip_on(&dir, &at_limit);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!((wkt_area(&stdout(&o)) - 0.5).abs() < 1e-9, "{}", stdout(&o));
    assert_input_error(&clip_on(&dir, &write(&dir, "over.wkt", &nested(255))), "nested deeper than 256 levels");
}

#[test]
fn geojson_nested_thousands_deep_exits_2_at_serde_json_s_limit() {
    let dir = scratch("geojson-deep");
    let n = 10_000;
    let text = format!(
        "{}{{\"type\":\"Point\",\"coordinates\":[0,0]}}{}",
        r#"{"type":"GeometryCollection","geometries":["#.repeat(n),
        "]}".repeat(n)
    );
    let deep = write(&dir, "deep.geojson", &text);
    assert_input_error(&clip_on(&dir, &deep), "deep.geojson: not valid GeoJSON: nested deeper than 128 levels");
}

#[test]
fn wkt_nan_coordinate_exits_2_naming_the_number_and_where_it_is() {
    let dir = scratch("wkt-nan");
    let subject = write(&dir, "nan.wkt", "MULTIPOLYGON(((0 0,4 0,4 4,0 0)),\n((5 5,NaN 5,6 6,5 5)))");
    assert_input_error(&clip_on(&dir, &subject), "nan.wkt: coordinate 'NaN' (line 2, column 7) is not finite");
}

#[test]
fn wkt_text_after_the_geometry_exits_2_instead_of_being_ignored() {
    let dir = scratch("wkt-trailing");
    let subject = write(&dir, "two.wkt", "POLYGON((0 0,1 0,1 1,0 0))\nPOLYGON((5 5,6 5,6 6,5 5))\n");
    assert_input_error(
        &clip_on(&dir, &subject),
        "two.wkt: text after the end of the geometry (line 2, column 1): 'POLYGON'",
    );
}

#[test]
fn unclosed_ring_exits_2_naming_the_ring_instead_of_being_closed() {
    let dir = scratch("unclosed");
    let wkt = write(&dir, "open.wkt", "MULTIPOLYGON(((0 0,4 0,4 4,0 0)),((5 5,6 5,6 6)))");
    assert_input_error(
        &clip_on(&dir, &wkt),
        "open.wkt: polygon 1, ring 0 is not closed: it starts at 5 5 and ends at 6 6 (a WKT ring ends where it starts)",
    );
    let geojson = write(&dir, "open.geojson", r#"{"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4]]]}"#);
    assert_input_error(
        &clip_on(&dir, &geojson),
        "open.geojson: ring 0 is not closed: it starts at [0, 0] and ends at [4, 4]",
    );
}

#[test]
fn polygon_z_is_clipped_in_the_plane_with_a_note_on_stderr() {
    let dir = scratch("polygon-z");
    let wkt = write(&dir, "z.wkt", "POLYGON Z((0 0 5,2 0 5,2 2 7,0 2 7,0 0 5))");
    let geojson =
        write(&dir, "z.geojson", r#"{"type":"Polygon","coordinates":[[[0,0,5],[2,0,5],[2,2,7],[0,2,7],[0,0,5]]]}"#);
    let m = write(&dir, "m.wkt", "POLYGON M((0 0 5,2 0 5,2 2 7,0 2 7,0 0 5))");
    for (file, dropped) in
        [(&wkt, "z coordinates"), (&geojson, "positions' numbers after x and y (z)"), (&m, "m values")]
    {
        let o = clip_on(&dir, file);
        assert!(o.status.success(), "{file}: {}", stderr(&o));
        assert!((wkt_area(&stdout(&o)) - 1.0).abs() < 1e-9, "{file}: {}", stdout(&o));
        assert_eq!(stderr(&o), format!("clipbench: note: {file}: {dropped} dropped: clipping is in the plane\n"));
    }
}

#[test]
fn line_string_among_polygons_exits_2_naming_it_instead_of_being_dropped() {
    let dir = scratch("mixed");
    let geojson = write(
        &dir,
        "mixed.geojson",
        r#"{"type":"FeatureCollection","features":[
            {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[2,0],[2,2],[0,0]]]}},
            {"type":"Feature","properties":{},"geometry":{"type":"LineString","coordinates":[[0,0],[2,2]]}}]}"#,
    );
    let expected = "mixed.geojson: feature 1 is a LineString, but feature 0 is a Polygon: a file holds polygons or line \
                    strings, not both";
    assert_input_error(&clip_on(&dir, &geojson), expected);
    // As the clip operand too, where it was dropped the same way.
    let square = write(&dir, "square.wkt", "POLYGON((0 0,1 0,1 1,0 1,0 0))");
    assert_input_error(&clipbench(&["clip", "--clipper", "geo", &square, &geojson]), expected);
    let wkt = write(&dir, "mixed.wkt", "GEOMETRYCOLLECTION(POLYGON((0 0,2 0,2 2,0 0)),LINESTRING(0 0,2 2))");
    assert_input_error(&clip_on(&dir, &wkt), "mixed.wkt: member 1 is a LineString, but member 0 is a Polygon");
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

/// `--shrink-seconds 0`: each failure is written as generated, and its case file says shrinking
/// stopped at the time limit (a hang would otherwise cost the call time-out on every try).
#[test]
fn verify_writes_unshrunk_cases_when_the_shrinking_time_is_up() {
    let dir = scratch("verify-shrink-time");
    let out = dir.join("failures");
    let o = clipbench(&[
        "verify",
        "--clipper",
        "clipper2",
        "--workload",
        "grid",
        "--cases",
        "2",
        "--fill",
        "even-odd",
        "--max-records",
        "1",
        "--shrink-seconds",
        "0",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let mut checked = 0;
    for entry in std::fs::read_dir(&out).unwrap() {
        let case: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(entry.unwrap().path().join("case.json")).unwrap()).unwrap();
        assert_eq!(case["shrunk_vertices"], case["generated_vertices"], "{case}");
        assert!(
            case["shrunk"].as_str().unwrap().ends_with("(shrinking stopped at its time limit, --shrink-seconds)"),
            "{case}"
        );
        checked += 1;
    }
    assert!(checked > 0, "clipper2 fails grid's first cases: {}", stdout(&o));
    let refused = clipbench(&["verify", "--shrink-seconds=-1", "--cases", "1"]);
    assert_eq!(refused.status.code(), Some(2), "{}", stderr(&refused));
    assert!(stderr(&refused).contains("at least 0"), "{}", stderr(&refused));
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
        "curve",
        "curve-no-tests",
        "text-string",
        "text-char",
        "text-outline",
        "text-bitmap",
    ];
    // Every workload the testkit names, so a new one is verified here from the day it exists.
    let small: Vec<&str> = POLYGON_WORKLOADS
        .iter()
        .chain(LINE_WORKLOADS)
        .chain(CURVE_WORKLOADS)
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
fn clip_takes_circles_ellipses_and_arcs_as_text_and_geojson() {
    let dir = scratch("clip-curves");
    let window = write(&dir, "window.wkt", "POLYGON((0 0,10 0,10 10,0 10,0 0))");
    // A circle centred on the right edge: half of it, 2π, inside.
    let text = write(&dir, "shapes.curve", "# one circle\ncircle 10 5 2\n");
    let o = clipbench(&["clip", "--clipper", "curve", &text, &window, "--tolerance", "1e-6"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let area = wkt_area(&stdout(&o));
    assert!((area - 2.0 * std::f64::consts::PI).abs() < 1e-5, "{area}");
    let geojson = write(
        &dir,
        "shapes.geojson",
        r#"{"type":"Feature","geometry":{"type":"Point","coordinates":[10,5]},"properties":{"circle":{"radius":2}}}"#,
    );
    let o = clipbench(&["clip", "--clipper", "curve-no-tests", &geojson, &window, "--tolerance", "1e-6"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!((wkt_area(&stdout(&o)) - area).abs() < 1e-9);
    let svg = dir.join("out.svg");
    let o = clipbench(&["clip", "--clipper", "curve", &text, &window, "-o", svg.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read_to_string(&svg).unwrap().contains(" 0 0 "), "SVG arcs expected");
    // Bad curves and a non-curve clipper: exit 2 with a line naming the problem.
    let bad = write(&dir, "bad.curve", "circle 1 1 0\n");
    let o = clipbench(&["clip", "--clipper", "curve", &bad, &window]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("bad.curve") && stderr(&o).contains("positive"), "{}", stderr(&o));
    let o = clipbench(&["clip", "--clipper", "vatti", &text, &window]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("curve clippers"), "{}", stderr(&o));
}

#[test]
fn clip_takes_sectors_and_chord_regions() {
    let dir = scratch("clip-filled-arcs");
    let window = write(&dir, "window.wkt", "POLYGON((0 0,10 0,10 10,0 10,0 0))");
    // Centred on the corner (0, 0), radius 4: the sector over 0°..180° keeps its quarter in the
    // window (4π); the chord region over 0°..90° is all inside (4π - 8).
    let text = write(&dir, "arcs.curve", "sector 0 0 4 4 0 0 180\nchord 0 0 4 4 0 0 90\n");
    let o = clipbench(&["clip", "--clipper", "curve", &text, &window, "--tolerance", "1e-7"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let area = wkt_area(&stdout(&o));
    let exact = 4.0 * std::f64::consts::PI + (4.0 * std::f64::consts::PI - 8.0);
    assert!((area - exact).abs() < 1e-4, "{area} vs {exact}");
    let geojson = write(
        &dir,
        "arcs.geojson",
        r#"{"type":"Feature","geometry":{"type":"Point","coordinates":[0,0]},"properties":{"circle":{"radius":4},"arc":{"start":0,"sweep":90},"fill":"chord"}}"#,
    );
    let o = clipbench(&["clip", "--clipper", "curve-no-tests", &geojson, &window, "--tolerance", "1e-7"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!((wkt_area(&stdout(&o)) - (4.0 * std::f64::consts::PI - 8.0)).abs() < 1e-4);
    // An empty sweep is an error naming the line.
    let bad = write(&dir, "bad.curve", "sector 0 0 4 4 0 30 0\n");
    let o = clipbench(&["clip", "--clipper", "curve", &bad, &window]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("bad.curve") && stderr(&o).contains("line 1"), "{}", stderr(&o));
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
fn replay_of_a_case_file_that_does_not_hang_together_exits_2_instead_of_passing() {
    let dir = scratch("replay-checked");
    write(&dir, "subject.wkt", "MULTIPOLYGON(((0 0,2 0,2 2,0 2,0 0)))");
    write(&dir, "clip.wkt", "MULTIPOLYGON(((1 1,3 1,3 3,1 3,1 1)))");
    write(&dir, "segments.wkt", "MULTILINESTRING((0 0,3 3))");
    write(&dir, "triangle.wkt", "MULTIPOLYGON(((1 1,3 1,3 3,1 1)))");
    let case = serde_json::json!({
        "kind": "polygon", "clipper": "clipper2", "check": "disagreement", "other": "geo",
        "workload": "star", "seed": 1, "index": 0, "window": "any", "op": "union", "fill": "even-odd",
        "found": "", "shrunk": "", "generated_vertices": [4, 4], "shrunk_vertices": [4, 4],
        "inputs": ["subject.wkt", "clip.wkt"], "replay": ""
    });
    let line = serde_json::json!({"kind": "line", "clipper": "liu", "check": "oracle", "other": null, "op": null, "fill": null});
    let cases: [(serde_json::Value, &str); 13] = [
        (
            serde_json::json!({"kind": "triangle"}),
            "case.json: unknown kind 'triangle' (a case is a polygon, line, curve or text case)",
        ),
        (serde_json::json!({"kind": "line"}), "case.json: clipper2 is a polygon clipper, and this is a line case"),
        (line.clone(), "clip.wkt: the segments must be line strings, but it holds polygons"),
        (serde_json::json!({"clipper": "liu"}), "case.json: liu is a line clipper, and this is a polygon case"),
        (
            serde_json::json!({"other": null}),
            "case.json: a disagreement case needs 'other', the clipper it disagreed with, and it is missing",
        ),
        (
            serde_json::json!({"check": "oracle"}),
            "case.json: 'other' (geo) is for a disagreement, and the check here is oracle",
        ),
        (
            serde_json::json!({"check": "triangle"}),
            "case.json: unknown check 'triangle' (oracle, hung, area-identities or disagreement)",
        ),
        (
            serde_json::json!({"check": "hung"}),
            "case.json: 'other' (geo) is for a disagreement, and the check here is hung",
        ),
        (
            serde_json::json!({"op": null}),
            "case.json: a polygon disagreement case needs 'op', the operation, and it is missing",
        ),
        (serde_json::json!({"fill": null}), "case.json: a polygon case needs 'fill', the fill rule, and it is missing"),
        (
            serde_json::json!({"clipper": "rect-four-state", "other": "vatti"}),
            "case.json: rect-four-state does not do union under even-odd, so verify never ran it",
        ),
        (
            serde_json::json!({
                "clipper": "rect-four-state", "other": "vatti", "op": "intersection", "window": "rectangle",
                "inputs": ["subject.wkt", "triangle.wkt"]
            }),
            "triangle.wkt: rect-four-state takes rectangle windows only, and this is not one",
        ),
        (serde_json::json!({"window": "hexagon"}), "case.json: unknown window 'hexagon' (any, convex or rectangle)"),
    ];
    for (changes, problem) in cases {
        let mut changed = case.clone();
        for (k, v) in changes.as_object().unwrap() {
            changed[k] = v.clone();
        }
        let file = write(&dir, "case.json", &changed.to_string());
        let o = clipbench(&["verify", "--replay", &file]);
        assert_eq!(o.status.code(), Some(2), "{changes}: {}{}", stdout(&o), stderr(&o));
        assert!(stderr(&o).contains(problem), "{changes}: expected '{problem}' in {}", stderr(&o));
        assert_eq!(stdout(&o), "", "{changes}");
    }
    // A line case on line inputs does run.
    let mut changed = case.clone();
    for (k, v) in line.as_object().unwrap() {
        changed[k] = v.clone();
    }
    changed["inputs"] = serde_json::json!(["clip.wkt", "segments.wkt"]);
    let o = clipbench(&["verify", "--replay", &write(&dir, "line.json", &changed.to_string())]);
    assert!(
        o.status.success() && stdout(&o).starts_with("passes now: line liu oracle"),
        "{}{}",
        stdout(&o),
        stderr(&o)
    );
    // A missing field is serde's error, naming the field.
    let mut missing = case.clone();
    missing.as_object_mut().unwrap().remove("kind");
    let o = clipbench(&["verify", "--replay", &write(&dir, "missing.json", &missing.to_string())]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("not a verify case file: missing field `kind`"), "{}", stderr(&o));
}

#[test]
fn conformance_suites_run_and_print_a_closing_line_per_clipper() {
    let dir = scratch("conformance");
    let json = dir.join("conformance.json");
    let o = clipbench(&[
        "conformance",
        "clipper2-polygons",
        "--clipper",
        "vatti",
        "--clipper",
        "clipper2",
        "--json",
        json.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    for line in ["vatti: 195 passed, 0 failed", "clipper2: 195 passed, 0 failed"] {
        assert!(stdout(&o).lines().any(|l| l == line), "{line}\n{}", stdout(&o));
    }
    // --json holds the same counts as the closing lines, clipper by clipper.
    let written: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(written["suite"], "clipper2-polygons");
    let clippers = written["clippers"].as_array().unwrap();
    let names: Vec<&str> = clippers.iter().map(|c| c["clipper"].as_str().unwrap()).collect();
    assert_eq!(names, ["vatti", "clipper2"]);
    for c in clippers {
        let line = format!("{}: {} passed, {} failed", c["clipper"].as_str().unwrap(), c["passed"], c["failed"]);
        assert!(stdout(&o).lines().any(|l| l == line), "{line}\n{}", stdout(&o));
        assert_eq!(c["skipped"], 0);
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

/// `--call-timeout 1e20` panicked converting float seconds to a Duration (exit 101) in clip,
/// verify and conformance (issue 28): it is a usage error naming the bound.
#[test]
fn call_timeout_beyond_a_day_is_a_usage_error_not_a_panic() {
    let dir = scratch("call-timeout");
    let square = write(&dir, "square.wkt", "POLYGON((0 0,1 0,1 1,0 1,0 0))");
    let external = ["--external", "gone=./no-such-clipper", "--call-timeout", "1e20"];
    let commands: [Vec<&str>; 3] = [
        [&["clip", "--clipper", "gone", &square, &square][..], &external[..]].concat(),
        [&["verify", "--workload", "star", "--cases", "1"][..], &external[..]].concat(),
        [&["conformance", "clipper2-lines"][..], &external[..]].concat(),
    ];
    for args in commands {
        let o = clipbench(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("--call-timeout") && stderr(&o).contains("at most 86400"), "{}", stderr(&o));
    }
}

/// `verify --threads 10000` on 2 cases ran for over a minute (issue 28): the option has a bound.
/// One past it is refused (the old code ran it, and a count as large as the issue's never ended).
#[test]
fn verify_threads_beyond_the_bound_exits_2_naming_it() {
    let o = clipbench(&["verify", "--clipper", "geo", "--workload", "star", "--cases", "2", "--threads", "1025"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("--threads") && stderr(&o).contains("1..=1024"), "{}", stderr(&o));
}

/// `verify --cases 0` said "no selected clipper handles the selected workloads" (issue 28): it
/// names the option and the range it takes.
#[test]
fn verify_cases_zero_exits_2_naming_the_option() {
    let o = clipbench(&["verify", "--clipper", "geo", "--workload", "star", "--cases", "0"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("--cases") && stderr(&o).contains("0 is not in 1.."), "{}", stderr(&o));
}

/// A Polygons.txt record cut after its header was graded as passed, its stored area taken as 0
/// (issue 28): it is that record's failure, naming what is missing.
#[test]
fn conformance_fails_a_record_cut_after_its_header_naming_what_is_missing() {
    let dir = scratch("conformance-cut");
    std::fs::create_dir_all(dir.join("clipper2")).unwrap();
    write(&dir.join("clipper2"), "Polygons.txt", "CAPTION: 1.\nCLIPTYPE: UNION\nFILLRULE: EVENODD\n");
    let o = clipbench(&["conformance", "clipper2-polygons", "--clipper", "vatti", "--testdata", dir.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
    assert!(stdout(&o).contains("Polygons.txt:1: no SOL_AREA"), "{}", stdout(&o));
    assert!(stdout(&o).contains("vatti: 0 passed, 1 failed"), "{}", stdout(&o));
}

/// A ring of 2 distinct points or an empty ring made `clip` refuse the file (issue 28). Like
/// GEOS and Boost.Geometry, it reads the file, drops such rings (they add nothing to any winding
/// number) and says where each was on standard error.
#[test]
fn rings_that_enclose_nothing_are_dropped_with_a_note_saying_where() {
    let dir = scratch("degenerate-rings");
    let square = write(&dir, "square.wkt", "POLYGON((0 0,4 0,4 4,0 4,0 0))");
    let wkt = write(&dir, "rings.wkt", "MULTIPOLYGON(((0 0,2 0,2 2,0 2,0 0),(1 1,3 3,1 1),()),((5 5,5 5,5 5)))");
    let o = clipbench(&["clip", "--clipper", "vatti", "--op", "union", &wkt, &square]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!((wkt_area(&stdout(&o)) - 16.0).abs() < 1e-9, "{}", stdout(&o));
    let err = stderr(&o);
    let notes: Vec<&str> = err.lines().collect();
    let expected = [
        "polygon 0, ring 1 has 2 distinct points and encloses nothing: dropped",
        "polygon 0, ring 2 is empty and encloses nothing: dropped",
        "polygon 1, ring 0 has 1 distinct point and encloses nothing: dropped",
    ];
    assert_eq!(notes.len(), expected.len(), "{}", stderr(&o));
    for (note, says) in notes.iter().zip(expected) {
        assert!(note.starts_with(&format!("clipbench: note: {wkt}: {says}")), "{note}");
    }
    let geojson = write(
        &dir,
        "rings.geojson",
        r#"{"type":"Polygon","coordinates":[[[0,0],[2,0],[2,2],[0,2],[0,0]],[],[[1,1],[1,2],[1,1]]]}"#,
    );
    let o = clipbench(&["clip", "--clipper", "geo", "--op", "intersection", &geojson, &square]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!((wkt_area(&stdout(&o)) - 4.0).abs() < 1e-9, "{}", stdout(&o));
    assert!(
        stderr(&o).contains("ring 1 is empty") && stderr(&o).contains("ring 2 has 2 distinct points"),
        "{}",
        stderr(&o)
    );
    // As the clip operand and as a line window too.
    let lines = write(&dir, "lines.wkt", "LINESTRING(-1 1,5 1)");
    let o = clipbench(&["clip", "--clipper", "liu", &lines, &wkt]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).starts_with("MULTILINESTRING ((0 1, 2 1))"), "{}", stdout(&o));
}

/// A WKT file that starts with a UTF-8 byte order mark failed with "Encountered non-ascii word"
/// (issue 28): the mark is no part of the text and is skipped; other non-ASCII is named with its
/// place.
#[test]
fn wkt_with_a_byte_order_mark_reads_and_other_non_ascii_is_named_with_its_place() {
    let dir = scratch("wkt-bom");
    let bom = write(&dir, "bom.wkt", "\u{feff}POLYGON((0 0,2 0,2 2,0 2,0 0))");
    let o = clip_on(&dir, &bom);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!((wkt_area(&stdout(&o)) - 1.0).abs() < 1e-9, "{}", stdout(&o));
    let accent = write(&dir, "accent.wkt", "POLYGON((0 0,2 0,\n2 2,0 2é,0 0))");
    assert_input_error(&clip_on(&dir, &accent), "accent.wkt: 'é' (line 2, column 8) is not ASCII");
}

/// 5 numbers in one WKT position said "Missing closing parenthesis for type", a missing `)` gave
/// no place, and an empty file "Invalid WKT format" (issue 28).
#[test]
fn wkt_positions_parentheses_and_empty_files_are_named_with_their_place() {
    let dir = scratch("wkt-messages");
    let five = write(&dir, "five.wkt", "POLYGON((0 0,1 0 1 2 3,1 1,0 0))");
    assert_input_error(
        &clip_on(&dir, &five),
        "five.wkt: the position at line 1, column 14 has 5 numbers: a WKT position has 2 to 4",
    );
    let open = write(&dir, "open.wkt", "MULTIPOLYGON(((0 0,1 0,1 1,0 0))");
    assert_input_error(&clip_on(&dir, &open), "open.wkt: the '(' at line 1, column 13 is never closed");
    let empty = write(&dir, "empty.wkt", "\n  \n");
    assert_input_error(&clip_on(&dir, &empty), "empty.wkt: it is empty: a WKT file holds one geometry");
    let word = write(&dir, "word.wkt", "POLYGOM((0 0,1 0,1 1,0 0))");
    assert_input_error(&clip_on(&dir, &word), "word.wkt: 'POLYGOM' (line 1, column 1) is not a WKT geometry type");
}

/// `MULTILINESTRING EMPTY` with `--clipper liu` said "unknown clipper 'liu'", and polygons with
/// `--clipper curve` "unknown clipper 'curve'" (issue 28): each clipper is named for what it is.
#[test]
fn a_clipper_of_another_kind_is_named_for_what_it_is() {
    let dir = scratch("clipper-kinds");
    let square = write(&dir, "square.wkt", "POLYGON((0 0,1 0,1 1,0 1,0 0))");
    let none = write(&dir, "none.wkt", "MULTILINESTRING EMPTY");
    let o = clipbench(&["clip", "--clipper", "liu", &none, &square]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stdout(&o).trim(), "MULTILINESTRING EMPTY");
    let o = clipbench(&["clip", "--clipper", "curve", &square, &square]);
    assert_input_error(&o, "'curve' is a curve clipper");
    assert!(stderr(&o).contains("the subject holds polygons (polygon clippers: vatti"), "{}", stderr(&o));
    let o = clipbench(&["clip", "--clipper", "vatti", &none, &square]);
    assert_input_error(
        &o,
        "'vatti' is a polygon clipper, and the subject holds line strings (line clippers: cyrus-beck",
    );
}

/// A curve file with an unknown keyword, nothing in it or only comments said "Invalid WKT
/// format", and a curve feature with both `circle` and `ellipse` used one of them (issue 28).
#[test]
fn curve_files_that_hold_no_curve_or_two_at_once_exit_2_naming_the_problem() {
    let dir = scratch("curve-messages");
    let window = write(&dir, "window.wkt", "POLYGON((0 0,10 0,10 10,0 10,0 0))");
    let cases = [
        ("typo.curve", "# shapes\ncircel 1 1 1\n", "typo.curve: line 2: unknown keyword 'circel'"),
        ("empty.curve", "", "empty.curve: it holds no curve"),
        ("comments.curve", "# nothing yet\n\n# still nothing\n", "comments.curve: it holds no curve"),
    ];
    for (name, text, says) in cases {
        let file = write(&dir, name, text);
        assert_input_error(&clipbench(&["clip", "--clipper", "curve", &file, &window]), says);
    }
    let both = write(
        &dir,
        "both.geojson",
        r#"{"type":"Feature","geometry":{"type":"Point","coordinates":[5,5]},"properties":{"circle":{"radius":2},"ellipse":{"rx":3,"ry":1}}}"#,
    );
    assert_input_error(
        &clipbench(&["clip", "--clipper", "curve", &both, &window]),
        "both.geojson: feature 0: it has both 'circle' and 'ellipse'",
    );
}

/// `text --window "POLYGON EMPTY"` said "cannot read it: No such file or directory" (issue 28).
#[test]
fn text_window_given_as_empty_wkt_is_named_as_empty() {
    let dir = scratch("text-window");
    let out = dir.join("out.svg");
    let o = clipbench(&[
        "text",
        "a",
        "--size",
        "20",
        "--window",
        "POLYGON EMPTY",
        "--strategy",
        "bitmap",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_input_error(&o, "--window 'POLYGON EMPTY': the window is empty");
    let o = clipbench(&[
        "text",
        "a",
        "--size",
        "20",
        "--window",
        "no-such.wkt",
        "--strategy",
        "bitmap",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_input_error(&o, "--window 'no-such.wkt': no such file, and not WKT");
}

/// A replay case file with a byte order mark, or with three inputs, got serde's words (issue 28).
#[test]
fn replay_case_file_with_a_byte_order_mark_reads_and_three_inputs_are_named() {
    let dir = scratch("replay-messages");
    write(&dir, "subject.wkt", "MULTIPOLYGON(((0 0,2 0,2 2,0 2,0 0)))");
    write(&dir, "clip.wkt", "MULTIPOLYGON(((1 1,3 1,3 3,1 3,1 1)))");
    let mut case = serde_json::json!({
        "kind": "polygon", "clipper": "clipper2", "check": "disagreement", "other": "geo",
        "workload": "star", "seed": 1, "index": 0, "window": "any", "op": "union", "fill": "even-odd",
        "found": "", "shrunk": "", "generated_vertices": [4, 4], "shrunk_vertices": [4, 4],
        "inputs": ["subject.wkt", "clip.wkt"], "replay": ""
    });
    let file = write(&dir, "bom.json", &format!("\u{feff}{case}"));
    let o = clipbench(&["verify", "--replay", &file]);
    assert!(o.status.success() && stdout(&o).starts_with("passes now"), "{}{}", stdout(&o), stderr(&o));
    case["inputs"] = serde_json::json!(["subject.wkt", "clip.wkt", "clip.wkt"]);
    let file = write(&dir, "three.json", &case.to_string());
    assert_input_error(
        &clipbench(&["verify", "--replay", &file]),
        "three.json: 'inputs' lists 3 file(s); a case has two",
    );
}

/// Every feature of a GeoJSON FeatureCollection lost its properties: `clip` returned one bare
/// MultiPolygon, and a feature with a null geometry gave `MULTIPOLYGON EMPTY` without a word
/// (issue 28). Each feature is clipped on its own and written back with its id and properties.
#[test]
fn clip_of_a_feature_collection_keeps_each_feature_with_its_id_and_properties() {
    let dir = scratch("features");
    let square = write(&dir, "square.wkt", "POLYGON((0 0,4 0,4 4,0 4,0 0))");
    // Two overlapping squares (clipped as one region under even-odd, their overlap would be a
    // hole) and a feature with no geometry.
    let features = write(
        &dir,
        "parcels.geojson",
        r#"{"type":"FeatureCollection","features":[
            {"type":"Feature","id":"a","properties":{"name":"west","n":1},"geometry":{"type":"Polygon","coordinates":[[[-2,1],[2,1],[2,3],[-2,3],[-2,1]]]}},
            {"type":"Feature","id":7,"properties":{"name":"east"},"geometry":{"type":"Polygon","coordinates":[[[1,1],[6,1],[6,3],[1,3],[1,1]]]}},
            {"type":"Feature","properties":{"name":"unsurveyed"},"geometry":null}]}"#,
    );
    let o = clipbench(&["clip", "--clipper", "vatti", &features, &square]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out: serde_json::Value = serde_json::from_str(&stdout(&o)).expect("GeoJSON out");
    assert_eq!(out["type"], "FeatureCollection");
    let got = out["features"].as_array().unwrap();
    assert_eq!(got.len(), 3);
    assert_eq!(
        (&got[0]["id"], &got[0]["properties"]["name"], &got[0]["properties"]["n"]),
        (&"a".into(), &"west".into(), &1.into())
    );
    assert_eq!((&got[1]["id"], &got[1]["properties"]["name"]), (&7.into(), &"east".into()));
    assert_eq!((&got[2]["properties"]["name"], &got[2]["geometry"]), (&"unsurveyed".into(), &serde_json::Value::Null));
    let area = |f: &serde_json::Value| {
        let g: geojson::Geometry = serde_json::from_value(f["geometry"].clone()).unwrap();
        let g: geo::Geometry<f64> = g.try_into().unwrap();
        use geo::Area;
        g.unsigned_area()
    };
    assert!((area(&got[0]) - 4.0).abs() < 1e-9 && (area(&got[1]) - 6.0).abs() < 1e-9, "{}", stdout(&o));
    assert_eq!(
        stderr(&o).trim_end(),
        format!(
            "clipbench: note: {features}: feature 2 has no geometry (null): it is written back as it is, with a null geometry"
        )
    );
    // Into a .geojson file the same; into WKT, the geometries in feature order, with a note.
    let wkt = dir.join("out.wkt");
    let o = clipbench(&["clip", "--clipper", "vatti", &features, &square, "-o", wkt.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&wkt).unwrap();
    assert!(
        text.starts_with("GEOMETRYCOLLECTION (MULTIPOLYGON") && text.trim_end().ends_with("GEOMETRYCOLLECTION EMPTY)"),
        "{text}"
    );
    assert!(stderr(&o).contains("ids and properties are not written to WKT"), "{}", stderr(&o));
}

/// `verify --partition K/N` runs part K of N of the cases; `merge` joins the parts' results
/// folders into the one a whole run writes: the same rows, runs and failure cases (issue 28).
#[test]
fn verify_in_three_parts_merged_equals_one_whole_run() {
    let dir = scratch("partition");
    // Peers that fail now and then on these workloads, so there are failures to shrink and write,
    // and --max-records 1 so that choosing which to write matters.
    let run = |results: &Path, part: Option<&str>| {
        let mut args = vec![
            "verify",
            "--clipper",
            "i_overlay",
            "--clipper",
            "clipper2-rust",
            "--clipper",
            "geo",
            "--workload",
            "grid",
            "--workload",
            "spiky-box",
            "--workload",
            "lines-degenerate",
            "--cases",
            "7",
            "--fill",
            "even-odd",
            "--segments",
            "20",
            "--max-records",
            "1",
            "--results",
            results.to_str().unwrap(),
        ];
        if let Some(p) = part {
            args.extend(["--partition", p]);
        }
        let o = clipbench(&args);
        assert!(o.status.success(), "{part:?}: {}{}", stdout(&o), stderr(&o));
    };
    let whole = dir.join("whole");
    run(&whole, None);
    let parts: Vec<PathBuf> = (1..=3).map(|k| dir.join(format!("part-{k}"))).collect();
    for (k, part) in parts.iter().enumerate() {
        run(part, Some(&format!("{}/3", k + 1)));
    }
    let merged = dir.join("merged");
    let mut args = vec!["merge".to_owned()];
    args.extend(parts.iter().rev().map(|p| p.to_str().unwrap().to_owned()));
    args.extend(["--out".to_owned(), merged.to_str().unwrap().to_owned()]);
    let o = clipbench(&args.iter().map(String::as_str).collect::<Vec<_>>());
    assert!(o.status.success(), "{}{}", stdout(&o), stderr(&o));
    let read = |d: &Path| -> serde_json::Value {
        let text = std::fs::read_to_string(d.join("verify.json")).unwrap();
        serde_json::from_str(
            &text.replace(whole.to_str().unwrap(), "RESULTS").replace(merged.to_str().unwrap(), "RESULTS"),
        )
        .unwrap()
    };
    let (one, joined) = (read(&whole), read(&merged));
    assert_eq!(one["rows"], joined["rows"], "rows and runs");
    assert!(one["rows"].as_array().unwrap().iter().map(|r| r["runs"].as_u64().unwrap()).sum::<u64>() > 0);
    assert_eq!(one["cases"], joined["cases"], "failure cases");
    assert!(!one["cases"].as_array().unwrap().is_empty(), "some failure to compare: {one}");
    assert_eq!(one, joined);
    // Every failure folder's files are the same, the replay commands pointing at each folder.
    for case in one["cases"].as_array().unwrap() {
        let folder = case["folder"].as_str().unwrap();
        assert!(folder.contains("-s1-"), "the seed is in the name: {folder}");
        let files = |d: &Path| -> Vec<(String, String)> {
            let at = d.join("verify-failures").join(folder);
            let mut files: Vec<(String, String)> = std::fs::read_dir(&at)
                .unwrap()
                .map(|f| {
                    let f = f.unwrap();
                    let text = std::fs::read_to_string(f.path()).unwrap().replace(d.to_str().unwrap(), "RESULTS");
                    (f.file_name().to_string_lossy().into_owned(), text)
                })
                .collect();
            files.sort();
            files
        };
        assert_eq!(files(&whole), files(&merged), "{folder}");
    }
    // report reads the merged folder.
    let o = clipbench(&["report", "--out", merged.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        std::fs::read_to_string(merged.join("REPORT.md"))
            .unwrap()
            .contains("Where the clippers disagree with the oracle")
    );
    // A part missing or given twice, and a whole run as a part, are usage errors.
    let o = clipbench(&[
        "merge",
        parts[0].to_str().unwrap(),
        parts[1].to_str().unwrap(),
        "--out",
        merged.to_str().unwrap(),
    ]);
    assert_input_error(&o, "part 3/3 is missing");
    let o =
        clipbench(&["merge", parts[0].to_str().unwrap(), whole.to_str().unwrap(), "--out", merged.to_str().unwrap()]);
    assert_input_error(&o, "is a whole run, not a part");
}

/// `conformance --partition K/N` splits the suite the same way: the parts' counts add up.
#[test]
fn conformance_parts_add_up_to_the_whole_suite() {
    let mut passed = 0;
    for k in 1..=3 {
        let part = format!("{k}/3");
        let o = clipbench(&["conformance", "clipper2-lines", "--clipper", "liu", "--partition", &part]);
        assert!(o.status.success(), "{}", stderr(&o));
        let line = stdout(&o).lines().find(|l| l.starts_with("liu: ")).unwrap().to_owned();
        let n: usize = line["liu: ".len()..].split(' ').next().unwrap().parse().unwrap();
        assert!(line.contains("passed, 0 failed") && n > 0, "{line}");
        passed += n;
    }
    assert_eq!(passed, 15);
}

/// `bench --help` says why bench has no --partition.
#[test]
fn bench_help_says_why_it_is_not_partitioned() {
    let o = clipbench(&["bench", "--help"]);
    assert!(
        stdout(&o).contains("bench has no --partition") && stdout(&o).contains("cannot be compared"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn hostile_sorts_every_call_of_each_clipper_into_one_outcome() {
    let dir = scratch("hostile");
    let json = dir.join("hostile.json");
    let o = clipbench(&["hostile", "--clipper", "vatti", "--clipper", "clipper1", "--json", json.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let file: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let cases = clip_testkit::workload::hard_cases().len() as u64;
    for t in file["tallies"].as_array().unwrap() {
        let count = |k: &str| t[k].as_u64().unwrap();
        // vatti: all four operations under all four rules; Clipper 1 (geo-clipper): non-zero only.
        let fills = if t["clipper"] == "vatti" { 4 } else { 1 };
        assert_eq!(count("runs"), cases * 4 * fills, "{t}");
        assert_eq!(
            count("runs"),
            ["right", "wrong", "refused", "crashed", "hung"].iter().map(|k| count(k)).sum::<u64>(),
            "{t}"
        );
    }
    let vatti = &file["tallies"][0];
    assert_eq!(
        (vatti["clipper"].as_str(), vatti["right"].as_u64()),
        (Some("vatti"), vatti["runs"].as_u64()),
        "{}",
        stdout(&o)
    );
}

#[test]
fn referee_sets_a_clippers_areas_against_the_oracle_within_rounding() {
    let dir = scratch("referee");
    // vatti as the referee of star's first three cases, with `extra` options; the JSON it wrote.
    let referee = |file: &str, extra: &[&str]| {
        let json = dir.join(file);
        let mut args = vec!["referee", "--referee", "vatti", "--workload", "star", "--cases", "3"];
        args.extend_from_slice(extra);
        args.extend(["--json", json.to_str().unwrap()]);
        let o = clipbench(&args);
        assert!(o.status.success(), "{}\n{}", stdout(&o), stderr(&o));
        serde_json::from_str::<serde_json::Value>(&std::fs::read_to_string(&json).unwrap()).unwrap()
    };
    let file = referee("referee.json", &[]);
    let star = &file["workloads"][0];
    assert_eq!((star["cases"].as_u64(), star["compared"].as_u64()), (Some(3), Some(48)), "{star}");
    assert!(star["largest_of_bound"].as_f64().unwrap() <= 1.0, "{star}");
    // Part 2 of 2 runs case 1 of star's three (positions 0, 1, 2: the odd ones).
    let file = referee("referee.part-2.json", &["--partition", "2/2"]);
    assert_eq!(file["partition"], serde_json::json!({"k": 2, "n": 2}), "{file}");
    assert_eq!(file["workloads"][0]["cases"].as_u64(), Some(1), "{file}");
    let unknown = clipbench(&["referee", "--referee", "no-such", "--cases", "1"]);
    assert_eq!(unknown.status.code(), Some(2));
    assert!(stderr(&unknown).contains("no-such"), "{}", stderr(&unknown));
}
