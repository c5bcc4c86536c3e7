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
//! | scanbeam table (SBT), MarkSBT | `scanbeam::Scanbeams` (every vertex height, sorted once) |
//! | active edge table (AET), edge record (Table 1) | `active::ActiveEdges`, `active::Edge` |
//! | sorted edge table (ST), intersection table (IT) | `intersections` |
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
//! # The paper's Extensions: prepared clip, rectangular clip bounds, envelope pre-filter
//!
//! The paper's Extensions section names two optimisations it does not describe: "clipping
//! several subject polygons against a constant clip polygon by preassigning the edges of the
//! clip polygon to the LMT", and that "the algorithm can be optimized for rectangular clip
//! bounds, which is a typical usage of clipping". A third comes from GEOS's overlay: never sweep
//! what cannot reach the other operand.
//!
//! - **Envelope pre-filter** (`envelope`), taken by [`PolygonClipper::clip`] by itself for
//!   operands of more than 64 edges in all (smaller ones are swept whole, which is cheaper): for ∩
//!   the subject is cut to the clip's bounding box (grown by an eighth), then the clip to the
//!   cut subject's; for − the clip to the subject's. A stretch of edges that misses the box is
//!   replaced by a path around it and the loops it wound around the box are added back as
//!   border loops, so every winding number inside the box is unchanged and no point is
//!   rounded. A spiky star of 10^6 edges against a small box inside it sweeps a handful of
//!   edges. When no edge of the other operand reaches the box, that operand is all or nothing
//!   there, and only the subject (or nothing) is swept.
//! - **Splice** (`far_splice`), for ∪, ⊕ and − of a big subject: outside the other operand's
//!   box the result is an operand itself, so when that operand is already in conventional form
//!   its chains there pass through unchanged. Only its part inside the box (cut exactly, windings
//!   kept) is swept with the other operand, and the chains are joined back where it crosses the
//!   box's border (exact crossing tests; the rounded crossing points are never output). Vatti's
//!   `clip` takes it when an operand is one big ring certified simple (`star_shaped`: a point it
//!   is star-shaped from, found by linear programming and checked exactly), so a spiky star's
//!   quadratic sweep is never run; a big ring that is simple but not star-shaped is still swept.
//!   Anything degenerate at the box's border falls back to the whole sweep.
//! - **Lone small simple ring** (`simple_ring`): a ring of at most 24 vertices swept alone (the
//!   rectangle path's cut subject, a subject the pre-filter found all inside) whose edges meet
//!   only at shared vertices (every pair tested exactly) is its own conventional form.
//! - **Rectangle path** (`rect_path`): ∩ with a clip that is one axis-aligned rectangle cuts
//!   the subject to it side by side (Sutherland-Hodgman against each side's half-plane, which
//!   keeps the winding numbers inside) and sweeps the cut subject alone, for any subject and
//!   fill rule. The crossings with the sides are rounded to f64, as the sweep rounds them.
//! - **Prepared clip** ([`Vatti::prepare`], [`PreparedClip`], `Send + Sync`): the clip is
//!   validated once and its rings get boxes over runs of edges (`edge_blocks`), so for ∩ and −
//!   each subject's sweep takes only the clip edges near it, found without visiting the others.
//!   For ∪ and ⊕ the clip's region under the fill rule is resolved once into conventional rings
//!   (on the first such call), which each subject splices into: only their part inside its
//!   grown box is swept. The clip's local minima are
//!   not kept between calls: the sweep's tables are built from the cut operands, which are small. [`VattiPrepared`] puts it behind [`PolygonClipper`]
//!   (`vatti-prepared` in the harness), keeping each thread's last prepared clip.
//!
//! [`Vatti::clip_unfiltered`] keeps the plain sweep reachable; the tests compare every path with
//! it and with the exact oracle.
//!
//! # Exactness and limits
//!
//! - Every in/out and ordering decision at a vertex (where a new edge enters the table, which
//!   way edges leave a shared point, where a horizontal stops) uses `clip_core::predicates`.
//!   Crossings inside a scanbeam are found from the edges' x at its top, computed once, clamped
//!   into the scanbeam, and processed so only adjacent edges swap. Points of crossings are
//!   rounded to f64: the output is exact for inputs whose crossings are representable (integer
//!   grids) and within a few ulps of the true region otherwise.
//! - Input rings lose repeated and collinear vertices (zero-area spikes included) first: that
//!   leaves every winding number off the ring unchanged.
//! - Output vertices are shared exactly between chains that meet: a point emitted at an event
//!   also goes into every contributing edge passing through it (exactly, or lying on the same
//!   line, or within 64 ulps when the point is a rounded crossing of several edges through one
//!   point). That tolerance (`active::ROUNDING`) decides only where output rings get vertices,
//!   never what is inside.
//! - Clean-up (`cleanup`) rebuilds only rings that touch: opposite coincident edges cancel,
//!   vertices inside horizontal output edges split them, and rings are re-walked corner by
//!   corner, then split where they still visit a vertex twice. Where nothing cancels or splits
//!   (most touches: holes on their outers, pinches), the walk turns only at the shared points
//!   (`turns`), with the same result.
//! - Output follows the workspace's conventions (`docs/DESIGN.md`): simple rings, outers
//!   counter-clockwise, holes clockwise, no repeated or collinear vertices, no zero-area rings.
//!   Where the result pinches at a point the rings are split there (two rings touching at a
//!   vertex, never one ring visiting it twice); `clip_core::nest` groups the holes with their
//!   outers. No area threshold is applied, so slivers a unit wide survive where Clipper2,
//!   rounding to its integer grid, drops them: ring counts differ from Clipper2's on many of its
//!   `Polygons.txt` cases (the cross-library test in `clip-peers` runs Clipper2 on each,
//!   normalises its output to these conventions and checks the counts agree).
//! - Repair (`repair`, `form_check`): with features a few ulps wide far from the origin, or
//!   nearly parallel edges running to points 1e50 and more times farther away, rounded crossings
//!   can leave two rings running the same way along an edge (their insides overlapping), a
//!   clockwise ring that no ring holds, or rings crossing or nested against their orientation.
//!   The clean-up reports the first two among the rings it rebuilds (for the first, two edges
//!   leaving or arriving at one point in the same direction once opposite edges cancelled; two
//!   one way and one back, as grid unions' holes retrace their outers, only in the sweep's own
//!   output near rounding); outputs of at most
//!   `form_check::MAX_EDGES` edges with an edge within 4096 ulps of the inputs' largest
//!   coordinate also get a full exact check of their form. A broken output is swept once more,
//!   alone, as its union under non-zero (the region the oracle reads from it), at most
//!   `repair::MAX_PASSES` times. Where the sweep left a point near an edge but off it (a near
//!   miss), the clean-up also splits slanted edges at the vertices on them, so rounded edges
//!   through exact vertices cancel or are reported like horizontal ones. Output coordinates
//!   below `clip_core::MIN_COORDINATE` become 0 before a repair sweep, and points within
//!   `clip_core::SNAP_ULPS` ulps of each other are merged, with edges passing that close routed
//!   through them (as snap rounding does), so that crossings rounded an ulp or two apart (edges
//!   nearly through a vertex and nearly parallel to its edges) do not leave rings crossing there.
//!   Known limit: a larger output broken between rings that share no point and with no near miss
//!   is not found.
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
mod edge_blocks;
mod envelope;
mod far_splice;
mod form_check;
mod horizontal;
mod intersections;
mod output;
mod prepared;
mod prepared_reuse;
mod raw_rings;
mod rect_path;
mod repair;
mod scanbeam;
mod scratch;
mod simple_ring;
mod simplify;
mod small_sort;
mod star_shaped;
mod sweep;
mod touches;
mod trapezoids;
mod turns;

use std::borrow::Cow;

use clip_core::{
    BoolOp, ClipError, FillRule, Operand, PolygonCapabilities, PolygonClipper, Polygons, Rect, Trapezoid,
    validate_polygons,
};

pub use crate::prepared::PreparedClip;
pub use crate::prepared_reuse::VattiPrepared;

use crate::contribution::Rules;
use crate::edge_blocks::EdgeBlocks;
use crate::raw_rings::RawRings;
use crate::scratch::Scratch;
use crate::sweep::Sweep;
use crate::touches::Touches;
use crate::turns::Turns;

/// Operands of at most this many edges in all are swept whole, not cut to each other's boxes
/// first: at 4-40 edges the cut cost more than the edges it removed saved (callgrind: grid 20 ∩
/// 70.9 K to 43.2 K instructions per call, star 20 ∩ 65.3 K to 56.7 K), and its box paths
/// and border loops add edges of their own.
const SWEPT_WHOLE_UP_TO: usize = 64;

/// Edges (vertices) of all rings.
fn edge_count(p: &Polygons) -> usize {
    p.rings.iter().map(|r| r.points.len()).sum()
}

/// Vatti's generic polygon clipper: all four operations under all four fill rules, any
/// operands, polygon or trapezoid output.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Vatti;

impl Vatti {
    /// `subject op clip` by the plain sweep, without the rectangle path and the envelope
    /// pre-filter that [`PolygonClipper::clip`] takes where they apply: every input edge enters
    /// the tables. The same region; for comparing the paths.
    pub fn clip_unfiltered(
        &self,
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
    ) -> Result<Polygons, ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        validate_polygons(clip, Operand::Clip)?;
        Ok(Vatti::sweep_polygons(subject, clip, op, fill))
    }

    /// `subject op clip` with the rectangle path and the envelope pre-filter wherever they
    /// apply, small operands included (which [`PolygonClipper::clip`] sweeps whole). The same
    /// region; for comparing the paths.
    pub fn clip_prefiltered(
        &self,
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
    ) -> Result<Polygons, ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        validate_polygons(clip, Operand::Clip)?;
        let (a, b, op) = Vatti::reduced(subject, clip, clip.bounds(), None, op, fill);
        Ok(Vatti::sweep_polygons(&a, &b, op, fill))
    }

    /// What the sweep is given for valid operands: with one rectangle as the clip of ∩, the
    /// subject cut to it alone (`rect_path`); otherwise both operands with what cannot reach the
    /// result cut away (`envelope`). The region of `subject op clip` is that of the returned
    /// `a op' b`. `clip_blocks` are the clip's edge blocks when it was prepared.
    fn reduced<'a>(
        subject: &'a Polygons,
        clip: &'a Polygons,
        clip_bounds: Rect,
        clip_blocks: Option<&[EdgeBlocks]>,
        op: BoolOp,
        fill: FillRule,
    ) -> (Cow<'a, Polygons>, Cow<'a, Polygons>, BoolOp) {
        if let Some((r, inside)) = rect_path::rectangle_clip(clip, op, fill) {
            // Outside the clip both operands wind zero, so ∩ becomes the cut subject ∪ nothing.
            let a = if inside { rect_path::cut_to_rectangle(subject, r) } else { Polygons::default() };
            return (Cow::Owned(a), Cow::Owned(Polygons::default()), BoolOp::Union);
        }
        envelope::prefilter(subject, clip, clip_bounds, clip_blocks, op, fill)
    }

    /// [`Vatti::reduced`] of valid operands, except that small ones (at most
    /// [`SWEPT_WHOLE_UP_TO`] edges in all) skip the envelope pre-filter: swept whole.
    fn reduced_unless_small<'a>(
        subject: &'a Polygons,
        clip: &'a Polygons,
        op: BoolOp,
        fill: FillRule,
    ) -> (Cow<'a, Polygons>, Cow<'a, Polygons>, BoolOp) {
        if edge_count(subject) + edge_count(clip) <= SWEPT_WHOLE_UP_TO
            && rect_path::rectangle_clip(clip, op, fill).is_none()
        {
            return (Cow::Borrowed(subject), Cow::Borrowed(clip), op);
        }
        Vatti::reduced(subject, clip, clip.bounds(), None, op, fill)
    }

    /// Validates both operands and reduces them ([`Vatti::reduced_unless_small`]).
    fn filtered<'a>(
        subject: &'a Polygons,
        clip: &'a Polygons,
        op: BoolOp,
        fill: FillRule,
    ) -> Result<(Cow<'a, Polygons>, Cow<'a, Polygons>, BoolOp), ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        validate_polygons(clip, Operand::Clip)?;
        Ok(Vatti::reduced_unless_small(subject, clip, op, fill))
    }

    /// The sweep's conventional rings of valid operands, repaired where rounding broke their form.
    fn sweep_polygons(subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Polygons {
        // A small simple ring alone (the rectangle path's cut subject, often) needs no sweep.
        if clip.rings.is_empty()
            && op != BoolOp::Intersection
            && let Some(out) = simple_ring::alone(subject, fill)
        {
            return out;
        }
        let clean = |a: &Polygons, b: &Polygons, op: BoolOp, fill: FillRule, strict: bool| {
            Vatti::sweep(a, b, op, fill, false, |rings, touches, turns, _| {
                cleanup::conventional_rings_checked(rings, touches, turns, strict, || {
                    form_check::raw_near_rounding(a, b, rings)
                })
            })
        };
        let mut rings = clean(subject, clip, op, fill, true);
        // The full check only judges the sweep's own output: the repair's sweeps are judged by the
        // clean-up alone, so a check stricter than the conventions cannot make it loop.
        rings.broken_form = rings.broken_form || form_check::small_output_broken(subject, clip, &rings.rings);
        Polygons::new(repair::join_overlapping(rings, |out| {
            // Rounded output can fall below the coordinates the sweep takes: such coordinates
            // become 0 (a move far below any rounding of the other coordinates), then validate.
            let out = repair::flushed_below_min(out);
            validate_polygons(&out, Operand::Subject)?;
            Ok(clean(&out, &Polygons::default(), BoolOp::Union, FillRule::NonZero, false))
        }))
    }

    /// The sweep's trapezoids of valid operands.
    fn sweep_trapezoids(subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Vec<Trapezoid> {
        Vatti::sweep(subject, clip, op, fill, true, |_, _, _, traps| traps)
    }

    /// Runs the sweep of valid operands in this thread's reused buffers and hands its raw rings
    /// and trapezoids to `finish`.
    fn sweep<T>(
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
        trapezoids: bool,
        finish: impl FnOnce(&RawRings, &mut Touches, &mut Turns, Vec<Trapezoid>) -> T,
    ) -> T {
        Scratch::with(|scratch| {
            scratch.bounds.rebuild(subject, clip);
            let buffers = std::mem::take(&mut scratch.sweep);
            let mut sweep = Sweep::new(&scratch.bounds, Rules::new(op, fill), trapezoids, buffers);
            sweep.run();
            sweep.out.rings_into(&mut scratch.raw);
            let traps = sweep.traps.take().unwrap_or_default();
            scratch.sweep = sweep.into_buffers();
            finish(&scratch.raw, &mut scratch.touches, &mut scratch.turns, traps)
        })
    }
}

impl PolygonClipper for Vatti {
    fn name(&self) -> &'static str {
        "vatti"
    }

    fn capabilities(&self) -> PolygonCapabilities {
        PolygonCapabilities { trapezoids: true, ..PolygonCapabilities::GENERAL }
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        validate_polygons(clip, Operand::Clip)?;
        if let Some(out) = far_splice::splice_big_ring(subject, clip, true, op, fill) {
            return Ok(out);
        }
        let (a, b, op) = Vatti::reduced_unless_small(subject, clip, op, fill);
        Ok(Vatti::sweep_polygons(&a, &b, op, fill))
    }

    fn clip_trapezoids(
        &self,
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
    ) -> Result<Vec<Trapezoid>, ClipError> {
        let (a, b, op) = Vatti::filtered(subject, clip, op, fill)?;
        Ok(Vatti::sweep_trapezoids(&a, &b, op, fill))
    }
}
