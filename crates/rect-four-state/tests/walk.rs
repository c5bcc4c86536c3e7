//! The paper's divide / move / remove steps, its restart rules, and bad input.

use clip_core::{BoolOp, ClipError, FillRule, Point, PolygonClipper, Polygons, Rect, Ring, WindowKind};
use clip_rect_four_state::{Event, FourState, State, clip_points, clip_points_observed, walk_as_written};

fn pts(points: &[(f64, f64)]) -> Vec<Point> {
    points.iter().map(|&p| p.into()).collect()
}

fn steps(points: &[(f64, f64)], rect: &Rect) -> (Vec<Event>, Vec<Point>) {
    let mut events = Vec::new();
    let out = clip_points_observed(&pts(points), rect, |e| events.push(e));
    (events, out)
}

/// The non-`Inside` steps, which are the ones the paper describes.
fn actions(events: &[Event]) -> Vec<Event> {
    events.iter().copied().filter(|e| !matches!(e, Event::Inside { .. })).collect()
}

const WINDOW: Rect = Rect::new(0.0, 0.0, 6.0, 6.0);

/// A point outside one boundary, with both neighbours inside: divided into (2a) and (2b), both
/// moved along their lines onto MaxY; the walk then goes on with the vertical states.
#[test]
fn outside_one_boundary_divide_and_move_both() {
    let (events, out) = steps(&[(1.0, 1.0), (5.0, 1.0), (3.0, 9.0)], &WINDOW);
    assert_eq!(
        actions(&events),
        vec![
            Event::Divide { index: 2, state: State::MaxY },
            Event::Move { index: 2, state: State::MaxY, to: Point::new(3.75, 6.0) },
            Event::Move { index: 3, state: State::MaxY, to: Point::new(2.25, 6.0) },
        ]
    );
    // After the move, (2a) is checked against MinX then MaxX only (rule 3: skip the horizontals).
    let after: Vec<Event> = events.iter().copied().skip_while(|e| !matches!(e, Event::Move { .. })).skip(2).collect();
    assert_eq!(after[0], Event::Inside { index: 2, state: State::MinX });
    assert_eq!(after[1], Event::Inside { index: 2, state: State::MaxX });
    assert_eq!(after[2], Event::Inside { index: 3, state: State::MinY });
    assert_eq!(out, pts(&[(1.0, 1.0), (5.0, 1.0), (3.75, 6.0), (2.25, 6.0)]));
}

/// A point outside two boundaries (beyond the top-right corner): divided at MaxY, both halves
/// moved onto y = 6; the first half is then outside MaxX, divided again, one half moved back along
/// its edge onto x = 6 and the other along y = 6 into the corner.
#[test]
fn outside_two_boundaries_divides_twice_and_reaches_the_corner() {
    let (events, out) = steps(&[(1.0, 1.0), (5.0, 1.0), (8.0, 7.0), (1.0, 5.0)], &WINDOW);
    let a = actions(&events);
    assert_eq!(a[0], Event::Divide { index: 2, state: State::MaxY });
    assert!(matches!(a[1], Event::Move { index: 2, state: State::MaxY, to } if to.y == 6.0));
    assert!(matches!(a[2], Event::Move { index: 3, state: State::MaxY, to } if to.y == 6.0));
    assert_eq!(a[3], Event::Divide { index: 2, state: State::MaxX });
    assert_eq!(a[4], Event::Move { index: 2, state: State::MaxX, to: Point::new(6.0, 3.0) });
    assert_eq!(a[5], Event::Move { index: 3, state: State::MaxX, to: Point::new(6.0, 6.0) });
    assert_eq!(a.len(), 6);
    assert_eq!(out[..4], pts(&[(1.0, 1.0), (5.0, 1.0), (6.0, 3.0), (6.0, 6.0)])[..]);
    assert_eq!(out[4].y, 6.0);
}

/// Rule 1 (remove when the next point is outside too): the second half of (5, 8) is removed
/// because (1, 8) is also above MaxY; (1, 8)'s first half then moves onto the kept point.
#[test]
fn a_half_whose_next_point_is_outside_is_removed() {
    let (events, out) = steps(&[(1.0, 1.0), (5.0, 1.0), (5.0, 8.0), (1.0, 8.0)], &WINDOW);
    assert_eq!(
        actions(&events),
        vec![
            Event::Divide { index: 2, state: State::MaxY },
            Event::Move { index: 2, state: State::MaxY, to: Point::new(5.0, 6.0) },
            Event::Remove { index: 3, state: State::MaxY },
            Event::Divide { index: 3, state: State::MaxY },
            Event::Move { index: 3, state: State::MaxY, to: Point::new(5.0, 6.0) },
            Event::Move { index: 4, state: State::MaxY, to: Point::new(1.0, 6.0) },
        ]
    );
    let ring = Ring::new(out).without_repeats();
    assert_eq!(ring.points, pts(&[(1.0, 1.0), (5.0, 1.0), (5.0, 6.0), (1.0, 6.0)]));
}

/// Restart rule 2: both halves removed, the following point becomes current and starts over at
/// state one. The list is cyclic: the first point's previous point is the last. Only the walk as
/// written can get there (its first point is outside, with an unprocessed previous point).
#[test]
fn both_halves_removed_restarts_at_state_one_with_the_next_point() {
    let mut events = Vec::new();
    let ring = pts(&[(3.0, 9.0), (1.0, 8.0), (1.0, 1.0), (5.0, 1.0), (5.0, 8.0)]);
    let out = walk_as_written(&ring, &WINDOW, 1000, |e| events.push(e)).expect("this walk ends");
    assert_eq!(
        events[..5],
        [
            Event::Inside { index: 0, state: State::MinY },
            Event::Divide { index: 0, state: State::MaxY },
            Event::Remove { index: 0, state: State::MaxY },
            Event::Remove { index: 0, state: State::MaxY },
            Event::Inside { index: 0, state: State::MinY },
        ]
    );
    assert_eq!(Ring::new(out).without_repeats().signed_area(), 20.0);
    // Started inside instead, the same ring gives the same region.
    assert_eq!(Ring::new(clip_points(&ring, &WINDOW)).without_repeats().signed_area(), 20.0);
}

/// The walk as written does not end when its first point is outside near a corner with an
/// unprocessed previous point: the point slides towards the corner for ever. Starting inside
/// (or, with no vertex inside, on an edge that meets the rectangle) fixes it.
#[test]
fn the_walk_as_written_can_run_for_ever_and_the_inside_start_ends() {
    // `star` workload, seed 11, case 7: the first vertex is below MinY and right of MaxX, and
    // so are, on one side each, its two neighbours.
    let star = pts(&[
        (750.80418452633, 378.8410636457391),
        (794.0672816221211, 589.6885445192668),
        (605.5448409741575, 610.799312003817),
        (588.9981655250713, 633.2938266549758),
        (469.9033653136179, 858.5321602610477),
        (423.5553188652996, 598.1307028777048),
        (340.3993534655799, 544.9293029633998),
        (304.4849270714639, 447.3052151773924),
        (301.77675362654963, 307.5876281321233),
        (409.9517618678025, 158.6654463576292),
        (528.8713461816368, 189.91062396625216),
        (573.362250672888, 403.0289032403639),
    ]);
    let window = Rect::new(330.36974738258743, 546.8760693873827, 731.0205678874562, 808.1777526209058);
    assert_eq!(walk_as_written(&star, &window, 100_000, |_| {}), None);
    let out = clip_points(&star, &window);
    assert!(out.iter().all(|p| window.contains(*p)));
    assert!(out.contains(&Point::new(window.max.x, window.min.y)), "the corner the walk slid towards");
    // Every vertex outside, edges crossing the window: the walk starts where an edge meets it,
    // and gives what the walk as written gives when that one ends.
    let corner_first = pts(&[(7.0, -1.0), (8.0, 3.0), (3.0, 8.0), (-2.0, 3.0), (2.0, -3.0)]);
    let as_written = walk_as_written(&corner_first, &WINDOW, 100_000, |_| {}).expect("this one ends");
    let from_edge = clip_points(&corner_first, &WINDOW);
    assert_eq!(Ring::new(from_edge).signed_area(), Ring::new(as_written).signed_area());
    // A square around the window: no edge meets it, so the answer is the window, once, in the
    // square's sense.
    let around = pts(&[(-10.0, -10.0), (20.0, -10.0), (20.0, 20.0), (-10.0, 20.0)]);
    assert_eq!(Ring::new(clip_points(&around, &WINDOW)).signed_area(), 36.0);
    let reversed: Vec<Point> = around.iter().rev().copied().collect();
    assert_eq!(Ring::new(clip_points(&reversed, &WINDOW)).signed_area(), -36.0);
    // Far away: nothing.
    let far = pts(&[(10.0, 10.0), (20.0, 10.0), (20.0, 20.0)]);
    assert!(clip_points(&far, &WINDOW).is_empty());
}

#[test]
fn a_polygon_wholly_outside_vanishes_and_one_inside_is_untouched() {
    let outside = pts(&[(10.0, 1.0), (12.0, 1.0), (11.0, 3.0)]);
    assert!(clip_points(&outside, &WINDOW).is_empty());
    let inside = pts(&[(1.0, 1.0), (2.0, 1.0), (1.0, 2.0)]);
    assert_eq!(clip_points(&inside, &WINDOW), inside);
}

#[test]
fn an_edge_cutting_across_a_corner_outside_goes_through_the_corner() {
    // (-3, 2) is left of the window, (2, -3) below it; their edge passes outside (0, 0).
    let out = FourState.clip_to_rect(&Polygons::from(Ring::from(&[(-3.0, 2.0), (2.0, -3.0), (5.0, 5.0)][..])), &WINDOW);
    assert!(out.rings[0].points.contains(&Point::new(0.0, 0.0)), "{out:?}");
}

#[test]
fn bad_input_gets_a_typed_error() {
    let subject = Polygons::from(Rect::new(0.0, 0.0, 2.0, 2.0));
    let clip = |s: &Polygons, w: &Polygons| FourState.clip(s, w, BoolOp::Intersection, FillRule::EvenOdd);
    let triangle = Polygons::from(Ring::from(&[(0.0, 0.0), (4.0, 0.0), (2.0, 3.0)][..]));
    assert!(matches!(clip(&subject, &triangle), Err(ClipError::WindowNotRectangle { .. })));
    let tilted = Polygons::from(Ring::from(&[(1.0, 0.0), (2.0, 1.0), (1.0, 2.0), (0.0, 1.0)][..]));
    assert!(matches!(clip(&subject, &tilted), Err(ClipError::WindowNotRectangle { .. })));
    let flat = Polygons::from(Ring::from(&[(0.0, 0.0), (4.0, 0.0), (4.0, 0.0), (0.0, 0.0)][..]));
    assert!(clip(&subject, &flat).is_err());
    let nan = Polygons::from(Ring::from(&[(0.0, 0.0), (f64::INFINITY, 1.0), (1.0, 1.0)][..]));
    assert!(matches!(clip(&nan, &subject), Err(ClipError::NonFinite { .. })));
    for op in [BoolOp::Union, BoolOp::Difference, BoolOp::Xor] {
        assert!(matches!(
            FourState.clip(&subject, &subject, op, FillRule::NonZero),
            Err(ClipError::Unsupported { .. })
        ));
    }
    let caps = FourState.capabilities();
    assert_eq!((caps.window, caps.bridges, FourState.name()), (WindowKind::Rectangle, true, "rect-four-state"));
}
