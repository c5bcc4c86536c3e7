//! The text oracle: each strategy's output rasterised and compared pixel by pixel with the unclipped text rasterised and then masked by the window.
//!
//! It lives here rather than in clip-oracle because it needs clip-raster's fill and this crate's
//! layout, and clip-oracle depends on clip-core alone. It takes clip-oracle's slab-decomposition
//! area ([`clip_oracle::polygon::region_area`]) to decide independently which boxes lie inside
//! the window.

use clip_core::{FillRule, Location, Point, Polygons, Segment, locate};
use clip_oracle::polygon::region_area;
use clip_raster::FrameBuffer;

use crate::layout::{Shape, Text};
use crate::raster::{rasterize_clipped, rasterize_glyphs};
use crate::strategy::{Clipped, Strategy, pixel_centre};
use crate::window::TextWindow;

/// A pixel of the per-component outline output may differ from the masked reference only when its
/// centre lies within this many pixels of a window edge or a glyph edge: there the clipped
/// outline's rounded crossings and the window's own edges meet the fill's half-open tie rule.
/// Everywhere else the two must agree exactly; bitmap output must agree everywhere.
pub const EXEMPT_DISTANCE: f64 = 1e-6;

/// A box is outside the window when more than this fraction of its area lies outside (by the slab
/// area); exactly zero means inside; in between, rounding decides and the glyph is not judged.
pub const BOX_AREA_TOLERANCE: f64 = 1e-9;

/// What a passing check looked at.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TextCheck {
    /// Pixels lit in the masked reference.
    pub reference_pixels: usize,
    /// Pixels that differ within [`EXEMPT_DISTANCE`] of an edge (outline components only).
    pub exempt_pixels: usize,
    /// All-or-none decisions left to rounding (a box outside by less than [`BOX_AREA_TOLERANCE`]).
    pub exempt_boxes: usize,
}

/// Checks one strategy's output on `text` (which must lie in `x, y >= 0`, the frame's quadrant).
///
/// - All-or-none string / character: the kept string or glyphs are exactly those whose boxes the
///   slab area finds inside the window, and the output draws exactly them, unclipped, which is
///   the same as them drawn and masked by the window.
/// - Per-component: the output drawn equals the whole text drawn and then masked (a pixel kept
///   when its centre is in the closed window), exactly for bitmap glyphs and up to
///   [`EXEMPT_DISTANCE`] for outline glyphs.
pub fn check_clipped_text(
    text: &Text,
    window: &TextWindow,
    strategy: Strategy,
    clipped: &Clipped,
) -> Result<TextCheck, String> {
    let b = text.bounds;
    if !b.is_empty() && (b.min.x < 0.0 || b.min.y < 0.0) {
        return Err(format!("the oracle draws in x, y >= 0, but the text's box starts at ({}, {})", b.min.x, b.min.y));
    }
    let (width, height) = ((b.max.x.max(0.0).ceil() as usize) + 2, (b.max.y.max(0.0).ceil() as usize) + 2);
    let mut check = TextCheck::default();
    let all: Vec<usize> = (0..text.glyphs.len()).collect();
    let (expected, got) = match strategy {
        Strategy::String | Strategy::Character => {
            let units: Vec<(clip_core::Rect, Vec<usize>)> = if strategy == Strategy::String {
                vec![(text.bounds, all)]
            } else {
                text.glyphs.iter().enumerate().map(|(i, g)| (g.bounds, vec![i])).collect()
            };
            let mut keep: Vec<usize> = Vec::new();
            for (bounds, glyphs) in units {
                let kept = glyphs.iter().all(|g| clipped.kept.contains(g));
                match box_inside(bounds, window.polygons()) {
                    Some(inside) if inside != kept => {
                        return Err(format!(
                            "{strategy}: glyphs {glyphs:?} (box {bounds:?}) {} but the window {} it",
                            if kept { "kept" } else { "dropped" },
                            if inside { "contains" } else { "does not contain" }
                        ));
                    }
                    Some(_) => {}
                    None => check.exempt_boxes += 1,
                }
                if kept {
                    keep.extend(glyphs);
                }
            }
            if clipped.kept.iter().any(|g| !keep.contains(g)) {
                return Err(format!("{strategy}: kept {:?}, a glyph outside the decided units", clipped.kept));
            }
            (
                masked(rasterize_glyphs(text, keep.into_iter(), width, height).map_err(|e| e.to_string())?, window),
                rasterize_clipped(clipped, width, height).map_err(|e| e.to_string())?,
            )
        }
        Strategy::Components => (
            masked(rasterize_glyphs(text, all.into_iter(), width, height).map_err(|e| e.to_string())?, window),
            rasterize_clipped(clipped, width, height).map_err(|e| e.to_string())?,
        ),
    };
    check.reference_pixels = expected.lit_count();
    let edges: Vec<Segment> = window.polygons().edges().chain(text.outlines().edges()).collect();
    for j in 0..height {
        for i in 0..width {
            let (want, have) = (expected.get(i, j) != 0, got.get(i, j) != 0);
            if want == have {
                continue;
            }
            let c = pixel_centre(i as i64, j as i64);
            let outline_output = strategy == Strategy::Components && has_outline(text);
            if outline_output && edges.iter().any(|&e| distance(c, e) <= EXEMPT_DISTANCE) {
                check.exempt_pixels += 1;
                continue;
            }
            return Err(format!(
                "{strategy}: pixel ({i}, {j}) is {} in the output but {} in the masked reference",
                if have { "lit" } else { "dark" },
                if want { "lit" } else { "dark" }
            ));
        }
    }
    Ok(check)
}

fn has_outline(text: &Text) -> bool {
    text.glyphs.iter().any(|g| matches!(g.shape, Shape::Outline(_)))
}

/// The frame with every pixel whose centre is outside the closed window turned off.
fn masked(mut frame: FrameBuffer, window: &TextWindow) -> FrameBuffer {
    for j in 0..frame.height() {
        for i in 0..frame.width() {
            if frame.get(i, j) != 0
                && locate(pixel_centre(i as i64, j as i64), window.polygons(), FillRule::NonZero) == Location::Outside
            {
                frame.set(i, j, 0);
            }
        }
    }
    frame
}

/// Whether the closed box lies in the window, by the slab area of the box outside it: `Some(true)`
/// when that area is 0, `Some(false)` when it is above the tolerance, `None` in between.
fn box_inside(b: clip_core::Rect, window: &Polygons) -> Option<bool> {
    if b.is_empty() {
        return Some(true);
    }
    let outside =
        region_area(&[(&Polygons::from(b), FillRule::NonZero), (window, FillRule::NonZero)], |i| i[0] && !i[1]);
    if outside == 0.0 {
        Some(true)
    } else if outside > BOX_AREA_TOLERANCE * b.area() {
        Some(false)
    } else {
        None
    }
}

fn distance(p: Point, e: Segment) -> f64 {
    let d = e.b - e.a;
    let length2 = d.dot(d);
    let t = if length2 > 0.0 { ((p - e.a).dot(d) / length2).clamp(0.0, 1.0) } else { 0.0 };
    p.distance(e.a + d * t)
}
