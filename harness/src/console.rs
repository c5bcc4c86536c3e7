//! What the commands print: results on standard output, notes on standard error. A reader that
//! stops early (`clipbench clip ... | head`) closes the pipe: the rest of the output is dropped
//! quietly and the command ends as it would have (files still written, same exit code). Any
//! other write error (`> /dev/full`) ends the command with a message instead of a panic.

use std::fmt;
use std::io::{self, Write};
use std::sync::atomic::{AtomicBool, Ordering};

use crate::cli_error::CliError;

/// Set once standard output's reader has gone; later output is dropped.
static READER_GONE: AtomicBool = AtomicBool::new(false);

/// Prints `text` on standard output as it is.
pub fn print(text: &str) -> Result<(), CliError> {
    if READER_GONE.load(Ordering::Relaxed) {
        return Ok(());
    }
    let mut out = io::stdout().lock();
    // Flushed at once: an error must surface here, not in the flush at exit, which ignores it.
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => {
            READER_GONE.store(true, Ordering::Relaxed);
            Ok(())
        }
        Err(e) => Err(CliError::failed(format!("cannot write to standard output: {e}"))),
    }
}

/// Prints `line` and a newline on standard output.
pub fn print_line(line: impl fmt::Display) -> Result<(), CliError> {
    print(&format!("{line}\n"))
}

/// Tells the user on standard error what reading changed (`clipbench: note: ...`); a note that
/// cannot be written is not worth failing for.
pub fn note(message: impl fmt::Display) {
    let _ = writeln!(io::stderr().lock(), "clipbench: note: {message}");
}
