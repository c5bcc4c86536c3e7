//! Measures Wang et al.'s Table 4: batches of random segments clipped against windows of 6 to 50
//! edges at the paper's two sizes by Liu's algorithm, the virtual-box algorithm without (New1)
//! and with (New2) the 45° box, the indexed clipper, Cyrus-Beck (convex windows) and geo; plus the share of segments
//! each rejection stage removes.

use std::hint::black_box;
use std::path::Path;

use clip_core::{LineClipper, Polygons, PreparedWindow, Segment, VisiblePiece};
use clip_cyrus_beck::{CyrusBeck, Liu, PreparedCyrusBeck, PreparedLiu};
use clip_line_index::LineIndex;
use clip_peers::GeoLineClipper;
use clip_testkit::workload::{WANG_EDGES, WangSize, wang_measure, wang_segments, wang_window};
use clip_virtual_box::{PreparedVirtualBox, VirtualBox};
use serde_json::json;

use crate::cli_error::CliError;
use crate::measure::progress::bar;
use crate::measure::provenance::Provenance;
use crate::measure::raw::{Measurement, write_csv};
use crate::measure::timing::{median, timed};
use crate::results_files::wang_table4::{
    CSV, META, STAGE_TIMES_CSV, STAGES_CSV, StageRecord, StageTimeRecord, WINDOWS_CSV, WindowRecord,
};

/// The workload name in the raw rows.
const WORKLOAD: &str = "wang-t4";
/// The peer, which is far slower per batch and gets fewer rounds.
const GEO: &str = "geo";

/// How much to measure.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// Seed of the windows and segments.
    pub seed: u64,
    /// Segments per batch (the paper's 10000).
    pub segments: usize,
    /// Timed rounds; each round clips the batch once per window and clipper.
    pub repetitions: usize,
    /// Rounds geo takes part in (its batches take far longer).
    pub geo_repetitions: usize,
}

impl Settings {
    /// Quick: 200 rounds (about 20 s); `full`: the paper's 1000; `repetitions` overrides both. geo runs in the
    /// first 3 rounds (10 with `full`).
    pub fn new(seed: u64, full: bool, repetitions: Option<usize>) -> Settings {
        let repetitions = repetitions.unwrap_or(if full { 1000 } else { 200 });
        let geo_repetitions = repetitions.min(if full { 10 } else { 3 });
        Settings { seed, segments: 10_000, repetitions, geo_repetitions }
    }
}

/// The line clippers of the table, in column order: adding one is a line here.
fn clippers() -> Vec<Box<dyn LineClipper>> {
    vec![
        Box::new(Liu),
        Box::new(VirtualBox::NEW1),
        Box::new(VirtualBox::NEW2),
        Box::new(LineIndex),
        Box::new(CyrusBeck),
        Box::new(GeoLineClipper),
    ]
}

/// One window with every clipper that takes it, prepared.
struct Window {
    shape: &'static str,
    size: WangSize,
    edges: usize,
    polygons: Polygons,
    prepared: Vec<(&'static str, Box<dyn PreparedWindow>)>,
}

impl Window {
    fn case(&self) -> String {
        format!("{}-{}", self.shape, self.size.name())
    }
}

/// Prepares the windows, counts the stages, times every clipper in interleaved rounds and writes
/// the raw CSV, the window and stage records and the sidecar into `out`.
pub fn measure(settings: &Settings, out: &Path) -> Result<(), CliError> {
    let segments = wang_segments(settings.segments, settings.seed);
    let windows = prepare_windows(settings.seed)?;
    let mut notes = Vec::new();
    let (stages, disagreements) = count_stages(&windows, &segments)?;
    notes.extend(disagreements);

    let mut progress = bar(settings.repetitions, "Table 4: timing");
    let mut rows = Vec::new();
    let mut pieces: Vec<VisiblePiece> = Vec::with_capacity(settings.segments * 2);
    for repetition in 0..settings.repetitions {
        for window in &windows {
            // Rotate the starting clipper each round so none always runs first.
            let n = window.prepared.len();
            for j in 0..n {
                let (name, prepared) = &window.prepared[(j + repetition) % n];
                if *name == GEO && repetition >= settings.geo_repetitions {
                    continue;
                }
                pieces.clear();
                let (result, took) = timed(|| prepared.clip_batch(black_box(&segments), &mut pieces));
                result.map_err(|e| CliError::failed(format!("Table 4: {name} on {}: {e}", window.case())))?;
                black_box(pieces.len());
                rows.push(Measurement {
                    workload: WORKLOAD.to_owned(),
                    case: window.case(),
                    clipper: (*name).to_owned(),
                    phase: "clip".to_owned(),
                    size: window.edges,
                    op: "lines".to_owned(),
                    fill_rule: "even-odd".to_owned(),
                    repetition,
                    iterations: 1,
                    time_ns: took.as_nanos() as f64,
                    correct: None,
                });
            }
        }
        progress.inc();
    }
    progress.finish();

    let stage_times = time_stages(&windows, &segments)?;
    let records: Vec<WindowRecord> = windows.iter().map(window_record).collect();
    write_csv(&out.join(CSV), &rows)?;
    write_csv(&out.join(WINDOWS_CSV), &records)?;
    write_csv(&out.join(STAGES_CSV), &stages)?;
    write_csv(&out.join(STAGE_TIMES_CSV), &stage_times)?;
    let parameters = json!({
        "window_edges": WANG_EDGES,
        "segments_per_batch": settings.segments,
        "segments": "endpoints uniform in the 800 x 600 screen (clip_testkit::workload::wang_segments)",
        "windows": "star-shaped concave (the table) and convex (extra, for cyrus-beck), MEB centred on the screen \
                    and sized per clip_testkit::workload::wang_box (L = MEB width + height)",
        "repetitions": settings.repetitions,
        "geo_repetitions": settings.geo_repetitions,
        "clippers": windows.first().map(|w| w.prepared.iter().map(|(n, _)| *n).collect::<Vec<_>>()),
    });
    let mut provenance = Provenance::now("reproduce wang-table4", settings.seed, parameters);
    provenance.notes.push(format!(
        "geo clips one segment per call (its BooleanOps::clip processes a whole batch together, far slower) and \
         takes part in the first {} rounds only.",
        settings.geo_repetitions
    ));
    provenance.notes.extend(notes);
    provenance.write(&out.join(META))
}

fn prepare_windows(seed: u64) -> Result<Vec<Window>, CliError> {
    let clippers = clippers();
    let mut windows = Vec::new();
    for (shape, convex) in [("concave", false), ("convex", true)] {
        for size in WangSize::ALL {
            for edges in WANG_EDGES {
                let polygons = wang_window(edges, size, seed, convex);
                let mut prepared = Vec::new();
                for c in clippers.iter().filter(|c| c.capabilities().window.accepts(&polygons)) {
                    let p = c.prepare(&polygons).map_err(|e| {
                        CliError::failed(format!("Table 4: {} refused the {shape} {edges}-edge window: {e}", c.name()))
                    })?;
                    prepared.push((c.name(), p));
                }
                windows.push(Window { shape, size, edges, polygons, prepared });
            }
        }
    }
    Ok(windows)
}

fn window_record(w: &Window) -> WindowRecord {
    let (w1, w2) = wang_measure(&w.polygons);
    let (paper_w1, paper_w2) = w.size.paper_w1_w2(w.edges);
    WindowRecord {
        shape: w.shape.to_owned(),
        size_row: w.size.name().to_owned(),
        edges: w.edges,
        w1,
        w2,
        paper_w1,
        paper_w2,
    }
}

/// Runs the counted entry points once per window: how many segments each stage settled. Also
/// returns a note for every window where the clippers disagree on how many segments are visible.
fn count_stages(windows: &[Window], segments: &[Segment]) -> Result<(Vec<StageRecord>, Vec<String>), CliError> {
    let mut records = Vec::new();
    let mut notes = Vec::new();
    let mut pieces = Vec::new();
    for w in windows {
        let fail =
            |name: &str, e: clip_core::ClipError| CliError::failed(format!("Table 4: {name} on {}: {e}", w.case()));
        let mut stages: Vec<(&str, Vec<(&str, usize)>)> = Vec::new();
        let c = PreparedLiu::new(&w.polygons).and_then(|p| p.clip_batch_counted(segments, &mut pieces));
        let c = c.map_err(|e| fail("liu", e))?;
        stages.push((
            "liu",
            vec![
                ("zero-length", c.zero_length),
                ("meb", c.bounding_box),
                ("no-crossing", c.no_crossing),
                ("intersected", c.segments - c.zero_length - c.bounding_box - c.no_crossing),
                ("visible", c.visible),
            ],
        ));
        for (name, rotated) in [("virtual-box-no45", false), ("virtual-box", true)] {
            let c =
                PreparedVirtualBox::new(&w.polygons, rotated).and_then(|p| p.clip_batch_counted(segments, &mut pieces));
            let c = c.map_err(|e| fail(name, e))?;
            stages.push((
                name,
                vec![
                    ("zero-length", c.zero_length),
                    ("meb", c.meb),
                    ("rotated-box", c.rotated_box),
                    ("virtual-box", c.virtual_box),
                    ("code-sum", c.code_sum),
                    ("intersected", c.intersected),
                    ("visible", c.visible),
                ],
            ));
        }
        if w.shape == "convex" {
            let c = PreparedCyrusBeck::new(&w.polygons).and_then(|p| p.clip_batch_counted(segments, &mut pieces));
            let c = c.map_err(|e| fail("cyrus-beck", e))?;
            stages.push((
                "cyrus-beck",
                vec![
                    ("zero-length", c.zero_length),
                    ("meb", c.bounding_box),
                    ("outside-edge", c.outside_edge),
                    ("empty-span", c.empty_span),
                    ("visible", c.visible),
                ],
            ));
        }
        let visible: Vec<(&str, usize)> =
            stages.iter().map(|(n, s)| (*n, s.iter().find(|(k, _)| *k == "visible").map_or(0, |(_, v)| *v))).collect();
        if visible.iter().any(|(_, v)| *v != visible[0].1) {
            notes.push(format!(
                "{} {} edges: the clippers disagree on how many segments are visible: {visible:?}",
                w.case(),
                w.edges
            ));
        }
        for (clipper, counts) in stages {
            for (stage, n) in counts {
                records.push(StageRecord {
                    shape: w.shape.to_owned(),
                    size_row: w.size.name().to_owned(),
                    edges: w.edges,
                    clipper: clipper.to_owned(),
                    stage: stage.to_owned(),
                    segments: n,
                    of: segments.len(),
                });
            }
        }
    }
    Ok((records, notes))
}

/// New2's stages, by the counter that records each.
const NEW2_STAGES: [&str; 6] = ["zero-length", "meb", "rotated-box", "virtual-box", "code-sum", "intersected"];

/// Rounds of each stage's timing (medians of these).
const STAGE_ROUNDS: usize = 31;

/// Splits the batch by the stage at which New2 settles each segment, then times New2 and Liu on
/// each part (concave windows): where New2's extra boxes save time against Liu and where they
/// cost it, measured rather than argued.
fn time_stages(windows: &[Window], segments: &[Segment]) -> Result<Vec<StageTimeRecord>, CliError> {
    let mut records = Vec::new();
    let mut pieces = Vec::new();
    for w in windows.iter().filter(|w| w.shape == "concave") {
        let fail =
            |name: &str, e: clip_core::ClipError| CliError::failed(format!("Table 4: {name} on {}: {e}", w.case()));
        let new2 = PreparedVirtualBox::new(&w.polygons, true).map_err(|e| fail("virtual-box", e))?;
        let liu = PreparedLiu::new(&w.polygons).map_err(|e| fail("liu", e))?;
        let mut parts: Vec<Vec<Segment>> = vec![Vec::new(); NEW2_STAGES.len()];
        for &s in segments {
            let c = new2.clip_batch_counted(&[s], &mut pieces).map_err(|e| fail("virtual-box", e))?;
            let at = [c.zero_length, c.meb, c.rotated_box, c.virtual_box, c.code_sum, c.intersected]
                .iter()
                .position(|&n| n == 1)
                .unwrap_or(NEW2_STAGES.len() - 1);
            parts[at].push(s);
        }
        for (stage, part) in NEW2_STAGES.iter().zip(&parts).filter(|(_, p)| !p.is_empty()) {
            let clippers: [(&str, &dyn PreparedWindow); 2] = [("virtual-box", &new2), ("liu", &liu)];
            let mut times = [Vec::new(), Vec::new()];
            for round in 0..STAGE_ROUNDS {
                for j in 0..2 {
                    let (name, prepared) = clippers[(j + round) % 2];
                    pieces.clear();
                    let (result, took) = timed(|| prepared.clip_batch(black_box(part), &mut pieces));
                    result.map_err(|e| fail(name, e))?;
                    times[(j + round) % 2].push(took.as_nanos() as f64 / part.len() as f64);
                }
            }
            for ((name, _), t) in clippers.iter().zip(&times) {
                records.push(StageTimeRecord {
                    size_row: w.size.name().to_owned(),
                    edges: w.edges,
                    stage: (*stage).to_owned(),
                    segments: part.len(),
                    of: segments.len(),
                    clipper: (*name).to_owned(),
                    ns_per_segment: median(t),
                });
            }
        }
    }
    Ok(records)
}
