//! DejaVu Sans for the tests, or a clear message saying how to get it.

use std::path::Path;

use clip_text::{DEJAVU_SANS, OutlineFont};

/// DejaVu Sans from Debian's `fonts-dejavu-core` (`.ci/run` installs it when missing).
pub fn dejavu() -> OutlineFont {
    let path = Path::new(DEJAVU_SANS);
    OutlineFont::from_file(path).unwrap_or_else(|e| {
        panic!("the text tests need DejaVu Sans at {DEJAVU_SANS} (Debian package fonts-dejavu-core: apt-get install fonts-dejavu-core): {e}")
    })
}
