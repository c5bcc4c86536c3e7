//! The four-state clipper on Vatti's Table 3 subjects (concave stars of 4-200 edges in
//! 1280x1024) against a rectangle, with Clipper2's general intersection and its dedicated
//! rectangle clipper (`RectClip`) side by side.

use clip_core::{BoolOp, FillRule, PolygonClipper, WindowKind};
use clip_peers::{Clipper2Clipper, Clipper2RectClipper};
use clip_rect_four_state::FourState;
use clip_testkit::workload::{VATTI_EDGES, polygon_case_sized};
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("rect-four-state/rectangle");
    group.sample_size(30).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(1));
    let clippers: [(&str, Box<dyn PolygonClipper>); 3] = [
        ("four-state", Box::new(FourState)),
        ("clipper2", Box::new(Clipper2Clipper::new())),
        ("clipper2-rect", Box::new(Clipper2RectClipper)),
    ];
    for edges in VATTI_EDGES {
        let case = polygon_case_sized("vatti-t3", 1, 0, edges, WindowKind::Rectangle).expect("vatti-t3 exists");
        for (name, clipper) in &clippers {
            group.bench_with_input(BenchmarkId::new(*name, edges), &case, |b, case| {
                b.iter(|| {
                    clipper.clip(
                        black_box(&case.subject),
                        black_box(&case.clip),
                        BoolOp::Intersection,
                        FillRule::NonZero,
                    )
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
