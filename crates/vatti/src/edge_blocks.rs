//! Bounding boxes of runs of consecutive ring edges in levels (a tree of fixed fan-out), so a
//! prepared operand finds the edges that reach a box without visiting every edge.

use clip_core::{Point, Rect};

/// Children per node, and edges per leaf box.
const FAN: usize = 8;

/// One ring's edge boxes: `levels[0][i]` bounds edges `FAN*i..FAN*(i+1)`, each higher level
/// bounds `FAN` boxes of the one below; the top level has at most `FAN` boxes.
#[derive(Clone, Debug)]
pub(crate) struct EdgeBlocks {
    levels: Vec<Vec<Rect>>,
}

/// A run of a ring's edges as [`EdgeBlocks::walk`] finds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum EdgeRun {
    /// Edges `first..end`, in a block whose box `bounds` misses the box looked for.
    Missed { first: usize, end: usize, bounds: Rect },
    /// Edge `i`, in a leaf block whose box does not miss it: to be tested on its own.
    Near(usize),
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

    /// The `n` edges of the ring, in order, as runs: the largest blocks whose box `misses` the
    /// box looked for, and one by one the edges of leaf blocks that do not.
    pub(crate) fn walk(&self, n: usize, misses: &impl Fn(&Rect) -> bool, visit: &mut impl FnMut(EdgeRun)) {
        let top = self.levels.len() - 1;
        for i in 0..self.levels[top].len() {
            self.visit(n, misses, top, i, visit);
        }
    }

    fn visit(
        &self,
        n: usize,
        misses: &impl Fn(&Rect) -> bool,
        level: usize,
        i: usize,
        visit: &mut impl FnMut(EdgeRun),
    ) {
        let span = FAN.pow(level as u32 + 1);
        let (first, end) = (i * span, ((i + 1) * span).min(n));
        let bounds = self.levels[level][i];
        if misses(&bounds) {
            visit(EdgeRun::Missed { first, end, bounds });
        } else if level == 0 {
            (first..end).for_each(|e| visit(EdgeRun::Near(e)));
        } else {
            let children = (i * FAN)..((i + 1) * FAN).min(self.levels[level - 1].len());
            children.for_each(|c| self.visit(n, misses, level - 1, c, visit));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_runs_cover_every_edge_in_order_and_missed_runs_miss() {
        let pts: Vec<Point> = (0..300)
            .map(|i| {
                let a = f64::from(i) * std::f64::consts::TAU / 300.0;
                let r = if i % 2 == 0 { 10.0 } else { 3.0 + f64::from(i % 5) };
                Point::new(r * a.cos(), r * a.sin())
            })
            .collect();
        let blocks = EdgeBlocks::new(&pts);
        let looked_for = Rect::new(2.0, -1.0, 9.0, 4.0);
        let misses = |r: &Rect| {
            r.max.x < looked_for.min.x
                || r.min.x > looked_for.max.x
                || r.max.y < looked_for.min.y
                || r.min.y > looked_for.max.y
        };
        let (mut next, mut missed, mut near) = (0, 0, 0);
        blocks.walk(pts.len(), &misses, &mut |run| match run {
            EdgeRun::Missed { first, end, bounds } => {
                assert_eq!(first, next);
                assert!(misses(&bounds));
                for i in first..end {
                    assert!(bounds.contains(pts[i]) && bounds.contains(pts[(i + 1) % pts.len()]), "edge {i}");
                }
                (next, missed) = (end, missed + 1);
            }
            EdgeRun::Near(i) => {
                assert_eq!(i, next);
                (next, near) = (i + 1, near + 1);
            }
        });
        assert_eq!(next, pts.len());
        assert!(missed > 0 && near > 0 && near < pts.len() / 2, "{missed} missed runs, {near} edges near");
    }
}
