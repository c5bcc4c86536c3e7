//! The paper's crossings inside a scanbeam: the sorted edge table (ST) finds them from every
//! active edge's x at the top of the beam, and the intersection table (IT) holds them sorted by
//! y, to be processed so that only adjacent edges are ever swapped. Every active edge is visited
//! in every scanbeam: Θ(n) per beam where n edges span it (the event sweep's `crossing_queue`
//! does without).

use clip_core::Point;

use crate::active::{ActiveEdges, X_AT_ERROR};
use crate::bounds::NONE;
use crate::scanbeam::height_key;
use crate::small_sort::insertion_sorted_by;

/// An entry of the intersection table: `left` precedes `right` in the active edge table.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Intersection {
    pub left: u32,
    pub right: u32,
    pub pt: Point,
    /// `pt.y` as an integer sort key.
    pub y_key: i64,
}

/// An active edge's x at the top of the beam and the magnitude of its ends' x, which scales
/// the rounding allowance.
#[derive(Clone, Copy, Debug)]
struct TopX {
    x: f64,
    magnitude: f64,
}

/// The tables' buffers, reused between scanbeams.
#[derive(Debug, Default)]
pub(crate) struct IntersectionTable {
    order: Vec<u32>,
    xtop: Vec<TopX>,
    sorted: Vec<u32>,
    pub table: Vec<Intersection>,
    /// True when a crossing of the last [`IntersectionTable::build`] was clamped onto an edge
    /// rising less than one per unit of x (`Edge::crossing_with`).
    pub off_flat: bool,
}

impl IntersectionTable {
    /// Bytes of capacity held.
    pub(crate) fn held_bytes(&self) -> usize {
        4 * (self.order.capacity() + self.sorted.capacity())
            + self.xtop.capacity() * size_of::<TopX>()
            + self.table.capacity() * size_of::<Intersection>()
    }

    /// Empties the buffers.
    pub(crate) fn clear(&mut self) {
        self.order.clear();
        self.xtop.clear();
        self.sorted.clear();
        self.table.clear();
    }

    /// Fills `table` with the crossings of the scanbeam `[yb, yt]`: the active edges are inserted
    /// right to left by their x at `yt`; each edge an edge has to jump over is a crossing (the
    /// paper's ST pass). Sorted by height, ties in the order found. Every edge's `curr_x` must be
    /// its x at `yb`.
    pub(crate) fn build(&mut self, ael: &mut ActiveEdges, yb: f64, yt: f64, max_error: f64) {
        self.table.clear();
        self.off_flat = false;
        let n = ael.len();
        if n < 2 {
            return;
        }
        // Most beams have no crossing: then no edge passes its left neighbour at the top, and
        // the tables below would find nothing. Until the first edge that does, only x at the
        // top is computed and compared; from there the edges are listed for the sorted edge table.
        self.order.clear();
        self.xtop.clear();
        let (mut id, mut prev) = (ael.first(), NONE);
        let mut prev_top = TopX { x: f64::NEG_INFINITY, magnitude: 0.0 };
        let mut first = None;
        let mut i = 0;
        while id != NONE {
            let e = ael.get_mut(id);
            e.next_x = e.x_at(yt);
            e.next_y = yt;
            let top = TopX { x: e.next_x, magnitude: e.magnitude.x_max };
            let next = e.next;
            if first.is_none() && prev != NONE && left_at_top_of(ael, id, top, prev, prev_top, yt) {
                first = Some(i);
                // Every edge before this one, for the table.
                let mut k = ael.first();
                while k != id {
                    self.order.push(k);
                    let ek = ael.get(k);
                    self.xtop.push(TopX { x: ek.next_x, magnitude: ek.magnitude.x_max });
                    k = ek.next;
                }
            }
            if first.is_some() {
                self.order.push(id);
                self.xtop.push(top);
            }
            (prev, prev_top) = (id, top);
            id = next;
            i += 1;
        }
        let Some(first) = first else { return };
        let (order, xtop) = (&self.order, &self.xtop);
        let st = &mut self.sorted;
        st.clear();
        st.extend(0..first as u32);
        for i in first..n {
            let mut j = st.len();
            st.push(i as u32);
            while j > 0 && left_at_top(ael, order, i, xtop[i], st[j - 1] as usize, xtop[st[j - 1] as usize], yt) {
                let (left, right) = (order[st[j - 1] as usize], order[i]);
                let (pt, off_flat) = scanbeam_crossing(ael, left, right, yb, yt, max_error);
                self.off_flat |= off_flat;
                self.table.push(Intersection { left, right, pt, y_key: height_key(pt.y) });
                st[j] = st[j - 1];
                j -= 1;
            }
            st[j] = i as u32;
        }
        if !insertion_sorted_by(&mut self.table, |a, b| a.y_key < b.y_key) {
            self.table.sort_by_key(|a| a.y_key);
        }
    }
}

/// True when the edge at active position `i` lies strictly left of the one at `k` at the
/// beam's top `yt`, given their rounded x there (`xi`, `xk`): by those where they are farther
/// apart than both can err, else exactly ([`crate::active::Edge::left_of_at`], with the
/// magnitudes kept beside the x so the loops stay in `xtop`). Rounded x within rounding of each
/// other would invent
/// crossings that cannot exist: a sliver triangle whose two bounds leave its lowest vertex 1e-16
/// apart in slope (the `vatti` fuzz target) was swapped and came out clockwise, and far from the
/// origin snap-rounded edges a pixel apart (which never cross) were swapped by their rounding.
#[inline(always)]
fn left_at_top(ael: &ActiveEdges, order: &[u32], i: usize, ti: TopX, k: usize, tk: TopX, yt: f64) -> bool {
    left_at_top_of(ael, order[i], ti, order[k], tk, yt)
}

/// [`left_at_top`] of edges `i` and `k` by id.
#[inline(always)]
fn left_at_top_of(ael: &ActiveEdges, i: u32, ti: TopX, k: u32, tk: TopX, yt: f64) -> bool {
    let (xi, xk) = (ti.x, tk.x);
    if (xi - xk).abs() > 2.0 * X_AT_ERROR * ti.magnitude.max(tk.magnitude) {
        return xi < xk;
    }
    ael.get(i).left_of_at_exactly(ael.get(k), yt)
}

/// Where edges `a` and `b` cross, kept inside the scanbeam `[yb, yt]`, from their x at both
/// ends of the beam (`curr_x` at the bottom, computed when the scanline was processed, and
/// `next_x` at the top, cached by [`IntersectionTable::build`]: no division spent on them).
fn scanbeam_crossing(ael: &ActiveEdges, a: u32, b: u32, yb: f64, yt: f64, max_error: f64) -> (Point, bool) {
    let (ea, eb) = (ael.get(a), ael.get(b));
    debug_assert!(ea.curr_x == ea.x_at(yb) && eb.curr_x == eb.x_at(yb));
    debug_assert!(ea.next_y == yt && eb.next_y == yt);
    ea.crossing_with(eb, yb, yt, [ea.curr_x, ea.next_x, eb.curr_x, eb.next_x], max_error)
}
