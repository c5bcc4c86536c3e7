//! The sweep's closed rings before clean-up: one flat point array with ring ranges, and for
//! every point the order in which the sweep emitted it.

use clip_core::Point;

/// Rings as ranges of one point array, without consecutive repeated points or horizontal spikes
/// (the seam included) and without rings of fewer than three points.
#[derive(Debug, Default)]
pub(crate) struct RawRings {
    pub points: Vec<Point>,
    /// Ring `i` is `points[ends[i - 1]..ends[i]]` (from 0 for the first).
    pub ends: Vec<usize>,
    /// Per point, a distinct emission stamp: the sweep emits points by non-decreasing y except
    /// where crossings at nearly one height are taken out of order.
    pub emitted: Vec<u32>,
    /// One past the largest emission stamp there may be.
    pub stamps: usize,
}

impl RawRings {
    /// Drops every ring, keeping the buffers.
    pub(crate) fn clear(&mut self) {
        self.points.clear();
        self.ends.clear();
        self.emitted.clear();
        self.stamps = 0;
    }

    /// Number of rings.
    #[inline]
    pub(crate) fn len(&self) -> usize {
        self.ends.len()
    }

    /// Index of ring `i`'s first point.
    #[inline]
    pub(crate) fn start(&self, i: usize) -> usize {
        if i == 0 { 0 } else { self.ends[i - 1] }
    }

    /// The points of ring `i`.
    #[inline]
    pub(crate) fn ring(&self, i: usize) -> &[Point] {
        &self.points[self.start(i)..self.ends[i]]
    }

    /// Appends `points` as a ring (repeats dropped; nothing if fewer than three remain), each
    /// point stamped by `stamp`.
    #[cfg(test)]
    pub(crate) fn push_ring(&mut self, points: impl Iterator<Item = (Point, u32)>) {
        let start = self.points.len();
        for (p, stamp) in points {
            self.push_point(start, p, stamp);
        }
        self.end_ring(start);
    }

    /// Adds `p` to the ring that began at point index `start` (see [`RawRings::end_ring`]),
    /// unless it repeats the ring's last point. A last point that `p` makes the tip of a
    /// horizontal spike (the ring ran out along the scanline and comes straight back) goes first,
    /// as often as that holds.
    #[inline]
    pub(crate) fn push_point(&mut self, start: usize, p: Point, stamp: u32) {
        let n = self.points.len();
        // One scanline test for both the repeat and the spike.
        if n > start && self.points[n - 1].y == p.y {
            if self.points[n - 1].x == p.x {
                return;
            }
            if n >= start + 2 && self.points[n - 2].y == p.y && self.drop_spike_tips(start, p) {
                return;
            }
        }
        self.points.push(p);
        self.emitted.push(stamp);
    }

    /// Drops the ring's last points while `p` makes them spike tips (see
    /// [`RawRings::push_point`]); true when `p` then repeats the last point left.
    #[inline(never)]
    fn drop_spike_tips(&mut self, start: usize, p: Point) -> bool {
        while self.points.len() >= start + 2 {
            let n = self.points.len();
            if !is_spike(self.points[n - 2], self.points[n - 1], p) {
                break;
            }
            self.points.pop();
            self.emitted.pop();
        }
        self.points.len() > start && self.points[self.points.len() - 1] == p
    }

    /// Closes the ring whose points begin at index `start`: the seam's repeats and spikes go,
    /// and a ring of fewer than three points is dropped.
    #[inline]
    pub(crate) fn end_ring(&mut self, start: usize) {
        // The first kept point: spikes at the seam's start are dropped in one move at the end.
        let mut first = start;
        while self.points.len() >= first + 3 {
            let n = self.points.len();
            let (a, b) = (self.points[first], self.points[first + 1]);
            let (y, z) = (self.points[n - 2], self.points[n - 1]);
            if z == a || is_spike(y, z, a) {
                self.points.pop();
                self.emitted.pop();
            } else if is_spike(z, a, b) {
                first += 1;
            } else {
                break;
            }
        }
        if first > start {
            self.points.drain(start..first);
            self.emitted.drain(start..first);
        }
        // The loop ends with the last point unlike the first, or with fewer than three left.
        if self.points.len() - start < 3 {
            self.points.truncate(start);
            self.emitted.truncate(start);
        } else {
            self.ends.push(self.points.len());
        }
    }

    /// Rings from lists of points, stamped in y order (a valid emission order), for tests.
    #[cfg(test)]
    pub(crate) fn from_rings(rings: Vec<Vec<Point>>) -> RawRings {
        let mut raw = RawRings::default();
        for r in rings {
            raw.push_ring(r.into_iter().map(|p| (p, 0)));
        }
        let mut by_y: Vec<usize> = (0..raw.points.len()).collect();
        by_y.sort_by(|&a, &b| raw.points[a].y.total_cmp(&raw.points[b].y));
        for (stamp, &k) in by_y.iter().enumerate() {
            raw.emitted[k] = stamp as u32;
        }
        raw.stamps = by_y.len();
        raw
    }
}

/// True when `b` is the tip of a horizontal spike between `a` and `c`: the three on one scanline
/// and the ring turning straight back at `b` (exact). The sweep's slides along a scanline emit
/// these where both operands have horizontal edges on it; dropping `b` changes no winding number
/// off the ring, and the tip no longer reads as a touch. Spikes along other lines are left to the
/// clean-up, which cancels opposite edges.
#[inline]
fn is_spike(a: Point, b: Point, c: Point) -> bool {
    a.y == b.y && b.y == c.y && (b.x - a.x) * (c.x - b.x) < 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(points: &[(f64, f64)]) -> RawRings {
        let mut raw = RawRings::default();
        raw.push_ring(points.iter().enumerate().map(|(i, &(x, y))| (Point::new(x, y), i as u32)));
        raw
    }

    fn points(raw: &RawRings, i: usize) -> Vec<(f64, f64)> {
        raw.ring(i).iter().map(|p| (p.x, p.y)).collect()
    }

    #[test]
    fn horizontal_spike_tips_go_with_their_stamps() {
        // Out to x = 6 along y = 0 and back to 5: the tip goes, the straight-through 4 stays.
        let raw = ring(&[(0.0, 0.0), (4.0, 0.0), (6.0, 0.0), (5.0, 0.0), (5.0, 3.0), (0.0, 3.0)]);
        assert_eq!(points(&raw, 0), [(0.0, 0.0), (4.0, 0.0), (5.0, 0.0), (5.0, 3.0), (0.0, 3.0)]);
        assert_eq!(raw.emitted, [0, 1, 3, 4, 5]);
        // Back past the previous point too: both tips go, the straight-through 3 stays.
        let raw = ring(&[(0.0, 0.0), (4.0, 0.0), (6.0, 0.0), (3.0, 0.0), (5.0, 0.0), (5.0, 3.0), (0.0, 3.0)]);
        assert_eq!(points(&raw, 0), [(0.0, 0.0), (3.0, 0.0), (5.0, 0.0), (5.0, 3.0), (0.0, 3.0)]);
        assert_eq!(raw.emitted, [0, 3, 4, 5, 6]);
    }

    #[test]
    fn spikes_at_the_seam_go_and_a_ring_of_spikes_is_dropped() {
        let raw = ring(&[(6.0, 0.0), (5.0, 0.0), (5.0, 3.0), (0.0, 3.0), (0.0, 0.0), (4.0, 0.0)]);
        assert_eq!(points(&raw, 0), [(5.0, 0.0), (5.0, 3.0), (0.0, 3.0), (0.0, 0.0), (4.0, 0.0)]);
        assert_eq!(raw.emitted, [1, 2, 3, 4, 5]);
        let raw = ring(&[(5.0, 3.0), (0.0, 3.0), (0.0, 0.0), (7.0, 0.0), (5.0, 0.0)]);
        assert_eq!(points(&raw, 0), [(5.0, 3.0), (0.0, 3.0), (0.0, 0.0), (5.0, 0.0)]);
        assert_eq!(ring(&[(0.0, 0.0), (2.0, 0.0), (1.0, 0.0)]).len(), 0);
    }

    #[test]
    fn other_spikes_and_straight_runs_stay() {
        // A slanted spike is the clean-up's (it cancels opposite edges); a straight run is not a spike.
        let slanted = [(0.0, 0.0), (2.0, 2.0), (1.0, 1.0), (1.0, 3.0)];
        assert_eq!(points(&ring(&slanted), 0), slanted);
        let straight = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 1.0)];
        assert_eq!(points(&ring(&straight), 0), straight);
    }
}
