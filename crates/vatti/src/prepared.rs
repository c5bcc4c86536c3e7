//! A clip polygon prepared once for many subjects (the paper's Extensions: "clipping several
//! subject polygons against a constant clip polygon"): validated, its box and edge blocks built.

use std::collections::HashSet;
use std::sync::OnceLock;

use clip_core::{BoolOp, ClipError, FillRule, Operand, Polygons, Rect, Trapezoid, validate_polygons};

use crate::Vatti;
use crate::edge_blocks::EdgeBlocks;
use crate::far_splice::{Far, splice};

/// A clip operand and fill rule fixed for many subjects. Each [`PreparedClip::clip`] validates
/// only the subject and, for ∩ and −, sweeps only the clip edges that can reach the subject's
/// box, found through the edge blocks without visiting the others. It is `Send + Sync`: one
/// value serves every thread.
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
        validate_polygons(subject, Operand::Subject)?;
        if let Some(out) = crate::far_splice::splice_big_ring(subject, &self.clip, false, op, self.fill) {
            return Ok(out);
        }
        if matches!(op, BoolOp::Union | BoolOp::Xor) {
            let resolved = self.resolved();
            // A region with rounded crossings of the clip's own edges would round twice.
            if resolved.exact {
                let far = Far { rings: &resolved.rings, blocks: Some(&resolved.blocks) };
                if let Some(out) = splice(subject, far, false, op, self.fill) {
                    return Ok(out);
                }
            }
        }
        let (a, b, op) = Vatti::reduced(subject, &self.clip, self.bounds, Some(&self.blocks), op, self.fill);
        Ok(Vatti::sweep_polygons(&a, &b, op, self.fill))
    }

    /// The clip's region in conventional form, resolved once.
    fn resolved(&self) -> &Resolved {
        self.resolved.get_or_init(|| {
            let rings = Vatti::sweep_polygons(&self.clip, &Polygons::default(), BoolOp::Union, self.fill);
            let blocks = rings.rings.iter().map(|r| EdgeBlocks::new(&r.points)).collect();
            let given: HashSet<(u64, u64)> =
                self.clip.rings.iter().flat_map(|r| &r.points).map(|p| (p.x.to_bits(), p.y.to_bits())).collect();
            let exact =
                rings.rings.iter().flat_map(|r| &r.points).all(|p| given.contains(&(p.x.to_bits(), p.y.to_bits())));
            Resolved { rings, blocks, exact }
        })
    }

    /// `subject op clip` as trapezoids, as [`Vatti`]'s `clip_trapezoids` gives them.
    pub fn clip_trapezoids(&self, subject: &Polygons, op: BoolOp) -> Result<Vec<Trapezoid>, ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        let (a, b, op) = Vatti::reduced(subject, &self.clip, self.bounds, Some(&self.blocks), op, self.fill);
        Ok(Vatti::sweep_trapezoids(&a, &b, op, self.fill))
    }
}

/// The clip's region in conventional form, with its edge blocks.
#[derive(Clone, Debug)]
struct Resolved {
    rings: Polygons,
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
