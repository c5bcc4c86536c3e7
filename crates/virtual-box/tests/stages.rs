//! Each rejection stage of the paper, pinned with the counters: which stage removes a segment,
//! and that New1 (no 45° box) leaves it to a later stage with the same (empty) result.

use clip_core::{Polygons, Segment};
use clip_testkit::line_probe::{seg, window};
use clip_virtual_box::{PreparedVirtualBox, StageCounts};

/// The counts of clipping `s` alone with New2 and New1; both must show nothing.
fn stages(w: &Polygons, s: Segment) -> (StageCounts, StageCounts) {
    let run = |rotated: bool| {
        let mut out = Vec::new();
        let counts = PreparedVirtualBox::new(w, rotated).unwrap().clip_batch_counted(&[s], &mut out).unwrap();
        assert!(out.is_empty(), "{s:?} shows {out:?}");
        counts
    };
    (run(true), run(false))
}

/// An L in the MEB [1,9]²: the empty quarter x > 3, y > 3 is inside the MEB but outside the window.
const L: &[(f64, f64)] = &[(1.0, 1.0), (9.0, 1.0), (9.0, 3.0), (3.0, 3.0), (3.0, 9.0), (1.0, 9.0)];
const SQUARE: &[(f64, f64)] = &[(1.0, 1.0), (9.0, 1.0), (9.0, 9.0), (1.0, 9.0)];

#[test]
fn meb_rejects_segments_beyond_one_side() {
    let (new2, new1) = stages(&window(L), seg(10.0, 0.0, 12.0, 8.0));
    assert_eq!((new2.meb, new1.meb), (1, 1));
}

#[test]
fn rotated_box_rejects_segments_across_a_corner() {
    // Across the MEB's top-right corner region of the L, beyond u = x + y = 12 at both ends.
    let (new2, new1) = stages(&window(L), seg(8.5, 8.0, 8.0, 8.5));
    assert_eq!((new2.meb, new2.rotated_box), (0, 1));
    // New1 has no rotated box: the code sum catches it (its line passes inside the MEB).
    assert_eq!((new1.rotated_box, new1.code_sum), (0, 1));
}

#[test]
fn virtual_box_rejects_lines_missing_the_meb() {
    // Ends left of and above the MEB (no common Cohen-Sutherland bit), on no common side of the
    // rotated box, but the steep line passes above the corner (1,9): Table 1, k > 1.
    let s = seg(0.0, 8.0, 2.0, 11.0);
    let (new2, new1) = stages(&window(SQUARE), s);
    assert_eq!((new2.meb, new2.rotated_box, new2.virtual_box), (0, 0, 1));
    assert_eq!(new1.virtual_box, 1);
    // The same with a flat line below the bottom-right corner (Table 1, -1 < k < 0).
    let (new2, _) = stages(&window(SQUARE), seg(7.0, -0.5, 10.0, -1.5).reversed());
    assert_eq!(new2.meb, 1);
    let (new2, _) = stages(&window(SQUARE), seg(8.5, 0.5, 10.0, 1.5));
    assert_eq!(new2.virtual_box, 1);
}

#[test]
fn code_sum_rejects_lines_through_the_empty_part_of_the_meb() {
    // The paper's segment e: its line crosses the MEB in the L's empty quarter, every vertex below.
    let s = seg(2.0, 9.5, 9.5, 8.0);
    let (new2, new1) = stages(&window(L), s);
    assert_eq!((new2.meb, new2.rotated_box, new2.virtual_box, new2.code_sum), (0, 0, 0, 1));
    assert_eq!(new1.code_sum, 1);
    // A segment wholly inside the MEB, in the empty quarter, whose line reaches the L: it gets to
    // the intersection stage and shows nothing.
    let (new2, _) = stages(&window(L), seg(5.0, 5.0, 6.0, 7.0));
    assert_eq!((new2.code_sum, new2.intersected, new2.visible), (0, 1, 0));
}

#[test]
fn counts_add_up_over_a_batch() {
    let segments = [
        seg(10.0, 0.0, 12.0, 8.0),
        seg(8.5, 8.0, 8.0, 8.5),
        seg(2.0, 9.5, 9.5, 8.0),
        seg(0.0, 2.0, 10.0, 2.0),
        seg(4.0, 4.0, 4.0, 4.0),
    ];
    let mut out = Vec::new();
    let c = PreparedVirtualBox::new(&window(L), true).unwrap().clip_batch_counted(&segments, &mut out).unwrap();
    let expected = StageCounts {
        segments: 5,
        zero_length: 1,
        meb: 1,
        rotated_box: 1,
        virtual_box: 0,
        code_sum: 1,
        intersected: 1,
        visible: 1,
    };
    assert_eq!(c, expected);
    assert_eq!(out.len(), 1);
    assert_eq!((out[0].piece.a.x, out[0].piece.b.x), (1.0, 9.0));
}
