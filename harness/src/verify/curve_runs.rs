//! Runs every selected curve clipper on one generated case (a window and a batch of circles,
//! ellipses and arcs) for a rectangle window and a polygon window: the curve oracle on each
//! outline and filled region (whole ellipses, sectors and chord regions), the split identities against the window's complement, the polygon
//! route (flatten finely, clip with Vatti) within its flattening bound, and the clippers against
//! each other.

use clip_core::{BoolOp, EllipseArc, FillRule, FilledArc, PolygonClipper, Polygons, WindowKind};
use clip_curve::{CurveClipper, flatten_filled_arc, flattening_area_bound};
use clip_oracle::curve::{
    CURVE_AREA_TOLERANCE, TANGENT_T_TOLERANCE, check_filled_region, check_identities, check_visible, complement_window,
};
use clip_testkit::workload::{CURVES_PER_CASE, curve_case, filled_object};
use clip_vatti::Vatti;

use super::finding::{CaseOutcome, Finding, Kind};
use crate::checks::{Check, Failing, guarded};
use crate::curve_input::CurveObject;
use crate::registry::CurveEntry;

/// The polygon route's name in the disagreement columns.
pub const POLYGON_ROUTE: &str = "flatten+vatti";

/// The window kinds every curve case runs on: the lecture's rectangle, and general polygons.
pub const CURVE_WINDOWS: [WindowKind; 2] = [WindowKind::Rectangle, WindowKind::Any];

/// Flattening tolerance of the polygon route, relative to the ellipse's long radius.
const ROUTE_TOLERANCE: f64 = 1e-4;

/// What to run on every curve case.
pub struct CurvePlan<'a> {
    /// The selected curve clippers.
    pub entries: Vec<&'a CurveEntry>,
    /// The run's seed.
    pub seed: u64,
}

/// One object's answer from one clipper.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectAnswer {
    /// Visible parameter intervals.
    pub intervals: Vec<(f64, f64)>,
    /// The clipped filled area, for filled objects.
    pub area: Option<f64>,
}

/// The objects of a generated case, each clipped as an outline and filled: whole ellipses as
/// filled ellipses, arcs as sectors or chord regions (`filled_object`).
pub fn case_objects(arcs: &[EllipseArc]) -> Vec<CurveObject> {
    arcs.iter().enumerate().map(|(k, &arc)| CurveObject::from_filled(filled_object(arc, k))).collect()
}

/// Every object's answer, and the failures found (object index, message).
pub type CheckedObjects = (Vec<ObjectAnswer>, Vec<(usize, String)>);

/// Runs `clipper` on every object against `window` and checks each answer: the oracle on the
/// outline (and the filled region), then the split identities against the window's complement.
/// Returns the answers and, per object, the first failure. A refusal or panic fails the whole
/// case (the `Err`).
pub fn run_objects(
    clipper: CurveClipper,
    window: &Polygons,
    objects: &[CurveObject],
) -> Result<CheckedObjects, String> {
    guarded(|| {
        let prepared = clipper.prepare(window).map_err(|e| format!("refused the window: {e}"))?;
        let around = objects.iter().fold(window.bounds(), |b, o| b.union(o.bounds()));
        let rest = complement_window(window, &around);
        let complement = clipper.prepare(&rest).map_err(|e| format!("refused the complement window: {e}"))?;
        let mut answers = Vec::with_capacity(objects.len());
        let mut failures = Vec::new();
        for (k, o) in objects.iter().enumerate() {
            let seen = prepared.visible(&o.arc);
            let other = complement.visible(&o.arc);
            let mut area = None;
            let mut verdict = check_visible(window, &o.arc, &seen.intervals).map_err(|e| format!("outline: {e}"));
            if let Some(filled) = o.filled_arc() {
                let inside = prepared.clip_filled_arc(&filled).region;
                let outside = complement.clip_filled_arc(&filled).region;
                area = Some(inside.area());
                verdict = verdict
                    .and_then(|()| {
                        check_filled_region(window, &filled, &inside)
                            .map_err(|e| format!("filled ({}): {e}", fill_name(&filled)))
                    })
                    .and_then(|()| {
                        check_identities(
                            &o.arc,
                            &seen.intervals,
                            &other.intervals,
                            Some((&filled, inside.area(), outside.area())),
                        )
                        .map_err(|e| e.to_string())
                    });
            } else {
                verdict = verdict.and_then(|()| {
                    check_identities(&o.arc, &seen.intervals, &other.intervals, None).map_err(|e| e.to_string())
                });
            }
            if let Err(message) = verdict {
                failures.push((k, format!("object {k} ({}): {message}", describe(&o.arc))));
            }
            answers.push(ObjectAnswer { intervals: seen.intervals, area });
        }
        Ok((answers, failures))
    })
}

/// How a filled shape is closed, in words.
fn fill_name(filled: &FilledArc) -> &'static str {
    if filled.is_whole() { "ellipse" } else { filled.fill().name() }
}

/// One object in words.
pub fn describe(arc: &EllipseArc) -> String {
    let e = arc.ellipse();
    let (c, (rx, ry)) = (e.center(), e.radii());
    let shape = if e.is_circle() {
        format!("circle at ({:.3}, {:.3}) r {rx:.3}", c.x, c.y)
    } else {
        format!("ellipse at ({:.3}, {:.3}) radii {rx:.3}, {ry:.3} turned {:.4} rad", c.x, c.y, e.rotation())
    };
    if arc.is_closed() { shape } else { format!("arc of {shape} from {:.6} sweeping {:.6}", arc.start(), arc.sweep()) }
}

/// The clipped area by the polygon route: the filled ellipse or arc flattened within
/// `ROUTE_TOLERANCE` of its long radius, intersected with the window by Vatti (even-odd), with
/// the bound it must meet.
pub fn polygon_route(window: &Polygons, filled: &FilledArc) -> Result<(f64, f64), String> {
    let e = filled.ellipse();
    let tolerance = ROUTE_TOLERANCE * e.max_radius();
    let ring = flatten_filled_arc(filled, tolerance).map_err(|err| err.to_string())?;
    let clipped = Vatti.clip(&ring, window, BoolOp::Intersection, FillRule::EvenOdd).map_err(|err| err.to_string())?;
    let bound = flattening_area_bound(&filled.region(), tolerance) + CURVE_AREA_TOLERANCE * e.bounds().area();
    Ok((clipped.signed_area(), bound))
}

/// Whether two clippers' answers agree: the same number of intervals with ends within
/// [`TANGENT_T_TOLERANCE`], and areas within [`CURVE_AREA_TOLERANCE`] of the ellipse's box.
fn answers_agree(objects: &[CurveObject], a: &[ObjectAnswer], b: &[ObjectAnswer]) -> Result<(), String> {
    for (k, ((o, x), y)) in objects.iter().zip(a).zip(b).enumerate() {
        let same_ends = x.intervals.len() == y.intervals.len()
            && x.intervals
                .iter()
                .zip(&y.intervals)
                .all(|(p, q)| (p.0 - q.0).abs() <= TANGENT_T_TOLERANCE && (p.1 - q.1).abs() <= TANGENT_T_TOLERANCE);
        if !same_ends {
            return Err(format!("object {k}: visible intervals {:?} vs {:?}", x.intervals, y.intervals));
        }
        if let (Some(p), Some(q)) = (x.area, y.area)
            && (p - q).abs() > CURVE_AREA_TOLERANCE * o.arc.ellipse().bounds().area()
        {
            return Err(format!("object {k}: filled areas {p} vs {q}"));
        }
    }
    Ok(())
}

impl CurvePlan<'_> {
    /// Runs case `index` of `workload` on a rectangle window and on a polygon window.
    pub fn run(&self, workload: &'static str, index: usize) -> Result<CaseOutcome, String> {
        let mut outcome =
            CaseOutcome::new(self.entries.iter().map(|e| (e.clipper.name(), e.origin, "curve")).collect(), workload);
        for variant in CURVE_WINDOWS {
            let case = curve_case(workload, self.seed, index, variant, CURVES_PER_CASE).map_err(|e| e.to_string())?;
            let objects = case_objects(&case.objects);
            let finding = |clipper: &'static str, check: Check, message: String| Finding {
                kind: Kind::Curve,
                workload,
                index,
                window: variant,
                op: None,
                fill: None,
                clipper,
                check,
                how: if check == Check::Oracle { Failing::Wrong } else { Failing::Disagrees },
                message,
            };
            // The polygon route, once per filled object: (area, bound).
            let route: Vec<Option<Result<(f64, f64), String>>> =
                objects.iter().map(|o| o.filled_arc().map(|f| guarded(|| polygon_route(&case.window, &f)))).collect();
            let mut answers: Vec<Option<Vec<ObjectAnswer>>> = vec![None; self.entries.len()];
            for (i, e) in self.entries.iter().enumerate() {
                let row = &mut outcome.rows[i];
                // A case counts once, though it runs on both window kinds.
                row.cases += usize::from(variant == CURVE_WINDOWS[0]);
                row.runs += objects.len() + objects.iter().filter(|o| o.filled).count();
                match run_objects(e.clipper, &case.window, &objects) {
                    Ok((got, failures)) => {
                        row.oracle_failures += failures.len();
                        if let Some((_, message)) = failures.into_iter().next() {
                            outcome.findings.push(finding(e.clipper.name(), Check::Oracle, message));
                        }
                        let mut off = 0;
                        let mut first = None;
                        for (k, (answer, r)) in got.iter().zip(&route).enumerate() {
                            let (Some(area), Some(r)) = (answer.area, r) else { continue };
                            let verdict = match r {
                                Ok((route_area, bound)) if (area - route_area).abs() <= *bound => Ok(()),
                                Ok((route_area, bound)) => Err(format!(
                                    "object {k} ({}): exact area {area} but the polygon route gives {route_area} (bound {bound:e})",
                                    describe(&objects[k].arc)
                                )),
                                Err(why) => Err(format!("object {k}: the polygon route failed: {why}")),
                            };
                            if let Err(message) = verdict {
                                off += 1;
                                first.get_or_insert(message);
                            }
                        }
                        *outcome.rows[i].disagreements.entry(POLYGON_ROUTE).or_default() += off;
                        if let Some(message) = first {
                            outcome.findings.push(finding(
                                e.clipper.name(),
                                Check::Disagreement(POLYGON_ROUTE),
                                message,
                            ));
                        }
                        answers[i] = Some(got);
                    }
                    Err(message) => {
                        row.oracle_failures += 1;
                        outcome.findings.push(finding(e.clipper.name(), Check::Oracle, message));
                    }
                }
            }
            for x in 0..self.entries.len() {
                for y in x + 1..self.entries.len() {
                    let (Some(ax), Some(ay)) = (&answers[x], &answers[y]) else { continue };
                    let verdict = answers_agree(&objects, ax, ay);
                    if let Some((me, other)) = outcome.compared((x, y), &|_| true, verdict.is_err())
                        && let Err(message) = verdict
                    {
                        let check = Check::Disagreement(self.entries[other].clipper.name());
                        outcome.findings.push(finding(self.entries[me].clipper.name(), check, message));
                    }
                }
            }
        }
        Ok(outcome)
    }
}

/// Why the curve check `check` of clipper `clipper` still fails on these inputs, or `None` when
/// it passes (the predicate for cutting a failing case down to one object, and `--replay`'s).
pub fn curve_failure(
    entries: &[CurveEntry],
    clipper: &str,
    check: Check,
    window: &Polygons,
    objects: &[CurveObject],
) -> Option<String> {
    let entry = entries.iter().find(|e| e.clipper.name() == clipper)?;
    let (answers, failures) = match run_objects(entry.clipper, window, objects) {
        Ok(done) => done,
        Err(message) => return (check == Check::Oracle).then_some(message),
    };
    match check {
        Check::Oracle => failures.into_iter().next().map(|(_, m)| m),
        Check::Disagreement(POLYGON_ROUTE) => objects.iter().zip(&answers).enumerate().find_map(|(k, (o, a))| {
            let (area, filled) = (a.area?, o.filled_arc()?);
            match guarded(|| polygon_route(window, &filled)) {
                Ok((route, bound)) if (area - route).abs() <= bound => None,
                Ok((route, bound)) => {
                    Some(format!("object {k}: exact area {area}, polygon route {route} (bound {bound:e})"))
                }
                Err(why) => Some(format!("object {k}: the polygon route failed: {why}")),
            }
        }),
        Check::Disagreement(other) => {
            let other = entries.iter().find(|e| e.clipper.name() == other)?;
            let (theirs, _) = run_objects(other.clipper, window, objects).ok()?;
            answers_agree(objects, &answers, &theirs).err()
        }
        Check::AreaIdentities | Check::Hung => None,
    }
}
