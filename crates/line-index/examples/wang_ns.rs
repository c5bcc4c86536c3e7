//! Prints ns per segment of the line clippers on wang-t4's concave windows (6 and 50 edges, both size rows), timed in interleaved rounds like `reproduce wang-table4`; `--only NAME` times one clipper, `--rounds N` sets the rounds, `--edges N[,M...]` the window sizes (one for callgrind), `--beyond` the lobed windows of `reproduce beyond-paper` instead, `--large` the indexed clipper on lines-large case 3, `--counts` the indexed clipper's stage counts instead of times, `--cold` evicts the caches before every timed batch (as the other clippers of `reproduce beyond-paper` do between two batches of one clipper).

use std::time::Instant;

use clip_core::{LineClipper, PreparedWindow, VisiblePiece};
use clip_cyrus_beck::Liu;
use clip_line_index::LineIndex;
use clip_testkit::workload::{WangSize, beyond_window, wang_segments, wang_window};
use clip_virtual_box::VirtualBox;

/// One timed pairing: the window's label, the clipper's name, the prepared window, its times.
type Run<'a> = (String, &'a str, Box<dyn PreparedWindow>, Vec<f64>);

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let only = args.iter().position(|a| a == "--only").and_then(|i| args.get(i + 1)).cloned();
    let rounds = args.iter().position(|a| a == "--rounds").and_then(|i| args.get(i + 1)?.parse().ok()).unwrap_or(101);
    let segments = wang_segments(10_000, 1);
    let clippers: [&dyn LineClipper; 3] = [&Liu, &VirtualBox::NEW2, &LineIndex];
    let clippers: Vec<&dyn LineClipper> =
        clippers.into_iter().filter(|c| only.as_deref().is_none_or(|o| o == c.name())).collect();
    let mut runs: Vec<Run> = Vec::new();
    // `--edges 50,10000`: several sizes, timed interleaved in one run.
    let sizes: Vec<usize> = match args.iter().position(|a| a == "--edges").and_then(|i| args.get(i + 1)) {
        Some(list) => list.split(',').map(str::parse).collect::<Result<_, _>>()?,
        None => vec![6, 50],
    };
    let beyond = args.iter().any(|a| a == "--beyond");
    if args.iter().any(|a| a == "--large") {
        // `reproduce beyond-paper`'s 10^6-segment window (lines-large case 3), on 10^5 segments.
        let case = clip_testkit::workload::line_case("lines-large", 1, 3, clip_core::WindowKind::Any, 100_000)?;
        let prepared = LineIndex.prepare(&case.window)?;
        let mut out = Vec::new();
        let mut times = Vec::new();
        for _ in 0..rounds.min(7) {
            out.clear();
            let start = Instant::now();
            prepared.clip_batch(&case.segments, &mut out)?;
            times.push(start.elapsed().as_secs_f64());
        }
        times.sort_by(f64::total_cmp);
        println!("lines-large case 3  indexed {:.1} ns", times[times.len() / 2] * 1e9 / case.segments.len() as f64);
        return Ok(());
    }
    for (label, window) in windows_of(&sizes, beyond) {
        for c in &clippers {
            runs.push((label.clone(), c.name(), c.prepare(&window)?, Vec::new()));
        }
    }
    let mut out: Vec<VisiblePiece> = Vec::with_capacity(30_000);
    if args.iter().any(|a| a == "--counts") {
        // What each stage of the indexed clipper settled, and the tree walked per walked segment.
        for (label, window) in windows_of(&sizes, beyond) {
            let c = clip_line_index::PreparedLineIndex::new(&window)?.clip_batch_counted(&segments, &mut out)?;
            let walked = (c.segments - c.zero_length - c.bounding_box).max(1) as f64;
            println!(
                "{label}  walked {:.1}%  nodes/walked {:.2}  leaves/walked {:.2}  visible {:.1}%",
                walked * 100.0 / c.segments as f64,
                c.nodes_tested as f64 / walked,
                c.leaves_scanned as f64 / walked,
                c.visible as f64 * 100.0 / c.segments as f64
            );
        }
        return Ok(());
    }
    // Larger than the last-level cache: writing it evicts the windows and the segments.
    let mut evict = if args.iter().any(|a| a == "--cold") { vec![0u8; 64 << 20] } else { Vec::new() };
    for round in 0..rounds {
        for (_, _, prepared, times) in &mut runs {
            evict.iter_mut().for_each(|b| *b = b.wrapping_add(round as u8));
            std::hint::black_box(&evict);
            out.clear();
            let start = Instant::now();
            prepared.clip_batch(&segments, &mut out)?;
            times.push(start.elapsed().as_secs_f64());
        }
    }
    for (window, name, _, times) in &mut runs {
        times.sort_by(f64::total_cmp);
        println!("{window}  {name:<12} {:.1} ns", times[rounds / 2] * 1e9 / segments.len() as f64);
    }
    Ok(())
}

/// wang-t4's two size rows per edge count, or with `beyond` the lobed concave window of
/// `reproduce beyond-paper`, each with its label.
fn windows_of(sizes: &[usize], beyond: bool) -> Vec<(String, clip_core::Polygons)> {
    let mut windows = Vec::new();
    for &edges in sizes {
        if beyond {
            windows.push((format!("{edges:>5} edges lobed"), beyond_window(edges, 1, false)));
        } else {
            for size in WangSize::ALL {
                windows.push((format!("{edges:>3} edges {}", size.name()), wang_window(edges, size, 1, false)));
            }
        }
    }
    windows
}
