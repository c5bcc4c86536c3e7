//! Output clean-up after the sweep: rings that touch or overlap become simple rings.
//!
//! The sweep's rings already bound the right region with the result on their left, but where
//! the result pinches at a point a ring may visit that point twice, two rings may share an edge
//! in opposite directions (zero-width gaps and slivers between coincident edges), and horizontal
//! output edges may overlap. Here such rings are taken apart into directed edges, split where a
//! vertex lies inside a horizontal edge (inside any edge, when the sweep reported a near miss:
//! see `touches`), opposite edges cancel, and rings are walked again,
//! leaving each vertex by the outgoing edge that bounds the same corner of the region as the
//! incoming one (the first one clockwise from the way back), then split wherever they still
//! visit a vertex twice. So every ring is simple; rings touch only at vertices; outers come out
//! counter-clockwise and holes clockwise. Collinear vertices are dropped last.
//!
//! One module a step, each used only from the ones after it:
//!
//! - `touches`: which rings touch (share a point or hold a vertex inside an edge), and an id per
//!   distinct point.
//! - `directions`: the exact orders of the ways out of a point that both walks turn by.
//! - `simple_loops`: a walk split where it visits a point twice.
//! - `turns`: the walk turned only at the shared points, where nothing cancels or splits (most
//!   touches: holes on their outers, pinches).
//! - `same_way` and `rebuild`: the general walk through directed edges, and the edges it finds
//!   overlapping the same way.
//! - `shared_points`: whether rebuilt rings meet cleanly where they share a point.
//! - `held`: whether the rebuilt clockwise rings are held by an outer.
//!
//! Where `turns` can plan a walk, it and `rebuild` give the same rings and the same verdict;
//! production runs the plan alone, and the tests hold the two against each other.

mod directions;
mod held;
mod rebuild;
mod same_way;
mod shared_points;
mod simple_loops;
mod touches;
mod turns;

use std::borrow::Cow;

use clip_core::{Point, Ring};

use self::held::HeldTest;
use self::rebuild::rebuild;
use self::same_way::SameWay;
pub(crate) use self::shared_points::cross_at_shared_points;
pub(crate) use self::touches::Touches;
pub(crate) use self::turns::Turns;
use crate::raw_rings::RawRings;
use crate::simplify::simplify_ring;

/// The clean-up's rings, and whether rounding left their form broken (`snap_fallback` then
/// replaces them): two rings (or two passes of one) running the same way along an edge, where rounded
/// crossings put both sides of a sliver an ulp wide onto one line and their insides overlap; or a
/// rebuilt clockwise ring that no other ring holds, a hole whose outer rounding lost or an outer
/// turned inside out.
#[derive(Debug, Default)]
pub(crate) struct CleanRings {
    pub rings: Vec<Ring>,
    pub broken_form: bool,
}

/// The sweep's rings as conventional output rings. Only rings that share a point with another
/// ring (or with themselves) or have a vertex inside a horizontal edge are rebuilt; the others
/// are already simple and lose only collinear vertices. `touches` is a reused work buffer.
#[cfg(test)]
pub(crate) fn conventional_rings(raw: &RawRings, touches: &mut Touches) -> CleanRings {
    conventional_rings_checked(raw, touches, &mut Turns::default(), true, || true)
}

/// Touched rings from which, when some edge needs a split, the rings meeting none are walked
/// along the turns apart from the rebuilt ones: below it, finding them costs more than
/// rebuilding them.
const SPLIT_WALK_FROM: usize = 64;

/// Clockwise rings times rings up to which the held test runs whatever `near_rounding` says.
const HELD_TEST_BUDGET: usize = 1 << 16;

/// [`conventional_rings`], testing whether rebuilt clockwise rings are held when
/// `near_rounding()` (asked only then: it scans the inputs) or the test is cheap ([`HELD_TEST_BUDGET`]): it can be quadratic
/// in the rings, and outputs with thousands of holes far above rounding (scribble unions) took
/// 30 times as long with it.
///
/// With `strict`, edges retraced near rounding also count as broken (see [`SameWay::Retraced`]).
/// Without it nothing is checked and `broken_form` is false: for outputs taken as final, the snap
/// fallback's sweep and sweeps whose rounding is harmless (`form_check::rounding_is_harmless`).
pub(crate) fn conventional_rings_checked(
    raw: &RawRings,
    touches: &mut Touches,
    turns: &mut Turns,
    strict: bool,
    near_rounding: impl FnOnce() -> bool,
) -> CleanRings {
    touches.find(raw);
    let walk = chosen_walk(raw, touches, turns, SPLIT_WALK_FROM);
    walked(raw, touches, walk, strict, near_rounding)
}

/// How the touched rings of `raw` are walked: along the turns where they can be planned, else
/// rebuilt; when some edge needs a split and at least `split_from` rings are touched, the rings
/// that meet no edge to split are walked along the turns apart from the rebuilt ones.
fn chosen_walk<'a>(raw: &RawRings, touches: &'a Touches, turns: &'a mut Turns, split_from: usize) -> Walk<'a> {
    if !touches.touched.contains(&true) {
        return Walk::rebuilt(touches);
    }
    if touches.splits.is_empty() {
        return if turns.plan(raw, touches, &touches.touched) {
            Walk::planned(turns, touches)
        } else {
            Walk::rebuilt(touches)
        };
    }
    if touches.touched.iter().filter(|&&t| t).count() < split_from {
        return Walk::rebuilt(touches);
    }
    let rebuilt = touches.rings_to_split(raw);
    let planned: Vec<bool> = touches.touched.iter().zip(&rebuilt).map(|(&t, &r)| t && !r).collect();
    if planned.contains(&true) && turns.plan(raw, touches, &planned) {
        Walk { turns: Some(turns), planned: Cow::Owned(planned), rebuilt: Cow::Owned(rebuilt) }
    } else {
        Walk::rebuilt(touches)
    }
}

/// How the touched rings are walked again: those of `planned` along the turns [`Turns::plan`]
/// chose at their shared points (it succeeded), those of `rebuilt` through the directed edges
/// ([`rebuild`]), which also reports edges running the same way. The two sets meet nowhere, so
/// each walk gives the rings and verdict it would give walking every touched ring, and where the
/// turns can be planned for every touched ring they give the rebuild's rings in its order.
struct Walk<'a> {
    turns: Option<&'a mut Turns>,
    planned: Cow<'a, [bool]>,
    rebuilt: Cow<'a, [bool]>,
}

impl<'a> Walk<'a> {
    /// Every touched ring along the planned turns.
    fn planned(turns: &'a mut Turns, touches: &'a Touches) -> Walk<'a> {
        Walk { turns: Some(turns), planned: Cow::Borrowed(&touches.touched), rebuilt: Cow::Owned(Vec::new()) }
    }

    /// Every touched ring rebuilt.
    fn rebuilt(touches: &'a Touches) -> Walk<'a> {
        Walk { turns: None, planned: Cow::Owned(Vec::new()), rebuilt: Cow::Borrowed(&touches.touched) }
    }
}

/// The untouched rings of `raw` simplified, then the touched ones walked again by `walk`, and
/// whether the form is broken ([`conventional_rings_checked`]).
fn walked(
    raw: &RawRings,
    touches: &Touches,
    walk: Walk,
    strict: bool,
    near_rounding: impl FnOnce() -> bool,
) -> CleanRings {
    let mut out = Vec::with_capacity(raw.len());
    for (i, &t) in touches.touched.iter().enumerate() {
        if !t {
            let s = simplify_ring(raw.ring(i));
            if s.len() >= 3 {
                out.push(Ring::new(s));
            }
        }
    }
    if !touches.touched.contains(&true) {
        return CleanRings { rings: out, broken_form: false };
    }
    let mut clockwise: Vec<usize> = Vec::new();
    // The rebuilt rings as point ids, for the check where they share a point.
    let (mut ring_ids, mut ring_ends) = (Vec::new(), Vec::new());
    if let Some(turns) = walk.turns {
        turns.walk(raw, touches, &walk.planned, &mut |points: &[Point]| {
            push_simplified(points, &mut out, &mut clockwise)
        });
    }
    let same_way = if walk.rebuilt.contains(&true) {
        rebuild(raw, touches, &walk.rebuilt, strict, &mut |ids: &[u32], points: &[Point]| {
            ring_ids.extend_from_slice(ids);
            ring_ends.push(ring_ids.len());
            push_simplified(points, &mut out, &mut clockwise);
        })
    } else {
        SameWay::None
    };
    // Asked once at most: it scans the inputs.
    let (mut near_rounding, mut near) = (Some(near_rounding), None);
    let mut near_rounding = || *near.get_or_insert_with(|| near_rounding.take().is_some_and(|f| f()));
    // Retraced edges are a valid form where nothing is rounded, but near rounding the walk over
    // them can leave rings crossing at a shared point (a fuzz input's xor): the rebuilt rings
    // (before collinear vertices go; untouched rings share no point) are then checked there
    // exactly, and the snap fallback runs only if they do not meet cleanly.
    let broken_form = strict
        && (same_way == SameWay::Remaining
            || (same_way == SameWay::Retraced
                && near_rounding()
                && cross_at_shared_points(&touches.distinct, &ring_ids, &ring_ends))
            || any_unheld(&out, &clockwise, &mut near_rounding));
    CleanRings { rings: out, broken_form }
}

/// `points` as a ring without repeated or collinear vertices, pushed onto `out` unless that
/// leaves fewer than three; its index goes to `clockwise` unless it runs counter-clockwise, decided
/// exactly where its area is rounding (a clockwise sliver's rounded area can come out positive).
fn push_simplified(points: &[Point], out: &mut Vec<Ring>, clockwise: &mut Vec<usize>) {
    let s = simplify_ring(points);
    if s.len() >= 3 {
        let ring = Ring::new(s);
        if !ring.runs_counter_clockwise() {
            clockwise.push(out.len());
        }
        out.push(ring);
    }
}

/// True when one of the `clockwise` rings of `out` is held by no other ring, tested when that is
/// cheap ([`HELD_TEST_BUDGET`]) or `near_rounding()`.
fn any_unheld(out: &[Ring], clockwise: &[usize], near_rounding: impl FnOnce() -> bool) -> bool {
    let check_holes = !clockwise.is_empty() && (clockwise.len() * out.len() <= HELD_TEST_BUDGET || near_rounding());
    check_holes && HeldTest::default().any_unheld(out, clockwise)
}

#[cfg(test)]
mod tests {
    use clip_core::{BoolOp, FillRule, Operand, Polygons, WindowKind, validate_polygons};
    use clip_testkit::workload::{polygon_case, polygon_case_sized};
    use proptest::prelude::*;

    use super::held::assert_batched_agrees;
    use super::*;
    use crate::Sweep;

    fn conventional_rings(rings: Vec<Vec<Point>>) -> Vec<Ring> {
        super::conventional_rings(&RawRings::from_rings(rings), &mut Touches::default()).rings
    }

    fn ring(points: &[(f64, f64)]) -> Vec<Point> {
        points.iter().map(|&(x, y)| Point::new(x, y)).collect()
    }

    fn areas(rings: &[Ring]) -> Vec<f64> {
        let mut a: Vec<f64> = rings.iter().map(Ring::signed_area).collect();
        a.sort_by(f64::total_cmp);
        a
    }

    #[test]
    fn rings_sharing_an_edge_merge_into_one() {
        let left = ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
        let right = ring(&[(1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0)]);
        let out = conventional_rings(vec![left, right]);
        assert_eq!(out.len(), 1);
        assert_eq!(out[0].len(), 4, "collinear vertices dropped: {:?}", out[0]);
        assert_eq!(out[0].signed_area(), 2.0);
    }

    #[test]
    fn a_ring_visiting_a_point_twice_splits_there() {
        // A bow tie of two counter-clockwise triangles meeting at (1, 1).
        let bow = ring(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0), (2.0, 2.0), (1.0, 1.0), (0.0, 2.0)]);
        let out = conventional_rings(vec![bow]);
        assert_eq!(areas(&out), vec![1.0, 1.0]);
    }

    #[test]
    fn horizontal_edges_split_where_the_other_ring_has_vertices() {
        // [0,2]x[0,1] above [1,3]x[-1,0]: they share (1,0)-(2,0), each end inside the other's edge.
        let top = ring(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (0.0, 1.0)]);
        let bottom = ring(&[(1.0, -1.0), (3.0, -1.0), (3.0, 0.0), (1.0, 0.0)]);
        let out = conventional_rings(vec![top, bottom]);
        assert_eq!(out.len(), 1);
        assert_eq!(out[0].len(), 8, "{:?}", out[0]);
        assert_eq!(out[0].signed_area(), 4.0);
    }

    #[test]
    fn rings_running_the_same_way_along_an_edge_are_reported() {
        // Both triangles lie left of (0,0) -> (2,0): their insides overlap there.
        let big = ring(&[(0.0, 0.0), (2.0, 0.0), (1.0, 2.0)]);
        let small = ring(&[(0.0, 0.0), (2.0, 0.0), (1.0, 1.0)]);
        let clean = super::conventional_rings(&RawRings::from_rings(vec![big, small]), &mut Touches::default());
        assert!(clean.broken_form);
        // Run opposite ways, the shared edge bounds nothing and the rings merge.
        let left = ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
        let right = ring(&[(1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0)]);
        let clean = super::conventional_rings(&RawRings::from_rings(vec![left, right]), &mut Touches::default());
        assert!(!clean.broken_form);
    }

    #[test]
    fn rings_leaving_or_arriving_at_a_point_the_same_way_are_reported() {
        // A square and a triangle inside it, both leaving (2,0) upwards, to different ends:
        // the square's (2,2) and the triangle's (2,1). Vertical edges are not split.
        let square = ring(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]);
        let leaving = ring(&[(2.0, 0.0), (2.0, 1.0), (1.5, 0.5)]);
        let clean =
            super::conventional_rings(&RawRings::from_rings(vec![square.clone(), leaving]), &mut Touches::default());
        assert!(clean.broken_form);
        // A clockwise triangle arriving at (2,2) along the square's right edge from (2,1): a
        // hole poking out of its outer.
        let arriving = ring(&[(2.0, 1.0), (2.0, 2.0), (2.5, 1.5)]);
        let clean =
            super::conventional_rings(&RawRings::from_rings(vec![square.clone(), arriving]), &mut Touches::default());
        assert!(clean.broken_form);
        // Touching at (0,0) in other directions is a valid form.
        let beside = ring(&[(0.0, 0.0), (-1.0, 0.0), (-1.0, -1.0)]);
        let clean = super::conventional_rings(&RawRings::from_rings(vec![square, beside]), &mut Touches::default());
        assert!(!clean.broken_form);
    }

    #[test]
    fn clockwise_rings_held_by_no_ring_are_reported() {
        // A clockwise triangle touching a square at its corner, outside it: an outer turned
        // inside out.
        let square = ring(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]);
        let outside = ring(&[(2.0, 2.0), (3.0, 4.0), (4.0, 3.0)]);
        let clean =
            super::conventional_rings(&RawRings::from_rings(vec![square.clone(), outside]), &mut Touches::default());
        assert!(clean.broken_form);
        // The same triangle inside the square, touching it at that corner: a hole.
        let inside = ring(&[(2.0, 2.0), (1.0, 0.5), (0.5, 1.0)]);
        let clean = super::conventional_rings(&RawRings::from_rings(vec![square, inside]), &mut Touches::default());
        assert!(!clean.broken_form);
    }

    #[test]
    fn a_hole_retracing_its_outers_edge_is_valid_where_the_rebuilt_rings_meet_cleanly() {
        // The outer runs up x = 4 through (4,1), (4,2), (4,3); the hole runs down it from (4,3) to
        // (4,1) and back up from (4,2) to (4,3): along (4,2)-(4,3) two edges go up, one down.
        let outer = ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 1.0), (4.0, 2.0), (4.0, 3.0), (4.0, 4.0), (0.0, 4.0)]);
        let hole =
            ring(&[(4.0, 3.0), (4.0, 2.0), (4.0, 1.0), (3.0, 1.5), (4.0, 2.0), (4.0, 3.0), (3.0, 3.0), (3.5, 3.5)]);
        let raw = RawRings::from_rings(vec![outer, hole]);
        let clean = |strict: bool, near: bool| {
            super::conventional_rings_checked(&raw, &mut Touches::default(), &mut Turns::default(), strict, || near)
        };
        let plain = clean(false, true);
        assert!(!plain.broken_form);
        assert_eq!(areas(&plain.rings), vec![-0.25, 15.5]);
        assert!(!clean(true, false).broken_form);
        // Near rounding and strict, the rebuilt rings are checked where they share a point: the
        // hole touches its outer at (4,1) and (4,3) without crossing it, so the form holds.
        assert!(!clean(true, true).broken_form);
    }

    #[test]
    fn after_a_near_miss_slanted_edges_split_and_opposite_overlaps_cancel() {
        // One ring runs up y = x from (0,0) to (4,4) and later down it from (3,3) to (1,1): no
        // point repeats and no horizontal edge holds a vertex, so only the sweep's near miss
        // (rounded edges through exact points) has the clean-up look at slanted edges.
        let points = ring(&[(0.0, 0.0), (4.0, 4.0), (1.0, 4.0), (3.0, 3.0), (1.0, 1.0), (0.0, 2.0)]);
        let mut raw = RawRings::from_rings(vec![points]);
        let clean = super::conventional_rings(&raw, &mut Touches::default());
        assert_eq!(clean.rings.len(), 1, "untouched without a near miss");
        raw.near_miss = true;
        let clean = super::conventional_rings(&raw, &mut Touches::default());
        assert!(!clean.broken_form);
        assert_eq!(areas(&clean.rings), vec![1.0, 1.5]);
    }

    #[test]
    fn untouched_rings_only_lose_collinear_vertices() {
        let square = ring(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]);
        let hole = ring(&[(0.5, 0.5), (0.5, 1.5), (1.5, 1.5), (1.5, 0.5)]);
        let out = conventional_rings(vec![square, hole]);
        assert_eq!(areas(&out), vec![-1.0, 4.0]);
        assert_eq!(out.iter().map(Ring::len).collect::<Vec<_>>(), vec![4, 4]);
    }

    /// Walks `raw`'s touched rings both ways when the turns can be planned, asserting that the
    /// planned walk gives the rebuild's rings and verdict (strict or not, near rounding or not).
    /// False when they cannot be planned: only the rebuild applies.
    fn assert_walks_agree(raw: &RawRings) -> bool {
        let (mut touches, mut turns) = (Touches::default(), Turns::default());
        touches.find(raw);
        if !(touches.touched.contains(&true)
            && touches.splits.is_empty()
            && turns.plan(raw, &touches, &touches.touched))
        {
            return false;
        }
        for (strict, near) in [(true, true), (true, false), (false, true), (false, false)] {
            let planned = walked(raw, &touches, Walk::planned(&mut turns, &touches), strict, || near);
            let rebuilt = walked(raw, &touches, Walk::rebuilt(&touches), strict, || near);
            assert_eq!(
                (&planned.rings, planned.broken_form),
                (&rebuilt.rings, rebuilt.broken_form),
                "the planned walk differs from the rebuild (strict {strict}, near rounding {near}) on {raw:?}"
            );
        }
        true
    }

    /// Rings as sorted lists of points, each from its least point: the same rings in any order.
    fn ring_set(rings: &[Ring]) -> Vec<Vec<(f64, f64)>> {
        let mut set: Vec<Vec<(f64, f64)>> = rings
            .iter()
            .map(|r| {
                let p: Vec<(f64, f64)> = r.points.iter().map(|q| (q.x, q.y)).collect();
                let least = (0..p.len()).min_by(|&a, &b| p[a].partial_cmp(&p[b]).unwrap()).unwrap_or(0);
                p[least..].iter().chain(&p[..least]).copied().collect()
            })
            .collect();
        set.sort_by(|a, b| a.partial_cmp(b).unwrap());
        set
    }

    /// Where some edge needs a split and the rings meeting none can be walked along the turns,
    /// asserts that walking them apart gives the rebuild's rings (in another order) and verdict.
    /// False when the walk cannot be split.
    fn assert_split_walk_agrees(raw: &RawRings) -> bool {
        let (mut touches, mut turns) = (Touches::default(), Turns::default());
        touches.find(raw);
        let walk = chosen_walk(raw, &touches, &mut turns, 0);
        if walk.turns.is_none() || !walk.rebuilt.contains(&true) {
            return false;
        }
        let (planned, rebuilt) = (walk.planned.into_owned(), walk.rebuilt.into_owned());
        for (strict, near) in [(true, true), (true, false), (false, true), (false, false)] {
            let mut turns = Turns::default();
            assert!(turns.plan(raw, &touches, &planned));
            let walk =
                Walk { turns: Some(&mut turns), planned: Cow::Borrowed(&planned), rebuilt: Cow::Borrowed(&rebuilt) };
            let split = walked(raw, &touches, walk, strict, || near);
            let whole = walked(raw, &touches, Walk::rebuilt(&touches), strict, || near);
            assert_eq!(
                (ring_set(&split.rings), split.broken_form),
                (ring_set(&whole.rings), whole.broken_form),
                "the split walk differs from the rebuild (strict {strict}, near rounding {near}) on {raw:?}"
            );
        }
        true
    }

    #[test]
    fn rings_meeting_no_split_are_walked_apart_with_the_rebuilds_result() {
        // A comb xor's raw rings: pieces touching at corners, and one ring whose spine runs out
        // and back along y = -2 (a horizontal edge holding a vertex: it splits), with the two
        // pieces it touches. {2, 5} meet no split and are walked along the turns.
        let rings = vec![
            ring(&[
                (9.0, 8.0),
                (9.0, 7.0),
                (10.0, 7.0),
                (10.0, -2.0),
                (1.0, -2.0),
                (1.0, 6.0),
                (0.0, 6.0),
                (0.0, -2.0),
                (10.0, -2.0),
                (11.0, -2.0),
                (11.0, 8.0),
            ]),
            ring(&[(6.0, 6.0), (6.0, 0.0), (7.0, 0.0), (7.0, 6.0)]),
            ring(&[(1.0, 7.0), (1.0, 6.0), (2.0, 6.0), (2.0, 0.0), (3.0, 0.0), (3.0, 7.0)]),
            ring(&[(8.0, 7.0), (8.0, 0.0), (9.0, 0.0), (9.0, 7.0)]),
            ring(&[(4.0, 8.0), (4.0, 0.0), (5.0, 0.0), (5.0, 6.0), (6.0, 6.0), (6.0, 8.0)]),
        ];
        let raw = RawRings::from_rings(rings);
        let mut touches = Touches::default();
        touches.find(&raw);
        assert_eq!(touches.rings_to_split(&raw), [true, false, true, true, false]);
        assert!(assert_split_walk_agrees(&raw));
        let out = super::conventional_rings(&raw, &mut Touches::default());
        assert_eq!(out.rings.len(), 6);
        assert!(!out.broken_form);
    }

    #[test]
    fn the_planned_walk_gives_the_rebuilds_rings() {
        let square = ring(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]);
        let planned = [
            // A bow tie: one ring through (1, 1) twice.
            vec![ring(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0), (2.0, 2.0), (1.0, 1.0), (0.0, 2.0)])],
            // A hole touching its outer at a corner.
            vec![square.clone(), ring(&[(2.0, 2.0), (1.0, 0.5), (0.5, 1.0)])],
            // A hole pinched to its outer at two corners.
            vec![square.clone(), ring(&[(0.0, 0.0), (0.5, 1.5), (2.0, 2.0), (1.5, 0.5)])],
            // Two outers touching at a corner.
            vec![square.clone(), ring(&[(2.0, 2.0), (3.0, 2.0), (3.0, 3.0), (2.0, 3.0)])],
        ];
        for rings in planned {
            assert!(assert_walks_agree(&RawRings::from_rings(rings.clone())), "planned: {rings:?}");
        }
        // Sharing an edge both ways (it cancels), and a horizontal edge holding a vertex (it
        // splits): the rebuild's alone.
        let rebuilt = [
            vec![square.clone(), ring(&[(2.0, 0.0), (4.0, 0.0), (4.0, 2.0), (2.0, 2.0)])],
            vec![square.clone(), ring(&[(1.0, -1.0), (3.0, -1.0), (3.0, 0.0), (1.0, 0.0)])],
        ];
        for rings in rebuilt {
            assert!(!assert_walks_agree(&RawRings::from_rings(rings.clone())), "rebuilt: {rings:?}");
        }
    }

    /// Runs `check` on the sweep's raw rings of `subject op clip` under `fill`, by both sweeps.
    fn on_swept_rings(
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
        check: &mut impl FnMut(&RawRings),
    ) {
        for sweep in [Sweep::Events, Sweep::Scanbeam] {
            crate::Vatti::sweep(sweep, subject, clip, op, fill, false, false, |raw, _, _, _| check(raw));
        }
    }

    #[test]
    fn on_the_sweeps_rings_the_walks_agree_and_so_do_the_held_tests() {
        let (mut planned, mut split, mut holes) = (0, 0, 0);
        let mut check = |raw: &RawRings| {
            planned += usize::from(assert_walks_agree(raw));
            split += usize::from(assert_split_walk_agrees(raw));
            let clean = super::conventional_rings(raw, &mut Touches::default());
            holes += assert_batched_agrees(&clean.rings);
        };
        for workload in ["grid", "holes", "scribble", "multi"] {
            for index in 0..12 {
                let case = polygon_case(workload, 1, index, WindowKind::Any).expect("a polygon workload");
                for op in BoolOp::ALL {
                    for fill in [FillRule::EvenOdd, FillRule::NonZero] {
                        on_swept_rings(&case.subject, &case.clip, op, fill, &mut check);
                    }
                }
            }
        }
        for index in 0..4 {
            let case = polygon_case_sized("comb", 1, index, 200, WindowKind::Any).expect("a polygon workload");
            for op in BoolOp::ALL {
                on_swept_rings(&case.subject, &case.clip, op, FillRule::EvenOdd, &mut check);
            }
        }
        // Every path was taken often enough to mean something.
        assert!(
            planned >= 300 && split >= 8 && holes >= 3000,
            "{planned} planned walks, {split} split walks, {holes} clockwise rings"
        );
    }

    /// Rings on a 6 x 6 integer grid: many shared points, pinches, shared edges and holes.
    fn grid_rings() -> impl Strategy<Value = Polygons> {
        let ring = prop::collection::vec((0u8..6, 0u8..6), 3..9)
            .prop_map(|v| Ring::new(v.into_iter().map(|(x, y)| Point::new(x.into(), y.into())).collect()));
        prop::collection::vec(ring, 1..4).prop_map(Polygons::new)
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

        #[test]
        fn on_grid_rings_the_walks_agree_and_so_do_the_held_tests(
            subject in grid_rings(),
            clip in grid_rings(),
            op in prop::sample::select(BoolOp::ALL.to_vec()),
            fill in prop::sample::select(FillRule::ALL.to_vec()),
        ) {
            prop_assume!(validate_polygons(&subject, Operand::Subject).is_ok());
            prop_assume!(validate_polygons(&clip, Operand::Clip).is_ok());
            on_swept_rings(&subject, &clip, op, fill, &mut |raw: &RawRings| {
                assert_walks_agree(raw);
                assert_split_walk_agrees(raw);
                assert_batched_agrees(&super::conventional_rings(raw, &mut Touches::default()).rings);
            });
        }
    }
}
