//! Progress bars for long steps: drawn on a terminal, replaced by one line per step elsewhere.

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressStyle};

/// A bar of `len` steps labelled `what`; hidden (with the label printed once) when standard
/// error is not a terminal, so logs stay readable.
pub fn bar(len: usize, what: &str) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        eprintln!("clipbench: {what} ({len} steps)");
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(len as u64);
    let template = format!("{what} {{bar:40}} {{pos}}/{{len}} {{msg}} {{elapsed}} elapsed, eta {{eta}}");
    if let Ok(style) = ProgressStyle::with_template(&template) {
        bar.set_style(style);
    }
    bar
}
