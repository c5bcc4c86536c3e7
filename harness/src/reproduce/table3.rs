//! Measures Vatti's Table 3: per subject size and case, the clip and fill times of Method 1
//! (`vatti` trapezoids, trapezoid fill) and Method 2 (`sutherland-hodgman`, scanline fill).

use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

use clip_core::{BoolOp, PolygonClipper, Polygons, Trapezoid, WindowKind};
use clip_raster::{FrameBuffer, fill_polygons, fill_trapezoids};
use clip_sutherland_hodgman::SutherlandHodgman;
use clip_testkit::workload::{VATTI_EDGES, polygon_case_sized, vatti_window};
use clip_vatti::Vatti;
use serde_json::json;

use super::pixel_check::{FILL, agree};
use crate::cli_error::CliError;
use crate::measure::progress::bar;
use crate::measure::provenance::Provenance;
use crate::measure::raw::{Measurement, write_csv};
use crate::measure::timing::{iterations_for, per_call_ns, timed};
use crate::results_files::vatti_table3::{CSV, META, METHOD1, METHOD2, PIXELS_CSV, PixelRecord};

/// The workload name in the raw rows.
const WORKLOAD: &str = "vatti-t3";
/// A clip measurement repeats short clips back to back until it lasts about this long.
const CLIP_TARGET: Duration = Duration::from_micros(50);

/// How much to measure.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Seed of the subjects.
    pub seed: u64,
    /// Subjects per size ("several cases" in the paper); improvement factors are averaged over them.
    pub cases: usize,
    /// Timed rounds; each round times every case with both methods.
    pub repetitions: usize,
}

impl Settings {
    /// Quick: 5 cases x 100 rounds (about 10 s); `full`: the paper-scale 1000 rounds;
    /// `repetitions` overrides both.
    pub fn new(seed: u64, full: bool, repetitions: Option<usize>) -> Settings {
        let repetitions = repetitions.unwrap_or(if full { 1000 } else { 100 });
        Settings { seed, cases: 5, repetitions }
    }
}

/// One subject and both methods' agreed output.
struct Case {
    size: usize,
    index: usize,
    subject: Polygons,
    trapezoids: Vec<Trapezoid>,
    polygons: Polygons,
    checksum: u64,
    clip_iterations: [u32; 2],
}

/// Checks every case's pixels, times both methods in interleaved rounds and writes the raw CSV,
/// the pixel record and the sidecar into `out`.
pub fn measure(settings: &Settings, out: &Path) -> Result<(), CliError> {
    let window = vatti_window(WindowKind::Convex);
    let mut frames = [FrameBuffer::default(), FrameBuffer::default()];
    let (cases, pixels) = prepare_cases(settings, &window, &mut frames)?;

    let mut progress = bar(settings.repetitions, "Table 3: timing");
    let mut rows = Vec::with_capacity(settings.repetitions * cases.len() * 4);
    let [frame, _] = &mut frames;
    for repetition in 0..settings.repetitions {
        for (k, case) in cases.iter().enumerate() {
            // Alternate which method goes first, so neither always inherits a warm cache.
            let order = if (repetition + k) % 2 == 0 { [0, 1] } else { [1, 0] };
            for method in order {
                let (clip_ns, fill_ns) = time_method(method, case, &window, frame)?;
                let row = |phase: &str, time_ns: f64, iterations: u32| Measurement {
                    workload: WORKLOAD.to_owned(),
                    case: case.index.to_string(),
                    clipper: [METHOD1, METHOD2][method].to_owned(),
                    phase: phase.to_owned(),
                    size: case.size,
                    op: BoolOp::Intersection.name().to_owned(),
                    fill_rule: FILL.name().to_owned(),
                    repetition,
                    iterations,
                    time_ns,
                    correct: None,
                };
                rows.push(row("clip", clip_ns, case.clip_iterations[method]));
                rows.push(row("fill", fill_ns, 1));
            }
        }
        progress.inc();
    }
    progress.finish();

    write_csv(&out.join(CSV), &rows)?;
    write_csv(&out.join(PIXELS_CSV), &pixels)?;
    let parameters = json!({
        "sizes": VATTI_EDGES,
        "cases_per_size": settings.cases,
        "repetitions": settings.repetitions,
        "window": window_description(&window),
        "frame": "1280 x 1024, one byte per pixel",
        "method1": "vatti clip_trapezoids (intersection, even-odd) + clip_raster::fill_trapezoids",
        "method2": "sutherland-hodgman (intersection) + clip_raster::fill_polygons (even-odd)",
        "clip_target_ns": CLIP_TARGET.as_nanos() as u64,
    });
    let mut provenance = Provenance::now("reproduce vatti-table3", settings.seed, parameters);
    provenance.notes.push(format!(
        "Before timing, both methods were checked to light identical pixels on all {} cases (see {PIXELS_CSV}); \
         every timed fill was checksummed against that frame.",
        cases.len()
    ));
    provenance.write(&out.join(META))
}

/// The cases of every size, each checked to render identically with both methods, with the
/// number of back-to-back clip calls per measurement calibrated for each method.
fn prepare_cases(
    settings: &Settings,
    window: &Polygons,
    frames: &mut [FrameBuffer; 2],
) -> Result<(Vec<Case>, Vec<PixelRecord>), CliError> {
    let mut progress = bar(VATTI_EDGES.len() * settings.cases, "Table 3: checking pixels");
    let mut cases = Vec::new();
    let mut pixels = Vec::new();
    for size in VATTI_EDGES {
        for index in 0..settings.cases {
            let case = polygon_case_sized(WORKLOAD, settings.seed, index, size, WindowKind::Convex)
                .map_err(|e| CliError::failed(e.to_string()))?;
            let agreed = agree(&case.subject, window, (size, index), frames)?;
            let single = [
                timed(|| Vatti.clip_trapezoids(&case.subject, window, BoolOp::Intersection, FILL)).1,
                timed(|| SutherlandHodgman::default().clip(&case.subject, window, BoolOp::Intersection, FILL)).1,
            ];
            pixels.push(agreed.record);
            cases.push(Case {
                size,
                index,
                subject: case.subject,
                trapezoids: agreed.trapezoids,
                polygons: agreed.polygons,
                checksum: agreed.checksum,
                clip_iterations: single.map(|d| iterations_for(d, CLIP_TARGET)),
            });
            progress.inc();
        }
    }
    progress.finish();
    Ok((cases, pixels))
}

/// Times one method on one case: clip (calls back to back, per call) and fill (one call into a
/// frame cleared outside the timed region, then checksummed against the agreed frame).
fn time_method(method: usize, case: &Case, window: &Polygons, frame: &mut FrameBuffer) -> Result<(f64, f64), CliError> {
    let iterations = case.clip_iterations[method];
    let clip_ns = if method == 0 {
        per_call_ns(iterations, || Vatti.clip_trapezoids(black_box(&case.subject), window, BoolOp::Intersection, FILL))
    } else {
        per_call_ns(iterations, || {
            SutherlandHodgman::default().clip(black_box(&case.subject), window, BoolOp::Intersection, FILL)
        })
    };
    frame.clear();
    let (filled, took) = if method == 0 {
        timed(|| fill_trapezoids(frame, black_box(&case.trapezoids), 1))
    } else {
        timed(|| fill_polygons(frame, black_box(&case.polygons), FILL, 1))
    };
    filled.map_err(|e| CliError::failed(format!("Table 3 fill at {} edges: {e}", case.size)))?;
    if black_box(frame.checksum()) != case.checksum {
        return Err(CliError::failed(format!(
            "Table 3 at {} edges, case {}: a timed fill drew a different frame than the checked one",
            case.size, case.index
        )));
    }
    Ok((clip_ns, took.as_nanos() as f64))
}

/// The fixed window in words, for the sidecar and the tables.
pub fn window_description(window: &Polygons) -> String {
    let b = window.bounds();
    format!(
        "regular octagon (convex, {} vertices) of circumradius 400 centred at (640, 512), four sides axis-parallel, \
         bounding box [{:.1}, {:.1}] x [{:.1}, {:.1}]",
        window.vertex_count(),
        b.min.x,
        b.max.x,
        b.min.y,
        b.max.y
    )
}
