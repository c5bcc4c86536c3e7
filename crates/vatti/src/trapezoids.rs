//! Trapezoid output straight from the sweep: between two event heights the edge order is fixed,
//! and every run of the result between a left and a right edge is one trapezoid.

use clip_core::Trapezoid;

use crate::active::Edge;
use crate::sweep::SweepLine;

impl SweepLine<'_> {
    /// Emits the result's trapezoids for the slab `[y0, y1]`, in which no two active edges cross.
    pub(crate) fn emit_slab(&mut self, y0: f64, y1: f64) {
        let Some(traps) = self.traps.as_mut() else { return };
        let mut inside = false;
        let mut left = None;
        for id in self.ael.iter() {
            let e = self.ael.get(id);
            let now = self.rules.inside(e.wind_right());
            if now == inside {
                continue;
            }
            if now {
                left = Some(e);
            } else if let Some(l) = left.take() {
                traps.push(trapezoid(l, e, y0, y1));
            }
            inside = now;
        }
    }
}

/// The trapezoid between edges `l` and `r` over `[y0, y1]`. Where a crossing rounded onto the
/// slab's end leaves the sides an ulp-sized step out of order, both sides start (or end) at
/// their mean, so no trapezoid is ever inside out.
fn trapezoid(l: &Edge, r: &Edge, y0: f64, y1: f64) -> Trapezoid {
    let ordered = |a: f64, b: f64| if a <= b { (a, b) } else { (0.5 * (a + b), 0.5 * (a + b)) };
    let (xl0, xr0) = ordered(l.x_at(y0), r.x_at(y0));
    let (xl1, xr1) = ordered(l.x_at(y1), r.x_at(y1));
    let h = y1 - y0;
    Trapezoid {
        x_left: xl0,
        x_right: xr0,
        y_bottom: y0,
        dx_left: (xl1 - xl0) / h,
        dx_right: (xr1 - xr0) / h,
        y_top: y1,
    }
}
