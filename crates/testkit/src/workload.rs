//! Seeded workload generators: every case is a pure function of (workload name, seed, index).

mod comb;
mod curves;
mod degenerate_lines;
mod extensions;
mod hard_cases;
mod large_lines;
mod maps;
mod near_coincident;
mod overlay_suite;
mod shapes;
mod text;
mod text_paragraph;
mod wang;
mod windows;
mod world_map;

pub use curves::{CURVE_FRAME, CURVE_WORKLOADS, CURVES_PER_CASE, CurveCase, curve_case, filled_object};
pub use extensions::MANY_SUBJECTS_CLIP_EDGES;
pub use hard_cases::{HardCase, hard_cases, invalid_inputs, mirrored};
pub use large_lines::{
    BEYOND_EDGES, LINES_LARGE_EDGES, beyond_window, lines_large_segments, lines_large_window, short_segments,
};
pub use maps::MAP_CASE_EDGES;
pub use shapes::convex_hull;
pub use text::{TEXT_CHARSET, TextCase, text_case};
pub use text_paragraph::{
    PARAGRAPH_LEADING, PARAGRAPH_LINES, PARAGRAPH_SIZE, PARAGRAPH_WINDOW_SIDES, paragraph_chars, paragraph_origin,
    paragraph_window,
};
pub use wang::{WANG_EDGES, WANG_SCREEN, WangSize, wang_box, wang_measure, wang_rectangle, wang_segments, wang_window};
pub use world_map::{Country, MapDataError, MapScale, WorldMap, parse_world_map, world_map};

use clip_core::{Point, Polygons, Rect, Ring, Segment, WindowKind};
use core::fmt;
use overlay_suite::SuiteTest;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use shapes::{checkerboard, edge_count, grid_ring, scribble, smooth, star};

/// The polygon workloads, by name.
pub const POLYGON_WORKLOADS: &[&str] = &[
    "vatti-t3",
    "star",
    "star-far",
    "scribble",
    "scribble-rect",
    "holes",
    "multi",
    "grid",
    "large",
    "spiky-box",
    "many-subjects",
    "near-coincident",
    "comb",
    "nested",
    "concentric",
    "spiral",
    "windows",
    "corrosion",
    "lines-net",
    "checkerboard",
    "not-overlap",
    "wind-mill",
    "maps",
];

/// The polygon workloads that stress a sweep (the last of [`POLYGON_WORKLOADS`]): many edges
/// span a level line at once, so a sweep that visits every active edge in every scanbeam goes
/// quadratic on them.
pub const SWEEP_WORKLOADS: &[&str] = {
    let all = POLYGON_WORKLOADS;
    all.split_at(all.len() - 11).1
};

/// How far `star-far` moves `star`'s cases: UTM-like magnitudes, where one ulp of a coordinate
/// (about 1.2e-7) is no longer small beside the 1e-9 relative area tolerance of a 1000-unit box.
pub const FAR_OFFSET: Point = Point::new(1.0e9, 1.0e9);

/// The line workloads, by name.
pub const LINE_WORKLOADS: &[&str] = &["wang-t4", "lines-degenerate", "lines-large"];

/// The text workloads, by name: strings, sizes, positions and windows for clip-text's strategies.
pub const TEXT_WORKLOADS: &[&str] = &["text"];

/// The subject sizes of Vatti's Table 3.
pub const VATTI_EDGES: [usize; 6] = [4, 10, 20, 40, 100, 200];

/// The frame Vatti's Table 3 polygons are fitted in: 1280 x 1024.
pub const VATTI_FRAME: Rect = Rect::new(0.0, 0.0, 1280.0, 1024.0);

/// The sizes `large` cycles through when no size is given.
pub const LARGE_EDGES: [usize; 4] = [1_000, 2_000, 5_000, 10_000];

/// A workload name that does not exist; its message lists the valid ones.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownWorkload {
    /// The name asked for.
    pub given: String,
    /// The names that exist (of the asked kind).
    pub valid: &'static [&'static str],
}

impl fmt::Display for UnknownWorkload {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "unknown workload '{}' (expected one of: {})", self.given, self.valid.join(", "))
    }
}

impl std::error::Error for UnknownWorkload {}

/// Why a polygon case could not be made: an unknown workload name, or (`maps`) a world map file
/// that could not be read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum WorkloadError {
    /// No polygon workload has this name.
    Unknown(UnknownWorkload),
    /// The world map the `maps` workload reads is missing or malformed.
    MapData(MapDataError),
}

impl fmt::Display for WorkloadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WorkloadError::Unknown(e) => e.fmt(f),
            WorkloadError::MapData(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for WorkloadError {}

impl From<UnknownWorkload> for WorkloadError {
    fn from(e: UnknownWorkload) -> WorkloadError {
        WorkloadError::Unknown(e)
    }
}

impl From<MapDataError> for WorkloadError {
    fn from(e: MapDataError) -> WorkloadError {
        WorkloadError::MapData(e)
    }
}

/// One polygon case: a subject and a clip operand to run under every op and fill rule.
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonCase {
    /// The workload's name.
    pub workload: &'static str,
    /// The run's seed.
    pub seed: u64,
    /// The case's index within the run.
    pub index: usize,
    /// The subject operand.
    pub subject: Polygons,
    /// The clip operand.
    pub clip: Polygons,
    /// What the case is, in words (`"star subject 37 edges vs star clip 12 edges"`).
    pub description: String,
}

/// One line case: a window and a batch of segments to clip against it.
#[derive(Clone, Debug, PartialEq)]
pub struct LineCase {
    /// The workload's name.
    pub workload: &'static str,
    /// The run's seed.
    pub seed: u64,
    /// The case's index within the run.
    pub index: usize,
    /// The window, read under even-odd.
    pub window: Polygons,
    /// The segments to clip.
    pub segments: Vec<Segment>,
    /// The window's edge count.
    pub window_edges: usize,
    /// What the case is, in words.
    pub description: String,
}

/// A generator seeded from a hash of `(stream, seed, index)`, so a case never depends on which
/// cases were made before it, on iteration order or on thread count.
pub(crate) fn stream_rng(stream: &str, seed: u64, index: u64) -> Pcg64 {
    // FNV-1a over the bytes, then a splitmix64 finaliser: stable across Rust versions.
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in stream.bytes().chain(seed.to_le_bytes()).chain(index.to_le_bytes()) {
        h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
    }
    h = (h ^ (h >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h = (h ^ (h >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    Pcg64::seed_from_u64(h ^ (h >> 31))
}

fn polygon_name(workload: &str) -> Result<&'static str, UnknownWorkload> {
    POLYGON_WORKLOADS
        .iter()
        .find(|&&w| w == workload)
        .copied()
        .ok_or_else(|| UnknownWorkload { given: workload.to_owned(), valid: POLYGON_WORKLOADS })
}

/// Case `index` of a polygon workload. `window` constrains the clip operand: `Any` (the
/// workload's own clip), `Convex` (a random convex polygon of 4-16 vertices overlapping the
/// subject) or `Rectangle` (an axis-aligned rectangle overlapping the subject); on `grid` these
/// have integer vertices. `vatti-t3`'s clip is always its fixed convex window, a rectangle when
/// `Rectangle` is asked (see [`vatti_window`]).
///
/// Sizes: `vatti-t3` cycles through [`VATTI_EDGES`] by index; `large` alternates smooth blobs and
/// checkerboards over [`LARGE_EDGES`]; `spiky-box` is a spiky star against a box of about 1% of
/// its area inside it; `scribble-rect` is a self-crossing scribble against an axis-aligned
/// rectangle overlapping it (one in four clockwise), so the clippers' rectangle paths are checked
/// on any subject under every fill rule; `many-subjects` is a subject of 4-40 edges over one clip polygon of
/// [`MANY_SUBJECTS_CLIP_EDGES`] edges that is the same for every index of a seed (a sized case
/// sizes that clip); `near-coincident` is a star with notches and spikes narrower than 1e-12 of
/// its extent against a copy turned by 1e-16 to 1e-6 rad, shifted by a few ulps, or tracing its
/// edges a few ulps off (index mod 3; see its module); the others draw 6-200 edges per operand,
/// log-uniformly.
///
/// The workloads that stress a sweep (a sized case gives their edge count over both operands):
/// `comb` (even indices a comb against a comb shifted half a tooth, odd ones a comb against a
/// box of 1% of its area over its teeth), i_overlay's performance suite (`nested`, `concentric`,
/// `spiral`, `windows`, `corrosion`, `lines-net`, `checkerboard`, `not-overlap`, `wind-mill`),
/// drawing 6-200 edges in all; and `maps`, real borders from `testdata/world` (index mod 3: a
/// dissolve, tiles, a country minus its neighbours), here around one country at 1:110m with at
/// most [`MAP_CASE_EDGES`] edges, sized over the whole map at the [`MapScale`] nearest in edges.
pub fn polygon_case(workload: &str, seed: u64, index: usize, window: WindowKind) -> Result<PolygonCase, WorkloadError> {
    let name = polygon_name(workload)?;
    let edges = match name {
        "vatti-t3" => VATTI_EDGES[index % VATTI_EDGES.len()],
        "large" => LARGE_EDGES[(index / 2) % LARGE_EDGES.len()],
        "many-subjects" => MANY_SUBJECTS_CLIP_EDGES,
        _ => 0,
    };
    make_polygon_case(name, seed, index, (edges > 0).then_some(edges), window)
}

/// A case of a given size: `edges` for the subject, and for the clip where the workload sizes
/// it (all but `vatti-t3`, whose window is fixed, and windows constrained to convex or
/// rectangle). For benches and `reproduce`: `vatti-t3` at 4..200 edges, `large` at 10^3..10^6.
/// For `comb`, i_overlay's suite and `maps`, `edges` counts both operands (their clip is not the
/// subject's size): the generator's count nearest to it, the map scale nearest to it.
pub fn polygon_case_sized(
    workload: &str,
    seed: u64,
    index: usize,
    edges: usize,
    window: WindowKind,
) -> Result<PolygonCase, WorkloadError> {
    make_polygon_case(polygon_name(workload)?, seed, index, Some(edges.max(3)), window)
}

fn make_polygon_case(
    name: &'static str,
    seed: u64,
    index: usize,
    edges: Option<usize>,
    window: WindowKind,
) -> Result<PolygonCase, WorkloadError> {
    let mut rng = stream_rng(name, seed, index as u64);
    let size = |rng: &mut Pcg64| edges.unwrap_or_else(|| edge_count(rng));
    let (subject, own_clip, what) = match (name, SuiteTest::of(name)) {
        ("vatti-t3", _) => {
            let n = size(&mut rng);
            let c = VATTI_FRAME.max * 0.5;
            let subject =
                Polygons::from(star(&mut rng, n, c, 0.48 * VATTI_FRAME.width(), 0.48 * VATTI_FRAME.height(), 0.2));
            let clip = vatti_window(window);
            let what = format!("vatti-t3 star subject {n} edges vs fixed {} window", window_word(window));
            return Ok(PolygonCase { workload: name, seed, index, subject, clip, description: what });
        }
        ("star" | "star-far", _) => {
            let (n, m) = (size(&mut rng), size(&mut rng));
            let far = if name == "star-far" { FAR_OFFSET } else { Point::ZERO };
            let s = star(&mut rng, n, Point::new(500.0, 500.0) + far, 400.0, 400.0, 0.2);
            let o = offset_center(&mut rng);
            let c = star(&mut rng, m, o + far, 350.0, 350.0, 0.2);
            (s.into(), c.into(), format!("{name} subject {n} edges vs star clip {m} edges"))
        }
        ("spiky-box", _) => {
            let n = size(&mut rng);
            let (s, c) = extensions::spiky_box(&mut rng, n);
            (s, c, format!("spiky-box star subject {n} edges vs a box of 1% of its area inside it"))
        }
        ("many-subjects", _) => {
            let m = size(&mut rng);
            let s = extensions::many_subjects_subject(&mut rng, index);
            let what = format!("many-subjects subject {} edges over a fixed star clip of {m} edges", s.len());
            (s.into(), extensions::many_subjects_clip(seed, m).into(), what)
        }
        ("near-coincident", _) => {
            let n = size(&mut rng);
            near_coincident::near_coincident(&mut rng, index, n)
        }
        ("scribble", _) => {
            let (n, m) = (size(&mut rng), size(&mut rng));
            let s = scribble(&mut rng, n, Rect::new(100.0, 100.0, 900.0, 900.0));
            let o = offset_center(&mut rng);
            let c = scribble(&mut rng, m, Rect::new(o.x - 350.0, o.y - 350.0, o.x + 350.0, o.y + 350.0));
            (s.into(), c.into(), format!("scribble subject {n} edges vs scribble clip {m} edges"))
        }
        ("scribble-rect", _) => {
            let n = size(&mut rng);
            let s = scribble(&mut rng, n, Rect::new(100.0, 100.0, 900.0, 900.0));
            let r = windows::rectangle_over(&mut rng, &s.bounds(), false);
            let cw = rng.random_bool(0.25);
            let c = if cw { Polygons::new(r.rings.iter().map(Ring::reversed).collect()) } else { r };
            let way = if cw { "clockwise" } else { "counter-clockwise" };
            (s.into(), c, format!("scribble-rect subject {n} edges vs a {way} rectangle"))
        }
        ("holes", _) => {
            let (n, m) = (size(&mut rng), size(&mut rng));
            let s = with_holes(&mut rng, n, Point::new(500.0, 500.0), 420.0);
            let o = offset_center(&mut rng);
            let c = with_holes(&mut rng, m, o, 360.0);
            let what = format!(
                "holes subject {n} edges ({} rings) vs holes clip {m} edges ({} rings)",
                s.rings.len(),
                c.rings.len()
            );
            (s, c, what)
        }
        ("multi", _) => {
            let (n, m) = (size(&mut rng), size(&mut rng));
            let s = several_parts(&mut rng, n);
            let c = several_parts(&mut rng, m);
            let what = format!(
                "multi subject {n} edges ({} parts) vs multi clip {m} edges ({} parts)",
                s.rings.len(),
                c.rings.len()
            );
            (s, c, what)
        }
        ("comb", _) => {
            let total = size(&mut rng);
            if index.is_multiple_of(2) {
                let teeth = (total / 8).max(1);
                let (s, c) = comb::comb_pair(&mut rng, teeth);
                (s, c, format!("comb of {teeth} teeth ({} edges) vs comb shifted half a tooth", 4 * teeth))
            } else {
                let teeth = (total.saturating_sub(4) / 4).max(1);
                let (s, c) = comb::comb_box(&mut rng, teeth);
                (s, c, format!("comb of {teeth} teeth ({} edges) vs a box of 1% of its area", 4 * teeth))
            }
        }
        ("maps", _) => match edges {
            Some(e) => maps::whole_map(world_map(MapScale::nearest(e))?, index),
            None => maps::around_a_country(world_map(MapScale::Small)?, &mut rng, index),
        },
        (_, Some(test)) => {
            let n = test.count_for(size(&mut rng));
            let (s, c) = test.operands(n);
            let what = format!(
                "{name} (i_overlay's suite) at n = {n}: subject {} edges in {} rings, clip {} edges in {} rings",
                s.vertex_count(),
                s.rings.len(),
                c.vertex_count(),
                c.rings.len()
            );
            (s, c, what)
        }
        ("grid", _) => {
            let (n, m) = (size(&mut rng), size(&mut rng));
            let g = (4 + n.max(m) / 8).min(24) as i32;
            let s = grid_rings(&mut rng, n, g);
            let c = grid_rings(&mut rng, m, g);
            let what = format!("grid [0,{g}]² subject {n} edges vs grid clip {m} edges");
            (s, c, what)
        }
        _ => {
            // "large": smooth blobs on even indices, checkerboards on odd ones.
            let n = size(&mut rng);
            if index.is_multiple_of(2) {
                let s = smooth(&mut rng, n, Point::new(500.0, 500.0), 400.0);
                let c = smooth(&mut rng, n, Point::new(650.0, 600.0), 350.0);
                (s.into(), c.into(), format!("large smooth subject {n} edges vs smooth clip {n} edges"))
            } else {
                let k = ((n as f64 / 2.0).sqrt().round() as usize).max(1);
                let cell = 1000.0 / k as f64;
                let s = checkerboard(k, cell, Point::ZERO);
                let c = checkerboard(k, cell, Point::new(cell * 0.5, cell / 3.0));
                let what = format!("large checkerboard {k}x{k} ({} squares) vs shifted checkerboard", s.len());
                (s.into(), c.into(), what)
            }
        }
    };
    let integer = name == "grid" || name == "comb" || SuiteTest::of(name).is_some_and(SuiteTest::on_integers);
    let bounds = subject.bounds();
    let (clip, what) = match window {
        WindowKind::Any => (own_clip, what),
        WindowKind::Convex => {
            let c = windows::convex_over(&mut rng, &bounds, integer);
            let what = format!("{} (clip replaced by a convex window of {} edges)", what, c.vertex_count());
            (c, what)
        }
        WindowKind::Rectangle => {
            (windows::rectangle_over(&mut rng, &bounds, integer), format!("{what} (clip replaced by a rectangle)"))
        }
    };
    Ok(PolygonCase { workload: name, seed, index, subject, clip, description: what })
}

fn window_word(window: WindowKind) -> &'static str {
    if window == WindowKind::Rectangle { "rectangle" } else { "octagon" }
}

/// `vatti-t3`'s fixed window: the regular octagon of circumradius 400 centred in the 1280x1024
/// frame, turned 22.5° so four of its sides are axis-parallel; or, when `Rectangle` is asked, the
/// rectangle [320, 960] x [256, 768] (the frame's central half).
pub fn vatti_window(window: WindowKind) -> Polygons {
    if window == WindowKind::Rectangle {
        return Polygons::from(Rect::new(320.0, 256.0, 960.0, 768.0));
    }
    let c = VATTI_FRAME.max * 0.5;
    let octagon = (0..8)
        .map(|k| {
            let a = std::f64::consts::PI * (0.125 + 0.25 * f64::from(k));
            Point::new(c.x + 400.0 * a.cos(), c.y + 400.0 * a.sin())
        })
        .collect();
    Polygons::from(Ring::new(octagon))
}

/// A clip centre offset from the subject's (500, 500) by up to 250 in each axis.
fn offset_center(rng: &mut Pcg64) -> Point {
    Point::new(500.0 + rng.random_range(-250.0..250.0), 500.0 + rng.random_range(-250.0..250.0))
}

/// A counter-clockwise star outer with 1-3 clockwise star holes, `n` edges in all (holes take
/// about half). The holes sit around the centre, inside the outer's inner radius.
fn with_holes(rng: &mut Pcg64, n: usize, center: Point, radius: f64) -> Polygons {
    let n = n.max(6);
    let hole_edges = n / 2;
    let k = rng.random_range(1..=(hole_edges / 3).clamp(1, 3));
    let mut rings = vec![star(rng, n - hole_edges, center, radius, radius, 0.6)];
    let phase = rng.random::<f64>() * std::f64::consts::TAU;
    for i in 0..k {
        let m = if i + 1 == k { hole_edges - (k - 1) * (hole_edges / k) } else { hole_edges / k };
        let (d, r) = if k == 1 { (0.0, 0.45 * radius) } else { (0.3 * radius, 0.25 * radius) };
        let a = phase + std::f64::consts::TAU * i as f64 / k as f64;
        let c = Point::new(center.x + d * a.cos(), center.y + d * a.sin());
        rings.push(star(rng, m, c, r, r, 0.4).reversed());
    }
    Polygons::new(rings)
}

/// 2-5 star parts at random places in [0, 1000]², `n` edges in all; they may overlap, and one
/// in five runs clockwise (so the fill rules disagree).
fn several_parts(rng: &mut Pcg64, n: usize) -> Polygons {
    let n = n.max(6);
    let parts = rng.random_range(2..=(n / 3).clamp(2, 5));
    let rings = (0..parts)
        .map(|i| {
            let m = if i + 1 == parts { n - (parts - 1) * (n / parts) } else { n / parts };
            let c = Point::new(rng.random_range(150.0..850.0), rng.random_range(150.0..850.0));
            let r = rng.random_range(80.0..250.0);
            let s = star(rng, m, c, r, r, 0.3);
            if rng.random_bool(0.2) { s.reversed() } else { s }
        })
        .collect();
    Polygons::new(rings)
}

/// 1-3 grid rings on `[0, g]²` with `n` edges in all (at least 3 per ring).
fn grid_rings(rng: &mut Pcg64, n: usize, g: i32) -> Polygons {
    let n = n.max(6);
    let parts = rng.random_range(1..=(n / 4).clamp(1, 3));
    Polygons::new(
        (0..parts)
            .map(|i| {
                let m = if i + 1 == parts { n - (parts - 1) * (n / parts) } else { n / parts };
                grid_ring(rng, m, g)
            })
            .collect(),
    )
}

/// Case `index` of a line workload with `segments` segments.
///
/// `wang-t4`: the window has [`WANG_EDGES`]`[index % 6]` edges, size [`WangSize::W1`] for even
/// `index / 6` and [`WangSize::W2`] for odd; a star-shaped concave window for `Any`, a convex one
/// for `Convex`, its MEB for `Rectangle`; the segments are [`wang_segments`]. The window's shape
/// depends on `seed` only, so the six edge counts and two sizes of one seed make one Table 4.
///
/// `lines-degenerate`: a window on even integer coordinates (concave for `Any`) and segments
/// through its vertices, along its edges, ending on its boundary, axis-parallel, zero-length.
///
/// `lines-large`: a concave window with holes of [`LINES_LARGE_EDGES`]`[index % 4]` edges (its
/// convex hull for `Convex`, its bounding box for `Rectangle`) and [`lines_large_segments`].
pub fn line_case(
    workload: &str,
    seed: u64,
    index: usize,
    window: WindowKind,
    segments: usize,
) -> Result<LineCase, UnknownWorkload> {
    match workload {
        "wang-t4" => {
            let edges = WANG_EDGES[index % WANG_EDGES.len()];
            let size = WangSize::ALL[(index / WANG_EDGES.len()) % 2];
            let w = match window {
                WindowKind::Rectangle => wang_rectangle(edges, size),
                kind => wang_window(edges, size, seed, kind == WindowKind::Convex),
            };
            let segs = wang_segments(segments, seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ index as u64);
            let (w1, w2) = wang_measure(&w);
            let description = format!(
                "wang-t4 {} window {} edges at size {} (W1 = {w1:.2}, W2 = {w2:.1}), {segments} random segments",
                shape_word(window),
                w.vertex_count(),
                size.name()
            );
            Ok(LineCase {
                workload: "wang-t4",
                seed,
                index,
                window_edges: w.vertex_count(),
                window: w,
                segments: segs,
                description,
            })
        }
        "lines-degenerate" => {
            let mut rng = stream_rng("lines-degenerate", seed, index as u64);
            let w = degenerate_lines::degenerate_window(&mut rng, window);
            let segs = degenerate_lines::degenerate_segments(&mut rng, &w, segments);
            let description = format!(
                "lines-degenerate {} window {} edges, {segments} segments through vertices, along edges, ending on the boundary",
                shape_word(window),
                w.vertex_count()
            );
            Ok(LineCase {
                workload: "lines-degenerate",
                seed,
                index,
                window_edges: w.vertex_count(),
                window: w,
                segments: segs,
                description,
            })
        }
        "lines-large" => {
            let mut rng = stream_rng("lines-large", seed, index as u64);
            let edges = LINES_LARGE_EDGES[index % LINES_LARGE_EDGES.len()];
            let concave = lines_large_window(&mut rng, edges);
            let w = match window {
                WindowKind::Any => concave,
                WindowKind::Convex => Polygons::from(Ring::new(shapes::convex_hull(&concave.rings[0].points))),
                WindowKind::Rectangle => Polygons::from(concave.bounds()),
            };
            let segs = lines_large_segments(&mut rng, &w, segments);
            let description = format!(
                "lines-large {} window {} edges in {} rings, {segments} long, short and incident segments",
                shape_word(window),
                w.vertex_count(),
                w.rings.len()
            );
            Ok(LineCase {
                workload: "lines-large",
                seed,
                index,
                window_edges: w.vertex_count(),
                window: w,
                segments: segs,
                description,
            })
        }
        _ => Err(UnknownWorkload { given: workload.to_owned(), valid: LINE_WORKLOADS }),
    }
}

fn shape_word(window: WindowKind) -> &'static str {
    match window {
        WindowKind::Any => "concave",
        WindowKind::Convex => "convex",
        WindowKind::Rectangle => "rectangle",
    }
}
