//! The named singular line cases (through vertices, along edges, ends on the boundary) on the
//! indexed clipper, with Liu beside it: hand answers and the exact oracle, both window
//! orientations and both segment directions; and bad input.

use clip_cyrus_beck::Liu;
use clip_line_index::LineIndex;
use clip_testkit::line_probe::check_bad_input;

clip_testkit::singular_case_tests!(&LineIndex, &Liu);

#[test]
fn bad_input_is_an_error_or_nothing() {
    check_bad_input(&LineIndex);
}
