//! What a section derives from the raw results: its text, and the files it puts beside it. The
//! section only computes; the report writes, so each file is written once per run.

use crate::plot::chart::Chart;

/// One section's output.
#[derive(Debug)]
pub struct Derived {
    /// Its text after the heading, in REPORT.md and in its own markdown file.
    pub body: String,
    /// The files it writes into the results folder, by file name, in order.
    pub files: Vec<(String, DerivedFile)>,
}

/// A file a section writes.
#[derive(Debug)]
pub enum DerivedFile {
    /// A plot, drawn as SVG.
    Plot(Chart),
    /// Text as it is (a derived CSV).
    Text(String),
}

impl Derived {
    /// A section with `body` and no files yet.
    pub fn new(body: String) -> Derived {
        Derived { body, files: Vec::new() }
    }

    /// The same with a plot `file` added.
    pub fn with_plot(mut self, file: impl Into<String>, chart: Chart) -> Derived {
        self.files.push((file.into(), DerivedFile::Plot(chart)));
        self
    }
}
