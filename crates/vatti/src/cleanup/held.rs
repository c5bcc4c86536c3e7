//! Whether the clockwise rings the clean-up rebuilt are held by an outer: a clockwise ring
//! that no ring holds is a hole whose outer rounding lost, or an outer turned inside out, and
//! the output's form is broken.

use clip_core::{Point, Ring, edge_winding};
#[cfg(test)]
use clip_core::{Rect, ring_winding};

/// Whether holes lie inside an outer, for all holes at once: each hole's first test point
/// ([`test_point`]) goes into a list sorted by y, and one pass over every ring's edges adds each edge's
/// winding to the points level with it. Holes whose point lies on a ring try their next point
/// in the next pass. The same answers as [`held`] hole by hole, which scanned the whole of a
/// large outer ring once per hole (half of a grid union's time with 150 holes). The buffers are
/// kept between calls.
#[derive(Default)]
pub(crate) struct HeldTest {
    /// `(y, x, slot)` of this pass's points, sorted by y.
    points: Vec<(f64, f64, u32)>,
    /// Per slot: the hole, its test point's index ([`test_point`]), the sum of the windings so
    /// far, and whether the point lies on a ring.
    slots: Vec<HeldSlot>,
}

#[derive(Clone, Copy)]
struct HeldSlot {
    hole: usize,
    candidate: usize,
    winding: i32,
    on_ring: bool,
}

impl HeldTest {
    /// True when one of `rings[holes]` is held by no other ring: none of its test points off
    /// the other rings has a winding number of 1 or more in them, or every test point lies on
    /// another ring.
    pub(crate) fn any_unheld(&mut self, rings: &[Ring], holes: &[usize]) -> bool {
        self.slots.clear();
        self.slots.extend(holes.iter().map(|&hole| HeldSlot { hole, candidate: 0, winding: 0, on_ring: false }));
        while !self.slots.is_empty() {
            self.points.clear();
            for (slot, s) in self.slots.iter().enumerate() {
                let p = test_point(&rings[s.hole].points, s.candidate);
                self.points.push((p.y, p.x, slot as u32));
            }
            self.points.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
            self.pass(rings);
            // Decided holes leave; the others move on to their next point, or are unheld
            // when every point lies on a ring.
            let mut unheld = false;
            self.slots.retain_mut(|s| {
                if !s.on_ring {
                    unheld |= s.winding <= 0;
                    return false;
                }
                s.candidate += 1;
                unheld |= s.candidate == 2 * rings[s.hole].points.len();
                (s.winding, s.on_ring) = (0, false);
                true
            });
            if unheld {
                return true;
            }
        }
        false
    }

    /// Adds every edge's winding to the points level with it (none of its own ring's).
    fn pass(&mut self, rings: &[Ring]) {
        let (Some(&(low, ..)), Some(&(high, ..))) = (self.points.first(), self.points.last()) else { return };
        for (k, ring) in rings.iter().enumerate() {
            let pts = &ring.points;
            let Some(&last) = pts.last() else { continue };
            let mut a = last;
            for &b in pts {
                let (y0, y1) = if a.y <= b.y { (a.y, b.y) } else { (b.y, a.y) };
                if y1 >= low && y0 <= high {
                    let first = self.points.partition_point(|q| q.0 < y0);
                    for &(y, x, slot) in self.points[first..].iter().take_while(|q| q.0 <= y1) {
                        // Edges wholly left of the point neither hold it nor cross its ray.
                        if a.x < x && b.x < x {
                            continue;
                        }
                        let s = &mut self.slots[slot as usize];
                        if s.hole != k && !s.on_ring {
                            match edge_winding(Point::new(x, y), a, b) {
                                Some(w) => s.winding += w,
                                None => s.on_ring = true,
                            }
                        }
                    }
                }
                a = b;
            }
        }
    }
}

/// Test point `i` of a ring: its edges' midpoints, then its vertices. A hole's vertices are
/// where it is pinched to its outer (130 of 153 holes' first vertices in a grid union lay on
/// another ring; in scribble unions, often all of them), its edges' midpoints rarely are.
fn test_point(points: &[Point], i: usize) -> Point {
    let n = points.len();
    if i >= n {
        return points[i - n];
    }
    let (a, b) = (points[i], points[(i + 1) % n]);
    Point::new(a.x + (b.x - a.x) / 2.0, a.y + (b.y - a.y) / 2.0)
}

/// True when a point of `rings[hole]` off every other ring (an edge's midpoint, else a vertex:
/// [`test_point`]) has a winding number of 1 or more in them: the hole lies inside an outer.
/// False when every such point lies on another ring (the snap fallback's sweep then decides). Exact
/// for the point tested. The reference for [`HeldTest`], which asks the same for all holes at
/// once; the tests hold the two against each other. `boxes` are the rings' bounds.
#[cfg(test)]
pub(crate) fn held(rings: &[Ring], boxes: &[Rect], hole: usize) -> bool {
    let points = &rings[hole].points;
    'point: for p in (0..2 * points.len()).map(|i| test_point(points, i)) {
        let mut winding = 0;
        for (k, r) in rings.iter().enumerate() {
            if k == hole || !boxes[k].contains(p) {
                continue;
            }
            match ring_winding(p, r) {
                Some(w) => winding += w,
                None => continue 'point,
            }
        }
        return winding > 0;
    }
    false
}

/// Asserts that the batched test and [`held`] agree on every clockwise ring of `rings`, one at a
/// time and all at once; returns how many clockwise rings there were.
#[cfg(test)]
pub(crate) fn assert_batched_agrees(rings: &[Ring]) -> usize {
    let boxes: Vec<Rect> = rings.iter().map(Ring::bounds).collect();
    let holes: Vec<usize> = (0..rings.len()).filter(|&k| !rings[k].runs_counter_clockwise()).collect();
    let mut test = HeldTest::default();
    for &h in &holes {
        assert_eq!(test.any_unheld(rings, &[h]), !held(rings, &boxes, h), "ring {h} of {rings:?}");
    }
    let unheld = holes.iter().any(|&h| !held(rings, &boxes, h));
    assert_eq!(test.any_unheld(rings, &holes), unheld, "all clockwise rings of {rings:?}");
    holes.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(points: &[(f64, f64)]) -> Ring {
        Ring::new(points.iter().map(|&(x, y)| Point::new(x, y)).collect())
    }

    #[test]
    fn holes_are_tested_all_at_once_at_points_off_the_other_rings() {
        let rings: Vec<Ring> = vec![
            ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)]),
            // Pinched to the outer at every vertex: held, told by its edges' midpoints.
            ring(&[(2.0, 0.0), (0.0, 2.0), (2.0, 4.0), (4.0, 2.0)]),
            // Its first edge runs along the outer's: held, told by its second edge's midpoint.
            ring(&[(2.0, 0.0), (1.0, 0.0), (1.0, 1.0), (2.0, 1.0)]),
            // Outside everything.
            ring(&[(10.0, 10.0), (10.0, 11.0), (11.0, 11.0), (11.0, 10.0)]),
            // The outer's first triangle, reversed, over a triangle: every point lies on it.
            ring(&[(5.0, 0.0), (6.0, 0.0), (5.0, 1.0)]),
            ring(&[(5.0, 0.0), (5.0, 1.0), (6.0, 0.0)]),
        ];
        let boxes: Vec<Rect> = rings.iter().map(Ring::bounds).collect();
        let mut test = HeldTest::default();
        for (holes, unheld) in [(&[1, 2][..], false), (&[1, 3], true), (&[3], true), (&[5], true), (&[2, 5], true)] {
            assert_eq!(test.any_unheld(&rings, holes), unheld, "holes {holes:?}");
            assert_eq!(holes.iter().any(|&h| !held(&rings, &boxes, h)), unheld, "holes {holes:?} one by one");
        }
        assert_eq!(assert_batched_agrees(&rings), 4);
    }
}
