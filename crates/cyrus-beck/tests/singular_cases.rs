//! The singular cases of Wang et al. (and of any line clipper), from clip-testkit's fixture list,
//! on Liu and, where the window is convex, Cyrus-Beck: each answer against the hand-computed
//! intervals and the exact oracle, both window orientations and both segment directions.

use clip_core::{ClipError, LineClipper, WindowKind};
use clip_cyrus_beck::{CyrusBeck, Liu};
use clip_testkit::line_probe::{check_bad_input, singular_cases};

clip_testkit::singular_case_tests!(&Liu, &CyrusBeck);

#[test]
fn bad_input_is_an_error_or_nothing() {
    check_bad_input(&Liu);
    check_bad_input(&CyrusBeck);
}

#[test]
fn cyrus_beck_rejects_every_window_but_one_convex_ring() {
    let mut rejected = 0;
    for case in singular_cases() {
        if !WindowKind::Convex.accepts(&case.window) {
            let result = CyrusBeck.prepare(&case.window);
            assert!(matches!(result, Err(ClipError::WindowNotConvex { .. })), "{}: {}", case.name, result.is_ok());
            rejected += 1;
        }
    }
    // The U, the L and every window of several rings.
    assert!(rejected >= 20, "only {rejected} non-convex windows among the cases");
}
