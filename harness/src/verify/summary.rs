//! The verify summary: counts per clipper and workload, printed as a table or written as JSON.
use crate::checks::Check;
use crate::registry::Origin;
use crate::results_files::verify::{CaseEntry, CountsRow, VerifyResults};

/// The counts of one clipper on one workload, while verify counts.
pub type Row = CountsRow<&'static str>;

impl Row {
    /// An empty row.
    pub fn new(clipper: &'static str, origin: Origin, kind: &'static str, workload: &'static str) -> Row {
        Row { clipper, origin: origin.label(), kind, workload, ..Row::default() }
    }

    /// The count a failed run is added to: `hung` for [`Check::Hung`], else `oracle_failures`.
    pub fn failures(&mut self, check: Check) -> &mut usize {
        if check == Check::Hung { &mut self.hung } else { &mut self.oracle_failures }
    }
}

/// The whole run.
#[derive(Clone, Debug, PartialEq)]
pub struct Summary {
    /// The seed every case was generated from.
    pub seed: u64,
    /// Cases per workload.
    pub cases_per_workload: usize,
    /// One row per clipper and workload it ran on.
    pub rows: Vec<Row>,
    /// Failure folders written.
    pub failures_recorded: usize,
    /// Failures found but not written because of `--max-records`.
    pub failures_not_recorded: usize,
    /// True when a clipper of this project failed the oracle (the run exits non-zero).
    pub ours_failed: bool,
    /// The part of the cases run, none for all.
    pub partition: Option<crate::partition::Partition>,
}

impl Summary {
    /// The summary as its results file, with the failure cases written.
    pub fn to_file(&self, cases: Vec<CaseEntry>) -> VerifyResults {
        VerifyResults {
            seed: self.seed,
            cases_per_workload: self.cases_per_workload,
            rows: self.rows.iter().map(Row::to_file).collect(),
            failures_recorded: self.failures_recorded,
            failures_not_recorded: self.failures_not_recorded,
            ours_failed: self.ours_failed,
            cases,
            partition: self.partition,
        }
    }
}

/// The table: one line per row; a column of disagreements for each other clipper that appears.
pub fn table(rows: &[Row]) -> String {
    let mut others: Vec<&'static str> = Vec::new();
    for r in rows {
        for name in r.disagreements.keys() {
            if !others.contains(name) {
                others.push(name);
            }
        }
    }
    let with_bridges = rows.iter().any(|r| r.bridges.is_some());
    let with_identities = rows.iter().any(|r| r.kind == "polygon");
    let mut header = vec!["clipper".to_owned(), "kind".into(), "workload".into(), "cases".into(), "runs".into()];
    header.push("oracle fail".into());
    header.push("hung".into());
    if with_identities {
        header.push("identity fail".into());
    }
    header.extend(others.iter().map(|o| format!("vs {o}")));
    if with_bridges {
        header.push("bridges".into());
    }
    let mut lines: Vec<Vec<String>> = vec![header];
    for r in rows {
        let mut cells = vec![
            r.clipper.to_owned(),
            r.kind.to_owned(),
            r.workload.to_owned(),
            r.cases.to_string(),
            r.runs.to_string(),
            r.oracle_failures.to_string(),
            r.hung.to_string(),
        ];
        if with_identities {
            cells.push(if r.kind == "polygon" { r.identity_failures.to_string() } else { "-".to_owned() });
        }
        cells.extend(others.iter().map(|o| r.disagreements.get(o).map_or("-".to_owned(), |n| n.to_string())));
        if with_bridges {
            cells.push(r.bridges.map_or("-".to_owned(), |b| b.to_string()));
        }
        lines.push(cells);
    }
    let widths: Vec<usize> = (0..lines[0].len()).map(|c| lines.iter().map(|l| l[c].len()).max().unwrap_or(0)).collect();
    let mut out = String::new();
    for (i, cells) in lines.iter().enumerate() {
        let row: Vec<String> = cells
            .iter()
            .enumerate()
            .map(|(c, s)| if c < 3 { format!("{s:<w$}", w = widths[c]) } else { format!("{s:>w$}", w = widths[c]) })
            .collect();
        out.push_str(row.join("  ").trim_end());
        out.push('\n');
        if i == 0 {
            out.push_str(&"-".repeat(widths.iter().sum::<usize>() + 2 * (widths.len() - 1)));
            out.push('\n');
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_has_a_column_per_other_clipper_and_dashes_where_none() {
        let mut a = Row::new("geo", Origin::Peer, "polygon", "star");
        a.cases = 10;
        a.runs = 160;
        a.disagreements.insert("clipper2", 2);
        let mut b = Row::new("clipper2", Origin::Peer, "polygon", "star");
        b.disagreements.insert("geo", 2);
        b.oracle_failures = 1;
        let t = table(&[a, b]);
        let lines: Vec<&str> = t.lines().collect();
        assert!(lines[0].contains("vs clipper2") && lines[0].contains("vs geo"), "{t}");
        assert!(lines[2].starts_with("geo") && lines[2].contains("160"), "{t}");
        assert!(lines[2].ends_with('-'), "geo is not compared with itself: {t}");
        assert!(!lines[0].contains("bridges"));
    }

    #[test]
    fn rows_add_up() {
        let mut a = Row::new("x", Origin::Ours, "polygon", "grid");
        let mut b = a.clone();
        b.cases = 3;
        b.bridges = Some(2);
        b.hung = 1;
        b.disagreements.insert("geo", 1);
        a.add(&b);
        a.add(&b);
        assert_eq!((a.cases, a.bridges, a.hung, a.disagreements["geo"]), (6, Some(4), 2, 2));
    }
}
