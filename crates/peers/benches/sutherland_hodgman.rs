//! Sutherland-Hodgman (both forms) on Vatti's Table 3 subjects (concave stars of 4-200 edges in
//! 1280x1024) against a rectangle and against a convex octagon, with Clipper2 side by side (and
//! Clipper2's dedicated rectangle clipper, `RectClip`, in the rectangle group).

use clip_core::{BoolOp, FillRule, PolygonClipper, WindowKind};
use clip_peers::{Clipper2Clipper, Clipper2RectClipper};
use clip_sutherland_hodgman::{Form, SutherlandHodgman};
use clip_testkit::workload::{VATTI_EDGES, polygon_case_sized};
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

fn clippers(window: WindowKind) -> Vec<(&'static str, Box<dyn PolygonClipper>)> {
    let mut clippers: Vec<(&'static str, Box<dyn PolygonClipper>)> = vec![
        ("sh-list", Box::new(SutherlandHodgman::new(Form::List))),
        ("sh-pipeline", Box::new(SutherlandHodgman::new(Form::Pipeline))),
        ("clipper2", Box::new(Clipper2Clipper::new())),
    ];
    if window == WindowKind::Rectangle {
        clippers.push(("clipper2-rect", Box::new(Clipper2RectClipper)));
    }
    clippers
}

fn bench(c: &mut Criterion) {
    for (label, window) in [("rectangle", WindowKind::Rectangle), ("octagon", WindowKind::Convex)] {
        let mut group = c.benchmark_group(format!("sutherland-hodgman/{label}"));
        group.sample_size(30).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(1));
        for edges in VATTI_EDGES {
            let case = polygon_case_sized("vatti-t3", 1, 0, edges, window).expect("vatti-t3 exists");
            for (name, clipper) in clippers(window) {
                group.bench_with_input(BenchmarkId::new(name, edges), &case, |b, case| {
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
}

criterion_group!(benches, bench);
criterion_main!(benches);
