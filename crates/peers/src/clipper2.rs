//! The C++ Clipper2 (through the `clipper2` crate) as a polygon clipper.

use clip_clipper2_rect::IntegerGrid;
use clip_core::{
    BoolOp, ClipError, FillRule, Operand, PolygonCapabilities, PolygonClipper, Polygons, Ring, validate_polygons,
};
use clipper2::{Clipper, FillRule as C2Fill, One, Path, Paths, Point as C2Point};

/// Clipper2's boolean operations: all four ops under all four fill rules.
///
/// Clipper2 works on 64-bit integers. The crate's default scaler rounds to 0.01, far too coarse
/// for unit-sized or grid inputs, so each call fits its own [`IntegerGrid`] (shared with the
/// `clipper2-rect` peer) to the inputs: their bounding-box centre at the origin and a power-of-two
/// scale that maps the largest distance from it to just under [`Clipper2Clipper::GRID_BITS`]
/// bits, so the rounding step is about extent x 2^-30 (like geo's snapping) wherever the inputs
/// sit, and the output is moved back. Every ring is passed in order with its orientation;
/// Clipper2 reads counter-clockwise loops as +1, as we do, and returns outers counter-clockwise
/// and holes clockwise (positive area for outers, y up), which is our convention, so the output
/// is converted ring by ring.
///
/// [`Clipper2Clipper::native`] skips the scaling: coordinates are rounded to integers and used
/// as they are, which is how Clipper2's own tests run their integer data (`Polygons.txt`). The
/// scale matters beyond precision: Clipper2 drops output rings of tiny area in its integer
/// space, so path counts depend on it.
#[derive(Clone, Copy, Debug, Default)]
pub struct Clipper2Clipper {
    native: bool,
}

impl Clipper2Clipper {
    /// Bits of the integer grid the inputs' extent is scaled to.
    pub const GRID_BITS: i32 = IntegerGrid::BITS;

    /// The adapter on a grid scaled to the inputs' extent.
    pub fn new() -> Clipper2Clipper {
        Clipper2Clipper { native: false }
    }

    /// The adapter on the unscaled integer grid (Clipper64 on coordinates rounded to integers).
    pub fn native() -> Clipper2Clipper {
        Clipper2Clipper { native: true }
    }
}

fn to_paths(p: &Polygons, grid: IntegerGrid) -> Paths<One> {
    Paths::new(
        p.rings
            .iter()
            .map(|r| {
                Path::new(
                    r.points
                        .iter()
                        .map(|&q| {
                            let [x, y] = grid.to_grid(q);
                            C2Point::from_scaled(x, y)
                        })
                        .collect(),
                )
            })
            .collect(),
    )
}

fn from_paths(paths: &Paths<One>, grid: IntegerGrid) -> Polygons {
    Polygons::new(
        paths
            .iter()
            .map(|path| Ring::new(path.iter().map(|q| grid.to_point([q.x_scaled(), q.y_scaled()])).collect()))
            .collect(),
    )
}

fn c2_fill(fill: FillRule) -> C2Fill {
    match fill {
        FillRule::EvenOdd => C2Fill::EvenOdd,
        FillRule::NonZero => C2Fill::NonZero,
        FillRule::Positive => C2Fill::Positive,
        FillRule::Negative => C2Fill::Negative,
    }
}

impl PolygonClipper for Clipper2Clipper {
    fn name(&self) -> &'static str {
        "clipper2"
    }

    fn capabilities(&self) -> PolygonCapabilities {
        PolygonCapabilities::GENERAL
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        validate_polygons(clip, Operand::Clip)?;
        let grid = if self.native {
            IntegerGrid { origin: clip_core::Point::ZERO, scale: 1.0 }
        } else {
            IntegerGrid::fitting(subject.bounds().union(clip.bounds()))
        };
        let clipper = Clipper::<_, One>::new().add_subject(to_paths(subject, grid)).add_clip(to_paths(clip, grid));
        let fill = c2_fill(fill);
        let result = match op {
            BoolOp::Intersection => clipper.intersect(fill),
            BoolOp::Union => clipper.union(fill),
            BoolOp::Difference => clipper.difference(fill),
            BoolOp::Xor => clipper.xor(fill),
        };
        match result {
            Ok(paths) => Ok(from_paths(&paths, grid)),
            Err(e) => Err(ClipError::Unsupported { clipper: "clipper2", what: format!("this input (Clipper2: {e})") }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::{Point, Rect};

    fn square(x0: f64, y0: f64, size: f64) -> Ring {
        Rect::new(x0, y0, x0 + size, y0 + size).to_ring()
    }

    #[test]
    fn small_coordinates_are_not_rounded_to_hundredths() {
        let a = Polygons::from(square(0.0, 0.0, 0.003));
        let b = Polygons::from(square(0.001, 0.001, 0.003));
        let out = Clipper2Clipper::new().clip(&a, &b, BoolOp::Intersection, FillRule::NonZero).unwrap();
        assert!((out.signed_area() - 4e-6).abs() < 1e-12, "{out:?}");
    }

    #[test]
    fn outers_come_out_counter_clockwise_and_holes_clockwise() {
        // Clockwise input: the difference is a square with a square hole.
        let a = Polygons::from(square(0.0, 0.0, 4.0).reversed());
        let b = Polygons::from(square(1.0, 1.0, 2.0).reversed());
        let out = Clipper2Clipper::new().clip(&a, &b, BoolOp::Difference, FillRule::NonZero).unwrap();
        let mut areas: Vec<f64> = out.rings.iter().map(Ring::signed_area).collect();
        areas.sort_by(f64::total_cmp);
        assert_eq!(areas, vec![-4.0, 16.0]);
    }

    #[test]
    fn fill_rules_follow_ring_orientation() {
        let ccw = Polygons::from(square(0.0, 0.0, 1.0));
        let cw = Polygons::from(square(0.0, 0.0, 1.0).reversed());
        let other = Polygons::from(square(5.0, 5.0, 1.0));
        let area = |p: &Polygons, fill| {
            Clipper2Clipper::new().clip(p, &other, BoolOp::Difference, fill).unwrap().signed_area()
        };
        assert_eq!(area(&ccw, FillRule::Positive), 1.0);
        assert_eq!(area(&ccw, FillRule::Negative), 0.0);
        assert_eq!(area(&cw, FillRule::Positive), 0.0);
        assert_eq!(area(&cw, FillRule::Negative), 1.0);
    }

    #[test]
    fn every_op_on_overlapping_squares() {
        let a = Polygons::from(square(0.0, 0.0, 2.0));
        let b = Polygons::from(square(1.0, 1.0, 2.0));
        let expected =
            [(BoolOp::Intersection, 1.0), (BoolOp::Union, 7.0), (BoolOp::Difference, 3.0), (BoolOp::Xor, 6.0)];
        for (op, area) in expected {
            let out = Clipper2Clipper::new().clip(&a, &b, op, FillRule::EvenOdd).unwrap();
            assert_eq!(out.signed_area(), area, "{op}");
        }
    }

    #[test]
    fn far_from_the_origin_the_grid_follows_the_extent() {
        // UTM-like coordinates: a grid scaled to the magnitude (1e6) would round to 1e-3.
        let a = Polygons::from(square(500_000.0, 4_000_000.0, 0.003));
        let b = Polygons::from(square(500_000.001, 4_000_000.001, 0.003));
        let out = Clipper2Clipper::new().clip(&a, &b, BoolOp::Intersection, FillRule::NonZero).unwrap();
        assert!((out.signed_area() - 4e-6).abs() < 1e-12, "{out:?}");
    }

    #[test]
    fn native_grid_rounds_to_integers() {
        let a = Polygons::from(square(0.0, 0.0, 2.0));
        let b = Polygons::from(Ring::from(&[(1.0, 1.0), (3.4, 1.0), (3.4, 3.4), (1.0, 3.4)][..]));
        let out = Clipper2Clipper::native().clip(&a, &b, BoolOp::Union, FillRule::NonZero).unwrap();
        assert!(out.points().all(|p| p.x.fract() == 0.0 && p.y.fract() == 0.0), "{out:?}");
        assert_eq!(out.signed_area(), 7.0);
    }

    #[test]
    fn empty_operands_and_bad_input() {
        let a = Polygons::from(square(0.0, 0.0, 2.0));
        let out = Clipper2Clipper::new().clip(&Polygons::empty(), &a, BoolOp::Union, FillRule::NonZero).unwrap();
        assert_eq!(out.signed_area(), 4.0);
        let out = Clipper2Clipper::new()
            .clip(&Polygons::empty(), &Polygons::empty(), BoolOp::Union, FillRule::NonZero)
            .unwrap();
        assert!(out.is_empty());
        let bad =
            Polygons::from(Ring::new(vec![Point::new(0.0, 0.0), Point::new(f64::INFINITY, 1.0), Point::new(1.0, 0.0)]));
        assert!(matches!(
            Clipper2Clipper::new().clip(&a, &bad, BoolOp::Union, FillRule::EvenOdd),
            Err(ClipError::NonFinite { operand: Operand::Clip, .. })
        ));
    }
}
