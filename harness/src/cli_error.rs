//! The errors a command ends with, each a one-line message and an exit code.

use std::fmt;
use std::path::{Path, PathBuf};

/// A file that cannot be used as input: unreadable, not WKT/GeoJSON, or invalid geometry.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InputError {
    /// The file.
    pub path: PathBuf,
    /// What is wrong with it, in one line.
    pub problem: String,
}

impl InputError {
    /// An error about `path`.
    pub fn new(path: &Path, problem: String) -> InputError {
        InputError { path: path.to_owned(), problem: problem.replace('\n', " ") }
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path.display(), self.problem)
    }
}

impl std::error::Error for InputError {}

/// Why a command stopped: a one-line message and the process exit code.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CliError {
    /// Printed on standard error after `clipbench: `.
    pub message: String,
    /// 2 for bad input or usage, 1 for everything else.
    pub code: u8,
}

impl CliError {
    /// Bad input or usage (unknown names, unreadable files): exit code 2.
    pub fn usage(message: impl Into<String>) -> CliError {
        CliError { message: message.into(), code: 2 }
    }

    /// A failure while running (a clipper refused valid-looking input, a file could not be written).
    pub fn failed(message: impl Into<String>) -> CliError {
        CliError { message: message.into(), code: 1 }
    }
}

impl From<InputError> for CliError {
    fn from(e: InputError) -> CliError {
        CliError::usage(e.to_string())
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}
