//! The `clipper2-polygons` and `clipper2-lines` suites: Clipper2's `Polygons.txt` and
//! `Lines.txt` as suite cases (graded by `clip_testkit::clipper2_suite`).

use std::path::Path;

use clip_core::{BoolOp, Polygons, Segment};
use clip_testkit::clipper2_suite::{Clipper2Case, parse_clipper2};

use super::suite_case::{CaseInput, PolygonExpectation, SuiteCase};
use crate::cli_error::{CliError, InputError};

/// `Polygons.txt`: every record a polygon case judged by stored area and count.
pub fn polygon_cases(testdata: &Path) -> Result<Vec<SuiteCase>, CliError> {
    let path = testdata.join("clipper2").join("Polygons.txt");
    Ok(read(&path)?
        .into_iter()
        .map(|(name, record)| SuiteCase {
            name,
            input: match record {
                Ok(c) if !c.open_subjects.is_empty() => {
                    CaseInput::NotApplicable("open subjects in a polygon case".into())
                }
                Ok(c) => CaseInput::Polygon {
                    subject: Polygons::new(c.subjects),
                    clip: Polygons::new(c.clips),
                    op: c.op,
                    fill: c.fill,
                    expected: PolygonExpectation::Clipper2 { number: c.number, area: c.area, count: c.count },
                },
                Err(problem) => CaseInput::Malformed(problem),
            },
        })
        .collect())
}

/// `Lines.txt`: the open subjects' edges clipped by the clip paths (even-odd), judged by the
/// exact line oracle. Its stored values are mostly 0, so they are not used; the one
/// `DIFFERENCE` record asks for the parts outside the window, which is not line clipping.
pub fn line_cases(testdata: &Path) -> Result<Vec<SuiteCase>, CliError> {
    let path = testdata.join("clipper2").join("Lines.txt");
    Ok(read(&path)?
        .into_iter()
        .map(|(name, record)| SuiteCase {
            name,
            input: match record {
                Ok(c) if c.op != BoolOp::Intersection => {
                    CaseInput::NotApplicable(format!("{} of open paths is not line clipping", c.op))
                }
                Ok(c) => CaseInput::Line {
                    window: Polygons::new(c.clips),
                    segments: c
                        .open_subjects
                        .iter()
                        .flat_map(|path| path.windows(2).map(|w| Segment::new(w[0], w[1])))
                        .collect(),
                },
                Err(problem) => CaseInput::Malformed(problem),
            },
        })
        .collect())
}

/// A record of the suite, or why it is malformed (`file:line: problem`).
pub type Record = Result<Clipper2Case, String>;

fn read(path: &Path) -> Result<Vec<(String, Record)>, CliError> {
    let text = std::fs::read_to_string(path).map_err(|e| InputError::new(path, format!("cannot read it: {e}")))?;
    records(&text, path).map_err(|problem| InputError::new(path, problem).into())
}

/// The numbered records of a suite file's text (`path` names it in messages); an error when it
/// holds none. The `readers` fuzz target calls this with any text.
pub fn records(text: &str, path: &Path) -> Result<Vec<(String, Record)>, String> {
    let records = parse_clipper2(text);
    if records.is_empty() {
        return Err("no CAPTION: record found".into());
    }
    Ok(records
        .into_iter()
        .enumerate()
        .map(|(i, r)| {
            let record = r.map_err(|m| format!("{}:{}: {}", path.display(), m.line, m.problem));
            ((i + 1).to_string(), record)
        })
        .collect())
}
