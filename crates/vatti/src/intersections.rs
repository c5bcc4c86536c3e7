//! Edge crossings inside a scanbeam: the paper's sorted edge table (ST) finds them from the
//! edges' x at the top, the intersection table (IT) holds them sorted by y, and they are
//! processed so that only adjacent edges are ever swapped.

use clip_core::Point;
use clip_core::predicates::{Orientation, orient};

use crate::active::ROUNDING;
use crate::scanbeam::height_key;
use crate::small_sort::insertion_sorted_by;
use crate::sweep::Sweep;

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
pub(crate) struct TopX {
    pub x: f64,
    pub magnitude: f64,
}

impl Sweep<'_> {
    /// Finds and processes every crossing in the scanbeam `[yb, yt]`, emitting trapezoids
    /// between consecutive crossing heights when asked.
    pub(crate) fn process_intersections(&mut self, yb: f64, yt: f64) {
        let mut table = self.intersection_table(yb, yt);
        let mut y_prev = yb;
        for i in 0..table.len() {
            if !self.adjacent(&table[i]) {
                // Crossings at (nearly) one height may come in any order; take the next one that
                // is adjacent now. One always is: the table holds exactly the inversions left.
                match (i + 1..table.len()).find(|&j| self.adjacent(&table[j])) {
                    Some(j) => table.swap(i, j),
                    None => break,
                }
            }
            let node = table[i];
            if self.traps.is_some() && node.pt.y > y_prev {
                self.emit_slab(y_prev, node.pt.y);
                y_prev = node.pt.y;
            }
            let pos = self.ael.pos(node.left);
            self.rounded_crossing = true;
            self.cross(pos, node.pt);
            self.rounded_crossing = false;
        }
        if self.traps.is_some() && yt > y_prev {
            self.emit_slab(y_prev, yt);
        }
        table.clear();
        self.table = table;
    }

    #[inline]
    fn adjacent(&self, node: &Intersection) -> bool {
        self.ael.pos(node.left) + 1 == self.ael.pos(node.right)
    }

    /// Builds the intersection table: the active edges are inserted right to left by their x
    /// at `yt`; each edge an edge has to jump over is a crossing (the paper's ST pass).
    fn intersection_table(&mut self, yb: f64, yt: f64) -> Vec<Intersection> {
        let n = self.ael.len();
        let mut table = std::mem::take(&mut self.table);
        if n < 2 {
            return table;
        }
        let mut xtop = std::mem::take(&mut self.xtop);
        xtop.clear();
        // Extended from the order's exact-length iterator: no capacity test per edge.
        let edges = &mut self.ael.edges;
        xtop.extend(self.ael.order.iter().map(|&id| {
            let e = &mut edges[id as usize];
            e.next_x = e.x_at(yt);
            e.next_y = yt;
            TopX { x: e.next_x, magnitude: e.magnitude.x_max }
        }));
        // Most beams have no crossing: then no edge passes its left neighbour, and the
        // insertion sort below would find nothing. Before the first edge that does, the
        // insertion sort would only confirm the order, so it starts there.
        let Some(first) = (1..n).find(|&i| self.left_at_top(i, xtop[i], i - 1, xtop[i - 1], yt)) else {
            self.xtop = xtop;
            return table;
        };
        // Sorted edge table: positions in the active edge table, by x at the top.
        let mut st = std::mem::take(&mut self.sorted);
        st.clear();
        st.extend(0..first as u32);
        for i in first..n {
            let mut j = st.len();
            st.push(i as u32);
            while j > 0 && self.left_at_top(i, xtop[i], st[j - 1] as usize, xtop[st[j - 1] as usize], yt) {
                let (left, right) = (self.ael.at(st[j - 1] as usize), self.ael.at(i));
                let pt = self.crossing_point(left, right, yb, yt);
                table.push(Intersection { left, right, pt, y_key: height_key(pt.y) });
                st[j] = st[j - 1];
                j -= 1;
            }
            st[j] = i as u32;
        }
        self.xtop = xtop;
        self.sorted = st;
        // By height, ties in the order found.
        if !insertion_sorted_by(&mut table, |a, b| a.y_key < b.y_key) {
            table.sort_by_key(|a| a.y_key);
        }
        table
    }

    /// True when the edge at active position `i` lies strictly left of the one at `k` at the
    /// beam's top `yt`, given their rounded x there (`xi`, `xk`). Where those are within rounding
    /// of each other, decided exactly in the cases where rounding would invent a crossing that
    /// cannot exist: edges from one bottom vertex, and an edge ending at `yt` (its top is an
    /// exact input vertex) beside one passing it. (Found by the `vatti` fuzz target: a sliver
    /// triangle whose two bounds leave its lowest vertex 1e-16 apart in slope was swapped by a
    /// rounded x and came out clockwise.) Two edges passing `yt` keep the rounded order: a crossing
    /// within rounding of `yt` is then taken in this beam or the next, at most ulps away.
    #[inline(always)]
    fn left_at_top(&self, i: usize, ti: TopX, k: usize, tk: TopX, yt: f64) -> bool {
        let (xi, xk) = (ti.x, tk.x);
        if (xi - xk).abs() > ROUNDING * ti.magnitude.max(tk.magnitude) {
            return xi < xk;
        }
        self.left_at_top_near(i, xi, k, xk, yt)
    }

    /// [`Sweep::left_at_top`] for x values within rounding of each other: rare, so kept out of
    /// line to leave the comparison loops tight.
    #[cold]
    #[inline(never)]
    fn left_at_top_near(&self, i: usize, xi: f64, k: usize, xk: f64, yt: f64) -> bool {
        let (a, b) = (self.ael.get(self.ael.at(i)), self.ael.get(self.ael.at(k)));
        let left = Orientation::CounterClockwise;
        if a.bot == b.bot {
            orient(a.bot, b.top, a.top) == left
        } else if a.top.y == yt && b.top.y != yt {
            orient(b.bot, b.top, a.top) == left
        } else if b.top.y == yt && a.top.y != yt {
            orient(a.bot, a.top, b.top) == Orientation::Clockwise
        } else {
            xi < xk
        }
    }

    /// Where edges `a` and `b` cross, computed once and kept inside the scanbeam: y clamped to
    /// `[yb, yt]` (x then taken on the steeper edge), x clamped to the edges' span in the beam.
    fn crossing_point(&self, a: u32, b: u32, yb: f64, yt: f64) -> Point {
        let (ea, eb) = (self.ael.get(a), self.ael.get(b));
        let (d1, d2) = (ea.top - ea.bot, eb.top - eb.bot);
        let den = d1.cross(d2);
        let num = (eb.bot - ea.bot).cross(d2);
        // Division last: exact whenever the true point is representable and the products fit.
        let mut p = Point::new((ea.bot.x * den + num * d1.x) / den, (ea.bot.y * den + num * d1.y) / den);
        if !p.is_finite() {
            let s = num / den;
            p = Point::new(ea.bot.x + s * d1.x, ea.bot.y + s * d1.y);
        }
        if !(p.y >= yb && p.y <= yt) {
            let y = if p.y > yt { yt } else { yb };
            let steeper = if (d1.x / d1.y).abs() <= (d2.x / d2.y).abs() { ea } else { eb };
            p = Point::new(steeper.x_at(y), y);
        }
        // At the beam's bottom every active edge's `curr_x` is its `x_at(yb)`, computed when the
        // scanline was processed: taking it spares two divisions per crossing.
        // Their x at the top was cached for this beam by `intersection_table`.
        debug_assert!(ea.curr_x == ea.x_at(yb) && eb.curr_x == eb.x_at(yb));
        debug_assert!(ea.next_y == yt && eb.next_y == yt);
        let xs = [ea.curr_x, ea.next_x, eb.curr_x, eb.next_x];
        let lo = xs.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = xs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Point::new(if p.x.is_finite() { p.x.clamp(lo, hi) } else { 0.5 * (lo + hi) }, p.y)
    }
}
