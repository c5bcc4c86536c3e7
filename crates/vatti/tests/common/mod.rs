//! Vatti's own output validity check, stricter than the oracle's: rings never visit a point twice,
//! since vatti splits them at pinches.

use clip_core::predicates::{SegmentIntersection, segment_intersection};
use clip_core::{Point, Polygons, Segment};

/// Checks docs/DESIGN.md's output convention: no repeated consecutive vertices, at least three
/// vertices and non-zero area per ring, no two edges crossing or overlapping (touching at a
/// point is allowed), each ring simple, and orientation by nesting depth (outers CCW, holes CW).
pub fn check_valid(out: &Polygons) -> Result<(), String> {
    let mut edges: Vec<(usize, usize, Segment)> = Vec::new();
    for (ri, r) in out.rings.iter().enumerate() {
        let n = r.points.len();
        if n < 3 {
            return Err(format!("ring {ri} has {n} vertices"));
        }
        if r.signed_area() == 0.0 {
            return Err(format!("ring {ri} has zero area"));
        }
        for i in 0..n {
            if r.points[i] == r.points[(i + 1) % n] {
                return Err(format!("ring {ri} repeats vertex {i}"));
            }
            for j in i + 1..n {
                if r.points[i] == r.points[j] {
                    return Err(format!("ring {ri} visits {:?} twice", r.points[i]));
                }
            }
            edges.push((ri, i, Segment::new(r.points[i], r.points[(i + 1) % n])));
        }
    }
    for (x, &(ra, ia, sa)) in edges.iter().enumerate() {
        let bb = sa.bounds();
        for &(rb, ib, sb) in &edges[x + 1..] {
            if !bb.intersects(&sb.bounds()) {
                continue;
            }
            match segment_intersection(sa, sb) {
                SegmentIntersection::None | SegmentIntersection::Touching(_) => {}
                other => {
                    let n = out.rings[ra].points.len();
                    let adjacent = ra == rb && (ib == (ia + 1) % n || ia == (ib + 1) % n);
                    if !(adjacent && matches!(other, SegmentIntersection::Touching(_))) {
                        return Err(format!("ring {ra} edge {ia} and ring {rb} edge {ib}: {other:?}"));
                    }
                }
            }
        }
    }
    // Orientation by depth: a ring's sign must match the parity of the rings holding it.
    for (ri, r) in out.rings.iter().enumerate() {
        let probe = probe_point(&r.points);
        let Some(p) = probe else { continue };
        let depth = out
            .rings
            .iter()
            .enumerate()
            .filter(|&(rj, o)| rj != ri && clip_core::ring_winding(p, o).is_some_and(|w| w != 0))
            .count();
        let ccw = r.signed_area() > 0.0;
        if ccw != (depth % 2 == 0) {
            return Err(format!("ring {ri} orientation does not match its depth {depth}"));
        }
    }
    Ok(())
}

/// The midpoint of the ring's first edge: for nesting depth it is enough (rings do not cross,
/// and a ring touching another does so at vertices).
fn probe_point(pts: &[Point]) -> Option<Point> {
    Some(pts.first()?.lerp(*pts.get(1)?, 0.5))
}
