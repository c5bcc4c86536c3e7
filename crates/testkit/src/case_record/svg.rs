//! Hand-written SVG pictures of a case: inputs, outputs, a legend; y flipped so up is up.

use clip_core::{FillRule, Point, Polygons, Rect, Segment, VisiblePiece};
use core::fmt::Write;

pub(super) const SUBJECT_COLOUR: &str = "#1f77b4";
pub(super) const CLIP_COLOUR: &str = "#d62728";
pub(super) const OUTPUT_COLOURS: [&str; 6] = ["#2ca02c", "#ff7f0e", "#9467bd", "#17becf", "#8c564b", "#e377c2"];
const WIDTH: f64 = 800.0;
const PAD: f64 = 20.0;
/// Outputs with at most this many vertices get a dot on each vertex (shows spikes and bridges).
const DOTTED_VERTICES: usize = 400;

/// Maps plane coordinates to picture coordinates: scaled to 800 px wide, y flipped.
pub(super) struct View {
    bounds: Rect,
    pub(super) scale: f64,
    pub(super) width: f64,
    pub(super) height: f64,
}

impl View {
    pub(super) fn new(bounds: Rect) -> View {
        View::sized(bounds, WIDTH)
    }

    /// A view `width` px wide (a panel of a picture of several).
    pub(super) fn sized(bounds: Rect, width: f64) -> View {
        let b = if bounds.is_empty() { Rect::new(0.0, 0.0, 1.0, 1.0) } else { bounds };
        let extent = b.extent().max(f64::MIN_POSITIVE);
        let b = b.inflate(extent * 0.02);
        let (w, h) = (b.width().max(extent * 0.05), b.height().max(extent * 0.05));
        let scale = (width - 2.0 * PAD) / w;
        let height = (h * scale + 2.0 * PAD).min(4.0 * width);
        View { bounds: Rect::new(b.min.x, b.min.y, b.min.x + w, b.min.y + h), scale, width, height }
    }

    pub(super) fn map(&self, p: Point) -> (f64, f64) {
        (PAD + (p.x - self.bounds.min.x) * self.scale, PAD + (self.bounds.max.y - p.y) * self.scale)
    }

    pub(super) fn open(&self) -> String {
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h:.0}\" viewBox=\"0 0 {w} {h:.0}\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
            w = self.width,
            h = self.height
        )
    }
}

pub(super) fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// One `<path>` for all rings of a polygon set.
pub(super) fn polygons_path(
    out: &mut String,
    view: &View,
    p: &Polygons,
    colour: &str,
    fill: Option<FillRule>,
    opacity: f64,
    width: f64,
) {
    let mut d = String::new();
    for r in &p.rings {
        for (i, &q) in r.points.iter().enumerate() {
            let (x, y) = view.map(q);
            let _ = write!(d, "{}{x:.2} {y:.2} ", if i == 0 { 'M' } else { 'L' });
        }
        d.push_str("Z ");
    }
    let fill_attr = match fill.and_then(svg_fill_rule) {
        Some(rule) => format!("fill=\"{colour}\" fill-opacity=\"{opacity}\" fill-rule=\"{rule}\""),
        None => "fill=\"none\"".to_owned(),
    };
    let _ = writeln!(
        out,
        "<path d=\"{}\" {fill_attr} stroke=\"{colour}\" stroke-width=\"{width}\" stroke-linejoin=\"round\"/>",
        d.trim_end()
    );
}

/// SVG's name for a fill rule; positive and negative have none (drawn as outlines).
fn svg_fill_rule(fill: FillRule) -> Option<&'static str> {
    match fill {
        FillRule::EvenOdd => Some("evenodd"),
        FillRule::NonZero => Some("nonzero"),
        FillRule::Positive | FillRule::Negative => None,
    }
}

pub(super) fn vertex_dots(out: &mut String, view: &View, p: &Polygons, colour: &str) {
    if p.vertex_count() > DOTTED_VERTICES {
        return;
    }
    for &q in p.points() {
        let (x, y) = view.map(q);
        let _ = writeln!(out, "<circle cx=\"{x:.2}\" cy=\"{y:.2}\" r=\"2.5\" fill=\"{colour}\"/>");
    }
}

pub(super) fn legend(out: &mut String, entries: &[(String, &str)]) {
    let h = 8.0 + 18.0 * entries.len() as f64;
    let _ = writeln!(
        out,
        "<rect x=\"4\" y=\"4\" width=\"360\" height=\"{h}\" fill=\"white\" fill-opacity=\"0.85\" stroke=\"#999\"/>"
    );
    for (i, (label, colour)) in entries.iter().enumerate() {
        let y = 10.0 + 18.0 * i as f64;
        let _ = writeln!(out, "<rect x=\"10\" y=\"{y}\" width=\"12\" height=\"12\" fill=\"{colour}\"/>");
        let _ = writeln!(
            out,
            "<text x=\"28\" y=\"{}\" font-family=\"sans-serif\" font-size=\"12\">{}</text>",
            y + 10.5,
            escape(label)
        );
    }
}

pub(super) fn describe(name: &str, p: &Polygons) -> String {
    format!("{name}: {} ring(s), {} vertices", p.rings.len(), p.vertex_count())
}

/// A picture of subject (blue), clip (red) and each named output in its own colour, inputs filled
/// even-odd. See [`polygons_svg_with_fill`].
pub fn polygons_svg(subject: &Polygons, clip: &Polygons, outputs: &[(&str, &Polygons)]) -> String {
    polygons_svg_with_fill(subject, clip, FillRule::EvenOdd, outputs)
}

/// A picture of subject, clip and outputs: the inputs filled under `input_fill` (SVG's
/// `fill-rule`; positive and negative, which SVG lacks, are drawn as outlines), the outputs
/// filled non-zero with a dot on each vertex, a legend top left; y flipped so up is up.
pub fn polygons_svg_with_fill(
    subject: &Polygons,
    clip: &Polygons,
    input_fill: FillRule,
    outputs: &[(&str, &Polygons)],
) -> String {
    let bounds = outputs.iter().fold(subject.bounds().union(clip.bounds()), |b, (_, p)| b.union(p.bounds()));
    let view = View::new(bounds);
    let mut out = view.open();
    polygons_path(&mut out, &view, subject, SUBJECT_COLOUR, Some(input_fill), 0.15, 1.5);
    polygons_path(&mut out, &view, clip, CLIP_COLOUR, Some(input_fill), 0.15, 1.5);
    let mut entries = vec![
        (format!("{} (fill {input_fill})", describe("subject", subject)), SUBJECT_COLOUR),
        (format!("{} (fill {input_fill})", describe("clip", clip)), CLIP_COLOUR),
    ];
    for (i, (name, p)) in outputs.iter().enumerate() {
        let colour = OUTPUT_COLOURS[i % OUTPUT_COLOURS.len()];
        polygons_path(&mut out, &view, p, colour, Some(FillRule::NonZero), 0.3, 2.0);
        vertex_dots(&mut out, &view, p, colour);
        entries.push((describe(name, p), colour));
    }
    legend(&mut out, &entries);
    out.push_str("</svg>\n");
    out
}

pub(super) fn line(out: &mut String, view: &View, s: Segment, colour: &str, width: f64) {
    let ((x1, y1), (x2, y2)) = (view.map(s.a), view.map(s.b));
    let _ = writeln!(
        out,
        "<line x1=\"{x1:.2}\" y1=\"{y1:.2}\" x2=\"{x2:.2}\" y2=\"{y2:.2}\" stroke=\"{colour}\" stroke-width=\"{width}\" stroke-linecap=\"round\"/>"
    );
}

/// A picture of a window (grey, even-odd), the input segments (thin, grey) and each named
/// output's pieces in its own colour, earlier outputs drawn wider so agreeing outputs nest.
pub fn lines_svg(window: &Polygons, segments: &[Segment], outputs: &[(&str, &[VisiblePiece])]) -> String {
    let bounds = segments.iter().fold(window.bounds(), |b, s| b.union(s.bounds()));
    let view = View::new(bounds);
    let mut out = view.open();
    polygons_path(&mut out, &view, window, "#555555", Some(FillRule::EvenOdd), 0.15, 1.5);
    for s in segments {
        line(&mut out, &view, *s, "#aaaaaa", 1.0);
    }
    let mut entries =
        vec![(describe("window", window), "#555555"), (format!("segments: {}", segments.len()), "#aaaaaa")];
    let n = outputs.len();
    for (i, (name, pieces)) in outputs.iter().enumerate() {
        let colour = OUTPUT_COLOURS[i % OUTPUT_COLOURS.len()];
        let width = 2.0 + 2.5 * (n - 1 - i) as f64;
        for p in pieces.iter() {
            line(&mut out, &view, p.piece, colour, width);
        }
        entries.push((format!("{name}: {} piece(s)", pieces.len()), colour));
    }
    legend(&mut out, &entries);
    out.push_str("</svg>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn y_is_flipped_and_names_escaped() {
        let a = Polygons::from(Rect::new(0.0, 0.0, 10.0, 10.0));
        let b = Polygons::from(Rect::new(5.0, 5.0, 15.0, 15.0));
        let svg = polygons_svg(&a, &b, &[("a<b & c", &a)]);
        assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
        assert!(svg.contains("a&lt;b &amp; c") && svg.contains("fill-rule=\"evenodd\""));
        let view = View::new(a.bounds());
        assert!(view.map(Point::new(0.0, 10.0)).1 < view.map(Point::new(0.0, 0.0)).1);
    }

    #[test]
    fn fill_rules_svg_lacks_are_outlines() {
        let a = Polygons::from(Rect::new(0.0, 0.0, 10.0, 10.0));
        let svg = polygons_svg_with_fill(&a, &a, FillRule::Positive, &[]);
        assert_eq!(svg.matches("fill=\"none\"").count(), 2);
        let lines = lines_svg(&a, &[Segment::new(Point::ZERO, Point::new(3.0, 3.0))], &[("x", &[])]);
        assert_eq!(lines.matches("<line").count(), 1);
    }
}
