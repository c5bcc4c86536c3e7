//! `From`/`Into` conversions with `geo-types` (feature `geo`).

use geo_types::{Coord, LineString, MultiPolygon, Polygon};

use crate::nesting::nest;
use crate::{Point, Polygons, Rect, Ring, Segment};

impl From<Coord<f64>> for Point {
    fn from(c: Coord<f64>) -> Point {
        Point::new(c.x, c.y)
    }
}

impl From<Point> for Coord<f64> {
    fn from(p: Point) -> Coord<f64> {
        Coord { x: p.x, y: p.y }
    }
}

impl From<geo_types::Point<f64>> for Point {
    fn from(p: geo_types::Point<f64>) -> Point {
        p.0.into()
    }
}

impl From<Point> for geo_types::Point<f64> {
    fn from(p: Point) -> geo_types::Point<f64> {
        geo_types::Point(p.into())
    }
}

impl From<geo_types::Line<f64>> for Segment {
    fn from(l: geo_types::Line<f64>) -> Segment {
        Segment::new(l.start.into(), l.end.into())
    }
}

impl From<Segment> for geo_types::Line<f64> {
    fn from(s: Segment) -> geo_types::Line<f64> {
        geo_types::Line::new(Coord::from(s.a), Coord::from(s.b))
    }
}

impl From<&LineString<f64>> for Ring {
    /// A closed line string's repeated closing vertex is dropped.
    fn from(ls: &LineString<f64>) -> Ring {
        Ring::new(ls.0.iter().map(|&c| c.into()).collect())
    }
}

impl From<&Ring> for LineString<f64> {
    /// The line string is closed explicitly, as geo-types expects of a polygon ring.
    fn from(r: &Ring) -> LineString<f64> {
        let mut coords: Vec<Coord<f64>> = r.points.iter().map(|&p| p.into()).collect();
        if let Some(&first) = coords.first() {
            coords.push(first);
        }
        LineString(coords)
    }
}

impl From<&Polygon<f64>> for Polygons {
    /// Exterior then interiors, each as a ring with the orientation it has.
    fn from(p: &Polygon<f64>) -> Polygons {
        let mut rings = Vec::with_capacity(1 + p.interiors().len());
        if !p.exterior().0.is_empty() {
            rings.push(Ring::from(p.exterior()));
        }
        rings.extend(p.interiors().iter().map(Ring::from));
        Polygons::new(rings)
    }
}

impl From<&MultiPolygon<f64>> for Polygons {
    /// Every ring of every polygon, each with the orientation it has.
    fn from(mp: &MultiPolygon<f64>) -> Polygons {
        Polygons::new(mp.0.iter().flat_map(|p| Polygons::from(p).rings).collect())
    }
}

impl From<&Polygons> for MultiPolygon<f64> {
    /// For output that follows the convention (simple rings, outers counter-clockwise, holes
    /// clockwise): holes are nested into the outers that hold them (see [`crate::nest`]).
    fn from(p: &Polygons) -> MultiPolygon<f64> {
        MultiPolygon(
            nest(p)
                .iter()
                .map(|n| Polygon::new((&n.outer).into(), n.holes.iter().map(LineString::from).collect()))
                .collect(),
        )
    }
}

impl From<Rect> for geo_types::Rect<f64> {
    fn from(r: Rect) -> geo_types::Rect<f64> {
        geo_types::Rect::new(Coord::from(r.min), Coord::from(r.max))
    }
}

impl From<geo_types::Rect<f64>> for Rect {
    fn from(r: geo_types::Rect<f64>) -> Rect {
        Rect::from_points(r.min().into(), r.max().into())
    }
}
