//! A slab decomposition of a polygon set into trapezoids, shared by the tests and the benches.

use clip_core::{Point, Polygons, Trapezoid};
use clip_raster::sampling::{edge_dx, edge_x_at};

/// Slab decomposition: cut at every vertex height; in each slab the edges that span it, ordered
/// by x at mid-slab, pair up (even-odd) into trapezoids anchored at the slab's bottom, as the
/// scanline fill anchors its active edges. Right for rings whose edges cross only at vertices.
pub fn trapezoids_of(region: &Polygons) -> Vec<Trapezoid> {
    let edges: Vec<(Point, Point)> = region.edges().filter(|e| e.a.y != e.b.y).map(|e| (e.a, e.b)).collect();
    let mut heights: Vec<f64> = region.points().map(|p| p.y).collect();
    heights.sort_by(f64::total_cmp);
    heights.dedup();
    let mut out = Vec::new();
    for slab in heights.windows(2) {
        let (y0, y1) = (slab[0], slab[1]);
        let mid = 0.5 * (y0 + y1);
        let mut spanning: Vec<&(Point, Point)> =
            edges.iter().filter(|(a, b)| a.y.min(b.y) <= y0 && a.y.max(b.y) >= y1).collect();
        spanning.sort_by(|p, q| edge_x_at(p.0, p.1, mid).total_cmp(&edge_x_at(q.0, q.1, mid)));
        for pair in spanning.chunks(2) {
            let (l, r) = (pair[0], pair[1]);
            out.push(Trapezoid {
                x_left: edge_x_at(l.0, l.1, y0),
                x_right: edge_x_at(r.0, r.1, y0),
                y_bottom: y0,
                dx_left: edge_dx(l.0, l.1),
                dx_right: edge_dx(r.0, r.1),
                y_top: y1,
            });
        }
    }
    out
}
