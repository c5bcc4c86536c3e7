//! How long the polygon oracle takes per output, at the sizes `verify` runs it on.

use clip_core::{BoolOp, FillRule, WindowKind};
use clip_oracle::line::visible_intervals;
use clip_oracle::polygon::{OutputRules, REGION_TOLERANCE, check_polygon_result, region_area};
use clip_testkit::workload::{WangSize, polygon_case_sized, wang_segments, wang_window};
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;

fn oracle(c: &mut Criterion) {
    let rules = OutputRules::conventional(REGION_TOLERANCE);
    for edges in [20, 200] {
        // A ∩ A = A: a right answer of the subject's size, so every check runs to the end.
        let case = polygon_case_sized("star", 1, 0, edges, WindowKind::Any).unwrap();
        let a = &case.subject;
        c.bench_function(&format!("check_polygon_result star {edges} edges"), |b| {
            b.iter(|| {
                check_polygon_result(black_box(a), a, BoolOp::Intersection, FillRule::NonZero, a, &rules).unwrap()
            })
        });
        // Three layers of self-intersecting rings: the slab sweep's worst case among the workloads.
        let s = polygon_case_sized("scribble", 1, 0, edges, WindowKind::Any).unwrap();
        let layers = [(&s.subject, FillRule::EvenOdd), (&s.clip, FillRule::EvenOdd), (&s.subject, FillRule::NonZero)];
        c.bench_function(&format!("region_area scribble 3 layers {edges} edges"), |b| {
            b.iter(|| region_area(black_box(&layers), |i| (i[0] && i[1]) != i[2]))
        });
    }
    let large = polygon_case_sized("large", 1, 0, 100_000, WindowKind::Any).unwrap();
    let layers = [(&large.subject, FillRule::NonZero), (&large.clip, FillRule::NonZero)];
    c.bench_function("region_area large smooth 2 x 100000 edges", |b| {
        b.iter(|| region_area(black_box(&layers), |i| i[0] && i[1]))
    });
}

fn line_oracle(c: &mut Criterion) {
    // One Table 4 batch: 10000 random segments against a 50-edge concave window.
    let window = wang_window(50, WangSize::W2, 1, false);
    let segments = wang_segments(10_000, 1);
    c.bench_function("visible_intervals wang-t4 50 edges x 10000 segments", |b| {
        b.iter(|| segments.iter().map(|&s| visible_intervals(black_box(&window), s).len()).sum::<usize>())
    });
}

criterion_group!(benches, oracle, line_oracle);
criterion_main!(benches);
