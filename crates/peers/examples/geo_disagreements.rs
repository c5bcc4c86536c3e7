//! Where geo's `clip` disagrees with the exact line oracle on the line workloads, by kind, and
//! whether this crate's clippers agree there. For the note on peers; not a test.
//!
//! `cargo run --release -p clip-virtual-box --example geo_disagreements [cases]`

use clip_core::{LineClipper, Polygons, Segment, WindowKind};
use clip_oracle::line::{pieces_to_intervals, visible_intervals};
use clip_peers::GeoLineClipper;
use clip_testkit::workload::line_case;
use clip_virtual_box::VirtualBox;

/// geo's parameter tolerance (its coordinates snap to about extent x 1e-9).
const TOLERANCE: f64 = 1e-6;

fn same(a: &[(f64, f64)], b: &[(f64, f64)]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x.0 - y.0).abs() <= TOLERANCE && (x.1 - y.1).abs() <= TOLERANCE)
}

fn intervals(c: &dyn LineClipper, w: &Polygons, s: &[Segment]) -> Vec<Vec<(f64, f64)>> {
    let mut out = Vec::new();
    c.prepare(w).unwrap().clip_batch(s, &mut out).unwrap();
    pieces_to_intervals(&w.bounds(), s, &out)
}

fn main() {
    let cases: usize = std::env::args().nth(1).and_then(|n| n.parse().ok()).unwrap_or(24);
    let geo = GeoLineClipper::new();
    for workload in ["wang-t4", "lines-degenerate"] {
        for kind in [WindowKind::Any, WindowKind::Convex] {
            let (mut segments, mut visible, mut geo_wrong, mut ours_wrong) = (0, 0, 0, 0);
            let (mut missing, mut extra, mut split, mut shifted) = (0, 0, 0, 0);
            let mut shown = 0;
            for index in 0..cases {
                let case = line_case(workload, 5, index, kind, 200).unwrap();
                let g = intervals(&geo, &case.window, &case.segments);
                let v = intervals(&VirtualBox::NEW2, &case.window, &case.segments);
                for (i, s) in case.segments.iter().enumerate() {
                    segments += 1;
                    let exact = visible_intervals(&case.window, *s);
                    visible += usize::from(!exact.is_empty());
                    ours_wrong += usize::from(!same(&v[i], &exact));
                    if same(&g[i], &exact) {
                        continue;
                    }
                    geo_wrong += 1;
                    let (len_g, len_e) = (g[i].len(), exact.len());
                    match len_g.cmp(&len_e) {
                        std::cmp::Ordering::Less if len_g == 0 => missing += 1,
                        std::cmp::Ordering::Less => split += 1,
                        std::cmp::Ordering::Greater => extra += 1,
                        std::cmp::Ordering::Equal => shifted += 1,
                    }
                    if shown < 3 {
                        shown += 1;
                        println!(
                            "  {workload} {kind:?} case {index} segment {i} {s:?}: exact {exact:?}, geo {:?}",
                            g[i]
                        );
                    }
                }
            }
            println!(
                "{workload} {kind:?}: {segments} segments ({visible} partly visible); geo differs on {geo_wrong} (nothing where the oracle has pieces: {missing}; fewer pieces: {split}; more pieces: {extra}; same count, other ends: {shifted}); virtual-box differs on {ours_wrong}"
            );
        }
    }
}
