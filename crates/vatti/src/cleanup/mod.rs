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
//! - `rebuild`: the general walk through directed edges.
//!
//! Where `turns` can plan a walk, it and `rebuild` give the same rings; production runs the plan
//! alone, and the tests hold the two against each other.
//!
//! Nothing here checks the form for rounding: the sweep's output is the exact arrangement's
//! where it is taken at all (`rounding_certificate`).

mod directions;
mod rebuild;
mod simple_loops;
mod touches;
mod turns;

use std::borrow::Cow;

use clip_core::{Point, Ring};

use self::rebuild::rebuild;
pub(crate) use self::touches::Touches;
pub(crate) use self::turns::Turns;
use crate::raw_rings::RawRings;
use crate::simplify::simplify_ring;

/// Touched rings from which, when some edge needs a split, the rings meeting none are walked
/// along the turns apart from the rebuilt ones: below it, finding them costs more than
/// rebuilding them.
const SPLIT_WALK_FROM: usize = 64;

/// The sweep's rings as conventional output rings. Only rings that share a point with another
/// ring (or with themselves) or have a vertex inside a horizontal edge are rebuilt; the others
/// are already simple and lose only collinear vertices. `touches` and `turns` are reused work
/// buffers.
pub(crate) fn conventional_rings(raw: &RawRings, touches: &mut Touches, turns: &mut Turns) -> Vec<Ring> {
    touches.find(raw);
    let walk = chosen_walk(raw, touches, turns, SPLIT_WALK_FROM);
    walked(raw, touches, walk)
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
/// ([`rebuild`]). The two sets meet nowhere, so each walk gives the rings it would give walking
/// every touched ring, and where the turns can be planned for every touched ring they give the
/// rebuild's rings in its order.
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

/// The untouched rings of `raw` simplified, then the touched ones walked again by `walk`.
fn walked(raw: &RawRings, touches: &Touches, walk: Walk) -> Vec<Ring> {
    let mut out = Vec::with_capacity(raw.len());
    for (i, &t) in touches.touched.iter().enumerate() {
        if !t {
            push_simplified(raw.ring(i), &mut out);
        }
    }
    if !touches.touched.contains(&true) {
        return out;
    }
    if let Some(turns) = walk.turns {
        turns.walk(raw, touches, &walk.planned, &mut |points: &[Point]| push_simplified(points, &mut out));
    }
    if walk.rebuilt.contains(&true) {
        rebuild(raw, touches, &walk.rebuilt, &mut |points: &[Point]| push_simplified(points, &mut out));
    }
    out
}

/// `points` as a ring without repeated or collinear vertices, pushed onto `out` unless that
/// leaves fewer than three.
fn push_simplified(points: &[Point], out: &mut Vec<Ring>) {
    let s = simplify_ring(points);
    if s.len() >= 3 {
        out.push(Ring::new(s));
    }
}

#[cfg(test)]
mod tests {
    use clip_core::{BoolOp, FillRule, Operand, Polygons, WindowKind, validate_polygons};
    use clip_testkit::workload::{polygon_case, polygon_case_sized};
    use proptest::prelude::*;

    use super::*;
    use crate::Sweep;

    fn conventional_rings(rings: Vec<Vec<Point>>) -> Vec<Ring> {
        clean(&RawRings::from_rings(rings))
    }

    fn clean(raw: &RawRings) -> Vec<Ring> {
        super::conventional_rings(raw, &mut Touches::default(), &mut Turns::default())
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
    fn a_hole_retracing_its_outers_edge_is_rebuilt_into_a_hole_touching_it() {
        // The outer runs up x = 4 through (4,1), (4,2), (4,3); the hole runs down it from (4,3) to
        // (4,1) and back up from (4,2) to (4,3): along (4,2)-(4,3) two edges go up, one down.
        let outer = ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 1.0), (4.0, 2.0), (4.0, 3.0), (4.0, 4.0), (0.0, 4.0)]);
        let hole =
            ring(&[(4.0, 3.0), (4.0, 2.0), (4.0, 1.0), (3.0, 1.5), (4.0, 2.0), (4.0, 3.0), (3.0, 3.0), (3.5, 3.5)]);
        assert_eq!(areas(&conventional_rings(vec![outer, hole])), vec![-0.25, 15.5]);
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
    /// planned walk gives the rebuild's rings. False when they cannot be planned: only the
    /// rebuild applies.
    fn assert_walks_agree(raw: &RawRings) -> bool {
        let (mut touches, mut turns) = (Touches::default(), Turns::default());
        touches.find(raw);
        if !(touches.touched.contains(&true)
            && touches.splits.is_empty()
            && turns.plan(raw, &touches, &touches.touched))
        {
            return false;
        }
        let planned = walked(raw, &touches, Walk::planned(&mut turns, &touches));
        let rebuilt = walked(raw, &touches, Walk::rebuilt(&touches));
        assert_eq!(planned, rebuilt, "the planned walk differs from the rebuild on {raw:?}");
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
    /// asserts that walking them apart gives the rebuild's rings (in another order).
    /// False when the walk cannot be split.
    fn assert_split_walk_agrees(raw: &RawRings) -> bool {
        let (mut touches, mut turns) = (Touches::default(), Turns::default());
        touches.find(raw);
        let walk = chosen_walk(raw, &touches, &mut turns, 0);
        if walk.turns.is_none() || !walk.rebuilt.contains(&true) {
            return false;
        }
        let (planned, rebuilt) = (walk.planned.into_owned(), walk.rebuilt.into_owned());
        let mut turns = Turns::default();
        assert!(turns.plan(raw, &touches, &planned));
        let walk = Walk { turns: Some(&mut turns), planned: Cow::Borrowed(&planned), rebuilt: Cow::Borrowed(&rebuilt) };
        let split = walked(raw, &touches, walk);
        let whole = walked(raw, &touches, Walk::rebuilt(&touches));
        assert_eq!(ring_set(&split), ring_set(&whole), "the split walk differs from the rebuild on {raw:?}");
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
        assert_eq!(clean(&raw).len(), 6);
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
            crate::Vatti::sweep(sweep, subject, clip, op, fill, false, false, crate::Certify::No, |raw, _, _, _, _| {
                check(raw)
            });
        }
    }

    #[test]
    fn on_the_sweeps_rings_the_walks_agree() {
        let (mut planned, mut split) = (0, 0);
        let mut check = |raw: &RawRings| {
            planned += usize::from(assert_walks_agree(raw));
            split += usize::from(assert_split_walk_agrees(raw));
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
        assert!(planned >= 300 && split >= 8, "{planned} planned walks, {split} split walks");
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
        fn on_grid_rings_the_walks_agree(
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
            });
        }
    }
}
