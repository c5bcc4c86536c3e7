//! Checks of GeoJSON geometries that must come before the geojson crate's conversion to geo
//! types: it indexes a position's x and y without looking, so a position `[0]` panics there, and
//! it closes every ring without a word, where GeoJSON requires a ring to end where it starts.

use geojson::{GeometryValue, Position};

use super::Place;

/// Whether a ring must end where it starts, as GeoJSON requires.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RingEnds {
    /// An open ring is an error naming it (files a user hands to `clip`).
    MustClose,
    /// An open ring is closed as geo's reader closes it (geo's own test fixtures hold one).
    MayBeOpen,
}

/// Checks every position of a geometry at `place` (two numbers or more, all finite) and, with
/// [`RingEnds::MustClose`], that every ring is closed; sets `beyond_xy` when a position has more
/// than x and y (a z).
pub fn check_geometry(
    value: &GeometryValue,
    place: &Place,
    ends: RingEnds,
    beyond_xy: &mut bool,
) -> Result<(), String> {
    let numbered = |part: &str, i: usize| place.then(format_args!("{part} {i}"));
    match value {
        GeometryValue::Point { coordinates } => check_position(coordinates, place, beyond_xy),
        GeometryValue::MultiPoint { coordinates } | GeometryValue::LineString { coordinates } => {
            check_positions(coordinates, place, beyond_xy)
        }
        GeometryValue::MultiLineString { coordinates } => coordinates
            .iter()
            .enumerate()
            .try_for_each(|(i, line)| check_positions(line, &numbered("line string", i), beyond_xy)),
        GeometryValue::Polygon { coordinates } => check_rings(coordinates, place, ends, beyond_xy),
        GeometryValue::MultiPolygon { coordinates } => coordinates
            .iter()
            .enumerate()
            .try_for_each(|(i, rings)| check_rings(rings, &numbered("polygon", i), ends, beyond_xy)),
        GeometryValue::GeometryCollection { geometries } => geometries
            .iter()
            .enumerate()
            .try_for_each(|(i, g)| check_geometry(&g.value, &numbered("member", i), ends, beyond_xy)),
    }
}

fn check_rings(rings: &[Vec<Position>], place: &Place, ends: RingEnds, beyond_xy: &mut bool) -> Result<(), String> {
    for (i, ring) in rings.iter().enumerate() {
        let place = place.then(format_args!("ring {i}"));
        check_positions(ring, &place, beyond_xy)?;
        // An empty ring encloses nothing: reading drops it with a note, as it does a ring of two
        // distinct points.
        let (Some(first), Some(last)) = (ring.first(), ring.last()) else { continue };
        if ends == RingEnds::MustClose && first.as_slice()[..2] != last.as_slice()[..2] {
            return Err(format!(
                "{place} is not closed: it starts at {} and ends at {} (a GeoJSON ring ends where it starts)",
                show(first.as_slice()),
                show(last.as_slice())
            ));
        }
    }
    Ok(())
}

fn check_positions(positions: &[Position], place: &Place, beyond_xy: &mut bool) -> Result<(), String> {
    positions
        .iter()
        .enumerate()
        .try_for_each(|(i, p)| check_position(p, &place.then(format_args!("position {i}")), beyond_xy))
}

fn check_position(position: &Position, place: &Place, beyond_xy: &mut bool) -> Result<(), String> {
    let numbers = position.as_slice();
    if numbers.len() < 2 {
        return Err(format!("{place} is {}: a position needs two numbers, x and y", show(numbers)));
    }
    if numbers.iter().any(|v| !v.is_finite()) {
        return Err(format!("{place} is {}: its numbers must be finite", show(numbers)));
    }
    *beyond_xy |= numbers.len() > 2;
    Ok(())
}

/// A position as it is written in GeoJSON: `[1, 2.5]`.
fn show(numbers: &[f64]) -> String {
    let numbers: Vec<String> = numbers.iter().map(f64::to_string).collect();
    format!("[{}]", numbers.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Checks a geometry read the way `read` reads it (`Geometry`'s own parser refuses short
    /// positions, `GeoJson`'s does not).
    /// Whether a position had a z, or the problem.
    fn check(json: &str) -> Result<bool, String> {
        let Ok(geojson::GeoJson::Geometry(g)) = json.parse() else { panic!("not a GeoJSON geometry: {json}") };
        let mut beyond_xy = false;
        check_geometry(&g.value, &Place::default().then("feature 3"), RingEnds::MustClose, &mut beyond_xy)
            .map(|()| beyond_xy)
    }

    #[test]
    fn geojson_position_of_one_number_is_an_error() {
        let problem = check(r#"{"type":"Polygon","coordinates":[[[0,0],[1,0],[0],[0,0]]]}"#).unwrap_err();
        assert_eq!(problem, "feature 3, ring 0, position 2 is [0]: a position needs two numbers, x and y");
        let problem = check(r#"{"type":"MultiLineString","coordinates":[[[0,0],[1,1]],[[2,2],[]]]}"#).unwrap_err();
        assert_eq!(problem, "feature 3, line string 1, position 1 is []: a position needs two numbers, x and y");
        // Inside a collection the parser refuses it itself; a value built in code gets here.
        let point = geojson::Geometry::new(GeometryValue::Point { coordinates: vec![7.0].into() });
        let collection = GeometryValue::GeometryCollection { geometries: vec![point] };
        let problem = check_geometry(&collection, &Place::default(), RingEnds::MustClose, &mut false).unwrap_err();
        assert_eq!(problem, "member 0 is [7]: a position needs two numbers, x and y");
        assert_eq!(check(r#"{"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[1,1],[0,0]]]]}"#), Ok(false));
        assert_eq!(check(r#"{"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[1,1,5],[0,0]]]]}"#), Ok(true), "a z");
    }

    #[test]
    fn geojson_unclosed_ring_is_an_error_naming_the_ring() {
        let problem =
            check(r#"{"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[1,1],[0,0]]],[[[0,0],[1,0],[1,1]]]]}"#);
        assert_eq!(
            problem.unwrap_err(),
            "feature 3, polygon 1, ring 0 is not closed: it starts at [0, 0] and ends at [1, 1] (a GeoJSON ring ends \
             where it starts)"
        );
        assert_eq!(
            check(r#"{"type":"Polygon","coordinates":[[]]}"#),
            Ok(false),
            "an empty ring is read (then dropped)"
        );
        // A z that differs does not open a ring: only x and y are read.
        assert_eq!(check(r#"{"type":"Polygon","coordinates":[[[0,0,1],[1,0,1],[1,1,1],[0,0,2]]]}"#), Ok(true));
        assert_eq!(check(r#"{"type":"Polygon","coordinates":[]}"#), Ok(false), "the empty polygon");
    }

    #[test]
    fn geojson_position_that_is_not_finite_is_an_error() {
        // JSON has no NaN or infinity, but a GeoJSON value built in code can hold them.
        let value = GeometryValue::LineString { coordinates: vec![vec![0.0, 0.0].into(), vec![f64::NAN, 1.0].into()] };
        let problem = check_geometry(&value, &Place::default(), RingEnds::MustClose, &mut false).unwrap_err();
        assert_eq!(problem, "position 1 is [NaN, 1]: its numbers must be finite");
    }
}
