//! GEOS (the `geos` crate against the system libgeos) as a polygon clipper.

use clip_core::{
    BoolOp, ClipError, FailureKind, FillRule, Operand, Point, PolygonCapabilities, PolygonClipper, Polygons, Ring,
    validate_polygons, winding_number,
};
use geos::{CoordSeq, Geom, Geometry, GeometryTypes};

const NAME: &str = "geos";

/// GEOS's overlay (OverlayNG since GEOS 3.9): every op, every fill rule through the adapter.
///
/// GEOS takes only valid OGC polygons, so it cannot read a ring list under a fill rule itself.
/// The adapter builds each operand's region the way the fill rule defines it, with GEOS doing
/// the geometry: the rings' lines are noded together (`GEOSUnaryUnion` of the line work), the
/// noded lines polygonized into faces, and a face kept when the fill rule accepts the winding
/// number of our rings around an interior point of it (`GEOSPointOnSurface`; the winding number
/// is clip-core's exact one). The kept faces, unioned, are a valid polygon that GEOS then
/// intersects, unites, subtracts or symmetric-differences. So GEOS's own noding decides where
/// crossings fall, and the fill rule is applied exactly as docs/DESIGN.md defines it; a face so
/// thin that both its interior point and centroid fall on one of our edges is dropped (it has
/// no area above the rounding). The time includes that region building, which a user who
/// already holds valid polygons would not pay. Output: every polygon's exterior turned
/// counter-clockwise and its holes clockwise; points and lines in a result are dropped (they
/// have no area). GEOS computes in f64 without a grid, but rounds crossings: it is compared
/// with `clip_oracle::GEO_TOLERANCE`.
#[derive(Clone, Copy, Debug, Default)]
pub struct GeosClipper;

impl GeosClipper {
    /// The adapter (it holds no state; GEOS contexts are per call).
    pub fn new() -> GeosClipper {
        GeosClipper
    }
}

fn failed(e: geos::Error) -> ClipError {
    ClipError::Failed { clipper: NAME, kind: FailureKind::Internal, reason: format!("GEOS: {e}") }
}

/// The region `polygons` covers under `fill`, as a valid GEOS polygon or multipolygon.
fn region(polygons: &Polygons, fill: FillRule) -> Result<Geometry, ClipError> {
    if polygons.rings.is_empty() {
        return Geometry::create_empty_polygon().map_err(failed);
    }
    let lines = polygons
        .rings
        .iter()
        .map(|r| {
            let mut coords: Vec<[f64; 2]> = r.points.iter().map(|p| [p.x, p.y]).collect();
            coords.push(coords[0]);
            CoordSeq::new_from_vec(&coords).and_then(Geometry::create_line_string)
        })
        .collect::<Result<Vec<_>, _>>()
        .map_err(failed)?;
    let noded = Geometry::create_multiline_string(lines).and_then(|l| l.unary_union()).map_err(failed)?;
    let faces = Geometry::polygonize(&[noded]).map_err(failed)?;
    let mut kept = Vec::new();
    for i in 0..faces.get_num_geometries().map_err(failed)? {
        let face = faces.get_geometry_n(i).map_err(failed)?;
        if winding_inside(&face, polygons).map_err(failed)?.is_some_and(|w| fill.is_inside(w)) {
            kept.push(Geom::clone(&face).map_err(failed)?);
        }
    }
    if kept.is_empty() {
        return Geometry::create_empty_polygon().map_err(failed);
    }
    Geometry::create_multipolygon(kept).and_then(|m| m.unary_union()).map_err(failed)
}

/// The winding number of our rings inside `face`: at its interior point, or its centroid where
/// that point falls on one of our edges; `None` when both do.
fn winding_inside(face: &impl Geom, polygons: &Polygons) -> Result<Option<i32>, geos::Error> {
    for point in [face.point_on_surface()?, face.get_centroid()?] {
        if point.is_empty()? {
            continue;
        }
        if let Some(w) = winding_number(Point::new(point.get_x()?, point.get_y()?), polygons) {
            return Ok(Some(w));
        }
    }
    Ok(None)
}

/// A GEOS ring as ours, the closing point dropped, turned the way asked.
fn ring(geometry: &impl Geom, counter_clockwise: bool) -> Result<Option<Ring>, geos::Error> {
    let seq = geometry.get_coord_seq()?;
    let n = seq.size()?;
    let mut points = Vec::with_capacity(n);
    for i in 0..n {
        points.push(Point::new(seq.get_x(i)?, seq.get_y(i)?));
    }
    if points.len() > 1 && points.first() == points.last() {
        points.pop();
    }
    if points.len() < 3 {
        return Ok(None);
    }
    let ring = Ring::new(points);
    Ok(Some(if (ring.signed_area() > 0.0) == counter_clockwise { ring } else { ring.reversed() }))
}

/// Every polygon ring of a result (polygons, multipolygons, collections), in our orientation.
fn collect_rings(geometry: &impl Geom, out: &mut Vec<Ring>) -> Result<(), geos::Error> {
    match geometry.geometry_type()? {
        GeometryTypes::Polygon => {
            if geometry.is_empty()? {
                return Ok(());
            }
            out.extend(ring(&geometry.get_exterior_ring()?, true)?);
            for i in 0..geometry.get_num_interior_rings()? {
                out.extend(ring(&geometry.get_interior_ring_n(i)?, false)?);
            }
        }
        GeometryTypes::MultiPolygon | GeometryTypes::GeometryCollection => {
            for i in 0..geometry.get_num_geometries()? {
                collect_rings(&geometry.get_geometry_n(i)?, out)?;
            }
        }
        _ => {}
    }
    Ok(())
}

impl PolygonClipper for GeosClipper {
    fn name(&self) -> &'static str {
        NAME
    }

    fn capabilities(&self) -> PolygonCapabilities {
        PolygonCapabilities::GENERAL
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        validate_polygons(clip, Operand::Clip)?;
        let (a, b) = (region(subject, fill)?, region(clip, fill)?);
        let result = match op {
            BoolOp::Intersection => a.intersection(&b),
            BoolOp::Union => a.union(&b),
            BoolOp::Difference => a.difference(&b),
            BoolOp::Xor => a.sym_difference(&b),
        }
        .map_err(failed)?;
        let mut rings = Vec::new();
        collect_rings(&result, &mut rings).map_err(failed)?;
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
            let out = GeosClipper.clip(&a, &b, op, FillRule::NonZero).unwrap();
            assert!((out.signed_area() - area).abs() < 1e-12, "{op}: {out:?}");
        }
    }

    #[test]
    fn fill_rules_read_crossing_and_overlapping_rings() {
        // A bow-tie: its two lobes wind +1 and -1.
        let bow_tie = Polygons::from(Ring::from(&[(0.0, 0.0), (2.0, 2.0), (2.0, 0.0), (0.0, 2.0)][..]));
        let far = Polygons::from(Rect::new(5.0, 5.0, 6.0, 6.0));
        let area = |p: &Polygons, fill| GeosClipper.clip(p, &far, BoolOp::Difference, fill).unwrap().signed_area();
        assert!((area(&bow_tie, FillRule::EvenOdd) - 2.0).abs() < 1e-12);
        assert!((area(&bow_tie, FillRule::Positive) - 1.0).abs() < 1e-12);
        assert!((area(&bow_tie, FillRule::Negative) - 1.0).abs() < 1e-12);
        // Two copies of one square: winding 2, inside under non-zero, outside under even-odd.
        let twice =
            Polygons::new(vec![Rect::new(0.0, 0.0, 1.0, 1.0).to_ring(), Rect::new(0.0, 0.0, 1.0, 1.0).to_ring()]);
        assert!((area(&twice, FillRule::NonZero) - 1.0).abs() < 1e-12);
        assert_eq!(area(&twice, FillRule::EvenOdd), 0.0);
    }

    #[test]
    fn holes_come_out_clockwise() {
        let a = Polygons::from(Rect::new(0.0, 0.0, 4.0, 4.0).to_ring().reversed());
        let b = Polygons::from(Rect::new(1.0, 1.0, 2.0, 2.0));
        let out = GeosClipper.clip(&a, &b, BoolOp::Difference, FillRule::EvenOdd).unwrap();
        let mut areas: Vec<f64> = out.rings.iter().map(Ring::signed_area).collect();
        areas.sort_by(f64::total_cmp);
        assert_eq!(areas, vec![-1.0, 16.0]);
    }
}
