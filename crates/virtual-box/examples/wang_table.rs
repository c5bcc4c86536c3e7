//! A quick Table 4 on a noisy machine: each clipper's best time of several interleaved rounds, in
//! ns per segment, on the `wang-t4` workload (the criterion bench `wang_t4` is the careful one).
//!
//! `cargo run --release -p clip-virtual-box --example wang_table [rounds]`, or with
//! `[rounds] <clipper> <W1|W2> <edges>` one configuration only (to run under `perf stat` or
//! callgrind; `cyrus-beck` runs on the convex window of that size).

use std::time::Instant;

use clip_core::{LineClipper, Segment};
use clip_cyrus_beck::{CyrusBeck, Liu};
use clip_testkit::workload::{WANG_EDGES, WangSize, wang_segments, wang_window};
use clip_virtual_box::VirtualBox;

fn best_ns_per_segment(
    clipper: &dyn LineClipper,
    window: &clip_core::Polygons,
    segments: &[Segment],
    rounds: usize,
) -> f64 {
    let prepared = clipper.prepare(window).expect("valid window");
    let mut out = Vec::with_capacity(segments.len() * 2);
    (0..rounds)
        .map(|_| {
            out.clear();
            let start = Instant::now();
            prepared.clip_batch(segments, &mut out).expect("finite segments");
            start.elapsed().as_nanos() as f64 / segments.len() as f64
        })
        .fold(f64::INFINITY, f64::min)
}

fn main() {
    let rounds: usize = std::env::args().nth(1).and_then(|r| r.parse().ok()).unwrap_or(30);
    let segments = wang_segments(10_000, 2005);
    let args: Vec<String> = std::env::args().collect();
    if let [_, _, name, size, edges] = args.as_slice() {
        let clipper: &dyn LineClipper = match name.as_str() {
            "liu" => &Liu,
            "cyrus-beck" => &CyrusBeck,
            "virtual-box-no45" => &VirtualBox::NEW1,
            _ => &VirtualBox::NEW2,
        };
        let size = if size == "W1" { WangSize::W1 } else { WangSize::W2 };
        // Cyrus-Beck takes convex windows only: it gets Table 4's convex window of the same size.
        let window = wang_window(edges.parse().expect("edge count"), size, 2005, name == "cyrus-beck");
        println!("{name}: {:.1} ns per segment", best_ns_per_segment(clipper, &window, &segments, rounds));
        return;
    }
    let clippers: [&dyn LineClipper; 3] = [&Liu, &VirtualBox::NEW1, &VirtualBox::NEW2];
    println!("| size | edges | liu | virtual-box-no45 | virtual-box | gain (liu - new2) / new2 |");
    println!("|---|---|---|---|---|---|");
    for size in WangSize::ALL {
        for edges in WANG_EDGES {
            let window = wang_window(edges, size, 2005, false);
            let mut best = [f64::INFINITY; 3];
            // Interleave the clippers so that a slow spell of the machine hits all of them.
            for _ in 0..5 {
                for (b, c) in best.iter_mut().zip(clippers) {
                    *b = b.min(best_ns_per_segment(c, &window, &segments, rounds / 5 + 1));
                }
            }
            let gain = 100.0 * (best[0] - best[2]) / best[2];
            println!("| {} | {edges} | {:.1} | {:.1} | {:.1} | {gain:.0}% |", size.name(), best[0], best[1], best[2]);
        }
    }
}
