//! Reads Clipper2's test files (`Polygons.txt`, `Lines.txt`): records of an operation, a fill
//! rule, expected area and count, and closed subject, open subject and clip paths; a malformed
//! record is reported with its file line and the rest are still read.

use clip_core::{BoolOp, FillRule, Point, Ring};

/// One record, numbered from 1 in file order.
#[derive(Clone, Debug, PartialEq)]
pub struct Clipper2Case {
    /// Position in the file, from 1 (Clipper2's tests address records this way).
    pub number: usize,
    /// Line of the file the record starts at, from 1.
    pub line: usize,
    /// The operation.
    pub op: BoolOp,
    /// The one fill rule for subject and clip.
    pub fill: FillRule,
    /// Expected area of the closed solution (0 or -1: not checked).
    pub area: i64,
    /// Expected number of solution paths (0 or -1: not checked).
    pub count: i64,
    /// Closed subject paths.
    pub subjects: Vec<Ring>,
    /// Open subject paths (polylines).
    pub open_subjects: Vec<Vec<Point>>,
    /// Clip paths.
    pub clips: Vec<Ring>,
}

/// A record that could not be read: its number, the file line and the problem.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MalformedCase {
    /// Position in the file, from 1.
    pub number: usize,
    /// The file line of the problem, from 1.
    pub line: usize,
    /// What is wrong.
    pub problem: String,
}

/// Which path block the following lines belong to.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Block {
    None,
    Subjects,
    OpenSubjects,
    Clips,
}

/// Every record of the file, each parsed or reported malformed (the rest still read).
pub fn parse_clipper2(text: &str) -> Vec<Result<Clipper2Case, MalformedCase>> {
    let lines: Vec<&str> = text.lines().collect();
    let starts: Vec<usize> = (0..lines.len()).filter(|&i| lines[i].trim_start().starts_with("CAPTION:")).collect();
    starts
        .iter()
        .enumerate()
        .map(|(k, &start)| {
            let end = starts.get(k + 1).copied().unwrap_or(lines.len());
            parse_record(k + 1, start, &lines[start..end])
        })
        .collect()
}

fn parse_record(number: usize, start: usize, lines: &[&str]) -> Result<Clipper2Case, MalformedCase> {
    let fail = |offset: usize, problem: String| MalformedCase { number, line: start + offset + 1, problem };
    let mut case = Clipper2Case {
        number,
        line: start + 1,
        op: BoolOp::Intersection,
        fill: FillRule::EvenOdd,
        area: 0,
        count: 0,
        subjects: Vec::new(),
        open_subjects: Vec::new(),
        clips: Vec::new(),
    };
    let (mut op, mut fill) = (None, None);
    let (mut area, mut count) = (None, None);
    let mut block = Block::None;
    for (offset, raw) in lines.iter().enumerate().skip(1) {
        let line = raw.trim();
        let value = |key: &str| line.split_once(key).map(|(_, v)| v.trim());
        if let Some(v) = value("CLIPTYPE:") {
            op = Some(match v {
                "INTERSECTION" => BoolOp::Intersection,
                "UNION" => BoolOp::Union,
                "DIFFERENCE" => BoolOp::Difference,
                "XOR" => BoolOp::Xor,
                other => return Err(fail(offset, format!("unknown CLIPTYPE '{other}'"))),
            });
        } else if let Some(v) = value("FILLRULE:") {
            fill = Some(match v {
                "EVENODD" => FillRule::EvenOdd,
                "NONZERO" => FillRule::NonZero,
                "POSITIVE" => FillRule::Positive,
                "NEGATIVE" => FillRule::Negative,
                other => return Err(fail(offset, format!("unknown FILLRULE '{other}'"))),
            });
        } else if let Some(v) = value("SOL_AREA:") {
            area = Some(v.parse().map_err(|_| fail(offset, format!("SOL_AREA '{v}' is not an integer")))?);
        } else if let Some(v) = value("SOL_COUNT:") {
            count = Some(v.parse().map_err(|_| fail(offset, format!("SOL_COUNT '{v}' is not an integer")))?);
        } else if line.starts_with("SUBJECTS_OPEN") {
            block = Block::OpenSubjects;
        } else if line.starts_with("SUBJECTS") {
            block = Block::Subjects;
        } else if line.starts_with("CLIPS") {
            block = Block::Clips;
        } else if line.starts_with(|c: char| c.is_ascii_digit() || c == '-') && block != Block::None {
            let path = parse_path(line).map_err(|p| fail(offset, p))?;
            match block {
                Block::Subjects => case.subjects.push(Ring::new(path)),
                Block::OpenSubjects => case.open_subjects.push(path),
                Block::Clips => case.clips.push(Ring::new(path)),
                Block::None => {}
            }
        } else {
            // A blank line or anything else ends the path block.
            block = Block::None;
        }
    }
    case.op = op.ok_or_else(|| fail(0, "no CLIPTYPE".into()))?;
    case.fill = fill.ok_or_else(|| fail(0, "no FILLRULE".into()))?;
    // Every record of Clipper2's files states both, even as 0 or -1 ("not checked"): a record
    // without them is cut short, and must not pass for one expecting nothing.
    case.area = area.ok_or_else(|| fail(0, "no SOL_AREA: the record is cut short".into()))?;
    case.count = count.ok_or_else(|| fail(0, "no SOL_COUNT: the record is cut short".into()))?;
    if case.subjects.is_empty() && case.open_subjects.is_empty() {
        return Err(fail(0, "no SUBJECTS or SUBJECTS_OPEN paths: the record is cut short".into()));
    }
    Ok(case)
}

/// `x,y, x,y, ...` or `x,y x,y ...`: commas and spaces alike separate integers.
fn parse_path(line: &str) -> Result<Vec<Point>, String> {
    let numbers: Vec<f64> = line
        .split([',', ' '])
        .filter(|s| !s.is_empty())
        .map(|s| s.parse::<i64>().map(|v| v as f64).map_err(|_| format!("'{s}' is not an integer coordinate")))
        .collect::<Result<_, _>>()?;
    if !numbers.len().is_multiple_of(2) {
        return Err(format!("odd number of coordinates ({})", numbers.len()));
    }
    Ok(numbers.chunks(2).map(|c| Point::new(c[0], c[1])).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn records_with_all_path_kinds() {
        let text = "CAPTION: 1. \nCLIPTYPE: DIFFERENCE\nFILLRULE: EVENODD\nSOL_AREA: 8\nSOL_COUNT: 1\nSUBJECTS\n5,4, 8,4, 8,8, 5,8\nSUBJECTS_OPEN\n6,7, 6,5\nCLIPS\n7,9, 4,9, 4,6, 7,6\n\nCAPTION: 2.\nCLIPTYPE: UNION\nFILLRULE: NONZERO\nSOL_AREA: 0\nSOL_COUNT: 0\nSUBJECTS\n0 0 1 0 1 1\n";
        let cases = parse_clipper2(text);
        assert_eq!(cases.len(), 2);
        let c = cases[0].as_ref().unwrap();
        assert_eq!((c.op, c.fill, c.area, c.count), (BoolOp::Difference, FillRule::EvenOdd, 8, 1));
        assert_eq!((c.subjects.len(), c.open_subjects.len(), c.clips.len()), (1, 1, 1));
        assert_eq!(c.open_subjects[0], vec![Point::new(6.0, 7.0), Point::new(6.0, 5.0)]);
        let c = cases[1].as_ref().unwrap();
        assert_eq!((c.number, c.line, c.subjects[0].len()), (2, 13, 3));
    }

    /// A record cut after its header was read as one expecting area 0 and count 0, which every
    /// clipper's empty answer passes (issue 28).
    #[test]
    fn a_record_cut_short_is_malformed_naming_what_is_missing() {
        let header = "CAPTION: 1.\nCLIPTYPE: UNION\nFILLRULE: EVENODD\n";
        let e = parse_clipper2(header).remove(0).unwrap_err();
        assert_eq!((e.line, e.problem.as_str()), (1, "no SOL_AREA: the record is cut short"));
        let e = parse_clipper2(&format!("{header}SOL_AREA: 5\n")).remove(0).unwrap_err();
        assert_eq!(e.problem, "no SOL_COUNT: the record is cut short");
        let e = parse_clipper2(&format!("{header}SOL_AREA: 5\nSOL_COUNT: 1\n")).remove(0).unwrap_err();
        assert!(e.problem.starts_with("no SUBJECTS"), "{}", e.problem);
        assert!(parse_clipper2(&format!("{header}SOL_AREA: 5\nSOL_COUNT: 1\nSUBJECTS\n0,0, 1,0, 1,1\n"))[0].is_ok());
    }

    #[test]
    fn a_malformed_record_is_reported_with_its_line_and_the_rest_still_read() {
        let text = "CAPTION: 1.\nCLIPTYPE: UNION\nFILLRULE: EVENODD\nSUBJECTS\n1,2, 3\nCAPTION: 2.\nCLIPTYPE: NOPE\nCAPTION: 3.\nCLIPTYPE: XOR\nFILLRULE: POSITIVE\nSOL_AREA: -1\nSOL_COUNT: -1\nSUBJECTS_OPEN\n0,0, 1,1\n";
        let cases = parse_clipper2(text);
        assert_eq!(cases[0].as_ref().unwrap_err().line, 5);
        assert!(cases[1].as_ref().unwrap_err().problem.contains("NOPE"));
        assert!(cases[2].is_ok());
    }
}
