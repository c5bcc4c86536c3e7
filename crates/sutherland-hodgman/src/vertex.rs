//! What travels through the boundary stages: a plain point, or one that remembers the boundaries it lies on.

use clip_core::Point;

/// A vertex carried through the stages. [`Point`] is the plain case; [`TaggedVertex`] records
/// the boundaries a vertex lies on, so bridges can be counted without re-deciding geometry.
pub trait StageVertex: Copy {
    /// Its position.
    fn point(self) -> Point;
    /// The same vertex, known to lie exactly on boundary `k`.
    fn on_boundary(self, k: usize) -> Self;
    /// The crossing of edge `a -> b` with boundary `k`, placed at `at`.
    fn crossing(a: Self, b: Self, k: usize, at: Point) -> Self;
}

impl StageVertex for Point {
    #[inline]
    fn point(self) -> Point {
        self
    }
    #[inline]
    fn on_boundary(self, _k: usize) -> Self {
        self
    }
    #[inline]
    fn crossing(_a: Self, _b: Self, _k: usize, at: Point) -> Self {
        at
    }
}

/// No boundary: a free slot in [`TaggedVertex::on`].
const NONE: usize = usize::MAX;

/// A vertex with the (at most two) window boundaries it lies on. Two suffice: a point on three
/// edge lines of a strictly convex window does not exist.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TaggedVertex {
    /// Position.
    pub point: Point,
    /// Indices of boundaries it lies on; `usize::MAX` marks a free slot.
    pub on: [usize; 2],
}

impl TaggedVertex {
    /// An input vertex, on no boundary yet.
    pub fn new(point: Point) -> TaggedVertex {
        TaggedVertex { point, on: [NONE; 2] }
    }

    /// True when it lies on boundary `k`.
    pub fn is_on(&self, k: usize) -> bool {
        self.on.contains(&k)
    }

    /// The boundaries it lies on (none, one or two).
    pub fn boundaries(&self) -> impl Iterator<Item = usize> + '_ {
        self.on.iter().copied().filter(|&k| k != NONE)
    }

    /// A boundary both `self` and `other` lie on, if any.
    pub fn shared_boundary(&self, other: &TaggedVertex) -> Option<usize> {
        self.boundaries().find(|&k| other.is_on(k))
    }

    /// The same point reached twice in a row: one vertex on the boundaries of both (at most two).
    pub fn merged(self, other: &TaggedVertex) -> TaggedVertex {
        other.boundaries().fold(self, |v, k| if v.on[1] == NONE || v.is_on(k) { v.with(k) } else { v })
    }

    fn with(mut self, k: usize) -> TaggedVertex {
        if !self.is_on(k) {
            if self.on[0] == NONE {
                self.on[0] = k;
            } else {
                self.on[1] = k;
            }
        }
        self
    }
}

impl StageVertex for TaggedVertex {
    fn point(self) -> Point {
        self.point
    }
    fn on_boundary(self, k: usize) -> Self {
        self.with(k)
    }
    fn crossing(a: Self, b: Self, k: usize, at: Point) -> Self {
        // The crossing lies on boundary k, and on any boundary the whole edge a-b lies along.
        let shared = a.on.iter().copied().find(|&j| j != NONE && b.is_on(j));
        let v = TaggedVertex::new(at).with(k);
        match shared {
            Some(j) => v.with(j),
            None => v,
        }
    }
}
