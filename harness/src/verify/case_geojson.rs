//! A failure folder's case as GeoJSON (`case.geojson`), to open in QGIS or geojson.io: one
//! feature per input and per clipper's output, each ring as drawn (no nesting is inferred, since
//! an input may cross itself and is read under its fill rule), with a `role` and a `name`.

use clip_core::{Polygons, Segment};
use geo::{LineString, MultiLineString, MultiPolygon, Polygon};
use geojson::{Feature, FeatureCollection, Geometry, GeometryValue, JsonObject};

/// One layer of the case: its role (`subject`, `clip`, `window`, `segments`, `output`), name and
/// shapes.
pub enum Layer<'a> {
    /// Polygon rings.
    Rings(&'a str, &'a str, &'a Polygons),
    /// Line segments.
    Segments(&'a str, &'a str, &'a [Segment]),
}

/// The FeatureCollection of `layers`, with `fill` (the input's fill rule) on every feature.
pub fn case_geojson(layers: &[Layer], fill: Option<&str>) -> String {
    let features = layers.iter().map(|layer| {
        let (role, name, value) = match layer {
            Layer::Rings(role, name, polygons) => {
                let rings = polygons.rings.iter().map(|r| {
                    Polygon::new(LineString::from(r.points.iter().map(|p| (p.x, p.y)).collect::<Vec<_>>()), vec![])
                });
                (role, name, GeometryValue::from(&MultiPolygon(rings.collect())))
            }
            Layer::Segments(role, name, segments) => {
                let lines = segments.iter().map(|s| LineString::from(vec![(s.a.x, s.a.y), (s.b.x, s.b.y)]));
                (role, name, GeometryValue::from(&MultiLineString(lines.collect())))
            }
        };
        let mut properties = JsonObject::new();
        properties.insert("role".into(), (*role).into());
        properties.insert("name".into(), (*name).into());
        if let Some(fill) = fill {
            properties.insert("fill_rule".into(), fill.into());
        }
        Feature { geometry: Some(Geometry::new(value)), properties: Some(properties), ..Feature::default() }
    });
    FeatureCollection::from_iter(features).to_string() + "\n"
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::{Point, Rect};

    #[test]
    fn every_layer_is_a_feature_with_its_role_and_rings_as_drawn() {
        let square = Polygons::from(Rect::new(0.0, 0.0, 2.0, 2.0));
        let segments = [Segment::new(Point::new(-1.0, 1.0), Point::new(3.0, 1.0))];
        let text = case_geojson(
            &[
                Layer::Rings("subject", "subject", &square),
                Layer::Rings("output", "vatti", &Polygons::default()),
                Layer::Segments("segments", "segments", &segments),
            ],
            Some("even-odd"),
        );
        let back: FeatureCollection = text.parse().unwrap();
        assert_eq!(back.features.len(), 3);
        let role = |i: usize| back.features[i].properties.as_ref().unwrap()["role"].as_str().unwrap().to_owned();
        assert_eq!((role(0), role(1), role(2)), ("subject".into(), "output".into(), "segments".into()));
        assert!(text.contains("\"MultiPolygon\"") && text.contains("\"MultiLineString\"") && text.contains("even-odd"));
    }
}
