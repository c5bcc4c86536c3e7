//! Failure records read back: the WKT parses with the `wkt` crate to the same coordinates.

use clip_core::{Polygons, WindowKind};
use clip_testkit::case_record::*;
use clip_testkit::workload::{line_case, polygon_case};
use std::str::FromStr;

fn parse(text: &str) -> wkt::Wkt<f64> {
    wkt::Wkt::from_str(text).unwrap_or_else(|e| panic!("{e}: {text}"))
}

#[test]
fn polygon_wkt_round_trips_exactly() {
    for w in ["star", "holes", "grid", "utm"] {
        let p: Polygons = if w == "utm" {
            clip_testkit::workload::hard_cases().into_iter().find(|c| c.name == "utm-coordinates").unwrap().clip
        } else {
            polygon_case(w, 4, 0, WindowKind::Any).unwrap().subject
        };
        let geometry: geo_types::Geometry<f64> = parse(&polygons_to_wkt(&p, false)).try_into().unwrap();
        let geo_types::Geometry::MultiPolygon(mp) = geometry else { panic!("not a multipolygon") };
        assert_eq!(mp.0.len(), p.rings.len());
        for (poly, ring) in mp.0.iter().zip(&p.rings) {
            let coords: Vec<(f64, f64)> = poly.exterior().coords().map(|c| (c.x, c.y)).collect();
            let mut want: Vec<(f64, f64)> = ring.points.iter().map(|q| (q.x, q.y)).collect();
            want.push(want[0]);
            assert_eq!(coords, want);
        }
    }
}

#[test]
fn nested_wkt_and_segments_parse() {
    let case = polygon_case("holes", 2, 0, WindowKind::Any).unwrap();
    let geometry: geo_types::Geometry<f64> = parse(&polygons_to_wkt(&case.subject, true)).try_into().unwrap();
    let geo_types::Geometry::MultiPolygon(mp) = geometry else { panic!("not a multipolygon") };
    assert_eq!(mp.0.len(), 1);
    assert_eq!(mp.0[0].interiors().len(), case.subject.rings.len() - 1);
    let lines = line_case("wang-t4", 1, 0, WindowKind::Any, 20).unwrap();
    let geometry: geo_types::Geometry<f64> = parse(&segments_to_wkt(&lines.segments)).try_into().unwrap();
    let geo_types::Geometry::MultiLineString(ml) = geometry else { panic!("not a multilinestring") };
    assert_eq!(ml.0.len(), 20);
    assert_eq!((ml.0[3].0[1].x, ml.0[3].0[1].y), (lines.segments[3].b.x, lines.segments[3].b.y));
}

#[test]
fn pictures_show_every_input_and_output() {
    let case = polygon_case("multi", 1, 0, WindowKind::Any).unwrap();
    let svg = polygons_svg(&case.subject, &case.clip, &[("geo", &case.subject), ("clipper2", &case.clip)]);
    assert_eq!(svg.matches("<path").count(), 4);
    assert!(svg.contains("geo: ") && svg.contains("clipper2: "));
    let lines = line_case("lines-degenerate", 1, 0, WindowKind::Any, 10).unwrap();
    let svg = lines_svg(&lines.window, &lines.segments, &[]);
    assert_eq!(svg.matches("<line").count(), 10);
}
