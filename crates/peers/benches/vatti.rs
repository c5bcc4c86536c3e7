//! Vatti against geo (i_overlay) and Clipper2 on star and scribble polygons of 4 to 200 edges,
//! all four operations, measured side by side in one run.

use clip_core::{BoolOp, FillRule, PolygonClipper, WindowKind};
use clip_peers::{Clipper2Clipper, GeoClipper};
use clip_testkit::workload::polygon_case_sized;
use clip_vatti::Vatti;
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

const SIZES: [usize; 4] = [4, 20, 100, 200];

fn clippers() -> Vec<Box<dyn PolygonClipper>> {
    vec![Box::new(Vatti), Box::new(GeoClipper::new()), Box::new(Clipper2Clipper::new())]
}

fn bench(c: &mut Criterion) {
    for workload in ["star", "scribble"] {
        for op in BoolOp::ALL {
            let mut group = c.benchmark_group(format!("{workload}/{op}"));
            group.warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(1)).sample_size(30);
            for edges in SIZES {
                let case = polygon_case_sized(workload, 1, 0, edges, WindowKind::Any).expect("workload");
                for clipper in clippers() {
                    group.bench_with_input(BenchmarkId::new(clipper.name(), edges), &case, |b, case| {
                        b.iter(|| clipper.clip(black_box(&case.subject), black_box(&case.clip), op, FillRule::NonZero))
                    });
                }
            }
            group.finish();
        }
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
