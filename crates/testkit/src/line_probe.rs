//! Hand-checked probes for line clippers: windows and segments from coordinates, one segment's
//! visible intervals, and the named singular cases (Wang et al.'s and any line clipper's).
//!
//! Every algorithm crate runs [`singular_cases`] through its clippers with [`check_singular_case`],
//! which compares the clipper, the hand-computed intervals and [`visible_intervals`] with each
//! other, for both window orientations and both segment directions.

use clip_core::{ClipError, LineClipper, Point, Polygons, Ring, Segment};
use clip_oracle::line::{LINE_T_TOLERANCE, check_line_batch, pieces_to_intervals, visible_intervals};

/// The parameter tolerance of the hand-computed cases: their answers are exact fractions.
pub const PROBE_T_TOLERANCE: f64 = 1e-12;

/// A ring from coordinate pairs.
pub fn ring(points: &[(f64, f64)]) -> Ring {
    Ring::from(points)
}

/// A window of one ring.
pub fn window(points: &[(f64, f64)]) -> Polygons {
    Polygons::from(ring(points))
}

/// The same window with every ring walked the other way.
pub fn reversed(w: &Polygons) -> Polygons {
    Polygons::new(w.rings.iter().map(Ring::reversed).collect())
}

/// A segment from coordinates.
pub fn seg(ax: f64, ay: f64, bx: f64, by: f64) -> Segment {
    Segment::new(Point::new(ax, ay), Point::new(bx, by))
}

/// Clips one segment and returns its visible parameter intervals, panicking if the clipper
/// rejects the window or the segment, or returns a piece reversed or empty.
pub fn clip(clipper: &dyn LineClipper, w: &Polygons, s: Segment) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    clipper.prepare(w).expect("window accepted").clip_batch(&[s], &mut out).expect("finite segment");
    let intervals = pieces_to_intervals(&w.bounds(), &[s], &out).pop().unwrap_or_default();
    for (piece, &(ta, tb)) in out.iter().zip(&intervals) {
        assert!(ta < tb, "{}: piece {piece:?} of {s:?} is reversed or empty", clipper.name());
    }
    intervals
}

/// Asserts two interval lists are equal within `tol`.
pub fn assert_intervals(got: &[(f64, f64)], expected: &[(f64, f64)], tol: f64, what: &str) {
    let close = got.len() == expected.len()
        && got.iter().zip(expected).all(|(g, e)| (g.0 - e.0).abs() <= tol && (g.1 - e.1).abs() <= tol);
    assert!(close, "{what}: got {got:?}, expected {expected:?}");
}

/// Clips the batch with `clipper` and panics, naming `what`, the clipper, the window and the
/// segments, unless [`check_line_batch`] accepts the pieces within [`LINE_T_TOLERANCE`].
pub fn assert_batch_matches_oracle(clipper: &dyn LineClipper, w: &Polygons, segments: &[Segment], what: &str) {
    let mut out = Vec::new();
    clipper.prepare(w).expect("window accepted").clip_batch(segments, &mut out).expect("finite segments");
    if let Err(failure) = check_line_batch(w, segments, &out, LINE_T_TOLERANCE) {
        panic!("{what}, {}: {failure} in {w:?} with {segments:?}", clipper.name());
    }
}

/// What a singular case exercises; the crates' tests run one kind per test.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SingularKind {
    /// Crossing the interior (horizontal, vertical, wholly inside).
    CrossingInterior,
    /// Through a convex vertex of the window.
    ConvexVertex,
    /// Through a concave vertex of the window (Wang et al.'s Eq. 5).
    ConcaveVertex,
    /// Along an edge (Wang et al.'s Fig. 7a-c).
    AlongEdge,
    /// An endpoint on an edge or a vertex.
    EndpointOnBoundary,
    /// Inside the window's bounding box (the paper's MEB) but outside the window: segment e.
    InsideBoxOutsideWindow,
    /// Outside the bounding box.
    OutsideBox,
    /// A convex window with collinear vertices in the middle of its edges.
    CollinearVertices,
    /// A window of several rings read under even-odd.
    SeveralRings,
}

impl SingularKind {
    /// Every kind, in the order [`singular_cases`] lists them.
    pub const ALL: [SingularKind; 9] = [
        SingularKind::CrossingInterior,
        SingularKind::ConvexVertex,
        SingularKind::ConcaveVertex,
        SingularKind::AlongEdge,
        SingularKind::EndpointOnBoundary,
        SingularKind::InsideBoxOutsideWindow,
        SingularKind::OutsideBox,
        SingularKind::CollinearVertices,
        SingularKind::SeveralRings,
    ];
}

/// One named singular case: a window, a segment, and its visible intervals computed by hand.
#[derive(Clone, Debug)]
pub struct SingularCase {
    /// What it exercises.
    pub kind: SingularKind,
    /// What the segment does (through a concave vertex, along an edge, ...).
    pub name: &'static str,
    /// The window, read under even-odd.
    pub window: Polygons,
    /// The segment.
    pub segment: Segment,
    /// Its visible parameter intervals, sorted.
    pub expected: Vec<(f64, f64)>,
}

const SQUARE: &[(f64, f64)] = &[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)];
/// A U: two arms x in [0,1] and [2,3], joined by the bottom y in [0,1]; the notch between the arms.
const U: &[(f64, f64)] =
    &[(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (2.0, 3.0), (2.0, 1.0), (1.0, 1.0), (1.0, 3.0), (0.0, 3.0)];
/// An L: a step at (2,2) where the edge (4,2)-(2,2) joins a convex and a concave vertex.
const L: &[(f64, f64)] = &[(0.0, 0.0), (4.0, 0.0), (4.0, 2.0), (2.0, 2.0), (2.0, 4.0), (0.0, 4.0)];
/// The square with extra vertices in the middle of three edges (convex, collinear vertices).
const SQUARE_WITH_MIDPOINTS: &[(f64, f64)] =
    &[(0.0, 0.0), (2.0, 0.0), (4.0, 0.0), (4.0, 4.0), (2.0, 4.0), (0.0, 4.0), (0.0, 2.0)];

/// An axis-aligned square ring of side `s` with its lower-left corner at `(x, y)`.
fn square(x: f64, y: f64, s: f64) -> Ring {
    ring(&[(x, y), (x + s, y), (x + s, y + s), (x, y + s)])
}

/// A case before its kind is given: name, window, segment, expected intervals.
type Untagged = (&'static str, Polygons, Segment, Vec<(f64, f64)>);

/// A one-ring case from coordinates.
fn on(name: &'static str, points: &[(f64, f64)], segment: Segment, expected: &[(f64, f64)]) -> Untagged {
    (name, window(points), segment, expected.to_vec())
}

/// The singular cases every line clipper must get right, with hand-computed intervals: through
/// convex and concave vertices, along edges (Wang et al.'s Fig. 7a-c), endpoints on edges and
/// vertices, the paper's segment e inside the MEB but outside the window, boxes' rejections,
/// collinear window vertices, and several rings under even-odd. Horizontal, vertical and
/// diagonal segments; [`check_singular_case`] adds both orientations and directions.
pub fn singular_cases() -> Vec<SingularCase> {
    let (sixth, twelfth) = (1.0 / 6.0, 1.0 / 12.0);
    let mut cases = Vec::new();
    let mut add = |kind, group: Vec<Untagged>| {
        cases.extend(group.into_iter().map(|(name, window, segment, expected)| SingularCase {
            kind,
            name,
            window,
            segment,
            expected,
        }));
    };
    add(
        SingularKind::CrossingInterior,
        vec![
            on("horizontal through", SQUARE, seg(-1.0, 2.0, 5.0, 2.0), &[(sixth, 5.0 * sixth)]),
            on("vertical through", SQUARE, seg(2.0, -1.0, 2.0, 5.0), &[(sixth, 5.0 * sixth)]),
            on("inside", SQUARE, seg(1.0, 1.0, 3.0, 2.0), &[(0.0, 1.0)]),
        ],
    );
    add(
        SingularKind::ConvexVertex,
        vec![
            on("touching the corner from outside", SQUARE, seg(2.0, 6.0, 6.0, 2.0), &[]),
            on("diagonal through two corners", SQUARE, seg(-2.0, -2.0, 6.0, 6.0), &[(0.25, 0.75)]),
            // The U's top-left corner (0,3) entering, the concave (2,1) crossing (Eq. 4), (3,0) leaving.
            on("corner, concave vertex, corner", U, seg(-1.0, 4.0, 4.0, -1.0), &[(0.2, 0.4), (0.6, 0.8)]),
        ],
    );
    add(
        SingularKind::ConcaveVertex,
        vec![
            // Through (1,1) with both neighbours above the line (Eq. 5): inside on both sides, one piece.
            on("touching a concave vertex from inside", U, seg(-1.0, 3.0, 3.0, -1.0), &[(0.25, 0.75)]),
            // The L's step (2,2): neighbours (4,2) and (2,4).
            on("through the step's concave vertex", L, seg(0.0, 4.0, 4.0, 0.0), &[(0.0, 1.0)]),
        ],
    );
    add(
        SingularKind::AlongEdge,
        vec![
            on("along the bottom, beyond both ends", SQUARE, seg(-1.0, 0.0, 5.0, 0.0), &[(sixth, 5.0 * sixth)]),
            on("along the bottom from its middle", SQUARE, seg(2.0, 0.0, 6.0, 0.0), &[(0.0, 0.5)]),
            on("inside the top edge", SQUARE, seg(1.0, 4.0, 3.0, 4.0), &[(0.0, 1.0)]),
            // The notch's bottom between two concave vertices: inside, boundary, inside: one piece (Fig. 7c).
            on("along the notch bottom", U, seg(-1.0, 1.0, 4.0, 1.0), &[(0.2, 0.8)]),
            // The arms' tops, both ends convex (Fig. 7a): two pieces, the notch opening between them.
            on("along the arms' tops", U, seg(-1.0, 3.0, 4.0, 3.0), &[(0.2, 0.4), (0.6, 0.8)]),
            // The step of the L, one convex and one concave end (Fig. 7b).
            on("along the step", L, seg(-1.0, 2.0, 5.0, 2.0), &[(sixth, 5.0 * sixth)]),
            on("along the step from its middle, leaving", L, seg(3.0, 2.0, 5.0, 2.0), &[(0.0, 0.5)]),
        ],
    );
    add(
        SingularKind::EndpointOnBoundary,
        vec![
            on("start on an edge, going in", SQUARE, seg(0.0, 2.0, 2.0, 2.0), &[(0.0, 1.0)]),
            on("start on an edge, going out", SQUARE, seg(0.0, 2.0, -2.0, 2.0), &[]),
            on("end on an edge", SQUARE, seg(2.0, 2.0, 4.0, 2.0), &[(0.0, 1.0)]),
            on("start on a vertex, going in", SQUARE, seg(0.0, 0.0, 2.0, 2.0), &[(0.0, 1.0)]),
            on("start on a vertex, going out", SQUARE, seg(0.0, 0.0, -1.0, 2.0), &[]),
            on("vertex to vertex through the interior", SQUARE, seg(4.0, 4.0, 0.0, 0.0), &[(0.0, 1.0)]),
            on("across the notch, edge to edge", U, seg(1.0, 2.0, 2.0, 2.0), &[]),
            on("from a concave vertex into the notch", U, seg(1.0, 1.0, 2.0, 2.0), &[]),
        ],
    );
    add(
        SingularKind::InsideBoxOutsideWindow,
        vec![
            // The paper's segment e: within the MEB, in the notch.
            on("in the notch (segment e)", U, seg(1.2, 2.0, 1.8, 2.5), &[]),
            on("vertical in the notch, leaving the box", U, seg(1.5, 1.5, 1.5, 4.0), &[]),
        ],
    );
    add(
        SingularKind::OutsideBox,
        vec![
            on("right of the box", SQUARE, seg(5.0, 5.0, 6.0, 1.0), &[]),
            on("below the box", SQUARE, seg(-3.0, -1.0, 9.0, -0.5), &[]),
            on("across the corner of the box", SQUARE, seg(3.0, 6.0, 6.0, 3.0), &[]),
        ],
    );
    // Extra vertices in the middle of edges do not change anything.
    let w = SQUARE_WITH_MIDPOINTS;
    add(
        SingularKind::CollinearVertices,
        vec![
            on("along an edge with a middle vertex", w, seg(-1.0, 0.0, 5.0, 0.0), &[(sixth, 5.0 * sixth)]),
            on("in at (0,1), out through the middle vertex (2,0)", w, seg(-2.0, 2.0, 6.0, -2.0), &[(0.25, 0.5)]),
            on("from the middle vertex (2,0) outwards", w, seg(2.0, 0.0, 2.0, -3.0), &[]),
            on("through the middle vertex (0,2)", w, seg(-2.0, 2.0, 6.0, 2.0), &[(0.25, 0.75)]),
        ],
    );
    let holed = Polygons::new(vec![square(0.0, 0.0, 10.0), square(3.0, 3.0, 4.0)]);
    // Two squares sharing an edge: the shared edge is boundary, so the pieces merge.
    let sharing = Polygons::new(vec![square(0.0, 0.0, 2.0), square(2.0, 0.0, 2.0)]);
    // Two copies cancel under even-odd, but their edges stay boundary.
    let twice = Polygons::new(vec![square(0.0, 0.0, 2.0), square(0.0, 0.0, 2.0)]);
    let mut rings = vec![
        (
            "apart",
            Polygons::new(vec![square(0.0, 0.0, 2.0), square(4.0, 0.0, 2.0)]),
            seg(-1.0, 1.0, 7.0, 1.0),
            vec![(0.125, 0.375), (0.625, 0.875)],
        ),
        ("sharing an edge", sharing, seg(-1.0, 1.0, 5.0, 1.0), vec![(sixth, 5.0 * sixth)]),
        ("cancelled", twice.clone(), seg(-1.0, 1.0, 3.0, 1.0), vec![]),
        ("cancelled, along an edge", twice, seg(-1.0, 0.0, 3.0, 0.0), vec![(0.25, 0.75)]),
    ];
    // A square with a square hole, its rings walked opposite ways and the same way.
    let holed_same_way = Polygons::new(vec![holed.rings[0].clone(), holed.rings[1].reversed()]);
    for w in [holed, holed_same_way] {
        rings.extend([
            (
                "holed square, across the hole",
                w.clone(),
                seg(-1.0, 5.0, 11.0, 5.0),
                vec![(twelfth, 4.0 * twelfth), (8.0 * twelfth, 11.0 * twelfth)],
            ),
            (
                "holed square, along the hole's edge",
                w.clone(),
                seg(-1.0, 3.0, 11.0, 3.0),
                vec![(twelfth, 11.0 * twelfth)],
            ),
            ("holed square, inside the hole", w.clone(), seg(4.0, 4.0, 6.0, 6.0), vec![]),
            ("holed square, between the rings", w, seg(7.0, 5.0, 8.0, 5.0), vec![(0.0, 1.0)]),
        ]);
    }
    add(SingularKind::SeveralRings, rings);
    cases
}

/// The cases of one kind.
pub fn singular_cases_of(kind: SingularKind) -> Vec<SingularCase> {
    singular_cases().into_iter().filter(|c| c.kind == kind).collect()
}

/// Checks `clipper` on `case`: the window as given and with its rings reversed, the segment and
/// the segment reversed (whose intervals are the expected ones mirrored). Each answer must equal
/// both the hand-computed intervals and [`visible_intervals`] within [`PROBE_T_TOLERANCE`].
/// Panics with the case's name, the clipper and the orientation on a mismatch.
pub fn check_singular_case(clipper: &dyn LineClipper, case: &SingularCase) {
    let mirrored: Vec<(f64, f64)> = case.expected.iter().rev().map(|&(a, b)| (1.0 - b, 1.0 - a)).collect();
    for win in [case.window.clone(), reversed(&case.window)] {
        let orientation = if win.rings[0].signed_area() > 0.0 { "ccw" } else { "cw" };
        for (s, expected, direction) in
            [(case.segment, &case.expected, ""), (case.segment.reversed(), &mirrored, ", reversed")]
        {
            let tag = format!("{} ({}, first ring {orientation}{direction})", case.name, clipper.name());
            assert_intervals(&visible_intervals(&win, s), expected, PROBE_T_TOLERANCE, &format!("{tag}, oracle"));
            assert_intervals(&clip(clipper, &win, s), expected, PROBE_T_TOLERANCE, &tag);
        }
    }
}

/// Runs every case of `kind` through each of `clippers` whose capabilities take its window,
/// with [`check_singular_case`]. Panics if no clipper takes a case's window.
pub fn check_singular_kind(kind: SingularKind, clippers: &[&dyn LineClipper]) {
    for case in singular_cases_of(kind) {
        let takers: Vec<_> = clippers.iter().filter(|c| c.capabilities().window.accepts(&case.window)).collect();
        assert!(!takers.is_empty(), "{}: no clipper takes the window {:?}", case.name, case.window);
        for c in takers {
            check_singular_case(*c, &case);
        }
    }
}

/// Defines, in the calling test file, one `#[test]` per
/// [`SingularKind`](crate::line_probe::SingularKind), each running
/// [`check_singular_kind`](crate::line_probe::check_singular_kind) with the given clippers
/// (`&dyn LineClipper`s): `clip_testkit::singular_case_tests!(&Liu, &CyrusBeck);` at the top
/// level of a test file.
#[macro_export]
macro_rules! singular_case_tests {
    ($($clipper:expr),+ $(,)?) => {
        $crate::singular_case_tests!(@each [$($clipper),+]
            crossing_the_interior CrossingInterior,
            through_a_convex_vertex ConvexVertex,
            through_a_concave_vertex ConcaveVertex,
            along_an_edge AlongEdge,
            endpoints_on_the_boundary EndpointOnBoundary,
            inside_the_box_but_outside_the_window InsideBoxOutsideWindow,
            rejected_by_the_bounding_box OutsideBox,
            a_convex_window_with_collinear_vertices CollinearVertices,
            several_rings_under_even_odd SeveralRings,
        );
        #[test]
        fn segments_reaching_far_past_the_window() {
            $crate::line_probe::check_far_segments_of(&[$($clipper),+]);
        }
    };
    (@each $clippers:tt $($test:ident $kind:ident,)+) => {
        $(
            #[test]
            fn $test() {
                $crate::line_probe::check_singular_kind($crate::line_probe::SingularKind::$kind, &$clippers);
            }
        )+
    };
}

/// A segment reaching far past a small window, and its visible pieces as points.
pub struct FarCase {
    /// What it exercises.
    pub name: &'static str,
    /// The window, read under even-odd.
    pub window: Polygons,
    /// The segment.
    pub segment: Segment,
    /// Its visible pieces, in order along the segment.
    pub pieces: Vec<(Point, Point)>,
}

/// Segments whose ends lie far beyond a window 10 wide (at ±1e150, the largest coordinates
/// accepted, at ±1e17 and at ±2^60), through it, along its edge, from inside it and past it. A
/// parameter along the whole segment cannot tell the window's sides apart (at ±1e17 the window
/// is 5e-17 of the segment, less than an ulp of t = 0.5), which made every line clipper here
/// answer nothing for the first (issue 28); the pieces are exact here, as points.
pub fn far_cases() -> Vec<FarCase> {
    let p = Point::new;
    let square = window(&[(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]);
    // The U of the singular cases, scaled to 10 wide: arms x in [0,10/3] and [20/3,10].
    let u = Polygons::from(Ring::new(U.iter().map(|&(x, y)| p(x * 10.0 / 3.0, y * 10.0 / 3.0)).collect()));
    let (third, two_thirds) = (10.0 / 3.0, 20.0 / 3.0);
    let far = 2f64.powi(60);
    let case = |name, window: &Polygons, segment, pieces| FarCase { name, window: window.clone(), segment, pieces };
    vec![
        case("horizontal, ends at ±1e150", &square, seg(-1e150, 2.0, 1e150, 2.0), vec![(p(0.0, 2.0), p(10.0, 2.0))]),
        case("horizontal, ends at ±1e17", &square, seg(-1e17, 2.0, 1e17, 2.0), vec![(p(0.0, 2.0), p(10.0, 2.0))]),
        case("vertical, ends at ±1e150", &square, seg(7.0, 1e150, 7.0, -1e150), vec![(p(7.0, 10.0), p(7.0, 0.0))]),
        case(
            "diagonal through two corners, ends at ±1e150",
            &square,
            seg(-1e150, -1e150, 1e150, 1e150),
            vec![(p(0.0, 0.0), p(10.0, 10.0))],
        ),
        case(
            "slope 1/2, ends at ±2^60",
            &square,
            seg(-far, -far / 2.0, far, far / 2.0),
            vec![(p(0.0, 0.0), p(10.0, 5.0))],
        ),
        case("along an edge, ends at ±1e150", &square, seg(-1e150, 0.0, 1e150, 0.0), vec![(p(0.0, 0.0), p(10.0, 0.0))]),
        case("from inside to 1e150", &square, seg(5.0, 5.0, 1e150, 5.0), vec![(p(5.0, 5.0), p(10.0, 5.0))]),
        case("passing the window at 1e150", &square, seg(-1e150, 20.0, 1e150, 20.0), vec![]),
        case(
            "through both arms of a U, ends at ±1e150",
            &u,
            seg(-1e150, 8.0, 1e150, 8.0),
            vec![(p(0.0, 8.0), p(third, 8.0)), (p(two_thirds, 8.0), p(10.0, 8.0))],
        ),
    ]
}

/// Checks `clipper` on every [`far_cases`] case whose window it takes, both window orientations
/// and both segment directions: its pieces must be the expected ones within 1e-9 of the window's
/// size, and [`check_line_batch`] must accept them and refuse no answer at all where there are
/// pieces. Panics naming the case otherwise.
pub fn check_far_segments(clipper: &dyn LineClipper) {
    for case in far_cases().into_iter().filter(|c| clipper.capabilities().window.accepts(&c.window)) {
        let tol = 1e-9 * case.window.bounds().extent();
        for win in [case.window.clone(), reversed(&case.window)] {
            for (s, backwards) in [(case.segment, false), (case.segment.reversed(), true)] {
                let tag = format!("{} ({}{})", case.name, clipper.name(), if backwards { ", reversed" } else { "" });
                let mut out = Vec::new();
                clipper.prepare(&win).expect("window accepted").clip_batch(&[s], &mut out).expect("finite segment");
                let mut expected = case.pieces.clone();
                if backwards {
                    expected = expected.into_iter().rev().map(|(a, b)| (b, a)).collect();
                }
                let close = |a: Point, b: Point| (a.x - b.x).abs() <= tol && (a.y - b.y).abs() <= tol;
                let same = out.len() == expected.len()
                    && out.iter().zip(&expected).all(|(got, &(a, b))| close(got.piece.a, a) && close(got.piece.b, b));
                assert!(
                    same,
                    "{tag}: got {:?}, expected {expected:?}",
                    out.iter().map(|p| p.piece).collect::<Vec<_>>()
                );
                if let Err(failure) = check_line_batch(&win, &[s], &out, LINE_T_TOLERANCE) {
                    panic!("{tag}: the oracle refuses the right pieces: {failure}");
                }
                if !expected.is_empty() {
                    assert!(
                        check_line_batch(&win, &[s], &[], LINE_T_TOLERANCE).is_err(),
                        "{tag}: the oracle takes no answer"
                    );
                }
            }
        }
    }
}

/// [`check_far_segments`] for each of `clippers`.
pub fn check_far_segments_of(clippers: &[&dyn LineClipper]) {
    for c in clippers {
        check_far_segments(*c);
    }
}

/// Checks that `clipper` turns bad input into an error or nothing: a non-finite segment fails
/// the whole batch with [`ClipError::NonFinite`] naming it and writes nothing, zero-length
/// segments show nothing, and empty, collinear or non-finite windows are rejected.
pub fn check_bad_input(clipper: &dyn LineClipper) {
    let name = clipper.name();
    let prepared = clipper.prepare(&window(SQUARE)).expect("the square accepted");
    let mut out = Vec::new();
    let nan = seg(0.0, f64::NAN, 1.0, 1.0);
    let err = prepared.clip_batch(&[seg(1.0, 1.0, 2.0, 2.0), nan], &mut out).unwrap_err();
    assert!(matches!(err, ClipError::NonFinite { part: 1, .. }), "{name}: {err:?}");
    assert!(out.is_empty(), "{name}: nothing written before the error");
    prepared.clip_batch(&[seg(2.0, 2.0, 2.0, 2.0), seg(9.0, 9.0, 9.0, 9.0)], &mut out).unwrap();
    assert!(out.is_empty(), "{name}: zero-length segments show nothing");
    let inf = seg(f64::INFINITY, 0.0, 1.0, 1.0);
    assert!(prepared.clip_batch(&[inf], &mut out).is_err(), "{name}: infinite segment accepted");
    for bad in [
        Polygons::empty(),
        window(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)]),
        window(&[(0.0, 0.0), (1.0, f64::NAN), (2.0, 0.0)]),
    ] {
        assert!(clipper.prepare(&bad).is_err(), "{name}: degenerate window {bad:?} accepted");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The oracle judges the far segments: their exact pieces pass, and no answer fails (issue 28).
    #[test]
    fn the_oracle_judges_segments_reaching_far_past_the_window() {
        for c in far_cases() {
            let pieces: Vec<clip_core::VisiblePiece> = c
                .pieces
                .iter()
                .map(|&(a, b)| clip_core::VisiblePiece { segment: 0, piece: Segment::new(a, b) })
                .collect();
            assert_eq!(check_line_batch(&c.window, &[c.segment], &pieces, LINE_T_TOLERANCE), Ok(()), "{}", c.name);
            if !pieces.is_empty() {
                assert!(check_line_batch(&c.window, &[c.segment], &[], LINE_T_TOLERANCE).is_err(), "{}", c.name);
                let mut short = pieces.clone();
                short[0].piece.b = Point::new(
                    (short[0].piece.a.x + short[0].piece.b.x) / 2.0,
                    (short[0].piece.a.y + short[0].piece.b.y) / 2.0,
                );
                assert!(
                    check_line_batch(&c.window, &[c.segment], &short, LINE_T_TOLERANCE).is_err(),
                    "{}: half a piece",
                    c.name
                );
            }
        }
    }

    #[test]
    fn every_case_agrees_with_the_oracle() {
        let cases = singular_cases();
        assert!(cases.len() >= 40);
        for kind in SingularKind::ALL {
            assert!(cases.iter().any(|c| c.kind == kind), "no {kind:?} case");
        }
        for c in &cases {
            for win in [c.window.clone(), reversed(&c.window)] {
                assert_intervals(&visible_intervals(&win, c.segment), &c.expected, PROBE_T_TOLERANCE, c.name);
            }
        }
    }
}
