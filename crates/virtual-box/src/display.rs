//! The DISPLAY-ARRAY of valid intersections and the visible pieces read from it (the paper's Table 3).

use clip_core::{Segment, VisiblePiece};

use crate::line_frame::{Along, LineFrame};

/// The paper's DISPLAY-ARRAY for one segment: the valid intersections of its line with the
/// window boundary, and the window edges lying along the line.
///
/// Intersections on the segment's extension are discarded from the array but counted first: the
/// start `M0` lies in the window when the intersections after it are odd in number (the paper's
/// Count1), the end `M1` when those before it are. Edges along the line are boundary, visible
/// under the closed-set rule, and are united with the pieces of Table 3.
#[derive(Debug, Default)]
pub(crate) struct DisplayArray {
    /// Intersections strictly after `M0` (`t > 0`).
    after_start: u32,
    /// Intersections strictly before `M1` (`t < 1`).
    before_end: u32,
    /// Parameters of the intersections strictly between `M0` and `M1`.
    inside: Vec<f64>,
    /// Parameter intervals (clamped to `[0, 1]`) of window edges along the line.
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

impl DisplayArray {
    /// Forgets the previous segment.
    #[inline]
    pub fn clear(&mut self) {
        self.after_start = 0;
        self.before_end = 0;
        self.inside.clear();
        self.along.clear();
    }

    /// Records a valid intersection at `place`, parameter `t`.
    #[inline]
    pub fn record(&mut self, place: Along, t: f64) {
        self.after_start += u32::from(place > Along::AtStart);
        self.before_end += u32::from(place < Along::AtEnd);
        if place == Along::Inside {
            self.inside.push(t.clamp(0.0, 1.0));
        }
    }

    /// Records a window edge along the line, its ends given by place and parameter.
    pub fn along(&mut self, p: (Along, f64), q: (Along, f64)) {
        let (tp, tq) = (clamped(p.0, p.1), clamped(q.0, q.1));
        let (lo, hi) = if tp <= tq { (tp, tq) } else { (tq, tp) };
        let (lo, hi) = (lo.max(0.0), hi.min(1.0));
        if lo < hi {
            self.along.push((lo, hi));
        }
    }

    /// Sorts the intersections and appends the visible pieces of segment `index` to `out` by
    /// Table 3: from `M0` (when inside) or `T1`, alternating, to `M1` (when inside) or the last
    /// `T`; then united with the edges along the line, touching pieces merged, points dropped.
    /// Returns the number of pieces written.
    pub fn display(&mut self, index: usize, frame: &LineFrame, out: &mut Vec<VisiblePiece>) -> usize {
        sort_small(&mut self.inside);
        snap(&mut self.inside);
        let (m0_inside, m1_inside) = (self.after_start % 2 == 1, self.before_end % 2 == 1);
        self.spans.clear();
        let mut inside = m0_inside;
        let mut from = 0.0;
        for &t in &self.inside {
            if inside {
                self.spans.push((from, t));
            }
            inside = !inside;
            from = t;
        }
        debug_assert_eq!(inside, m1_inside, "parity of the intersections between M0 and M1");
        if m1_inside {
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
fn push_piece(out: &mut Vec<VisiblePiece>, index: usize, frame: &LineFrame, (t0, t1): (f64, f64)) {
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

/// Insertion sort: a segment meets a window's boundary a handful of times.
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

    fn show(d: &mut DisplayArray) -> Vec<(f64, f64)> {
        let frame = LineFrame::new(Segment::new(Point::new(0.0, 0.0), Point::new(10.0, 0.0)));
        let mut out = Vec::new();
        d.display(0, &frame, &mut out);
        out.iter().map(|p| (p.piece.a.x / 10.0, p.piece.b.x / 10.0)).collect()
    }

    #[test]
    fn table_3_rows() {
        let mut d = DisplayArray::default();
        // M0 out, M1 out: {L(T1,T2), L(T3,T4)}.
        for t in [0.6, 0.1, 0.8, 0.3] {
            d.record(Along::Inside, t);
        }
        assert_eq!(show(&mut d), vec![(0.1, 0.3), (0.6, 0.8)]);
        // M0 out, M1 in: {L(T1,T2), L(T3,M1)}.
        d.clear();
        for (p, t) in [(Along::Inside, 0.2), (Along::Inside, 0.4), (Along::Inside, 0.7), (Along::After, 1.0)] {
            d.record(p, t);
        }
        assert_eq!(show(&mut d), vec![(0.2, 0.4), (0.7, 1.0)]);
        // M0 in, M1 out: {L(M0,T1), L(T2,T3)}.
        d.clear();
        for (p, t) in [(Along::Before, 0.0), (Along::Inside, 0.2), (Along::Inside, 0.4), (Along::Inside, 0.7)] {
            d.record(p, t);
        }
        assert_eq!(show(&mut d), vec![(0.0, 0.2), (0.4, 0.7)]);
        // M0 in, M1 in: {L(M0,T1), L(T2,M1)}; a touch at 0.5 from inside is merged away.
        d.clear();
        for (p, t) in [(Along::Before, 0.0), (Along::Inside, 0.5), (Along::Inside, 0.5), (Along::After, 1.0)] {
            d.record(p, t);
        }
        assert_eq!(show(&mut d), vec![(0.0, 1.0)]);
    }

    #[test]
    fn edges_along_the_line_are_shown() {
        let mut d = DisplayArray::default();
        d.along((Along::Inside, 0.3), (Along::Inside, 0.5));
        d.along((Along::Before, 0.0), (Along::AtStart, 0.0));
        assert_eq!(show(&mut d), vec![(0.3, 0.5)]);
    }
}
