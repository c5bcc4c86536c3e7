//! Exact pixel counts on shapes whose counts are known, and the two fills lighting identical
//! pixels on random polygons decomposed into trapezoids.

use clip_core::{FillRule, Location, Point, Polygons, Rect, Ring, Trapezoid, locate};
use clip_raster::{FrameBuffer, fill_polygons, fill_trapezoids};

mod slabs;
use slabs::trapezoids_of;

fn scanline(p: &Polygons, fill: FillRule) -> FrameBuffer {
    let mut frame = FrameBuffer::default();
    fill_polygons(&mut frame, p, fill, 1).unwrap();
    frame
}

fn ring(points: &[(f64, f64)]) -> Polygons {
    Polygons::from(Ring::from(points))
}

/// Pixels whose centres are inside `p`, by exact point location, over a `w x h` corner of the
/// buffer; panics if a centre lies on an edge (the shapes are chosen so none does).
fn brute_force_count(p: &Polygons, fill: FillRule, w: usize, h: usize) -> usize {
    let mut count = 0;
    for j in 0..h {
        for i in 0..w {
            match locate(Point::new(i as f64 + 0.5, j as f64 + 0.5), p, fill) {
                Location::Inside => count += 1,
                Location::Outside => {}
                Location::Boundary => panic!("centre ({i}, {j}) on an edge"),
            }
        }
    }
    count
}

#[test]
fn rectangles_light_width_times_height() {
    assert_eq!(scanline(&Polygons::from(Rect::new(2.0, 3.0, 12.0, 8.0)), FillRule::EvenOdd).lit_count(), 50);
    // Edges through pixel centres: the low sides are in, the high sides out.
    assert_eq!(scanline(&Polygons::from(Rect::new(0.5, 0.5, 10.5, 4.5)), FillRule::EvenOdd).lit_count(), 40);
    assert_eq!(scanline(&Polygons::from(Rect::new(0.2, 0.7, 3.4, 2.6)), FillRule::NonZero).lit_count(), 3 * 2);
    // Two abutting rectangles share no pixel and miss none.
    let mut frame = FrameBuffer::default();
    fill_polygons(&mut frame, &Polygons::from(Rect::new(0.0, 0.0, 5.5, 7.5)), FillRule::EvenOdd, 1).unwrap();
    fill_polygons(&mut frame, &Polygons::from(Rect::new(5.5, 0.0, 9.0, 7.5)), FillRule::EvenOdd, 2).unwrap();
    assert_eq!(frame.pixels().iter().filter(|&&v| v == 1).count(), 5 * 7);
    assert_eq!(frame.pixels().iter().filter(|&&v| v == 2).count(), 4 * 7);
    // Clipped to the buffer.
    assert_eq!(
        scanline(&Polygons::from(Rect::new(-100.0, -100.0, 1e6, 1e6)), FillRule::EvenOdd).lit_count(),
        1280 * 1024
    );
}

#[test]
fn right_triangles_light_n_times_n_minus_one_over_two() {
    for n in [1usize, 2, 10, 37, 200] {
        let size = n as f64;
        let lower_left = ring(&[(0.0, 0.0), (size, 0.0), (0.0, size)]);
        // Centres (i + .5, j + .5) with i + j + 1 < n; those on the hypotenuse are out.
        assert_eq!(scanline(&lower_left, FillRule::EvenOdd).lit_count(), n * (n - 1) / 2, "n = {n}");
        // Clockwise, under non-zero: the same pixels.
        let cw = Polygons::from(lower_left.rings[0].reversed());
        assert_eq!(scanline(&cw, FillRule::NonZero).lit_count(), n * (n - 1) / 2);
        assert_eq!(scanline(&cw, FillRule::Positive).lit_count(), 0);
        assert_eq!(scanline(&cw, FillRule::Negative).lit_count(), n * (n - 1) / 2);
    }
}

#[test]
fn stars_light_their_known_counts() {
    // A plus sign: two 30 x 10 bars crossing in a 10 x 10 square: 300 + 300 - 100 pixels.
    let plus = ring(&[
        (10.0, 0.0),
        (20.0, 0.0),
        (20.0, 10.0),
        (30.0, 10.0),
        (30.0, 20.0),
        (20.0, 20.0),
        (20.0, 30.0),
        (10.0, 30.0),
        (10.0, 20.0),
        (0.0, 20.0),
        (0.0, 10.0),
        (10.0, 10.0),
    ]);
    assert_eq!(scanline(&plus, FillRule::EvenOdd).lit_count(), 500);
    // A pentagram: self-intersecting, so its inner pentagon has winding 2: out under even-odd,
    // in under non-zero. Vertices are off the half-pixel lattice, so no centre is on an edge.
    let pentagram: Vec<(f64, f64)> = (0..5)
        .map(|k| {
            let a = std::f64::consts::FRAC_PI_2 + f64::from(k) * 4.0 * std::f64::consts::PI / 5.0;
            (100.3 + 90.0 * a.cos(), 100.1 + 90.0 * a.sin())
        })
        .collect();
    let star = ring(&pentagram);
    for fill in [FillRule::EvenOdd, FillRule::NonZero] {
        assert_eq!(scanline(&star, fill).lit_count(), brute_force_count(&star, fill, 200, 200), "{fill}");
    }
    let (even_odd, non_zero) = (scanline(&star, FillRule::EvenOdd), scanline(&star, FillRule::NonZero));
    assert!(non_zero.lit_count() > even_odd.lit_count());
}

#[test]
fn trapezoids_light_known_counts() {
    let mut frame = FrameBuffer::default();
    let square = Trapezoid { x_left: 2.0, x_right: 12.0, y_bottom: 3.0, dx_left: 0.0, dx_right: 0.0, y_top: 8.0 };
    fill_trapezoids(&mut frame, &[square], 1).unwrap();
    assert_eq!(frame.lit_count(), 50);
    frame.clear();
    assert_eq!(frame.lit_count(), 0);
    let triangle = Trapezoid { x_left: 0.0, x_right: 10.0, y_bottom: 0.0, dx_left: 0.0, dx_right: -1.0, y_top: 10.0 };
    fill_trapezoids(&mut frame, &[triangle], 1).unwrap();
    assert_eq!(frame.lit_count(), 45);
    let bad = Trapezoid { x_left: f64::NAN, ..triangle };
    assert!(fill_trapezoids(&mut frame, &[bad], 1).is_err());
    assert!(
        fill_polygons(&mut frame, &ring(&[(0.0, 0.0), (f64::NAN, 1.0), (1.0, 1.0)]), FillRule::EvenOdd, 1).is_err()
    );
}

/// A small deterministic generator (SplitMix64), so the test needs no dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A random simple polygon: a star-shaped ring (increasing angles, random radii) around a random
/// centre, sometimes with vertices snapped to the half-pixel lattice so that edges run through
/// pixel centres and horizontal edges occur.
fn random_polygon(rng: &mut Rng, snap: bool) -> Ring {
    let n = 4 + (rng.next() * 40.0) as usize;
    let (cx, cy) = (310.0 + rng.next() * 660.0, 310.0 + rng.next() * 400.0); // fits in the frame
    // Jittered angles: consecutive ones stay less than half a turn apart, so the ring is simple.
    let angles: Vec<f64> = (0..n).map(|k| (k as f64 + 0.8 * rng.next()) / n as f64 * std::f64::consts::TAU).collect();
    let points = angles
        .iter()
        .map(|&a| {
            let r = 5.0 + rng.next() * 300.0;
            let (x, y) = (cx + r * a.cos(), cy + r * a.sin());
            if snap { Point::new((x * 2.0).round() / 2.0, (y * 2.0).round() / 2.0) } else { Point::new(x, y) }
        })
        .collect();
    Ring::new(points).without_repeats()
}

#[test]
fn scanline_and_trapezoid_fills_light_identical_pixels_on_random_polygons() {
    let mut rng = Rng(20_260_422);
    let mut lit = 0;
    for case in 0..150 {
        let mut polygon = random_polygon(&mut rng, case % 3 == 0);
        // Every fifth polygon hangs off the frame's lower-left corner: both fills skip the same rows.
        let off_frame = case % 5 == 4;
        if off_frame {
            polygon.points.iter_mut().for_each(|p| *p = *p - Point::new(400.0, 350.0));
        }
        let region = Polygons::from(polygon);
        let trapezoids = trapezoids_of(&region);
        let area: f64 = trapezoids.iter().map(Trapezoid::area).sum();
        assert!((area - region.signed_area().abs()).abs() <= 1e-6 * area.max(1.0), "case {case}: bad decomposition");
        let by_scanline = scanline(&region, FillRule::EvenOdd);
        let mut by_trapezoid = FrameBuffer::default();
        fill_trapezoids(&mut by_trapezoid, &trapezoids, 1).unwrap();
        assert_eq!(by_scanline.checksum(), by_trapezoid.checksum(), "case {case}");
        assert_eq!(by_scanline, by_trapezoid, "case {case}");
        assert_eq!(scanline(&region, FillRule::NonZero), by_scanline, "case {case}: simple, so non-zero = even-odd");
        lit += by_scanline.lit_count();
        // The lit count approximates the area (one pixel per unit square).
        assert!(
            off_frame
                || (by_scanline.lit_count() as f64 - area).abs()
                    <= 2.0 * region.rings[0].edges().map(|e| e.length()).sum::<f64>() + 4.0
        );
    }
    assert!(lit > 1000);
}

#[test]
fn frame_buffer_basics() {
    let frame = FrameBuffer::default();
    assert_eq!((frame.width(), frame.height(), frame.lit_count()), (1280, 1024, 0));
    let mut a = FrameBuffer::new(8, 4);
    let b = FrameBuffer::new(8, 4);
    assert_eq!(a.checksum(), b.checksum());
    fill_polygons(&mut a, &Polygons::from(Rect::new(1.0, 1.0, 2.0, 2.0)), FillRule::EvenOdd, 7).unwrap();
    assert_eq!((a.get(1, 1), a.get(0, 0), a.get(100, 100)), (7, 0, 0));
    assert_ne!(a.checksum(), b.checksum());
}
