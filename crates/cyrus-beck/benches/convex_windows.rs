//! Cyrus-Beck against Liu on convex windows: the `wang-t4` workload with convex windows of 6-50
//! edges at sizes W1 and W2, 10000 random segments in 800x600. Throughput is per segment.
//!
//! `cargo bench -p clip-cyrus-beck --bench convex_windows`

use clip_core::{LineClipper, VisiblePiece};
use clip_cyrus_beck::{CyrusBeck, Liu};
use clip_testkit::workload::{WANG_EDGES, WangSize, wang_segments, wang_window};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;

fn convex_windows(c: &mut Criterion) {
    let segments = wang_segments(10_000, 2005);
    for size in WangSize::ALL {
        let mut group = c.benchmark_group(format!("wang-t4 convex {}", size.name()));
        group.sample_size(20).throughput(Throughput::Elements(segments.len() as u64));
        for edges in WANG_EDGES {
            let window = wang_window(edges, size, 2005, true);
            for clipper in [&CyrusBeck as &dyn LineClipper, &Liu] {
                let prepared = clipper.prepare(&window).expect("convex wang-t4 windows are valid");
                let mut out: Vec<VisiblePiece> = Vec::with_capacity(segments.len());
                group.bench_with_input(BenchmarkId::new(clipper.name(), edges), &segments, |b, segments| {
                    b.iter(|| {
                        out.clear();
                        prepared.clip_batch(black_box(segments), &mut out).expect("finite segments");
                        black_box(out.len())
                    })
                });
            }
        }
        group.finish();
    }
}

criterion_group!(benches, convex_windows);
criterion_main!(benches);
