//! The form conventional output must have (docs/DESIGN.md), judged strictly and exactly: the
//! output is read by other software (a renderer, a database, the next boolean operation), so a
//! crossing, an overlap or a hole running the wrong way is a wrong answer even when the area is
//! right.
//!
//! One sweep over the vertices in (x, y) order, in the manner of Shamos and Hoey: the edges under
//! the sweep line sit in an ordered set, and each pair is tested when it becomes adjacent. Every
//! decision is an exact orientation (`clip_core::predicates`); nothing is within a tolerance.
//! Edges meet only at output vertices, where the rings passing through are compared by the
//! order of their edges around the point. Cost: O((n + k) log n) for n edges and k places where a
//! vertex lies inside another edge, plus O(d log d) at a point that d rings pass through; no
//! size gate, no pair skipped.

use core::cmp::Ordering;
use core::fmt;
use core::ops::Bound;
use std::collections::BTreeSet;

use clip_core::predicates::{Orientation, SegmentIntersection, orient, segment_intersection};
use clip_core::{Point, Polygons, Ring, Segment};

/// Edge `edge` of ring `ring`: from vertex `edge` to the next one (the last edge closes the ring).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct EdgeAt {
    /// The ring's index in the output.
    pub ring: usize,
    /// The edge's index in the ring.
    pub edge: usize,
}

/// Where a ring passes through a point: at one of its vertices, or inside one of its edges.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Visit {
    /// At vertex `i`.
    Vertex(usize),
    /// Inside edge `i` (strictly between its ends).
    Edge(usize),
}

/// Why conventional output breaks the form of docs/DESIGN.md, and where. Each variant is one
/// fault; [`check_form`] reports the first it meets.
#[derive(Clone, Debug, PartialEq)]
pub enum FormFailure {
    /// A vertex coordinate is NaN or infinite.
    NonFinite {
        /// The ring.
        ring: usize,
        /// The vertex.
        vertex: usize,
        /// Its coordinates.
        point: Point,
    },
    /// A ring encloses no area: fewer than three vertices, or all on one line.
    ZeroArea {
        /// The ring.
        ring: usize,
        /// How many vertices it has.
        vertices: usize,
    },
    /// A ring visits a point twice: a repeated vertex (consecutive or not), or a vertex lying on
    /// another edge of its own ring.
    RepeatedPoint {
        /// The ring.
        ring: usize,
        /// The point.
        point: Point,
        /// Its first visit there.
        first: Visit,
        /// Another visit there.
        second: Visit,
    },
    /// Two edges (of one ring or of two) overlap along a positive length; a zero-width spike is
    /// two consecutive edges of one ring overlapping.
    OverlappingEdges {
        /// One edge.
        first: EdgeAt,
        /// The other.
        second: EdgeAt,
        /// One end of the shared stretch (exact).
        from: Point,
        /// The other end (exact).
        to: Point,
    },
    /// Two rings (or two passes of one ring) cross: two edges crossing inside both, or two rings
    /// meeting at a point where one passes from the inside of the other to its outside.
    Crossing {
        /// An edge of one ring.
        first: EdgeAt,
        /// An edge of the other.
        second: EdgeAt,
        /// Where: exact at a shared point, the crossing rounded to f64 inside two edges.
        near: Point,
    },
    /// An outer ring runs clockwise: a ring at even nesting depth that holds other rings (its
    /// holes), or one held by a hole (an island, depth 2, 4, ...).
    WrongWayOuter {
        /// The ring.
        ring: usize,
        /// How many rings hold it.
        depth: usize,
    },
    /// A hole runs counter-clockwise: a ring held by an odd number of rings.
    WrongWayHole {
        /// The ring.
        ring: usize,
        /// How many rings hold it.
        depth: usize,
    },
    /// A clockwise ring (a hole by its turn) that no ring holds and that holds none: a hole
    /// outside its outer. A lone outer running clockwise looks the same and is reported so.
    HoleOutsideOuter {
        /// The ring.
        ring: usize,
    },
}

impl FormFailure {
    /// The fault's name, for summaries: `non-finite`, `zero-area`, `repeated-point`,
    /// `overlapping-edges`, `crossing`, `wrong-way-outer`, `wrong-way-hole`,
    /// `hole-outside-outer`.
    pub fn kind(&self) -> &'static str {
        match self {
            FormFailure::NonFinite { .. } => "non-finite",
            FormFailure::ZeroArea { .. } => "zero-area",
            FormFailure::RepeatedPoint { .. } => "repeated-point",
            FormFailure::OverlappingEdges { .. } => "overlapping-edges",
            FormFailure::Crossing { .. } => "crossing",
            FormFailure::WrongWayOuter { .. } => "wrong-way-outer",
            FormFailure::WrongWayHole { .. } => "wrong-way-hole",
            FormFailure::HoleOutsideOuter { .. } => "hole-outside-outer",
        }
    }
}

fn at(p: Point) -> String {
    format!("({}, {})", p.x, p.y)
}

impl fmt::Display for Visit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Visit::Vertex(i) => write!(f, "vertex {i}"),
            Visit::Edge(i) => write!(f, "inside edge {i}"),
        }
    }
}

impl fmt::Display for EdgeAt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "ring {} edge {}", self.ring, self.edge)
    }
}

impl fmt::Display for FormFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FormFailure::NonFinite { ring, vertex, point } => {
                write!(f, "ring {ring} vertex {vertex} is not finite ({}, {})", point.x, point.y)
            }
            FormFailure::ZeroArea { ring, vertices } => {
                write!(f, "ring {ring} has zero area ({vertices} vertices, all on one line or fewer than three)")
            }
            FormFailure::RepeatedPoint { ring, point, first, second } => {
                write!(f, "ring {ring} visits {} twice (at {first} and {second})", at(*point))
            }
            FormFailure::OverlappingEdges { first, second, from, to } => {
                write!(f, "{first} and {second} overlap along {} - {}", at(*from), at(*to))
            }
            FormFailure::Crossing { first, second, near } => write!(f, "{first} crosses {second} at {}", at(*near)),
            FormFailure::WrongWayOuter { ring, depth } => {
                write!(f, "ring {ring} is an outer ring (depth {depth}) but runs clockwise")
            }
            FormFailure::WrongWayHole { ring, depth } => {
                write!(f, "ring {ring} is a hole (depth {depth}) but runs counter-clockwise")
            }
            FormFailure::HoleOutsideOuter { ring } => {
                write!(f, "ring {ring} runs clockwise like a hole, but no ring holds it")
            }
        }
    }
}

impl std::error::Error for FormFailure {}

/// Checks conventional output strictly, with exact predicates: every coordinate finite; every
/// ring of positive area that visits no point twice; no two edges crossing or overlapping
/// (whether of one ring or two); rings meeting only at isolated points, where neither passes
/// from the other's inside to its outside; outer rings counter-clockwise and holes clockwise by
/// nesting depth (the number of rings holding them).
pub fn check_form(output: &Polygons) -> Result<(), FormFailure> {
    for (r, ring) in output.rings.iter().enumerate() {
        check_ring(r, ring)?;
    }
    let nesting = Sweep::new(output).run()?;
    check_turns(&nesting)
}

/// What can be judged on a ring alone: finite, positive area, no repeated consecutive vertex, no
/// spike.
fn check_ring(r: usize, ring: &Ring) -> Result<(), FormFailure> {
    let p = &ring.points;
    if let Some(v) = p.iter().position(|q| !q.is_finite()) {
        return Err(FormFailure::NonFinite { ring: r, vertex: v, point: p[v] });
    }
    let n = p.len();
    let zero_area = FormFailure::ZeroArea { ring: r, vertices: n };
    let Some(&other) = p.iter().find(|&&q| q != p[0]) else { return Err(zero_area) };
    if n < 3 || p.iter().all(|&q| orient(p[0], other, q) == Orientation::Collinear) {
        return Err(zero_area);
    }
    for i in 0..n {
        let (j, k) = ((i + 1) % n, (i + 2) % n);
        if p[i] == p[j] {
            return Err(FormFailure::RepeatedPoint {
                ring: r,
                point: p[i],
                first: Visit::Vertex(i),
                second: Visit::Vertex(j),
            });
        }
        if orient(p[i], p[j], p[k]) == Orientation::Collinear && same_direction(p[j], p[i], p[k]) {
            let near = if p[j].distance(p[i]) <= p[j].distance(p[k]) { p[i] } else { p[k] };
            return Err(FormFailure::OverlappingEdges {
                first: EdgeAt { ring: r, edge: i },
                second: EdgeAt { ring: r, edge: j },
                from: p[j],
                to: near,
            });
        }
    }
    Ok(())
}

/// For `a` and `b` on one line through `p` (and distinct from it): true when they lie on the same
/// side of `p`. Exact: compares coordinates.
fn same_direction(p: Point, a: Point, b: Point) -> bool {
    let side = |q: Point| if q.x != p.x { q.x > p.x } else { q.y > p.y };
    side(a) == side(b)
}

/// The sweep order: by x, then by y. Coordinates are finite here, and -0.0 equals 0.0.
fn sweep_order(a: Point, b: Point) -> Ordering {
    a.x.partial_cmp(&b.x).unwrap_or(Ordering::Equal).then(a.y.partial_cmp(&b.y).unwrap_or(Ordering::Equal))
}

/// One output edge, its ends in sweep order.
#[derive(Clone, Copy, Debug)]
struct Edge {
    lo: Point,
    hi: Point,
    at: EdgeAt,
    /// The ring runs it from `lo` to `hi`.
    forward: bool,
}

/// The ids of the two probes that find the pieces through a point: they sort just below and
/// just above every piece through it.
const PROBE_BELOW: usize = usize::MAX - 1;
const PROBE_ABOVE: usize = usize::MAX;

/// What is left of edge `id` beyond the sweep line: from `lo` (its start, or the last point the
/// sweep split it at) to its end. Or a probe, a point with id [`PROBE_BELOW`] or [`PROBE_ABOVE`].
///
/// The order is bottom to top along the sweep line. It is total on the pieces the sweep holds at
/// once: they all span the sweep position and none crosses another (the sweep stops at the first
/// crossing, before it passes it), so two pieces compare the same way wherever they are compared.
#[derive(Clone, Copy, Debug)]
struct Piece {
    lo: Point,
    hi: Point,
    id: usize,
}

impl Piece {
    fn probe(p: Point, id: usize) -> Piece {
        Piece { lo: p, hi: p, id }
    }

    fn is_probe(&self) -> bool {
        self.id >= PROBE_BELOW
    }

    fn segment(&self) -> Segment {
        Segment::new(self.lo, self.hi)
    }
}

/// Where a probe lies against piece `t`.
fn probe_against(probe: &Piece, t: &Piece) -> Ordering {
    match orient(t.lo, t.hi, probe.lo) {
        Orientation::CounterClockwise => Ordering::Greater,
        Orientation::Clockwise => Ordering::Less,
        Orientation::Collinear if probe.id == PROBE_BELOW => Ordering::Less,
        Orientation::Collinear => Ordering::Greater,
    }
}

/// Where piece `s` lies against `t`, `s` starting no earlier than `t` (so `t` spans its start):
/// by the side of `t` its start is on, or, starting on `t`, its end is on. Collinear pieces
/// (an overlap, reported by the sweep) are ordered by id.
fn piece_against(s: &Piece, t: &Piece) -> Ordering {
    let by = |o: Orientation| match o {
        Orientation::CounterClockwise => Some(Ordering::Greater),
        Orientation::Clockwise => Some(Ordering::Less),
        Orientation::Collinear => None,
    };
    by(orient(t.lo, t.hi, s.lo)).or_else(|| by(orient(t.lo, t.hi, s.hi))).unwrap_or_else(|| s.id.cmp(&t.id))
}

impl Ord for Piece {
    fn cmp(&self, other: &Piece) -> Ordering {
        if self.id == other.id {
            return Ordering::Equal;
        }
        match (self.is_probe(), other.is_probe()) {
            (true, true) => self.id.cmp(&other.id),
            (true, false) => probe_against(self, other),
            (false, true) => probe_against(other, self).reverse(),
            (false, false) if sweep_order(self.lo, other.lo) != Ordering::Less => piece_against(self, other),
            (false, false) => piece_against(other, self).reverse(),
        }
    }
}

impl PartialOrd for Piece {
    fn partial_cmp(&self, other: &Piece) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl PartialEq for Piece {
    fn eq(&self, other: &Piece) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Piece {}

/// How the rings nest, as the sweep found it: per ring, its turn, depth and whether it holds
/// another ring.
struct Nesting {
    ccw: Vec<bool>,
    depth: Vec<usize>,
    holds: Vec<bool>,
}

struct Sweep<'a> {
    rings: &'a [Ring],
    edges: Vec<Edge>,
    /// Per ring, the id of its edge 0 (edges are numbered ring by ring).
    offsets: Vec<usize>,
    /// Edge ids by their `lo`, in sweep order.
    starts: Vec<usize>,
    /// Every vertex, in sweep order, once.
    points: Vec<Point>,
    /// Per ring, its first vertex in sweep order.
    first: Vec<Point>,
    status: BTreeSet<Piece>,
    nesting: Nesting,
    /// Per ring, the ring immediately holding it, once the sweep has met it.
    parent: Vec<Option<usize>>,
}

/// One way a ring passes through a point: where it comes from and goes to, and by which edges.
#[derive(Clone, Copy, Debug)]
struct Passage {
    ring: usize,
    visit: Visit,
    from: (Point, usize),
    to: (Point, usize),
}

impl<'a> Sweep<'a> {
    fn new(output: &'a Polygons) -> Sweep<'a> {
        let rings = &output.rings[..];
        let mut edges = Vec::with_capacity(output.vertex_count());
        let mut first = Vec::with_capacity(rings.len());
        let mut ccw = Vec::with_capacity(rings.len());
        let mut offsets = Vec::with_capacity(rings.len());
        for (r, ring) in rings.iter().enumerate() {
            offsets.push(edges.len());
            let p = &ring.points;
            let n = p.len();
            for i in 0..n {
                let (a, b) = (p[i], p[(i + 1) % n]);
                let forward = sweep_order(a, b) == Ordering::Less;
                let (lo, hi) = if forward { (a, b) } else { (b, a) };
                edges.push(Edge { lo, hi, at: EdgeAt { ring: r, edge: i }, forward });
            }
            // The turn at the first vertex in sweep order is the ring's (it has no spike there).
            let v = (0..n).min_by(|&i, &j| sweep_order(p[i], p[j])).unwrap_or(0);
            first.push(p[v]);
            ccw.push(orient(p[(v + n - 1) % n], p[v], p[(v + 1) % n]) == Orientation::CounterClockwise);
        }
        let mut starts: Vec<usize> = (0..edges.len()).collect();
        starts.sort_by(|&i, &j| sweep_order(edges[i].lo, edges[j].lo));
        let mut points: Vec<Point> = rings.iter().flat_map(|r| r.points.iter().copied()).collect();
        points.sort_by(|&a, &b| sweep_order(a, b));
        points.dedup();
        let count = rings.len();
        Sweep {
            rings,
            edges,
            offsets,
            starts,
            points,
            first,
            status: BTreeSet::new(),
            nesting: Nesting { ccw, depth: vec![0; count], holds: vec![false; count] },
            parent: vec![None; count],
        }
    }

    fn run(mut self) -> Result<Nesting, FormFailure> {
        let mut next_start = 0;
        let mut ends: Vec<usize> = Vec::new();
        let mut through: Vec<usize> = Vec::new();
        let mut outgoing: Vec<Piece> = Vec::new();
        for k in 0..self.points.len() {
            let p = self.points[k];
            let (below, above) = (Piece::probe(p, PROBE_BELOW), Piece::probe(p, PROBE_ABOVE));
            // The pieces through p: they end here or pass through (and are split here).
            let here: Vec<Piece> = self.status.range(below..=above).copied().collect();
            ends.clear();
            through.clear();
            outgoing.clear();
            for piece in &here {
                self.status.remove(piece);
                if piece.hi == p {
                    ends.push(piece.id);
                } else {
                    through.push(piece.id);
                    outgoing.push(Piece { lo: p, hi: piece.hi, id: piece.id });
                }
            }
            while next_start < self.starts.len() && self.edges[self.starts[next_start]].lo == p {
                let id = self.starts[next_start];
                ends.push(id);
                outgoing.push(Piece { lo: p, hi: self.edges[id].hi, id });
                next_start += 1;
            }
            // One vertex of one ring (two edge ends, nothing passing through) needs no node check.
            if ends.len() > 2 || !through.is_empty() {
                self.check_node(p, &ends, &through)?;
            }
            self.status.extend(outgoing.iter().copied());
            let lower = self.status.range(..below).next_back().copied();
            let upper = self.status.range((Bound::Excluded(above), Bound::Unbounded)).next().copied();
            if outgoing.is_empty() {
                if let (Some(s), Some(t)) = (lower, upper) {
                    self.check_adjacent(s, t)?;
                }
            } else {
                outgoing.sort_unstable();
                if let Some(s) = lower {
                    self.check_adjacent(s, outgoing[0])?;
                }
                if let Some(t) = upper {
                    self.check_adjacent(outgoing[outgoing.len() - 1], t)?;
                }
                self.nest_rings_starting(p, &outgoing);
            }
        }
        Ok(self.nesting)
    }

    /// Two pieces that became neighbours on the sweep line may touch at an end (judged at that
    /// point) but not cross inside both or overlap.
    fn check_adjacent(&self, s: Piece, t: Piece) -> Result<(), FormFailure> {
        let (e, f) = (self.edges[s.id].at, self.edges[t.id].at);
        match segment_intersection(s.segment(), t.segment()) {
            SegmentIntersection::Crossing(q) => Err(FormFailure::Crossing { first: e, second: f, near: q }),
            SegmentIntersection::Overlap(_) => Err(self.overlap(s.id, t.id)),
            SegmentIntersection::None | SegmentIntersection::Touching(_) => Ok(()),
        }
    }

    fn overlap(&self, a: usize, b: usize) -> FormFailure {
        let (e, f) = (self.edges[a], self.edges[b]);
        let (from, to) = match segment_intersection(Segment::new(e.lo, e.hi), Segment::new(f.lo, f.hi)) {
            SegmentIntersection::Overlap(s) => (s.a, s.b),
            _ => (e.lo, e.hi),
        };
        FormFailure::OverlappingEdges { first: e.at, second: f.at, from, to }
    }

    /// At a point where several rings meet (or one ring twice): no ring visits it twice, no two
    /// edges leave it the same way (they overlap), and no two rings' passages interleave around
    /// it (one would go from the other's inside to its outside).
    fn check_node(&self, p: Point, ends: &[usize], through: &[usize]) -> Result<(), FormFailure> {
        let mut passages: Vec<Passage> = Vec::with_capacity(ends.len() / 2 + through.len());
        for &id in ends {
            let EdgeAt { ring, edge } = self.edges[id].at;
            let pts = &self.rings[ring].points;
            let n = pts.len();
            let v = if pts[edge] == p { edge } else { (edge + 1) % n };
            let (u, w) = ((v + n - 1) % n, (v + 1) % n);
            passages.push(Passage { ring, visit: Visit::Vertex(v), from: (pts[u], u), to: (pts[w], v) });
        }
        for &id in through {
            let EdgeAt { ring, edge } = self.edges[id].at;
            let pts = &self.rings[ring].points;
            let next = (edge + 1) % pts.len();
            passages.push(Passage { ring, visit: Visit::Edge(edge), from: (pts[edge], edge), to: (pts[next], edge) });
        }
        passages.sort_unstable_by_key(|q| (q.ring, q.visit));
        passages.dedup_by_key(|q| (q.ring, q.visit));
        if let Some(w) = passages.windows(2).find(|w| w[0].ring == w[1].ring) {
            return Err(FormFailure::RepeatedPoint {
                ring: w[0].ring,
                point: p,
                first: w[0].visit,
                second: w[1].visit,
            });
        }
        // The edges leaving p, by angle: (direction, passage, edge).
        let mut spokes: Vec<(Point, usize, usize)> =
            passages.iter().enumerate().flat_map(|(k, q)| [(q.from.0, k, q.from.1), (q.to.0, k, q.to.1)]).collect();
        spokes.sort_by(|a, b| around(p, a.0, b.0));
        if let Some(w) = spokes.windows(2).find(|w| around(p, w[0].0, w[1].0) == Ordering::Equal) {
            let id = |k: usize, e: usize| self.offsets[passages[k].ring] + e;
            return Err(self.overlap(id(w[0].1, w[0].2), id(w[1].1, w[1].2)));
        }
        // Passages that do not interleave nest like parentheses, wherever the circle is cut.
        let mut open: Vec<(usize, usize)> = Vec::new();
        let mut seen = vec![false; passages.len()];
        for &(_, k, e) in &spokes {
            match open.last() {
                Some(&(top, _)) if top == k => {
                    open.pop();
                }
                Some(&(top, top_edge)) if seen[k] => {
                    return Err(FormFailure::Crossing {
                        first: EdgeAt { ring: passages[k].ring, edge: e },
                        second: EdgeAt { ring: passages[top].ring, edge: top_edge },
                        near: p,
                    });
                }
                _ => {
                    seen[k] = true;
                    open.push((k, e));
                }
            }
        }
        Ok(())
    }

    /// Finds, for each ring whose first vertex is `p`, the ring immediately holding it: from the
    /// piece just below its lower edge. If that piece's ring has its inside above the piece, it
    /// holds the new ring; otherwise the new ring sits beside it, in whatever holds that ring.
    /// Rings starting at one point are taken bottom to top, so the one below is always known.
    fn nest_rings_starting(&mut self, p: Point, outgoing: &[Piece]) {
        // `outgoing` is sorted: a ring's first piece in it is its lower edge.
        let mut met: Vec<usize> = Vec::new();
        for piece in outgoing {
            let ring = self.edges[piece.id].at.ring;
            if self.first[ring] != p || met.contains(&ring) {
                continue;
            }
            met.push(ring);
            let parent = self.status.range(..*piece).next_back().and_then(|below| {
                let e = self.edges[below.id];
                let s = e.at.ring;
                if self.nesting.ccw[s] == e.forward { Some(s) } else { self.parent[s] }
            });
            self.parent[ring] = parent;
            if let Some(s) = parent {
                self.nesting.depth[ring] = self.nesting.depth[s] + 1;
                self.nesting.holds[s] = true;
            }
        }
    }
}

/// The order of directions around `p`, counter-clockwise from the positive x axis, exactly.
fn around(p: Point, a: Point, b: Point) -> Ordering {
    let half = |q: Point| !(q.y > p.y || (q.y == p.y && q.x > p.x));
    half(a).cmp(&half(b)).then_with(|| match orient(p, a, b) {
        Orientation::CounterClockwise => Ordering::Less,
        Orientation::Clockwise => Ordering::Greater,
        Orientation::Collinear => Ordering::Equal,
    })
}

/// Outer rings (even depth) counter-clockwise, holes (odd depth) clockwise.
fn check_turns(nesting: &Nesting) -> Result<(), FormFailure> {
    for (ring, (&ccw, &depth)) in nesting.ccw.iter().zip(&nesting.depth).enumerate() {
        match (depth % 2 == 0, ccw) {
            (true, true) | (false, false) => {}
            (false, true) => return Err(FormFailure::WrongWayHole { ring, depth }),
            (true, false) if depth == 0 && !nesting.holds[ring] => return Err(FormFailure::HoleOutsideOuter { ring }),
            (true, false) => return Err(FormFailure::WrongWayOuter { ring, depth }),
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::ring_winding;
    use proptest::prelude::*;

    /// The sweep's verdict in three words: valid, broken in topology, or turned the wrong way (and
    /// how); the all-pairs reference below gives the same words.
    #[derive(Debug, PartialEq)]
    enum Verdict {
        Valid,
        Topology,
        Turn(FormFailure),
    }

    fn sweep_verdict(output: &Polygons) -> Verdict {
        match check_form(output) {
            Ok(()) => Verdict::Valid,
            Err(
                f @ (FormFailure::WrongWayOuter { .. }
                | FormFailure::WrongWayHole { .. }
                | FormFailure::HoleOutsideOuter { .. }),
            ) => Verdict::Turn(f),
            Err(_) => Verdict::Topology,
        }
    }

    /// The same judgement by brute force: every pair of edges, every ring at every vertex, and
    /// nesting by exact winding numbers at a point of each ring off the other.
    fn all_pairs_verdict(output: &Polygons) -> Verdict {
        let rings = &output.rings;
        if rings.iter().enumerate().any(|(r, ring)| check_ring(r, ring).is_err()) {
            return Verdict::Topology;
        }
        let edges: Vec<(usize, Segment)> =
            rings.iter().enumerate().flat_map(|(r, ring)| ring.edges().map(move |e| (r, e))).collect();
        for (i, &(_, e)) in edges.iter().enumerate() {
            for &(_, f) in &edges[i + 1..] {
                if matches!(
                    segment_intersection(e, f),
                    SegmentIntersection::Crossing(_) | SegmentIntersection::Overlap(_)
                ) {
                    return Verdict::Topology;
                }
            }
        }
        for q in rings.iter().flat_map(|r| r.points.iter().copied()) {
            // (ring, from, to) for every pass through q.
            let mut passes: Vec<(usize, Point, Point)> = Vec::new();
            for (r, ring) in rings.iter().enumerate() {
                let p = &ring.points;
                let n = p.len();
                for i in 0..n {
                    let (a, b) = (p[i], p[(i + 1) % n]);
                    if a == q {
                        passes.push((r, p[(i + n - 1) % n], b));
                    } else if b != q
                        && orient(a, b, q) == Orientation::Collinear
                        && Segment::new(a, b).bounds().contains(q)
                    {
                        passes.push((r, a, b));
                    }
                }
            }
            for (k, x) in passes.iter().enumerate() {
                for y in &passes[k + 1..] {
                    if x.0 == y.0 {
                        return Verdict::Topology;
                    }
                    let mut four = [(x.1, 0), (x.2, 0), (y.1, 1), (y.2, 1)];
                    four.sort_by(|a, b| around(q, a.0, b.0));
                    let same = four.windows(2).any(|w| around(q, w[0].0, w[1].0) == Ordering::Equal);
                    let interleaved = four[0].1 == four[2].1;
                    if same || interleaved {
                        return Verdict::Topology;
                    }
                }
            }
        }
        let inside = |r: &Ring, s: &Ring| {
            let probes = r.points.iter().copied().chain(r.edges().map(|e| e.at(0.5)));
            probes.filter_map(|p| ring_winding(p, s)).next().is_some_and(|w| w != 0)
        };
        let depth: Vec<usize> = (0..rings.len())
            .map(|r| (0..rings.len()).filter(|&s| s != r && inside(&rings[r], &rings[s])).count())
            .collect();
        let holds: Vec<bool> = (0..rings.len())
            .map(|s| (0..rings.len()).any(|r| r != s && depth[r] == depth[s] + 1 && inside(&rings[r], &rings[s])))
            .collect();
        let ccw = rings.iter().map(Ring::runs_counter_clockwise).collect();
        match check_turns(&Nesting { ccw, depth, holds }) {
            Ok(()) => Verdict::Valid,
            Err(f) => Verdict::Turn(f),
        }
    }

    fn grid_rings() -> impl Strategy<Value = Polygons> {
        let ring = prop::collection::vec((0i32..5, 0i32..5), 3..7)
            .prop_map(|v| Ring::new(v.into_iter().map(|(x, y)| Point::new(f64::from(x), f64::from(y))).collect()));
        prop::collection::vec(ring, 1..4).prop_map(Polygons::new)
    }

    fn squares() -> impl Strategy<Value = Polygons> {
        // Axis-aligned squares on a grid, either way round: they nest, touch and share corners.
        let square = (0i32..6, 0i32..6, 1i32..5, any::<bool>()).prop_map(|(x, y, s, cw)| {
            let r = clip_core::Rect::new(f64::from(x), f64::from(y), f64::from(x + s), f64::from(y + s)).to_ring();
            if cw { r.reversed() } else { r }
        });
        prop::collection::vec(square, 1..6).prop_map(Polygons::new)
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

        #[test]
        fn the_sweep_agrees_with_all_pairs_on_grid_rings(output in grid_rings()) {
            prop_assert_eq!(sweep_verdict(&output), all_pairs_verdict(&output), "{:?}", output);
        }

        #[test]
        fn the_sweep_agrees_with_all_pairs_on_nested_squares(output in squares()) {
            prop_assert_eq!(sweep_verdict(&output), all_pairs_verdict(&output), "{:?}", output);
        }
    }
}
