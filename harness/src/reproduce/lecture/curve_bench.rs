//! What the lecture's preliminary tests save: circles and ellipses of the `circles` and
//! `ellipses` workloads, binned by radius, clipped against a rectangle and a concave window with
//! holes by the curve clipper with the tests on and off, and by the polygon route (flatten, then
//! Vatti or geo); plus how many objects each test settled.

use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

use clip_core::{BoolOp, Ellipse, EllipseArc, FillRule, PolygonClipper, Polygons, WindowKind};
use clip_curve::{CurveClipper, PreparedCurveWindow, Stage, flatten_ellipse, flattening_area_bound};
use clip_oracle::polygon::GEO_TOLERANCE;
use clip_peers::GeoClipper;
use clip_testkit::workload::{CURVE_WORKLOADS, CURVES_PER_CASE, curve_case};
use clip_vatti::Vatti;
use serde_json::json;

use crate::cli_error::CliError;
use crate::measure::progress::bar;
use crate::measure::provenance::Provenance;
use crate::measure::raw::write_csv;
use crate::measure::timing::{iterations_for, per_call_ns, timed};
use crate::results_files::lecture_curves::{
    CSV, CurveStageRecord, CurveTiming, FLATTEN_GEO, FLATTEN_VATTI, META, STAGES_CSV, WITH_TESTS, WITHOUT_TESTS,
};

/// Long-radius bins (the workloads draw 5 to 600 in a 1000 x 1000 frame; windows are 300 to 800
/// wide).
pub const RADIUS_BINS: [(f64, f64); 5] = [(5.0, 15.0), (15.0, 40.0), (40.0, 100.0), (100.0, 250.0), (250.0, 600.0)];

/// The polygon route's flattening tolerance, relative to the long radius (about 70 chords per
/// circle, area within 0.2% of the exact).
pub const ROUTE_TOLERANCE: f64 = 1e-3;

/// How long one timed measurement should last: short batches are repeated back to back.
const TARGET: Duration = Duration::from_millis(2);

/// How much to measure.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Seed of the cases.
    pub seed: u64,
    /// Generated cases per workload and window (each with [`CURVES_PER_CASE`] objects).
    pub cases: usize,
    /// Timed rounds.
    pub repetitions: usize,
    /// Rounds the geo route takes part in (it is far slower).
    pub geo_repetitions: usize,
}

impl Settings {
    /// Quick: 15 rounds over 40 cases; `full`: 100 rounds; `repetitions` overrides both. The geo
    /// route runs in the first 3 rounds (10 with `full`).
    pub fn new(seed: u64, full: bool, repetitions: Option<usize>) -> Settings {
        let repetitions = repetitions.unwrap_or(if full { 100 } else { 15 });
        Settings { seed, cases: 40, repetitions, geo_repetitions: repetitions.min(if full { 10 } else { 3 }) }
    }
}

/// The methods timed, with their phase: the clipper's outline and filled clipping with the tests
/// on and off, and the two polygon routes (filled only).
const METHODS: [(&str, &str); 6] = [
    (WITH_TESTS, "outline"),
    (WITHOUT_TESTS, "outline"),
    (WITH_TESTS, "filled"),
    (WITHOUT_TESTS, "filled"),
    (FLATTEN_VATTI, "filled"),
    (FLATTEN_GEO, "filled"),
];

/// The objects of one radius bin for one workload and window kind, each with its case's window.
struct Batch {
    workload: &'static str,
    window: &'static str,
    bin: (f64, f64),
    /// (case, ellipse).
    objects: Vec<(usize, Ellipse)>,
}

/// The cases of one workload and window kind: windows as polygons and prepared both ways.
struct Windows {
    polygons: Vec<Polygons>,
    with_tests: Vec<PreparedCurveWindow>,
    without_tests: Vec<PreparedCurveWindow>,
}

fn failed(what: String) -> CliError {
    CliError::failed(format!("lecture curve bench: {what}"))
}

/// Generates the batches, counts the stages, checks the methods agree, times everything in
/// interleaved rounds and writes the raw CSVs and the sidecar into `out`.
pub fn measure(settings: &Settings, out: &Path) -> Result<(), CliError> {
    let mut batches = Vec::new();
    let mut windows = Vec::new();
    for workload in CURVE_WORKLOADS {
        for (kind, name) in [(WindowKind::Rectangle, "rectangle"), (WindowKind::Any, "polygon")] {
            let mut w = Windows { polygons: Vec::new(), with_tests: Vec::new(), without_tests: Vec::new() };
            let mut objects = Vec::new();
            for index in 0..settings.cases {
                let case = curve_case(workload, settings.seed, index, kind, CURVES_PER_CASE)
                    .map_err(|e| failed(e.to_string()))?;
                let prepare =
                    |c: CurveClipper| c.prepare(&case.window).map_err(|e| failed(format!("{workload} {index}: {e}")));
                w.with_tests.push(prepare(CurveClipper::WITH_TESTS)?);
                w.without_tests.push(prepare(CurveClipper::WITHOUT_TESTS)?);
                w.polygons.push(case.window);
                objects.extend(case.objects.iter().filter(|a| a.is_closed()).map(|a| (index, *a.ellipse())));
            }
            let group = windows.len();
            windows.push(w);
            for bin in RADIUS_BINS {
                let objects: Vec<(usize, Ellipse)> =
                    objects.iter().copied().filter(|(_, e)| (bin.0..bin.1).contains(&e.max_radius())).collect();
                if !objects.is_empty() {
                    batches.push((group, Batch { workload, window: name, bin, objects }));
                }
            }
        }
    }
    let stages = count_stages(&batches, &windows);
    let notes = agreement(&batches, &windows);

    let mut iterations: Vec<[u32; METHODS.len()]> = vec![[0; METHODS.len()]; batches.len()];
    let mut rows = Vec::new();
    let mut progress = bar(settings.repetitions, "lecture curves: timing");
    for repetition in 0..settings.repetitions {
        for (b, (group, batch)) in batches.iter().enumerate() {
            let w = &windows[*group];
            for j in 0..METHODS.len() {
                let m = (j + repetition) % METHODS.len();
                let (method, phase) = METHODS[m];
                if method == FLATTEN_GEO && repetition >= settings.geo_repetitions {
                    continue;
                }
                let run = || run_batch(METHODS[m], batch, w);
                if iterations[b][m] == 0 {
                    let (_, single) = timed(run);
                    iterations[b][m] = iterations_for(single, TARGET);
                }
                let ns = per_call_ns(iterations[b][m], run);
                rows.push(CurveTiming {
                    workload: batch.workload.to_owned(),
                    window: batch.window.to_owned(),
                    radius_lo: batch.bin.0,
                    radius_hi: batch.bin.1,
                    method: method.to_owned(),
                    phase: phase.to_owned(),
                    objects: batch.objects.len(),
                    repetition,
                    iterations: iterations[b][m],
                    ns_per_object: ns / batch.objects.len() as f64,
                });
            }
        }
        progress.inc();
    }
    progress.finish();

    write_csv(&out.join(CSV), &rows)?;
    write_csv(&out.join(STAGES_CSV), &stages)?;
    let parameters = json!({
        "workloads": CURVE_WORKLOADS,
        "windows": "rectangle (30-80% of the 1000 x 1000 frame) and polygon (a concave star with 1-3 holes, in a quarter \
                    of the cases crossed by a second star), clip_testkit::workload::curve_case",
        "cases_per_workload_and_window": settings.cases,
        "objects_per_case": CURVES_PER_CASE,
        "objects": "the whole circles and ellipses of each case (arcs left out, so the polygon routes can run)",
        "radius_bins": RADIUS_BINS,
        "route_tolerance_relative_to_radius": ROUTE_TOLERANCE,
        "repetitions": settings.repetitions,
        "geo_repetitions": settings.geo_repetitions,
        "target_ms_per_measurement": TARGET.as_secs_f64() * 1e3,
    });
    let mut provenance = Provenance::now("reproduce lecture", settings.seed, parameters);
    provenance.notes.push(format!(
        "The polygon routes flatten each ellipse within {ROUTE_TOLERANCE} of its long radius (inside the timed call), \
         then clip the polygon against the window under even-odd; flatten+geo runs in the first {} rounds only.",
        settings.geo_repetitions
    ));
    provenance.notes.extend(notes);
    provenance.write(&out.join(META))
}

/// Clips every object of a batch once by one method; returns a number that depends on the
/// results, so nothing is optimised away.
fn run_batch((method, phase): (&str, &str), batch: &Batch, w: &Windows) -> f64 {
    let mut acc = 0.0;
    for &(case, e) in &batch.objects {
        acc += match (method, phase) {
            (FLATTEN_VATTI | FLATTEN_GEO, _) => route_area(method, &w.polygons[case], &e).unwrap_or(f64::NAN),
            (_, "outline") => {
                let p = if method == WITH_TESTS { &w.with_tests[case] } else { &w.without_tests[case] };
                p.visible(&EllipseArc::full(black_box(e))).intervals.len() as f64
            }
            _ => {
                let p = if method == WITH_TESTS { &w.with_tests[case] } else { &w.without_tests[case] };
                p.clip_filled(&black_box(e)).region.area()
            }
        };
    }
    acc
}

/// The clipped area by a polygon route: flatten, then clip with Vatti or geo.
fn route_area(method: &str, window: &Polygons, e: &Ellipse) -> Result<f64, String> {
    let ring = flatten_ellipse(e, ROUTE_TOLERANCE * e.max_radius()).map_err(|err| err.to_string())?;
    let clipped = if method == FLATTEN_VATTI {
        Vatti.clip(&ring, window, BoolOp::Intersection, FillRule::EvenOdd)
    } else {
        GeoClipper::new().clip(&ring, window, BoolOp::Intersection, FillRule::EvenOdd)
    };
    clipped.map(|p| p.signed_area()).map_err(|err| err.to_string())
}

/// How many objects of each batch each stage settled, with the tests on.
fn count_stages(batches: &[(usize, Batch)], windows: &[Windows]) -> Vec<CurveStageRecord> {
    let mut records = Vec::new();
    for (group, batch) in batches {
        let mut counts = [0usize; Stage::ALL.len()];
        for &(case, e) in &batch.objects {
            let stage = windows[*group].with_tests[case].visible(&EllipseArc::full(e)).stage;
            counts[Stage::ALL.iter().position(|&s| s == stage).unwrap_or(0)] += 1;
        }
        for (stage, n) in Stage::ALL.iter().zip(counts) {
            records.push(CurveStageRecord {
                workload: batch.workload.to_owned(),
                window: batch.window.to_owned(),
                radius_lo: batch.bin.0,
                radius_hi: batch.bin.1,
                stage: stage.name().to_owned(),
                objects: n,
                of: batch.objects.len(),
            });
        }
    }
    records
}

/// Notes on any object where the methods disagree: tests on and off must give the same area,
/// the polygon routes the exact area within their flattening bound (geo also within its grid).
fn agreement(batches: &[(usize, Batch)], windows: &[Windows]) -> Vec<String> {
    let mut notes = Vec::new();
    let (mut checked, mut off) = (0usize, 0usize);
    for (group, batch) in batches {
        let w = &windows[*group];
        for &(case, e) in &batch.objects {
            let exact = w.with_tests[case].clip_filled(&e).region;
            let area = exact.area();
            let bound = flattening_area_bound(&clip_core::CurveRegion::whole(e), ROUTE_TOLERANCE * e.max_radius());
            let box_area = e.bounds().area().max(w.polygons[case].bounds().area());
            let within = |method: &str, slack: f64| {
                route_area(method, &w.polygons[case], &e).is_ok_and(|a| (a - area).abs() <= bound + slack * box_area)
            };
            let no_tests = w.without_tests[case].clip_filled(&e).region.area();
            checked += 1;
            if (no_tests - area).abs() > 1e-9 * box_area
                || !within(FLATTEN_VATTI, 1e-9)
                || !within(FLATTEN_GEO, GEO_TOLERANCE)
            {
                off += 1;
                if off <= 5 {
                    notes.push(format!(
                        "{} {} case {case}: the methods disagree on the clipped area of {e:?} (exact {area})",
                        batch.workload, batch.window
                    ));
                }
            }
        }
    }
    notes.push(format!(
        "Checked before timing: on {checked} objects the tests-on and tests-off areas agree and both polygon routes land \
         within their flattening bound of the exact area on {} of them.",
        checked - off
    ));
    notes
}
