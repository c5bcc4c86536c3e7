//! The git revision of the checkout in the working directory; shared with the build script.

use std::path::Path;
use std::process::Command;

/// `git rev-parse HEAD`, with "+dirty" when the code (not result files) differs from that
/// commit; `None` outside git.
pub fn checkout_revision() -> Option<String> {
    checkout_revision_in(Path::new("."))
}

/// [`checkout_revision`] of the checkout holding `dir`.
///
/// It leaves the git index alone (`--no-optional-locks`): `git status` otherwise writes back the
/// index whenever it refreshes the file stamps there, as it does on the first status after a
/// clone, and the build script watches the index, so a fresh clone's first build made its second
/// rebuild this crate and everything above it (`scripts/fuzz.sh` lost its minutes to that).
pub fn checkout_revision_in(dir: &Path) -> Option<String> {
    let rev = git_in(dir, &["rev-parse", "HEAD"])?;
    // Dirty means the code differs from the commit; result files being rewritten do not count.
    let code = [
        "--no-optional-locks",
        "status",
        "--porcelain",
        "--untracked-files=no",
        "--",
        "*.rs",
        "*.toml",
        "Cargo.lock",
        "*.sh",
    ];
    Some(if git_in(dir, &code).is_some() { format!("{rev}+dirty") } else { rev })
}

/// What `git args` prints, trimmed; `None` when it fails or prints nothing.
pub fn git(args: &[&str]) -> Option<String> {
    git_in(Path::new("."), args)
}

/// [`git`] run in `dir`.
fn git_in(dir: &Path, args: &[&str]) -> Option<String> {
    Command::new("git")
        .current_dir(dir)
        .args(args)
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_owned())
        .filter(|s| !s.is_empty())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::{Duration, SystemTime};

    /// A fresh clone's first build rewrote the git index (through `git status`), which the build
    /// script watches, so the next build recompiled clipbench: `scripts/fuzz.sh` on a fresh clone
    /// spent its fuzzing minutes on that (issue 28). Reading the revision writes nothing now.
    #[test]
    fn reading_the_revision_leaves_the_git_index_alone() {
        let dir = std::env::temp_dir().join(format!("clipbench-git-index-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let run = |args: &[&str]| {
            let ok = Command::new("git").current_dir(&dir).args(args).output().is_ok_and(|o| o.status.success());
            assert!(ok, "git {args:?}");
        };
        run(&["init", "-q"]);
        std::fs::write(dir.join("lib.rs"), "fn main() {}\n").unwrap();
        run(&["add", "lib.rs"]);
        run(&["-c", "user.name=t", "-c", "user.email=t@t", "commit", "-q", "-m", "one"]);
        // A file whose stamp no longer matches the index (as after a clone or a touch): a plain
        // `git status` refreshes the stamp and writes the index back.
        let later = SystemTime::now() + Duration::from_secs(120);
        std::fs::File::options().write(true).open(dir.join("lib.rs")).unwrap().set_modified(later).unwrap();
        let index = dir.join(".git").join("index");
        let before = std::fs::read(&index).unwrap();
        let revision = checkout_revision_in(&dir).expect("a revision");
        assert!(!revision.ends_with("+dirty"), "{revision}");
        assert_eq!(std::fs::read(&index).unwrap(), before, "the index was written");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
