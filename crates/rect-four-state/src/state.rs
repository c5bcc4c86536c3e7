//! The paper's four states: one clip condition each, tried in the order MinY, MaxY, MinX, MaxX.

use clip_core::{Point, Rect};

/// One clip boundary of the rectangle, the "current clip region" of a state.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum State {
    /// State one (horizontal): inside when `y >= MinY`.
    MinY,
    /// State two (horizontal): inside when `y <= MaxY`.
    MaxY,
    /// State three (vertical): inside when `x >= MinX`.
    MinX,
    /// State four (vertical): inside when `x <= MaxX`.
    MaxX,
}

impl State {
    /// The states in the order they are tried.
    pub const ORDER: [State; 4] = [State::MinY, State::MaxY, State::MinX, State::MaxX];

    /// True for the horizontal clip boundaries (states one and two).
    #[inline]
    pub fn is_horizontal(self) -> bool {
        matches!(self, State::MinY | State::MaxY)
    }

    /// The boundary's value: MinY, MaxY, MinX or MaxX of `rect`.
    #[inline]
    pub fn value(self, rect: &Rect) -> f64 {
        match self {
            State::MinY => rect.min.y,
            State::MaxY => rect.max.y,
            State::MinX => rect.min.x,
            State::MaxX => rect.max.x,
        }
    }

    /// The paper's clip condition (boundary included); exact, it only compares coordinates.
    #[inline]
    pub fn inside(self, p: Point, rect: &Rect) -> bool {
        match self {
            State::MinY => p.y >= rect.min.y,
            State::MaxY => p.y <= rect.max.y,
            State::MinX => p.x >= rect.min.x,
            State::MaxX => p.x <= rect.max.x,
        }
    }

    /// The state after this one when the point was inside, `None` after the fourth.
    #[inline]
    pub fn next(self) -> Option<State> {
        match self {
            State::MinY => Some(State::MaxY),
            State::MaxY => Some(State::MinX),
            State::MinX => Some(State::MaxX),
            State::MaxX => None,
        }
    }

    /// Where a moved point goes on: a point moved onto a horizontal boundary is inside both
    /// horizontal conditions, so the vertical states come next; after a vertical move the
    /// horizontal ones are unknown again (the paper's restart rule 3).
    #[inline]
    pub fn after_move(self) -> State {
        if self.is_horizontal() { State::MinX } else { State::MinY }
    }

    /// The paper's trace equations (2.4 for horizontal states, 1.4 for vertical ones): the point
    /// on the line from `current` towards `next` whose y (or x) is the boundary value. `next` is
    /// inside and `current` outside, so the line is never parallel to the boundary. When `next`
    /// lies on the boundary it is the answer, taken exactly; otherwise the other coordinate is
    /// clamped between the two points so rounding cannot overshoot.
    pub fn move_towards(self, current: Point, next: Point, rect: &Rect) -> Point {
        let c = self.value(rect);
        if self.is_horizontal() {
            if next.y == c {
                return next;
            }
            let x = current.x + (c - current.y) * ((next.x - current.x) / (next.y - current.y));
            Point::new(x.clamp(current.x.min(next.x), current.x.max(next.x)), c)
        } else {
            if next.x == c {
                return next;
            }
            let y = current.y + (c - current.x) * ((next.y - current.y) / (next.x - current.x));
            Point::new(c, y.clamp(current.y.min(next.y), current.y.max(next.y)))
        }
    }
}
