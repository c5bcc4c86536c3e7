//! Scanline polygon fill: an edge table sorted by bottom y, an active edge table walked row by
//! row, spans between crossings chosen by the fill rule.

use clip_core::{ClipError, FillRule, Operand, Point, Polygons, validate_polygons};

use crate::frame::FrameBuffer;
use crate::sampling::{SideWalk, edge_dx, edge_x_at, pixel_edge, rows};

/// One non-horizontal polygon edge in the edge table.
#[derive(Clone, Copy, Debug)]
struct TableEdge {
    lower: Point,
    upper: Point,
    /// +1 for an edge walked downwards, -1 upwards: the winding number gained crossing it
    /// left to right (counter-clockwise rings count +1 inside).
    winding: i32,
}

/// Fills the region `polygons` covers under `fill` with `value`: pixel `(i, j)` is set when its
/// centre is inside, by the crate's sampling rule. Horizontal edges are skipped (they bound no
/// row's span). The active edges are re-anchored at every vertex height (the bottom of each
/// slab between consecutive vertex heights), then walked by `x += dx`, exactly as the trapezoid
/// fill walks a trapezoid that starts at that height.
pub fn fill_polygons(frame: &mut FrameBuffer, polygons: &Polygons, fill: FillRule, value: u8) -> Result<(), ClipError> {
    validate_polygons(polygons, Operand::Subject)?;
    let mut table: Vec<TableEdge> = polygons
        .edges()
        .filter(|e| e.a.y != e.b.y)
        .map(|e| {
            let (lower, upper, winding) = if e.a.y < e.b.y { (e.a, e.b, -1) } else { (e.b, e.a, 1) };
            TableEdge { lower, upper, winding }
        })
        .collect();
    table.sort_by(|a, b| a.lower.y.total_cmp(&b.lower.y));
    let mut heights: Vec<f64> = table.iter().flat_map(|e| [e.lower.y, e.upper.y]).collect();
    heights.sort_by(f64::total_cmp);
    heights.dedup();

    let (width, height) = (frame.width(), frame.height());
    let mut pending = table.iter().peekable();
    // The active edge table: each edge with its walk through the current slab.
    let mut active: Vec<(TableEdge, SideWalk)> = Vec::new();
    for slab in heights.windows(2) {
        let (y0, y1) = (slab[0], slab[1]);
        active.retain(|(edge, _)| edge.upper.y > y0);
        while let Some(edge) = pending.next_if(|e| e.lower.y <= y0) {
            active.push((*edge, SideWalk { x: 0.0, dx: 0.0 }));
        }
        let slab_rows = rows(y0, y1, height);
        if slab_rows.is_empty() {
            continue;
        }
        for (edge, walk) in active.iter_mut() {
            let x0 = edge_x_at(edge.lower, edge.upper, y0);
            *walk = SideWalk::start(x0, y0, edge_dx(edge.lower, edge.upper), slab_rows.start);
        }
        for row in slab_rows {
            // Nearly sorted from the last row: insertion sort (edges cross only where rings cross).
            for i in 1..active.len() {
                let mut j = i;
                while j > 0 && active[j - 1].1.x > active[j].1.x {
                    active.swap(j - 1, j);
                    j -= 1;
                }
            }
            let mut winding = 0;
            for pair in active.windows(2) {
                winding += pair[0].0.winding;
                if fill.is_inside(winding) {
                    let columns = pixel_edge(pair[0].1.x, width)..pixel_edge(pair[1].1.x, width);
                    if !columns.is_empty() {
                        frame.fill_span(row, columns, value);
                    }
                }
            }
            active.iter_mut().for_each(|(_, walk)| walk.step());
        }
    }
    Ok(())
}
