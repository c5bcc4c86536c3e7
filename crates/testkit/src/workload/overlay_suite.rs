//! i_overlay's published performance suite (github.com/iShape-Rust/iOverlayPerformance,
//! `iOverlayAppRust/src/test/`), re-implemented: the same shapes, coordinates, ring orientation
//! and operand split as its generators, one function per test. Its rings run clockwise, except
//! where a generator says otherwise; no operand covers a point twice except `spiral`'s, so
//! even-odd and non-zero read every other operand alike.
//!
//! Each generator takes the suite's own count `n`; [`SuiteTest::count_for`] picks the `n` whose
//! two operands have, together, the edge count nearest to the one asked for.

use clip_core::{Point, Polygons, Ring};
use std::f64::consts::PI;

/// One test of the suite.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum SuiteTest {
    /// Test 0, `test_0_checkerboard.rs`: an n x n grid of squares against an (n-1) x (n-1) grid
    /// overlapping their corners; timed with ⊕.
    Checkerboard,
    /// Test 1, `test_1_not_overlap.rs`: the same grids with smaller squares that never meet; ∪.
    NotOverlap,
    /// Test 2, `test_2_lines_net.rs`: n vertical strips against n horizontal ones; ∩ (n² squares).
    LinesNet,
    /// Test 3, `test_3_spiral.rs`: one self-crossing spiral band of 4n vertices united with
    /// itself (the suite's `simplify_shape`, Clipper2's union with no clip).
    Spiral,
    /// Test 4, `test_4_windows.rs`: an n x n grid of squares minus a smaller square centred in
    /// each: −.
    Windows,
    /// Test 5, `test_5_nested_squares.rs`: 2n concentric square frames split into vertical
    /// (subject) and horizontal (clip) strips overlapping at the corners; ⊕.
    Nested,
    /// Test 6, `test_6_corrosion.rs`: an n x n grid of regular 3- to 7-gons minus a denser
    /// (2.5n)² grid of smaller ones; −.
    Corrosion,
    /// Test 7, `test_7_concentric.rs`: n concentric polygonal rings of growing vertex counts ∩
    /// small regular polygons strung along each; ∩.
    Concentric,
    /// Test 8, `test_8_wind_mill.rs`: an n x n grid of wind-mills, four triangles each, minus
    /// four squares each; −.
    WindMill,
}

impl SuiteTest {
    /// The test of a workload name, if it is one of the suite's.
    pub(crate) fn of(workload: &str) -> Option<SuiteTest> {
        Some(match workload {
            "checkerboard" => SuiteTest::Checkerboard,
            "not-overlap" => SuiteTest::NotOverlap,
            "lines-net" => SuiteTest::LinesNet,
            "spiral" => SuiteTest::Spiral,
            "windows" => SuiteTest::Windows,
            "nested" => SuiteTest::Nested,
            "corrosion" => SuiteTest::Corrosion,
            "concentric" => SuiteTest::Concentric,
            "wind-mill" => SuiteTest::WindMill,
            _ => return None,
        })
    }

    /// The smallest count the generator takes.
    fn min_count(self) -> usize {
        match self {
            SuiteTest::Checkerboard | SuiteTest::NotOverlap | SuiteTest::Spiral => 2,
            _ => 1,
        }
    }

    /// Whether every coordinate is an integer (the suite's `IntPoint` tests).
    pub(crate) fn on_integers(self) -> bool {
        !matches!(self, SuiteTest::Spiral | SuiteTest::Corrosion | SuiteTest::Concentric)
    }

    /// The edges of both operands at count `n`, without building them.
    pub(crate) fn edges_at(self, n: usize) -> usize {
        match self {
            SuiteTest::Checkerboard | SuiteTest::NotOverlap => 4 * (n * n + (n - 1) * (n - 1)),
            SuiteTest::LinesNet => 8 * n,
            SuiteTest::Spiral => 4 * n,
            SuiteTest::Windows => 8 * n * n,
            SuiteTest::Nested => 16 * n,
            SuiteTest::Corrosion => corrosion_edges(n) + corrosion_edges(corrosion_clip_count(n)),
            SuiteTest::Concentric => (0..n).map(|i| 2 * (i + 3) + concentric_clip_edges(i)).sum(),
            SuiteTest::WindMill => 28 * n * n,
        }
    }

    /// The count whose [`Self::edges_at`] is nearest to `edges` (by ratio), at least the
    /// generator's smallest.
    pub(crate) fn count_for(self, edges: usize) -> usize {
        let target = edges.max(1) as f64;
        let off = |n: usize| (self.edges_at(n) as f64 / target).ln().abs();
        // Every count grows with n: double up past the target, then bisect the last step.
        let (mut lo, mut hi) = (self.min_count(), self.min_count());
        while self.edges_at(hi) < edges {
            lo = hi;
            hi *= 2;
        }
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if self.edges_at(mid) < edges { lo = mid } else { hi = mid }
        }
        if off(lo) <= off(hi) { lo } else { hi }
    }

    /// The two operands at count `n` (`spiral`'s clip is empty).
    pub(crate) fn operands(self, n: usize) -> (Polygons, Polygons) {
        let n = n.max(self.min_count());
        match self {
            SuiteTest::Checkerboard => (many_squares(0, 20, 30, n), many_squares(15, 20, 30, n - 1)),
            SuiteTest::NotOverlap => (many_squares(0, 10, 30, n), many_squares(15, 10, 30, n - 1)),
            SuiteTest::LinesNet => (many_lines_x(20, n), many_lines_y(20, n)),
            SuiteTest::Spiral => (Polygons::from(spiral(n, 100.0)), Polygons::empty()),
            SuiteTest::Windows => {
                // `test_4_windows.rs`: the grid centred on the origin.
                let x = n as i64 * 30 / 2;
                many_windows(-x, 20, 10, 30, n)
            }
            SuiteTest::Nested => concentric_squares(4, n),
            SuiteTest::Corrosion => corrosion(100.0, n),
            SuiteTest::Concentric => concentric(100.0, n),
            SuiteTest::WindMill => wind_mills(80, n),
        }
    }
}

fn int_ring(points: &[(i64, i64)]) -> Ring {
    Ring::new(points.iter().map(|&(x, y)| Point::new(x as f64, y as f64)).collect())
}

/// `Util::many_squares`: an n x n grid of clockwise squares of side `size`, `offset` apart,
/// from (`start`, `start`).
fn many_squares(start: i64, size: i64, offset: i64, n: usize) -> Polygons {
    let mut rings = Vec::with_capacity(n * n);
    for row in 0..n as i64 {
        let y = start + row * offset;
        for col in 0..n as i64 {
            let x = start + col * offset;
            rings.push(int_ring(&[(x, y), (x, y + size), (x + size, y + size), (x + size, y)]));
        }
    }
    Polygons::new(rings)
}

/// `Util::many_windows`: an n x n grid of clockwise squares of side `a` (the boundaries) and a
/// clockwise square of side `b` centred in each (the clip).
fn many_windows(start: i64, a: i64, b: i64, offset: i64, n: usize) -> (Polygons, Polygons) {
    let (mut boundaries, mut holes) = (Vec::with_capacity(n * n), Vec::with_capacity(n * n));
    let c = (a - b) / 2;
    let d = b + c;
    for row in 0..n as i64 {
        let y = start + row * offset;
        for col in 0..n as i64 {
            let x = start + col * offset;
            boundaries.push(int_ring(&[(x, y), (x, y + a), (x + a, y + a), (x + a, y)]));
            holes.push(int_ring(&[(x + c, y + c), (x + c, y + d), (x + d, y + d), (x + d, y + c)]));
        }
    }
    (Polygons::new(boundaries), Polygons::new(holes))
}

/// `Util::concentric_squares`: frame k (k = 1..=n) at half-size r = 2ak, of width `a`, as two
/// vertical strips (subject) and two horizontal ones (clip), all clockwise.
fn concentric_squares(a: i64, n: usize) -> (Polygons, Polygons) {
    let (mut vert, mut horz) = (Vec::with_capacity(2 * n), Vec::with_capacity(2 * n));
    let s = 2 * a;
    for k in 1..=n as i64 {
        let r = s * k;
        horz.push(int_ring(&[(-r, r - a), (-r, r), (r, r), (r, r - a)]));
        horz.push(int_ring(&[(-r, -r), (-r, -r + a), (r, -r + a), (r, -r)]));
        vert.push(int_ring(&[(-r, -r), (-r, r), (-r + a, r), (-r + a, -r)]));
        vert.push(int_ring(&[(r - a, -r), (r - a, r), (r, r), (r, -r)]));
    }
    (Polygons::new(vert), Polygons::new(horz))
}

/// `Util::many_lines_x` and `many_lines_y`: n clockwise strips of width a/2, a apart, across
/// [-an/2, an/2], vertical (subject) and horizontal (clip).
fn many_lines_x(a: i64, n: usize) -> Polygons {
    let w = a / 2;
    let s = a * n as i64 / 2;
    Polygons::new(
        (0..n as i64)
            .map(|i| {
                let x = -s + w / 2 + i * a;
                int_ring(&[(x, -s), (x, s), (x + w, s), (x + w, -s)])
            })
            .collect(),
    )
}

fn many_lines_y(a: i64, n: usize) -> Polygons {
    let h = a / 2;
    let s = a * n as i64 / 2;
    Polygons::new(
        (0..n as i64)
            .map(|i| {
                let y = -s + h / 2 + i * a;
                int_ring(&[(-s, y), (s, y), (s, y - h), (-s, y - h)])
            })
            .collect(),
    )
}

/// `Util::spiral`: a band of half-width `radius / 10` along a zig-zag spiral (the radius
/// alternating ±20% about one that grows by `radius` per turn), each of its `count` segments
/// offset on its own, so consecutive offsets cross or leave notches; one ring of 4 `count`
/// vertices, the left offsets out and the right ones back.
fn spiral(count: usize, radius: f64) -> Ring {
    let (mut left, mut right) = (Vec::with_capacity(2 * count), Vec::with_capacity(2 * count));
    let (mut a, mut r) = (0.0f64, radius);
    let w = 0.1 * radius;
    let mut p0 = Point::ZERO;
    for i in 0..count {
        let (sy, sx) = a.sin_cos();
        let rr = if i % 2 == 0 { r + 0.2 * radius } else { r - 0.2 * radius };
        let p = Point::new(rr * sx, rr * sy);
        let (dx, dy) = (p.x - p0.x, p.y - p0.y);
        let len = (dx * dx + dy * dy).sqrt();
        let t = Point::new(w * -dy / len, w * dx / len);
        left.push(Point::new(p0.x + t.x, p0.y + t.y));
        left.push(Point::new(p.x + t.x, p.y + t.y));
        right.push(Point::new(p0.x - t.x, p0.y - t.y));
        right.push(Point::new(p.x - t.x, p.y - t.y));
        a += radius / r;
        r = radius * (1.0 + a / (2.0 * PI));
        p0 = p;
    }
    right.reverse();
    left.append(&mut right);
    Ring::new(left)
}

/// `CorrosionTest::shape` (and `ConcentricTest::shape` with `dir`): a regular `count`-gon of
/// circumradius `radius` from angle `angle`, counter-clockwise for `dir` 1, clockwise for -1.
fn regular(center: Point, angle: f64, radius: f64, count: usize, dir: f64) -> Ring {
    let da = dir * 2.0 * PI / count as f64;
    let mut a = angle;
    let points = (0..count)
        .map(|_| {
            let p = Point::new(a.cos() * radius + center.x, a.sin() * radius + center.y);
            a += da;
            p
        })
        .collect();
    Ring::new(points)
}

/// The clip grid's side in `CorrosionTest::geometry`.
fn corrosion_clip_count(n: usize) -> usize {
    (n as f64 * 2.5).round() as usize
}

/// The edges of `CorrosionTest::shapes` over a `count` x `count` grid.
fn corrosion_edges(count: usize) -> usize {
    (0..count).flat_map(|i| (0..count).map(move |j| (i + j) % 5 + 3)).sum()
}

/// `CorrosionTest::geometry(size, count)`: a `count` x `count` grid of counter-clockwise
/// regular polygons of radius 0.4 size, `size` apart, from the origin (subject), and a
/// (2.5 count)² grid of radius 0.16 size, 0.4 size apart, from (-0.4 size, -0.4 size) (clip).
fn corrosion(size: f64, count: usize) -> (Polygons, Polygons) {
    let subject_radius = 0.4 * size;
    let subject = corrosion_shapes(0.0, size, subject_radius, count);
    let clip = corrosion_shapes(subject_radius, 0.4 * size, 0.4 * subject_radius, corrosion_clip_count(count));
    (subject, clip)
}

/// `CorrosionTest::shapes`: row i, column j holds a regular ((i + j) mod 5 + 3)-gon.
fn corrosion_shapes(offset: f64, step: f64, radius: f64, count: usize) -> Polygons {
    let mut rings = Vec::with_capacity(count * count);
    let mut y = -offset;
    for i in 0..count {
        let mut x = -offset;
        for j in 0..count {
            rings.push(regular(Point::new(x, y), 0.0, radius, (i + j) % 5 + 3, 1.0));
            x += step;
        }
        y += step;
    }
    Polygons::new(rings)
}

/// How many small polygons `ConcentricTest::geometry` strings along ring `i` (size 100), and
/// their edges.
fn concentric_strung(size: f64, i: usize) -> (usize, f64) {
    let r = size + 2.0 * size * i as f64;
    let along = 2.0 * PI * r * (0.8 / size);
    (along as usize, along)
}

fn concentric_clip_edges(i: usize) -> usize {
    (0..concentric_strung(100.0, i).0).map(|j| j % 5 + 3).sum()
}

/// `ConcentricTest::geometry(size, count)`: ring i (radius r = size (1 + 2i), turned 0.05 i)
/// is a clockwise (i + 3)-gon of radius r inside a counter-clockwise one of radius r + size
/// (subject: the band between them); the clip strings counter-clockwise 3- to 7-gons of radius
/// size / 2 along the circle of radius r, 1.25 size apart.
fn concentric(size: f64, count: usize) -> (Polygons, Polygons) {
    let (mut subject, mut clip) = (Vec::with_capacity(2 * count), Vec::new());
    let mut angle = 0.0;
    for i in 0..count {
        let r = size + 2.0 * size * i as f64;
        subject.push(regular(Point::ZERO, angle, r, i + 3, -1.0));
        subject.push(regular(Point::ZERO, angle, r + size, i + 3, 1.0));
        let (strung, along) = concentric_strung(size, i);
        let da = 2.0 * PI / along;
        let mut a = angle;
        for j in 0..strung {
            clip.push(regular(Point::new(a.cos() * r, a.sin() * r), 0.0, 0.5 * size, j % 5 + 3, 1.0));
            a += da;
        }
        angle += 0.05;
    }
    (Polygons::new(subject), Polygons::new(clip))
}

/// `WindMillTest::geometry(size, count)`: a `count` x `count` grid of wind-mills `size` apart
/// from (size/2, size/2), each four clockwise triangles (subject) and four clockwise squares
/// (clip) on a unit of a = size / 8.
fn wind_mills(size: i64, count: usize) -> (Polygons, Polygons) {
    let (mut subject, mut clip) = (Vec::with_capacity(4 * count * count), Vec::with_capacity(4 * count * count));
    let a = size / 8;
    for i in 0..count as i64 {
        let x = size / 2 + i * size;
        for j in 0..count as i64 {
            let y = size / 2 + j * size;
            let at = |points: &[(i64, i64)]| {
                int_ring(&points.iter().map(|&(u, v)| (x + u * a, y + v * a)).collect::<Vec<_>>())
            };
            clip.push(at(&[(-3, 1), (-3, 3), (-1, 3), (-1, 1)]));
            clip.push(at(&[(1, 2), (1, 4), (3, 4), (3, 2)]));
            clip.push(at(&[(-2, -3), (-2, -1), (0, -1), (0, -3)]));
            clip.push(at(&[(2, -2), (2, 0), (4, 0), (4, -2)]));
            subject.push(at(&[(0, 0), (-3, 0), (0, 3)]));
            subject.push(at(&[(0, 1), (0, 4), (3, 1)]));
            subject.push(at(&[(1, 0), (1, -3), (-2, 0)]));
            subject.push(at(&[(1, 1), (4, 1), (1, -2)]));
        }
    }
    (Polygons::new(subject), Polygons::new(clip))
}

#[cfg(test)]
mod tests {
    use super::*;

    const ALL: [SuiteTest; 9] = [
        SuiteTest::Checkerboard,
        SuiteTest::NotOverlap,
        SuiteTest::LinesNet,
        SuiteTest::Spiral,
        SuiteTest::Windows,
        SuiteTest::Nested,
        SuiteTest::Corrosion,
        SuiteTest::Concentric,
        SuiteTest::WindMill,
    ];

    #[test]
    fn edge_counts_match_the_built_operands() {
        for test in ALL {
            for n in [1, 2, 3, 5, 8] {
                let (s, c) = test.operands(n);
                let n = n.max(test.min_count());
                assert_eq!(s.vertex_count() + c.vertex_count(), test.edges_at(n), "{test:?} at {n}");
            }
        }
    }

    #[test]
    fn counts_land_nearest_to_the_asked_edges() {
        for test in ALL {
            for edges in [1, 10, 100, 1_000, 10_000, 1_000_000] {
                let n = test.count_for(edges);
                let off = |m: usize| (test.edges_at(m) as f64 / edges as f64).ln().abs();
                assert!(n >= test.min_count());
                if n > test.min_count() {
                    assert!(off(n) <= off(n - 1), "{test:?} {edges}: {n}");
                }
                assert!(off(n) <= off(n + 1), "{test:?} {edges}: {n}");
            }
        }
    }

    #[test]
    fn the_suites_rings_run_as_its_generators_draw_them() {
        // Clockwise throughout, but for corrosion's and concentric's counter-clockwise polygons
        // and concentric's clockwise inner rings.
        for test in ALL {
            let (s, c) = test.operands(3);
            for (k, ring) in s.rings.iter().chain(&c.rings).enumerate() {
                let ccw = ring.signed_area() > 0.0;
                let want_ccw = match test {
                    SuiteTest::Corrosion => true,
                    SuiteTest::Concentric => k >= s.rings.len() || k % 2 == 1,
                    _ => false,
                };
                assert_eq!(ccw, want_ccw, "{test:?} ring {k}");
            }
        }
    }
}
