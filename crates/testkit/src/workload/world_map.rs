//! The world map kept in `testdata/world/`: Natural Earth's admin-0 countries at three scales,
//! from the npm package world-atlas (format: `testdata/world/FORMAT.md`; made by
//! `scripts/world_map.sh`). Each file is read once per process.

use clip_core::{Point, Ring};
use core::fmt;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// A scale of the world map: Natural Earth's 1:110m, 1:50m and 1:10m.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MapScale {
    /// 1:110m, about 10^4 vertices.
    Small,
    /// 1:50m, about 10^5 vertices.
    Medium,
    /// 1:10m, about 5·10^5 vertices.
    Large,
}

impl MapScale {
    /// The three scales, coarse to fine.
    pub const ALL: [MapScale; 3] = [MapScale::Small, MapScale::Medium, MapScale::Large];

    /// Natural Earth's name of the scale (`110m`, `50m`, `10m`).
    pub fn name(self) -> &'static str {
        match self {
            MapScale::Small => "110m",
            MapScale::Medium => "50m",
            MapScale::Large => "10m",
        }
    }

    /// The vertices of every country at this scale (what `testdata/world/README.md` lists; the
    /// testkit's tests check them against the files).
    pub fn edges(self) -> usize {
        match self {
            MapScale::Small => 10_299,
            MapScale::Medium => 97_656,
            MapScale::Large => 540_564,
        }
    }

    /// The scale whose [`Self::edges`] is nearest to `edges` (by ratio).
    pub fn nearest(edges: usize) -> MapScale {
        let off = |s: MapScale| (s.edges() as f64 / edges.max(1) as f64).ln().abs();
        MapScale::ALL.into_iter().min_by(|&a, &b| off(a).total_cmp(&off(b))).unwrap_or(MapScale::Small)
    }

    /// The file under the testdata folder.
    pub fn file(self) -> PathBuf {
        crate::testdata_dir().join("world").join(format!("countries-{}.txt", self.name()))
    }
}

/// One country: its rings (exteriors counter-clockwise, enclaves' holes clockwise).
#[derive(Clone, Debug, PartialEq)]
pub struct Country {
    /// ISO 3166-1 numeric code, or `-` where Natural Earth gives none.
    pub id: String,
    /// The name.
    pub name: String,
    /// The rings.
    pub rings: Vec<Ring>,
}

/// The countries of one scale, in the file's order, and which share a border.
#[derive(Debug)]
pub struct WorldMap {
    /// The scale.
    pub scale: MapScale,
    /// The countries.
    pub countries: Vec<Country>,
    /// Per country, the countries sharing at least one edge with it, ascending.
    pub neighbours: Vec<Vec<usize>>,
}

impl WorldMap {
    /// All vertices.
    pub fn vertex_count(&self) -> usize {
        self.countries.iter().flat_map(|c| &c.rings).map(Ring::len).sum()
    }
}

/// A map file that could not be read, or a line of it that is not in the format.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MapDataError {
    /// The file.
    pub path: PathBuf,
    /// The line (1-based), or 0 for the file as a whole.
    pub line: usize,
    /// What is wrong.
    pub problem: String,
}

impl fmt::Display for MapDataError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "world map {}: {}", self.path.display(), self.problem)
        } else {
            write!(f, "world map {} line {}: {}", self.path.display(), self.line, self.problem)
        }
    }
}

impl std::error::Error for MapDataError {}

/// The map at `scale`, read from the testdata folder on first use.
pub fn world_map(scale: MapScale) -> Result<&'static WorldMap, MapDataError> {
    static MAPS: [OnceLock<Result<WorldMap, MapDataError>>; 3] = [OnceLock::new(), OnceLock::new(), OnceLock::new()];
    let slot = &MAPS[MapScale::ALL.iter().position(|&s| s == scale).unwrap_or(0)];
    slot.get_or_init(|| {
        let path = scale.file();
        let text = std::fs::read_to_string(&path).map_err(|e| MapDataError {
            path: path.clone(),
            line: 0,
            problem: format!("cannot read it: {e}"),
        })?;
        parse_world_map(&text, &path, scale)
    })
    .as_ref()
    .map_err(Clone::clone)
}

/// Reads a map file's text (`path` names it in errors).
pub fn parse_world_map(text: &str, path: &Path, scale: MapScale) -> Result<WorldMap, MapDataError> {
    let error = |line: usize, problem: String| MapDataError { path: path.to_owned(), line, problem };
    let mut transform: Option<[f64; 4]> = None;
    let mut countries: Vec<Country> = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let at = i + 1;
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let (keyword, rest) = line.split_once(' ').unwrap_or((line, ""));
        match keyword {
            "transform" => {
                let numbers: Vec<f64> = rest
                    .split_whitespace()
                    .map(|w| w.parse::<f64>().map_err(|_| error(at, format!("'{w}' is not a number"))))
                    .collect::<Result<_, _>>()?;
                match numbers[..] {
                    [kx, ky, tx, ty] if numbers.iter().all(|v| v.is_finite()) && kx > 0.0 && ky > 0.0 => {
                        transform = Some([kx, ky, tx, ty]);
                    }
                    _ => {
                        return Err(error(
                            at,
                            "transform wants four finite numbers: scale x, y > 0, translate x, y".into(),
                        ));
                    }
                }
            }
            "country" => {
                let (id, name) = rest.split_once(' ').unwrap_or((rest, ""));
                if id.is_empty() || name.trim().is_empty() {
                    return Err(error(at, "country wants an id and a name".into()));
                }
                countries.push(Country { id: id.to_owned(), name: name.trim().to_owned(), rings: Vec::new() });
            }
            "ring" => {
                let [kx, ky, tx, ty] = transform.ok_or_else(|| error(at, "a ring before the transform".into()))?;
                let country = countries.last_mut().ok_or_else(|| error(at, "a ring before any country".into()))?;
                let words: Vec<i64> = rest
                    .split_whitespace()
                    .map(|w| w.parse::<i64>().map_err(|_| error(at, format!("'{w}' is not an integer"))))
                    .collect::<Result<_, _>>()?;
                if !words.len().is_multiple_of(2) || words.len() < 6 {
                    return Err(error(at, format!("a ring wants at least 3 x y pairs, got {} numbers", words.len())));
                }
                let (mut qx, mut qy) = (0i64, 0i64);
                let mut points = Vec::with_capacity(words.len() / 2);
                for pair in words.chunks_exact(2) {
                    qx = qx.checked_add(pair[0]).ok_or_else(|| error(at, "a coordinate overflows".into()))?;
                    qy = qy.checked_add(pair[1]).ok_or_else(|| error(at, "a coordinate overflows".into()))?;
                    // topojson-client's arithmetic, so the coordinates are the ones it gives.
                    points.push(Point::new(qx as f64 * kx + tx, qy as f64 * ky + ty));
                }
                country.rings.push(Ring::new(points));
            }
            other => return Err(error(at, format!("unknown line '{other}' (expected transform, country or ring)"))),
        }
    }
    if countries.is_empty() {
        return Err(error(0, "no country in it".into()));
    }
    if let Some(c) = countries.iter().find(|c| c.rings.is_empty()) {
        return Err(error(0, format!("country '{}' has no ring", c.name)));
    }
    let neighbours = shared_borders(&countries);
    Ok(WorldMap { scale, countries, neighbours })
}

/// Per country, the others that have an edge with the same two ends (the file keeps shared
/// borders vertex for vertex).
fn shared_borders(countries: &[Country]) -> Vec<Vec<usize>> {
    let key = |a: Point, b: Point| {
        let (a, b) = ((a.x.to_bits(), a.y.to_bits()), (b.x.to_bits(), b.y.to_bits()));
        if a <= b { (a, b) } else { (b, a) }
    };
    let mut owner: HashMap<_, usize> = HashMap::new();
    let mut neighbours: Vec<Vec<usize>> = vec![Vec::new(); countries.len()];
    for (c, country) in countries.iter().enumerate() {
        for e in country.rings.iter().flat_map(Ring::edges) {
            match owner.get(&key(e.a, e.b)) {
                Some(&o) if o != c => {
                    neighbours[c].push(o);
                    neighbours[o].push(c);
                }
                Some(_) => {}
                None => {
                    owner.insert(key(e.a, e.b), c);
                }
            }
        }
    }
    for n in &mut neighbours {
        n.sort_unstable();
        n.dedup();
    }
    neighbours
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<WorldMap, MapDataError> {
        parse_world_map(text, Path::new("test.txt"), MapScale::Small)
    }

    #[test]
    fn rings_decode_from_deltas_through_the_transform() {
        let m = parse(
            "# a map\ntransform 0.5 2 -10 1\ncountry 1 A land\nring 0 0 4 0 0 4\ncountry - B\nring 4 0 0 4 -4 0\n",
        )
        .unwrap();
        assert_eq!(m.countries[0].name, "A land");
        assert_eq!(m.countries[1].id, "-");
        let a = &m.countries[0].rings[0].points;
        assert_eq!(a, &[Point::new(-10.0, 1.0), Point::new(-8.0, 1.0), Point::new(-8.0, 9.0)]);
        // A and B share the edge (4, 0)-(4, 4) in grid units, run the other way.
        assert_eq!(m.neighbours, vec![vec![1], vec![0]]);
    }

    #[test]
    fn bad_lines_are_named_with_their_number() {
        let cases = [
            ("transform 1 1 0 0\nring 0 0 1 0 0 1\n", 2, "before any country"),
            ("country 1 A\nring 0 0 1 0 0 1\n", 2, "before the transform"),
            ("transform 1 1 0 0\ncountry 1 A\nring 0 0 1 0\n", 3, "at least 3"),
            ("transform 1 1 0 0\ncountry 1 A\nring 0 0 1 x 0 1\n", 3, "'x' is not an integer"),
            ("transform 1 0 0 0\n", 1, "transform wants"),
            ("transform 1 1 0 0\npolygon\n", 2, "unknown line 'polygon'"),
            ("transform 1 1 0 0\ncountry 1 A\n", 0, "has no ring"),
            ("transform 1 1 0 0\n", 0, "no country"),
        ];
        for (text, line, problem) in cases {
            let e = parse(text).unwrap_err();
            assert_eq!(e.line, line, "{text:?}: {e}");
            assert!(e.to_string().contains(problem) && e.to_string().contains("test.txt"), "{e}");
        }
    }

    #[test]
    fn scales_are_picked_by_the_nearest_size() {
        assert_eq!(MapScale::nearest(100), MapScale::Small);
        assert_eq!(MapScale::nearest(100_000), MapScale::Medium);
        assert_eq!(MapScale::nearest(1_000_000), MapScale::Large);
    }
}
