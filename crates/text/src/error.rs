//! What can go wrong laying out or clipping text: one typed error per kind of bad input.

use std::path::PathBuf;

use clip_core::ClipError;

/// Bad input to text layout or clipping.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum TextError {
    /// The font file could not be read.
    #[error("cannot read font file {}: {source}", path.display())]
    FontUnreadable {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The bytes are not a TrueType/OpenType font ttf-parser can read.
    #[error("{what} is not a font ttf-parser can read: {why}")]
    FontInvalid {
        /// The file or source named.
        what: String,
        /// The parser's reason.
        why: String,
    },
    /// The font has no glyph for a character of the string.
    #[error("the font {font} has no glyph for {ch:?} (U+{code:04X})", code = u32::from(*ch))]
    MissingGlyph {
        /// The font's name.
        font: String,
        /// The character.
        ch: char,
    },
    /// The string has no characters.
    #[error("the string is empty")]
    EmptyString,
    /// The size is not a finite positive number of pixels (or is absurdly large).
    #[error("the text size must be a finite number of pixels in (0, {MAX_SIZE}], got {size}")]
    BadSize {
        /// The size given.
        size: f64,
    },
    /// The origin is not finite, or the text would reach beyond the coordinate range.
    #[error("the text origin must be finite and within ±{MAX_COORDINATE_TEXT}, got ({x}, {y})")]
    BadOrigin {
        /// x.
        x: f64,
        /// y.
        y: f64,
    },
    /// The flattening tolerance is not a finite positive number.
    #[error("the flattening tolerance must be finite and positive, got {tolerance}")]
    BadTolerance {
        /// The tolerance given.
        tolerance: f64,
    },
    /// The window is not a usable clip window (no ring, zero area, non-finite), or the polygon
    /// clipper refused it.
    #[error(transparent)]
    Clip(#[from] ClipError),
}

/// The largest text size accepted, in pixels.
pub const MAX_SIZE: f64 = 1.0e6;

/// The largest origin coordinate accepted: far below clip-core's range, so a string of any
/// reasonable length stays within it.
pub const MAX_COORDINATE_TEXT: f64 = 1.0e12;
