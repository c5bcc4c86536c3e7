//! The singular cases of Wang et al., from clip-testkit's fixture list, on New1 and New2 (and, as
//! a cross-check, Liu and, where the window is convex, Cyrus-Beck): each answer against the
//! hand-computed intervals and the exact oracle, both window orientations and both segment
//! directions.

use clip_core::LineClipper;
use clip_cyrus_beck::{CyrusBeck, Liu};
use clip_testkit::line_probe::{SingularKind, check_bad_input, check_singular_case, singular_cases_of};
use clip_virtual_box::VirtualBox;

/// Runs every case of `kind` through each clipper whose capabilities take its window.
fn check(kind: SingularKind) {
    let clippers: [&dyn LineClipper; 4] = [&VirtualBox::NEW2, &VirtualBox::NEW1, &Liu, &CyrusBeck];
    for case in singular_cases_of(kind) {
        for c in clippers {
            if c.capabilities().window.accepts(&case.window) {
                check_singular_case(c, &case);
            }
        }
    }
}

#[test]
fn crossing_the_interior() {
    check(SingularKind::CrossingInterior);
}

#[test]
fn through_a_convex_vertex() {
    check(SingularKind::ConvexVertex);
}

#[test]
fn through_a_concave_vertex() {
    check(SingularKind::ConcaveVertex);
}

#[test]
fn along_an_edge() {
    check(SingularKind::AlongEdge);
}

#[test]
fn endpoints_on_the_boundary() {
    check(SingularKind::EndpointOnBoundary);
}

#[test]
fn inside_the_box_but_outside_the_window() {
    check(SingularKind::InsideBoxOutsideWindow);
}

#[test]
fn rejected_by_the_bounding_box() {
    check(SingularKind::OutsideBox);
}

#[test]
fn several_rings_under_even_odd() {
    check(SingularKind::SeveralRings);
}

#[test]
fn a_convex_window_with_collinear_vertices() {
    check(SingularKind::CollinearVertices);
}

#[test]
fn bad_input_is_an_error_or_nothing() {
    check_bad_input(&VirtualBox::NEW2);
    check_bad_input(&VirtualBox::NEW1);
}
