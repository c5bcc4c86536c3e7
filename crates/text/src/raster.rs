//! Drawing text into a frame buffer with clip-raster's scanline fill (outlines, non-zero) and its pixel rule (bitmaps).

use clip_core::{FillRule, Polygons};
use clip_raster::{FrameBuffer, fill_polygons};

use crate::error::TextError;
use crate::layout::{Shape, Text};
use crate::strategy::Clipped;

/// Draws outlines (non-zero) and pixels into a `width x height` buffer; what lies outside it is
/// skipped. Pixel `(i, j)` is lit when its centre `(i + 0.5, j + 0.5)` is inside an outline
/// (clip-raster's rule: ties half-open, left and bottom in).
pub fn rasterize(
    polygons: &Polygons,
    pixels: &[(i64, i64)],
    width: usize,
    height: usize,
) -> Result<FrameBuffer, TextError> {
    let mut frame = FrameBuffer::new(width, height);
    fill_polygons(&mut frame, polygons, FillRule::NonZero, 1)?;
    for &(i, j) in pixels {
        if let (Ok(i), Ok(j)) = (usize::try_from(i), usize::try_from(j)) {
            frame.set(i, j, 1);
        }
    }
    Ok(frame)
}

/// Draws what a strategy kept.
pub fn rasterize_clipped(clipped: &Clipped, width: usize, height: usize) -> Result<FrameBuffer, TextError> {
    rasterize(&clipped.polygons, &clipped.pixels, width, height)
}

/// Draws the glyphs `which` of `text`, unclipped.
pub fn rasterize_glyphs(
    text: &Text,
    which: impl Iterator<Item = usize>,
    width: usize,
    height: usize,
) -> Result<FrameBuffer, TextError> {
    let (mut polygons, mut pixels) = (Polygons::empty(), Vec::new());
    for i in which {
        match &text.glyphs[i].shape {
            Shape::Outline(p) => polygons.rings.extend(p.rings.iter().cloned()),
            Shape::Pixels(p) => pixels.extend_from_slice(p),
        }
    }
    rasterize(&polygons, &pixels, width, height)
}
