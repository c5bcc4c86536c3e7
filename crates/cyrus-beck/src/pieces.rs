//! Visible pieces from the crossings of a segment's line with the window boundary (even-odd parity).

use clip_core::{Segment, VisiblePiece};

use crate::line_frame::{Along, LineFrame};

/// The crossings of one segment's line with the window boundary, and the boundary edges lying on
/// the line, gathered before the visible pieces are read off.
///
/// Under even-odd, a point of the line that is on no edge is inside when an odd number of
/// crossings lie beyond it. Crossings off the segment only count; those on it are kept (as
/// rounded parameters) to cut the segment. Edges along the line are boundary, hence visible
/// under the closed-set rule, and are united with the inside intervals at the end.
#[derive(Debug, Default)]
pub(crate) struct Crossings {
    /// Crossings strictly after the start point (`t > 0`).
    after_start: u32,
    /// Parameters of the crossings strictly inside the segment.
    inside: Vec<f64>,
    /// Parameter intervals (clamped to `[0, 1]`) of window edges lying on the line.
    along: Vec<(f64, f64)>,
    /// Visible intervals before merging.
    spans: Vec<(f64, f64)>,
}

/// A place on the line as a parameter clamped to `[0, 1]` (the place decides, the value follows).
#[inline]
fn clamped(place: Along, t: f64) -> f64 {
    match place {
        Along::Before => -1.0,
        Along::AtStart => 0.0,
        Along::Inside => t.clamp(0.0, 1.0),
        Along::AtEnd => 1.0,
        Along::After => 2.0,
    }
}

impl Crossings {
    /// Forgets the previous segment.
    #[inline]
    pub fn clear(&mut self) {
        self.after_start = 0;
        self.inside.clear();
        self.along.clear();
    }

    /// True when nothing was recorded: the line misses the window's boundary.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.after_start == 0 && self.inside.is_empty() && self.along.is_empty()
    }

    /// Records one crossing of the boundary.
    #[inline]
    pub fn cross(&mut self, place: Along, t: f64) {
        if place > Along::AtStart {
            self.after_start += 1;
            if place == Along::Inside {
                self.inside.push(t.clamp(0.0, 1.0));
            }
        }
    }

    /// Records a window edge lying on the line, its ends given by place and parameter.
    pub fn along(&mut self, p: (Along, f64), q: (Along, f64)) {
        let (tp, tq) = (clamped(p.0, p.1), clamped(q.0, q.1));
        let (lo, hi) = if tp <= tq { (tp, tq) } else { (tq, tp) };
        let (lo, hi) = (lo.max(0.0), hi.min(1.0));
        if lo < hi {
            self.along.push((lo, hi));
        }
    }

    /// Appends the visible pieces of segment `index` to `out`: the inside intervals between sorted
    /// crossings, united with the edges along the line, touching intervals merged, points dropped.
    /// Returns the number of pieces written.
    pub fn emit(&mut self, index: usize, frame: &LineFrame, out: &mut Vec<VisiblePiece>) -> usize {
        sort_small(&mut self.inside);
        snap(&mut self.inside);
        self.spans.clear();
        let mut inside = self.after_start % 2 == 1;
        let mut from = 0.0;
        for &t in &self.inside {
            if inside {
                self.spans.push((from, t));
            }
            inside = !inside;
            from = t;
        }
        if inside {
            self.spans.push((from, 1.0));
        }
        if !self.along.is_empty() {
            self.spans.extend_from_slice(&self.along);
            self.spans.sort_unstable_by(|x, y| x.0.total_cmp(&y.0));
        }
        let before = out.len();
        let mut current: Option<(f64, f64)> = None;
        for &(lo, hi) in &self.spans {
            current = match current {
                Some((clo, chi)) if lo <= chi + SNAP => Some((clo, chi.max(hi))),
                Some(done) => {
                    push_piece(out, index, frame, done);
                    Some((lo, hi))
                }
                None => Some((lo, hi)),
            };
        }
        if let Some(done) = current {
            push_piece(out, index, frame, done);
        }
        out.len() - before
    }
}

/// Appends the piece `[t0, t1]` of segment `index` when it has positive length.
#[inline]
pub(crate) fn push_piece(out: &mut Vec<VisiblePiece>, index: usize, frame: &LineFrame, (t0, t1): (f64, f64)) {
    let (a, b) = (frame.at(t0), frame.at(t1));
    if t1 - t0 > SNAP && a != b {
        out.push(VisiblePiece { segment: index, piece: Segment::new(a, b) });
    }
}

/// Parameters closer than this are one point: the rounding of parameters computed from different
/// edges (two edges crossing the line at one point, an edge through another ring's vertex) stays
/// well below it, and a true piece or gap this short is below the resolution of the parameters.
pub(crate) const SNAP: f64 = 1e-12;

/// Makes sorted parameters within [`SNAP`] of their predecessor equal to it.
#[inline]
fn snap(v: &mut [f64]) {
    for i in 1..v.len() {
        if v[i] - v[i - 1] <= SNAP {
            v[i] = v[i - 1];
        }
    }
}

/// Insertion sort: a segment crosses a window's boundary a handful of times.
#[inline]
fn sort_small(v: &mut [f64]) {
    for i in 1..v.len() {
        let x = v[i];
        let mut j = i;
        while j > 0 && v[j - 1] > x {
            v[j] = v[j - 1];
            j -= 1;
        }
        v[j] = x;
    }
}

#[cfg(test)]
mod tests {
    use clip_core::Point;

    use super::*;

    fn frame() -> LineFrame {
        LineFrame::new(Segment::new(Point::new(0.0, 0.0), Point::new(10.0, 0.0)))
    }

    fn intervals(c: &mut Crossings) -> Vec<(f64, f64)> {
        let mut out = Vec::new();
        c.emit(0, &frame(), &mut out);
        out.iter().map(|p| (p.piece.a.x / 10.0, p.piece.b.x / 10.0)).collect()
    }

    #[test]
    fn pairs_sorted_crossings_by_parity() {
        let mut c = Crossings::default();
        c.cross(Along::Before, 0.0);
        c.cross(Along::Inside, 0.6);
        c.cross(Along::Inside, 0.2);
        c.cross(Along::Inside, 0.4);
        assert_eq!(intervals(&mut c), vec![(0.0, 0.2), (0.4, 0.6)]);
        c.clear();
        c.cross(Along::Inside, 0.3);
        c.cross(Along::After, 1.0);
        assert_eq!(intervals(&mut c), vec![(0.3, 1.0)]);
    }

    #[test]
    fn merges_touching_intervals_and_drops_points() {
        let mut c = Crossings::default();
        // In at 0.2, out and in again at 0.5 (a vertex touched from inside), out at 0.8.
        for t in [0.2, 0.5, 0.5, 0.8] {
            c.cross(Along::Inside, t);
        }
        assert_eq!(intervals(&mut c), vec![(0.2, 0.8)]);
        c.clear();
        // A vertex touched from outside: a zero-length inside interval, dropped.
        c.cross(Along::Inside, 0.5);
        c.cross(Along::Inside, 0.5);
        assert_eq!(intervals(&mut c), vec![]);
    }

    #[test]
    fn unites_edges_along_the_line() {
        let mut c = Crossings::default();
        c.along((Along::Inside, 0.3), (Along::Inside, 0.1));
        c.cross(Along::Inside, 0.3);
        c.cross(Along::Inside, 0.6);
        c.along((Along::Inside, 0.8), (Along::After, 9.0));
        c.along((Along::Before, -3.0), (Along::Before, -1.0));
        assert_eq!(intervals(&mut c), vec![(0.1, 0.6), (0.8, 1.0)]);
    }
}
