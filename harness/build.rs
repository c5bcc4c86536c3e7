//! Stamps the binary with the git revision it is built from, so result files name the code that
//! measured them even when the checkout has moved on by the time a long run writes them.

use std::path::Path;
use std::process::Command;

fn git(args: &[&str]) -> Option<String> {
    Command::new("git")
        .args(args)
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_owned())
        .filter(|s| !s.is_empty())
}

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
    let revision = match git(&["rev-parse", "HEAD"]) {
        Some(rev) => {
            // Dirty means the code differs from the commit; result files being rewritten do not count.
            let code = ["status", "--porcelain", "--untracked-files=no", "--", "*.rs", "*.toml", "Cargo.lock", "*.sh"];
            if git(&code).is_some() { format!("{rev}+dirty") } else { rev }
        }
        None => "unknown".to_owned(),
    };
    println!("cargo:rustc-env=CLIPBENCH_BUILD_REVISION={revision}");
}
