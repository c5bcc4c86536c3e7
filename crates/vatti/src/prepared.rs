//! A clip polygon prepared once for many subjects (the paper's Extensions: "clipping several
//! subject polygons against a constant clip polygon"): validated, its box and edge blocks built.

use std::collections::HashSet;
use std::sync::OnceLock;

use clip_core::{BoolOp, ClipError, FillRule, Operand, Polygons, Rect, Trapezoid, validate_polygons};

use crate::edge_blocks::EdgeBlocks;
use crate::far_splice::{Far, splice};
use crate::route::{Plan, Route, SweepAxis};
use crate::sweep::Sweep;
use crate::{Vatti, clip_planned, trapezoids_planned};

/// A clip operand and fill rule fixed for many subjects. Each [`PreparedClip::clip`] validates
/// only the subject and, for ∩ and −, sweeps only the clip edges that can reach the subject's
/// box, found through the edge blocks without visiting the others; for ∪ and ⊕ it splices the
/// subject's neighbourhood into the clip's region, resolved once ([`Route::Splice`]). It is
/// `Send + Sync`: one value serves every thread.
///
/// ```
/// use clip_core::{BoolOp, FillRule, Polygons, Rect};
/// use clip_vatti::Vatti;
///
/// let sheet = Polygons::from(Rect::new(0.0, 0.0, 100.0, 100.0));
/// let prepared = Vatti::prepare(&sheet, FillRule::NonZero).unwrap();
/// let parcel = Polygons::from(Rect::new(90.0, 90.0, 110.0, 110.0));
/// assert_eq!(prepared.clip(&parcel, BoolOp::Intersection).unwrap().signed_area(), 100.0);
/// ```
#[derive(Clone, Debug)]
pub struct PreparedClip {
    clip: Polygons,
    fill: FillRule,
    bounds: Rect,
    blocks: Vec<EdgeBlocks>,
    /// The clip's region under `fill` in conventional form with its edge blocks, made on the
    /// first ∪ or ⊕: those splice the subject's neighbourhood into it (`far_splice`).
    resolved: OnceLock<Resolved>,
}

impl Vatti {
    /// Prepares `clip` under `fill` for clipping many subjects; a bad clip operand is refused here.
    pub fn prepare(clip: &Polygons, fill: FillRule) -> Result<PreparedClip, ClipError> {
        validate_polygons(clip, Operand::Clip)?;
        Ok(PreparedClip {
            clip: clip.clone(),
            fill,
            bounds: clip.bounds(),
            blocks: clip.rings.iter().map(|r| EdgeBlocks::new(&r.points)).collect(),
            resolved: OnceLock::new(),
        })
    }
}

impl PreparedClip {
    /// The prepared clip operand.
    pub fn operand(&self) -> &Polygons {
        &self.clip
    }

    /// The fill rule both operands are read under.
    pub fn fill(&self) -> FillRule {
        self.fill
    }

    /// `subject op clip`, as [`Vatti`]'s `clip` gives it.
    pub fn clip(&self, subject: &Polygons, op: BoolOp) -> Result<Polygons, ClipError> {
        self.clip_along(Plan::of(subject, &self.clip, op, true).route, None, None, subject, op)
    }

    /// `subject op clip` along the given route, sweep and axis (each chosen on the operands
    /// when `None`), for comparing the paths: the same region.
    pub fn clip_along(
        &self,
        route: Route,
        sweep: Option<Sweep>,
        axis: Option<SweepAxis>,
        subject: &Polygons,
        op: BoolOp,
    ) -> Result<Polygons, ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        Ok(clip_planned(subject, &self.clip, Some(self), op, self.fill, Plan { route, sweep, axis }))
    }

    /// `subject op clip` as trapezoids, as [`Vatti`]'s `clip_trapezoids` gives them.
    pub fn clip_trapezoids(&self, subject: &Polygons, op: BoolOp) -> Result<Vec<Trapezoid>, ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        let plan = Plan::of(subject, &self.clip, op, true);
        Ok(trapezoids_planned(subject, &self.clip, Some(self), op, self.fill, plan))
    }

    /// The clip's bounding box.
    pub(crate) fn bounds(&self) -> Rect {
        self.bounds
    }

    /// The clip's edge blocks, one per ring.
    pub(crate) fn blocks(&self) -> &[EdgeBlocks] {
        &self.blocks
    }

    /// `subject op clip` for ∪ and ⊕ spliced into the clip's resolved region (see
    /// [`Route::Splice`]), `sweep(a, b, op)` sweeping the subject's neighbourhood; `None` where
    /// that does not apply.
    pub(crate) fn splice(
        &self,
        subject: &Polygons,
        op: BoolOp,
        sweep: impl FnOnce(&Polygons, &Polygons, BoolOp) -> Polygons,
    ) -> Option<Polygons> {
        if !matches!(op, BoolOp::Union | BoolOp::Xor) {
            return None;
        }
        let resolved = self.resolved();
        // A region with rounded crossings of the clip's own edges would round twice.
        if !resolved.exact {
            return None;
        }
        let far = Far { rings: &resolved.rings, blocks: Some(&resolved.blocks) };
        splice(subject, far, false, op, self.fill, sweep)
    }

    /// The clip's region in conventional form, resolved once.
    pub(crate) fn resolved(&self) -> &Resolved {
        self.resolved.get_or_init(|| {
            let rings = clip_planned(&self.clip, &Polygons::default(), None, BoolOp::Union, self.fill, Plan::WHOLE);
            let blocks = rings.rings.iter().map(|r| EdgeBlocks::new(&r.points)).collect();
            let given: HashSet<(u64, u64)> =
                self.clip.rings.iter().flat_map(|r| &r.points).map(|p| (p.x.to_bits(), p.y.to_bits())).collect();
            let exact =
                rings.rings.iter().flat_map(|r| &r.points).all(|p| given.contains(&(p.x.to_bits(), p.y.to_bits())));
            Resolved { rings, blocks, exact }
        })
    }
}

/// The clip's region in conventional form, with its edge blocks.
#[derive(Clone, Debug)]
pub(crate) struct Resolved {
    pub(crate) rings: Polygons,
    blocks: Vec<EdgeBlocks>,
    /// Every vertex is one of the clip's own: resolving it rounded no crossing, so the region's
    /// edges lie exactly on the clip's and splicing around it rounds only once, as the sweep does.
    exact: bool,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prepared_clips_are_shared_between_threads() {
        fn shared<T: Send + Sync>() {}
        shared::<PreparedClip>();
    }
}
