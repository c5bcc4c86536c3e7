//! Measures the beyond-the-paper table: ns per segment against windows of 6 to 10^4 edges (lobed
//! concave and convex; long random segments as in `wang-t4` and short road-like ones) for the
//! linear clippers, the indexed one and geo, each clipper's preparation time, and 10^6 segments
//! against a 10^4-edge window with holes on every core.

use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

use clip_core::{LineClipper, Polygons, PreparedWindow, Segment, VisiblePiece, WindowKind};
use clip_cyrus_beck::{CyrusBeck, Liu};
use clip_line_index::{LineIndex, PreparedLineIndex};
use clip_peers::{Clipper2OpenLines, GeoLineClipper, OPEN_LINES_NAME};
use clip_testkit::workload::{BEYOND_EDGES, beyond_window, line_case, short_segments, wang_segments};
use clip_virtual_box::VirtualBox;
use serde_json::json;

use crate::cli_error::CliError;
use crate::measure::cpu_time::process_cpu_ns;
use crate::measure::parallel::clip_parallel;
use crate::measure::progress::bar;
use crate::measure::provenance::Provenance;
use crate::measure::raw::{Measurement, write_csv};
use crate::measure::timing::{median, timed};
use crate::results_files::beyond_paper::{CSV, LARGE_CSV, LargeRecord, META, PREPARE_CSV, PrepareRecord};

/// The workload name in the raw rows.
const WORKLOAD: &str = "beyond-paper";
/// The peer, far slower per segment: fewer rounds and segments.
const GEO: &str = "geo";
/// Short segments are at most this fraction of the window's width.
const SHORT: f64 = 0.02;

/// How much to measure.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Seed of the windows and segments.
    pub seed: u64,
    /// Segments per batch.
    pub segments: usize,
    /// Timed rounds; each clips every batch once per window and clipper.
    pub repetitions: usize,
    /// Rounds geo takes part in, and the segments of its batches.
    pub geo_repetitions: usize,
    /// Segments of geo's batches (the first of each batch).
    pub geo_segments: usize,
    /// Segments of the many-segments point.
    pub large_segments: usize,
    /// Rounds of the many-segments point for the indexed clipper (Liu runs once).
    pub large_repetitions: usize,
}

impl Settings {
    /// Quick: 15 rounds; `full`: 100; `repetitions` overrides both. geo takes part in 2 rounds
    /// (5 with `full`) on 1000 segments.
    pub fn new(seed: u64, full: bool, repetitions: Option<usize>) -> Settings {
        let repetitions = repetitions.unwrap_or(if full { 100 } else { 15 });
        Settings {
            seed,
            segments: 10_000,
            repetitions,
            geo_repetitions: repetitions.min(if full { 5 } else { 2 }),
            geo_segments: 1_000,
            large_segments: 1_000_000,
            large_repetitions: if full { 5 } else { 3 },
        }
    }
}

/// The clippers of the table, in column order: adding one is a line here.
fn clippers() -> Vec<Box<dyn LineClipper>> {
    vec![
        Box::new(Liu),
        Box::new(VirtualBox::NEW1),
        Box::new(VirtualBox::NEW2),
        Box::new(LineIndex),
        Box::new(CyrusBeck),
        Box::new(GeoLineClipper),
        Box::new(Clipper2OpenLines),
    ]
}

/// Peers that clip one segment per call (geo's `BooleanOps::clip`, a `Clipper64::Execute` per
/// segment): they run on the first segments of a batch, in the first rounds only.
fn per_segment_call(name: &str) -> bool {
    name == GEO || name == OPEN_LINES_NAME
}

/// One window, its two segment batches, and every clipper that takes it, prepared.
struct Window {
    shape: &'static str,
    edges: usize,
    short: Vec<Segment>,
    prepared: Vec<(&'static str, Box<dyn PreparedWindow>)>,
}

/// Prepares the windows (timing each preparation), times every clipper on both batches in
/// interleaved rounds, runs the many-segments point, and writes the raw files into `out`.
pub fn measure(settings: &Settings, out: &Path) -> Result<(), CliError> {
    let long = wang_segments(settings.segments, settings.seed);
    let (windows, prepare_records) = prepare_windows(settings)?;

    let mut progress = bar(settings.repetitions, "beyond the paper: timing");
    let mut rows = Vec::new();
    let mut pieces: Vec<VisiblePiece> = Vec::with_capacity(settings.segments * 4);
    for repetition in 0..settings.repetitions {
        for window in &windows {
            for (set, segments) in [("long", &long), ("short", &window.short)] {
                let n = window.prepared.len();
                for j in 0..n {
                    let (name, prepared) = &window.prepared[(j + repetition) % n];
                    let batch = if per_segment_call(name) {
                        if repetition >= settings.geo_repetitions {
                            continue;
                        }
                        &segments[..settings.geo_segments.min(segments.len())]
                    } else {
                        &segments[..]
                    };
                    pieces.clear();
                    let (result, took) = timed(|| prepared.clip_batch(black_box(batch), &mut pieces));
                    result.map_err(|e| {
                        CliError::failed(format!("beyond-paper: {name} on {} {}: {e}", window.shape, window.edges))
                    })?;
                    black_box(pieces.len());
                    rows.push(Measurement {
                        workload: WORKLOAD.to_owned(),
                        case: format!("{}-{set}", window.shape),
                        clipper: (*name).to_owned(),
                        phase: "clip".to_owned(),
                        size: window.edges,
                        op: "lines".to_owned(),
                        fill_rule: "even-odd".to_owned(),
                        repetition,
                        iterations: batch.len() as u32,
                        time_ns: took.as_nanos() as f64 / batch.len() as f64,
                        correct: None,
                    });
                }
            }
        }
        progress.inc();
    }
    progress.finish();
    let (large, large_notes) = many_segments(settings)?;

    write_csv(&out.join(CSV), &rows)?;
    write_csv(&out.join(PREPARE_CSV), &prepare_records)?;
    write_csv(&out.join(LARGE_CSV), &large)?;
    let parameters = json!({
        "window_edges": BEYOND_EDGES,
        "segments_per_batch": settings.segments,
        "long_segments": "endpoints uniform in the 800 x 600 screen, as in wang-t4 (clip_testkit::workload::wang_segments)",
        "short_segments": "midpoints uniform in the window's bounding box, length uniform up to 2% of its width \
                           (clip_testkit::workload::short_segments)",
        "windows": "lobed concave (7 petals) and convex, bounding box sized like Table 4's second size row \
                    (W1 = 4, W2 = 80) and centred on the screen (clip_testkit::workload::beyond_window)",
        "repetitions": settings.repetitions,
        "geo_repetitions": settings.geo_repetitions,
        "geo_segments": settings.geo_segments,
        "large_segments": settings.large_segments,
        "large_window": "lines-large case 3: 10^4 edges, a lobed outer ring with lobed holes",
        "large_repetitions": settings.large_repetitions,
        "threads": rayon::current_num_threads(),
        "clippers": clippers().iter().map(|c| c.name()).collect::<Vec<_>>(),
    });
    let mut provenance = Provenance::now("reproduce beyond-paper", settings.seed, parameters);
    provenance.notes.push(format!(
        "geo and Clipper2's open-path clipping (`clipper2-open`) clip one segment per call and take part in the first {} \
         rounds, on the first {} segments of each batch.",
        settings.geo_repetitions, settings.geo_segments
    ));
    provenance.notes.extend(large_notes);
    provenance.write(&out.join(META))
}

/// Every window with its short segments and prepared clippers, and how long each preparation took.
fn prepare_windows(settings: &Settings) -> Result<(Vec<Window>, Vec<PrepareRecord>), CliError> {
    let clippers = clippers();
    let mut windows = Vec::new();
    let mut records = Vec::new();
    for (shape, convex) in [("concave", false), ("convex", true)] {
        for edges in BEYOND_EDGES {
            let polygons = beyond_window(edges, settings.seed, convex);
            let b = polygons.bounds();
            let short = short_segments(settings.segments, settings.seed, &b, SHORT * b.width());
            let mut prepared = Vec::new();
            for c in clippers.iter().filter(|c| c.capabilities().window.accepts(&polygons)) {
                let fail = |e: clip_core::ClipError| {
                    CliError::failed(format!("beyond-paper: {} refused the {shape} {edges}-edge window: {e}", c.name()))
                };
                let times: Vec<f64> =
                    (0..7).map(|_| timed(|| c.prepare(black_box(&polygons)).map(drop)).1.as_nanos() as f64).collect();
                let memory_bytes = (c.name() == LineIndex.name())
                    .then(|| PreparedLineIndex::new(&polygons).map(|p| p.memory_bytes()))
                    .transpose()
                    .map_err(fail)?;
                records.push(PrepareRecord {
                    shape: shape.to_owned(),
                    edges,
                    clipper: c.name().to_owned(),
                    prepare_ns: median(&times),
                    memory_bytes,
                });
                prepared.push((c.name(), c.prepare(&polygons).map_err(fail)?));
            }
            windows.push(Window { shape, edges, short, prepared });
        }
    }
    Ok((windows, records))
}

/// 10^6 segments against `lines-large`'s 10^4-edge window with holes: the indexed clipper on one
/// thread and on every core (checked to write the same pieces in the same order), and Liu on
/// every core once, for the ratio.
fn many_segments(settings: &Settings) -> Result<(Vec<LargeRecord>, Vec<String>), CliError> {
    let case = line_case("lines-large", settings.seed, 3, WindowKind::Any, settings.large_segments)
        .map_err(|e| CliError::failed(e.to_string()))?;
    let window: &Polygons = &case.window;
    let segments = &case.segments;
    let threads = rayon::current_num_threads();
    let fail =
        |name: &str, e: clip_core::ClipError| CliError::failed(format!("beyond-paper: {name} on lines-large: {e}"));
    let mut records = Vec::new();
    let record =
        |clipper: &str, threads: usize, repetition: usize, (seconds, cpu_seconds), pieces: usize| LargeRecord {
            clipper: clipper.to_owned(),
            threads,
            segments: segments.len(),
            edges: case.window_edges,
            rings: window.rings.len(),
            repetition,
            seconds,
            cpu_seconds,
            pieces,
        };
    let indexed = LineIndex.prepare(window).map_err(|e| fail("indexed", e))?;
    let mut one = Vec::with_capacity(segments.len());
    let mut many = Vec::with_capacity(segments.len());
    let mut progress = bar(2 * settings.large_repetitions + 1, "beyond the paper: 10^6 segments");
    for repetition in 0..settings.large_repetitions {
        one.clear();
        let start = Clock::start();
        indexed.clip_batch(segments, &mut one).map_err(|e| fail("indexed", e))?;
        records.push(record("indexed", 1, repetition, start.read(), one.len()));
        progress.inc();
        many.clear();
        let start = Clock::start();
        clip_parallel(indexed.as_ref(), segments, &mut many).map_err(|e| fail("indexed", e))?;
        records.push(record("indexed", threads, repetition, start.read(), many.len()));
        progress.inc();
        if one != many {
            return Err(CliError::failed("beyond-paper: the parallel clip wrote other pieces than one thread"));
        }
    }
    let liu = Liu.prepare(window).map_err(|e| fail("liu", e))?;
    let mut by_liu = Vec::with_capacity(segments.len());
    let start = Clock::start();
    clip_parallel(liu.as_ref(), segments, &mut by_liu).map_err(|e| fail("liu", e))?;
    records.push(record("liu", threads, 0, start.read(), by_liu.len()));
    progress.inc();
    progress.finish();
    let same_count = by_liu.len() == one.len() && by_liu.iter().zip(&one).all(|(l, o)| l.segment == o.segment);
    let notes = vec![format!(
        "10^6 segments: the {threads}-thread clip wrote the same pieces in the same order as one thread in every round; \
         Liu wrote {} pieces and the indexed clipper {} ({}).",
        by_liu.len(),
        one.len(),
        if same_count { "on the same segments" } else { "NOT on the same segments" }
    )];
    Ok((records, notes))
}

/// Wall clock and process CPU time from one moment on.
struct Clock {
    wall: Instant,
    cpu_ns: Option<u64>,
}

impl Clock {
    fn start() -> Clock {
        Clock { cpu_ns: process_cpu_ns(), wall: Instant::now() }
    }

    /// Wall-clock seconds and CPU seconds since the start.
    fn read(&self) -> (f64, Option<f64>) {
        let wall = self.wall.elapsed().as_secs_f64();
        let cpu = self.cpu_ns.zip(process_cpu_ns()).map(|(a, b)| b.saturating_sub(a) as f64 / 1e9);
        (wall, cpu)
    }
}
