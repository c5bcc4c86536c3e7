//! Writes the seed inputs of every target into `fuzz/corpus/<target>/seed-*`: real cases from
//! `testdata/` (Clipper2's `Polygons.txt` and `Lines.txt`, geo's fixtures), each also moved to
//! 1e9 and with a clip vertex snapped onto a subject vertex (near-degenerate mutations), the
//! `lines-degenerate` workload, and one small file of each format for the readers.
//! `cargo run -p clip-fuzz-checks --example seed`

use std::fs;
use std::path::Path;

use clip_core::{FillRule, Point, Polygons, Ring, Segment, WindowKind};
use clip_fuzz_checks::shape::{MAX_RINGS, MAX_STEPS};
use clip_fuzz_checks::{encode, fuzz_dir};
use clip_testkit::clipper2_suite::parse_clipper2;
use clip_testkit::testdata_dir;
use clip_testkit::workload::line_case;

fn small(p: &Polygons) -> bool {
    p.rings.len() <= MAX_RINGS && p.rings.iter().all(|r| r.len() <= MAX_STEPS)
}

fn moved(p: &Polygons, by: f64) -> Polygons {
    Polygons::new(
        p.rings.iter().map(|r| Ring::new(r.points.iter().map(|q| Point::new(q.x + by, q.y + by)).collect())).collect(),
    )
}

/// `clip` with its first vertex moved onto `subject`'s first vertex.
fn snapped(subject: &Polygons, clip: &Polygons) -> Polygons {
    let mut c = clip.clone();
    if let (Some(s), Some(q)) =
        (subject.rings.first().and_then(|r| r.points.first()), c.rings.first_mut().and_then(|r| r.points.first_mut()))
    {
        *q = *s;
    }
    c
}

fn write(target: &str, name: &str, bytes: &[u8]) {
    let dir = fuzz_dir().join("corpus").join(target);
    fs::create_dir_all(&dir).expect("corpus folder");
    fs::write(dir.join(format!("seed-{name}")), bytes).expect("seed file");
}

fn polygon_seeds(name: &str, subject: &Polygons, clip: &Polygons, fill: FillRule) {
    if !small(subject) || !small(clip) {
        return;
    }
    let variants = [
        ("", subject.clone(), clip.clone()),
        ("-far", moved(subject, 1e9), moved(clip, 1e9)),
        ("-snapped", subject.clone(), snapped(subject, clip)),
    ];
    for (suffix, s, c) in variants {
        write("vatti", &format!("{name}{suffix}"), &encode::vatti(&s, &c, fill));
        write("window_clippers", &format!("{name}{suffix}"), &encode::window_clippers(&s, &c, fill));
    }
}

fn main() {
    let testdata = testdata_dir();
    let text = fs::read_to_string(testdata.join("clipper2/Polygons.txt")).expect("Polygons.txt");
    for case in parse_clipper2(&text).into_iter().flatten().take(60) {
        let (s, c) = (Polygons::new(case.subjects.clone()), Polygons::new(case.clips.clone()));
        polygon_seeds(&format!("clipper2-{}", case.number), &s, &c, case.fill);
    }
    let geo = testdata.join("geo/booleanop-geojson/generic_test_cases");
    let mut files: Vec<_> = fs::read_dir(&geo).expect("geo fixtures").map(|e| e.unwrap().path()).collect();
    files.sort();
    for file in &files {
        let text = fs::read_to_string(file).expect("fixture");
        let Ok(cases) = clipbench::conformance::geo_booleanop::fixture_cases(&text, file) else { continue };
        if let Some((_, clipbench::conformance::suite_case::CaseInput::Polygon { subject, clip, .. })) = cases.first() {
            let stem = file.file_stem().unwrap().to_string_lossy();
            polygon_seeds(&format!("geo-{stem}"), subject, clip, FillRule::NonZero);
        }
        if text.len() < 2000 {
            let mut bytes = vec![3u8];
            bytes.extend(text.as_bytes());
            write("readers", &format!("geo-{}", file.file_stem().unwrap().to_string_lossy()), &bytes);
        }
    }
    let lines = fs::read_to_string(testdata.join("clipper2/Lines.txt")).expect("Lines.txt");
    for case in parse_clipper2(&lines).into_iter().flatten().take(20) {
        let window = Polygons::new(case.clips.clone());
        let segments: Vec<Segment> =
            case.open_subjects.iter().flat_map(|p| p.windows(2).map(|w| Segment::new(w[0], w[1]))).take(48).collect();
        if small(&window) {
            write(
                "line_clippers",
                &format!("clipper2-lines-{}", case.number),
                &encode::line_clippers(&window, &segments),
            );
        }
    }
    for i in 0..12 {
        let case = line_case("lines-degenerate", 15, i, WindowKind::Any, 48).expect("a line workload");
        if small(&case.window) {
            let segments: Vec<Segment> = case.segments.iter().copied().take(48).collect();
            write("line_clippers", &format!("lines-degenerate-{i}"), &encode::line_clippers(&case.window, &segments));
        }
    }
    readers_seeds(&text, &lines);
    println!("seeds written under {}", Path::new(&fuzz_dir()).join("corpus").display());
}

fn readers_seeds(polygons_txt: &str, lines_txt: &str) {
    let first_records = |text: &str, n: usize| text.split("CAPTION:").take(n + 1).collect::<Vec<_>>().join("CAPTION:");
    let case_file = r#"{"kind":"polygon","clipper":"vatti","check":"oracle","other":null,"workload":"grid","seed":1,"index":3,"window":"any","op":"intersection","fill":"non-zero","found":"x","shrunk":"y","generated_vertices":[3,6],"shrunk_vertices":[3,6],"inputs":["subject.wkt","clip.wkt"],"replay":"clipbench verify --replay case.json"}"#;
    let seeds: [(&str, u8, String); 9] = [
        ("wkt-polygon", 0, "POLYGON((0 0,4 0,4 4,0 4,0 0),(1 1,1 2,2 2,2 1,1 1))".into()),
        ("wkt-collection", 0, "GEOMETRYCOLLECTION(MULTIPOLYGON(((0 0,1 0,1 1,0 0))),LINESTRING(0 0,2 2))".into()),
        ("wkt-lines", 0, "MULTILINESTRING((0 0,1 1,2 0),(5 5,6 6))".into()),
        (
            "geojson-features",
            1,
            r#"{"type":"FeatureCollection","features":[{"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}}]}"#.into(),
        ),
        ("geojson-geometry", 1, r#"{"type":"MultiLineString","coordinates":[[[0,0],[2,2,1]],[[3,3],[4,4]]]}"#.into()),
        ("clipper2-polygons", 2, first_records(polygons_txt, 3)),
        ("clipper2-lines", 2, first_records(lines_txt, 2)),
        ("tcases", 4, r#"[{"p1":"POLYGON((0 0,2 0,2 2,0 2,0 0))","p2":"POLYGON((1 1,3 1,3 3,1 3,1 1))","op":"intersection","expected":"POLYGON((1 1,2 1,2 2,1 2,1 1))"}]"#.into()),
        ("case-file", 5, case_file.into()),
    ];
    for (name, format, text) in seeds {
        let mut bytes = vec![format];
        bytes.extend(text.as_bytes());
        write("readers", name, &bytes);
    }
}
