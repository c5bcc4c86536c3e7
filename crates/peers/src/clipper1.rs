//! Angus Johnson's Clipper 1 (C++, through the `geo-clipper` crate) as a polygon clipper.

use clip_clipper2_rect::IntegerGrid;
use clip_core::{
    BoolOp, ClipError, FillRule, Operand, OutputForm, PolygonCapabilities, PolygonClipper, Polygons, Ring, WindowKind,
    validate_polygons,
};
use geo::{Coord, LineString, MultiPolygon, Polygon};
use geo_clipper::Clipper;

/// Clipper 1's boolean operations, non-zero fill only.
///
/// `geo-clipper` always calls Clipper 1 with `pftNonZero` for both operands, so this adapter
/// declares non-zero alone: `verify`, `conformance` and `bench` run it only under that rule
/// (`bench`, which reads its cases under even-odd, times it under non-zero only where every
/// operand covers the same region under both rules). Coordinates go through the same fitted integer grid as the Clipper2 peers (step
/// about extent x 2^-30, inside Clipper 1's fast 2^30 range); `geo-clipper` is given them as
/// whole numbers with a factor of 1, so its truncation to integers changes nothing. Each of our
/// rings becomes the exterior of its own polygon, in order, orientation kept. Output: every
/// polygon's exterior turned counter-clockwise and its holes clockwise, moved back off the grid.
#[derive(Clone, Copy, Debug, Default)]
pub struct Clipper1Clipper;

impl Clipper1Clipper {
    /// The adapter (it holds no state).
    pub fn new() -> Clipper1Clipper {
        Clipper1Clipper
    }
}

fn on_grid(p: &Polygons, grid: IntegerGrid) -> MultiPolygon<f64> {
    MultiPolygon(
        p.rings
            .iter()
            .map(|r| {
                let mut coords: Vec<Coord<f64>> = r
                    .points
                    .iter()
                    .map(|&q| {
                        let [x, y] = grid.to_grid(q);
                        Coord { x: x as f64, y: y as f64 }
                    })
                    .collect();
                coords.push(coords[0]);
                Polygon::new(LineString(coords), Vec::new())
            })
            .collect(),
    )
}

fn off_grid(ring: &LineString<f64>, grid: IntegerGrid, counter_clockwise: bool) -> Ring {
    let mut points: Vec<_> = ring.0.iter().map(|c| grid.to_point([c.x as i64, c.y as i64])).collect();
    if points.len() > 1 && points.first() == points.last() {
        points.pop();
    }
    let ring = Ring::new(points);
    if (ring.signed_area() > 0.0) == counter_clockwise { ring } else { ring.reversed() }
}

impl PolygonClipper for Clipper1Clipper {
    fn name(&self) -> &'static str {
        "clipper1"
    }

    fn capabilities(&self) -> PolygonCapabilities {
        PolygonCapabilities {
            ops: &BoolOp::ALL,
            fill_rules: &[FillRule::NonZero],
            window: WindowKind::Any,
            trapezoids: false,
            bridges: false,
            output: OutputForm::Conventional,
        }
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        self.capabilities().check(self.name(), op, fill)?;
        validate_polygons(subject, Operand::Subject)?;
        validate_polygons(clip, Operand::Clip)?;
        let grid = IntegerGrid::fitting(subject.bounds().union(clip.bounds()));
        let (a, b) = (on_grid(subject, grid), on_grid(clip, grid));
        let out = match op {
            BoolOp::Intersection => a.intersection(&b, 1.0),
            BoolOp::Union => a.union(&b, 1.0),
            BoolOp::Difference => a.difference(&b, 1.0),
            BoolOp::Xor => a.xor(&b, 1.0),
        };
        let mut rings = Vec::new();
        for polygon in &out.0 {
            rings.push(off_grid(polygon.exterior(), grid, true));
            rings.extend(polygon.interiors().iter().map(|hole| off_grid(hole, grid, false)));
        }
        rings.retain(|r| r.len() >= 3);
        Ok(Polygons::new(rings))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::Rect;

    #[test]
    fn every_op_on_overlapping_squares() {
        let a = Polygons::from(Rect::new(0.0, 0.0, 2.0, 2.0));
        let b = Polygons::from(Rect::new(1.0, 1.0, 3.0, 3.0).to_ring().reversed());
        for (op, area) in
            [(BoolOp::Intersection, 1.0), (BoolOp::Union, 7.0), (BoolOp::Difference, 3.0), (BoolOp::Xor, 6.0)]
        {
            let out = Clipper1Clipper.clip(&a, &b, op, FillRule::NonZero).unwrap();
            assert_eq!(out.signed_area(), area, "{op}: {out:?}");
        }
    }

    #[test]
    fn holes_come_out_clockwise_and_other_rules_are_refused() {
        let a = Polygons::from(Rect::new(0.0, 0.0, 4.0, 4.0));
        let b = Polygons::from(Rect::new(1.0, 1.0, 2.0, 2.0));
        let out = Clipper1Clipper.clip(&a, &b, BoolOp::Difference, FillRule::NonZero).unwrap();
        let mut areas: Vec<f64> = out.rings.iter().map(Ring::signed_area).collect();
        areas.sort_by(f64::total_cmp);
        assert_eq!(areas, vec![-1.0, 16.0]);
        assert!(matches!(
            Clipper1Clipper.clip(&a, &b, BoolOp::Union, FillRule::EvenOdd),
            Err(ClipError::Unsupported { clipper: "clipper1", .. })
        ));
    }
}
