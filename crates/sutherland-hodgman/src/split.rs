//! The notes' fix for concave results: each output list cut where it runs along the window, and the pieces rejoined in pairs along the window boundary.
//!
//! The notes: "modify the Sutherland-Hodgeman approach to check the final vertex list for
//! multiple vertex points along any clip window boundary and correctly join pairs of vertices".
//! Here every subject ring is clipped with tagged vertices ([`TaggedVertex`]), so an output edge
//! runs along boundary `k` exactly when both its ends lie on `k` (no tolerance). Those edges, the
//! *runs*, are removed; what is left of each list is a set of *chains*, each entering the window
//! at one perimeter point and leaving it at another. Each chain's exit is then joined to an
//! entry by a *walk* along the window boundary, and the walks close the chains into rings.
//!
//! Which entry? Let `c(s)` be the net number of times the removed runs cover perimeter point `s`
//! (counter-clockwise +1, clockwise -1): a point just inside the window at `s` has winding number
//! `c(s)`. Going counter-clockwise, `c` rises by one at every exit and falls by one at every
//! entry. The walks are laid to cover `s` exactly `c(s)` times, counter-clockwise where `c > 0`
//! and clockwise where `c < 0`, paired last-opened-first-closed; layers no endpoint opens or
//! closes are whole window loops. So every winding number inside the window is kept (the output
//! is the same region as Sutherland-Hodgman's, under any fill rule), and no walk runs against
//! another: the bridges, which are runs covering a stretch both ways, cancel out. A chain vertex
//! that touches the boundary between its ends splits the chain there, so a walk passing it closes
//! one ring and opens the next: rings meet at such a point instead of one visiting it twice. For a
//! subject in conventional form `c` is 0 or 1, so the rings are simple, outers counter-clockwise
//! and holes clockwise: the conventional output of docs/DESIGN.md.
//!
//! Every decision is exact: the tags come from exact side tests, and perimeter positions are
//! compared by coordinates along each boundary's dominant axis.

use std::cmp::Ordering;

use clip_core::{Point, Polygons, Ring};

use crate::list_form::clip_list;
use crate::vertex::{StageVertex, TaggedVertex};
use crate::window::ConvexWindow;

/// Clips every ring of `subject` and rejoins the pieces into separate rings (see the module docs).
/// Rings that enclose no area are dropped by `keep`.
pub(crate) fn clip_split(subject: &Polygons, window: &ConvexWindow, keep: impl Fn(Ring) -> Option<Ring>) -> Polygons {
    let perimeter = Perimeter::new(window);
    let mut pieces = Pieces::default();
    for ring in &subject.rings {
        let tagged: Vec<TaggedVertex> = ring.points.iter().map(|&p| on_lines(p, window)).collect();
        pieces.add(&without_repeats(clip_list(&tagged, window)), &perimeter);
    }
    let mut rings: Vec<Ring> = Vec::with_capacity(pieces.closed.len() + pieces.chains.len());
    rings.extend(pieces.closed.drain(..).filter_map(&keep));
    let joined = pieces.join(&perimeter);
    rings.extend(joined.into_iter().filter_map(&keep));
    Polygons::new(rings)
}

/// A subject vertex tagged with every boundary line it lies on exactly, before any stage runs: an
/// edge along boundary `k` may be cut by an earlier stage, and its crossing lies on line `k` only
/// up to rounding, so it can inherit tag `k` only if both ends already carry it.
fn on_lines(p: Point, window: &ConvexWindow) -> TaggedVertex {
    let mut v = TaggedVertex::new(p);
    for (k, boundary) in window.boundaries().iter().enumerate() {
        if boundary.side(p).on_line() {
            v = v.on_boundary(k);
        }
    }
    v
}

/// The list with consecutive repeats (the closing pair too) merged into one vertex.
fn without_repeats(list: Vec<TaggedVertex>) -> Vec<TaggedVertex> {
    let mut out: Vec<TaggedVertex> = Vec::with_capacity(list.len());
    for v in list {
        match out.last_mut() {
            Some(last) if last.point == v.point => *last = last.merged(&v),
            _ => out.push(v),
        }
    }
    while out.len() > 1 && out.first().map(|v| v.point) == out.last().map(|v| v.point) {
        if let Some(last) = out.pop() {
            out[0] = out[0].merged(&last);
        }
    }
    out
}

/// A position on the window's perimeter: a boundary, then a coordinate along it. `side == m`
/// (one past the last boundary) is the perimeter's end, where a run on the last boundary that
/// reaches the first corner stops.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Place {
    side: usize,
    along: f64,
}

impl Place {
    fn cmp(&self, other: &Place) -> Ordering {
        self.side.cmp(&other.side).then(self.along.total_cmp(&other.along))
    }
}

/// One boundary's exact coordinate: `sign * x` when it runs more along x than y, else `sign * y`;
/// it increases from `start` (at the boundary's first corner) to `end`.
#[derive(Clone, Copy, Debug)]
struct Axis {
    use_x: bool,
    sign: f64,
    start: f64,
    end: f64,
}

impl Axis {
    fn coordinate(&self, p: Point) -> f64 {
        self.sign * if self.use_x { p.x } else { p.y }
    }
}

/// The window's boundaries as perimeter coordinates.
struct Perimeter {
    corners: Vec<Point>,
    axes: Vec<Axis>,
}

impl Perimeter {
    fn new(window: &ConvexWindow) -> Perimeter {
        let boundaries = window.boundaries();
        let axes = boundaries
            .iter()
            .map(|b| {
                let d = b.to - b.from;
                let use_x = d.x.abs() >= d.y.abs();
                let sign = if (if use_x { d.x } else { d.y }) > 0.0 { 1.0 } else { -1.0 };
                let mut axis = Axis { use_x, sign, start: 0.0, end: 0.0 };
                (axis.start, axis.end) = (axis.coordinate(b.from), axis.coordinate(b.to));
                axis
            })
            .collect();
        Perimeter { corners: boundaries.iter().map(|b| b.from).collect(), axes }
    }

    fn sides(&self) -> usize {
        self.axes.len()
    }

    /// Where a vertex on at least one boundary sits: at a corner when it lies on two neighbouring
    /// boundaries, else by its coordinate along its boundary, clamped to the boundary (rounded
    /// crossings may lie a few ulps beyond a corner); the end of a boundary is the next one's start.
    fn place(&self, v: &TaggedVertex) -> Option<Place> {
        let m = self.sides();
        let mut on = v.boundaries();
        let first = on.next()?;
        if let Some(second) = on.next() {
            for (a, b) in [(first, second), (second, first)] {
                if b == (a + 1) % m {
                    return Some(Place { side: b, along: self.axes[b].start });
                }
            }
        }
        let axis = &self.axes[first];
        let along = axis.coordinate(v.point).clamp(axis.start, axis.end);
        Some(if along >= axis.end {
            let next = (first + 1) % m;
            Place { side: next, along: self.axes[next].start }
        } else {
            Place { side: first, along }
        })
    }

    /// True when `place` is the first corner of its boundary.
    fn at_corner(&self, place: Place) -> bool {
        place.side < self.sides() && place.along == self.axes[place.side].start
    }
}

/// A run's net cover of the perimeter: `[from, to)` counted `sign` (+1 counter-clockwise).
#[derive(Clone, Copy, Debug)]
struct Cover {
    from: Place,
    to: Place,
    sign: i64,
}

/// A chain's end on the perimeter.
#[derive(Clone, Copy, Debug)]
struct End {
    place: Place,
    exit: bool,
    chain: usize,
}

/// What the clipped lists leave once their runs are removed.
#[derive(Default)]
struct Pieces {
    /// Lists that never run along the window: kept as they are.
    closed: Vec<Ring>,
    /// Chains from an entry to an exit, inclusive.
    chains: Vec<Vec<Point>>,
    ends: Vec<End>,
    covers: Vec<Cover>,
}

impl Pieces {
    /// Cuts one clipped list (no consecutive repeats) at its runs.
    fn add(&mut self, list: &[TaggedVertex], perimeter: &Perimeter) {
        let n = list.len();
        if n < 3 {
            return; // encloses nothing, and its runs (if any) go there and back
        }
        let run: Vec<Option<usize>> = (0..n).map(|i| list[i].shared_boundary(&list[(i + 1) % n])).collect();
        let Some(first_run) = run.iter().position(Option::is_some) else {
            self.closed.push(Ring::new(list.iter().map(|v| v.point).collect()));
            return;
        };
        let m = perimeter.sides();
        for (i, k) in run.iter().enumerate() {
            let Some(k) = *k else { continue };
            let (Some(mut a), Some(mut b)) = (perimeter.place(&list[i]), perimeter.place(&list[(i + 1) % n])) else {
                continue;
            };
            // A run on the last boundary ends at the perimeter's end, not at its start.
            if k == m - 1 {
                for p in [&mut a, &mut b] {
                    if p.side == 0 {
                        *p = Place { side: m, along: 0.0 };
                    }
                }
            }
            match a.cmp(&b) {
                Ordering::Less => self.covers.push(Cover { from: a, to: b, sign: 1 }),
                Ordering::Greater => self.covers.push(Cover { from: b, to: a, sign: -1 }),
                Ordering::Equal => {}
            }
        }
        // Chains start after a run and end where the next run starts.
        let mut i = (first_run + 1) % n;
        for _ in 0..n {
            // Both ends are on a run, so on a boundary: `place` is `Some` for them.
            if run[(i + n - 1) % n].is_some()
                && run[i].is_none()
                && let Some(mut entry) = perimeter.place(&list[i])
            {
                let mut chain = vec![list[i].point];
                let mut j = i;
                loop {
                    j = (j + 1) % n;
                    chain.push(list[j].point);
                    let Some(place) = perimeter.place(&list[j]) else { continue };
                    // A vertex inside the chain that touches the boundary ends one chain and
                    // starts the next, so a walk passing it closes a ring there: the rings share
                    // the point instead of one ring visiting it twice.
                    self.push_chain(core::mem::replace(&mut chain, vec![list[j].point]), entry, place);
                    entry = place;
                    if run[j].is_some() {
                        break;
                    }
                }
            }
            i = (i + 1) % n;
        }
    }

    /// A chain from `entry` to `exit`, with its two ends.
    fn push_chain(&mut self, chain: Vec<Point>, entry: Place, exit: Place) {
        let id = self.chains.len();
        self.chains.push(chain);
        self.ends.push(End { place: entry, exit: false, chain: id });
        self.ends.push(End { place: exit, exit: true, chain: id });
    }

    /// The net cover just past `place` (a point of no run's end beyond it, or the perimeter's start).
    fn cover_after(&self, place: Place) -> i64 {
        self.covers
            .iter()
            .filter(|c| c.from.cmp(&place) != Ordering::Greater && place.cmp(&c.to) == Ordering::Less)
            .map(|c| c.sign)
            .sum()
    }

    /// Closes the chains with walks along the perimeter and adds whole window loops.
    fn join(&mut self, perimeter: &Perimeter) -> Vec<Ring> {
        // Around the perimeter; at one place entries first, so a pinch there closes before it reopens.
        self.ends.sort_by(|a, b| a.place.cmp(&b.place).then(a.exit.cmp(&b.exit)).then(a.chain.cmp(&b.chain)));
        let origin = Place { side: 0, along: perimeter.axes[0].start };
        let c0 = match self.ends.last() {
            Some(last) => self.cover_after(last.place),
            None => self.cover_after(origin),
        };
        let ends = &self.ends;
        let count = ends.len();
        let mut before = Vec::with_capacity(count);
        let mut c = c0;
        for e in ends {
            before.push(c);
            c += if e.exit { 1 } else { -1 };
        }
        // Two laps: layers opened before the perimeter's start close in the second.
        let mut ccw: Vec<usize> = Vec::new();
        let mut cw: Vec<usize> = Vec::new();
        let mut matched = vec![false; count];
        // next_of[chain] = (the chain its exit walks to, the walk's corners)
        let mut next_of: Vec<Option<(usize, Vec<Point>)>> = vec![None; self.chains.len()];
        let (mut wrapped_ccw, mut wrapped_cw) = (0_i64, 0_i64);
        for lap in 0..2 {
            for (i, e) in ends.iter().enumerate() {
                let counter_clockwise = if e.exit { before[i] >= 0 } else { before[i] > 0 };
                let opens = e.exit == counter_clockwise;
                let stack = if counter_clockwise { &mut ccw } else { &mut cw };
                if opens {
                    if lap == 0 {
                        stack.push(i);
                    }
                    continue;
                }
                if matched[i] {
                    continue;
                }
                let Some(o) = stack.pop() else { continue };
                matched[i] = true;
                let wrapped = lap == 1;
                let (exit, entry) = if counter_clockwise { (o, i) } else { (i, o) };
                let corners = if counter_clockwise {
                    wrapped_ccw += i64::from(wrapped);
                    walk_ccw(perimeter, ends[exit].place, ends[entry].place, wrapped)
                } else {
                    wrapped_cw += i64::from(wrapped);
                    walk_cw(perimeter, ends[exit].place, ends[entry].place, wrapped)
                };
                next_of[ends[exit].chain] = Some((ends[entry].chain, corners));
            }
        }
        let mut rings = Vec::new();
        let mut visited = vec![false; self.chains.len()];
        for start in 0..self.chains.len() {
            if visited[start] {
                continue;
            }
            let mut points = Vec::new();
            let mut at = start;
            while !visited[at] {
                visited[at] = true;
                points.extend_from_slice(&self.chains[at]);
                let Some((next, corners)) = &next_of[at] else { break };
                points.extend_from_slice(corners);
                at = *next;
            }
            rings.push(Ring::new(points));
        }
        // Layers no endpoint opens or closes: whole loops of the window.
        let loops_ccw = c0.max(0) - wrapped_ccw;
        let loops_cw = (-c0).max(0) - wrapped_cw;
        let window_ring = Ring::new(perimeter.corners.clone());
        for _ in 0..loops_ccw.max(0) {
            rings.push(window_ring.clone());
        }
        for _ in 0..loops_cw.max(0) {
            rings.push(window_ring.reversed());
        }
        rings
    }
}

/// The window corners passed walking counter-clockwise from `exit` to `entry` (past the
/// perimeter's start when `wrapped`), without a corner the entry sits on.
fn walk_ccw(perimeter: &Perimeter, exit: Place, entry: Place, wrapped: bool) -> Vec<Point> {
    let m = perimeter.sides();
    let last = entry.side + if wrapped { m } else { 0 };
    ((exit.side + 1)..=last)
        .filter(|&j| !(j == last && perimeter.at_corner(entry)))
        .map(|j| perimeter.corners[j % m])
        .collect()
}

/// The window corners passed walking clockwise from `exit` down to `entry` (past the perimeter's
/// start when `wrapped`), without a corner the exit sits on.
fn walk_cw(perimeter: &Perimeter, exit: Place, entry: Place, wrapped: bool) -> Vec<Point> {
    let m = perimeter.sides();
    let first = exit.side + if wrapped { m } else { 0 };
    ((entry.side + 1)..=first)
        .rev()
        .filter(|&j| !(j == first && perimeter.at_corner(exit)))
        .map(|j| perimeter.corners[j % m])
        .collect()
}
