//! Assigns hole rings to the outer rings that hold them.

use crate::winding::ring_winding;
use crate::{Point, Polygons, Ring};

/// An outer ring with the holes directly inside it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct NestedPolygon {
    /// Counter-clockwise outer boundary.
    pub outer: Ring,
    /// Clockwise holes.
    pub holes: Vec<Ring>,
}

/// Groups conventional output (simple, non-crossing rings; outers counter-clockwise, holes
/// clockwise) into outers with their holes. A hole goes to the smallest outer that contains
/// it; a hole no outer contains becomes an outer of its own, reversed, so nothing is lost.
pub fn nest(polygons: &Polygons) -> Vec<NestedPolygon> {
    let mut outers: Vec<(f64, NestedPolygon)> = Vec::new();
    let mut holes: Vec<&Ring> = Vec::new();
    for ring in &polygons.rings {
        let a = ring.signed_area();
        if a > 0.0 {
            outers.push((a, NestedPolygon { outer: ring.clone(), holes: Vec::new() }));
        } else if a < 0.0 {
            holes.push(ring);
        }
    }
    let mut orphans = Vec::new();
    for hole in holes {
        let probe = interior_probe(hole);
        let owner = outers
            .iter_mut()
            .filter(|(_, o)| probe.iter().any(|&p| ring_winding(p, &o.outer).is_some_and(|w| w != 0)))
            .min_by(|a, b| a.0.total_cmp(&b.0));
        match owner {
            Some((_, o)) => o.holes.push(hole.clone()),
            None => orphans.push(NestedPolygon { outer: hole.reversed(), holes: Vec::new() }),
        }
    }
    outers.into_iter().map(|(_, o)| o).chain(orphans).collect()
}

/// Points to test a ring's containment with: its vertices, then its edge midpoints. Simple
/// output rings may touch their outer at vertices, but not along all of them.
fn interior_probe(ring: &Ring) -> Vec<Point> {
    let mut probe = ring.points.clone();
    probe.extend(ring.edges().map(|e| e.at(0.5)));
    probe
}
