//! The exact, library-independent oracle for boolean operations on polygons.
//!
//! Three checks, cheapest first to fail usefully: the output's form ([`check_form`], for
//! conventional output: strict and exact), exact membership at sample points away from every
//! edge, and the area of the symmetric difference between the output and the exact answer
//! ([`region_area`]).

mod bridges;
mod form;
mod region_area;
pub(crate) mod sampling;

pub use bridges::{bridge_count, bridge_count_along, bridge_count_within};
pub use form::{EdgeAt, FormFailure, Visit, check_form};
pub use region_area::{region_area, region_area_with_witness, region_area_work};

use clip_core::{BoolOp, FillRule, OutputForm, Point, Polygons, Rect};
use core::fmt;
use sampling::{PointClassifier, sample_points};

/// Relative area tolerance for f64 clippers: the symmetric difference may be this fraction of
/// the inputs' bounding-box area (rounded intersection points move edges by ulps).
pub const REGION_TOLERANCE: f64 = 1e-9;

/// Relative area tolerance against `geo` and Clipper2, which snap coordinates to an integer grid
/// of about extent x 1e-9 (i_overlay) or a scaled integer grid (Clipper2): a sliver one grid step
/// wide along every edge stays far below this.
pub const GEO_TOLERANCE: f64 = 1e-6;

/// How far, relative to the tolerance, a sample point must be from every edge to be checked:
/// margin = extent x relative tolerance x this. Rounded output vertices move edges by far less.
pub const MARGIN_FACTOR: f64 = 1e3;

/// How far an f64 clipper's edges may sit from the exact ones, in ulps of the largest coordinate:
/// each output vertex is rounded to the nearest f64 (half an ulp each way), and a crossing computed
/// there carries about an ulp more. Measured: vatti on `star-far` (coordinates near 1e9) stays
/// within a fifth of this; a vertex moved by a millionth of the box is still several times over.
pub const ROUNDING_ULPS: f64 = 2.0;

/// The absolute area tolerance for a case: `relative` times the area of the bounding box of both
/// inputs, plus what rounding to f64 can move at their magnitude ([`rounding_distance`] along
/// every input edge: the result's boundary runs along the inputs'). Near the origin the first term
/// rules; far from it (coordinates of 1e9, a box of a few hundred units) the second does, since no
/// f64 result can be closer to the exact region than its coordinates' precision allows.
pub fn tolerance(subject: &Polygons, clip: &Polygons, relative: f64) -> f64 {
    let b = subject.bounds().union(clip.bounds());
    let perimeter: f64 = subject.edges().chain(clip.edges()).map(|e| e.a.distance(e.b)).sum();
    relative * b.area() + rounding_distance(&b) * perimeter
}

/// How far rounding to f64 can move an edge at the magnitude of the coordinates in `b`:
/// [`ROUNDING_ULPS`] ulps of the largest coordinate magnitude.
pub fn rounding_distance(b: &Rect) -> f64 {
    if b.is_empty() {
        return 0.0;
    }
    let magnitude = b.min.x.abs().max(b.max.x.abs()).max(b.min.y.abs()).max(b.max.y.abs());
    // The power of two at or below the magnitude, times epsilon: one ulp there.
    let binade = f64::from_bits(magnitude.to_bits() & 0x7ff0_0000_0000_0000);
    ROUNDING_ULPS * (binade * f64::EPSILON).max(f64::MIN_POSITIVE)
}

/// How many rounding distances ([`rounding_distance`]) apart two edges of bridged output may be
/// and still count as one bridge: their ends were rounded separately, and a shallow angle moves
/// them farther still (found by the `vatti` fuzz target at 1e15, where 2 ulps were not enough).
pub const SNAP_ROUNDINGS: f64 = 4.0;

/// The distance within which an edge pair counts as a bridge, and (times [`MARGIN_FACTOR`]) the
/// margin sample points keep from every edge: the relative tolerance of the box's extent, or
/// [`SNAP_ROUNDINGS`] rounding distances at its magnitude where that is larger. The form check
/// uses no such distance: it is exact.
pub fn snap_distance(b: &Rect, relative: f64) -> f64 {
    (b.extent() * relative).max(SNAP_ROUNDINGS * rounding_distance(b))
}

/// How an output is to be read and checked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OutputRules {
    /// False for bridged output (Sutherland-Hodgman, four-state): no simplicity or
    /// orientation check, only the region.
    pub conventional: bool,
    /// The fill rule the output is read under: `NonZero` for conventional output; the input's
    /// rule for bridged output.
    pub output_fill: FillRule,
    /// The relative area tolerance: [`REGION_TOLERANCE`], or [`GEO_TOLERANCE`] for the peers.
    pub relative_tolerance: f64,
}

impl OutputRules {
    /// Conventional output (simple rings, outers counter-clockwise), read under non-zero, with
    /// the given relative tolerance.
    pub fn conventional(relative_tolerance: f64) -> OutputRules {
        OutputRules { conventional: true, output_fill: FillRule::NonZero, relative_tolerance }
    }

    /// Bridged output, read under the input's fill rule.
    pub fn bridged(input_fill: FillRule, relative_tolerance: f64) -> OutputRules {
        OutputRules { conventional: false, output_fill: input_fill, relative_tolerance }
    }

    /// The rules for a clipper whose output takes `form`, on `subject` read under `input_fill`.
    /// [`OutputForm::ConventionalForConventionalSubject`] is checked as conventional output when
    /// the subject passes [`check_form`] and the rule is not negative (which
    /// reads a conventional subject as empty), and by region under the input's rule otherwise.
    pub fn for_form(
        form: OutputForm,
        subject: &Polygons,
        input_fill: FillRule,
        relative_tolerance: f64,
    ) -> OutputRules {
        OutputRules::for_form_given(form, || check_form(subject).is_ok(), input_fill, relative_tolerance)
    }

    /// [`OutputRules::for_form`] with the subject's form check answered by `subject_conventional`,
    /// asked only for [`OutputForm::ConventionalForConventionalSubject`]: a caller with a time
    /// budget, or many results on one subject, answers it once (or "no" where the check is too
    /// dear: the output is then read by region under the input's rule, which a conventional
    /// result also passes).
    pub fn for_form_given(
        form: OutputForm,
        subject_conventional: impl FnOnce() -> bool,
        input_fill: FillRule,
        relative_tolerance: f64,
    ) -> OutputRules {
        let conventional = match form {
            OutputForm::Conventional => true,
            OutputForm::InputRule => false,
            OutputForm::ConventionalForConventionalSubject => {
                input_fill != FillRule::Negative && subject_conventional()
            }
        };
        if conventional {
            OutputRules::conventional(relative_tolerance)
        } else {
            OutputRules::bridged(input_fill, relative_tolerance)
        }
    }
}

/// Why an output is wrong.
#[derive(Clone, Debug, PartialEq)]
pub enum PolygonFailure {
    /// The output's form breaks the conventions: which fault, and where.
    Invalid(FormFailure),
    /// A sample point away from every edge is on the wrong side.
    WrongPoint {
        /// The point.
        point: Point,
        /// Whether the exact answer covers it.
        expected: bool,
        /// Whether the output covers it.
        got: bool,
    },
    /// The symmetric difference between the output and the exact answer is too big.
    WrongRegion {
        /// Its area.
        xor_area: f64,
        /// The absolute tolerance it exceeded.
        tolerance: f64,
    },
    /// The areas of the four operations do not add up.
    AreaIdentity(String),
}

impl fmt::Display for PolygonFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PolygonFailure::Invalid(why) => write!(f, "invalid output: {why}"),
            PolygonFailure::WrongPoint { point, expected, got } => {
                let word = |b: bool| if b { "inside" } else { "outside" };
                write!(
                    f,
                    "point ({}, {}) should be {} the result but is {}",
                    point.x,
                    point.y,
                    word(*expected),
                    word(*got)
                )
            }
            PolygonFailure::WrongRegion { xor_area, tolerance } => {
                write!(f, "result differs from the exact region by area {xor_area:e} (tolerance {tolerance:e})")
            }
            PolygonFailure::AreaIdentity(why) => write!(f, "area identity broken: {why}"),
        }
    }
}

impl std::error::Error for PolygonFailure {}

/// The full oracle for one output of `subject op clip` under `fill`: its form (if
/// conventional, [`check_form`], exact), every sample point (a 12 x 12 grid and 112 seeded random points over the
/// bounding box of inputs and output) farther than a margin from every edge classified exactly,
/// and the area of the symmetric difference within the tolerance. On success, that area: two
/// outputs that pass differ by at most the sum of theirs (the triangle inequality), which lets a
/// caller compare them without another sweep.
pub fn check_polygon_result(
    subject: &Polygons,
    clip: &Polygons,
    op: BoolOp,
    fill: FillRule,
    output: &Polygons,
    rules: &OutputRules,
) -> Result<f64, PolygonFailure> {
    let Some(b) = finite_box(subject, clip, output)? else { return Ok(0.0) };
    if rules.conventional {
        check_valid_output(output)?;
    }
    check_sample_points(subject, clip, op, fill, output, rules, &b)?;
    let tol = tolerance(subject, clip, rules.relative_tolerance);
    let layers = [(subject, fill), (clip, fill), (output, rules.output_fill)];
    let xor_area = region_area(&layers, |inside| op.apply(inside[0], inside[1]) != inside[2]);
    if xor_area > tol {
        return Err(PolygonFailure::WrongRegion { xor_area, tolerance: tol });
    }
    Ok(xor_area)
}

/// Only the sample-point part of [`check_polygon_result`]: no validity check and no area sweep,
/// for inputs whose exact sweep is too costly ([`region_area_work`]). Linear in the edges; it
/// catches a result wrong around any sample point (a missing or extra piece, a fixed or empty
/// answer), not a sliver between them.
pub fn check_polygon_samples(
    subject: &Polygons,
    clip: &Polygons,
    op: BoolOp,
    fill: FillRule,
    output: &Polygons,
    rules: &OutputRules,
) -> Result<(), PolygonFailure> {
    let Some(b) = finite_box(subject, clip, output)? else { return Ok(()) };
    check_sample_points(subject, clip, op, fill, output, rules, &b)
}

/// The first step of both checks: every output vertex finite, then the box of inputs and output;
/// `None` when it is empty (nothing anywhere, so nothing to check).
fn finite_box(subject: &Polygons, clip: &Polygons, output: &Polygons) -> Result<Option<Rect>, PolygonFailure> {
    if let Some(failure) = check_finite(output) {
        return Err(PolygonFailure::Invalid(failure));
    }
    let b = subject.bounds().union(clip.bounds()).union(output.bounds());
    Ok((!b.is_empty()).then_some(b))
}

/// [`check_form`] as an oracle verdict.
pub fn check_valid_output(output: &Polygons) -> Result<(), PolygonFailure> {
    check_form(output).map_err(PolygonFailure::Invalid)
}

/// The first non-finite vertex, if any (bridged output too is checked for it).
fn check_finite(output: &Polygons) -> Option<FormFailure> {
    output.rings.iter().enumerate().find_map(|(ring, r)| {
        let vertex = r.points.iter().position(|p| !p.is_finite())?;
        Some(FormFailure::NonFinite { ring, vertex, point: r.points[vertex] })
    })
}

fn check_sample_points(
    subject: &Polygons,
    clip: &Polygons,
    op: BoolOp,
    fill: FillRule,
    output: &Polygons,
    rules: &OutputRules,
    b: &Rect,
) -> Result<(), PolygonFailure> {
    let margin = snap_distance(b, rules.relative_tolerance) * MARGIN_FACTOR;
    let (s, c, o) = (
        PointClassifier::new(subject, margin),
        PointClassifier::new(clip, margin),
        PointClassifier::new(output, margin),
    );
    for p in sample_points(b) {
        let (Some(ws), Some(wc), Some(wo)) = (s.winding(p), c.winding(p), o.winding(p)) else { continue };
        let expected = op.apply(fill.is_inside(ws), fill.is_inside(wc));
        let got = rules.output_fill.is_inside(wo);
        if expected != got {
            return Err(PolygonFailure::WrongPoint { point: p, expected, got });
        }
    }
    Ok(())
}

/// Checks the area identities on the outputs given (each read under `rules.output_fill`):
/// |A ∪ B| + |A ∩ B| = |A| + |B|, |A − B| + |A ∩ B| = |A|, |A ⊕ B| = |A ∪ B| − |A ∩ B|, with
/// |A| and |B| from [`region_area`]. Identities whose outputs are missing are skipped.
pub fn check_area_identities(
    subject: &Polygons,
    clip: &Polygons,
    fill: FillRule,
    outputs: &[(BoolOp, &Polygons)],
    rules: &OutputRules,
) -> Result<(), PolygonFailure> {
    let tol = tolerance(subject, clip, rules.relative_tolerance);
    check_area_identities_given(operand_areas(subject, clip, fill), tol, outputs, rules)
}

/// |A| and |B| under `fill`, by [`region_area`]: measure them once per case and fill rule and
/// pass them to [`check_area_identities_given`] for every clipper.
pub fn operand_areas(subject: &Polygons, clip: &Polygons, fill: FillRule) -> (f64, f64) {
    (region_area(&[(subject, fill)], |i| i[0]), region_area(&[(clip, fill)], |i| i[0]))
}

/// [`check_area_identities`] with |A| and |B| given ([`operand_areas`]) and the case's absolute
/// tolerance ([`tolerance`]). Conventional outputs are measured by the shoelace formula, which
/// is their area when they are valid and does not share code with the sweep that measured |A|
/// and |B|; bridged outputs by [`region_area`] under the input's rule.
pub fn check_area_identities_given(
    (a, b): (f64, f64),
    tolerance: f64,
    outputs: &[(BoolOp, &Polygons)],
    rules: &OutputRules,
) -> Result<(), PolygonFailure> {
    let area_of = |op: BoolOp| {
        outputs.iter().find(|(o, _)| *o == op).map(|(_, p)| {
            if rules.conventional { p.signed_area() } else { region_area(&[(p, rules.output_fill)], |i| i[0]) }
        })
    };
    let (i, u, d, x) =
        (area_of(BoolOp::Intersection), area_of(BoolOp::Union), area_of(BoolOp::Difference), area_of(BoolOp::Xor));
    // Each side sums up to three areas, each within the tolerance.
    let tol = 3.0 * tolerance;
    let check = |name: &str, lhs: f64, rhs: f64| {
        if (lhs - rhs).abs() > tol {
            Err(PolygonFailure::AreaIdentity(format!("{name}: {lhs} vs {rhs} (tolerance {tol:e})")))
        } else {
            Ok(())
        }
    };
    if let (Some(u), Some(i)) = (u, i) {
        check("|A∪B| + |A∩B| = |A| + |B|", u + i, a + b)?;
    }
    if let (Some(d), Some(i)) = (d, i) {
        check("|A−B| + |A∩B| = |A|", d + i, a)?;
    }
    if let (Some(x), Some(u), Some(i)) = (x, u, i) {
        check("|A⊕B| = |A∪B| − |A∩B|", x, u - i)?;
    }
    Ok(())
}

/// Whether two outputs cover the same region: `Err(area)` with the area of their symmetric
/// difference when it exceeds `tolerance` (absolute).
pub fn same_region(a: (&Polygons, FillRule), b: (&Polygons, FillRule), tolerance: f64) -> Result<(), f64> {
    let xor_area = region_area(&[a, b], |i| i[0] != i[1]);
    if xor_area > tolerance { Err(xor_area) } else { Ok(()) }
}
