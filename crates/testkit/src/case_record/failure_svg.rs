//! The picture of a failure folder: the inputs in one panel, each output outlined over the faint
//! inputs in a panel of its own (same scale), the failing point or edge marked in every panel and
//! named by its coordinates above them, the legend above the panels so it covers nothing.

use clip_core::{FillRule, Point, Polygons, Rect, Segment, VisiblePiece};
use core::fmt::Write;

use super::svg::{
    CLIP_COLOUR, OUTPUT_COLOURS, SUBJECT_COLOUR, View, describe, escape, line, polygons_path, vertex_dots,
};
use super::wkt::format_coordinate;

/// Where a check failed, to be marked on the picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FailureMark {
    /// A point (a wrong sample point, a crossing, a repeated vertex).
    Point(Point),
    /// An edge or segment (an overlap, a wrongly clipped segment).
    Edge(Point, Point),
}

impl FailureMark {
    /// The mark's text: `point (x, y)` or `edge (x1, y1) - (x2, y2)`.
    pub fn describe(&self) -> String {
        let at = |p: Point| format!("({}, {})", format_coordinate(p.x), format_coordinate(p.y));
        match *self {
            FailureMark::Point(p) => format!("failing point {}", at(p)),
            FailureMark::Edge(a, b) => format!("failing edge {} - {}", at(a), at(b)),
        }
    }

    fn bounds(&self) -> Rect {
        match *self {
            FailureMark::Point(p) => Rect::new(p.x, p.y, p.x, p.y),
            FailureMark::Edge(a, b) => Segment::new(a, b).bounds(),
        }
    }
}

const MARK_COLOUR: &str = "#e6007e";
const PANEL: f64 = 380.0;
const COLUMNS: usize = 3;
const LINE: f64 = 18.0;
/// Characters of the failure message per caption line.
const CAPTION_WIDTH: usize = 120;

/// A panel's drawing: the picture so far and the panel's view.
type Draw<'a> = Box<dyn Fn(&mut String, &View) + 'a>;

/// Lays `panels` (title and drawing) out in rows of [`COLUMNS`] under a header of the failure
/// message, the mark's coordinates and the legend.
fn panels_svg(
    bounds: Rect,
    message: &str,
    mark: Option<FailureMark>,
    legend: &[(&str, &str)],
    panels: Vec<(String, Draw<'_>)>,
) -> String {
    let bounds = mark.map_or(bounds, |m| bounds.union(m.bounds()));
    let view = View::sized(bounds, PANEL);
    let caption = wrap(message, CAPTION_WIDTH);
    let header = LINE * (caption.len() + 3) as f64;
    let columns = panels.len().clamp(1, COLUMNS);
    let rows = panels.len().div_ceil(COLUMNS).max(1);
    let (width, height) = (PANEL * columns as f64, header + (LINE + view.height) * rows as f64);
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{height:.0}\" viewBox=\"0 0 {width} {height:.0}\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    );
    let text = |out: &mut String, x: f64, y: f64, colour: &str, body: &str| {
        let _ = writeln!(
            out,
            "<text x=\"{x}\" y=\"{y}\" font-family=\"sans-serif\" font-size=\"13\" fill=\"{colour}\">{}</text>",
            escape(body)
        );
    };
    for (i, l) in caption.iter().enumerate() {
        text(&mut out, 8.0, LINE * (i + 1) as f64 - 4.0, "black", l);
    }
    let below = LINE * (caption.len() + 1) as f64 - 4.0;
    let where_ = mark.map_or("no point or edge located by the check".to_owned(), |m| m.describe());
    text(&mut out, 8.0, below, MARK_COLOUR, &where_);
    let mut x = 8.0;
    for (label, colour) in legend.iter().copied().chain(mark.map(|_| ("failure", MARK_COLOUR))) {
        let y = below + LINE;
        let _ = writeln!(out, "<rect x=\"{x}\" y=\"{}\" width=\"12\" height=\"12\" fill=\"{colour}\"/>", y - 10.0);
        text(&mut out, x + 16.0, y, "black", label);
        x += 28.0 + 7.0 * label.chars().count() as f64;
    }
    for (i, (title, draw)) in panels.iter().enumerate() {
        let (px, py) = (PANEL * (i % COLUMNS) as f64, header + (LINE + view.height) * (i / COLUMNS) as f64);
        let _ = writeln!(out, "<g transform=\"translate({px} {py})\">");
        let _ = writeln!(
            out,
            "<rect x=\"2\" y=\"{LINE}\" width=\"{}\" height=\"{:.0}\" fill=\"none\" stroke=\"#ccc\"/>",
            PANEL - 4.0,
            view.height
        );
        text(&mut out, 8.0, LINE - 4.0, "black", title);
        let _ = writeln!(out, "<g transform=\"translate(0 {LINE})\">");
        draw(&mut out, &view);
        if let Some(m) = mark {
            draw_mark(&mut out, &view, m);
        }
        out.push_str("</g>\n</g>\n");
    }
    out.push_str("</svg>\n");
    out
}

fn draw_mark(out: &mut String, view: &View, mark: FailureMark) {
    let ring = |out: &mut String, p: Point| {
        let (x, y) = view.map(p);
        let _ = writeln!(
            out,
            "<circle cx=\"{x:.2}\" cy=\"{y:.2}\" r=\"7\" fill=\"none\" stroke=\"{MARK_COLOUR}\" stroke-width=\"2.5\"/>"
        );
    };
    match mark {
        FailureMark::Point(p) => ring(out, p),
        FailureMark::Edge(a, b) => {
            line(out, view, Segment::new(a, b), MARK_COLOUR, 4.0);
            ring(out, a);
            ring(out, b);
        }
    }
}

/// `text` in lines of at most `width` characters, broken at spaces.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split_whitespace() {
        match lines.last_mut() {
            Some(l) if l.chars().count() + 1 + word.chars().count() <= width => {
                l.push(' ');
                l.push_str(word);
            }
            _ => lines.push(word.to_owned()),
        }
    }
    if lines.is_empty() {
        lines.push(String::new());
    }
    lines
}

/// The picture of a polygon failure: `message` (what the check said) and the mark's coordinates
/// on top, then the inputs filled under `input_fill`, then each named output outlined (with its
/// vertices dotted) over the faint inputs, one panel each.
pub fn polygon_failure_svg(
    subject: &Polygons,
    clip: &Polygons,
    input_fill: FillRule,
    outputs: &[(&str, &Polygons)],
    message: &str,
    mark: Option<FailureMark>,
) -> String {
    let bounds = outputs.iter().fold(subject.bounds().union(clip.bounds()), |b, (_, p)| b.union(p.bounds()));
    let inputs = move |out: &mut String, view: &View, opacity: f64, width: f64| {
        polygons_path(out, view, subject, SUBJECT_COLOUR, Some(input_fill), opacity, width);
        polygons_path(out, view, clip, CLIP_COLOUR, Some(input_fill), opacity, width);
    };
    let mut panels: Vec<(String, Draw<'_>)> = vec![(
        format!("inputs (fill {input_fill}): {} / {} vertices", subject.vertex_count(), clip.vertex_count()),
        Box::new(move |out, view| inputs(out, view, 0.25, 1.5)),
    )];
    for (i, (name, p)) in outputs.iter().enumerate() {
        let colour = OUTPUT_COLOURS[i % OUTPUT_COLOURS.len()];
        panels.push((
            describe(name, p),
            Box::new(move |out, view| {
                inputs(out, view, 0.08, 0.5);
                polygons_path(out, view, p, colour, None, 0.0, 2.0);
                vertex_dots(out, view, p, colour);
            }),
        ));
    }
    panels_svg(bounds, message, mark, &[("subject", SUBJECT_COLOUR), ("clip", CLIP_COLOUR)], panels)
}

/// The picture of a line failure: as [`polygon_failure_svg`], the window and segments first, then
/// each named output's pieces over the faint window and segments.
pub fn line_failure_svg(
    window: &Polygons,
    segments: &[Segment],
    outputs: &[(&str, &[VisiblePiece])],
    message: &str,
    mark: Option<FailureMark>,
) -> String {
    let bounds = segments.iter().fold(window.bounds(), |b, s| b.union(s.bounds()));
    let inputs = move |out: &mut String, view: &View, opacity: f64| {
        polygons_path(out, view, window, "#555555", Some(FillRule::EvenOdd), opacity, 1.0);
        for s in segments {
            line(out, view, *s, "#aaaaaa", 1.0);
        }
    };
    let mut panels: Vec<(String, Draw<'_>)> = vec![(
        format!("inputs: window of {} vertices, {} segment(s)", window.vertex_count(), segments.len()),
        Box::new(move |out, view| inputs(out, view, 0.15)),
    )];
    for (i, (name, pieces)) in outputs.iter().enumerate() {
        let colour = OUTPUT_COLOURS[i % OUTPUT_COLOURS.len()];
        panels.push((
            format!("{name}: {} piece(s)", pieces.len()),
            Box::new(move |out, view| {
                inputs(out, view, 0.05);
                for p in pieces.iter() {
                    line(out, view, p.piece, colour, 2.5);
                }
            }),
        ));
    }
    panels_svg(bounds, message, mark, &[("window", "#555555"), ("segments", "#aaaaaa")], panels)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn panels_sit_apart_and_the_mark_is_named() {
        let a = Polygons::from(Rect::new(0.0, 0.0, 10.0, 10.0));
        let b = Polygons::from(Rect::new(5.0, 5.0, 15.0, 15.0));
        let mark = FailureMark::Edge(Point::new(5.0, 5.0), Point::new(10.0, 5.5));
        let svg = polygon_failure_svg(&a, &b, FillRule::EvenOdd, &[("x", &a), ("y", &b)], "it failed", Some(mark));
        assert!(svg.contains("failing edge (5, 5) - (10, 5.5)"), "{svg}");
        // One panel of inputs and one per output, side by side.
        assert_eq!(svg.matches("<g transform=\"translate(").count(), 6);
        assert!(svg.contains("translate(380 ") && svg.contains("translate(760 "));
        // Outputs are outlines.
        assert_eq!(svg.matches("fill=\"none\" stroke=\"#2ca02c\"").count(), 1);
        assert!(wrap("a b c", 3) == ["a b", "c"]);
    }
}
