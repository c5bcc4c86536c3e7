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
//!   table. O((n + k) log n) for n edges and k crossings. Before it (and before the scanbeam
//!   sweep of operands off a coarse grid, whose rounding is certified: an edge crossing such a
//!   pair would cross it twice at one point), an operand of several rings loses its pairs of
//!   exactly coincident edges running opposite ways (`opposite_edges`): such a pair separates
//!   equal winding numbers, and layers that tile the plane (a map's countries, a grid of tiles)
//!   run every shared border once each way.
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
//! - Valid output by proof (`rounding_certificate`). Rounded crossings can break an output's
//!   form only where something else lies within a few ulps of them (nearly coincident edges,
//!   vertices a few ulps off an edge, three edges through a crossing f64 cannot hold). So either
//!   rounding is proven harmless, and the output has the exact arrangement's form with each
//!   vertex within 76 ulps of the largest input coordinate of its exact place (in each
//!   coordinate), or the snap-rounded operands are swept instead:
//!   - on coarse grids (every coordinate an integer below 2^9 in units of one power of two) it is
//!     proven before the sweep: crossings are the exact ones rounded once, taken in their exact
//!     order, and no rounded point comes within rounding of anything it is not on; and where
//!     every edge is horizontal or vertical, at any coordinates, nothing is rounded at all;
//!   - on any other operands the sweep certifies it as it goes, in O(1) per event: no two events
//!     within a box of `2D × 2H` of each other (`D` a thousandth of the largest coordinate, `H`
//!     408 ulps of it), no edge flatter than `4H/D` near an output point (those are checked on a
//!     list of their own), and at every output point the nearest edges either side in the table
//!     farther than 256 ulps. Crossings whose quotient may err by over 32 ulps (edges at a small
//!     angle) are computed from accurate determinants. The argument is in `rounding_certificate`.
//!   - Where the certificate fails, the event sweep runs once more routing the near misses it
//!     meets (`near_misses`): an edge passing within 4 ulps of the largest coordinate of a
//!     vertex it does not end at is split there while nothing it decided depends on its line (a
//!     walk beside every vertex finds them), and a crossing of the vertex's own edge with it
//!     just below is put off until the vertex. Its output is the exact one of operands within
//!     that distance of the given ones. Not on the first sweep: the walks cost a few percent,
//!     and most sweeps hold without them. The paper's sweep does not route: it falls back below.
//!   - Where the certificate fails and a rounded point was output, the sweep stops. With `s`
//!     the smallest power of two at least 4 ulps of the largest input coordinate, every edge
//!     passing within `s` of a vertex it does not end at is routed through that vertex
//!     (`clip_core::snap_edges_to_vertices`: vertices stay, edges move by at most `s`) and the
//!     routed operands are swept and certified again: the near misses of map layers whose shared
//!     borders were rounded apart are of that kind. Where that fails too, both operands are snap
//!     rounded (`clip_core::snap_round`, Hobby 1999) on a grid of pixels of `s` and swept once
//!     (`snap_fallback`): their edges meet only at vertices, so that sweep rounds nothing and
//!     its output is valid by construction; each of its vertices is within `s·√2/2` of the
//!     exact vertex or crossing. No output is checked or repaired afterwards.
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
mod horizontal;
mod intersections;
mod near_misses;
mod opposite_edges;
mod order_index;
mod output;
mod prepared;
mod prepared_reuse;
mod raw_rings;
mod rounding_certificate;
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
    BoolOp, ClipError, FillRule, NearEdges, Operand, PolygonCapabilities, PolygonClipper, Polygons, Trapezoid,
    snap_edges_to_vertices, validate_polygons,
};

pub use crate::prepared::PreparedClip;
pub use crate::prepared_reuse::VattiPrepared;
pub use crate::route::{Route, SweepAxis};
pub use crate::sweep::Sweep;

use crate::cleanup::{Touches, Turns};
use crate::contribution::Rules;
use crate::opposite_edges::cancel_opposite_edges;
use crate::raw_rings::RawRings;
use crate::rounding_certificate::rounding_is_harmless;
use crate::route::{Plan, edge_count};
use crate::scratch::Scratch;
pub(crate) use crate::sweep::Certify;
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

/// What is known of the operands of a sweep, which decides whether its rounding is certified.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Operands {
    /// Any valid operands: the sweep certifies that rounding left its output's form as the
    /// exact arrangement's (`rounding_certificate`), or gives no output.
    Float,
    /// Any valid operands, swept by the event sweep certified and routing the near misses it
    /// meets (`near_misses`): the retry where the certificate failed.
    FloatRouted,
    /// Operands on a coarse grid or with only horizontal and vertical edges, where rounding
    /// provably changes nothing ([`rounding_is_harmless`]).
    RoundingHarmless,
    /// The snap fallback's operands: noded (their edges meet only at vertices, so their
    /// straight-through vertices stay), and nothing is rounded.
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

    /// The sweep's conventional rings of valid operands, by a chain of fallbacks from floating
    /// point to snap rounding (as GEOS OverlayNG falls back). Where the rounding certificate
    /// fails (`rounding_certificate`: some rounded point came within its clearance of an edge or
    /// event it is not on), the event sweep runs again routing the near misses it meets
    /// (`near_misses`); where that fails too, the operands are swept again with every edge that passes within a
    /// pixel ([`snap_fallback::pixel_size`]) of a vertex not its own routed through that vertex
    /// (`clip_core::snap_edges_to_vertices`: the near misses of layers whose shared borders were
    /// rounded apart), certified again; where that fails too, the snap-rounded operands are
    /// swept (`snap_fallback`): their edges meet only at vertices, so that sweep rounds nothing.
    /// Each way the output's form is the exact arrangement's, of the operands, of the routed ones
    /// or of the snapped ones.
    fn sweep_polygons(subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule, sweep: Sweep) -> Polygons {
        let operands = if rounding_is_harmless(subject, clip) { Operands::RoundingHarmless } else { Operands::Float };
        let (subject, clip) = swept_operands(subject, clip, sweep, operands == Operands::Float);
        if let Some(out) = Vatti::sweep_clean(&subject, &clip, op, fill, sweep, operands) {
            return out;
        }
        // The event sweep again, routing the near misses it meets: where those were all that
        // failed (map layers rounded apart), it holds without a search over every edge. Not on
        // the first try: the walks cost every certified sweep a few percent.
        if sweep == Sweep::Events
            && let Some(out) = Vatti::sweep_clean(&subject, &clip, op, fill, sweep, Operands::FloatRouted)
        {
            return out;
        }
        // Both later steps start from the pairs of edges within a pixel of each other, found once.
        // The grid cannot refuse valid operands (the pixel is chosen for their largest
        // coordinate); were it to, they are swept uncertified.
        let Ok(near) = NearEdges::of(&subject, &clip, snap_fallback::pixel_size(&subject, &clip)) else {
            return Vatti::sweep_clean(&subject, &clip, op, fill, sweep, Operands::RoundingHarmless)
                .unwrap_or_default();
        };
        if let Some((a, b)) = snap_edges_to_vertices(&near) {
            // Not cancelled again: routing makes few new pairs of opposite coincident edges (where
            // the vertex ended a neighbour's edge along the one routed), and a pair left costs
            // only a certificate that fails where an edge crosses it, not a wrong output.
            if let Some(out) = Vatti::sweep_clean(&a, &b, op, fill, sweep, Operands::Float) {
                return out;
            }
        }
        // Snapped as swept: without their opposite coincident pairs, so shared borders are noded
        // once, not twice.
        let snapped = snap_fallback::SnappedOperands::of(&near);
        snapped.to_world(&Vatti::sweep_polygons_once(&snapped.subject, &snapped.clip, op, fill, sweep))
    }

    /// The sweep's conventional rings of snap-rounded operands, swept as they are: they were
    /// snapped from operands without opposite coincident pairs, and the sweep takes the few that
    /// snapping makes as it takes any overlapping edges.
    fn sweep_polygons_once(subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule, sweep: Sweep) -> Polygons {
        Vatti::sweep_clean(subject, clip, op, fill, sweep, Operands::Noded).unwrap_or_default()
    }

    /// The sweep's conventional rings of valid operands (as [`swept_operands`] gives them), `None`
    /// where they are [`Operands::Float`] and the rounding certificate failed.
    fn sweep_clean(
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
        sweep: Sweep,
        operands: Operands,
    ) -> Option<Polygons> {
        let certify = match operands {
            Operands::Float => Certify::Yes,
            Operands::FloatRouted => Certify::Routing,
            Operands::RoundingHarmless | Operands::Noded => Certify::No,
        };
        let noded = operands == Operands::Noded;
        Vatti::sweep(sweep, subject, clip, op, fill, false, noded, certify, |rings, touches, turns, _, verdict| {
            verdict.is_ok().then(|| Polygons::new(cleanup::conventional_rings(rings, touches, turns)))
        })
    }

    /// Runs the sweep of valid operands (as [`swept_operands`] gives them) in this thread's
    /// reused buffers and hands its raw rings (none where the certificate failed), trapezoids
    /// and whether its rounding is certified to `finish`. `noded`: the operands' edges
    /// meet only at vertices (snap rounded), so their straight-through vertices are kept
    /// (`Bounds::rebuild`). `certify`: rounding is certified (else the certificate holds), and the
    /// sweep stops early where it cannot be.
    #[allow(clippy::too_many_arguments)]
    fn sweep<T>(
        sweep: Sweep,
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
        trapezoids: bool,
        noded: bool,
        certify: Certify,
        finish: impl FnOnce(&RawRings, &mut Touches, &mut Turns, Vec<Trapezoid>, Result<(), &'static str>) -> T,
    ) -> T {
        Scratch::with(|scratch| {
            scratch.bounds.rebuild(subject, clip, noded);
            let buffers = std::mem::take(&mut scratch.sweep);
            let mut line = SweepLine::new(sweep, &scratch.bounds, Rules::new(op, fill), trapezoids, certify, buffers);
            line.run();
            let verdict = line.cert.verdict();
            // A failed certificate's rings are swept again, never read.
            if verdict.is_ok() {
                line.out.rings_into(&mut scratch.raw);
            } else {
                scratch.raw.clear();
            }
            let traps = line.traps.take().unwrap_or_default();
            scratch.sweep = line.into_buffers();
            finish(&scratch.raw, &mut scratch.touches, &mut scratch.turns, traps, verdict)
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

/// The operands as the sweep takes them: for the event sweep and for a certified one, without
/// their pairs of exactly coincident edges running opposite ways (`opposite_edges`). The event
/// sweep is taken for large operands, where a hash pass over the edges costs little beside the
/// sweep and layers that tile the plane are common; and a certified sweep would fail where an
/// edge crosses such a pair (two crossings at one point).
fn swept_operands<'a>(
    subject: &'a Polygons,
    clip: &'a Polygons,
    sweep: Sweep,
    certify: bool,
) -> (Cow<'a, Polygons>, Cow<'a, Polygons>) {
    if sweep == Sweep::Events || certify {
        (cancel_opposite_edges(subject), cancel_opposite_edges(clip))
    } else {
        (Cow::Borrowed(subject), Cow::Borrowed(clip))
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
    let (a, b) = swept_operands(&a, &b, sweep, false);
    Vatti::sweep(sweep, &a, &b, op, fill, true, false, Certify::No, |_, _, _, traps, _| traps)
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
