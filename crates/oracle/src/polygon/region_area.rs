//! Exact-topology area of a boolean combination of regions, by slab decomposition.
//!
//! Horizontal lines through every vertex cut the plane into slabs; inside a slab the edges
//! crossing it keep their order except where two of them cross, and those crossings are the
//! inversions between the order at the slab's bottom and at its top. Each gap between
//! neighbouring edges is a trapezoid (area: height times width at mid-height) whose membership
//! follows from the winding counts of each layer to its left. A crossing swaps two neighbours,
//! which changes only the gaps around them, so a slab costs O(active edges + crossings), not
//! O(active edges) per crossing.

use clip_core::{FillRule, Point, Polygons};

/// A non-horizontal edge, stored bottom to top.
#[derive(Clone, Copy, Debug)]
struct SlabEdge {
    bottom: Point,
    top: Point,
    /// dx/dy along the edge.
    slope: f64,
    layer: usize,
    /// Change of the layer's winding number when a left-to-right walk crosses the edge: +1 for
    /// a downward edge, -1 for an upward one (a counter-clockwise ring winds +1 inside).
    wind: i32,
}

impl SlabEdge {
    #[inline]
    fn x_at(&self, y: f64) -> f64 {
        if y == self.bottom.y {
            self.bottom.x
        } else if y == self.top.y {
            self.top.x
        } else {
            self.bottom.x + (y - self.bottom.y) * self.slope
        }
    }
}

/// The area of `{ p : predicate(in_0(p), in_1(p), ...) }`, where `in_i(p)` says whether layer
/// `i`'s rings cover `p` under its fill rule. Library-independent: it reads only the rings.
///
/// ```
/// use clip_core::{FillRule, Polygons, Rect};
/// use clip_oracle::polygon::region_area;
///
/// let a = Polygons::from(Rect::new(0.0, 0.0, 2.0, 2.0));
/// let b = Polygons::from(Rect::new(1.0, 1.0, 3.0, 3.0));
/// let union = region_area(&[(&a, FillRule::NonZero), (&b, FillRule::NonZero)], |i| i[0] || i[1]);
/// assert_eq!(union, 7.0);
/// ```
pub fn region_area(layers: &[(&Polygons, FillRule)], predicate: impl Fn(&[bool]) -> bool) -> f64 {
    region_area_with_witness(layers, predicate).0
}

/// Like [`region_area`], and also the centre of the largest trapezoid counted (a point well
/// inside the region, for failure reports), or `None` when the area is zero.
pub fn region_area_with_witness(
    layers: &[(&Polygons, FillRule)],
    predicate: impl Fn(&[bool]) -> bool,
) -> (f64, Option<Point>) {
    let mut edges = collect_edges(layers);
    if edges.is_empty() {
        return (0.0, None);
    }
    edges.sort_unstable_by(|a, b| a.bottom.y.total_cmp(&b.bottom.y));
    let ys = slab_heights(&edges);

    let mut sweep = Sweep::new(layers, edges.len(), &predicate);
    // Active edges (indices into `edges`), in left-to-right order.
    let mut active: Vec<usize> = Vec::new();
    let mut crossings: Vec<Crossing> = Vec::new();
    let mut deferred: Vec<Crossing> = Vec::new();
    let mut scratch = (Vec::new(), Vec::new());
    let mut next = 0;
    for w in ys.windows(2) {
        let (y0, y1) = (w[0], w[1]);
        active.retain(|&i| edges[i].top.y > y0);
        while next < edges.len() && edges[next].bottom.y <= y0 {
            if edges[next].top.y > y0 {
                active.push(next);
            }
            next += 1;
        }
        if active.is_empty() {
            continue;
        }
        // Order at the slab's bottom, ties broken by the top (so by the order just above y0).
        for &i in &active {
            sweep.xs[i] = edges[i].x_at(y0);
        }
        let xs = &sweep.xs;
        insertion_sort(&mut active, |a, b| xs[a] > xs[b] || (xs[a] == xs[b] && edges[a].x_at(y1) > edges[b].x_at(y1)));
        crossings.clear();
        find_crossings(&edges, &active, (y0, y1), &mut crossings, &mut scratch);
        crossings.sort_unstable_by(|a, b| a.y.total_cmp(&b.y));
        sweep.open(&edges, &active, y0);
        // Crossings at (nearly) one height may come in an order where a pair is not yet
        // neighbours; such a pair waits until the others at that height are done.
        let near = 1e-6 * (y1 - y0);
        for (k, c) in crossings.iter().enumerate() {
            if sweep.swap(&edges, &mut active, c, c.y) {
                while deferred.iter().any(|d| sweep.swap(&edges, &mut active, d, c.y)) {
                    deferred.retain(|d| sweep.position[d.left] < sweep.position[d.right]);
                }
            } else {
                deferred.push(*c);
            }
            let y_next = crossings.get(k + 1).map_or(y1, |n| n.y);
            if !deferred.is_empty() && y_next > c.y + near {
                sweep.resort(&edges, &mut active, c.y, y_next);
                deferred.clear();
            }
        }
        sweep.close_all(&edges, &active, y1);
    }
    (sweep.area, sweep.best.1)
}

/// Two edges that swap places at height `y`: `left` was left of `right` below it.
#[derive(Clone, Copy, Debug)]
struct Crossing {
    y: f64,
    left: usize,
    right: usize,
}

/// How many edge-slab pairs [`region_area`] visits on `layers`: the sum over its slabs of the
/// edges crossing each (crossings inside slabs add to its work; simple rings have none). It is
/// near-linear for most inputs but quadratic where a horizontal line crosses a fixed share of all
/// edges (a star with 10^6 spikes: about 10^11), so callers with big inputs can check it first.
/// O(n log n).
///
/// ```
/// use clip_core::{FillRule, Polygons, Rect};
/// use clip_oracle::polygon::region_area_work;
///
/// // Two edges crossing one slab, and a second box level with it adds two more.
/// let a = Polygons::from(Rect::new(0.0, 0.0, 1.0, 1.0));
/// let b = Polygons::from(Rect::new(2.0, 0.0, 3.0, 1.0));
/// assert_eq!(region_area_work(&[(&a, FillRule::NonZero)]), 2);
/// assert_eq!(region_area_work(&[(&a, FillRule::NonZero), (&b, FillRule::NonZero)]), 4);
/// ```
pub fn region_area_work(layers: &[(&Polygons, FillRule)]) -> u64 {
    let edges = collect_edges(layers);
    let ys = slab_heights(&edges);
    // An edge is active in the slabs from its bottom up to its top: one per height in between.
    let slot = |y: f64| ys.partition_point(|&h| h < y) as u64;
    edges.iter().map(|e| slot(e.top.y) - slot(e.bottom.y)).sum()
}

/// The heights of the slabs' bottoms and tops: every edge's ends, sorted, without repeats.
fn slab_heights(edges: &[SlabEdge]) -> Vec<f64> {
    let mut ys: Vec<f64> = edges.iter().flat_map(|e| [e.bottom.y, e.top.y]).collect();
    ys.sort_unstable_by(f64::total_cmp);
    ys.dedup();
    ys
}

fn collect_edges(layers: &[(&Polygons, FillRule)]) -> Vec<SlabEdge> {
    let mut edges = Vec::new();
    for (layer, (polygons, _)) in layers.iter().enumerate() {
        for ring in &polygons.rings {
            let n = ring.points.len();
            for i in 0..n {
                let (a, b) = (ring.points[i], ring.points[(i + 1) % n]);
                if a.y == b.y || !a.is_finite() || !b.is_finite() {
                    continue;
                }
                let (bottom, top, wind) = if a.y < b.y { (a, b, -1) } else { (b, a, 1) };
                let slope = (top.x - bottom.x) / (top.y - bottom.y);
                edges.push(SlabEdge { bottom, top, slope, layer, wind });
            }
        }
    }
    edges
}

/// Pushes every crossing inside `(y0, y1)`: the pairs whose order at `y1` is the
/// reverse of their order at `y0` (`active` is sorted at `y0`). Found by insertion-sorting a
/// copy by the x at `y1`, one swap per inverted pair.
/// `scratch` holds the x at `y1` per active edge and their order, reused between slabs.
fn find_crossings(
    edges: &[SlabEdge],
    active: &[usize],
    (y0, y1): (f64, f64),
    out: &mut Vec<Crossing>,
    (tops, order): &mut (Vec<f64>, Vec<usize>),
) {
    tops.clear();
    tops.extend(active.iter().map(|&i| edges[i].x_at(y1)));
    if tops.windows(2).all(|w| w[0] <= w[1]) {
        return;
    }
    order.clear();
    order.extend(0..active.len());
    let h = y1 - y0;
    for k in 1..order.len() {
        let mut j = k;
        while j > 0 && tops[order[j - 1]] > tops[order[j]] {
            let (l, r) = (&edges[active[order[j - 1]]], &edges[active[order[j]]]);
            // l starts left of r at y0 and ends right of it at y1.
            let gap0 = r.x_at(y0) - l.x_at(y0);
            let gap1 = l.x_at(y1) - r.x_at(y1);
            let s = if gap0 + gap1 > 0.0 { (gap0 / (gap0 + gap1)).clamp(0.0, 1.0) } else { 0.5 };
            let y = (y0 + s * h).clamp(y0, y1);
            out.push(Crossing { y, left: active[order[j - 1]], right: active[order[j]] });
            order.swap(j - 1, j);
            j -= 1;
        }
    }
}

/// Sorts in place with `greater(a, b)` meaning `a` belongs after `b`; linear on nearly
/// sorted input, which is what consecutive slabs give.
fn insertion_sort(v: &mut [usize], mut greater: impl FnMut(usize, usize) -> bool) {
    for k in 1..v.len() {
        let mut j = k;
        while j > 0 && greater(v[j - 1], v[j]) {
            v.swap(j - 1, j);
            j -= 1;
        }
    }
}

/// The running state of one area computation, reused across slabs: for each gap between
/// neighbouring active edges, where its current trapezoid started, the winding counts left of
/// it, and whether the predicate keeps it.
struct Sweep<'p, P: Fn(&[bool]) -> bool> {
    fills: Vec<FillRule>,
    predicate: &'p P,
    /// Scratch x per edge, for sorting.
    xs: Vec<f64>,
    /// Position of each active edge in the order.
    position: Vec<usize>,
    gap_start: Vec<f64>,
    gap_kept: Vec<bool>,
    /// Winding counts left of each gap, `layers` per gap.
    gap_windings: Vec<i32>,
    /// Scratch: the running winding counts and inside flags of a left-to-right walk.
    windings: Vec<i32>,
    inside: Vec<bool>,
    area: f64,
    best: (f64, Option<Point>),
}

impl<'p, P: Fn(&[bool]) -> bool> Sweep<'p, P> {
    fn new(layers: &[(&Polygons, FillRule)], edges: usize, predicate: &'p P) -> Self {
        Sweep {
            fills: layers.iter().map(|l| l.1).collect(),
            predicate,
            xs: vec![0.0; edges],
            position: vec![0; edges],
            gap_start: Vec::new(),
            gap_kept: Vec::new(),
            gap_windings: Vec::new(),
            windings: vec![0; layers.len()],
            inside: vec![false; layers.len()],
            area: 0.0,
            best: (0.0, None),
        }
    }

    /// Starts every gap of `order` at height `y`.
    fn open(&mut self, edges: &[SlabEdge], order: &[usize], y: f64) {
        let (m, l) = (order.len(), self.fills.len());
        let gaps = m.saturating_sub(1);
        self.gap_start.clear();
        self.gap_start.resize(gaps, y);
        self.gap_kept.clear();
        self.gap_kept.resize(gaps, false);
        self.gap_windings.clear();
        self.gap_windings.resize(gaps * l, 0);
        for (k, &e) in order.iter().enumerate() {
            self.position[e] = k;
        }
        // One running count left to right; only the crossed edge's layer changes per gap.
        self.windings.iter_mut().for_each(|w| *w = 0);
        self.inside.iter_mut().for_each(|f| *f = false);
        for k in 0..gaps {
            let e = &edges[order[k]];
            self.windings[e.layer] += e.wind;
            self.inside[e.layer] = self.fills[e.layer].is_inside(self.windings[e.layer]);
            self.gap_windings[k * l..(k + 1) * l].copy_from_slice(&self.windings);
            self.gap_kept[k] = (self.predicate)(&self.inside);
        }
    }

    /// Recomputes gap `k`'s winding counts (from gap `k - 1`'s) and whether it is kept.
    fn update_gap(&mut self, edges: &[SlabEdge], order: &[usize], k: usize) {
        let l = self.fills.len();
        if k == 0 {
            self.gap_windings[..l].iter_mut().for_each(|w| *w = 0);
        } else {
            self.gap_windings.copy_within((k - 1) * l..k * l, k * l);
        }
        let e = &edges[order[k]];
        self.gap_windings[k * l + e.layer] += e.wind;
        for (layer, flag) in self.inside.iter_mut().enumerate() {
            *flag = self.fills[layer].is_inside(self.gap_windings[k * l + layer]);
        }
        self.gap_kept[k] = (self.predicate)(&self.inside);
    }

    /// Ends gap `k`'s current trapezoid at height `y`, counting it if kept.
    fn close(&mut self, edges: &[SlabEdge], order: &[usize], k: usize, y: f64) {
        let start = self.gap_start[k];
        self.gap_start[k] = y;
        if !self.gap_kept[k] || y <= start {
            return;
        }
        let ym = 0.5 * (start + y);
        let (xl, xr) = (edges[order[k]].x_at(ym), edges[order[k + 1]].x_at(ym));
        if xr > xl {
            let piece = (xr - xl) * (y - start);
            self.area += piece;
            if piece > self.best.0 {
                self.best = (piece, Some(Point::new(0.5 * (xl + xr), ym)));
            }
        }
    }

    fn close_all(&mut self, edges: &[SlabEdge], order: &[usize], y: f64) {
        for k in 0..order.len().saturating_sub(1) {
            self.close(edges, order, k, y);
        }
    }

    /// Swaps the two edges of a crossing at height `y` when they are neighbours, closing the
    /// three gaps the swap changes. True when they are swapped now or were already.
    fn swap(&mut self, edges: &[SlabEdge], order: &mut [usize], c: &Crossing, y: f64) -> bool {
        let (pl, pr) = (self.position[c.left], self.position[c.right]);
        if pr < pl {
            return true;
        }
        if pr != pl + 1 {
            return false;
        }
        let gaps = order.len() - 1;
        for k in pl.saturating_sub(1)..=(pl + 1).min(gaps - 1) {
            self.close(edges, order, k, y);
        }
        order.swap(pl, pr);
        self.position[order[pl]] = pl;
        self.position[order[pr]] = pr;
        self.update_gap(edges, order, pl);
        true
    }

    /// Where rounding has put edges out of step with the crossings found: closes every gap at
    /// `y` and re-sorts the order at the height midway to `y_next`.
    fn resort(&mut self, edges: &[SlabEdge], order: &mut [usize], y: f64, y_next: f64) {
        self.close_all(edges, order, y);
        let ym = 0.5 * (y + y_next);
        for &i in order.iter() {
            self.xs[i] = edges[i].x_at(ym);
        }
        let xs = &self.xs;
        insertion_sort(order, |a, b| xs[a] > xs[b]);
        self.open(edges, order, y);
    }
}
