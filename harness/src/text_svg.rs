//! SVG pictures of clipped text: the window, the whole text faint, what a strategy kept in black.

use std::fmt::Write as _;

use clip_core::Polygons;
use clip_text::{Clipped, Shape, Text};

/// A picture `width` pixels wide of `text` clipped to `window` (y up in the plane, down in SVG),
/// titled `title`.
pub fn text_svg(text: &Text, window: &Polygons, clipped: &Clipped, title: &str, width: f64) -> String {
    let b = text.bounds.union(window.bounds()).expanded(4.0);
    let scale = width / b.width().max(1.0);
    let height = b.height() * scale + 24.0;
    let x = |v: f64| (v - b.min.x) * scale;
    let y = |v: f64| 24.0 + (b.max.y - v) * scale;
    let mut svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width:.0}\" height=\"{height:.0}\" viewBox=\"0 0 {width:.1} {height:.1}\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"4\" y=\"16\" font-family=\"sans-serif\" font-size=\"13\">{}</text>\n",
        escape(title)
    );
    let path = |p: &Polygons| -> String {
        let mut d = String::new();
        for r in &p.rings {
            for (k, q) in r.points.iter().enumerate() {
                let _ = write!(d, "{}{:.2},{:.2} ", if k == 0 { "M" } else { "L" }, x(q.x), y(q.y));
            }
            d.push_str("Z ");
        }
        d
    };
    let pixels = |px: &[(i64, i64)], fill: &str, out: &mut String| {
        for &(i, j) in px {
            let _ = writeln!(
                out,
                "<rect x=\"{:.2}\" y=\"{:.2}\" width=\"{:.2}\" height=\"{:.2}\" fill=\"{fill}\"/>",
                x(i as f64),
                y((j + 1) as f64),
                scale,
                scale
            );
        }
    };
    // The whole text, faint.
    for g in &text.glyphs {
        match &g.shape {
            Shape::Outline(p) => {
                let _ = writeln!(svg, "<path d=\"{}\" fill=\"#d8d8d8\" fill-rule=\"nonzero\"/>", path(p));
            }
            Shape::Pixels(px) => pixels(px, "#d8d8d8", &mut svg),
        }
    }
    // What the strategy kept.
    if !clipped.polygons.is_empty() {
        let _ = writeln!(svg, "<path d=\"{}\" fill=\"black\" fill-rule=\"nonzero\"/>", path(&clipped.polygons));
    }
    pixels(&clipped.pixels, "black", &mut svg);
    let _ = writeln!(svg, "<path d=\"{}\" fill=\"none\" stroke=\"#d03030\" stroke-width=\"1.5\"/>", path(window));
    svg.push_str("</svg>\n");
    svg
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}
