//! The paragraph the text timings clip (`bench --workload text` and `reproduce lecture`): laid
//! out once per font, clipped by each strategy row, checked by clip-text's raster oracle.

use clip_core::{PolygonClipper, Polygons, Rect};
use clip_sutherland_hodgman::SutherlandHodgman;
use clip_testkit::workload::{PARAGRAPH_LINES, PARAGRAPH_SIZE, paragraph_origin, paragraph_window};
use clip_text::oracle::check_clipped_text;
use clip_text::{DEFAULT_TOLERANCE, OutlineFont, Strategy, Text, TextError, TextWindow, clip_text};
use clip_vatti::Vatti;

/// The rows timed: a strategy on a font with a polygon clipper, in the notes' order.
pub const ROWS: [&str; 5] = ["string", "char", "outline-vatti", "outline-sh-split", "bitmap"];

/// The name a row has in `bench.csv`: verify's row names (`text-outline` is per-component with
/// Vatti), and `text-outline-sh-split` for per-component with Sutherland-Hodgman (split).
pub fn bench_name(row: &str) -> &'static str {
    match row {
        "string" => "text-string",
        "char" => "text-char",
        "outline-vatti" => "text-outline",
        "outline-sh-split" => "text-outline-sh-split",
        _ => "text-bitmap",
    }
}

/// The row a `bench.csv` name stands for, if it is one.
pub fn row_of_bench_name(name: &str) -> Option<&'static str> {
    ROWS.into_iter().find(|&r| bench_name(r) == name)
}

/// The paragraph laid out in the outline font and in the bitmap font.
pub struct Paragraph {
    outline: Vec<Text>,
    bitmap: Vec<Text>,
    /// The box of both layouts.
    pub bounds: Rect,
}

impl Paragraph {
    /// Lays the paragraph out in `font` (flattened within clip-text's default tolerance) and in
    /// the 8x8 bitmap font.
    pub fn new(font: &OutlineFont) -> Result<Paragraph, TextError> {
        let lines = || PARAGRAPH_LINES.iter().enumerate();
        let outline: Vec<Text> = lines()
            .map(|(k, l)| Text::outline(font, l, PARAGRAPH_SIZE, paragraph_origin(k), DEFAULT_TOLERANCE))
            .collect::<Result<_, _>>()?;
        let bitmap: Vec<Text> =
            lines().map(|(k, l)| Text::bitmap(l, PARAGRAPH_SIZE, paragraph_origin(k))).collect::<Result<_, _>>()?;
        let bounds = outline.iter().chain(&bitmap).fold(Rect::EMPTY, |b, t| b.union(t.bounds));
        Ok(Paragraph { outline, bitmap, bounds })
    }

    /// The centred window with sides `side` times the paragraph box's.
    pub fn window(&self, side: f64) -> Polygons {
        paragraph_window(&self.bounds, side)
    }

    /// The lines, strategy and outline clipper of a row.
    fn pick(&self, row: &str) -> (&[Text], Strategy, &'static dyn PolygonClipper) {
        match row {
            "string" => (&self.outline, Strategy::String, &Vatti),
            "char" => (&self.outline, Strategy::Character, &Vatti),
            "outline-vatti" => (&self.outline, Strategy::Components, &Vatti),
            "outline-sh-split" => (&self.outline, Strategy::Components, &SutherlandHodgman::SPLIT),
            _ => (&self.bitmap, Strategy::Components, &Vatti),
        }
    }

    /// Clips every line with `row`'s strategy; returns how many rings and pixels were drawn.
    pub fn run(&self, row: &str, window: &TextWindow) -> Result<usize, TextError> {
        let (texts, strategy, clipper) = self.pick(row);
        let mut drawn = 0;
        for t in texts {
            let c = clip_text(t, window, strategy, clipper)?;
            drawn += c.polygons.rings.len() + c.pixels.len();
        }
        Ok(drawn)
    }

    /// Checks every line of `row`'s output with clip-text's raster oracle.
    pub fn check(&self, row: &str, window: &TextWindow) -> Result<(), String> {
        let (texts, strategy, clipper) = self.pick(row);
        for t in texts {
            let c = clip_text(t, window, strategy, clipper).map_err(|e| e.to_string())?;
            check_clipped_text(t, window, strategy, &c).map_err(|e| e.to_string())?;
        }
        Ok(())
    }

    /// Glyphs of `row`'s font the window cuts (neither wholly inside nor wholly outside the box
    /// test).
    pub fn cut_glyphs(&self, row: &str, window: &TextWindow) -> usize {
        let (texts, _, _) = self.pick(row);
        texts
            .iter()
            .flat_map(|t| &t.glyphs)
            .filter(|g| !g.bounds.is_empty() && g.bounds.intersects(&window.bounds()) && !window.contains_box(g.bounds))
            .count()
    }
}
