//! `maps`: what map users run on real layers (the world map of [`super::world_map`]), where
//! neighbouring countries share their borders vertex for vertex. Case `index mod 3` picks the
//! operation's setting:
//!
//! - 0, a dissolve (∪): the countries split into two operands by their order in the file, even
//!   places the subject and odd ones the clip, so the union must remove every border between
//!   them (about half of all borders; a border inside one operand goes too, as its two rings
//!   meet there). Two operands rather than one with an empty clip, so no clipper can hand the
//!   subject back as it came.
//! - 1, tiles (∩): every country against a grid of square tiles that share their edges.
//! - 2, neighbours (−): one country minus the countries that share a border with it.

use clip_core::{Point, Polygons, Rect, Ring};
use rand::Rng;
use rand_pcg::Pcg64;

use super::world_map::{Country, WorldMap};

/// The most edges a `maps` case without a size has (the country and its neighbours at 1:110m),
/// so the oracle's exact checks stay affordable.
pub const MAP_CASE_EDGES: usize = 400;

/// The tiles of a sized `tiles` case: 10° squares over [-180°, 180°] x [-80°, 80°], which cut
/// Antarctica, Greenland and the rings that run past the antimeridian.
const WORLD_TILE: f64 = 10.0;

/// What a `maps` case does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum MapCase {
    Dissolve,
    Tiles,
    Neighbours,
}

impl MapCase {
    pub(crate) fn of(index: usize) -> MapCase {
        match index % 3 {
            0 => MapCase::Dissolve,
            1 => MapCase::Tiles,
            _ => MapCase::Neighbours,
        }
    }
}

fn rings_of<'a>(countries: impl IntoIterator<Item = &'a Country>) -> Polygons {
    Polygons::new(countries.into_iter().flat_map(|c| c.rings.iter().cloned()).collect())
}

/// `cols` x `rows` counter-clockwise square tiles of side `side` from `origin`, each corner
/// computed from its grid index so neighbours share corners and edges exactly.
fn tiles(origin: Point, side: f64, cols: usize, rows: usize) -> Polygons {
    let at = |k: usize, o: f64| o + k as f64 * side;
    let mut rings = Vec::with_capacity(cols * rows);
    for i in 0..cols {
        for j in 0..rows {
            rings.push(Rect::new(at(i, origin.x), at(j, origin.y), at(i + 1, origin.x), at(j + 1, origin.y)).to_ring());
        }
    }
    Polygons::new(rings)
}

/// The countries by how many neighbours they have, most first (ties in file order).
fn by_neighbours(map: &WorldMap) -> Vec<usize> {
    let mut order: Vec<usize> = (0..map.countries.len()).collect();
    order.sort_by_key(|&c| std::cmp::Reverse(map.neighbours[c].len()));
    order
}

/// A case over the whole map: case `index` of [`MapCase::of`]; for `Neighbours` the country is
/// the one ranked `index / 3` by [`by_neighbours`].
pub(crate) fn whole_map(map: &WorldMap, index: usize) -> (Polygons, Polygons, String) {
    let scale = map.scale.name();
    match MapCase::of(index) {
        MapCase::Dissolve => {
            let subject = rings_of(map.countries.iter().step_by(2));
            let clip = rings_of(map.countries.iter().skip(1).step_by(2));
            let what = format!(
                "maps {scale} dissolve: {} countries ({} edges) ∪ the other {} ({} edges), alternating in file order",
                map.countries.len().div_ceil(2),
                subject.vertex_count(),
                map.countries.len() / 2,
                clip.vertex_count()
            );
            (subject, clip, what)
        }
        MapCase::Tiles => {
            let subject = rings_of(&map.countries);
            let clip = tiles(Point::new(-180.0, -80.0), WORLD_TILE, 36, 16);
            let what = format!(
                "maps {scale} tiles: {} countries ({} edges) ∩ 36 x 16 tiles of {WORLD_TILE}° sharing their edges",
                map.countries.len(),
                subject.vertex_count()
            );
            (subject, clip, what)
        }
        MapCase::Neighbours => {
            let order = by_neighbours(map);
            let c = order[(index / 3) % order.len()];
            neighbours_case(map, c)
        }
    }
}

fn neighbours_case(map: &WorldMap, c: usize) -> (Polygons, Polygons, String) {
    let country = &map.countries[c];
    let subject = rings_of([country]);
    let clip = rings_of(map.neighbours[c].iter().map(|&n| &map.countries[n]));
    let what = format!(
        "maps {} neighbours: {} ({} edges) − its {} neighbours ({} edges)",
        map.scale.name(),
        country.name,
        subject.vertex_count(),
        map.neighbours[c].len(),
        clip.vertex_count()
    );
    (subject, clip, what)
}

/// A small case around one country (for verify): a country with at least one neighbour and at
/// most [`MAP_CASE_EDGES`] edges with them, drawn by `rng`. `Dissolve` splits the country and
/// its neighbours alternately (in file order) into the two operands; `Tiles` is the country
/// against a random block (at least a third of the grid each way) of a grid of whole-degree
/// tiles over its bounding box, about three to its longer side; `Neighbours` as for the whole map.
pub(crate) fn around_a_country(map: &WorldMap, rng: &mut Pcg64, index: usize) -> (Polygons, Polygons, String) {
    let edges = |c: usize| map.countries[c].rings.iter().map(Ring::len).sum::<usize>();
    let eligible: Vec<usize> = (0..map.countries.len())
        .filter(|&c| {
            !map.neighbours[c].is_empty()
                && edges(c) + map.neighbours[c].iter().map(|&n| edges(n)).sum::<usize>() <= MAP_CASE_EDGES
        })
        .collect();
    let c = eligible[rng.random_range(0..eligible.len())];
    let scale = map.scale.name();
    let country = &map.countries[c];
    match MapCase::of(index) {
        MapCase::Dissolve => {
            let mut cluster = map.neighbours[c].clone();
            cluster.push(c);
            cluster.sort_unstable();
            let subject = rings_of(cluster.iter().step_by(2).map(|&k| &map.countries[k]));
            let clip = rings_of(cluster.iter().skip(1).step_by(2).map(|&k| &map.countries[k]));
            let what = format!(
                "maps {scale} dissolve around {}: {} countries ({} edges) ∪ {} ({} edges)",
                country.name,
                cluster.len().div_ceil(2),
                subject.vertex_count(),
                cluster.len() / 2,
                clip.vertex_count()
            );
            (subject, clip, what)
        }
        MapCase::Tiles => {
            let subject = rings_of([country]);
            let b = subject.bounds();
            let side = (b.width().max(b.height()) / 3.0).ceil().max(1.0);
            let (x0, y0) = ((b.min.x / side).floor(), (b.min.y / side).floor());
            let cols = ((b.max.x / side).ceil() - x0) as usize;
            let rows = ((b.max.y / side).ceil() - y0) as usize;
            // A block of at least a third of the grid each way, so most cases cut the country.
            let (c0, r0) = (rng.random_range(0..=cols / 3), rng.random_range(0..=rows / 3));
            let c1 = rng.random_range((c0 + 1).max(2 * cols / 3)..=cols);
            let r1 = rng.random_range((r0 + 1).max(2 * rows / 3)..=rows);
            let origin = Point::new((x0 + c0 as f64) * side, (y0 + r0 as f64) * side);
            let clip = tiles(origin, side, c1 - c0, r1 - r0);
            let what = format!(
                "maps {scale} tiles: {} ({} edges) ∩ {} x {} tiles of {side}°",
                country.name,
                subject.vertex_count(),
                c1 - c0,
                r1 - r0
            );
            (subject, clip, what)
        }
        MapCase::Neighbours => neighbours_case(map, c),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tiles_share_corners_exactly() {
        let t = tiles(Point::new(-180.0, -80.0), 10.0, 36, 16);
        assert_eq!(t.rings.len(), 576);
        assert_eq!(t.bounds(), Rect::new(-180.0, -80.0, 180.0, 80.0));
        assert!(t.rings.iter().all(|r| r.signed_area() == 100.0));
    }

    #[test]
    fn case_kinds_cycle_with_the_index() {
        assert_eq!(MapCase::of(0), MapCase::Dissolve);
        assert_eq!(MapCase::of(4), MapCase::Tiles);
        assert_eq!(MapCase::of(5), MapCase::Neighbours);
    }
}
