//! Trapezoid output straight from the sweep: between two event heights the edge order is fixed,
//! and every run of the result between a left and a right edge is one trapezoid.

use clip_core::Trapezoid;

use crate::sweep::Sweep;

impl Sweep<'_> {
    /// Emits the result's trapezoids for the slab `[y0, y1]`, in which no two active edges cross.
    pub(crate) fn emit_slab(&mut self, y0: f64, y1: f64) {
        let Some(traps) = self.traps.as_mut() else { return };
        let mut inside = false;
        let mut left = None;
        for &id in &self.ael.order {
            let e = self.ael.get(id);
            let now = self.rules.inside(e.wind_right());
            if now == inside {
                continue;
            }
            if now {
                left = Some(e);
            } else if let Some(l) = left.take() {
                traps.push(Trapezoid {
                    x_left: l.x_at(y0),
                    x_right: e.x_at(y0),
                    y_bottom: y0,
                    dx_left: (l.top.x - l.bot.x) / (l.top.y - l.bot.y),
                    dx_right: (e.top.x - e.bot.x) / (e.top.y - e.bot.y),
                    y_top: y1,
                });
            }
            inside = now;
        }
    }
}
