//! A polygon window's boundary under even-odd as edges with the window on their left.

use std::collections::HashMap;

use clip_core::predicates::{Orientation, orient};
use clip_core::{Point, Polygons, Segment, SegmentIntersection, segment_intersection};

/// The even-odd boundary of `window` as directed edges, each with the window's interior on its
/// left: every edge is split where another crosses or touches it (so one side is inside along
/// the whole piece), pieces covered an even number of times cancel (even-odd), and each piece is
/// turned by the parity of a ray from its midpoint. Works for any rings: concave, holes, several
/// parts, rings crossing themselves or each other. O(n²) in the window's edges, done once per
/// window.
pub fn oriented_boundary(window: &Polygons) -> Vec<Segment> {
    let edges: Vec<Segment> = window.edges().filter(|e| !e.is_degenerate()).collect();
    let pieces = cancel_even(split_at_meetings(&edges));
    pieces.iter().enumerate().map(|(i, &s)| if interior_on_left(s, i, &pieces) { s } else { s.reversed() }).collect()
}

/// Each edge cut at every point where another edge meets its interior.
fn split_at_meetings(edges: &[Segment]) -> Vec<Segment> {
    let mut cuts: Vec<Vec<Point>> = vec![Vec::new(); edges.len()];
    for i in 0..edges.len() {
        for j in i + 1..edges.len() {
            let (s, t) = (edges[i], edges[j]);
            if !s.bounds().intersects(&t.bounds()) {
                continue;
            }
            match segment_intersection(s, t) {
                SegmentIntersection::None => {}
                SegmentIntersection::Crossing(p) | SegmentIntersection::Touching(p) => {
                    cuts[i].push(p);
                    cuts[j].push(p);
                }
                SegmentIntersection::Overlap(o) => {
                    cuts[i].extend([o.a, o.b]);
                    cuts[j].extend([o.a, o.b]);
                }
            }
        }
    }
    let mut pieces = Vec::with_capacity(edges.len());
    for (e, mut at) in edges.iter().zip(cuts) {
        at.retain(|&p| p != e.a && p != e.b);
        at.sort_by(|p, q| e.param_of(*p).total_cmp(&e.param_of(*q)));
        let mut from = e.a;
        for p in at.into_iter().chain([e.b]) {
            if p != from {
                pieces.push(Segment::new(from, p));
                from = p;
            }
        }
    }
    pieces
}

/// Drops pieces that lie on the same two points an even number of times (either direction):
/// under even-odd crossing them twice changes nothing, so they bound nothing.
fn cancel_even(pieces: Vec<Segment>) -> Vec<Segment> {
    let key = |s: &Segment| {
        let (a, b) = ((s.a.x.to_bits(), s.a.y.to_bits()), (s.b.x.to_bits(), s.b.y.to_bits()));
        if a <= b { (a, b) } else { (b, a) }
    };
    let mut count: HashMap<_, usize> = HashMap::new();
    for s in &pieces {
        *count.entry(key(s)).or_default() += 1;
    }
    let mut kept = Vec::with_capacity(pieces.len());
    for s in pieces {
        if let Some(n) = count.get_mut(&key(&s)) {
            if *n % 2 == 1 {
                kept.push(s);
            }
            *n = 0;
        }
    }
    kept
}

/// True when the window lies left of piece `s` (index `own` in `pieces`): the parity of the
/// crossings of a ray from its midpoint that leaves on one known side, exact for the rounded
/// midpoint (half-open crossing rule, exact orientation).
fn interior_on_left(s: Segment, own: usize, pieces: &[Segment]) -> bool {
    let m = s.a.lerp(s.b, 0.5);
    let others = pieces.iter().enumerate().filter(|&(j, _)| j != own).map(|(_, e)| e);
    if s.a.y != s.b.y {
        // A ray towards +x: it leaves on the right of an upward piece, the left of a downward one.
        let crossings = others
            .filter(|e| (e.a.y > m.y) != (e.b.y > m.y))
            .filter(|e| {
                let (lo, hi) = if e.a.y < e.b.y { (e.a, e.b) } else { (e.b, e.a) };
                orient(lo, hi, m) == Orientation::CounterClockwise
            })
            .count();
        let ray_side_inside = crossings % 2 == 1;
        if s.a.y < s.b.y { !ray_side_inside } else { ray_side_inside }
    } else {
        // A horizontal piece: a ray towards +y, which leaves on the left of a piece going +x.
        let crossings = others
            .filter(|e| (e.a.x > m.x) != (e.b.x > m.x))
            .filter(|e| {
                let (l, r) = if e.a.x < e.b.x { (e.a, e.b) } else { (e.b, e.a) };
                orient(l, r, m) == Orientation::Clockwise
            })
            .count();
        let ray_side_inside = crossings % 2 == 1;
        if s.a.x < s.b.x { ray_side_inside } else { !ray_side_inside }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::{Rect, Ring};

    fn twice_area(edges: &[Segment]) -> f64 {
        edges.iter().map(|e| e.a.cross(e.b)).sum()
    }

    #[test]
    fn outer_and_hole_any_orientation_bound_the_even_odd_region() {
        let outer = Rect::new(0.0, 0.0, 10.0, 10.0).to_ring().reversed();
        let hole = Rect::new(2.0, 2.0, 4.0, 4.0).to_ring();
        let b = oriented_boundary(&Polygons::new(vec![outer, hole]));
        assert_eq!(b.len(), 8);
        assert_eq!(twice_area(&b), 2.0 * (100.0 - 4.0));
    }

    #[test]
    fn a_bow_tie_and_overlapping_squares_are_read_even_odd() {
        let p = |x, y| Point::new(x, y);
        let bow = Ring::new(vec![p(0.0, 0.0), p(4.0, 4.0), p(4.0, 0.0), p(0.0, 4.0)]);
        let b = oriented_boundary(&Polygons::from(bow));
        assert_eq!(twice_area(&b), 2.0 * 8.0);
        // Two squares sharing their left half: even-odd leaves the two outer thirds.
        let a = Rect::new(0.0, 0.0, 3.0, 1.0).to_ring();
        let c = Rect::new(1.0, 0.0, 4.0, 1.0).to_ring();
        let b = oriented_boundary(&Polygons::new(vec![a, c]));
        assert_eq!(twice_area(&b), 2.0 * 2.0);
    }
}
