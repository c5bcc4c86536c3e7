//! The generators: deterministic per (seed, index), valid input, the asked window kinds and sizes.

use clip_core::{Operand, WindowKind, validate_polygons, validate_segments, validate_window};
use clip_testkit::workload::*;

const KINDS: [WindowKind; 3] = [WindowKind::Any, WindowKind::Convex, WindowKind::Rectangle];

#[test]
fn polygon_cases_are_deterministic_and_valid() {
    for &w in POLYGON_WORKLOADS {
        for kind in KINDS {
            for index in [0usize, 1, 2, 3, 7, 11] {
                if w == "large" && index > 1 {
                    continue;
                }
                let a = polygon_case(w, 42, index, kind).unwrap();
                let b = polygon_case(w, 42, index, kind).unwrap();
                assert_eq!(a, b, "{w} {index} not deterministic");
                validate_polygons(&a.subject, Operand::Subject).unwrap_or_else(|e| panic!("{}: {e}", a.description));
                validate_polygons(&a.clip, Operand::Clip).unwrap_or_else(|e| panic!("{}: {e}", a.description));
                assert!(kind.accepts(&a.clip), "{}: clip is not {kind:?}", a.description);
                assert_eq!((a.workload, a.seed, a.index), (w, 42, index));
            }
        }
    }
}

#[test]
fn cases_depend_on_seed_and_index_only() {
    // Making other cases first, in any order, changes nothing.
    let direct = polygon_case("star", 9, 5, WindowKind::Any).unwrap();
    for i in (0..5).rev() {
        polygon_case("star", 9, i, WindowKind::Any).unwrap();
    }
    assert_eq!(polygon_case("star", 9, 5, WindowKind::Any).unwrap(), direct);
    assert_ne!(polygon_case("star", 10, 5, WindowKind::Any).unwrap().subject, direct.subject);
    assert_ne!(polygon_case("star", 9, 6, WindowKind::Any).unwrap().subject, direct.subject);
}

#[test]
fn sizes_are_honoured() {
    for (i, &n) in VATTI_EDGES.iter().enumerate() {
        let c = polygon_case("vatti-t3", 1, i, WindowKind::Any).unwrap();
        assert_eq!(c.subject.vertex_count(), n);
        let b = c.subject.bounds();
        assert!(b.min.x >= 0.0 && b.min.y >= 0.0 && b.max.x <= 1280.0 && b.max.y <= 1024.0);
        assert!(WindowKind::Convex.accepts(&c.clip));
    }
    assert!(WindowKind::Rectangle.accepts(&polygon_case("vatti-t3", 1, 0, WindowKind::Rectangle).unwrap().clip));
    for w in ["star", "scribble", "holes", "multi", "grid"] {
        for i in 0..20 {
            let c = polygon_case(w, 3, i, WindowKind::Any).unwrap();
            for p in [&c.subject, &c.clip] {
                let n = p.vertex_count();
                // Grid spikes add two vertices per ring.
                assert!((6..=206).contains(&n), "{}: {n} edges", c.description);
            }
        }
    }
    let big = polygon_case_sized("large", 1, 0, 100_000, WindowKind::Any).unwrap();
    assert_eq!(big.subject.vertex_count(), 100_000);
}

#[test]
fn grid_cases_are_on_integers() {
    for i in 0..30 {
        let c = polygon_case("grid", 5, i, WindowKind::Any).unwrap();
        assert!(c.subject.points().chain(c.clip.points()).all(|p| p.x.fract() == 0.0 && p.y.fract() == 0.0));
    }
}

#[test]
fn wang_windows_have_the_papers_sizes() {
    for &edges in &WANG_EDGES {
        for size in WangSize::ALL {
            for convex in [false, true] {
                let w = wang_window(edges, size, 4, convex);
                validate_window(&w).unwrap();
                assert_eq!(w.vertex_count(), edges);
                if convex {
                    assert!(WindowKind::Convex.accepts(&w));
                }
                let (w1, w2) = wang_measure(&w);
                let (p1, p2) = size.paper_w1_w2(edges);
                assert!((w1 - p1).abs() < 1e-9 * p1, "{edges} {size:?}: W1 {w1} vs {p1}");
                // W2 is met exactly where a rectangle can meet both, within 7% elsewhere.
                assert!((w2 - p2).abs() < 0.07 * p2, "{edges} {size:?}: W2 {w2} vs {p2}");
                let b = w.bounds();
                assert!(WANG_SCREEN.contains(b.min) && WANG_SCREEN.contains(b.max));
            }
        }
    }
    // The standard row: W1 = 4 means w + h = 150.
    let b = wang_window(20, WangSize::W2, 1, false).bounds();
    assert!((b.width() + b.height() - 150.0).abs() < 1e-9);
    // 20 edges, first row: both met (w + h = 142.18, w h = 4958.7).
    let (w1, w2) = wang_measure(&wang_window(20, WangSize::W1, 1, false));
    assert!((w1 - 4.22).abs() < 1e-9 && (w2 - 96.8).abs() < 1e-6);
}

#[test]
fn line_cases_are_deterministic_and_valid() {
    for &w in LINE_WORKLOADS {
        for kind in KINDS {
            for index in 0..12 {
                let a = line_case(w, 8, index, kind, 200).unwrap();
                assert_eq!(a, line_case(w, 8, index, kind, 200).unwrap());
                validate_window(&a.window).unwrap_or_else(|e| panic!("{}: {e}", a.description));
                validate_segments(&a.segments).unwrap();
                assert_eq!(a.segments.len(), 200);
                assert_eq!(a.window_edges, a.window.vertex_count());
                assert!(kind.accepts(&a.window), "{}", a.description);
            }
        }
    }
    let s = wang_segments(1000, 3);
    assert!(s.iter().all(|s| WANG_SCREEN.contains(s.a) && WANG_SCREEN.contains(s.b)));
    assert_eq!(s, wang_segments(1000, 3));
}

#[test]
fn unknown_names_list_the_valid_ones() {
    let e = polygon_case("stars", 0, 0, WindowKind::Any).unwrap_err();
    assert!(e.to_string().contains("'stars'") && e.to_string().contains("scribble"));
    let e = line_case("star", 0, 0, WindowKind::Any, 1).unwrap_err();
    assert!(e.to_string().contains("wang-t4"));
}

#[test]
fn hard_cases_are_valid_and_invalid_inputs_are_refused() {
    let cases = hard_cases();
    assert!(cases.len() >= 12);
    for c in &cases {
        validate_polygons(&c.subject, Operand::Subject).unwrap_or_else(|e| panic!("{}: {e}", c.name));
        validate_polygons(&c.clip, Operand::Clip).unwrap_or_else(|e| panic!("{}: {e}", c.name));
    }
    for (name, p) in invalid_inputs() {
        assert!(validate_polygons(&p, Operand::Subject).is_err(), "{name} accepted");
    }
}

#[test]
fn near_coincident_clips_lie_within_a_millionth_of_the_extent_of_their_subjects() {
    for index in 0..30 {
        let c = polygon_case("near-coincident", 1, index, WindowKind::Any).unwrap();
        let extent = c.subject.bounds().extent();
        let kind = ["turned", "shifted", "traced"][index % 3];
        assert!(c.description.contains(kind), "{}", c.description);
        // Every clip vertex is near the subject's boundary (the traced kind pulls one edge in six
        // a few per cent off), and a clip is the subject itself only where the case says so.
        let off = |q: clip_core::Point| {
            c.subject
                .edges()
                .map(|e| clip_core::predicates::orient2d(e.a, e.b, q).abs() / e.length())
                .fold(f64::MAX, f64::min)
        };
        let near = c.clip.points().filter(|&&q| off(q) <= 1e-6 * extent).count();
        let want = if kind == "traced" { c.clip.vertex_count() / 2 } else { c.clip.vertex_count() };
        assert!(near >= want, "{}: {near} of {} vertices near the subject", c.description, c.clip.vertex_count());
        let copy = c.clip.rings[0] == c.subject.rings[0] || c.clip.rings[0] == c.subject.rings[0].reversed();
        assert_eq!(copy, c.description.contains("exact copy"), "{}", c.description);
    }
    let sized = polygon_case_sized("near-coincident", 1, 0, 10_000, WindowKind::Any).unwrap();
    let n = sized.subject.vertex_count();
    assert!((9_000..=11_000).contains(&n), "{n}");
}
