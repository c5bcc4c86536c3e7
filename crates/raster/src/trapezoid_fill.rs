//! Vatti's trapezoid fill: each `(x_left, x_right, y_bottom, dx_left, dx_right, y_top)` drawn by
//! the paper's incremental loop.

use clip_core::{ClipError, Operand, Trapezoid};

use crate::frame::FrameBuffer;
use crate::sampling::{SideWalk, pixel_edge, rows};

/// Fills every trapezoid with `value` by the paper's loop
///
/// ```text
/// For Y = Ybot to Ytop do;
///   DrawLine(Xleft, Xright, Y);
///   Xleft = Xleft + DXleft;
///   Xright = Xright + DXright;
/// End loop;
/// ```
///
/// taken at pixel centres: the rows are those whose centres lie in `[y_bottom, y_top)`, the
/// sides start at the first such row's centre and step by `dx` per row, and each row lights the
/// pixels whose centres lie in `[x_left, x_right)` (the crate's sampling rule, the same as
/// [`crate::fill_polygons`]). A trapezoid with a non-finite field is an error
/// ([`ClipError::NonFinite`], `part` = its index); nothing is drawn then.
pub fn fill_trapezoids(frame: &mut FrameBuffer, trapezoids: &[Trapezoid], value: u8) -> Result<(), ClipError> {
    for (part, t) in trapezoids.iter().enumerate() {
        let fields = [t.x_left, t.x_right, t.y_bottom, t.dx_left, t.dx_right, t.y_top];
        if let Some(vertex) = fields.iter().position(|v| !v.is_finite()) {
            return Err(ClipError::NonFinite { operand: Operand::Subject, part, vertex, x: t.x_left, y: t.y_bottom });
        }
    }
    let width = frame.width();
    for t in trapezoids {
        let rows = rows(t.y_bottom, t.y_top, frame.height());
        let mut left = SideWalk::start(t.x_left, t.y_bottom, t.dx_left, rows.start);
        let mut right = SideWalk::start(t.x_right, t.y_bottom, t.dx_right, rows.start);
        for row in rows {
            let columns = pixel_edge(left.x, width)..pixel_edge(right.x, width);
            if !columns.is_empty() {
                frame.fill_span(row, columns, value);
            }
            left.step();
            right.step();
        }
    }
    Ok(())
}
