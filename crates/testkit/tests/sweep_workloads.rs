//! The workloads that stress a sweep (`comb`, i_overlay's suite, `maps`): deterministic, about
//! the asked size, small enough for the oracle when unsized, and meaningful under the rules they
//! are meant for; and the world map they read loads at every scale.

use clip_core::{FillRule, Operand, Polygons, WindowKind, validate_polygons};
use clip_oracle::polygon::{region_area, same_region};
use clip_testkit::workload::*;

const SWEEP: &[&str] = SWEEP_WORKLOADS;

#[test]
fn the_sweep_workloads_are_the_comb_the_suite_and_the_maps() {
    assert_eq!(SWEEP[0], "comb");
    assert_eq!(SWEEP[SWEEP.len() - 1], "maps");
    assert!(SWEEP.iter().all(|w| POLYGON_WORKLOADS.contains(w)));
    assert!(!SWEEP.contains(&"many-subjects"));
}

fn edges(c: &PolygonCase) -> usize {
    c.subject.vertex_count() + c.clip.vertex_count()
}

#[test]
fn sized_cases_are_deterministic_and_within_a_factor_of_one_and_a_half_of_the_asked_edges() {
    // The suite's counts grow in steps (corrosion's from 48 to 141 edges near 100), so a sized
    // case lands within 1.5x of the ask; combs land within four edges of it.
    for w in SWEEP.iter().filter(|&&w| w != "maps") {
        for asked in [100, 1_000, 10_000, 100_000] {
            for index in [0, 1] {
                let a = polygon_case_sized(w, 7, index, asked, WindowKind::Any).unwrap();
                assert_eq!(a, polygon_case_sized(w, 7, index, asked, WindowKind::Any).unwrap(), "{w} {asked}");
                let ratio = edges(&a) as f64 / asked as f64;
                assert!((1.0 / 1.5..=1.5).contains(&ratio), "{}: {} edges for {asked}", a.description, edges(&a));
                if *w == "comb" {
                    assert!(edges(&a).abs_diff(asked) <= 4, "{}", a.description);
                }
            }
        }
    }
    // Maps: the scale nearest in edges; the dissolve splits every country between the operands.
    for scale in [MapScale::Small, MapScale::Medium] {
        for asked in [scale.edges() / 2, scale.edges(), scale.edges() * 2] {
            let c = polygon_case_sized("maps", 1, 0, asked, WindowKind::Any).unwrap();
            assert_eq!(edges(&c), scale.edges(), "{}", c.description);
        }
    }
}

#[test]
fn unsized_cases_stay_small_enough_for_the_oracle() {
    for &w in SWEEP {
        for index in 0..40 {
            let c = polygon_case(w, 5, index, WindowKind::Any).unwrap();
            // 6-200 edges drawn, the suite's step at most 1.5x; maps' country cases at most
            // MAP_CASE_EDGES, plus at most 5 x 5 tiles.
            let most = if w == "maps" { MAP_CASE_EDGES + 100 } else { 300 };
            assert!(edges(&c) <= most, "{}: {} edges", c.description, edges(&c));
            assert!(c.subject.vertex_count() >= 3, "{}", c.description);
        }
    }
}

/// The area an operand covers under even-odd.
fn area(p: &Polygons) -> f64 {
    region_area(&[(p, FillRule::EvenOdd)], |inside| inside[0])
}

/// Whether an operand covers the same region under even-odd and non-zero (no point wound twice).
fn reads_alike(p: &Polygons) -> bool {
    same_region((p, FillRule::EvenOdd), (p, FillRule::NonZero), 0.0).is_ok()
}

#[test]
fn operands_are_valid_and_read_alike_under_even_odd_and_non_zero_but_the_spirals() {
    let mut cases: Vec<PolygonCase> = Vec::new();
    for &w in SWEEP {
        cases.extend((0..6).map(|i| polygon_case(w, 11, i, WindowKind::Any).unwrap()));
        if w != "maps" {
            cases.extend((0..2).map(|i| polygon_case_sized(w, 11, i, 1_000, WindowKind::Any).unwrap()));
        }
    }
    // The whole map at 1:110m: its countries never overlap, so the bench's even-odd reads it as
    // non-zero does.
    cases.extend((0..3).map(|i| polygon_case_sized("maps", 11, i, 10_000, WindowKind::Any).unwrap()));
    for c in &cases {
        validate_polygons(&c.subject, Operand::Subject).unwrap_or_else(|e| panic!("{}: {e}", c.description));
        validate_polygons(&c.clip, Operand::Clip).unwrap_or_else(|e| panic!("{}: {e}", c.description));
        assert!(area(&c.subject) > 0.0, "{}: empty subject", c.description);
        if c.workload == "spiral" {
            // One self-crossing band with an empty clip (the suite's self-union): the crossings
            // at its joints are wound twice, so even-odd leaves notches that non-zero fills.
            assert!(c.clip.is_empty());
            assert!(!reads_alike(&c.subject), "{}", c.description);
        } else {
            assert!(reads_alike(&c.subject), "{}: subject", c.description);
            assert!(reads_alike(&c.clip), "{}: clip", c.description);
            assert!(area(&c.clip) > 0.0, "{}: empty clip", c.description);
        }
    }
}

#[test]
fn the_world_map_loads_at_every_scale_with_shared_borders() {
    for scale in MapScale::ALL {
        let map = world_map(scale).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(map.vertex_count(), scale.edges(), "{}", scale.name());
        assert!(map.countries.len() > 170, "{}", scale.name());
        let named = |name: &str| map.countries.iter().position(|c| c.name == name).unwrap();
        let (france, spain, china) = (named("France"), named("Spain"), named("China"));
        assert!(map.neighbours[france].contains(&spain) && map.neighbours[spain].contains(&france));
        assert!(map.neighbours[china].len() >= 12, "{}: China has {:?}", scale.name(), map.neighbours[china]);
        for (c, n) in map.neighbours.iter().enumerate() {
            assert!(n.iter().all(|&o| o != c && map.neighbours[o].contains(&c)), "{}", map.countries[c].name);
        }
        for country in &map.countries {
            // Exteriors counter-clockwise, enclaves' holes clockwise: each country has area.
            assert!(country.rings.iter().map(|r| r.signed_area()).sum::<f64>() > 0.0, "{}", country.name);
            for p in country.rings.iter().flat_map(|r| &r.points) {
                // Longitudes run past ±180° (Chukotka to -200°) where a ring was made continuous
                // across the antimeridian, never by a whole turn.
                assert!(p.x.abs() < 360.0 && (-90.0..=90.0).contains(&p.y), "{}: {p:?}", country.name);
            }
        }
    }
}
