//! The one list of REPORT.md's sections, in the report's order. Each names the `reproduce` table
//! that measures it (if any), its own markdown file (if any) and the function that derives it from
//! the raw results. `reproduce`'s table names and its `--help`, the step after each table is
//! measured, `report` and REPORT.md's order all come from this list.

use std::path::Path;

use super::derived::Derived;
use super::results_folder::ResultsFolder;
use super::{
    atlas, bench_tables, beyond_paper, lecture_curves, lecture_sh, lecture_text, oracle_failures, summary, table3,
    table4,
};
use crate::cli_error::CliError;
use crate::reproduce::{self, ReproduceArgs};

/// A table `clipbench reproduce` measures.
#[derive(Debug)]
pub struct Table {
    /// Its name on the command line.
    pub name: &'static str,
    /// What it measures, for `--help`.
    pub about: &'static str,
    /// Measures it and writes its raw files into the folder.
    pub measure: fn(&ReproduceArgs, &Path) -> Result<(), CliError>,
}

/// One section of REPORT.md.
#[derive(Debug)]
pub struct Section {
    /// Its short name.
    pub name: &'static str,
    /// Its heading in REPORT.md (and in its own markdown file).
    pub title: &'static str,
    /// The `reproduce` table that measures it; `None` for what `bench` and `verify` measure.
    pub table: Option<&'static Table>,
    /// Its own markdown file beside REPORT.md, holding the same text.
    pub markdown: Option<&'static str>,
    /// Reads the raw results and derives its text and files; `None` when the folder has none of
    /// its results.
    pub derive: fn(&ResultsFolder) -> Result<Option<Derived>, CliError>,
}

/// `reproduce`'s name for every table at once, in the order of [`SECTIONS`].
pub const ALL_TABLES: &str = "all";

/// Vatti 1992, Table 3.
pub static VATTI_TABLE3: Table =
    Table { name: "vatti-table3", about: "Vatti 1992, Table 3", measure: reproduce::measure_vatti_table3 };

/// Wang et al. 2005, Table 4.
pub static WANG_TABLE4: Table =
    Table { name: "wang-table4", about: "Wang et al. 2005, Table 4", measure: reproduce::measure_wang_table4 };

/// Line clipping beyond Table 4's window sizes.
pub static BEYOND_PAPER: Table = Table {
    name: "beyond-paper",
    about: "line clipping against windows of 6 to 10^4 edges, and 10^6 segments on every core",
    measure: reproduce::measure_beyond_paper,
};

/// The lecture notes' figures, curve clipping and text clipping.
pub static LECTURE: Table = Table {
    name: "lecture",
    about: "the lecture notes' figures redrawn, the curve clipping bench and what the text strategies cost",
    measure: reproduce::measure_lecture,
};

/// REPORT.md's sections in order: the summary first (trust and speed side by side), then the
/// oracle failures behind it, the atlas of external clippers, then each experiment.
pub static SECTIONS: [Section; 10] = [
    Section {
        name: "summary",
        title: "Summary: which clipper to trust, and how fast it is",
        table: None,
        markdown: None,
        derive: summary::derive,
    },
    Section {
        name: "oracle-failures",
        title: "Where the clippers disagree with the oracle",
        table: None,
        markdown: None,
        derive: oracle_failures::derive,
    },
    Section {
        name: "atlas",
        title: "The atlas: the clippers people use, judged and timed",
        table: None,
        markdown: Some("atlas.md"),
        derive: atlas::derive,
    },
    Section {
        name: "vatti-table3",
        title: "Vatti 1992, Table 3: clip and fill, Method 1 against Method 2",
        table: Some(&VATTI_TABLE3),
        markdown: Some("vatti-table3.md"),
        derive: table3::derive,
    },
    Section {
        name: "wang-table4",
        title: "Wang et al. 2005, Table 4: line clipping against concave windows",
        table: Some(&WANG_TABLE4),
        markdown: Some("wang-table4.md"),
        derive: table4::derive,
    },
    Section {
        name: "beyond-paper",
        title: "Beyond the paper: line clipping against windows of 6 to 10^4 edges",
        table: Some(&BEYOND_PAPER),
        markdown: Some("beyond-paper.md"),
        derive: beyond_paper::derive,
    },
    Section {
        name: "bench",
        title: "Bench: the polygon clippers against geo and Clipper2",
        table: None,
        markdown: Some("bench.md"),
        derive: bench_tables::derive,
    },
    Section {
        name: "lecture-sh",
        title: "Lecture notes: Sutherland-Hodgman on a concave polygon (Fig. 6-24)",
        table: Some(&LECTURE),
        markdown: None,
        derive: lecture_sh::derive,
    },
    Section {
        name: "lecture-curves",
        title: "Curve clipping: what the preliminary tests save",
        table: Some(&LECTURE),
        markdown: Some("lecture-curves.md"),
        derive: lecture_curves::derive,
    },
    Section {
        name: "lecture-text",
        title: "Lecture notes: text clipping (Figs. 6-28 to 6-30)",
        table: Some(&LECTURE),
        markdown: Some("lecture-text.md"),
        derive: lecture_text::derive,
    },
];

/// Every table `reproduce` measures, once each, in the order of their first section.
pub fn tables() -> Vec<&'static Table> {
    let mut tables: Vec<&'static Table> = Vec::new();
    for table in SECTIONS.iter().filter_map(|s| s.table) {
        if !tables.iter().any(|t| t.name == table.name) {
            tables.push(table);
        }
    }
    tables
}

/// The tables `reproduce NAME` measures: one, or every one for [`ALL_TABLES`].
pub fn tables_named(name: &str) -> Result<Vec<&'static Table>, CliError> {
    let tables = tables();
    if name == ALL_TABLES {
        return Ok(tables);
    }
    match tables.iter().find(|t| t.name == name) {
        Some(table) => Ok(vec![*table]),
        None => {
            let names: Vec<&str> = tables.iter().map(|t| t.name).chain([ALL_TABLES]).collect();
            Err(CliError::usage(format!("unknown table '{name}' (valid: {})", names.join(", "))))
        }
    }
}

/// The sections `table` measures, by their place in [`SECTIONS`].
pub fn measured_by(table: &Table) -> impl Iterator<Item = usize> + '_ {
    SECTIONS.iter().enumerate().filter(move |(_, s)| s.table.is_some_and(|t| t.name == table.name)).map(|(i, _)| i)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_all_measures_every_table_in_report_order() {
        let mut names: Vec<&str> = SECTIONS.iter().map(|s| s.name).collect();
        let mut files: Vec<&str> = SECTIONS.iter().filter_map(|s| s.markdown).collect();
        names.sort_unstable();
        names.dedup();
        files.sort_unstable();
        files.dedup();
        assert_eq!(names.len(), SECTIONS.len());
        assert_eq!(files.len(), SECTIONS.iter().filter(|s| s.markdown.is_some()).count());
        let all: Vec<&str> = tables_named(ALL_TABLES).unwrap().iter().map(|t| t.name).collect();
        assert_eq!(all, ["vatti-table3", "wang-table4", "beyond-paper", "lecture"]);
        assert_eq!(tables_named("lecture").unwrap()[0].name, "lecture");
        let lecture: Vec<&str> = measured_by(&LECTURE).map(|i| SECTIONS[i].name).collect();
        assert_eq!(lecture, ["lecture-sh", "lecture-curves", "lecture-text"]);
        let err = tables_named("table5").unwrap_err();
        assert_eq!(err.code, 2);
        assert!(err.message.contains("unknown table 'table5' (valid: vatti-table3, wang-table4,"), "{}", err.message);
    }
}
