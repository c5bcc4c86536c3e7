//! The two fills of Vatti's Table 3 on the same regions: the scanline fill of a polygon and the
//! trapezoid fill of its slab decomposition, for the Table 3 subjects (concave stars of 4-200
//! edges fitted in 1280x1024).

use clip_core::{FillRule, WindowKind};
use clip_raster::{FrameBuffer, fill_polygons, fill_trapezoids};
use clip_testkit::workload::{VATTI_EDGES, polygon_case_sized};
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

#[path = "../tests/slabs/mod.rs"]
mod slabs;

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("raster/fill");
    group.sample_size(30).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(1));
    let mut frame = FrameBuffer::default();
    for edges in VATTI_EDGES {
        let region = polygon_case_sized("vatti-t3", 1, 0, edges, WindowKind::Convex).expect("vatti-t3 exists").subject;
        let trapezoids = slabs::trapezoids_of(&region);
        group.bench_with_input(BenchmarkId::new("scanline", edges), &region, |b, region| {
            b.iter(|| fill_polygons(&mut frame, black_box(region), FillRule::EvenOdd, 1))
        });
        group.bench_with_input(BenchmarkId::new("trapezoids", edges), &trapezoids, |b, trapezoids| {
            b.iter(|| fill_trapezoids(&mut frame, black_box(trapezoids), 1))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
