//! The cyclic point list and the point-splitting walk over it.

use clip_core::{Point, Rect};

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

/// Clips one closed point list to `rect` by the four-state walk, as the paper writes it.
pub fn clip_points(points: &[Point], rect: &Rect) -> Vec<Point> {
    clip_points_observed(points, rect, |_| {})
}

/// [`clip_points`], reporting every step to `observe`.
///
/// The list is cyclic: the previous point of the first is the last, the next of the last is the
/// first. `current` is an index into the list; removing the current point makes the following
/// point current. A point is finished when it is inside the fourth state; the walk ends when
/// the index runs past the end of the list.
///
/// It terminates: a half is removed, or slides along the line to its neighbour onto a boundary,
/// towards the neighbour and never past it (the neighbour is inside that boundary), so a half
/// that keeps its neighbour moves at most once per boundary; a half made from an already moved
/// point has its sibling, on the same boundary line, as neighbour, and slides along that line.
pub fn clip_points_observed(points: &[Point], rect: &Rect, mut observe: impl FnMut(Event)) -> Vec<Point> {
    let mut list = points.to_vec();
    let mut current = 0;
    let mut state = State::MinY;
    while current < list.len() {
        let p = list[current];
        if state.inside(p, rect) {
            observe(Event::Inside { index: current, state });
            match state.next() {
                Some(next) => state = next,
                None => {
                    current += 1;
                    state = State::MinY;
                }
            }
            continue;
        }
        // Divide: (prev - p - next) becomes (prev - pa - pb - next), both at p.
        observe(Event::Divide { index: current, state });
        list.insert(current + 1, p);
        let mut moved = false;
        // First sub-point: its next point is the previous one in the list.
        let prev = list[(current + list.len() - 1) % list.len()];
        let mut second = current + 1;
        if state.inside(prev, rect) {
            let to = state.move_towards(p, prev, rect);
            list[current] = to;
            observe(Event::Move { index: current, state, to });
            moved = true;
        } else {
            observe(Event::Remove { index: current, state });
            list.remove(current);
            second = current;
        }
        // Second sub-point: its next point is the following one in the list.
        let next = list[(second + 1) % list.len()];
        if state.inside(next, rect) {
            let to = state.move_towards(p, next, rect);
            list[second] = to;
            observe(Event::Move { index: second, state, to });
            moved = true;
        } else {
            observe(Event::Remove { index: second, state });
            list.remove(second);
        }
        // Both removed: the point now at `current` is unknown, start over at state one.
        // Moved: the current point is inside this boundary and its opposite.
        state = if moved { state.after_move() } else { State::MinY };
    }
    list
}
