//! Clipper2's `Lines.txt` (`testdata/clipper2/`): every segment of every open subject
//! path clipped by every line clipper here and by geo, checked against the exact line oracle.
//!
//! Clipper2's own expected values are not used: they grade Clipper2's open-path output, which
//! keeps or drops a segment on the window boundary by the window's orientation (docs/DESIGN.md, Peers), while
//! the closed-set rule always keeps it. The `DIFFERENCE` cases are clipped as intersections (the
//! line clippers compute the part inside the window). Windows are read under even-odd.

use clip_core::{LineClipper, Point, Polygons, Ring, Segment};
use clip_cyrus_beck::{CyrusBeck, Liu};
use clip_oracle::line::{LINE_T_TOLERANCE, check_line_batch};
use clip_peers::GeoLineClipper;
use clip_virtual_box::VirtualBox;

/// geo snaps coordinates to a grid of about extent x 1e-9 (docs/DESIGN.md, Peers); its pieces are checked
/// with this looser parameter tolerance.
const GEO_T_TOLERANCE: f64 = 1e-6;

/// One record: the open subject paths and the clip rings.
struct Case {
    caption: String,
    open: Vec<Vec<Point>>,
    clips: Vec<Vec<Point>>,
}

fn numbers(line: &str) -> Vec<f64> {
    line.split([',', ' ']).filter(|t| !t.is_empty()).filter_map(|t| t.parse().ok()).collect()
}

fn parse(text: &str) -> Vec<Case> {
    let mut cases: Vec<Case> = Vec::new();
    let mut block = "";
    for line in text.lines() {
        if let Some(caption) = line.strip_prefix("CAPTION:") {
            cases.push(Case { caption: caption.trim().to_owned(), open: Vec::new(), clips: Vec::new() });
            block = "";
        } else if line.starts_with("SUBJECTS_OPEN") {
            block = "open";
        } else if line.starts_with("SUBJECTS") {
            block = "closed";
        } else if line.starts_with("CLIPS") {
            block = "clips";
        } else {
            let n = numbers(line);
            if n.is_empty() {
                block = "";
                continue;
            }
            let path: Vec<Point> = n.chunks_exact(2).map(|c| Point::new(c[0], c[1])).collect();
            let case = cases.last_mut().expect("a record starts with CAPTION");
            match block {
                "open" => case.open.push(path),
                "clips" => case.clips.push(path),
                _ => {}
            }
        }
    }
    cases
}

#[test]
fn lines_txt_agrees_with_the_oracle() {
    let path = clip_testkit::testdata_dir().join("clipper2/Lines.txt");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
    let cases = parse(&text);
    assert_eq!(cases.len(), 16, "Lines.txt has 16 records");
    let geo = GeoLineClipper::new();
    let mut checked = 0;
    for case in &cases {
        let window = Polygons::new(case.clips.iter().map(|r| Ring::new(r.clone())).collect());
        let segments: Vec<Segment> =
            case.open.iter().flat_map(|p| p.windows(2).map(|w| Segment::new(w[0], w[1]))).collect();
        let mut clippers: Vec<(&dyn LineClipper, f64)> = vec![
            (&VirtualBox::NEW2, LINE_T_TOLERANCE),
            (&VirtualBox::NEW1, LINE_T_TOLERANCE),
            (&Liu, LINE_T_TOLERANCE),
            (&geo, GEO_T_TOLERANCE),
        ];
        if CyrusBeck.prepare(&window).is_ok() {
            clippers.push((&CyrusBeck, LINE_T_TOLERANCE));
        }
        for (clipper, tolerance) in clippers {
            let mut out = Vec::new();
            let prepared = clipper.prepare(&window).unwrap_or_else(|e| panic!("case {}: {e}", case.caption));
            prepared.clip_batch(&segments, &mut out).unwrap();
            if let Err(failure) = check_line_batch(&window, &segments, &out, tolerance) {
                panic!("Lines.txt case {} ({}): {failure}", case.caption, clipper.name());
            }
            checked += 1;
        }
    }
    assert!(checked >= 16 * 4);
}
