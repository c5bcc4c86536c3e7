//! Every crash the fuzzers found, fixed, as a named test: the input file under
//! `fuzz/regressions/<target>/` must pass its target's check, and its picture (made by
//! `clip_testkit::case_record`, written beside it when `CLIP_FUZZ_BLESS=1`) must be there.
//!
//! Each test's comment says what was found and how it was fixed then. Since issue 29, vatti's
//! "repair" named in them (sweeps of the output's own union, with points a few ulps apart merged)
//! is gone: a broken output is replaced by one sweep of both operands snap rounded
//! (`clip_core::snap_round`), and these inputs hold it to the same checks.

use std::fs;

use clip_fuzz_checks::picture::picture;
use clip_fuzz_checks::{fuzz_dir, target};

fn regression(target_name: &str, name: &str) {
    let dir = fuzz_dir().join("regressions").join(target_name);
    let data = fs::read(dir.join(name)).unwrap_or_else(|e| panic!("{target_name}/{name}: {e}"));
    let check = target(target_name).expect("a registered target").check;
    assert_eq!(check(&data), Ok(()), "{target_name}/{name}");
    if let Some(svg) = picture(target_name, &data) {
        let path = dir.join(format!("{name}.svg"));
        if std::env::var_os("CLIP_FUZZ_BLESS").is_some() {
            fs::write(&path, svg).expect("writable picture");
        }
        let kept = fs::read_to_string(&path)
            .unwrap_or_else(|e| panic!("{}: {e} (CLIP_FUZZ_BLESS=1 writes it)", path.display()));
        assert!(kept.starts_with("<svg"), "{} is not an SVG picture", path.display());
    }
}

/// Vatti's clean-up took a triangle 7 × 5 units at 1e15 (an ulp is 0.125) for rounding: a
/// local minimum's exact vertex was added to the other bound's chain because it lay within 64
/// ulps of the magnitude (14 units) of that bound. Every operation lost the triangle.
#[test]
fn vatti_small_triangle_at_1e15() {
    regression("vatti", "small-triangle-at-1e15");
}

/// A segment from (8.3e-317, 0) to (0, 0): its squared length underflows to 0, so Cyrus-Beck
/// returned a piece whose parameters could not be measured. Coordinates below
/// `clip_core::MIN_COORDINATE` are now refused with `ClipError::OutOfRange`.
#[test]
fn line_clippers_subnormal_segment() {
    regression("line_clippers", "subnormal-segment");
}

/// Cyrus-Beck's piece of a segment 2.3e-6 long at 1e9 (where an ulp is 1.2e-7) ended an ulp off
/// the segment, which the line oracle called "not on segment": its tolerance of 1e-9 of the
/// segment's length was below the rounding of any f64 point there. The oracle now allows
/// `clip_oracle::line::parameter_tolerance`.
#[test]
fn line_clippers_short_segment_at_1e9() {
    regression("line_clippers", "short-segment-at-1e9");
}

/// A visible interval of 0.083 against Cyrus-Beck's 0.099, with a tolerance of 0.087: the oracle
/// dropped intervals shorter than the tolerance on each side separately, so one side's interval
/// counted and the other's did not. It now compares each side, shrunk by the tolerance, with the
/// other, grown by it.
#[test]
fn line_clippers_interval_at_the_tolerance() {
    regression("line_clippers", "interval-at-the-tolerance");
}

/// A sliver triangle whose two bounds leave its lowest vertex 1e-16 apart in slope: vatti's
/// intersection table took the rounded x of one bound at the other's top for a crossing and
/// swapped them, and the triangle came out clockwise. Near ties are now decided exactly.
#[test]
fn vatti_sliver_swapped_by_rounded_x() {
    regression("vatti", "sliver-swapped-by-rounded-x");
}

/// A self-crossing quadrilateral 18 units across at 1e15 vanished: vatti put rounded crossings
/// into the chains of every edge within 64 ulps of the magnitude (14 units). The allowance is
/// now 4 ulps.
#[test]
fn vatti_self_crossing_quad_at_1e15() {
    regression("vatti", "self-crossing-quad-at-1e15");
}

/// A self-crossing quadrilateral of area 0.008 at 1e15 (an ulp is 0.125): the result is a
/// triangle of rounded crossings that runs clockwise. The oracle now lets a ring with a computed
/// vertex and an area within the snap distance times its perimeter run either way.
#[test]
fn vatti_rounded_ring_inside_out() {
    regression("vatti", "rounded-ring-inside-out");
}

/// A thin triangle with vertices near 1e140 and at 1e15: its exact area (2e155) is far below the
/// rounding of its shoelace terms, which cancel to 0, and the oracle called the (correct) output
/// clockwise. The oracle now takes a ring's turn exactly at its lowest vertex.
#[test]
fn vatti_thin_triangle_at_1e140() {
    regression("vatti", "thin-triangle-at-1e140");
}

/// Edges near 1e-90 whose crossing rounds to -1.5e-105, below `clip_core::MIN_COORDINATE`:
/// vatti's union is then not valid input for the next operation, and the region identity that
/// feeds it back must skip the case rather than call the refusal a failure.
#[test]
fn vatti_output_below_min_coordinate() {
    regression("vatti", "output-below-min-coordinate");
}

/// A window edge 2.2e-16 long: Sutherland-Hodgman placed its crossing by orient2d's magnitude,
/// which Shewchuk's predicate leaves 4% off once the sign is certain, and a crossing moved by
/// 0.003 cut off a triangle of the result. `clip_core::predicates::orient2d` now refines the
/// magnitude where the plain determinant is not clearly above its rounding.
#[test]
fn window_clippers_boundary_2e_16_long() {
    regression("window_clippers", "boundary-2e-16-long");
}

/// At 1e9 (an ulp is 1.2e-7) vatti's crossings rounded onto input vertices and made a clockwise
/// triangle of them, with an edge along no input edge. The oracle lets such a ring, as thin as
/// rounding, run either way.
#[test]
fn vatti_crossings_rounded_onto_input_vertices_at_1e9() {
    regression("vatti", "crossings-rounded-onto-input-vertices-at-1e9");
}

/// A ring simple only up to the snap distance, with a loop one ulp wide at its lowest vertex: the
/// oracle's exact turn there said clockwise for a ring whose area is clearly positive. The
/// shoelace sum decides now wherever it is clearly beyond its rounding.
#[test]
fn vatti_ulp_wide_loop_at_lowest_vertex() {
    regression("vatti", "ulp-wide-loop-at-lowest-vertex");
}

/// At 1e15 a rounded crossing sat 3 ulps off a clip edge it meets at 25°, and the edge it starts
/// crossed that clip edge 0.38 from its end, beyond the oracle's 2-ulp snap. The snap is now 4
/// rounding distances, and an end within the snap of the other edge also explains a crossing.
#[test]
fn vatti_shallow_crossing_at_1e15() {
    regression("vatti", "shallow-crossing-at-1e15");
}

/// Two triangles at 1e15 (an ulp is 0.125) whose union has a sliver an ulp wide between two of
/// its parts: the sliver's crossings rounded onto one line, and the clean-up left two rings running
/// the same way along it (their insides overlapping). Such rings are now joined by sweeping the
/// output's own union under the positive rule (`clip_vatti`'s `repair`).
#[test]
fn vatti_triangles_joined_along_a_rounded_edge_at_1e15() {
    regression("vatti", "triangles-joined-along-a-rounded-edge-at-1e15");
}

/// Near (0.1, 0.7), where an ulp is 1.4e-17: a triangle a few ulps wide inside a large one left
/// the union with a clockwise ring of rounded crossings running the same way as the outer ring
/// along one of its edges. Joined by the same repair.
#[test]
fn vatti_hole_an_ulp_wide_along_an_outer_edge() {
    regression("vatti", "hole-an-ulp-wide-along-an-outer-edge");
}

/// At 1e15 two rings of the union ran the same way along parts of one horizontal edge: the
/// clean-up splits horizontal edges at the vertices inside them, so the parts became one directed
/// edge twice, which it now reports and the repair joins.
#[test]
fn vatti_horizontal_edge_run_twice_at_1e15() {
    regression("vatti", "horizontal-edge-run-twice-at-1e15");
}

/// A triangle near the origin and a sliver running to (-6.2e66, -6.2e66) from nearly parallel
/// edges: at the sliver's scale (an ulp is 1e51) the union lost its outer ring and kept the
/// triangle, a clockwise hole of it, with no ring around it. The clean-up now checks that each
/// clockwise ring it rebuilds is held by another ring; one that is not is joined by the repair's
/// sweep (the output's union under non-zero, which turns it counter-clockwise).
#[test]
fn vatti_hole_left_by_an_outer_lost_at_6e66() {
    regression("vatti", "hole-left-by-an-outer-lost-at-6e66");
}

/// At 1e15 (an ulp is 0.125) a triangle of the union made of input vertices came out clockwise
/// beside the ring it touches: an outer turned inside out by rounded crossings. Fixed as above.
#[test]
fn vatti_outer_turned_clockwise_at_1e15() {
    regression("vatti", "outer-turned-clockwise-at-1e15");
}

/// A 5-vertex ring with a vertex at 5e25 (an ulp is 8.6e9) and a triangle near the origin: the
/// union's two rings near the origin share no point, yet one crossed into the other, which the
/// oracle saw as a counter-clockwise hole. The clean-up cannot see rings that share no point;
/// today the rounding certificate fails there (features within its clearance), and the
/// snap-rounded operands are swept instead.
#[test]
fn vatti_rings_crossing_near_a_sliver_to_5e25() {
    regression("vatti", "rings-crossing-near-a-sliver-to-5e25");
}

/// At 1e15 the clip's triangle of three input vertices, 0.4 by 0.3 (a few ulps), was swept in
/// the wrong order among rounded x, and the difference's hole came out counter-clockwise, apart
/// from every other ring. Found by the full check above, joined by the repair.
#[test]
fn vatti_hole_of_input_vertices_counter_clockwise_at_1e15() {
    regression("vatti", "hole-of-input-vertices-counter-clockwise-at-1e15");
}

/// At 1e9 with an edge running to 6.2e66: two rounded crossings fell exactly on each other's
/// edges, and the union's rings, sharing no point, ran the same way along part of an edge that is
/// not horizontal. Found by the full check above, joined by the repair.
#[test]
fn vatti_rings_sharing_no_point_overlap_along_an_edge_at_1e9() {
    regression("vatti", "rings-sharing-no-point-overlap-along-an-edge-at-1e9");
}

/// A self-overlapping ring near (2, 3) under even-odd whose vertices lie nearly on one line:
/// the union's sliver hole of three input vertices (area -2e-16) arrived at (2.85, 3.45) along the
/// outer ring's edge from (2.1, 2.7), one of its vertices, the same way: the hole poked out of its
/// outer. The clean-up only compared the ends of edges leaving a point, and the full form check
/// skips outputs whose edges are far above rounding. Edges leaving or arriving at a point in the
/// same direction are now reported, and the repair joins them.
#[test]
fn vatti_sliver_hole_arriving_along_an_outer_edge() {
    regression("vatti", "sliver-hole-arriving-along-an-outer-edge");
}

/// At 1e15 (an ulp is 0.125) the union was broken and repaired, but the repair's sweep left two
/// rings leaving (-1e15, 1e15 + 0.125) downwards along x = -1e15 to different ends. The full
/// check does not judge the repair's sweeps; the clean-up's check of edges in one direction
/// (above) does, and the next sweep joins them.
#[test]
fn vatti_repair_leaving_a_point_twice_downwards_at_1e15() {
    regression("vatti", "repair-leaving-a-point-twice-downwards-at-1e15");
}

/// Near (5e5, 4e6) (an ulp is 5.8e-11 in x) some fifty rings of the xor an ulp or two apart: every
/// repair sweep rounded new crossings among them, and the clean-up found the form broken after
/// each of the 4 sweeps allowed, so the last broken output was returned. It takes 5; the repair
/// now allows 8 (`clip_vatti`'s `repair::MAX_PASSES`).
#[test]
fn vatti_xor_needing_five_repair_sweeps_at_5e5() {
    regression("vatti", "xor-needing-five-repair-sweeps-at-5e5");
}

/// Rings with vertices on y = x near 1e141 and an edge from (5e5, 4e6) to (5e140, 5e140), which
/// passes 1.4e6 (far below an ulp there) above the exact vertices (3e140, 3e140) and
/// (3.75e140, 3.75e140): the union's hole ran up y = x between crossings rounded onto it, through
/// both vertices, and later down from one to the other, overlapping itself. The sweep rightly kept
/// the vertices out of that edge's chain (they are not on it), and the clean-up split only
/// horizontal edges at the vertices inside them. The sweep now reports such a near miss, and the
/// clean-up then splits every edge at the vertices on it, so the two runs cancel.
#[test]
fn vatti_union_retracing_y_equals_x_at_1e141() {
    regression("vatti", "union-retracing-y-equals-x-at-1e141");
}

/// Spikes from (5e5, 4e6) to points on y = x near 1e141: the union's first output was broken and
/// the repair's sweep rounded crossings onto y = x, leaving a ring that runs down it across
/// exact vertices it ran up through before (a self-overlap the repair's own clean-up did not
/// see). Fixed by the same split after a near miss.
#[test]
fn vatti_repair_retracing_y_equals_x_at_1e141() {
    regression("vatti", "repair-retracing-y-equals-x-at-1e141");
}

/// At 1e15 (an ulp is 0.125) the union had two rings running the same way up
/// x = -999999999999999.9 between exact input vertices and rounded crossings: one ring's edge
/// passed through the other's vertices, so they shared no end and the clean-up did not compare
/// them. Fixed by the split after a near miss, which makes the shared stretch an edge of both and
/// lets the repair join them.
#[test]
fn vatti_rounded_vertical_through_exact_vertices_at_1e15() {
    regression("vatti", "rounded-vertical-through-exact-vertices-at-1e15");
}

/// Near 1e-7 with a clip vertex at -2.8e18 on y = x: the xor's repair left a triangle a few ulps
/// wide whose vertices on y = x lie inside another ring's edge from (0, 0) to (-2.8e18, -2.8e18),
/// both running the same way. Fixed twice over: crossings found while an edge slides along a
/// horizontal are now rounded crossings (edges within rounding of them take the point), and the
/// split after a near miss.
#[test]
fn vatti_triangle_inside_a_slanted_edge_at_1e_7() {
    regression("vatti", "triangle-inside-a-slanted-edge-at-1e-7");
}

/// Near (5e5, 4e6) with clip edges to 1e21 that are nearly horizontal: every repair sweep rounded
/// their crossings at new x on y = 3999999.999999947, and the clean-up called each result broken
/// because two edges ran one way and one back along a stretch (a valid form: it bounds the
/// stretch once). After 8 sweeps the last, really broken output was returned. Edges now count as
/// running the same way only once opposite edges cancelled; the stricter reading (two one way
/// and one back, near rounding) judges the sweep's own output only, where a fuzz input's xor
/// (`fuzz/crashes/vatti/crash-2d517e83...`) needs it.
#[test]
fn vatti_repair_never_settling_near_horizontal_edges_at_5e5() {
    regression("vatti", "repair-never-settling-near-horizontal-edges-at-5e5");
}

/// Rings near 1e-89 under even-odd: the union's first output had two rings running the same way
/// along an edge, but a rounded crossing at 1.4e-104 lay below `clip_core::MIN_COORDINATE`, so
/// the repair's sweep refused the output and it was returned broken. Such coordinates now become
/// 0 before the repair (rings left without area go), a move far below the rounding of the rest.
#[test]
fn vatti_union_repair_refused_below_min_coordinate_at_1e_89() {
    regression("vatti", "union-repair-refused-below-min-coordinate-at-1e-89");
}

/// The same refusal in an xor near 1e-89 (a crossing rounded to 2.4e-103), fixed the same way.
#[test]
fn vatti_xor_repair_refused_below_min_coordinate_at_1e_89() {
    regression("vatti", "xor-repair-refused-below-min-coordinate-at-1e-89");
}

/// Near (0.1, 0.7) the union left a sliver ring along y = x + 0.6 and the outer ring both running
/// up the edge (0.1, 0.7)-(0.1, 0.7000000000000003), through every repair sweep. The sliver's edge
/// from (-2.9, -2.3) crosses the outer's horizontal y = 0.7 3e-16 left of its end (0.1, 0.7), but
/// its x on that scanline, interpolated from the far end, came out 8e-17 right of it (an ulp of
/// 2.9 is 4e-16), so the slide along the horizontal stopped before it. A slide now decides the
/// side of an edge whose x lies within rounding of its end exactly.
#[test]
fn vatti_slide_missing_a_crossing_rounded_past_a_horizontals_end() {
    regression("vatti", "slide-missing-a-crossing-rounded-past-a-horizontals-end");
}

/// Found by a 10-minute run of the `vatti` target after the fix above (the two inputs found are
/// `fuzz/crashes/vatti/crash-28921e1a...` and `crash-51cf9085...`; this is the first shrunk). The
/// subject's spike (0.865625, 7.340624999999999)-(0.85, 7.449999999999999)-(1.1, 5.699999999999999)
/// and its edge from there to (0.1, 12.7) lie on one line in decimal, through that vertex V, which
/// the clip visits twice; in doubles the edge passes 9e-17 right of V, nearly parallel to the two
/// copies of the edge from V to (0.85, 7.45), and their crossings round to points an ulp from V.
/// The xor's rings crossed there; the repair's sweep rounded new crossings among edges an ulp apart
/// and left two rings crossing at (0.865625, 7.340624999999998). The repair now first merges points
/// within a few ulps of each other and routes edges passing that close through them (as snap
/// rounding does), so its sweep has nothing to round there. (Since issue 29 the broken output is
/// replaced by one sweep of the snap-rounded operands, `clip_core::snap_round`, instead.)
#[test]
fn vatti_spike_nearly_through_a_vertex_visited_twice() {
    regression("vatti", "spike-nearly-through-a-vertex-visited-twice");
}

/// The same with five rounded crossings within 3 ulps of (500009, 4000015) (an ulp is 4.7e-10 in
/// y), where the xor's repair left rings crossing at (500008.9999999999, 4000014.9999999963).
/// Fixed by the same snap before the repair's sweep.
#[test]
fn vatti_rounded_crossings_clustered_at_5e5() {
    regression("vatti", "rounded-crossings-clustered-at-5e5");
}

/// Two rings whose vertices lie on y = x + 0.6 in decimal, under even-odd (found by the 10-minute
/// run after the fix above): the union's triangle (1.1, 1.7)-(0.1, 0.7)-(8.1, 8.7) of input vertices
/// runs clockwise exactly, but its rounded shoelace area is +4.4e-16, so the clean-up took it for
/// an outer (the full form check skips outputs whose edges are far above rounding). The clean-up
/// and the form check now decide a ring's way exactly where its area is rounding
/// (`clip_core::runs_counter_clockwise`, which the oracle uses too), and the repair turns the
/// unheld clockwise ring round.
#[test]
fn vatti_clockwise_sliver_with_a_positive_rounded_area() {
    regression("vatti", "clockwise-sliver-with-a-positive-rounded-area");
}

/// At 1e15 (an ulp is 0.125) a triangle touching a clip ring at a vertex that ring visits twice,
/// with a spike inside the triangle: every point is an input vertex, yet vatti's xor came out with
/// an outer ring missing and the hole left bare. Points that are not crossings were taken for
/// rounded ones and joined chains of edges within 4 ulps; only computed crossings may now.
#[test]
fn vatti_input_vertex_taken_for_rounded_at_1e15() {
    regression("vatti", "input-vertex-taken-for-rounded-at-1e15");
}

/// A segment crossing a sliver window 5e-17 wide lengthwise: Cyrus-Beck's piece was right, and
/// the line oracle wrong twice: it classified the run by a rounded midpoint (outside the sliver)
/// and computed crossing parameters from cross products that cancel for near-parallel lines. Runs
/// are now classified by the parity of the edges crossed beyond them, and parameters come from
/// `orient2d`'s accurate magnitudes.
#[test]
fn line_clippers_sliver_window_crossed_lengthwise() {
    regression("line_clippers", "sliver-window-crossed-lengthwise");
}

/// A segment along a sliver window whose crossings with its nearly parallel edges the oracle
/// placed by cancelling cross products: [0, 0.22] expected against Cyrus-Beck's [0.087, 0.111]
/// before either was accurate.
#[test]
fn line_clippers_segment_nearly_parallel_to_sliver_edges() {
    regression("line_clippers", "segment-nearly-parallel-to-sliver-edges");
}

/// A segment ending on a window vertex and running 1e-17 inside the window's edge: visible whole
/// (Cyrus-Beck, by exact signs); with both ends on the boundary the oracle had only a rounded
/// midpoint to decide by, and called it outside.
#[test]
fn line_clippers_segment_an_ulp_inside_an_edge() {
    regression("line_clippers", "segment-an-ulp-inside-an-edge");
}

/// Near 4e6 (a point's rounding spans 3e-11 of the segment, above `PARAMETER_SNAP`) Liu returned
/// two pieces meeting at one rounded point where spikes of the window cross the segment. Gaps whose
/// ends round to one point are now merged in `clip_core::LineCrossings`.
#[test]
fn line_clippers_pieces_meet_at_a_rounded_point() {
    regression("line_clippers", "pieces-meet-at-a-rounded-point");
}

/// A window turning back at (3e140, 3e140) by 1e74 and winding twice: its nearly 180° turn had a
/// rounded cross product of 0, counted as -π, and `Ring::convex_orientation` called it convex, so
/// Cyrus-Beck clipped against half-planes that are not the window. Turns are now summed the way the
/// exact test found them.
#[test]
fn line_clippers_window_winding_twice_through_a_hairpin() {
    regression("line_clippers", "window-winding-twice-through-a-hairpin");
}

/// A window edge near the origin and a segment end at 6.4e25: the determinant's terms (4e51) cancel
/// to 2.4e25, and the compensated sum left `orient2d`'s magnitude 1e-4 off, so the oracle and
/// Cyrus-Beck put the exit 1e-7 of the segment early (exact rationals agree with Liu). The terms
/// are now summed exactly into an expansion.
#[test]
fn line_clippers_edge_near_origin_segment_end_at_6e25() {
    regression("line_clippers", "edge-near-origin-segment-end-at-6e25");
}

/// A segment nearly parallel to a window edge 1e149 long: the plain determinant, trusted down to
/// 1e-8 of its terms, was 2e-8 off in relative terms, and a crossing 1.2e-9 of the segment off.
/// It is now trusted down to 1e-4 only.
#[test]
fn line_clippers_plain_determinant_1e_8_off() {
    regression("line_clippers", "plain-determinant-1e-8-off");
}

/// A segment from (2.3e77, 4.9e-33) to (4.9e-33, 4.9e-33) under a window edge of slope 6e-75 it
/// crosses 1.9e31 from a window corner at 1.1e74 (1e-43 of the window: nothing visible, within
/// tolerance). The oracle measured the far segment along its part near the window, and took the
/// crossing with that nearly parallel edge from the edge's line function at the part's ends, which
/// lie on the segment's line only to within rounding at 1e74 (1e58 off): the crossing came out
/// at the part's end, and half the part "visible". The crossing is now placed along the edge.
#[test]
fn line_clippers_edge_nearly_parallel_to_a_far_segment() {
    regression("line_clippers", "edge-nearly-parallel-to-a-far-segment");
}

/// Points 1e-7 apart on a diagonal that f64 cannot hold exactly: vatti's xor retraced a ring
/// for one ulp at a rounded crossing, which the oracle called a self-overlap. A same-ring overlap
/// no longer than the snap distance is now a rounded vertex, as a crossing that close is.
#[test]
fn vatti_ulp_long_self_overlap() {
    regression("vatti", "ulp-long-self-overlap");
}

/// One ring runs three times along y = x + 0.6, through vertices that f64 holds only nearly on
/// that line: the even-odd union has slivers about 1e-15 wide made of input vertices alone. Its
/// edges were long, so the form check skipped the output, and a sliver inside an outer was left
/// running counter-clockwise. A ring that thin is now near rounding as a short edge is.
#[test]
fn vatti_sliver_of_nearly_collinear_input_vertices_counter_clockwise() {
    regression("vatti", "sliver-of-nearly-collinear-input-vertices-counter-clockwise");
}

/// A geo boolean-op fixture whose ring holds a position of one number: the conformance reader
/// handed it to the geojson crate's conversion, which indexes x and y unchecked and panicked.
/// The fixture reader now checks positions and rings first, as `clip`'s GeoJSON reader does.
#[test]
fn readers_geo_fixture_with_a_position_of_one_number() {
    regression("readers", "geo-fixture-with-a-position-of-one-number");
}

/// A union near (5e5, 4e6) with one vertex at 5e-33: its snap fallback runs in pixel units up to
/// 2^51, where crossings cannot be computed exactly. Snap rounding had noded two edges at a grid
/// point, but the sweep's simplification dropped both straight-through vertices there, made the
/// two edges cross again, and rounded the crossing off the grid. The fallback's sweep now keeps
/// straight-through vertices (`simplify_ring_keeping`).
#[test]
fn vatti_snapped_crossing_at_a_dropped_straight_vertex_near_2e51_pixels() {
    regression("vatti", "snapped-crossing-at-a-dropped-straight-vertex-near-2e51-pixels");
}

/// The same kind of input's xor, where a fallback ring crossed itself for the same reason.
#[test]
fn vatti_snapped_self_crossing_xor_near_4e6() {
    regression("vatti", "snapped-self-crossing-xor-near-4e6");
}

/// A union at 1e149 whose small triangles have all three corners on other rings: vatti's form
/// check placed each ring by a vertex off every other ring, found none, and counted the valid
/// output as broken; the snap fallback's output there was not valid. Such a ring is now placed
/// by an edge's midpoint.
#[test]
fn vatti_triangles_whose_corners_touch_other_rings_at_1e149() {
    regression("vatti", "triangles-whose-corners-touch-other-rings-at-1e149");
}

/// An intersection near 1e141 whose snap fallback's output crossed itself: `snap_round` decided
/// which pixel holds a crossing with predicates whose degree-three terms overflow beyond about
/// 1e100, so crossings went into the wrong pixels and the snapped operands still crossed.
/// `snap_round` now decides in pixel units, where every coordinate is below 2^51.
#[test]
fn vatti_snapped_intersection_crossing_itself_at_1e141() {
    regression("vatti", "snapped-intersection-crossing-itself-at-1e141");
}

/// The same fault in an xor: two of the fallback's rings crossed.
#[test]
fn vatti_snapped_xor_rings_crossing_beyond_1e100() {
    regression("vatti", "snapped-xor-rings-crossing-beyond-1e100");
}

/// The same fault in a union: two of the fallback's rings overlapped along an edge.
#[test]
fn vatti_snapped_union_rings_overlapping_beyond_1e100() {
    regression("vatti", "snapped-union-rings-overlapping-beyond-1e100");
}

/// The event sweep along y (session 28, 30 minutes of `fuzz/vatti`, shrunk): a sliver 8 units
/// long and an ulp high, its long lower edge rising 6 ulps, crossed a steep triangle edge 0.05
/// ulp below the row of the sliver's horizontal top. The crossing was computed 1.5 ulps above
/// that row, so the horizontal's slide met the two edges in their order below the crossing,
/// their x on the row in the order above it, and the union filled a region below the sliver.
/// Crossings computed just above a scanline whose edges have crossed by it, exactly, are now
/// taken before it (`SweepLine::crossed_below`).
#[test]
fn vatti_crossing_computed_above_the_horizontal_it_lies_below() {
    regression("vatti", "crossing-computed-above-the-horizontal-it-lies-below");
}

/// The same at 5e5 (its first find, also a union).
#[test]
fn vatti_crossing_computed_above_the_horizontal_it_lies_below_at_5e5() {
    regression("vatti", "crossing-computed-above-the-horizontal-it-lies-below-at-5e5");
}

/// The rounding certificate (session 29, 30 minutes of `fuzz/vatti`): a ring of spikes and
/// repeated points an ulp or two apart near (5e5, 4e6), a positive union. Its checks failed, but
/// the certificate still held, because no output point had been marked rounded: every crossing
/// was computed outside its edges' range and clamped onto one of their ends, an input vertex. A
/// crossing between scanlines now counts as rounded wherever it lands, and events out of their
/// exact order fail the certificate whatever was rounded.
#[test]
fn vatti_crossings_clamped_onto_vertices_count_as_rounded_at_4e6() {
    regression("vatti", "crossings-clamped-onto-vertices-count-as-rounded-at-4e6");
}

/// The same found with a ring running out to -6e66, where the clearance is 1e53 wide (an
/// even-odd union swept along x).
#[test]
fn vatti_crossings_clamped_onto_vertices_count_as_rounded_to_6e66() {
    regression("vatti", "crossings-clamped-onto-vertices-count-as-rounded-to-6e66");
}

/// Found by `fuzz/vatti` (60 minutes, an even-odd union of one ring near 1e149 with nothing): the
/// rounding certificate held where the output crossed itself. Its test of an output point's
/// nearest neighbour compared squares, the point's offset from the edge's line against the
/// clearance times the edge's length, and near `MAX_COORDINATE` both overflowed to infinity,
/// which passed as clear. It compares them unsquared.
#[test]
fn vatti_neighbour_distance_squared_overflowing_at_1e149() {
    regression("vatti", "neighbour-distance-squared-overflowing-at-1e149");
}

/// The same with two subject rings.
#[test]
fn vatti_neighbour_distance_squared_overflowing_at_1e149_two_rings() {
    regression("vatti", "neighbour-distance-squared-overflowing-at-1e149-two-rings");
}

/// The same with the event sweep along x.
#[test]
fn vatti_neighbour_distance_squared_overflowing_at_1e149_along_x() {
    regression("vatti", "neighbour-distance-squared-overflowing-at-1e149-along-x");
}

/// A time-out (libFuzzer's 10 s, on a loaded machine): rings of vertices near (5e5, 4e6) with
/// one vertex at -6.3e66, whose snap fallback's pixel (4 ulps of 6.3e66) holds the whole
/// cluster. Every pair of its edges was a near pair, and each asked the pixel's far corners
/// against the edge, an orientation the filter cannot decide. An edge inside one pixel now meets
/// it without a corner asked, its crossings are not computed (they lie in that hot pixel), and an
/// edge is not given a pixel of its own ends again: 0.24 s a check to 0.03 s.
#[test]
fn vatti_cluster_a_pixel_wide_beside_a_vertex_at_6e66() {
    regression("vatti", "cluster-a-pixel-wide-beside-a-vertex-at-6e66");
}

/// Near-miss routing in the event sweep (session 37): a ring along one line, visiting its points
/// many times, each a fraction of an ulp off the others' edges. Routing an edge through a vertex
/// while another edge lay between them, unrouted, made the routed edge cross it without a
/// crossing taken: a ring crossing another at (0.1, 12.7). An edge the walk passes that is not
/// routed now blocks the split of those beyond it.
#[test]
fn vatti_routing_blocked_by_an_edge_between_the_vertex_and_the_near_edge() {
    regression("vatti", "routing-blocked-by-an-edge-between-the-vertex-and-the-near-edge");
}

/// Near-miss routing at coordinates near 1e149: the distance test compared squares, which
/// overflowed to infinity on both sides, so every edge counted as a near miss and was split at
/// vertices far from it (a point of the union left outside). Now compared by `hypot`.
#[test]
fn vatti_near_miss_distance_squared_overflowing_at_1e149() {
    regression("vatti", "near-miss-distance-squared-overflowing-at-1e149");
}
