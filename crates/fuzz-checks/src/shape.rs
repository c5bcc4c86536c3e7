//! Polygon operands built from fuzz bytes: grid points, repeats, collinear runs, spikes, ulp nudges, shared vertices and raw floats, in a frame of any magnitude.

use arbitrary::Arbitrary;
use clip_core::{Point, Polygons, Ring};

/// Most rings an operand is built with (longer lists are cut: bounded work per input).
pub const MAX_RINGS: usize = 4;
/// Most vertex steps a ring is built from.
pub const MAX_STEPS: usize = 32;

/// Where the grid sits and how fine it is: the magnitudes clippers find hard (tiny steps far from
/// the origin, huge coordinates near `clip_core::MAX_COORDINATE`, tiny ones near `MIN_COORDINATE`).
#[derive(Arbitrary, Clone, Copy, Debug, PartialEq, Eq)]
pub struct Frame {
    /// The grid step.
    pub step: Step,
    /// The grid's origin.
    pub offset: Offset,
}

/// A grid step.
#[derive(Arbitrary, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// 1: integer grids, where every crossing of axis-parallel edges is exact.
    One,
    /// 1/8: still exact in binary, with more coincidences per unit.
    Eighth,
    /// 3: crossings of slanted edges land between grid points.
    Three,
    /// 1e-7: edges a few ulps apart once far from the origin.
    Tiny,
    /// 1e-90: a little above `clip_core::MIN_COORDINATE` (1e-100), where products of
    /// coordinate differences are still normal numbers.
    Minute,
    /// 1e6: UTM-like coordinates.
    Large,
    /// 1e140: close to `MAX_COORDINATE` (1e150).
    Huge,
}

impl Step {
    /// The step's length.
    pub fn value(self) -> f64 {
        match self {
            Step::One => 1.0,
            Step::Eighth => 0.125,
            Step::Three => 3.0,
            Step::Tiny => 1e-7,
            Step::Minute => 1e-90,
            Step::Large => 1e6,
            Step::Huge => 1e140,
        }
    }
}

/// The grid's origin.
#[derive(Arbitrary, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Offset {
    /// The origin.
    Zero,
    /// (0.1, 0.7): not representable, so every grid point is rounded.
    Fraction,
    /// (5e5, 4e6): UTM-sized.
    Utm,
    /// (1e9, 1e9): the `star-far` workload's offset.
    Far,
    /// (-1e15, 1e15): an ulp of 0.125.
    VeryFar,
    /// (1e149, -1e149): a tenth of `MAX_COORDINATE`.
    Edge,
}

impl Offset {
    /// The origin's coordinates.
    pub fn value(self) -> Point {
        match self {
            Offset::Zero => Point::new(0.0, 0.0),
            Offset::Fraction => Point::new(0.1, 0.7),
            Offset::Utm => Point::new(5e5, 4e6),
            Offset::Far => Point::new(1e9, 1e9),
            Offset::VeryFar => Point::new(-1e15, 1e15),
            Offset::Edge => Point::new(1e149, -1e149),
        }
    }
}

impl Frame {
    /// The point at grid coordinates `(i, j)`.
    pub fn grid(&self, i: i32, j: i32) -> Point {
        let (o, s) = (self.offset.value(), self.step.value());
        Point::new(o.x + f64::from(i) * s, o.y + f64::from(j) * s)
    }
}

/// One step of a ring's construction. Each adds zero or more vertices, mostly relative to the
/// last one, so the fuzzer's small byte changes make small geometric changes.
#[derive(Arbitrary, Clone, Copy, Debug, PartialEq)]
pub enum Vertex {
    /// A grid point, coordinates reduced to -16..=16 so points coincide often.
    Grid(i8, i8),
    /// The last vertex moved by a few grid steps (-8..=8); repeating it makes a collinear run.
    Move(i8, i8),
    /// The last vertex again (a repeated point).
    Repeat,
    /// Out by a few grid steps and straight back: a zero-width spike.
    Spike(i8, i8),
    /// The last vertex moved by a few ulps of its coordinates: near-coincident points and edges.
    Nudge(i8, i8),
    /// A vertex already made for this case, either operand (shared vertices, fans, shared edges).
    Reuse(u8),
    /// The point `k/8` of the way from one earlier vertex to the next: on (or, rounded, next to)
    /// an existing edge.
    Along(u8, u8),
    /// Any coordinates at all: NaN, infinities, out of range, subnormal. Must give a typed error
    /// or a correct answer.
    Raw(f64, f64),
}

/// One ring: its steps, and whether to reverse it (holes, clockwise parts, cancelling copies).
#[derive(Arbitrary, Clone, Debug, PartialEq)]
pub struct RingSpec {
    /// How its vertices are made, in order.
    pub steps: Vec<Vertex>,
    /// Reverse the ring once built.
    pub reversed: bool,
}

/// A polygon operand: up to [`MAX_RINGS`] rings.
#[derive(Arbitrary, Clone, Debug, PartialEq)]
pub struct ShapeSpec {
    /// Its rings.
    pub rings: Vec<RingSpec>,
}

/// Builds operands in one frame, keeping every vertex made so far for [`Vertex::Reuse`] and
/// [`Vertex::Along`].
#[derive(Debug)]
pub struct Builder {
    frame: Frame,
    made: Vec<Point>,
}

fn small(v: i8, limit: i8) -> i32 {
    i32::from(v % (limit + 1))
}

fn nudge(v: f64, ulps: i8) -> f64 {
    let ulp = (v.abs() * f64::EPSILON).max(f64::MIN_POSITIVE);
    v + f64::from(ulps % 4) * ulp
}

impl Builder {
    /// A builder for one case.
    pub fn new(frame: Frame) -> Builder {
        Builder { frame, made: Vec::new() }
    }

    /// The frame's grid step.
    pub fn step(&self) -> f64 {
        self.frame.step.value()
    }

    /// The grid point at `(i, j)`, both reduced to -16..=16.
    pub fn grid_point(&self, i: i8, j: i8) -> Point {
        self.frame.grid(small(i, 16), small(j, 16))
    }

    /// Every vertex made so far.
    pub fn made(&self) -> &[Point] {
        &self.made
    }

    /// The vertices of one ring (not closed; `Ring::new` drops a closing repeat).
    pub fn ring(&mut self, spec: &RingSpec) -> Ring {
        let mut points: Vec<Point> = Vec::new();
        for &step in spec.steps.iter().take(MAX_STEPS) {
            let last = points.last().copied().unwrap_or_else(|| self.frame.grid(0, 0));
            let s = self.step();
            let moved =
                |dx: i8, dy: i8| Point::new(last.x + f64::from(small(dx, 8)) * s, last.y + f64::from(small(dy, 8)) * s);
            match step {
                Vertex::Grid(i, j) => points.push(self.grid_point(i, j)),
                Vertex::Move(dx, dy) => points.push(moved(dx, dy)),
                Vertex::Repeat => points.push(last),
                Vertex::Spike(dx, dy) => points.extend([moved(dx, dy), last]),
                Vertex::Nudge(dx, dy) => points.push(Point::new(nudge(last.x, dx), nudge(last.y, dy))),
                Vertex::Reuse(k) => {
                    let pool = self.made.iter().chain(points.iter()).copied().collect::<Vec<_>>();
                    if !pool.is_empty() {
                        points.push(pool[usize::from(k) % pool.len()]);
                    }
                }
                Vertex::Along(k, t) => {
                    let pool = self.made.iter().chain(points.iter()).copied().collect::<Vec<_>>();
                    if pool.len() >= 2 {
                        let i = usize::from(k) % (pool.len() - 1);
                        points.push(pool[i].lerp(pool[i + 1], f64::from(t % 9) / 8.0));
                    }
                }
                Vertex::Raw(x, y) => points.push(Point::new(x, y)),
            }
        }
        self.made.extend(points.iter().copied());
        let ring = Ring::new(points);
        if spec.reversed { ring.reversed() } else { ring }
    }

    /// A whole operand; rings with no vertex are left out (the empty operand is valid).
    pub fn polygons(&mut self, spec: &ShapeSpec) -> Polygons {
        let rings = spec.rings.iter().take(MAX_RINGS).map(|r| self.ring(r)).filter(|r| !r.is_empty()).collect();
        Polygons::new(rings)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame() -> Frame {
        Frame { step: Step::One, offset: Offset::Zero }
    }

    #[test]
    fn steps_make_the_degeneracies_they_name() {
        let mut b = Builder::new(frame());
        let spec = RingSpec {
            steps: vec![
                Vertex::Grid(0, 0),
                Vertex::Move(2, 0),
                Vertex::Move(2, 0),
                Vertex::Repeat,
                Vertex::Spike(0, 3),
            ],
            reversed: false,
        };
        let ring = b.ring(&spec);
        let p = |x, y| Point::new(x, y);
        assert_eq!(ring.points, vec![p(0.0, 0.0), p(2.0, 0.0), p(4.0, 0.0), p(4.0, 0.0), p(4.0, 3.0), p(4.0, 0.0)]);
        let shared = b.ring(&RingSpec { steps: vec![Vertex::Reuse(1), Vertex::Along(0, 4)], reversed: true });
        assert_eq!(shared.points, vec![p(1.0, 0.0), p(2.0, 0.0)]);
    }

    #[test]
    fn grid_coordinates_stay_small_and_rings_are_bounded() {
        let b = Builder::new(frame());
        assert_eq!(b.grid_point(127, -128), Point::new(8.0, -9.0));
        let mut b = Builder::new(Frame { step: Step::Tiny, offset: Offset::Far });
        let long = RingSpec { steps: vec![Vertex::Move(1, 1); 100], reversed: false };
        assert_eq!(b.ring(&long).len(), MAX_STEPS);
        assert!(b.polygons(&ShapeSpec { rings: vec![long; 9] }).rings.len() <= MAX_RINGS);
    }
}
