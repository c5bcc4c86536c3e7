//! The singular cases of Wang et al., from clip-testkit's fixture list, on New1 and New2 (and, as
//! a cross-check, Liu and, where the window is convex, Cyrus-Beck): each answer against the
//! hand-computed intervals and the exact oracle, both window orientations and both segment
//! directions.

use clip_cyrus_beck::{CyrusBeck, Liu};
use clip_testkit::line_probe::check_bad_input;
use clip_virtual_box::VirtualBox;

clip_testkit::singular_case_tests!(&VirtualBox::NEW2, &VirtualBox::NEW1, &Liu, &CyrusBeck);

#[test]
fn bad_input_is_an_error_or_nothing() {
    check_bad_input(&VirtualBox::NEW2);
    check_bad_input(&VirtualBox::NEW1);
}
