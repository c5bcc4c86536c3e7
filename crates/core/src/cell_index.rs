//! A sparse uniform grid of boxes, for finding the boxes that meet without testing every pair.
//!
//! Shared by the oracle's checks (pairs of output edges), the near pairs of input edges that
//! vertex snapping and snap rounding start from (`NearEdges`), and vatti's far splice. Cost: near
//! linear when the boxes are small beside their extent; a box covers every cell it spans, so many
//! long boxes sharing cells (nested squares, combs, long near-parallel edges) make it quadratic.

use crate::{Point, Rect};

/// The most columns (and rows) of cells: keys fit 32 bits.
const MAX_SIDE_CELLS: u64 = 1 << 16;

/// Boxes binned into a uniform grid whose square cells are about as large as a typical box,
/// kept sparse as sorted (cell, box) entries: every cell a box covers lists it.
#[derive(Clone, Debug)]
pub struct CellIndex {
    origin: Point,
    /// The side of a cell: a power of two, so that `inverse` is exact and a cell's column is
    /// found by a product (a division takes several times as long, for every box and point).
    size: f64,
    /// `1 / size`, exactly.
    inverse: f64,
    columns: u64,
    rows: u64,
    /// (cell key, box index), sorted. At most 2^16 columns and rows, so a key fits 32 bits: 8
    /// bytes an entry, half the memory a sort and a walk of millions of them move.
    entries: Vec<(u32, u32)>,
}

/// The smallest power of two at least `v`, for `v` positive and normal (else `v` itself): exact
/// to divide by, or to multiply by its inverse.
pub fn power_of_two_at_least(v: f64) -> f64 {
    if !v.is_finite() || v < f64::MIN_POSITIVE {
        return v;
    }
    let p = f64::from_bits(v.to_bits() & (0x7ff << 52));
    if p < v { p * 2.0 } else { p }
}

/// Sorts `entries`, made box by box (so ascending in box within each cell), by cell key below
/// `cells`: into the order `sort_unstable` gives, by stable passes of eleven bits of the key
/// (at most three: keys are below 2^32), or of up to sixteen in two passes where there are
/// enough entries to fill the larger counts. Linear where a comparison sort is n log n, and
/// indexes of thousands of edges are built for every clip the form check examines.
fn sort_by_cell(entries: &mut Vec<(u32, u32)>, cells: u64) {
    if entries.len() < 256 {
        entries.sort_unstable();
        return;
    }
    let bits = 64 - cells.saturating_sub(1).leading_zeros();
    let digit_bits = if bits > 22 && entries.len() >= 1 << 16 { bits.div_ceil(2) } else { 11 };
    let mut other = vec![(0u32, 0u32); entries.len()];
    let mut starts = vec![0usize; 1 << digit_bits];
    let mut shift = 0;
    while shift < bits {
        let digit = |key: u32| ((key >> shift) & ((1 << digit_bits) - 1)) as usize;
        starts.fill(0);
        for e in entries.iter() {
            starts[digit(e.0)] += 1;
        }
        let mut sum = 0;
        for s in starts.iter_mut() {
            (*s, sum) = (sum, sum + *s);
        }
        for &e in entries.iter() {
            let d = digit(e.0);
            other[starts[d]] = e;
            starts[d] += 1;
        }
        std::mem::swap(entries, &mut other);
        shift += digit_bits;
    }
}

impl CellIndex {
    /// The index of `boxes`, or `None` when there are none. Cells start at twice the median
    /// box's larger side, rounded up to a power of two (a typical box then covers one to four
    /// cells, not four: fewer entries to sort, for a few more pairs to test in each cell) and
    /// double until the boxes cover at most eight cells each on average (a few long boxes among
    /// many small ones must not cover millions).
    pub fn new(boxes: &[Rect]) -> Option<CellIndex> {
        let b = boxes.iter().fold(Rect::EMPTY, |b, r| b.union(*r));
        if b.is_empty() {
            return None;
        }
        let mut sides: Vec<f64> = boxes.iter().map(|r| r.width().max(r.height())).collect();
        let middle = sides.len() / 2;
        let median = *sides.select_nth_unstable_by(middle, f64::total_cmp).1;
        let mut size = (2.0 * median).max(b.width().max(b.height()) / 65_536.0).max(f64::MIN_POSITIVE);
        loop {
            // Whole cells a side by truncation (sides are not negative; see `coordinates`): an
            // estimate, so the inverse need not be exact.
            let inverse = 1.0 / size;
            let cells = |side: f64| (side * inverse) as i64 as f64 + 2.0;
            let covered: f64 = boxes.iter().map(|r| cells(r.width()) * cells(r.height())).sum();
            if covered <= 8.0 * boxes.len() as f64 || !size.is_finite() {
                break;
            }
            size *= 2.0;
        }
        Some(CellIndex::with_cell_size(boxes, b, size))
    }

    /// The index of `boxes`, whose union is `b` (not empty), on cells of side `size` (rounded
    /// up to a power of two, and at least 1/65536 of their extent).
    fn with_cell_size(boxes: &[Rect], b: Rect, size: f64) -> CellIndex {
        let size = power_of_two_at_least(size.max(b.width().max(b.height()) / 65_536.0).max(f64::MIN_POSITIVE));
        // At most 2^16 each, whatever the rounding of the quotient: the last column and row
        // then reach a little farther, as `coordinates` clamps every point the same way.
        let count = |span: f64| ((span / size).floor() as u64).saturating_add(1).min(MAX_SIDE_CELLS);
        let mut index = CellIndex {
            origin: b.min,
            size,
            inverse: 1.0 / size,
            columns: count(b.width()),
            rows: count(b.height()),
            entries: Vec::new(),
        };
        let mut entries = Vec::with_capacity(2 * boxes.len());
        for (i, r) in boxes.iter().enumerate() {
            let ((x0, y0), (x1, y1)) = (index.coordinates(r.min), index.coordinates(r.max));
            for y in y0..=y1 {
                entries.extend((x0..=x1).map(|x| ((y * index.columns + x) as u32, i as u32)));
            }
        }
        sort_by_cell(&mut entries, index.columns.saturating_mul(index.rows));
        index.entries = entries;
        index
    }

    /// The side of the cells.
    pub fn cell_size(&self) -> f64 {
        self.size
    }

    /// The (cell key, box index) entries, sorted by cell: one per cell a box covers.
    pub fn entries(&self) -> &[(u32, u32)] {
        &self.entries
    }

    /// The column and row holding `p` (clamped to the grid).
    fn coordinates(&self, p: Point) -> (u64, u64) {
        // Truncation is the floor of a positive quotient: `f64::floor` is a library call on
        // targets without SSE4.1, and this runs for every box and pair the index visits. Through
        // i64 (one instruction; saturating, as `min` needs), not u64 (a branchy sequence).
        let index = |v: f64, lo: f64, n: u64| {
            let k = (v - lo) * self.inverse;
            if k > 0.0 { (k as i64 as u64).min(n - 1) } else { 0 }
        };
        (index(p.x, self.origin.x, self.columns), index(p.y, self.origin.y, self.rows))
    }

    /// The key of the cell holding `p` (clamped to the grid).
    pub fn cell(&self, p: Point) -> u32 {
        let (x, y) = self.coordinates(p);
        (y * self.columns + x) as u32
    }

    /// Calls `visit(i, j)` (i before j in a cell's list) once on every pair of the indexed
    /// `boxes` that meet, in the one cell that holds the lower-left corner of their overlap;
    /// stops at the first error.
    pub fn try_for_each_close_pair<E>(
        &self,
        boxes: &[Rect],
        mut visit: impl FnMut(usize, usize) -> Result<(), E>,
    ) -> Result<(), E> {
        for members in self.entries.chunk_by(|a, b| a.0 == b.0) {
            for (k, &(cell, i)) in members.iter().enumerate() {
                let e = &boxes[i as usize];
                for &(_, j) in &members[k + 1..] {
                    let f = &boxes[j as usize];
                    if !e.intersects(f) {
                        continue;
                    }
                    let corner = Point::new(e.min.x.max(f.min.x), e.min.y.max(f.min.y));
                    if self.cell(corner) == cell {
                        visit(i as usize, j as usize)?;
                    }
                }
            }
        }
        Ok(())
    }

    /// Calls `visit(i)` once on every indexed box of `boxes` that meets `query`. Walks the cells
    /// `query` covers, or every entry when that is fewer.
    pub fn for_each_meeting(&self, boxes: &[Rect], query: &Rect, mut visit: impl FnMut(usize)) {
        if query.is_empty() {
            return;
        }
        let ((x0, y0), (x1, y1)) = (self.coordinates(query.min), self.coordinates(query.max));
        let cells = (x1 - x0 + 1).saturating_mul(y1 - y0 + 1);
        if cells as usize >= self.entries.len() {
            // Every box once: entries of one box are never adjacent across cells, so mark them.
            let mut seen = vec![false; boxes.len()];
            for &(_, i) in &self.entries {
                let i = i as usize;
                if !seen[i] && boxes[i].intersects(query) {
                    seen[i] = true;
                    visit(i);
                }
            }
            return;
        }
        for y in y0..=y1 {
            let (from, to) = ((y * self.columns + x0) as u32, (y * self.columns + x1) as u32);
            let start = self.entries.partition_point(|e| e.0 < from);
            for &(cell, i) in self.entries[start..].iter().take_while(|e| e.0 <= to) {
                let b = &boxes[i as usize];
                if !b.intersects(query) {
                    continue;
                }
                let corner = Point::new(b.min.x.max(query.min.x), b.min.y.max(query.min.y));
                if self.cell(corner) == cell {
                    visit(i as usize);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn entries_sort_by_cell_as_a_comparison_sort_does() {
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = |n: u64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state % n
        };
        for (count, cells) in [
            (0, 1),
            (5, 1),
            (300, 1),
            (1000, 7),
            (5000, 3000),
            (20_000, 1 << 32),
            (700, 1 << 22),
            (70_000, 1 << 32),
            (70_000, (1 << 32) - 1),
        ] {
            // Made box by box, each box's cells in any order: ascending in box within a cell.
            let mut entries: Vec<(u32, u32)> = Vec::new();
            let mut boxes = 0u32;
            while entries.len() < count {
                for _ in 0..1 + next(5) {
                    entries.push((next(cells) as u32, boxes));
                }
                boxes += 1;
            }
            let mut expected = entries.clone();
            expected.sort_unstable();
            sort_by_cell(&mut entries, cells);
            assert_eq!(entries, expected, "{count} entries in {cells} cells");
        }
    }

    /// The pairs `try_for_each_close_pair` visits, each as (lower, higher), sorted.
    fn close_pairs(index: &CellIndex, boxes: &[Rect]) -> Vec<(usize, usize)> {
        let mut found = Vec::new();
        index
            .try_for_each_close_pair::<()>(boxes, |i, j| {
                found.push((i.min(j), i.max(j)));
                Ok(())
            })
            .unwrap();
        found.sort_unstable();
        found
    }

    /// Every pair of `boxes` that meet, by brute force, sorted.
    fn meeting_pairs(boxes: &[Rect]) -> Vec<(usize, usize)> {
        (0..boxes.len())
            .flat_map(|i| (i + 1..boxes.len()).map(move |j| (i, j)))
            .filter(|&(i, j)| boxes[i].intersects(&boxes[j]))
            .collect()
    }

    #[test]
    fn the_full_grid_of_2_to_the_16_cells_a_side_keeps_every_close_pair() {
        // Tiny boxes at both ends of a wide, tall extent: cells are at their smallest, and the
        // grid at its largest (keys up to 2^32 - 1); boxes on the far border are clamped in.
        let mut boxes = Vec::new();
        for k in 0..30 {
            let t = f64::from(k) * 1e-9;
            boxes.push(Rect::new(t, t, t + 2e-9, t + 2e-9));
            boxes.push(Rect::new(1.0 - t - 2e-9, 1.0 - t - 2e-9, 1.0 - t, 1.0 - t));
        }
        boxes.push(Rect::new(1.0 - 1e-12, 0.0, 1.0, 1.0));
        let bounds = boxes.iter().fold(Rect::EMPTY, |b, r| b.union(*r));
        let index = CellIndex::with_cell_size(&boxes, bounds, 1e-12);
        assert_eq!((index.columns, index.rows), (MAX_SIDE_CELLS, MAX_SIDE_CELLS));
        let expected = meeting_pairs(&boxes);
        assert!(expected.len() > 60);
        assert_eq!(close_pairs(&index, &boxes), expected);
    }

    #[test]
    fn close_pairs_and_queries_match_brute_force() {
        // Small and long boxes mixed, on a grid with touching neighbours.
        let mut boxes = Vec::new();
        for k in 0..40 {
            let (x, y) = (f64::from(k % 7) * 1.5, f64::from(k / 7) * 1.25);
            boxes.push(Rect::new(x, y, x + 1.5, y + 0.5));
        }
        boxes.push(Rect::new(-3.0, 2.0, 30.0, 2.1));
        boxes.push(Rect::new(4.0, -1.0, 4.2, 9.0));
        let index = CellIndex::new(&boxes).expect("boxes");
        assert_eq!(close_pairs(&index, &boxes), meeting_pairs(&boxes));
        for query in
            [Rect::new(2.0, 1.0, 5.0, 3.0), Rect::new(-100.0, -100.0, 100.0, 100.0), Rect::new(9.0, 9.0, 9.0, 9.0)]
        {
            let mut met = Vec::new();
            index.for_each_meeting(&boxes, &query, |i| met.push(i));
            met.sort_unstable();
            let expected: Vec<usize> = (0..boxes.len()).filter(|&i| boxes[i].intersects(&query)).collect();
            assert_eq!(met, expected, "{query:?}");
        }
    }
}
