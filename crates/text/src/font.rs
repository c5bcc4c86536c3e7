//! The two kinds of font: an outline font read from a TrueType/OpenType file with ttf-parser, and the 8x8 bitmap font of `font8x8`.

use std::path::Path;

use font8x8::UnicodeFonts;

use crate::error::TextError;

/// An outline font: the file's bytes, checked once by ttf-parser.
#[derive(Clone)]
pub struct OutlineFont {
    data: Vec<u8>,
    name: String,
    units_per_em: u16,
}

impl std::fmt::Debug for OutlineFont {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "OutlineFont({}, {} bytes, {} units per em)", self.name, self.data.len(), self.units_per_em)
    }
}

impl OutlineFont {
    /// Reads and checks a font file.
    pub fn from_file(path: &Path) -> Result<OutlineFont, TextError> {
        let data = std::fs::read(path).map_err(|source| TextError::FontUnreadable { path: path.to_owned(), source })?;
        let name = path.file_name().map_or_else(|| path.display().to_string(), |n| n.to_string_lossy().into_owned());
        OutlineFont::from_bytes(data, &name)
    }

    /// Checks font bytes; `name` names them in errors.
    pub fn from_bytes(data: Vec<u8>, name: &str) -> Result<OutlineFont, TextError> {
        let units_per_em = ttf_parser::Face::parse(&data, 0)
            .map_err(|e| TextError::FontInvalid { what: name.to_owned(), why: e.to_string() })?
            .units_per_em();
        Ok(OutlineFont { data, name: name.to_owned(), units_per_em })
    }

    /// The font's name (its file name).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Font units per em.
    pub fn units_per_em(&self) -> u16 {
        self.units_per_em
    }

    /// The parsed face (parsing is a few table look-ups; the bytes were checked when loaded).
    pub(crate) fn face(&self) -> Result<ttf_parser::Face<'_>, TextError> {
        ttf_parser::Face::parse(&self.data, 0)
            .map_err(|e| TextError::FontInvalid { what: self.name.clone(), why: e.to_string() })
    }
}

/// The name `font8x8`'s basic Latin font goes by in errors.
pub const BITMAP_FONT_NAME: &str = "font8x8 basic";

/// The 8 rows of `ch` in the 8x8 bitmap font, top row first, bit 0 the leftmost pixel; only
/// basic Latin (U+0000 to U+007F) is used, so every font8x8 table agrees on it.
pub fn bitmap_glyph(ch: char) -> Result<[u8; 8], TextError> {
    font8x8::BASIC_FONTS.get(ch).ok_or(TextError::MissingGlyph { font: BITMAP_FONT_NAME.to_owned(), ch })
}

/// Where the tests and the CLI look for DejaVu Sans: Debian's `fonts-dejavu-core` puts it here.
pub const DEJAVU_SANS: &str = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
