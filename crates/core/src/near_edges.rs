//! Both operands' edges on a pixel grid, with the pairs of them that come within a pixel of each
//! other: what snap rounding ([`crate::snap_round_near`]) and vertex snapping
//! ([`crate::snap_edges_to_vertices`]) both start from, found once for the two.
//!
//! The pairs come from a [`CellIndex`] of the edges' boxes grown by a pixel, less those a float
//! test with bounded error finds farther apart than a pixel's diagonal: near linear when edges
//! are short beside the extent, quadratic when many long edges lie close to each other (bundles
//! of nearly coincident edges), and the box index itself is quadratic in the long edges sharing
//! its cells (stars).

use crate::{CellIndex, ClipError, Operand, Point, Polygons, Ring, Segment};

/// Both operands' rings in units of a pixel (a power of two), their edges, and the pairs of
/// edges within a pixel of each other.
#[derive(Clone, Debug)]
pub struct NearEdges {
    /// The pixel's side, in the operands' units.
    pub(crate) pixel: f64,
    /// How many of `rings` are the subject's (the clip's follow).
    pub(crate) subject_rings: usize,
    /// Both operands' rings, every coordinate divided by the pixel (exact: a power of two).
    pub(crate) rings: Vec<Ring>,
    /// The rings' edges, ring by ring.
    pub(crate) segments: Vec<Segment>,
    /// Pairs of `segments` (indices) that may come within a pixel's diagonal of each other,
    /// each once: a ring's consecutive edges among them.
    pub(crate) pairs: Vec<(u32, u32)>,
}

impl NearEdges {
    /// The operands' edges in units of `pixel` (a power of two) and their near pairs. Refuses a
    /// pixel that is not a positive power of two, and coordinates that are not finite or lie
    /// 2^51 pixels or more from the origin (where a pixel's centre and borders are no longer
    /// exact).
    pub fn of(subject: &Polygons, clip: &Polygons, pixel: f64) -> Result<NearEdges, ClipError> {
        if !(pixel.is_normal() && pixel > 0.0 && pixel.to_bits() & ((1u64 << 52) - 1) == 0) {
            return Err(ClipError::InvalidPixel { value: pixel });
        }
        for (operand, polygons) in [(Operand::Subject, subject), (Operand::Clip, clip)] {
            check_on_grid(operand, polygons, pixel)?;
        }
        // Decided in pixel units (dividing by a power of two is exact): there every coordinate
        // is below 2^51, so the degree-three crossing predicates of snap rounding stay finite
        // whatever the pixel (in world units they overflow for coordinates beyond about 1e100).
        let in_pixels = |r: &Ring| Ring::new(r.points.iter().map(|p| Point::new(p.x / pixel, p.y / pixel)).collect());
        let rings: Vec<Ring> = subject.rings.iter().chain(&clip.rings).map(in_pixels).collect();
        let segments: Vec<Segment> = rings.iter().flat_map(|r| r.edges()).collect();
        let pairs = near_pairs(rings.iter().map(Ring::len), &segments, 1.0);
        Ok(NearEdges { pixel, subject_rings: subject.rings.len(), rings, segments, pairs })
    }

    /// The pixel's side, in the operands' units.
    pub fn pixel(&self) -> f64 {
        self.pixel
    }

    /// `rings` (in pixel units) back in the operands' units as the subject and the clip: exact
    /// for points on the operands' grid of coordinates (multiplying by a power of two).
    pub(crate) fn in_world(&self, rings: impl IntoIterator<Item = Option<Vec<Point>>>) -> (Polygons, Polygons) {
        let pixel = self.pixel;
        let world =
            |points: Vec<Point>| Ring::new(points.into_iter().map(|p| Point::new(p.x * pixel, p.y * pixel)).collect());
        let mut rings = rings.into_iter();
        let mut take = |n: usize| Polygons::new(rings.by_ref().take(n).flatten().map(world).collect());
        let a = take(self.subject_rings);
        let b = take(usize::MAX);
        (a, b)
    }
}

/// Every coordinate finite and within 2^51 pixels of the origin, where the pixel's centre and
/// borders are exact.
fn check_on_grid(operand: Operand, polygons: &Polygons, pixel: f64) -> Result<(), ClipError> {
    let limit = pixel * 2f64.powi(51);
    for (part, ring) in polygons.rings.iter().enumerate() {
        for (vertex, p) in ring.points.iter().enumerate() {
            if !p.is_finite() {
                return Err(ClipError::NonFinite { operand, part, vertex, x: p.x, y: p.y });
            }
            if let Some(value) = [p.x, p.y].into_iter().find(|v| v.abs() >= limit) {
                return Err(ClipError::BeyondGrid { operand, part, vertex, value, pixel });
            }
        }
    }
    Ok(())
}

/// The pairs of `segments` (the edges of rings of `lengths` edges, ring after ring) whose boxes,
/// grown by `s`, meet, less those certainly farther apart than `s·√2` ([`apart`]). A ring's
/// consecutive edges, the most common close pairs, are all kept, listed first in order along
/// their rings: the index walk skips them, and the walks over the pairs (vertex snapping, snap
/// rounding) read their segments in order instead of scattered by cell.
pub(crate) fn near_pairs(lengths: impl IntoIterator<Item = usize>, segments: &[Segment], s: f64) -> Vec<(u32, u32)> {
    let mut pairs: Vec<(u32, u32)> = Vec::new();
    // The edge after each one in its ring.
    let mut next: Vec<u32> = Vec::with_capacity(segments.len());
    for n in lengths {
        let (first, end) = (next.len() as u32, (next.len() + n) as u32);
        let after = |k: u32| if k + 1 == end { first } else { k + 1 };
        next.extend((first..end).map(after));
        // Each pair once: a ring of two edges makes one, a ring of one none.
        let count = if n > 2 { n } else { n.saturating_sub(1) };
        pairs.extend((first..end).take(count).map(|k| (k, after(k))));
    }
    debug_assert_eq!(next.len(), segments.len(), "the rings' lengths add up to the segments");
    let boxes: Vec<_> = segments.iter().map(|e| e.bounds().expanded(s)).collect();
    if let Some(index) = CellIndex::new(&boxes) {
        let _ = index.try_for_each_close_pair::<()>(&boxes, |i, j| {
            if next[i] as usize == j || next[j] as usize == i {
                return Ok(());
            }
            let (e, f) = (segments[i], segments[j]);
            if shared_end(e, f).is_some() || !apart(e, f, s) {
                pairs.push((i as u32, j as u32));
            }
            Ok(())
        });
    }
    pairs
}

/// An end `e` and `f` have in common.
#[inline]
pub(crate) fn shared_end(e: Segment, f: Segment) -> Option<Point> {
    [e.a, e.b].into_iter().find(|&v| v == f.a || v == f.b)
}

/// True when `e` and `f` are certainly farther apart than a pixel's diagonal `s·√2`: the ends of
/// one lie on one side of the other's line, both farther than that from it. Such a pair neither
/// crosses nor has a point of one within a pixel of the other. A float test with its rounding
/// bounded, so it keeps every pair within reach: boxes that meet are a poor test for long edges
/// at an angle, which share boxes with many others far from them.
#[inline]
pub(crate) fn apart(e: Segment, f: Segment, s: f64) -> bool {
    // The side of `c` from the line of `a`-`b`, scaled by |b - a|, and what it errs by (Shewchuk's
    // bound for orient2d, over twice).
    let side = |a: Point, b: Point, c: Point| {
        let (l, r) = ((b.x - a.x) * (c.y - a.y), (b.y - a.y) * (c.x - a.x));
        (l - r, 8.0 * f64::EPSILON * (l.abs() + r.abs()))
    };
    // |b - a| is at most its L1 length, and √2 < 1.5.
    let beyond = |a: Point, b: Point, c: Point, d: Point| {
        let reach = 1.5 * s * ((b.x - a.x).abs() + (b.y - a.y).abs());
        let ((p, ep), (q, eq)) = (side(a, b, c), side(a, b, d));
        (p > reach + ep && q > reach + eq) || (p < -(reach + ep) && q < -(reach + eq))
    };
    beyond(e.a, e.b, f.a, f.b) || beyond(f.a, f.b, e.a, e.b)
}
