//! Checks of a parsed WKT geometry before its conversion to geo types, which closes every ring
//! without a word: WKT requires a ring to end where it starts, and one that does not is refused
//! rather than closed by a guess at what was meant.

use wkt::Wkt;
use wkt::types::{Coord, Polygon};

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
}
