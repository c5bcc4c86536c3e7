//! The curve workloads: circles or ellipses (and arcs of them) of random radius and position
//! against a window.

use core::f64::consts::{PI, TAU};

use clip_core::{ArcFill, Ellipse, EllipseArc, FilledArc, Point, Polygons, Rect, WindowKind};
use rand::Rng;
use rand_pcg::Pcg64;

use super::{UnknownWorkload, stream_rng, windows, with_holes};

/// The curve workloads, by name.
pub const CURVE_WORKLOADS: &[&str] = &["circles", "ellipses"];

/// Objects per generated case.
pub const CURVES_PER_CASE: usize = 24;

/// The frame windows and objects are placed in.
pub const CURVE_FRAME: Rect = Rect::new(0.0, 0.0, 1000.0, 1000.0);

/// One curve case: a window and a batch of objects to clip against it.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveCase {
    /// The workload's name.
    pub workload: &'static str,
    /// The run's seed.
    pub seed: u64,
    /// The case's index within the run.
    pub index: usize,
    /// The window (read under even-odd).
    pub window: Polygons,
    /// The objects: whole ellipses and arcs, each clipped as an outline and filled (arcs as
    /// sectors or chord regions, see [`filled_object`]).
    pub objects: Vec<EllipseArc>,
    /// What the case is, in words.
    pub description: String,
}

/// Case `index` of a curve workload with `count` objects.
///
/// The window is a rectangle of 30%-80% of the 1000 x 1000 frame for `Rectangle`, a random convex
/// polygon for `Convex`, and for `Any` a concave star with 1-3 holes (some cases cross a second
/// star over it, so rings cross each other). Objects: centres uniform over the window's box grown
/// by half, long radius log-uniform from 0.5% to 60% of the frame; `circles` draws circles,
/// `ellipses` radius ratios up to 10, half of them rotated. One object in three is an arc (random
/// start and sweep). Of the circles, one in ten is placed tangent to a side of the window's box and
/// one in twenty through one of its corners, the inputs where crossings meet or merge.
pub fn curve_case(
    workload: &str,
    seed: u64,
    index: usize,
    window: WindowKind,
    count: usize,
) -> Result<CurveCase, UnknownWorkload> {
    let name = CURVE_WORKLOADS
        .iter()
        .find(|&&w| w == workload)
        .copied()
        .ok_or_else(|| UnknownWorkload { given: workload.to_owned(), valid: CURVE_WORKLOADS })?;
    let mut rng = stream_rng(name, seed, index as u64);
    let (w, shape) = curve_window(&mut rng, window);
    let b = w.bounds();
    let objects: Vec<EllipseArc> = (0..count).filter_map(|_| object(&mut rng, name == "circles", &b)).collect();
    let description =
        format!("{name}: {} objects against a {shape} window of {} edges", objects.len(), w.vertex_count());
    Ok(CurveCase { workload: name, seed, index, window: w, objects, description })
}

/// Object `k` of a case as a filled shape: a whole ellipse is the filled ellipse, and arcs are
/// closed alternately by two radii (sectors, even `k`) and by their chord (odd `k`), so every
/// case clips filled arcs of both kinds, besides their outlines.
pub fn filled_object(arc: EllipseArc, k: usize) -> FilledArc {
    FilledArc::new(arc, if k.is_multiple_of(2) { ArcFill::Sector } else { ArcFill::Chord })
}

fn curve_window(rng: &mut Pcg64, kind: WindowKind) -> (Polygons, &'static str) {
    let frame = CURVE_FRAME;
    match kind {
        WindowKind::Rectangle => {
            let (hw, hh) = (rng.random_range(150.0..400.0), rng.random_range(150.0..400.0));
            let c = Point::new(rng.random_range(400.0..600.0), rng.random_range(400.0..600.0));
            (Polygons::from(Rect::new(c.x - hw, c.y - hh, c.x + hw, c.y + hh)), "rectangle")
        }
        WindowKind::Convex => (windows::convex_over(rng, &frame, false), "convex"),
        WindowKind::Any => {
            let n = rng.random_range(12..=60);
            let mut w = with_holes(rng, n, Point::new(500.0, 500.0), 380.0);
            if rng.random_bool(0.25) {
                // A second ring over the first: rings crossing each other, read even-odd.
                let c = Point::new(rng.random_range(350.0..650.0), rng.random_range(350.0..650.0));
                w.rings.push(super::shapes::star(rng, 8, c, 200.0, 150.0, 0.3));
                return (w, "crossing-rings");
            }
            (w, "concave-with-holes")
        }
    }
}

/// One object; `None` only if the drawn parameters were refused, which they are not by
/// construction (radii 5 to 600, centres within a few thousand of the origin).
fn object(rng: &mut Pcg64, circle: bool, window: &Rect) -> Option<EllipseArc> {
    let grow = 0.5 * window.extent();
    let long = 1000.0 * (0.005f64.ln() + rng.random::<f64>() * (0.6f64 / 0.005).ln()).exp();
    let (rx, ry, rotation) = if circle {
        (long, long, 0.0)
    } else {
        let short = long / rng.random_range(1.0..10.0);
        let rotation = if rng.random_bool(0.5) { 0.0 } else { rng.random_range(0.0..PI) };
        if rng.random_bool(0.5) { (long, short, rotation) } else { (short, long, rotation) }
    };
    let mut center = Point::new(
        rng.random_range(window.min.x - grow..window.max.x + grow),
        rng.random_range(window.min.y - grow..window.max.y + grow),
    );
    let placement: f64 = rng.random();
    if circle && placement < 0.1 {
        // Tangent to a side of the box, from either side.
        let side = rng.random_range(0..4);
        let out = if rng.random_bool(0.5) { 1.0 } else { -1.0 };
        match side {
            0 => center.x = window.min.x - out * rx,
            1 => center.x = window.max.x + out * rx,
            2 => center.y = window.min.y - out * ry,
            _ => center.y = window.max.y + out * ry,
        }
    } else if circle && placement < 0.15 {
        // Through a corner of the box.
        let corners =
            [window.min, window.max, Point::new(window.min.x, window.max.y), Point::new(window.max.x, window.min.y)];
        let k = corners[rng.random_range(0..4)];
        let a = rng.random_range(0.0..TAU);
        center = Point::new(k.x + rx * a.cos(), k.y + rx * a.sin());
    }
    let e = Ellipse::new(center, rx, ry, rotation).ok()?;
    if rng.random_bool(1.0 / 3.0) {
        let start = rng.random_range(0.0..TAU);
        let sweep = rng.random_range(0.05..TAU);
        EllipseArc::new(e, start, sweep).ok()
    } else {
        Some(EllipseArc::full(e))
    }
}
