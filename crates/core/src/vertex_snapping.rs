//! Edges routed through the vertices that lie within a pixel of them: the middle step of a
//! fallback chain that starts with floating point and ends with snap rounding (GEOS OverlayNG
//! snaps in the same place, between its floating noder and its snap-rounding noder).
//!
//! Layers that share borders, each rounded on its own (map layers, tiles cut from them), hold
//! vertices a fraction of an ulp off the neighbour's edge they were on, and the edges of such a
//! vertex cross that edge within an ulp of it: slivers f64 cannot hold. Splitting the edge at the
//! vertex makes the two meet exactly there, and the slivers go. No vertex moves; an edge moves by
//! at most a pixel. Property used: such near misses are a vertex near an edge, not two edges near
//! each other along their length (those are left to snap rounding).

use crate::near_edges::NearEdges;
use crate::{Point, Polygons, Segment};

/// The operands `near` was made of, with every edge that passes within a pixel of a vertex of
/// either operand split at that vertex (unless the vertex lies within a pixel of one of the
/// edge's ends, where a split would only make an edge without length); `None` where there is no
/// such vertex. A split edge runs through its vertices in their order along it. The distances
/// are computed in floating point: which vertices count near the pixel's distance is a choice,
/// not a decision that needs to be exact.
pub fn snap_edges_to_vertices(near: &NearEdges) -> Option<(Polygons, Polygons)> {
    let segments = &near.segments;
    // (segment, vertex) for every vertex near a segment it does not end at, from both ends of
    // every near pair: a vertex within a pixel of a segment makes its segments a near pair.
    let mut splits: Vec<(u32, Point)> = Vec::new();
    for &(i, j) in &near.pairs {
        let (s, t) = (segments[i as usize], segments[j as usize]);
        for (k, e, v) in [(i, s, t.a), (i, s, t.b), (j, t, s.a), (j, t, s.b)] {
            if passes_near(e, v, 1.0) {
                splits.push((k, v));
            }
        }
    }
    if splits.is_empty() {
        return None;
    }
    // By segment, then along it: a vertex comes from both its segments, so repeats go.
    let along = |k: u32, v: Point| {
        let e = segments[k as usize];
        (v - e.a).dot(e.b - e.a)
    };
    splits.sort_unstable_by(|&(i, p), &(j, q)| {
        i.cmp(&j).then(along(i, p).total_cmp(&along(j, q))).then(p.x.total_cmp(&q.x)).then(p.y.total_cmp(&q.y))
    });
    splits.dedup();
    let mut next = splits.iter().peekable();
    let mut k = 0u32;
    let rings = near.rings.iter().map(|ring| {
        let mut points = Vec::with_capacity(ring.points.len());
        for &a in &ring.points {
            points.push(a);
            while let Some(&(_, v)) = next.next_if(|&&(s, _)| s == k) {
                points.push(v);
            }
            k += 1;
        }
        Some(points)
    });
    Some(near.in_world(rings))
}

/// True when vertex `v` lies within `tolerance` of edge `e` (within its span), and farther than
/// that from both its ends.
#[inline]
fn passes_near(e: Segment, v: Point, tolerance: f64) -> bool {
    let d = e.b - e.a;
    let (w, length2) = (v - e.a, d.dot(d));
    let along = w.dot(d);
    // Also false for an edge without length.
    if along <= 0.0 || along >= length2 {
        return false;
    }
    let near_end = |q: Point| {
        let r = v - q;
        r.dot(r) <= tolerance * tolerance
    };
    let off = w.cross(d);
    off * off <= tolerance * tolerance * length2 && !near_end(e.a) && !near_end(e.b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Rect, Ring};

    fn ring(points: &[(f64, f64)]) -> Ring {
        Ring::new(points.iter().map(|&(x, y)| Point::new(x, y)).collect())
    }

    /// [`snap_edges_to_vertices`] on a pixel of four ulps of the largest coordinate, a power of
    /// two at least `largest`.
    fn snapped(a: &Polygons, b: &Polygons, largest: f64) -> Option<(Polygons, Polygons)> {
        snap_edges_to_vertices(&NearEdges::of(a, b, largest * 4.0 * f64::EPSILON).expect("valid operands"))
    }

    #[test]
    fn an_edge_an_ulp_from_a_neighbours_vertex_runs_through_it() {
        // The square's right edge runs up x = 1; the triangle's vertex sits an ulp right of it.
        let square = Polygons::from(Rect::new(0.0, 0.0, 1.0, 1.0).to_ring());
        let off = 1.0 + f64::EPSILON;
        let triangle = Polygons::from(ring(&[(off, 0.5), (2.0, 0.0), (2.0, 1.0)]));
        let (a, b) = snapped(&square, &triangle, 2.0).expect("a split");
        assert_eq!(a.rings[0].points, ring(&[(0.0, 0.0), (1.0, 0.0), (off, 0.5), (1.0, 1.0), (0.0, 1.0)]).points);
        assert_eq!(b, triangle, "the triangle's edges pass near no vertex");
    }

    #[test]
    fn vertices_far_from_edges_or_at_their_ends_split_nothing() {
        let square = Polygons::from(Rect::new(0.0, 0.0, 1.0, 1.0).to_ring());
        // Far from every edge, and a shared corner.
        let far = Polygons::from(ring(&[(1.1, 0.5), (2.0, 0.0), (2.0, 1.0)]));
        let corner = Polygons::from(ring(&[(1.0, 1.0), (2.0, 1.0), (2.0, 2.0)]));
        assert_eq!(snapped(&square, &far, 2.0), None);
        assert_eq!(snapped(&square, &corner, 2.0), None);
        // An ulp from the square's corner: a split there would make an edge without length.
        let near_corner = Polygons::from(ring(&[(1.0 + f64::EPSILON, 1.0), (2.0, 1.0), (2.0, 2.0)]));
        assert_eq!(snapped(&square, &near_corner, 2.0), None);
    }

    #[test]
    fn several_vertices_on_one_edge_come_in_order_along_it() {
        // Three teeth whose tips come within 2 ulps of a wide box's bottom edge from below,
        // listed out of order; the box's ring runs right to left along that edge.
        let d = 2.0 * f64::EPSILON;
        let tooth = |x: f64| ring(&[(x, -d), (x + 0.25, -1.0), (x - 0.25, -1.0)]);
        let teeth = Polygons::new(vec![tooth(3.0), tooth(1.0), tooth(2.0)]);
        let box_ = Polygons::from(ring(&[(0.0, 0.0), (0.0, 1.0), (4.0, 1.0), (4.0, 0.0)]));
        let (a, _) = snapped(&box_, &teeth, 4.0).expect("splits");
        let xs: Vec<f64> = a.rings[0].points.iter().map(|p| p.x).collect();
        assert_eq!(xs, vec![0.0, 0.0, 4.0, 4.0, 3.0, 2.0, 1.0]);
    }
}
