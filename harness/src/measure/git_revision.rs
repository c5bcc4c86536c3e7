//! The git revision of the checkout in the working directory; shared with the build script.

use std::process::Command;

/// `git rev-parse HEAD`, with "+dirty" when the code (not result files) differs from that
/// commit; `None` outside git.
pub fn checkout_revision() -> Option<String> {
    let rev = git(&["rev-parse", "HEAD"])?;
    // Dirty means the code differs from the commit; result files being rewritten do not count.
    let code = ["status", "--porcelain", "--untracked-files=no", "--", "*.rs", "*.toml", "Cargo.lock", "*.sh"];
    Some(if git(&code).is_some() { format!("{rev}+dirty") } else { rev })
}

/// What `git args` prints, trimmed; `None` when it fails or prints nothing.
pub fn git(args: &[&str]) -> Option<String> {
    Command::new("git")
        .args(args)
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_owned())
        .filter(|s| !s.is_empty())
}
