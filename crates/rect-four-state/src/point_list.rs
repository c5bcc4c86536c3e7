//! The cyclic point list and the point-splitting walk over it.

use clip_core::{Point, Rect};

use crate::start::{WalkStart, enclosed_rectangle, walk_start};
use crate::state::State;

/// One step of the walk, reported to an observer (the unit tests follow the paper's steps).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Event {
    /// The point at `index` is inside `state`'s clip region and goes on.
    Inside {
        /// Position in the current list.
        index: usize,
        /// The state.
        state: State,
    },
    /// The point at `index` is outside and is divided into two at the same place.
    Divide {
        /// Position of the first sub-point; the second is at `index + 1`.
        index: usize,
        /// The state.
        state: State,
    },
    /// A sub-point is moved along the line to its next point, onto `state`'s boundary.
    Move {
        /// Position of the sub-point.
        index: usize,
        /// The state.
        state: State,
        /// Where it was moved to.
        to: Point,
    },
    /// A sub-point is removed, because its next point is outside too.
    Remove {
        /// Position it had.
        index: usize,
        /// The state.
        state: State,
    },
}

/// Clips one closed point list to `rect` by the four-state walk.
pub fn clip_points(points: &[Point], rect: &Rect) -> Vec<Point> {
    clip_points_observed(points, rect, |_| {})
}

/// [`clip_points`], reporting every step of the walk to `observe`.
///
/// The walk starts at a point inside the rectangle (see the crate docs, "Where the walk
/// starts", for why and for polygons with none), so every point's previous point is finished (inside all
/// four states) when the point is taken, and then the walk ends: a half moved towards a finished
/// point, or towards a fixed next point inside the boundary it was moved onto, stays inside that
/// boundary from then on, so each half moves at most once per boundary.
pub fn clip_points_observed(points: &[Point], rect: &Rect, observe: impl FnMut(Event)) -> Vec<Point> {
    match walk_start(points, rect) {
        WalkStart::From(mut list) => {
            // From a start inside, the walk ends long before usize::MAX steps (see above).
            walk(&mut list, rect, usize::MAX, observe);
            list
        }
        WalkStart::Enclosed { winding } => enclosed_rectangle(rect, winding),
    }
}

/// The paper's walk exactly as written, from the list's first point, giving up after
/// `max_steps` steps (one step per state check). `None` when it gave up.
///
/// As written, the walk need not end: when the first point lies outside two boundaries near a
/// corner and its previous point (the list's last, not yet processed) is outside too, the point
/// slides back and forth between the two sides towards the corner for ever. [`clip_points`]
/// avoids this by where it starts; this function is kept to show the paper's rules (including
/// removing both halves and restarting, which only an unprocessed previous point can cause).
pub fn walk_as_written(
    points: &[Point],
    rect: &Rect,
    max_steps: usize,
    observe: impl FnMut(Event),
) -> Option<Vec<Point>> {
    let mut list = points.to_vec();
    walk(&mut list, rect, max_steps, observe).then_some(list)
}

/// The walk over the cyclic list. The list is kept as the finished points (`done`, inside all
/// four states) followed by the points still to walk (`ahead`, a stack whose top is the current
/// point), so dividing and removing at the current point cost O(1). Removing the current point
/// makes the following point current. A point is finished when it is inside the fourth state;
/// the walk ends when no point is left ahead. Returns false when it stopped after `max_steps`
/// steps (one per state check) instead.
fn walk(list: &mut Vec<Point>, rect: &Rect, max_steps: usize, mut observe: impl FnMut(Event)) -> bool {
    let mut done: Vec<Point> = Vec::with_capacity(list.len() + 8);
    let mut ahead: Vec<Point> = list.drain(..).rev().collect();
    let mut state = State::MinY;
    let mut steps = 0usize;
    while let Some(&p) = ahead.last() {
        if steps == max_steps {
            list.extend(done);
            list.extend(ahead.iter().rev());
            return false;
        }
        steps += 1;
        let current = done.len();
        if state.inside(p, rect) {
            observe(Event::Inside { index: current, state });
            match state.next() {
                Some(next) => state = next,
                None => {
                    ahead.pop();
                    done.push(p);
                    state = State::MinY;
                }
            }
            continue;
        }
        // Divide: (prev - p - next) becomes (prev - pa - pb - next), both at p; pa is current.
        observe(Event::Divide { index: current, state });
        ahead.push(p);
        let mut moved = false;
        // First sub-point: its next point is the previous one in the cyclic list.
        let prev = done.last().copied().unwrap_or(ahead[0]);
        let top = ahead.len() - 1;
        if state.inside(prev, rect) {
            let to = state.move_towards(p, prev, rect);
            ahead[top] = to;
            observe(Event::Move { index: current, state, to });
            moved = true;
        } else {
            observe(Event::Remove { index: current, state });
            ahead.pop();
        }
        // Second sub-point, just below the top: its next point is the following one.
        let second = top - 1;
        let next = if second > 0 { ahead[second - 1] } else { done.first().copied().unwrap_or(ahead[second]) };
        let index = if moved { current + 1 } else { current };
        if state.inside(next, rect) {
            let to = state.move_towards(p, next, rect);
            ahead[second] = to;
            observe(Event::Move { index, state, to });
            moved = true;
        } else {
            observe(Event::Remove { index, state });
            ahead.remove(second);
        }
        // Both removed: the point now current is unknown, start over at state one.
        // Moved: the current point is inside this boundary and its opposite.
        state = if moved { state.after_move() } else { State::MinY };
    }
    *list = done;
    true
}
