//! The pipeline form: each vertex passes through the boundary stages one by one, with no intermediate lists.

use clip_core::Point;

use crate::boundary::Side;
use crate::stage::step;
use crate::window::ConvexWindow;

/// What one boundary stage remembers between vertices.
#[derive(Clone, Copy, Debug, Default)]
struct StageMemory {
    /// The first vertex the stage saw, kept for the closing edge.
    first: Option<(Point, Side)>,
    /// The previous vertex (the `s` of the edge `s -> p`).
    last: Option<(Point, Side)>,
}

/// A reentrant clipper for one ring at a time: call [`Pipeline::push`] with each vertex in order,
/// then [`Pipeline::finish`] to close the ring and take the clipped vertices.
#[derive(Clone, Debug)]
pub struct Pipeline<'w> {
    window: &'w ConvexWindow,
    stages: Vec<StageMemory>,
    output: Vec<Point>,
}

impl<'w> Pipeline<'w> {
    /// A pipeline with one stage per boundary of `window`.
    pub fn new(window: &'w ConvexWindow) -> Pipeline<'w> {
        Pipeline { window, stages: vec![StageMemory::default(); window.boundaries().len()], output: Vec::new() }
    }

    /// Feeds the next vertex of the ring into the first stage.
    pub fn push(&mut self, p: Point) {
        self.feed(0, p);
    }

    /// Closes the ring, stage by stage (each stage's closing edge may feed the next stage), and
    /// returns the clipped vertices. The pipeline is then empty and ready for another ring.
    pub fn finish(&mut self) -> Vec<Point> {
        for k in 0..self.stages.len() {
            let memory = std::mem::take(&mut self.stages[k]);
            if let (Some((first, first_side)), Some((s, s_side))) = (memory.first, memory.last) {
                let boundary = self.window.boundaries()[k];
                for q in step(&boundary, k, s, s_side, first, first_side).into_iter() {
                    self.feed(k + 1, q);
                }
            }
        }
        std::mem::take(&mut self.output)
    }

    /// Passes `p` to stage `k`, or to the output past the last stage.
    fn feed(&mut self, k: usize, p: Point) {
        let Some(memory) = self.stages.get(k).copied() else {
            self.output.push(p);
            return;
        };
        let boundary = self.window.boundaries()[k];
        let p_side = boundary.side(p);
        let stage = &mut self.stages[k];
        stage.last = Some((p, p_side));
        match memory.last {
            None => stage.first = Some((p, p_side)),
            Some((s, s_side)) => {
                for q in step(&boundary, k, s, s_side, p, p_side).into_iter() {
                    self.feed(k + 1, q);
                }
            }
        }
    }
}
