//! Bounds and the local minima table (the paper's LMT): the input rings as linked vertices, each
//! local minimum the start of two bounds that climb to local maxima.

use clip_core::{Point, Polygons};

use crate::simplify::simplify_ring_keeping;
use crate::small_sort::insertion_sorted_by;

/// "No index" for the u32 links of the sweep's arenas.
pub(crate) const NONE: u32 = u32::MAX;

/// Which operand an edge belongs to (the paper's clip/subject type flag); indexes winding pairs.
pub(crate) const SUBJECT: u8 = 0;
/// See [`SUBJECT`].
pub(crate) const CLIP: u8 = 1;

/// An input vertex, linked to its ring neighbours.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Vertex {
    pub pt: Point,
    pub next: u32,
    pub prev: u32,
}

/// A local minimum: where two bounds start. With a horizontal bottom edge `vertex -> next`,
/// the backward bound starts at `vertex` and the forward bound at `next`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LocalMinimum {
    pub vertex: u32,
    pub kind: u8,
    /// True when the minimum is a horizontal edge from `vertex` to its ring successor.
    pub horizontal: bool,
}

/// All input vertices and the local minima table sorted by y.
#[derive(Debug, Default)]
pub(crate) struct Bounds {
    pub vertices: Vec<Vertex>,
    pub minima: Vec<LocalMinimum>,
    /// The ring being simplified (a reused buffer).
    ring: Vec<Point>,
}

impl Bounds {
    /// Links every ring of both operands (repeated and collinear vertices removed, which leaves
    /// the region unchanged; with `noded`, straight-through vertices stay, see
    /// [`simplify_ring_keeping`]) and lists their local minima by increasing y, in this value's
    /// buffers (whatever they held before is dropped).
    pub(crate) fn rebuild(&mut self, subject: &Polygons, clip: &Polygons, noded: bool) {
        let total: usize = [subject, clip].iter().flat_map(|p| &p.rings).map(|r| r.points.len()).sum();
        self.vertices.clear();
        self.minima.clear();
        self.vertices.reserve(total);
        let mut simple = std::mem::take(&mut self.ring);
        for (kind, polygons) in [(SUBJECT, subject), (CLIP, clip)] {
            for ring in &polygons.rings {
                simplify_ring_keeping(&ring.points, &mut simple, noded);
                self.add_ring(&simple, kind);
            }
        }
        self.ring = simple;
        let vertices = &self.vertices;
        // Ties in vertex order, as a stable sort would leave them.
        let by_y = |p: &LocalMinimum, q: &LocalMinimum| {
            vertices[p.vertex as usize].pt.y.total_cmp(&vertices[q.vertex as usize].pt.y).then(p.vertex.cmp(&q.vertex))
        };
        if !insertion_sorted_by(&mut self.minima, |p, q| by_y(p, q).is_lt()) {
            self.minima.sort_unstable_by(by_y);
        }
    }

    /// Points the simplification buffer has room for.
    pub(crate) fn ring_capacity(&self) -> usize {
        self.ring.capacity()
    }

    fn add_ring(&mut self, points: &[Point], kind: u8) {
        let n = points.len() as u32;
        if n < 3 {
            return;
        }
        let base = self.vertices.len() as u32;
        let last = base + n - 1;
        // Links without a division per vertex: only the ends wrap.
        self.vertices.extend(points.iter().zip(base..).map(|(&pt, v)| Vertex {
            pt,
            next: if v == last { base } else { v + 1 },
            prev: if v == base { last } else { v - 1 },
        }));
        for v in base..base + n {
            let here = self.pt(v);
            let before = self.pt(self.vertices[v as usize].prev);
            let next = self.vertices[v as usize].next;
            let after = self.pt(next);
            if before.y > here.y && after.y > here.y {
                self.minima.push(LocalMinimum { vertex: v, kind, horizontal: false });
            } else if before.y > here.y && after.y == here.y && self.pt(self.vertices[next as usize].next).y > here.y {
                // Simplified rings have no two horizontal edges in a row.
                self.minima.push(LocalMinimum { vertex: v, kind, horizontal: true });
            }
        }
    }

    /// The vertex's point.
    #[inline]
    pub(crate) fn pt(&self, v: u32) -> Point {
        self.vertices[v as usize].pt
    }

    /// The next vertex along a bound: the ring successor for a forward bound, else the predecessor.
    #[inline]
    pub(crate) fn along(&self, v: u32, forward: bool) -> u32 {
        let vx = &self.vertices[v as usize];
        if forward { vx.next } else { vx.prev }
    }

    /// y of a local minimum.
    #[inline]
    pub(crate) fn minimum_y(&self, m: &LocalMinimum) -> f64 {
        self.pt(m.vertex).y
    }
}
