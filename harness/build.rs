//! Stamps the binary with the git revision it is built from, so result files name the code that
//! measured them even when the checkout has moved on by the time a long run writes them.

use std::path::Path;

#[path = "src/measure/git_revision.rs"]
mod git_revision;

use git_revision::{checkout_revision, git};

fn main() {
    // Re-stamp when a commit moves HEAD or the code changes; a directory is scanned whole.
    for path in ["../crates", "src", "Cargo.toml", "../Cargo.toml", "../Cargo.lock"] {
        println!("cargo:rerun-if-changed={path}");
    }
    let git_files = ["HEAD", "index", "packed-refs"].into_iter().map(str::to_owned);
    let branch = git(&["symbolic-ref", "-q", "HEAD"]);
    for name in git_files.chain(branch) {
        if let Some(path) = git(&["rev-parse", "--git-path", &name]).filter(|p| Path::new(p).exists()) {
            println!("cargo:rerun-if-changed={path}");
        }
    }
    let revision = checkout_revision().unwrap_or_else(|| "unknown".to_owned());
    println!("cargo:rustc-env=CLIPBENCH_BUILD_REVISION={revision}");
}
