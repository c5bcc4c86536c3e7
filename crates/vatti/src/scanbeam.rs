//! The scanbeam table (the paper's SBT): every vertex height, sorted once and deduplicated.

use crate::bounds::Vertex;
use crate::small_sort::insertion_sorted_by;

/// The scanlines of one sweep, bottom to top. Vatti marks an edge's top as the edge becomes
/// active (MarkSBT); every vertex of a simplified ring is a local minimum or the top of an edge
/// reached from one, so the marks are exactly the vertex heights, known before the sweep.
/// Sorting them once replaces a heap's push and pop per edge.
#[derive(Debug, Default)]
pub(crate) struct Scanbeams {
    /// The heights as order-preserving integer keys (see [`height_key`]), ascending, no repeats.
    keys: Vec<i64>,
    /// Index of the first height not yet passed.
    next: usize,
}

/// Heights kept between clips at most (a large buffer is freed when its sweep ends); as many as
/// a 10^4-vertex clip has, whose other buffers `scratch` keeps too.
const KEEP_AT_MOST: usize = 1 << 15;

/// `f64::total_cmp`'s order as a signed integer: cheaper to sort by than the floats.
#[inline]
pub(crate) fn height_key(y: f64) -> i64 {
    let bits = y.to_bits() as i64;
    bits ^ (((bits >> 63) as u64) >> 1) as i64
}

/// The inverse of [`height_key`].
#[inline]
pub(crate) fn height(k: i64) -> f64 {
    f64::from_bits((k ^ (((k >> 63) as u64) >> 1) as i64) as u64)
}

impl Scanbeams {
    /// The heights of `vertices`, replacing whatever was there (the buffer is kept).
    pub(crate) fn rebuild(&mut self, vertices: &[Vertex]) {
        self.keys.clear();
        self.keys.extend(vertices.iter().map(|v| height_key(v.pt.y)));
        // Few heights: the small insertion sort (less code to load than the library's). Many:
        // the stable sort merges the rings' monotone runs (each bound is one).
        if !insertion_sorted_by(&mut self.keys, |a, b| a < b) {
            self.keys.sort();
        }
        self.keys.dedup();
        self.next = 0;
    }

    /// Once the sweep is over: frees a large buffer at once, so it does not add to the peak
    /// memory of the clean-up that follows (a small one is kept for the thread's next clip).
    pub(crate) fn release_if_large(&mut self) {
        if self.keys.capacity() > KEEP_AT_MOST {
            self.keys = Vec::new();
        }
    }

    /// Heights the buffer has room for.
    pub(crate) fn capacity(&self) -> usize {
        self.keys.capacity()
    }

    /// The smallest height above `y`; heights at or below `y` are passed for good.
    #[inline]
    pub(crate) fn next_above(&mut self, y: f64) -> Option<f64> {
        let k = height_key(y);
        while let Some(&top) = self.keys.get(self.next) {
            if top > k {
                return Some(height(top));
            }
            self.next += 1;
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::Point;

    fn vertex(y: f64) -> Vertex {
        Vertex { pt: Point::new(0.0, y), next: 0, prev: 0 }
    }

    #[test]
    fn keys_order_heights_as_total_cmp_does() {
        let ys = [-f64::MAX, -1.5, -1e-300, -0.0, 0.0, 1e-300, 2.0, 3.5, f64::MAX];
        for w in ys.windows(2) {
            assert!(height_key(w[0]) < height_key(w[1]), "{} before {}", w[0], w[1]);
        }
        for y in ys {
            assert_eq!(height(height_key(y)).to_bits(), y.to_bits());
        }
    }

    #[test]
    fn heights_come_once_each_in_order() {
        let mut beams = Scanbeams::default();
        beams.rebuild(&[3.0, -1.0, 2.0, 3.0, -1.0, 0.5].map(vertex));
        let mut seen = vec![];
        let mut y = f64::NEG_INFINITY;
        while let Some(next) = beams.next_above(y) {
            seen.push(next);
            y = next;
        }
        assert_eq!(seen, [-1.0, 0.5, 2.0, 3.0]);
        // Asking below a passed height does not go back.
        assert_eq!(beams.next_above(-5.0), None);
    }
}
