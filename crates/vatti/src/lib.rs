//! clip-vatti: Vatti's generic polygon clipper (1992): intersection, union, difference and xor,
//! polygon and trapezoid output.
//!
//! Implements B. R. Vatti, *A generic solution to polygon clipping*, Communications of the ACM
//! 35(7):56-63, 1992. Subject and clip may be any polygons: concave, self-intersecting, with
//! holes, in several parts, read under any [`FillRule`].
//!
//! # The paper's vocabulary in the code
//!
//! | paper | here |
//! | --- | --- |
//! | bounds, local minima table (LMT) | `bounds::Bounds`, `bounds::LocalMinimum` |
//! | scanbeam table (SBT), MarkSBT | `scanbeam::Scanbeams` (every vertex height, sorted once), or `edge_tops` (the active edges' tops in a heap, those that start together in sorted runs) |
//! | active edge table (AET), edge record (Table 1) | `active::ActiveEdges` (a linked list with a search tree, `order_index`), `active::Edge` |
//! | sorted edge table (ST), intersection table (IT) | `intersections`, or `crossing_queue` |
//! | contributing edge, left/right side, rules 1-6 | `contribution` (derived from winding counts) |
//! | AddLocalMin, AddLeft/AddRight, AddLocalMax, AppendPolygon | `output::OutputBuilder` |
//! | horizontal edges (Extensions) | `horizontal` (edges slide along the scanline) |
//! | trapezoid generation | `trapezoids` |
//!
//! Instead of the paper's even-odd parity, every active edge carries the winding numbers of
//! both operands just left of it (`wind_left`), updated on every swap. A region is in the result
//! when `op(fill(w_subject), fill(w_clip))` holds; an edge contributes where the result differs
//! on its two sides. The paper's rule tables for intersection, union and difference all follow
//! from this, and so does xor, which the paper does not give: see `contribution` for the
//! derivation. Non-zero, positive and negative fill only change `fill`.
//!
//! # Two sweeps
//!
//! The sweep keeps the paper's model: local minima start pairs of bounds, edges carry their
//! winding numbers and output chains, and the output is built at local minima, intermediate
//! vertices, crossings and local maxima. What happens between scanlines can be found two ways
//! ([`Sweep`]), with the same output:
//!
//! - [`Sweep::Scanbeam`], the paper's: every vertex height is a scanline, and in every scanbeam
//!   every active edge's x at the top is computed and sorted to find the crossings. That is
//!   Θ(n) per scanbeam with n edges active, so Θ(n²) where many edges span many scanbeams
//!   (nested or concentric rings, combs, long spirals).
//! - [`Sweep::Events`], after Bentley and Ottmann (1979): an edge is touched only where it
//!   starts, where it ends and where it crosses a neighbour. The active edges' tops wait in a
//!   heap, a pair of edges is tested (exactly) for a crossing only when it becomes adjacent,
//!   and crossings wait in a second heap; a new edge finds its place in a search tree over the
//!   table. O((n + k) log n) for n edges and k crossings. Before it, an operand of several
//!   rings loses its pairs of exactly coincident edges running opposite ways
//!   (`opposite_edges`): such a pair separates equal winding numbers, and layers that tile the
//!   plane (a map's countries, a grid of tiles) run every shared border once each way.
//!
//! [`Vatti`] takes the scanbeam sweep for operands of at most 512 edges in all, where its
//! quadratic term is bounded and its cheaper crossings win on crossing-dense inputs, and the
//! event sweep above; [`FixedSweep`] fixes either (`vatti-scanbeam` in the harness reproduces
//! the paper's cost at every size).
//!
//! Either sweep runs along y, as the paper's does, or along x ([`SweepAxis`]): the operands
//! are then mirrored across y = x, exactly and with every winding number kept
//! (`Polygons::transposed`), swept, and the output mirrored back. [`Vatti`] sweeps along x
//! when a vertical line spans, on average, fewer than half the edges a horizontal one does
//! (`Σ|Δx| / width` against `Σ|Δy| / height`): the cost of each event grows with the edges
//! spanning the line, so a comb's upright teeth, swept upwards, keep half its edges in the
//! table at once, and swept rightwards a handful. [`FixedSweep`] sweeps along y.
//!
//! # Routes: the paper's Extensions and a pre-filter
//!
//! The paper's Extensions name two optimisations they do not describe: "clipping several
//! subject polygons against a constant clip polygon by preassigning the edges of the clip
//! polygon to the LMT", and rectangular clip bounds. A third comes from GEOS's overlay: never
//! sweep what cannot reach the other operand. What a clip does around the sweep is a [`Route`],
//! chosen by one function (`route::Plan::of`) from one block of limits (`route::limits`):
//!
//! - [`Route::Whole`]: both operands swept as given; ∪ and ⊕, and operands of at most 64 edges
//!   in all, where cutting costs more than it saves.
//! - [`Route::Envelope`] (`envelope`): for ∩ the subject is cut to the clip's bounding box
//!   (grown by an eighth), then the clip to the cut subject's; for − the clip to the subject's.
//!   A stretch of edges that misses the box is replaced by a path around it and the loops it
//!   wound around the box are added back as border loops, so every winding number inside the
//!   box is unchanged and no point is rounded. A spiky star of 10^6 edges against a small box
//!   inside it sweeps a handful of edges; a rectangular clip is the box itself. When no edge of
//!   the other operand reaches the box, that operand is all or nothing there, and only the
//!   subject (or nothing) is swept.
//! - [`Route::Splice`] (`far_splice`), for ∪ and ⊕ with a prepared clip ([`Vatti::prepare`],
//!   [`PreparedClip`], `Send + Sync`): outside the subject's grown box the result is the clip's
//!   region, which preparing resolved once into conventional rings, so its chains there pass
//!   through unchanged; only the subject with the clip's part inside the box (cut exactly,
//!   windings kept) is swept, and the chains are joined back where they cross the box's border
//!   (exact crossing tests; the rounded crossing points are never output). Anything degenerate
//!   at the border sweeps whole. For ∩ and − the prepared clip's rings have boxes over runs of
//!   edges (`edge_blocks`), so the envelope finds the clip edges near a subject without visiting
//!   the others. [`VattiPrepared`] puts it behind [`PolygonClipper`] (`vatti-prepared` in the
//!   harness), keeping each thread's last prepared clip.
//!
//! [`Vatti::clip_along`] and [`PreparedClip::clip_along`] take any route, sweep and axis; the tests
//! run every one on the same inputs against each other and the exact oracle.
//!
//! # Exactness and limits
//!
//! - Every in/out and ordering decision at a vertex (where a new edge enters the table, which
//!   way edges leave a shared point, where a horizontal stops) uses `clip_core::predicates`, and
//!   so does the event sweep's test of whether two adjacent edges cross, and the order of two
//!   edges whose computed x at a beam's top are within their rounding of each other
//!   (`predicates::x_at_height_cmp`: rounded x there would invent crossings). Crossing points are
//!   computed once, kept inside the scanbeam, and processed so only adjacent edges swap. They
//!   are rounded to f64: the output is exact for inputs whose crossings are representable
//!   (integer grids) and within a few ulps of the true region otherwise.
//! - Input rings lose repeated and collinear vertices (zero-area spikes included) first: that
//!   leaves every winding number off the ring unchanged.
//! - Output vertices are shared exactly between chains that meet: a point emitted at an event
//!   also goes into every contributing edge passing through it (exactly, or lying on the same
//!   line, or within 64 ulps when the point is a rounded crossing of several edges through one
//!   point). That tolerance (`active::ROUNDING`) decides only where output rings get vertices,
//!   never what is inside, and only for points that are rounded: an edge passed on a scanline
//!   at its own vertex, at a sliding edge's x or exactly on its line (`predicates::on_line`)
//!   is passed at an exact point.
//! - Clean-up (`cleanup`) rebuilds only rings that touch: opposite coincident edges cancel,
//!   vertices inside horizontal output edges split them, and rings are re-walked corner by
//!   corner, then split where they still visit a vertex twice. Where nothing cancels or splits
//!   (most touches: holes on their outers, pinches), the walk turns only at the shared points
//!   (`turns`), with the same result; where something splits, the rings sharing no point with
//!   it are walked that way apart from the rest. Horizontal spikes (a ring running out along a
//!   scanline and straight back, which slides emit where both operands have horizontals on it)
//!   are dropped as the sweep's rings are read out.
//! - Output follows the workspace's conventions (`docs/DESIGN.md`): simple rings, outers
//!   counter-clockwise, holes clockwise, no repeated or collinear vertices, no zero-area rings.
//!   Where the result pinches at a point the rings are split there (two rings touching at a
//!   vertex, never one ring visiting it twice); `clip_core::nest` groups the holes with their
//!   outers. No area threshold is applied, so slivers a unit wide survive where Clipper2,
//!   rounding to its integer grid, drops them: ring counts differ from Clipper2's on many of its
//!   `Polygons.txt` cases (the cross-library test in `clip-peers` runs Clipper2 on each,
//!   normalises its output to these conventions and checks the counts agree).
//! - Snap-rounded fallback (`snap_fallback`, `form_check`): with features a few ulps wide far
//!   from the origin, or nearly coincident edges (angles of 1e-16, offsets of a few ulps), rounded
//!   crossings can leave two rings running the same way along an edge (their insides
//!   overlapping), a clockwise ring that no ring holds, or rings crossing or nested against their
//!   orientation. The clean-up reports the first two among the rings it rebuilds (for the first,
//!   two edges leaving or arriving at one point in the same direction once opposite edges
//!   cancelled; two one way and one back, as grid unions' holes retrace their outers, only near
//!   rounding and when the rebuilt rings then cross or overlap at a point they share, checked
//!   exactly); outputs near rounding also get a full exact check of their form (`form_check`:
//!   up to 65,536 edges where two distinct vertices lie within 4096 ulps of the inputs' largest
//!   coordinate of each other or the sweep met a near miss, up to 1024 where an edge or a ring is
//!   that short or thin), and every output, whatever its size, gets an exact check of the edges
//!   passing near crossings taken one after another within 16 ulps of each other (several edges
//!   through one point that f64 cannot hold: `form_check::crossing_near`). Where the sweep
//!   left a point near an edge but off it (a near miss), the clean-up also splits slanted edges
//!   at the vertices on them, so rounded edges through exact vertices cancel or are reported like
//!   horizontal ones. A broken output is replaced once, by the sweep of both operands snap
//!   rounded (`clip_core::snap_round`, Hobby 1999) on a grid of pixels of `s`, the smallest power
//!   of two at least 4 ulps of the largest input coordinate: the rounded operands' edges meet
//!   only at vertices, so that sweep (ordering edges exactly where rounding could swap them, and
//!   taking no exact point for a rounded one) rounds nothing, and its output is valid by
//!   construction; each of its vertices is within `s·√2/2` of the exact vertex or crossing.
//!   Outputs not reported broken are returned as the first sweep made them, but for one repair
//!   in outputs of over 1024 edges: a sliver (a ring at most 4 ulps of its coordinates wide) that
//!   runs against its nesting, turned inside out by rounded crossings, is dropped, as snap
//!   rounding would collapse it (`form_check::drop_flipped_slivers`). Known limit: any other
//!   output broken between rings that share no point, away from near crossings, with no near
//!   vertices and over 1024 edges (or over 65,536), is not found.
//! - Exact by construction on coarse grids (`form_check::rounding_is_harmless`): where every
//!   coordinate of both operands is an integer below 2^9 in units of one power of two, crossings
//!   are the exact ones rounded once, the sweep takes its events in their exact order, and no
//!   rounded point comes within rounding of an edge or point it is not on; edges through a
//!   crossing f64 cannot hold are found exactly (`predicates::through_crossing`). Such outputs
//!   are not checked, and never fall back.
//! - Bad input (NaN, infinity, coordinates beyond `clip_core::MAX_COORDINATE` or non-zero below
//!   `clip_core::MIN_COORDINATE`, rings with fewer than three distinct points) gives a
//!   [`ClipError`]; nothing panics or loops.
//!
//! # Example
//!
//! ```
//! use clip_core::{BoolOp, FillRule, PolygonClipper, Polygons, Rect};
//! use clip_vatti::Vatti;
//!
//! let a = Polygons::from(Rect::new(0.0, 0.0, 2.0, 2.0));
//! let b = Polygons::from(Rect::new(1.0, 1.0, 3.0, 3.0));
//! let both = Vatti.clip(&a, &b, BoolOp::Intersection, FillRule::NonZero).unwrap();
//! assert_eq!(both.signed_area(), 1.0);
//! let either = Vatti.clip(&a, &b, BoolOp::Union, FillRule::NonZero).unwrap();
//! assert_eq!(either.signed_area(), 7.0);
//! assert_eq!(either.rings.len(), 1);
//!
//! // The same intersection as trapezoids, straight from the sweep.
//! let traps = Vatti.clip_trapezoids(&a, &b, BoolOp::Intersection, FillRule::NonZero).unwrap();
//! assert_eq!(traps.iter().map(|t| t.area()).sum::<f64>(), 1.0);
//! ```

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

mod active;
mod bounds;
mod cleanup;
mod contribution;
mod crossing_queue;
mod edge_blocks;
mod edge_tops;
mod envelope;
mod far_splice;
mod form_check;
mod horizontal;
mod intersections;
mod opposite_edges;
mod order_index;
mod output;
mod prepared;
mod prepared_reuse;
mod raw_rings;
mod route;
mod scanbeam;
mod scratch;
mod simplify;
mod small_sort;
mod snap_fallback;
mod sweep;
mod trapezoids;

use std::borrow::Cow;

use clip_core::{
    BoolOp, ClipError, FillRule, Operand, PolygonCapabilities, PolygonClipper, Polygons, Trapezoid, validate_polygons,
};

pub use crate::prepared::PreparedClip;
pub use crate::prepared_reuse::VattiPrepared;
pub use crate::route::{Route, SweepAxis};
pub use crate::sweep::Sweep;

use crate::cleanup::{Touches, Turns};
use crate::contribution::Rules;
use crate::opposite_edges::cancel_opposite_edges;
use crate::raw_rings::RawRings;
use crate::route::{Plan, edge_count};
use crate::scratch::Scratch;
use crate::sweep::SweepLine;

/// Vatti's generic polygon clipper: all four operations under all four fill rules, any
/// operands, polygon or trapezoid output. Its route and sweep are chosen by the operands'
/// sizes and the operation ([`Route`], [`Sweep`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Vatti;

/// [`Vatti`] with its sweep fixed, along y as the paper sweeps: `vatti-scanbeam` (the paper's
/// sweep, whatever the input) and `vatti-events` in the harness. The same region as [`Vatti`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FixedSweep(pub Sweep);

/// What is known of the operands of a sweep, which decides what its output is checked for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Operands {
    /// Any valid operands: rounded crossings can break the output's form, which is checked.
    Rounded,
    /// Operands whose rounding cannot change the output's form
    /// (`form_check::rounding_is_harmless`): nothing is checked.
    Exact,
    /// The snap fallback's operands: noded (their edges meet only at vertices, so their
    /// straight-through vertices stay) and final.
    Noded,
}

impl Vatti {
    /// `subject op clip` along the given route, by the given sweep and axis (each chosen on the
    /// operands when `None`): for comparing the paths, which give the same region. A
    /// [`Route::Splice`] needs a prepared clip ([`PreparedClip::clip_along`]); here it is
    /// [`Route::Envelope`].
    #[allow(clippy::too_many_arguments)]
    pub fn clip_along(
        &self,
        route: Route,
        sweep: Option<Sweep>,
        axis: Option<SweepAxis>,
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
    ) -> Result<Polygons, ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        validate_polygons(clip, Operand::Clip)?;
        Ok(clip_planned(subject, clip, None, op, fill, Plan { route, sweep, axis }))
    }

    /// The sweep's conventional rings of valid operands. Where rounding broke their form (the
    /// clean-up's report, or `form_check`'s exact check of a small output near rounding), the
    /// snap-rounded operands are swept once instead (`snap_fallback`): their edges meet only at
    /// vertices, so that sweep rounds nothing. In larger outputs, slivers that rounding turned
    /// inside out are dropped (`form_check::drop_flipped_slivers`).
    fn sweep_polygons(subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule, sweep: Sweep) -> Polygons {
        if form_check::rounding_is_harmless(subject, clip) {
            return Polygons::new(Vatti::sweep_clean(subject, clip, op, fill, sweep, Operands::Exact).0.rings);
        }
        let (mut rings, near_vertices) = Vatti::sweep_clean(subject, clip, op, fill, sweep, Operands::Rounded);
        let broken = rings.broken_form || form_check::broken_near_rounding(subject, clip, &rings.rings, near_vertices);
        if broken && let Some(snapped) = snap_fallback::SnappedOperands::of(subject, clip) {
            return snapped.to_world(&Vatti::sweep_polygons_once(&snapped.subject, &snapped.clip, op, fill, sweep));
        }
        form_check::drop_flipped_slivers(&mut rings.rings);
        Polygons::new(rings.rings)
    }

    /// The sweep's conventional rings of valid operands, whatever the clean-up reports.
    fn sweep_polygons_once(subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule, sweep: Sweep) -> Polygons {
        Polygons::new(Vatti::sweep_clean(subject, clip, op, fill, sweep, Operands::Noded).0.rings)
    }

    /// The sweep's clean-up of valid operands. For [`Operands::Rounded`] only: with whether
    /// rounding broke its form (edges retraced near rounding count too), and whether two of its
    /// distinct points lie within rounding of each other (`form_check::vertices_near_rounding`)
    /// or the sweep met a near miss (a vertex within rounding of another edge).
    fn sweep_clean(
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
        sweep: Sweep,
        operands: Operands,
    ) -> (cleanup::CleanRings, bool) {
        let (strict, noded) = (operands == Operands::Rounded, operands == Operands::Noded);
        Vatti::sweep(sweep, subject, clip, op, fill, false, noded, |rings, touches, turns, _| {
            let mut clean = cleanup::conventional_rings_checked(rings, touches, turns, strict, || {
                form_check::raw_near_rounding(subject, clip, rings)
            });
            clean.broken_form |=
                strict && !clean.broken_form && form_check::crossing_near(&clean.rings, &rings.near_crossings);
            // Already broken: the fallback runs anyway, so the near test would be wasted.
            let near = strict
                && !clean.broken_form
                && form_check::checked(&clean.rings)
                && (rings.near_miss || form_check::vertices_near_rounding(subject, clip, touches.distinct_by_y()));
            (clean, near)
        })
    }

    /// Runs the sweep of valid operands in this thread's reused buffers and hands its raw rings
    /// and trapezoids to `finish`. `noded`: the operands' edges meet only at vertices (snap
    /// rounded), so their straight-through vertices are kept (`Bounds::rebuild`).
    #[allow(clippy::too_many_arguments)]
    fn sweep<T>(
        sweep: Sweep,
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
        trapezoids: bool,
        noded: bool,
        finish: impl FnOnce(&RawRings, &mut Touches, &mut Turns, Vec<Trapezoid>) -> T,
    ) -> T {
        // The event sweep is taken for large operands, where a hash pass over the edges costs
        // little beside the sweep and layers that tile the plane are common.
        let (subject, clip) = match sweep {
            Sweep::Events => (cancel_opposite_edges(subject), cancel_opposite_edges(clip)),
            Sweep::Scanbeam => (Cow::Borrowed(subject), Cow::Borrowed(clip)),
        };
        Scratch::with(|scratch| {
            scratch.bounds.rebuild(&subject, &clip, noded);
            let buffers = std::mem::take(&mut scratch.sweep);
            let mut line = SweepLine::new(sweep, &scratch.bounds, Rules::new(op, fill), trapezoids, buffers);
            line.run();
            line.out.rings_into(&mut scratch.raw);
            let traps = line.traps.take().unwrap_or_default();
            scratch.sweep = line.into_buffers();
            finish(&scratch.raw, &mut scratch.touches, &mut scratch.turns, traps)
        })
    }
}

/// The operands the sweep is given along `route` (of valid operands), and the operation
/// between them: the region of `subject op clip` is that of `a op' b`. `prepared` is the clip's
/// preparation when it has one.
fn reduced<'a>(
    route: Route,
    subject: &'a Polygons,
    clip: &'a Polygons,
    prepared: Option<&PreparedClip>,
    op: BoolOp,
    fill: FillRule,
) -> (Cow<'a, Polygons>, Cow<'a, Polygons>, BoolOp) {
    match route {
        Route::Whole => (Cow::Borrowed(subject), Cow::Borrowed(clip), op),
        Route::Envelope | Route::Splice => match prepared {
            Some(p) => envelope::prefilter(subject, clip, p.bounds(), Some(p.blocks()), op, fill),
            None => envelope::prefilter(subject, clip, clip.bounds(), None, op, fill),
        },
    }
}

/// `subject op clip` of valid operands along `plan`; `prepared` is the clip's preparation when
/// it has one.
fn clip_planned(
    subject: &Polygons,
    clip: &Polygons,
    prepared: Option<&PreparedClip>,
    op: BoolOp,
    fill: FillRule,
    plan: Plan,
) -> Polygons {
    if plan.route == Route::Splice
        && let Some(out) = prepared.and_then(|p| p.splice(subject, op, |a, b, op| swept(a, b, op, fill, plan)))
    {
        return out;
    }
    let (a, b, op) = reduced(plan.route, subject, clip, prepared, op, fill);
    swept(&a, &b, op, fill, plan)
}

/// The sweep's clean output for `a op b` (valid operands), by the plan's sweep along its axis.
fn swept(a: &Polygons, b: &Polygons, op: BoolOp, fill: FillRule, plan: Plan) -> Polygons {
    let edges = edge_count(a) + edge_count(b);
    let sweep = plan.sweep_for(edges);
    match plan.axis_for(a, b, edges) {
        SweepAxis::Y => Vatti::sweep_polygons(a, b, op, fill, sweep),
        SweepAxis::X => Vatti::sweep_polygons(&a.transposed(), &b.transposed(), op, fill, sweep).transposed(),
    }
}

/// `subject op clip` as trapezoids along `plan`.
fn trapezoids_planned(
    subject: &Polygons,
    clip: &Polygons,
    prepared: Option<&PreparedClip>,
    op: BoolOp,
    fill: FillRule,
    plan: Plan,
) -> Vec<Trapezoid> {
    let (a, b, op) = reduced(plan.route, subject, clip, prepared, op, fill);
    let sweep = plan.sweep_for(edge_count(&a) + edge_count(&b));
    Vatti::sweep(sweep, &a, &b, op, fill, true, false, |_, _, _, traps| traps)
}

impl PolygonClipper for Vatti {
    fn name(&self) -> &'static str {
        "vatti"
    }

    fn capabilities(&self) -> PolygonCapabilities {
        PolygonCapabilities { trapezoids: true, ..PolygonCapabilities::GENERAL }
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        let plan = validated_plan(subject, clip, op, None)?;
        Ok(clip_planned(subject, clip, None, op, fill, plan))
    }

    fn clip_trapezoids(
        &self,
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
    ) -> Result<Vec<Trapezoid>, ClipError> {
        let plan = validated_plan(subject, clip, op, None)?;
        Ok(trapezoids_planned(subject, clip, None, op, fill, plan))
    }
}

/// Both operands checked, then the plan for them; `sweep` fixes the sweep, along y, instead of
/// the rules' choice.
fn validated_plan(subject: &Polygons, clip: &Polygons, op: BoolOp, sweep: Option<Sweep>) -> Result<Plan, ClipError> {
    validate_polygons(subject, Operand::Subject)?;
    validate_polygons(clip, Operand::Clip)?;
    let plan = Plan::of(subject, clip, op, false);
    match sweep {
        Some(sweep) => Ok(Plan { sweep: Some(sweep), axis: Some(SweepAxis::Y), ..plan }),
        None => Ok(plan),
    }
}

impl PolygonClipper for FixedSweep {
    fn name(&self) -> &'static str {
        match self.0 {
            Sweep::Scanbeam => "vatti-scanbeam",
            Sweep::Events => "vatti-events",
        }
    }

    fn capabilities(&self) -> PolygonCapabilities {
        Vatti.capabilities()
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        let plan = validated_plan(subject, clip, op, Some(self.0))?;
        Ok(clip_planned(subject, clip, None, op, fill, plan))
    }

    fn clip_trapezoids(
        &self,
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
    ) -> Result<Vec<Trapezoid>, ClipError> {
        let plan = validated_plan(subject, clip, op, Some(self.0))?;
        Ok(trapezoids_planned(subject, clip, None, op, fill, plan))
    }
}
