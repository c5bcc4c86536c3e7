//! The `vatti` target: two operands from the bytes, all four operations under one fill rule,
//! each result through the exact oracle, then the area and region identities. `Vatti` sweeps
//! inputs this small with the paper's scanbeam sweep along y, so each operation also runs the
//! event sweep along y and along x (`Vatti::clip_along`), judged by the oracle and against
//! `Vatti`'s region.

use arbitrary::{Arbitrary, Unstructured};
use clip_core::{BoolOp, FillRule, Operand, PolygonClipper, Polygons, Rect, Ring, validate_polygons};
use clip_oracle::polygon::{
    OutputRules, REGION_TOLERANCE, check_area_identities, check_polygon_result, same_region, tolerance,
};
use clip_vatti::{Route, Sweep, SweepAxis, Vatti};

use crate::shape::{Builder, Frame, ShapeSpec};
use crate::{Fill, Outcome};

/// What the bytes decode to.
#[derive(Arbitrary, Clone, Debug, PartialEq)]
pub struct VattiInput {
    /// The grid both operands are built on.
    pub frame: Frame,
    /// Operand A.
    pub subject: ShapeSpec,
    /// Operand B.
    pub clip: ShapeSpec,
    /// The rule both are read under.
    pub fill: Fill,
}

/// A decoded case.
#[derive(Clone, Debug, PartialEq)]
pub struct VattiCase {
    /// Operand A.
    pub subject: Polygons,
    /// Operand B.
    pub clip: Polygons,
    /// The fill rule.
    pub fill: FillRule,
}

/// Decodes the bytes as libFuzzer hands them to the target (`None`: too short to decode).
pub fn decode(data: &[u8]) -> Option<VattiCase> {
    let input = VattiInput::arbitrary_take_rest(Unstructured::new(data)).ok()?;
    let mut b = Builder::new(input.frame);
    let subject = b.polygons(&input.subject);
    let clip = b.polygons(&input.clip);
    Some(VattiCase { subject, clip, fill: input.fill.into() })
}

/// The target: decodes and checks.
pub fn check_bytes(data: &[u8]) -> Result<(), String> {
    decode(data).map_or(Ok(()), |case| check(&case).map(|_| ()))
}

/// Runs vatti on all four operations. Invalid operands must be refused with a typed error by
/// every operation; valid ones must give results the oracle accepts, whose areas add up
/// (`check_area_identities`) and whose regions satisfy A ⊕ B = (A ∪ B) − (A ∩ B) and
/// A − B = A ∩ complement(B), each computed by vatti again. Returns the four results.
pub fn check(case: &VattiCase) -> Result<Outcome, String> {
    let VattiCase { subject, clip, fill } = case;
    let valid = validate_polygons(subject, Operand::Subject).and(validate_polygons(clip, Operand::Clip));
    let rules = OutputRules::conventional(REGION_TOLERANCE);
    let mut outputs = Vec::new();
    for op in BoolOp::ALL {
        match (&valid, Vatti.clip(subject, clip, op, *fill)) {
            (Err(_), Err(_)) => {}
            (Err(why), Ok(_)) => return Err(format!("{op:?}: accepted invalid input ({why})")),
            (Ok(()), Err(e)) => return Err(format!("{op:?}: refused valid input: {e}")),
            (Ok(()), Ok(out)) => {
                check_polygon_result(subject, clip, op, *fill, &out, &rules).map_err(|f| format!("{op:?}: {f}"))?;
                events_sweep_agrees(case, op, &out, &rules)?;
                outputs.push((op, out));
            }
        }
    }
    if valid.is_err() {
        return Ok(Outcome::Refused);
    }
    let given: Vec<(BoolOp, &Polygons)> = outputs.iter().map(|(op, p)| (*op, p)).collect();
    check_area_identities(subject, clip, *fill, &given, &rules).map_err(|f| f.to_string())?;
    let [(_, inter), (_, union), (_, diff), (_, xor)] = <[_; 4]>::try_from(outputs).expect("four operations");
    let tol = tolerance(subject, clip, REGION_TOLERANCE);
    xor_is_union_minus_intersection(&union, &inter, &xor, tol)?;
    difference_is_intersection_with_complement(case, &diff, tol)?;
    Ok(Outcome::Polygons(vec![("intersection", inter), ("union", union), ("difference", diff), ("xor", xor)]))
}

/// The event sweep on the same operation, along y and along x: each accepted by the oracle, and
/// the same region as `out` (`Vatti`'s result) within both results' rounding.
fn events_sweep_agrees(case: &VattiCase, op: BoolOp, out: &Polygons, rules: &OutputRules) -> Result<(), String> {
    let VattiCase { subject, clip, fill } = case;
    for axis in [SweepAxis::Y, SweepAxis::X] {
        let events = Vatti
            .clip_along(Route::Whole, Some(Sweep::Events), Some(axis), subject, clip, op, *fill)
            .map_err(|e| format!("{op:?}: the event sweep along {axis:?} refused valid input: {e}"))?;
        check_polygon_result(subject, clip, op, *fill, &events, rules)
            .map_err(|f| format!("{op:?}, event sweep along {axis:?}: {f}"))?;
        let allowed = 2.0 * tolerance(subject, clip, REGION_TOLERANCE);
        same_region((&events, FillRule::NonZero), (out, FillRule::NonZero), allowed).map_err(|area| {
            format!("{op:?}: the event sweep's region along {axis:?} differs from vatti's by area {area:e}")
        })?;
    }
    Ok(())
}

/// Whether vatti's outputs (or shapes built from them) can be fed back in: a crossing of edges
/// near 1e-100 close to zero can round to a coordinate below `clip_core::MIN_COORDINATE`, and a
/// box around coordinates near `MAX_COORDINATE` can leave it. The identity is skipped then.
fn valid_operands(a: &Polygons, b: &Polygons) -> bool {
    validate_polygons(a, Operand::Subject).is_ok() && validate_polygons(b, Operand::Clip).is_ok()
}

/// A ⊕ B and (A ∪ B) − (A ∩ B) cover the same region: each of the three results is within `tol`
/// of the exact one, and the difference adds its own rounding.
fn xor_is_union_minus_intersection(union: &Polygons, inter: &Polygons, xor: &Polygons, tol: f64) -> Result<(), String> {
    if !valid_operands(union, inter) {
        return Ok(());
    }
    let rebuilt = Vatti
        .clip(union, inter, BoolOp::Difference, FillRule::NonZero)
        .map_err(|e| format!("(A ∪ B) − (A ∩ B) refused vatti's own output: {e}"))?;
    let allowed = 3.0 * tol + tolerance(union, inter, REGION_TOLERANCE);
    same_region((xor, FillRule::NonZero), (&rebuilt, FillRule::NonZero), allowed)
        .map_err(|area| format!("A ⊕ B and (A ∪ B) − (A ∩ B) differ by area {area:e} (allowed {allowed:e})"))
}

/// A − B and A ∩ complement(B) cover the same region. The complement is taken inside a box a
/// quarter of the extent larger than both operands: B normalised by vatti (outers
/// counter-clockwise, holes clockwise, winding 0 or 1), reversed, inside the box's
/// counter-clockwise ring. A is normalised too, so both are read under non-zero whatever the
/// case's rule. Skipped when the box would leave `MAX_COORDINATE`, or when a normalised operand
/// has a coordinate below `MIN_COORDINATE` (see [`valid_operands`]).
fn difference_is_intersection_with_complement(case: &VattiCase, diff: &Polygons, tol: f64) -> Result<(), String> {
    let VattiCase { subject, clip, fill } = case;
    let normalise = |p: &Polygons| {
        Vatti
            .clip(p, &Polygons::default(), BoolOp::Union, *fill)
            .map_err(|e| format!("normalising an operand (its union with nothing) refused it: {e}"))
    };
    let (a, b) = (normalise(subject)?, normalise(clip)?);
    let bounds = subject.bounds().union(clip.bounds());
    if bounds.is_empty() {
        return Ok(());
    }
    let margin = bounds.extent() / 4.0;
    let frame = Rect::new(bounds.min.x - margin, bounds.min.y - margin, bounds.max.x + margin, bounds.max.y + margin);
    let mut rings = vec![frame.to_ring()];
    rings.extend(b.rings.iter().map(Ring::reversed));
    let complement = Polygons::new(rings);
    if !valid_operands(&a, &complement) {
        return Ok(());
    }
    let rebuilt = Vatti
        .clip(&a, &complement, BoolOp::Intersection, FillRule::NonZero)
        .map_err(|e| format!("A ∩ complement(B) refused: {e}"))?;
    let allowed = 2.0 * tol + tolerance(&a, &complement, REGION_TOLERANCE);
    same_region((diff, FillRule::NonZero), (&rebuilt, FillRule::NonZero), allowed)
        .map_err(|area| format!("A − B and A ∩ complement(B) differ by area {area:e} (allowed {allowed:e})"))
}
