//! Clipper2's `Polygons.txt` (195 cases) with vatti, graded by `clip_testkit::clipper2_suite` as
//! `clipbench conformance` grades it: every area within Clipper2's own tolerance of the stored
//! area (or of the exact area where the stored one is off: case 44), every count within its count
//! tolerance of the stored count, or, where ring conventions differ, of Clipper2's count run live
//! with both normalised to ours. On top, every output passes the polygon oracle.

use clip_core::{BoolOp, FillRule, PolygonClipper, Polygons};
use clip_oracle::{OutputRules, REGION_TOLERANCE, check_polygon_result};
use clip_peers::normalised_counts_agree;
use clip_testkit::clipper2_suite::{Passed, Record, judge, parse_clipper2};
use clip_testkit::testdata_dir;
use clip_vatti::Vatti;

/// Our convention, applied to any rings: a union with nothing under non-zero.
fn normalise(rings: &Polygons) -> Result<Polygons, String> {
    Vatti.clip(rings, &Polygons::empty(), BoolOp::Union, FillRule::NonZero).map_err(|e| e.to_string())
}

#[test]
fn vatti_passes_polygons_txt_with_live_clipper2_counts() {
    let text = std::fs::read_to_string(testdata_dir().join("clipper2/Polygons.txt")).expect("Polygons.txt");
    let records = parse_clipper2(&text);
    assert_eq!(records.len(), 195);
    let rules = OutputRules::conventional(REGION_TOLERANCE);
    let recount = |record: &Record<'_>, out: &Polygons| normalised_counts_agree(record, out, &normalise);
    let mut failures = Vec::new();
    // Cases passed by the exact area, by the normalised count.
    let mut tally = [0usize; 2];
    for record in records {
        let c = record.expect("every record of Polygons.txt reads");
        let (subject, clip) = (Polygons::new(c.subjects), Polygons::new(c.clips));
        let out = match Vatti.clip(&subject, &clip, c.op, c.fill) {
            Ok(out) => out,
            Err(e) => {
                failures.push(format!("case {}: error {e}", c.number));
                continue;
            }
        };
        let record = Record {
            number: c.number,
            subject: &subject,
            clip: &clip,
            op: c.op,
            fill: c.fill,
            area: c.area,
            count: c.count,
        };
        match judge(&record, &out, &rules, &recount) {
            Ok(Passed { by_exact_area, by_normalised_count }) => {
                tally[0] += usize::from(by_exact_area);
                tally[1] += usize::from(by_normalised_count);
            }
            Err((expected, got)) => failures.push(format!("case {}: expected {expected}, got {got}", c.number)),
        }
        if let Err(e) = check_polygon_result(&subject, &clip, c.op, c.fill, &out, &rules) {
            failures.push(format!("case {}: {e}", c.number));
        }
    }
    eprintln!("passed by the exact area: {} cases; by the normalised count: {} cases", tally[0], tally[1]);
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}
