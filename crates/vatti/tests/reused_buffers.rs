//! One thread's clips share kept buffers: a clip's result must not depend on what ran before it.

use clip_core::{BoolOp, FillRule, PolygonClipper, WindowKind};
use clip_testkit::workload::{polygon_case, polygon_case_sized};
use clip_vatti::Vatti;

#[test]
fn a_clip_gives_the_same_result_whatever_ran_before_it_on_the_thread() {
    let small = polygon_case("star", 7, 0, WindowKind::Any).unwrap();
    let other = polygon_case("scribble", 7, 3, WindowKind::Any).unwrap();
    // Large enough that its buffers are freed rather than kept.
    let large = polygon_case_sized("large", 7, 0, 20_000, WindowKind::Any).unwrap();
    for op in BoolOp::ALL {
        let run = |c: &clip_testkit::workload::PolygonCase| Vatti.clip(&c.subject, &c.clip, op, FillRule::EvenOdd);
        // Alone on a fresh thread, then after other clips (polygons and trapezoids) on this one.
        let alone = std::thread::scope(|s| s.spawn(|| run(&small)).join().unwrap()).unwrap();
        for before in [&other, &large, &small] {
            run(before).unwrap();
            Vatti.clip_trapezoids(&before.subject, &before.clip, op, FillRule::NonZero).unwrap();
            assert_eq!(run(&small).unwrap(), alone, "{op} after {}", before.workload);
        }
    }
}
