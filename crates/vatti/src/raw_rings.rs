//! The sweep's closed rings before clean-up: one flat point array with ring ranges, and for
//! every point the order in which the sweep emitted it.

use clip_core::Point;

/// Rings as ranges of one point array, without consecutive repeated points (the seam included)
/// and without rings of fewer than three points.
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
    /// The sweep's [`crate::output::OutputBuilder::near_miss`]: every edge is split at the
    /// points on it.
    pub near_miss: bool,
    /// The sweep's [`crate::output::OutputBuilder::near_crossings`].
    pub near_crossings: Vec<Point>,
}

impl RawRings {
    /// Drops every ring, keeping the buffers.
    pub(crate) fn clear(&mut self) {
        self.points.clear();
        self.ends.clear();
        self.emitted.clear();
        self.stamps = 0;
        self.near_miss = false;
        self.near_crossings.clear();
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
    /// unless it repeats the ring's last point.
    #[inline]
    pub(crate) fn push_point(&mut self, start: usize, p: Point, stamp: u32) {
        if self.points.len() > start && self.points[self.points.len() - 1] == p {
            return;
        }
        self.points.push(p);
        self.emitted.push(stamp);
    }

    /// Closes the ring whose points begin at index `start`: the seam's repeats go, and a ring of
    /// fewer than three points is dropped.
    #[inline]
    pub(crate) fn end_ring(&mut self, start: usize) {
        while self.points.len() > start + 1 && self.points[start] == self.points[self.points.len() - 1] {
            self.points.pop();
            self.emitted.pop();
        }
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
