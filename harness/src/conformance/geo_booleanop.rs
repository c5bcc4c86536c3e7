//! The `geo-booleanop` suite: the Martinez-Rueda GeoJSON fixtures geo ships (subject, clip and
//! expected results per operation) and `tcases.json`, each judged by region.

use std::path::{Path, PathBuf};

use clip_core::{BoolOp, FillRule, Polygons};

use super::suite_case::{CaseInput, PolygonExpectation, SuiteCase};
use crate::cli_error::{CliError, InputError};
use crate::read::{Place, Placed, RingEnds, geo_geometry, parse_wkt, shapes_of};

/// Every fixture file's cases (one per expected operation), then `tcases.json`'s.
pub fn cases(testdata: &Path) -> Result<Vec<SuiteCase>, CliError> {
    let root = testdata.join("geo").join("booleanop-geojson");
    let mut files: Vec<PathBuf> = Vec::new();
    for folder in ["generic_test_cases", "benchmarks"] {
        let dir = root.join(folder);
        let entries = std::fs::read_dir(&dir).map_err(|e| InputError::new(&dir, format!("cannot read it: {e}")))?;
        let mut found: Vec<PathBuf> = entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "geojson"))
            .collect();
        found.sort();
        files.extend(found);
    }
    let mut cases = Vec::new();
    for file in &files {
        let stem = file.file_stem().and_then(|s| s.to_str()).unwrap_or("?").to_owned();
        match fixture(file) {
            Ok(found) => cases.extend(
                found.into_iter().map(|(op_name, input)| SuiteCase { name: format!("{stem}/{op_name}"), input }),
            ),
            Err(problem) => cases.push(SuiteCase { name: stem, input: CaseInput::Malformed(problem) }),
        }
    }
    cases.extend(tcases(&root.join("tcases.json"))?);
    Ok(cases)
}

/// The operation a fixture's `properties.operation` names, and whether the operands swap.
fn operation(name: &str) -> Option<(BoolOp, bool)> {
    match name {
        "intersection" => Some((BoolOp::Intersection, false)),
        "union" => Some((BoolOp::Union, false)),
        "xor" => Some((BoolOp::Xor, false)),
        "diff" => Some((BoolOp::Difference, false)),
        "diff_ba" => Some((BoolOp::Difference, true)),
        _ => None,
    }
}

fn case(subject: &Polygons, clip: &Polygons, op_name: &str, expected: Polygons) -> Result<CaseInput, String> {
    let (op, swap) = operation(op_name).ok_or_else(|| format!("unknown operation '{op_name}'"))?;
    if op == BoolOp::Union && expected.is_empty() && !(subject.is_empty() && clip.is_empty()) {
        // The benchmark files (asia, hole_hole, states_source) store an empty union: no answer.
        return Ok(CaseInput::NotApplicable("the fixture stores no expected union".into()));
    }
    let (subject, clip) = if swap { (clip.clone(), subject.clone()) } else { (subject.clone(), clip.clone()) };
    // The fixtures' rings come in either orientation, holes as rings inside: even-odd.
    Ok(CaseInput::Polygon {
        subject,
        clip,
        op,
        fill: FillRule::EvenOdd,
        expected: PolygonExpectation::Region(expected),
    })
}

fn polygons(g: &Option<geojson::Geometry>, what: &str) -> Result<Polygons, String> {
    let g = g.as_ref().ok_or_else(|| format!("{what} has no geometry"))?;
    // geo's fixtures hold an open ring (issue76), which geo's reader closes: read them as geo does.
    let g = geo_geometry(&g.value, &Place::default().then(what), RingEnds::MayBeOpen, &mut false)?;
    Ok(shapes_of(&[Placed::whole(g)]).map_err(|e| format!("{what}: {e}"))?.polygons())
}

fn fixture(file: &Path) -> Result<Vec<(String, CaseInput)>, String> {
    let text = std::fs::read_to_string(file).map_err(|e| format!("{}: cannot read it: {e}", file.display()))?;
    fixture_cases(&text, file)
}

/// The cases of a fixture file's text (`file` names it in messages): subject, clip, then one
/// expected result per operation. The `readers` fuzz target calls this with any text.
pub fn fixture_cases(text: &str, file: &Path) -> Result<Vec<(String, CaseInput)>, String> {
    let fc: geojson::FeatureCollection =
        text.parse().map_err(|e| format!("{}: not a GeoJSON FeatureCollection: {e}", file.display()))?;
    if fc.features.len() < 3 {
        return Err(format!("{}: fewer than 3 features (subject, clip, expected)", file.display()));
    }
    let subject = polygons(&fc.features[0].geometry, "feature 0 (subject)")?;
    let clip = polygons(&fc.features[1].geometry, "feature 1 (clip)")?;
    fc.features[2..]
        .iter()
        .enumerate()
        .map(|(i, f)| {
            let op_name = f
                .property("operation")
                .and_then(|v| v.as_str())
                .ok_or_else(|| format!("{}: feature {} has no operation", file.display(), i + 2))?;
            let expected = polygons(&f.geometry, &format!("feature {} (expected {op_name})", i + 2))?;
            Ok((op_name.to_owned(), case(&subject, &clip, op_name, expected)?))
        })
        .collect()
}

/// `tcases.json`: WKT inputs `p1`, `p2`, an operation and the expected WKT.
fn tcases(path: &Path) -> Result<Vec<SuiteCase>, CliError> {
    let text = std::fs::read_to_string(path).map_err(|e| InputError::new(path, format!("cannot read it: {e}")))?;
    tcases_of(&text, path).map_err(|problem| InputError::new(path, problem).into())
}

/// The cases of a `tcases.json` text (`path` names it in messages). The `readers` fuzz target
/// calls this with any text.
pub fn tcases_of(text: &str, path: &Path) -> Result<Vec<SuiteCase>, String> {
    let records: Vec<serde_json::Value> = serde_json::from_str(text).map_err(|e| format!("not a JSON array: {e}"))?;
    Ok(records
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let field = |k: &str| r.get(k).and_then(|v| v.as_str()).ok_or_else(|| format!("record {i} has no '{k}'"));
            let wkt = |k: &str| -> Result<Polygons, String> {
                let parsed = parse_wkt(field(k)?).map_err(|e| format!("record {i} '{k}': {e}"))?;
                Ok(shapes_of(&parsed.geometries)?.polygons())
            };
            let input = (|| case(&wkt("p1")?, &wkt("p2")?, field("op")?, wkt("expected")?))();
            let op = field("op").unwrap_or("?");
            SuiteCase {
                name: format!("tcases-{i}/{op}"),
                input: input.unwrap_or_else(|p| CaseInput::Malformed(format!("{}: {p}", path.display()))),
            }
        })
        .collect())
}
