//! The crossings of a segment's line with a window boundary, and the visible pieces read from them by parity.

use crate::line_frame::{Along, LineFrame};
use crate::{Segment, VisiblePiece};

/// The crossings of one segment's line with a window boundary read under even-odd, and the window
/// edges lying along the line, gathered before the visible pieces are read off (Liu's sorted
/// intersections; Wang et al.'s DISPLAY-ARRAY).
///
/// Crossings on the segment's extension are not kept but counted: the start lies in the window
/// when the crossings after it are odd in number, the end when those before it are. Edges along
/// the line are boundary, visible under the closed-set rule, and are united with the inside
/// intervals at the end.
#[derive(Debug)]
pub struct LineCrossings {
    /// Intersections strictly after `M0` (`t > 0`).
    after_start: u32,
    /// Intersections strictly before `M1` (`t < 1`).
    before_end: u32,
    /// How many intersections lie strictly between `M0` and `M1`.
    inside_count: usize,
    /// The parameters of the first [`HELD`] of them (those past `inside_count` are left over from
    /// earlier segments): a segment rarely has more, and these sort in place by a fixed network.
    held: [f64; HELD],
    /// All of their parameters once there are more than [`HELD`] (the held ones first).
    spilled: Vec<f64>,
    /// Parameter intervals (clamped to `[0, 1]`) of window edges along the line.
    along: Vec<(f64, f64)>,
    /// Visible intervals before merging.
    spans: Vec<(f64, f64)>,
}

/// Crossings inside the segment held in [`LineCrossings::held`] before they spill to a vector.
const HELD: usize = 8;

impl Default for LineCrossings {
    fn default() -> LineCrossings {
        LineCrossings {
            after_start: 0,
            before_end: 0,
            inside_count: 0,
            held: [f64::INFINITY; HELD],
            spilled: Vec::new(),
            along: Vec::new(),
            spans: Vec::new(),
        }
    }
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

impl LineCrossings {
    /// Forgets the previous segment.
    #[inline]
    pub fn clear(&mut self) {
        self.after_start = 0;
        self.before_end = 0;
        self.inside_count = 0;
        self.along.clear();
    }

    /// True when nothing of the segment can be visible: no crossing after its start (so the start
    /// is outside), none on it and no edge along it.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.after_start == 0 && self.inside_count == 0 && self.along.is_empty()
    }

    /// Records a crossing of the boundary at `place`, parameter `t`.
    #[inline]
    pub fn record(&mut self, place: Along, t: f64) {
        self.after_start += u32::from(place > Along::AtStart);
        self.before_end += u32::from(place < Along::AtEnd);
        if place == Along::Inside {
            let t = t.clamp(0.0, 1.0);
            if self.inside_count < HELD {
                self.held[self.inside_count] = t;
            } else {
                self.spill(t);
            }
            self.inside_count += 1;
        }
    }

    /// Records a crossing past the [`HELD`] ones; out of line, so the common path stays small in
    /// the callers' loops.
    #[cold]
    #[inline(never)]
    fn spill(&mut self, t: f64) {
        if self.inside_count == HELD {
            self.spilled.clear();
            self.spilled.extend_from_slice(&self.held);
        }
        self.spilled.push(t);
    }

    /// Records `before` crossings before the start and `after` past the end, which only count
    /// toward the ends' parities (stand-ins for crossings not looked for). No branch.
    #[inline]
    pub fn count_beyond(&mut self, before: u32, after: u32) {
        self.before_end += before;
        self.after_start += after;
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

    /// Sorts the crossings and appends the visible pieces of segment `index` to `out`: from the
    /// start (when inside) or the first crossing, alternating, to the end (when inside) or the last
    /// crossing; then united with the edges along the line, touching pieces merged, points
    /// dropped. Returns the number of pieces written.
    pub fn emit(&mut self, index: usize, frame: &LineFrame, out: &mut Vec<VisiblePiece>) -> usize {
        if self.along.is_empty() {
            return self.emit_few(index, frame, out);
        }
        self.emit_general(index, frame, out)
    }

    /// [`LineCrossings::emit`] in general: any number of crossings, edges along the line.
    fn emit_general(&mut self, index: usize, frame: &LineFrame, out: &mut Vec<VisiblePiece>) -> usize {
        let crossings = sorted(&mut self.held, self.inside_count, &mut self.spilled);
        snap(crossings);
        let (m0_inside, m1_inside) = (self.after_start % 2 == 1, self.before_end % 2 == 1);
        self.spans.clear();
        let mut inside = m0_inside;
        let mut from = 0.0;
        for &t in &*crossings {
            if inside {
                self.spans.push((from, t));
            }
            inside = !inside;
            from = t;
        }
        debug_assert_eq!(inside, m1_inside, "parity of the crossings between the ends");
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
                // A gap whose ends round to one point is no gap: the pieces would meet there
                // (found by the `line_clippers` fuzz target at 4e6, where a point's rounding spans
                // 3e-11 of a segment 16 long, above PARAMETER_SNAP).
                Some((clo, chi)) if lo <= chi + PARAMETER_SNAP || frame.at(lo) == frame.at(chi) => {
                    Some((clo, chi.max(hi)))
                }
                Some(done) => {
                    frame.push_piece(out, index, done);
                    Some((lo, hi))
                }
                None => Some((lo, hi)),
            };
        }
        if let Some(done) = current {
            frame.push_piece(out, index, done);
        }
        out.len() - before
    }
}

impl LineCrossings {
    /// [`LineCrossings::emit`] with no edge along the line: up to two crossings on the segment (the
    /// common case) written out without the general loops, whose trip counts vary from segment to
    /// segment and mispredict; the same pieces.
    #[inline]
    fn emit_few(&mut self, index: usize, frame: &LineFrame, out: &mut Vec<VisiblePiece>) -> usize {
        let before = out.len();
        let m0_inside = self.after_start % 2 == 1;
        // Read one slot at a time: a load spanning two slots written apart cannot be forwarded
        // from the stores and waits for them.
        let (t0, t1) = (self.held[0], self.held[1]);
        match self.inside_count {
            0 => {
                if m0_inside {
                    frame.push_piece(out, index, (0.0, 1.0));
                }
            }
            1 => frame.push_piece(out, index, if m0_inside { (0.0, t0) } else { (t0, 1.0) }),
            2 => {
                let (t0, t1) = (t0.min(t1), t0.max(t1));
                let t1 = if t1 - t0 <= PARAMETER_SNAP { t0 } else { t1 };
                if !m0_inside {
                    frame.push_piece(out, index, (t0, t1));
                } else if t1 <= t0 + PARAMETER_SNAP || frame.at(t1) == frame.at(t0) {
                    frame.push_piece(out, index, (0.0, 1.0));
                } else {
                    frame.push_piece(out, index, (0.0, t0));
                    frame.push_piece(out, index, (t1, 1.0));
                }
            }
            _ => self.emit_sorted(index, frame, out),
        }
        out.len() - before
    }

    /// [`LineCrossings::emit`] with no edge along the line, in one pass over the sorted crossings:
    /// snapping, pairing by parity and merging as the general path does, without its separate
    /// loops (each loop of varying length mispredicts once at its end).
    fn emit_sorted(&mut self, index: usize, frame: &LineFrame, out: &mut Vec<VisiblePiece>) {
        let crossings = sorted(&mut self.held, self.inside_count, &mut self.spilled);
        let mut inside = self.after_start % 2 == 1;
        let (mut from, mut previous) = (0.0, f64::NEG_INFINITY);
        let mut current: Option<(f64, f64)> = None;
        let mut show = |span: (f64, f64), current: &mut Option<(f64, f64)>| {
            *current = match *current {
                Some((clo, chi)) if span.0 <= chi + PARAMETER_SNAP || frame.at(span.0) == frame.at(chi) => {
                    Some((clo, chi.max(span.1)))
                }
                Some(done) => {
                    frame.push_piece(out, index, done);
                    Some(span)
                }
                None => Some(span),
            };
        };
        for &t in &*crossings {
            let t = if t - previous <= PARAMETER_SNAP { previous } else { t };
            previous = t;
            if inside {
                show((from, t), &mut current);
            }
            inside = !inside;
            from = t;
        }
        debug_assert_eq!(inside, self.before_end % 2 == 1, "parity of the crossings between the ends");
        if self.before_end % 2 == 1 {
            show((from, 1.0), &mut current);
        }
        if let Some(done) = current {
            frame.push_piece(out, index, done);
        }
    }
}

impl LineFrame {
    /// Appends the piece `[t0, t1]` of segment `index` to `out` when it has positive length
    /// (longer than [`PARAMETER_SNAP`] and with distinct end points).
    #[inline]
    pub fn push_piece(&self, out: &mut Vec<VisiblePiece>, index: usize, (t0, t1): (f64, f64)) {
        let (a, b) = (self.at(t0), self.at(t1));
        if t1 - t0 > PARAMETER_SNAP && a != b {
            out.push(VisiblePiece { segment: index, piece: Segment::new(a, b) });
        }
    }
}

/// Parameters closer than this are one point: the rounding of parameters computed from different
/// edges (two edges crossing the line at one point, an edge through another ring's vertex) stays
/// well below it, and a true piece or gap this short is below the resolution of the parameters.
pub const PARAMETER_SNAP: f64 = 1e-12;

/// Makes sorted parameters within [`PARAMETER_SNAP`] of their predecessor equal to it.
#[inline]
fn snap(v: &mut [f64]) {
    for i in 1..v.len() {
        if v[i] - v[i - 1] <= PARAMETER_SNAP {
            v[i] = v[i - 1];
        }
    }
}

/// The `count` crossing parameters of one segment, sorted: up to [`HELD`] in `held` (padded with
/// +inf here) by a sorting network, 19 compare-exchanges that compile to `min` and `max` with no
/// branch on the data (crossings come in ring order, not along the line, so a comparison sort
/// mispredicts about once per element); more, in `spilled`, by insertion.
#[inline]
fn sorted<'a>(held: &'a mut [f64; HELD], count: usize, spilled: &'a mut Vec<f64>) -> &'a mut [f64] {
    if count <= HELD {
        // The slots past `count` as +inf, which sorts last: a select per slot, no branch.
        for (i, t) in held.iter_mut().enumerate() {
            *t = if i < count { *t } else { f64::INFINITY };
        }
        sort_network(held);
        return &mut held[..count];
    }
    for i in 1..spilled.len() {
        let x = spilled[i];
        let mut j = i;
        while j > 0 && spilled[j - 1] > x {
            spilled[j] = spilled[j - 1];
            j -= 1;
        }
        spilled[j] = x;
    }
    spilled
}

/// Sorts 8 values (no NaN) by Knuth's optimal network for 8 inputs (19 comparators in 6
/// rounds; The Art of Computer Programming, vol. 3, 5.3.4), written out so that the values stay
/// in registers and each comparator is a `min` and a `max`.
#[inline]
fn sort_network(v: &mut [f64; HELD]) {
    macro_rules! rounds {
        ($($i:literal $j:literal),*) => {{
            let mut w = *v;
            $(
                let (x, y) = (w[$i], w[$j]);
                (w[$i], w[$j]) = (if y < x { y } else { x }, if y < x { x } else { y });
            )*
            *v = w;
        }};
    }
    rounds!(
        0 2, 1 3, 4 6, 5 7,
        0 4, 1 5, 2 6, 3 7,
        0 1, 2 3, 4 5, 6 7,
        2 4, 3 5,
        1 4, 3 6,
        1 2, 3 4, 5 6
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Point;

    fn show(d: &mut LineCrossings) -> Vec<(f64, f64)> {
        let frame = LineFrame::new(Segment::new(Point::new(0.0, 0.0), Point::new(10.0, 0.0)));
        let mut out = Vec::new();
        d.emit(0, &frame, &mut out);
        out.iter().map(|p| (p.piece.a.x / 10.0, p.piece.b.x / 10.0)).collect()
    }

    #[test]
    fn table_3_rows() {
        let mut d = LineCrossings::default();
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

    /// Found by the `line_clippers` fuzz target: at 5e5 an ulp is 5.8e-11, so a gap of 1.5e-12 of
    /// a segment 16 long (above `PARAMETER_SNAP`) rounds to one point, and the pieces must be one.
    #[test]
    fn a_gap_that_rounds_to_a_point_is_merged() {
        let frame = LineFrame::new(Segment::new(Point::new(500000.0, 4000000.0), Point::new(500016.0, 4000000.0)));
        let mut d = LineCrossings::default();
        for t in [0.25, 0.5, 0.5 + 1.5e-12, 0.75] {
            d.record(Along::Inside, t);
        }
        let mut out = Vec::new();
        d.emit(0, &frame, &mut out);
        assert_eq!(out.len(), 1, "{out:?}");
        // A gap a few ulps long stays a gap.
        d.clear();
        for t in [0.25, 0.5, 0.5 + 1e-9, 0.75] {
            d.record(Along::Inside, t);
        }
        out.clear();
        d.emit(0, &frame, &mut out);
        assert_eq!(out.len(), 2, "{out:?}");
    }

    #[test]
    fn the_network_sorts_every_input_of_zeros_and_ones() {
        // By the 0-1 principle a comparator network that sorts all 2^8 inputs of zeros and ones
        // sorts every input.
        for bits in 0u32..1 << HELD {
            let mut v: [f64; HELD] = core::array::from_fn(|i| f64::from((bits >> i) & 1));
            sort_network(&mut v);
            assert!(v.is_sorted(), "{bits:08b}: {v:?}");
        }
    }

    #[test]
    fn held_and_spilled_crossings_sort_alike() {
        // One recorder throughout, more and fewer crossings in turn: slots left over from a
        // longer list must not show up in a shorter one.
        let mut c = LineCrossings::default();
        for n in (0..=12).chain((0..=12).rev()) {
            let values: Vec<f64> = (0..n).map(|i| f64::from((i * 7 + 3) % 5) / 4.0).collect();
            c.clear();
            for &t in &values {
                c.record(Along::Inside, t);
            }
            let mut expected = values.clone();
            expected.sort_by(f64::total_cmp);
            assert_eq!(sorted(&mut c.held, c.inside_count, &mut c.spilled), &expected[..], "{n} values");
        }
    }

    #[test]
    fn edges_along_the_line_are_shown() {
        let mut d = LineCrossings::default();
        d.along((Along::Inside, 0.3), (Along::Inside, 0.5));
        d.along((Along::Before, 0.0), (Along::AtStart, 0.0));
        assert_eq!(show(&mut d), vec![(0.3, 0.5)]);
    }

    #[test]
    fn pairs_sorted_crossings_by_parity() {
        let mut c = LineCrossings::default();
        c.record(Along::Before, 0.0);
        c.record(Along::Inside, 0.6);
        c.record(Along::Inside, 0.2);
        c.record(Along::Inside, 0.4);
        assert_eq!(show(&mut c), vec![(0.0, 0.2), (0.4, 0.6)]);
        c.clear();
        c.record(Along::Inside, 0.3);
        c.record(Along::After, 1.0);
        assert_eq!(show(&mut c), vec![(0.3, 1.0)]);
    }

    #[test]
    fn merges_touching_intervals_and_drops_points() {
        let mut c = LineCrossings::default();
        // In at 0.2, out and in again at 0.5 (a vertex touched from inside), out at 0.8.
        for t in [0.2, 0.5, 0.5, 0.8] {
            c.record(Along::Inside, t);
        }
        assert_eq!(show(&mut c), vec![(0.2, 0.8)]);
        c.clear();
        // A vertex touched from outside: a zero-length inside interval, dropped.
        c.record(Along::Inside, 0.5);
        c.record(Along::Inside, 0.5);
        assert_eq!(show(&mut c), vec![]);
    }

    #[test]
    fn unites_edges_along_the_line() {
        let mut c = LineCrossings::default();
        c.along((Along::Inside, 0.3), (Along::Inside, 0.1));
        c.record(Along::Inside, 0.3);
        c.record(Along::Inside, 0.6);
        c.along((Along::Inside, 0.8), (Along::After, 9.0));
        c.along((Along::Before, -3.0), (Along::Before, -1.0));
        assert_eq!(show(&mut c), vec![(0.1, 0.6), (0.8, 1.0)]);
    }
}
