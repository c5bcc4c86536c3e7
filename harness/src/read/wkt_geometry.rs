//! Checks of a parsed WKT geometry before its conversion to geo types, which closes every ring
//! and drops z and m values without a word. WKT requires a ring to end where it starts: one that
//! does not is refused rather than closed by a guess at what was meant. Z and m are dropped as
//! before (clipping is in the plane), but said.

use wkt::Wkt;
use wkt::types::{Coord, Dimension, Polygon};

use super::Place;

/// Checks that every ring of the polygons in `wkt` (at `place`) is closed.
pub fn check_rings(wkt: &Wkt<f64>, place: &Place) -> Result<(), String> {
    match wkt {
        Wkt::Polygon(p) => check_polygon(p, place),
        Wkt::MultiPolygon(mp) => mp
            .polygons()
            .iter()
            .enumerate()
            .try_for_each(|(i, p)| check_polygon(p, &place.then(format_args!("polygon {i}")))),
        Wkt::GeometryCollection(gc) => gc
            .geometries()
            .iter()
            .enumerate()
            .try_for_each(|(i, g)| check_rings(g, &place.then(format_args!("member {i}")))),
        Wkt::Point(_) | Wkt::LineString(_) | Wkt::MultiPoint(_) | Wkt::MultiLineString(_) => Ok(()),
    }
}

fn check_polygon(polygon: &Polygon<f64>, place: &Place) -> Result<(), String> {
    for (i, ring) in polygon.rings().iter().enumerate() {
        let (Some(first), Some(last)) = (ring.coords().first(), ring.coords().last()) else { continue };
        if (first.x, first.y) != (last.x, last.y) {
            return Err(format!(
                "{} is not closed: it starts at {} and ends at {} (a WKT ring ends where it starts)",
                place.then(format_args!("ring {i}")),
                show(first),
                show(last)
            ));
        }
    }
    Ok(())
}

/// What the conversion drops from `wkt` (`POLYGON Z`, `POLYGON M`, `POLYGON ZM`, anywhere in
/// a collection), as a note; `None` when it is all x and y.
pub fn dropped(wkt: &Wkt<f64>) -> Option<String> {
    let (mut z, mut m) = (false, false);
    let mut pending = vec![wkt];
    while let Some(g) = pending.pop() {
        let dimension = g.dimension();
        z |= matches!(dimension, Dimension::XYZ | Dimension::XYZM);
        m |= matches!(dimension, Dimension::XYM | Dimension::XYZM);
        if let Wkt::GeometryCollection(gc) = g {
            pending.extend(gc.geometries());
        }
    }
    let what = match (z, m) {
        (false, false) => return None,
        (true, false) => "z coordinates",
        (false, true) => "m values",
        (true, true) => "z coordinates and m values",
    };
    Some(format!("{what} dropped: clipping is in the plane"))
}

/// A point as WKT writes it: `1 2.5`.
fn show(c: &Coord<f64>) -> String {
    format!("{} {}", c.x, c.y)
}

#[cfg(test)]
mod tests {
    use std::str::FromStr;

    use super::*;

    fn check(text: &str) -> Result<(), String> {
        check_rings(&Wkt::from_str(text).unwrap(), &Place::default())
    }

    #[test]
    fn wkt_unclosed_ring_is_an_error_naming_the_ring() {
        assert_eq!(
            check("POLYGON((0 0,4 0,4 4,0 0),(1 1,2 1,2 2,1 2))").unwrap_err(),
            "ring 1 is not closed: it starts at 1 1 and ends at 1 2 (a WKT ring ends where it starts)"
        );
        let problem = check("GEOMETRYCOLLECTION(POINT(0 0),MULTIPOLYGON(((0 0,1 0,1 1,0 0)),((0 0,1 0,1 1))))");
        assert!(
            problem
                .unwrap_err()
                .starts_with("member 1, polygon 1, ring 0 is not closed: it starts at 0 0 and ends at 1 1")
        );
        assert!(check("MULTIPOLYGON(((0 0,1 0,1 1,0 0)),EMPTY)").is_ok());
        assert!(check("LINESTRING(0 0,1 0,1 1)").is_ok(), "line strings need not close");
    }

    #[test]
    fn wkt_z_and_m_are_dropped_with_a_note() {
        let note = |text| dropped(&Wkt::from_str(text).unwrap());
        assert_eq!(note("POLYGON((0 0,1 0,1 1,0 0))"), None);
        assert_eq!(
            note("POLYGON Z((0 0 5,1 0 5,1 1 5,0 0 5))").unwrap(),
            "z coordinates dropped: clipping is in the plane"
        );
        assert_eq!(note("POLYGONM((0 0 5,1 0 5,1 1 5,0 0 5))").unwrap(), "m values dropped: clipping is in the plane");
        assert_eq!(
            note("GEOMETRYCOLLECTION(POLYGON((0 0,1 0,1 1,0 0)),LINESTRING ZM(0 0 1 2,1 1 1 2))").unwrap(),
            "z coordinates and m values dropped: clipping is in the plane"
        );
    }
}
