//! `vatti-prepared`: the prepared clip behind the `PolygonClipper` trait, reused while the clip
//! operand stays the same, so harnesses that pass the clip with every call time the prepared path.

use std::cell::RefCell;
use std::sync::Arc;

use clip_core::{BoolOp, ClipError, FillRule, PolygonCapabilities, PolygonClipper, Polygons, Trapezoid};

use crate::{PreparedClip, Vatti};

thread_local! {
    /// This thread's last prepared clip.
    static LAST: RefCell<Option<Arc<PreparedClip>>> = const { RefCell::new(None) };
}

/// [`Vatti`] through [`Vatti::prepare`]: each thread keeps its last [`PreparedClip`] and reuses
/// it when a call's clip operand and fill rule equal it (compared in full, so a changed clip is
/// never mistaken for the kept one); otherwise it prepares the new clip. The same results as
/// [`Vatti`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct VattiPrepared;

impl VattiPrepared {
    fn prepared(clip: &Polygons, fill: FillRule) -> Result<Arc<PreparedClip>, ClipError> {
        let kept =
            LAST.with_borrow(|last| last.as_ref().filter(|p| p.fill() == fill && p.operand() == clip).map(Arc::clone));
        if let Some(p) = kept {
            return Ok(p);
        }
        let p = Arc::new(Vatti::prepare(clip, fill)?);
        LAST.with_borrow_mut(|last| *last = Some(Arc::clone(&p)));
        Ok(p)
    }
}

impl PolygonClipper for VattiPrepared {
    fn name(&self) -> &'static str {
        "vatti-prepared"
    }

    fn capabilities(&self) -> PolygonCapabilities {
        Vatti.capabilities()
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        VattiPrepared::prepared(clip, fill)?.clip(subject, op)
    }

    fn clip_trapezoids(
        &self,
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
    ) -> Result<Vec<Trapezoid>, ClipError> {
        VattiPrepared::prepared(clip, fill)?.clip_trapezoids(subject, op)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::Rect;

    #[test]
    fn a_changed_clip_is_prepared_anew() {
        let s = Polygons::from(Rect::new(0.0, 0.0, 4.0, 4.0));
        let a = Polygons::from(Rect::new(1.0, 1.0, 2.0, 2.0));
        let b = Polygons::from(Rect::new(1.0, 1.0, 3.0, 3.0));
        let op = BoolOp::Intersection;
        assert_eq!(VattiPrepared.clip(&s, &a, op, FillRule::NonZero).unwrap().signed_area(), 1.0);
        assert_eq!(VattiPrepared.clip(&s, &b, op, FillRule::NonZero).unwrap().signed_area(), 4.0);
        assert_eq!(VattiPrepared.clip(&s, &a, op, FillRule::NonZero).unwrap().signed_area(), 1.0);
    }
}
