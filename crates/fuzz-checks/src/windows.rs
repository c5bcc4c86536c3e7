//! The `window_clippers` target: Sutherland-Hodgman (both forms) and the four-state clipper on
//! a convex or rectangular window from the bytes, checked by the oracle as bridged output and
//! against vatti by region.

use arbitrary::{Arbitrary, Unstructured};
use clip_core::{BoolOp, FillRule, Operand, PolygonClipper, Polygons, Rect, Ring, validate_polygons};
use clip_oracle::polygon::{OutputRules, REGION_TOLERANCE, check_polygon_result, same_region, tolerance};
use clip_rect_four_state::FourState;
use clip_sutherland_hodgman::{Form, SutherlandHodgman};
use clip_testkit::workload::convex_hull;
use clip_vatti::Vatti;

use crate::shape::{Builder, Frame, ShapeSpec};
use crate::{Fill, Outcome};

/// How the window is made.
#[derive(Arbitrary, Clone, Debug, PartialEq)]
pub enum WindowSpec {
    /// The convex hull of a shape's vertices (counter-clockwise, or clockwise when `reversed`).
    Hull(ShapeSpec, bool),
    /// The axis-aligned rectangle spanned by two grid points (zero width when they line up).
    Rect((i8, i8), (i8, i8), bool),
    /// A shape as it comes: usually not convex, so the clippers must refuse it with a typed error.
    Raw(ShapeSpec),
}

/// What the bytes decode to.
#[derive(Arbitrary, Clone, Debug, PartialEq)]
pub struct WindowInput {
    /// The grid both operands are built on.
    pub frame: Frame,
    /// The subject.
    pub subject: ShapeSpec,
    /// The window.
    pub window: WindowSpec,
    /// The rule the subject and window are read under.
    pub fill: Fill,
}

/// A decoded case.
#[derive(Clone, Debug, PartialEq)]
pub struct WindowCase {
    /// The subject.
    pub subject: Polygons,
    /// The window (clip operand).
    pub window: Polygons,
    /// The fill rule.
    pub fill: FillRule,
}

/// Builds a window as `spec` says; the builder's vertices so far are reused by later steps.
pub fn window(b: &mut Builder, spec: &WindowSpec) -> Polygons {
    let oriented = |ring: Ring, reversed: bool| Polygons::from(if reversed { ring.reversed() } else { ring });
    match spec {
        WindowSpec::Hull(shape, reversed) => {
            let points: Vec<_> = b.polygons(shape).points().copied().filter(|p| p.is_finite()).collect();
            oriented(Ring::new(convex_hull(&points)), *reversed)
        }
        WindowSpec::Rect((i, j), (k, l), reversed) => {
            let r = Rect::from_points(b.grid_point(*i, *j), b.grid_point(*k, *l));
            oriented(r.to_ring(), *reversed)
        }
        WindowSpec::Raw(shape) => b.polygons(shape),
    }
}

/// Decodes the bytes as libFuzzer hands them to the target (`None`: too short to decode).
pub fn decode(data: &[u8]) -> Option<WindowCase> {
    let input = WindowInput::arbitrary_take_rest(Unstructured::new(data)).ok()?;
    let mut b = Builder::new(input.frame);
    let subject = b.polygons(&input.subject);
    let window = window(&mut b, &input.window);
    Some(WindowCase { subject, window, fill: input.fill.into() })
}

/// The target: decodes and checks.
pub fn check_bytes(data: &[u8]) -> Result<(), String> {
    decode(data).map_or(Ok(()), |case| check(&case).map(|_| ()))
}

/// The window clippers under test, by registry name.
pub fn clippers() -> [(&'static str, Box<dyn PolygonClipper>); 3] {
    [
        ("sutherland-hodgman", Box::new(SutherlandHodgman::new(Form::List))),
        ("sutherland-hodgman pipeline", Box::new(SutherlandHodgman::new(Form::Pipeline))),
        ("rect-four-state", Box::new(FourState)),
    ]
}

/// Each window clipper must refuse an invalid subject or a window of the wrong kind with a typed
/// error, and otherwise return bridged output (read under the input's rule) that the oracle
/// accepts and that covers vatti's intersection within both tolerances. Returns the outputs.
pub fn check(case: &WindowCase) -> Result<Outcome, String> {
    let WindowCase { subject, window, fill } = case;
    let subject_valid = validate_polygons(subject, Operand::Subject);
    let rules = OutputRules::bridged(*fill, REGION_TOLERANCE);
    let tol = tolerance(subject, window, REGION_TOLERANCE);
    let mut vatti: Option<Polygons> = None;
    let mut outputs = Vec::new();
    for (name, clipper) in clippers() {
        let accepts = clipper.capabilities().window.accepts(window);
        match (subject_valid.is_ok() && accepts, clipper.clip(subject, window, BoolOp::Intersection, *fill)) {
            (false, Err(_)) => {}
            (false, Ok(_)) => {
                return Err(format!(
                    "{name}: accepted an invalid subject or a window it does not take ({subject_valid:?})"
                ));
            }
            (true, Err(e)) => return Err(format!("{name}: refused valid input: {e}")),
            (true, Ok(out)) => {
                check_polygon_result(subject, window, BoolOp::Intersection, *fill, &out, &rules)
                    .map_err(|f| format!("{name}: {f}"))?;
                if vatti.is_none() {
                    let v = Vatti.clip(subject, window, BoolOp::Intersection, *fill);
                    vatti = Some(v.map_err(|e| format!("vatti refused what {name} took: {e}"))?);
                }
                let v = vatti.as_ref().expect("set above");
                same_region((&out, *fill), (v, FillRule::NonZero), 2.0 * tol)
                    .map_err(|area| format!("{name} and vatti differ by area {area:e} (allowed {:e})", 2.0 * tol))?;
                outputs.push((name, out));
            }
        }
    }
    Ok(if outputs.is_empty() { Outcome::Refused } else { Outcome::Polygons(outputs) })
}
