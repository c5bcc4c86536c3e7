//! The output folder: created and proven writable before any measuring starts.

use std::path::{Path, PathBuf};

use crate::cli_error::CliError;

/// Creates `dir` if needed and writes and removes a probe file in it, so an unwritable folder is
/// a usage error before minutes of measuring, not after.
pub fn ready_out_dir(dir: &Path) -> Result<PathBuf, CliError> {
    let unwritable = |e: std::io::Error| {
        CliError::usage(format!("output folder {} is not writable ({e}); choose another with --out", dir.display()))
    };
    std::fs::create_dir_all(dir).map_err(unwritable)?;
    let probe = dir.join(".clipbench-write-probe");
    std::fs::write(&probe, b"probe").map_err(unwritable)?;
    std::fs::remove_file(&probe).map_err(unwritable)?;
    Ok(dir.to_owned())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_in_the_way_is_a_usage_error() {
        let dir = std::env::temp_dir().join(format!("clipbench-out-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("not-a-folder");
        std::fs::write(&file, b"x").unwrap();
        let err = ready_out_dir(&file.join("results")).unwrap_err();
        assert_eq!(err.code, 2);
        assert!(err.message.contains("not writable"), "{}", err.message);
        assert!(ready_out_dir(&dir.join("fresh")).is_ok());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
