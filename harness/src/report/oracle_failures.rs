//! REPORT.md's "Where the clippers disagree with the oracle": from `verify --results`, oracle
//! failures per clipper and workload, and the smallest shrunk failing case of each kind, drawn.

use std::collections::BTreeMap;

use super::derived::Derived;
use super::markdown::table;
use super::provenance_line::provenance_line;
use super::results_folder::ResultsFolder;
use super::summary::with_hung;
use crate::cli_error::CliError;
use crate::results_files::verify::{CaseEntry, FAILURES, META, PICTURE, VerifyRow};

/// The section (it draws nothing: `verify` drew each case's picture), or `None` when the folder
/// holds no verify results.
pub fn derive(folder: &ResultsFolder) -> Result<Option<Derived>, CliError> {
    let Some(results) = folder.verify()? else { return Ok(None) };
    let meta = folder.join(META);
    let notes = if meta.exists() { provenance_line(&meta)?.1 } else { String::new() };
    let mut text = format!(
        "`clipbench verify` with {} generated cases per workload (seed {}): every clipper on every case, operation \
         and fill rule it supports, against the exact oracle (output validity, membership at sample points, region \
         area) and the area identities. Each cell is failures / checked results, then the failed area identities \
         (one check per case and fill rule, over its four results) where there are any; a refusal of valid input, or an \
         external clipper that crashed or answered garbage, counts as a failure. An external clipper that gave no \
         answer within the call time-out is not counted as a failure but as hung, beside it (\"2 hung\"). Peers \
         (geo, Clipper2, GEOS, i_overlay, Clipper 1, clipper2-rust and external clippers) are judged with the \
         looser peer tolerance (`GEO_TOLERANCE`, 1e-6 of the inputs' box area), this project's clippers with \
         1e-9.\n\n{notes}\n",
        results.cases_per_workload, results.seed
    );
    for kind in ["polygon", "line"] {
        if let Some(t) = failure_table(&results.rows, kind) {
            text.push_str(&format!("{kind} clipping:\n\n{t}\n"));
        }
    }
    let smallest = smallest_cases(&results.cases);
    if smallest.is_empty() {
        text.push_str("No failure case was written.\n");
        return Ok(Some(Derived::new(text)));
    }
    text.push_str(
        "### The smallest failing case of each kind\n\n\
         Per clipper and check, the written failure whose shrunk inputs have the fewest vertices (subject and \
         clip, or window and segment end points). Each folder holds the WKT inputs and outputs and a `case.json` \
         to replay it with `clipbench verify --replay`.\n\n",
    );
    for c in smallest {
        let what = [c.op.as_deref(), c.fill.as_deref()].into_iter().flatten().collect::<Vec<_>>().join(", ");
        let case_folder = format!("{FAILURES}/{}", c.folder);
        text.push_str(&format!(
            "#### {} — {} on `{}`{}\n\n{} vertices after shrinking: {}\n\n![{}]({case_folder}/{PICTURE})\n\n",
            c.clipper,
            c.check,
            c.workload,
            if what.is_empty() { String::new() } else { format!(" ({what})") },
            c.shrunk_vertices[0] + c.shrunk_vertices[1],
            one_line(&c.shrunk),
            c.folder,
        ));
    }
    Ok(Some(Derived::new(text)))
}

/// Clippers down, workloads across, `failures / runs` in each cell ("–" where it did not run).
fn failure_table(rows: &[VerifyRow], kind: &str) -> Option<String> {
    let rows: Vec<&VerifyRow> = rows.iter().filter(|r| r.kind == kind).collect();
    let mut clippers: Vec<(&str, &str)> = Vec::new();
    let mut workloads: Vec<&str> = Vec::new();
    for r in &rows {
        if !clippers.iter().any(|(c, _)| *c == r.clipper) {
            clippers.push((&r.clipper, &r.origin));
        }
        if !workloads.contains(&r.workload.as_str()) {
            workloads.push(&r.workload);
        }
    }
    if clippers.is_empty() {
        return None;
    }
    let cells: BTreeMap<(&str, &str), &VerifyRow> =
        rows.iter().map(|r| ((r.clipper.as_str(), r.workload.as_str()), *r)).collect();
    let mut header = vec!["clipper".to_owned(), "origin".to_owned()];
    header.extend(workloads.iter().map(|w| format!("`{w}`")));
    let body: Vec<Vec<String>> = clippers
        .iter()
        .map(|&(c, origin)| {
            let mut line = vec![format!("`{c}`"), origin.to_owned()];
            line.extend(workloads.iter().map(|&w| {
                cells.get(&(c, w)).map_or("–".to_owned(), |r| {
                    let mut cell = format!("{} / {}", r.oracle_failures, r.runs);
                    if r.identity_failures > 0 {
                        cell.push_str(&format!(" + {} identity", r.identity_failures));
                    }
                    let cell = if r.oracle_failures + r.identity_failures > 0 { format!("**{cell}**") } else { cell };
                    with_hung(cell, r.hung)
                })
            }));
            line
        })
        .collect();
    Some(table(&header, &body))
}

/// Per clipper and oracle check (disagreements between clippers are left out), the case with the
/// fewest shrunk vertices; ties go to the first written. In clipper, then check order of first
/// appearance.
fn smallest_cases(cases: &[CaseEntry]) -> Vec<&CaseEntry> {
    let mut chosen: Vec<&CaseEntry> = Vec::new();
    for c in cases.iter().filter(|c| c.check != "disagreement") {
        let size = |c: &CaseEntry| c.shrunk_vertices[0] + c.shrunk_vertices[1];
        match chosen.iter_mut().find(|k| k.clipper == c.clipper && k.check == c.check) {
            Some(kept) if size(c) < size(kept) => *kept = c,
            Some(_) => {}
            None => chosen.push(c),
        }
    }
    chosen.sort_by_key(|c| cases.iter().position(|k| k.clipper == c.clipper).unwrap_or(usize::MAX));
    chosen
}

/// A message on one line, with markdown's table and emphasis characters left alone.
fn one_line(message: &str) -> String {
    message.split_whitespace().collect::<Vec<_>>().join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn case(clipper: &str, check: &str, vertices: usize) -> CaseEntry {
        CaseEntry {
            folder: format!("{clipper}-{check}-{vertices}"),
            seed: 1,
            index: 0,
            kind: "polygon".into(),
            clipper: clipper.into(),
            workload: "star".into(),
            check: check.into(),
            other: None,
            op: Some("union".into()),
            fill: Some("even-odd".into()),
            shrunk_vertices: [vertices, 3],
            shrunk: "area off".into(),
        }
    }

    #[test]
    fn the_smallest_case_of_each_clipper_and_check_is_kept() {
        let cases = vec![
            case("geos", "oracle", 9),
            case("geos", "oracle", 5),
            case("geos", "disagreement", 3),
            case("geos", "area-identities", 7),
            case("clipper1", "oracle", 4),
            case("geos", "oracle", 5),
        ];
        let kept: Vec<&str> = smallest_cases(&cases).iter().map(|c| c.folder.as_str()).collect();
        assert_eq!(kept, vec!["geos-oracle-5", "geos-area-identities-7", "clipper1-oracle-4"]);
    }

    #[test]
    fn the_table_has_a_cell_per_clipper_and_workload() {
        let row = |clipper: &str, workload: &str, failures: usize| VerifyRow {
            clipper: clipper.into(),
            origin: "peer".into(),
            kind: "polygon".into(),
            workload: workload.into(),
            runs: 64,
            oracle_failures: failures,
            ..VerifyRow::default()
        };
        let t =
            failure_table(&[row("geos", "star", 2), row("geos", "grid", 0), row("i_overlay", "star", 0)], "polygon")
                .unwrap();
        let lines: Vec<&str> = t.lines().collect();
        assert_eq!(lines[0], "| clipper | origin | `star` | `grid` |");
        assert_eq!(lines[2], "| `geos` | peer | **2 / 64** | 0 / 64 |");
        assert_eq!(lines[3], "| `i_overlay` | peer | 0 / 64 | – |");
        assert!(failure_table(&[row("geos", "star", 0)], "line").is_none());
    }
}
