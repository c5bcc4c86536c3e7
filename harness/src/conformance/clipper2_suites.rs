//! The `clipper2-polygons` and `clipper2-lines` suites: Clipper2's `Polygons.txt` and
//! `Lines.txt` as suite cases, and the tolerances Clipper2's own C++ test grades them with.

use std::path::Path;

use clip_core::{BoolOp, Polygons, Segment};
use clip_testkit::polygon_oracle::{OutputRules, region_area};

use super::clipper2_file::parse_clipper2;
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

type Record = Result<super::clipper2_file::Clipper2Case, String>;

fn read(path: &Path) -> Result<Vec<(String, Record)>, CliError> {
    let text = std::fs::read_to_string(path).map_err(|e| InputError::new(path, format!("cannot read it: {e}")))?;
    let records = parse_clipper2(&text);
    if records.is_empty() {
        return Err(InputError::new(path, "no CAPTION: record found".into()).into());
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

/// The count tolerance of Clipper2's TestPolygons.cpp for record `n`.
pub fn count_tolerance(n: usize) -> i64 {
    const FIVE: [usize; 16] = [120, 121, 130, 138, 140, 148, 163, 165, 166, 167, 168, 172, 173, 175, 178, 180];
    const ONE: [usize; 7] = [23, 45, 87, 102, 111, 113, 191];
    if FIVE.contains(&n) {
        5
    } else if n == 126 {
        3
    } else if [16, 27, 181].contains(&n) || (120..=184).contains(&n) {
        2
    } else if ONE.contains(&n) {
        1
    } else {
        0
    }
}

/// The area tolerance of TestPolygons.cpp for record `n`, as a fraction of the measured area.
pub fn area_tolerance(n: usize) -> f64 {
    match n {
        19 | 22 | 23 | 24 => 0.5,
        193 => 0.2,
        63 => 0.1,
        16 => 0.075,
        26 => 0.05,
        15 | 52 | 53 | 54 | 59 | 60 | 64 | 117 | 119 | 184 => 0.02,
        _ => 0.01,
    }
}

/// What a result is judged on: its net area, and its ring count where rings mean something.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measured {
    /// Net covered area.
    pub area: f64,
    /// Number of output rings; `None` for bridged output (Sutherland-Hodgman, four-state), whose
    /// rings keep the subject's rings joined by bridges and so do not count polygons.
    pub count: Option<i64>,
}

impl Measured {
    /// Conventional output: the rings' signed area (outers positive, holes negative) and their
    /// number, as Clipper2's test measures. Bridged output keeps the subject's orientation and is
    /// read under the input's fill rule, so its area is the covered region's, computed exactly.
    pub fn of(output: &Polygons, rules: &OutputRules) -> Measured {
        if rules.conventional {
            Measured { area: output.signed_area(), count: Some(output.rings.len() as i64) }
        } else {
            Measured { area: region_area(&[(output, rules.output_fill)], |inside| inside[0]), count: None }
        }
    }
}

/// Judges a result the way TestPolygons.cpp does: the truncated net area within the record's
/// fraction of the measured area, the path count within its count tolerance; a stored value of 0
/// or less is not checked, and neither is the count of bridged output.
pub fn judge(number: usize, area: i64, count: i64, measured: Measured) -> Result<(), (String, String)> {
    let measured_area = measured.area.trunc();
    let area_ok = area <= 0 || (measured_area - area as f64).abs() <= area_tolerance(number) * measured_area.abs();
    let count_ok = count <= 0 || measured.count.is_none_or(|c| (c - count).abs() <= count_tolerance(number));
    if area_ok && count_ok {
        Ok(())
    } else {
        let got_count = measured.count.map_or("not judged (bridged output)".to_owned(), |c| c.to_string());
        Err((
            format!("area {area} ±{}%, count {count} ±{}", area_tolerance(number) * 100.0, count_tolerance(number)),
            format!("area {measured_area}, count {got_count}"),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::FillRule;
    use clip_core::Rect;

    #[test]
    fn tolerances_follow_the_cpp_test() {
        assert_eq!((count_tolerance(168), count_tolerance(126), count_tolerance(150)), (5, 3, 2));
        assert_eq!((count_tolerance(16), count_tolerance(45), count_tolerance(1)), (2, 1, 0));
        assert_eq!((area_tolerance(23), area_tolerance(184), area_tolerance(1)), (0.5, 0.02, 0.01));
    }

    #[test]
    fn judge_checks_area_and_count_unless_stored_as_zero() {
        let square = Polygons::from(Rect::new(0.0, 0.0, 10.0, 10.0));
        let m = Measured::of(&square, &OutputRules::conventional(1e-9));
        assert!(judge(1, 100, 1, m).is_ok());
        assert!(judge(1, 101, 1, m).is_ok(), "1% of 100");
        assert!(judge(1, 110, 1, m).is_err());
        assert!(judge(1, 100, 2, m).is_err());
        assert!(judge(1, 0, -1, m).is_ok());
    }

    #[test]
    fn bridged_output_is_judged_by_region_under_the_input_rule() {
        // A clockwise square kept clockwise, as Sutherland-Hodgman keeps a subject's orientation:
        // under the negative rule it covers its area; its ring count is not judged.
        let cw = Polygons::from(Rect::new(0.0, 0.0, 3.0, 3.0).to_ring().reversed());
        let m = Measured::of(&cw, &OutputRules::bridged(FillRule::Negative, 1e-9));
        assert_eq!(m, Measured { area: 9.0, count: None });
        assert!(judge(188, 9, 1, m).is_ok());
        assert!(judge(188, 10, 1, m).is_err());
        let wrong_rule = Measured::of(&cw, &OutputRules::bridged(FillRule::Positive, 1e-9));
        assert!(judge(188, 9, 1, wrong_rule).is_err());
    }
}
