//! Which git revision measured the results in a folder: every `.meta.json` sidecar names one, and
//! REPORT.md states it once at the top, or says plainly which file came from which revision.

use std::collections::BTreeMap;
use std::path::Path;

use crate::cli_error::CliError;
use crate::measure::provenance::Provenance;

/// The sidecars' file name ending.
const SIDECAR: &str = ".meta.json";

/// The git revision each sidecar directly in `folder` names, by file name.
pub fn of_folder(folder: &Path) -> Result<BTreeMap<String, String>, CliError> {
    let unreadable = |e: std::io::Error| CliError::failed(format!("{}: cannot list it ({e})", folder.display()));
    let mut revisions = BTreeMap::new();
    for entry in std::fs::read_dir(folder).map_err(unreadable)? {
        let path = entry.map_err(unreadable)?.path();
        let Some(name) = path.file_name().and_then(|n| n.to_str()) else { continue };
        if name.ends_with(SIDECAR) && path.is_file() {
            revisions.insert(name.to_owned(), Provenance::read(&path)?.git_revision);
        }
    }
    Ok(revisions)
}

/// REPORT.md's statement of the revision: the one revision when every sidecar names the same,
/// otherwise which sidecar names which; `None` when there is no sidecar.
pub fn statement(revisions: &BTreeMap<String, String>) -> Option<String> {
    let mut distinct: Vec<&str> = revisions.values().map(String::as_str).collect();
    distinct.sort_unstable();
    distinct.dedup();
    match distinct.as_slice() {
        [] => None,
        [one] => Some(format!(
            "Every result here was measured at git revision `{one}` (all {} `{SIDECAR}` sidecars name it){}.\n\n",
            revisions.len(),
            if one.ends_with("+dirty") {
                "; `+dirty`: the code had uncommitted changes, so no commit holds exactly what was measured"
            } else {
                ""
            }
        )),
        several => {
            let mut text = format!(
                "**The results here come from {} different git revisions**, so they were not all measured by the \
                 same code. Each sidecar's revision:\n\n| Sidecar | Git revision |\n| --- | --- |\n",
                several.len()
            );
            for (file, revision) in revisions {
                text.push_str(&format!("| `{file}` | `{revision}` |\n"));
            }
            text.push('\n');
            Some(text)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::write::write_file;

    fn folder_with(name: &str, sidecars: &[(&str, &str)]) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("clipbench-revisions-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        for (file, revision) in sidecars {
            let provenance =
                Provenance { git_revision: (*revision).to_owned(), ..Provenance::now("test", 1, 0.into()) };
            provenance.write(&dir.join(file)).unwrap();
        }
        // Not a sidecar: ignored.
        write_file(&dir.join("bench.csv"), "workload\n").unwrap();
        dir
    }

    #[test]
    fn one_revision_is_stated_once() {
        let dir = folder_with("one", &[("bench.meta.json", "abc123"), ("verify.meta.json", "abc123")]);
        let revisions = of_folder(&dir).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        assert_eq!(revisions.len(), 2);
        let text = statement(&revisions).unwrap();
        assert_eq!(text.matches("abc123").count(), 1, "{text}");
        assert!(text.starts_with("Every result here was measured at git revision `abc123` (all 2 "), "{text}");
        assert!(statement(&BTreeMap::new()).is_none());
    }

    #[test]
    fn several_revisions_are_listed_file_by_file() {
        let dir = folder_with(
            "several",
            &[("bench.meta.json", "abc123"), ("verify.meta.json", "abc123"), ("vatti-table3.meta.json", "def456")],
        );
        let text = statement(&of_folder(&dir).unwrap()).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        assert!(text.starts_with("**The results here come from 2 different git revisions**"), "{text}");
        assert!(text.contains("| `bench.meta.json` | `abc123` |"), "{text}");
        assert!(text.contains("| `vatti-table3.meta.json` | `def456` |"), "{text}");
        assert!(text.contains("| `verify.meta.json` | `abc123` |"), "{text}");
    }

    #[test]
    fn a_broken_sidecar_is_named() {
        let dir = folder_with("broken", &[]);
        write_file(&dir.join("bench.meta.json"), "{ not json").unwrap();
        let err = of_folder(&dir).unwrap_err();
        std::fs::remove_dir_all(&dir).unwrap();
        assert!(err.message.contains("bench.meta.json: not a result sidecar"), "{}", err.message);
    }
}
