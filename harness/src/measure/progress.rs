//! Progress of long steps: a bar on a terminal; elsewhere one line per tenth done, so logs show
//! that a long run is alive without filling up.

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressStyle};

/// Progress through `len` steps of one long step.
pub struct Progress {
    bar: ProgressBar,
    what: String,
    len: usize,
    done: usize,
    terminal: bool,
}

impl Progress {
    /// One step done.
    pub fn inc(&mut self) {
        self.done += 1;
        self.bar.inc(1);
        if !self.terminal && self.len >= 10 && (self.done * 10 / self.len) > ((self.done - 1) * 10 / self.len) {
            eprintln!("clipbench: {}: {}/{} done", self.what, self.done, self.len);
        }
    }

    /// What is being done now (shown on the bar only).
    pub fn set_message(&self, message: String) {
        self.bar.set_message(message);
    }

    /// Removes the bar.
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

/// Progress of `len` steps labelled `what`.
pub fn bar(len: usize, what: &str) -> Progress {
    let terminal = std::io::stderr().is_terminal();
    let bar = if terminal {
        let bar = ProgressBar::new(len as u64);
        let template = format!("{what} {{bar:40}} {{pos}}/{{len}} {{msg}} {{elapsed}} elapsed, eta {{eta}}");
        if let Ok(style) = ProgressStyle::with_template(&template) {
            bar.set_style(style);
        }
        bar
    } else {
        eprintln!("clipbench: {what} ({len} steps)");
        ProgressBar::hidden()
    };
    Progress { bar, what: what.to_owned(), len, done: 0, terminal }
}
