//! Wang et al.'s Table 4 on these machines: ns per segment of liu, virtual-box-no45 (New1),
//! virtual-box (New2) and geo's `clip`, on the `wang-t4` workload (10000 random segments in
//! 800x600; star-shaped windows of 6-50 edges at sizes W1 and W2). Throughput is per segment, so
//! criterion's "thrpt" line reads segments per second; time / 10000 is the time per segment.
//!
//! `cargo bench -p clip-virtual-box --bench wang_t4` (add `-- liu` etc. to filter). geo clips
//! 1000 of the segments (it is about a hundred times slower); its time is per segment too.

use clip_core::{LineClipper, Segment, VisiblePiece};
use clip_cyrus_beck::Liu;
use clip_peers::GeoLineClipper;
use clip_testkit::workload::{WANG_EDGES, WangSize, wang_segments, wang_window};
use clip_virtual_box::VirtualBox;
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;

const SEGMENTS: usize = 10_000;
const GEO_SEGMENTS: usize = 1_000;
const SEED: u64 = 2005;

fn wang_t4(c: &mut Criterion) {
    let segments = wang_segments(SEGMENTS, SEED);
    let geo = GeoLineClipper::new();
    let clippers: [(&dyn LineClipper, &[Segment]); 4] = [
        (&Liu, &segments),
        (&VirtualBox::NEW1, &segments),
        (&VirtualBox::NEW2, &segments),
        (&geo, &segments[..GEO_SEGMENTS]),
    ];
    for size in WangSize::ALL {
        let mut group = c.benchmark_group(format!("wang-t4 {}", size.name()));
        group.sample_size(20);
        for edges in WANG_EDGES {
            let window = wang_window(edges, size, SEED, false);
            for (clipper, batch) in clippers {
                let prepared = clipper.prepare(&window).expect("wang-t4 windows are valid");
                let mut out: Vec<VisiblePiece> = Vec::with_capacity(batch.len() * 2);
                group.throughput(Throughput::Elements(batch.len() as u64));
                group.bench_with_input(BenchmarkId::new(clipper.name(), edges), batch, |b, batch| {
                    b.iter(|| {
                        out.clear();
                        prepared.clip_batch(black_box(batch), &mut out).expect("finite segments");
                        black_box(out.len())
                    })
                });
            }
        }
        group.finish();
    }
}

criterion_group!(benches, wang_t4);
criterion_main!(benches);
