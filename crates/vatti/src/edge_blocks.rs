//! Bounding boxes of runs of consecutive ring edges in levels (a tree of fixed fan-out), so a
//! prepared operand finds the edges that reach a box without visiting every edge.

use clip_core::{Point, Rect};

use crate::envelope::{Envelope, Stretch};

/// Children per node, and edges per leaf box.
const FAN: usize = 8;

/// One ring's edge boxes: `levels[0][i]` bounds edges `FAN*i..FAN*(i+1)`, each higher level
/// bounds `FAN` boxes of the one below; the top level has at most `FAN` boxes.
#[derive(Clone, Debug)]
pub(crate) struct EdgeBlocks {
    levels: Vec<Vec<Rect>>,
}

impl EdgeBlocks {
    /// The boxes of ring `pts` (edge `i` runs from vertex `i` to `i + 1`, the last one closing).
    pub(crate) fn new(pts: &[Point]) -> EdgeBlocks {
        let n = pts.len();
        let leaves: Vec<Rect> = (0..n.div_ceil(FAN))
            .map(|b| {
                let last = (FAN * (b + 1)).min(n);
                (FAN * b..=last).fold(Rect::EMPTY, |r, i| r.including(pts[i % n]))
            })
            .collect();
        let mut levels = vec![leaves];
        while levels.last().is_some_and(|l| l.len() > FAN) {
            let below = levels.last().map(Vec::as_slice).unwrap_or_default();
            let up = below.chunks(FAN).map(|c| c.iter().fold(Rect::EMPTY, |r, &b| r.union(b))).collect();
            levels.push(up);
        }
        EdgeBlocks { levels }
    }

    /// The ring's stretches against `env`, in edge order, as [`Envelope::push_edge`] gives them
    /// edge by edge (missed stretches merged).
    pub(crate) fn walk(&self, pts: &[Point], env: &Envelope, out: &mut Vec<Stretch>) {
        let top = self.levels.len() - 1;
        for i in 0..self.levels[top].len() {
            self.visit(pts, env, top, i, out);
        }
    }

    fn visit(&self, pts: &[Point], env: &Envelope, level: usize, i: usize, out: &mut Vec<Stretch>) {
        let n = pts.len();
        let span = FAN.pow(level as u32 + 1);
        let (first, end) = (i * span, ((i + 1) * span).min(n));
        let b = self.levels[level][i];
        if env.misses(&b) {
            let crossings = env.missed_crossings(pts[first], pts[end % n], b.min.x);
            Envelope::push(out, Stretch::Missed { first, end, crossings });
        } else if level == 0 {
            (first..end).for_each(|e| env.push_edge(pts, e, out));
        } else {
            let children = (i * FAN)..((i + 1) * FAN).min(self.levels[level - 1].len());
            children.for_each(|c| self.visit(pts, env, level - 1, c, out));
        }
    }
}
