//! The `lines-degenerate` workload: windows on even integer coordinates and segments through
//! their vertices, along their edges, ending on their boundary, axis-parallel, or of zero length.
//!
//! Every coordinate is a small integer or a multiple of 1/4, so the incidences are exact: a
//! segment built to run along an edge really is collinear with it, and an endpoint built at an
//! edge's midpoint really lies on the edge.

use super::shapes::{convex_hull, star};
use clip_core::{Point, Polygons, Rect, Ring, Segment, WindowKind};
use rand::Rng;
use rand_pcg::Pcg64;

/// A window of the asked kind on even integer coordinates in the 800x600 screen.
pub(crate) fn degenerate_window(rng: &mut Pcg64, kind: WindowKind) -> Polygons {
    let even = |v: f64| (v / 2.0).round() * 2.0;
    match kind {
        WindowKind::Rectangle => {
            let (x0, y0) = (even(rng.random_range(100.0..300.0)), even(rng.random_range(100.0..250.0)));
            let (x1, y1) = (even(rng.random_range(500.0..700.0)), even(rng.random_range(350.0..500.0)));
            Polygons::from(Rect::new(x0, y0, x1, y1))
        }
        WindowKind::Convex => {
            let n = rng.random_range(5..=12);
            let s = star(rng, n, Point::new(400.0, 300.0), 250.0, 200.0, 0.99);
            let rounded: Vec<Point> = s.points.iter().map(|p| Point::new(even(p.x), even(p.y))).collect();
            Polygons::from(Ring::new(convex_hull(&rounded)))
        }
        WindowKind::Any => {
            let n = rng.random_range(5..=16);
            let s = star(rng, n, Point::new(400.0, 300.0), 250.0, 200.0, 0.3);
            let mut pts: Vec<Point> = s.points.iter().map(|p| Point::new(even(p.x), even(p.y))).collect();
            super::shapes::dedup_consecutive(&mut pts);
            Polygons::from(Ring::new(pts))
        }
    }
}

/// `count` segments, each of a random degenerate kind relative to `window`'s first ring.
pub(crate) fn degenerate_segments(rng: &mut Pcg64, window: &Polygons, count: usize) -> Vec<Segment> {
    let ring = &window.rings[0].points;
    let n = ring.len();
    let int = |rng: &mut Pcg64, lo: i32, hi: i32| f64::from(rng.random_range(lo..=hi));
    (0..count)
        .map(|_| {
            let i = rng.random_range(0..n);
            let (prev, v, next) = (ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]);
            let mut s = match rng.random_range(0..8) {
                // Through a vertex, in a random integer direction.
                0 => {
                    let d = Point::new(int(rng, -40, 40), int(rng, -40, 40));
                    Segment::new(v - d * int(rng, 1, 6), v + d * int(rng, 0, 6))
                }
                // Along an edge: part of it, all of it, or beyond its ends (quarter steps).
                1 => {
                    let d = next - v;
                    let t0 = [-0.5, 0.0, 0.25, 0.5][rng.random_range(0..4)];
                    let t1 = [0.5, 0.75, 1.0, 1.5][rng.random_range(0..4)];
                    Segment::new(v + d * t0, v + d * t1)
                }
                // From a vertex or an edge midpoint to a random grid point.
                2 => {
                    let on = if rng.random_bool(0.5) { v } else { v + (next - v) * 0.5 };
                    Segment::new(on, Point::new(int(rng, 0, 800), int(rng, 0, 600)))
                }
                // Horizontal or vertical through a vertex.
                3 => {
                    let l = int(rng, 10, 400);
                    if rng.random_bool(0.5) {
                        Segment::new(Point::new(v.x - l, v.y), Point::new(v.x + l, v.y))
                    } else {
                        Segment::new(Point::new(v.x, v.y - l), Point::new(v.x, v.y + l))
                    }
                }
                // Zero length: at a vertex, at an edge midpoint, or anywhere.
                4 => {
                    let p = match rng.random_range(0..3) {
                        0 => v,
                        1 => v + (next - v) * 0.5,
                        _ => Point::new(int(rng, 0, 800), int(rng, 0, 600)),
                    };
                    Segment::new(p, p)
                }
                // Through a vertex, parallel to its neighbours' chord: touches there at convex
                // vertices.
                5 => {
                    let d = next - prev;
                    Segment::new(v - d * 0.5, v + d * 0.75)
                }
                // From one vertex to another (a chord or a diagonal).
                6 => Segment::new(v, ring[rng.random_range(0..n)]),
                // Anywhere on the integer screen.
                _ => Segment::new(
                    Point::new(int(rng, 0, 800), int(rng, 0, 600)),
                    Point::new(int(rng, 0, 800), int(rng, 0, 600)),
                ),
            };
            if rng.random_bool(0.5) {
                s = s.reversed();
            }
            s
        })
        .collect()
}
