//! SVG pictures of clipped curves, drawn with SVG's own elliptical arcs, so the picture shows
//! the exact result rather than a flattening.

use core::f64::consts::PI;
use core::fmt::Write;

use clip_core::{BoundaryPiece, CurveRegion, Ellipse, EllipseArc, FillRule, Polygons};

use super::svg::{View, legend, polygons_path};

const WINDOW_COLOUR: &str = "#555555";
const CURVE_COLOUR: &str = "#999999";
const REGION_COLOUR: &str = "#2ca02c";
const VISIBLE_COLOUR: &str = "#d62728";

/// One object in a picture: the arc (or whole ellipse) as given, its visible intervals, and its
/// clipped filled region when it was clipped filled.
#[derive(Clone, Copy, Debug)]
pub struct CurvePicture<'a> {
    /// The object.
    pub arc: &'a EllipseArc,
    /// Its visible parameter intervals.
    pub visible: &'a [(f64, f64)],
    /// Its clipped region, for a filled object.
    pub region: Option<&'a CurveRegion>,
}

/// SVG path commands drawing ellipse `e` from parameter `from` to `to` (the pen already at the
/// start): pieces of at most half a turn, so the large-arc flag is always 0. The plane's y is
/// flipped, so counter-clockwise in the plane is sweep-flag 0 and the rotation changes sign.
fn arc_commands(d: &mut String, view: &View, e: &Ellipse, from: f64, to: f64) {
    let (rx, ry) = e.radii();
    let rotation = 0.0 - e.rotation().to_degrees() + 0.0;
    let n = ((to - from) / PI).ceil().max(1.0);
    for k in 1..=n as usize {
        let (x, y) = view.map(e.point_at(from + (to - from) * k as f64 / n));
        let _ = write!(d, "A{:.3} {:.3} {rotation:.4} 0 0 {x:.2} {y:.2} ", rx * view.scale, ry * view.scale);
    }
}

fn region_path(out: &mut String, view: &View, region: &CurveRegion) {
    let e = &region.ellipse;
    let mut d = String::new();
    for lp in &region.loops {
        let Some(first) = lp.first() else { continue };
        let (x, y) = view.map(first.start(e));
        let _ = write!(d, "M{x:.2} {y:.2} ");
        for piece in lp {
            match *piece {
                BoundaryPiece::Arc { from, to } => arc_commands(&mut d, view, e, from, to),
                BoundaryPiece::Segment(s) => {
                    let (x, y) = view.map(s.b);
                    let _ = write!(d, "L{x:.2} {y:.2} ");
                }
            }
        }
        d.push_str("Z ");
    }
    let _ = writeln!(
        out,
        "<path d=\"{}\" fill=\"{REGION_COLOUR}\" fill-opacity=\"0.45\" fill-rule=\"nonzero\" stroke=\"{REGION_COLOUR}\" stroke-width=\"1.5\"/>",
        d.trim_end()
    );
}

fn arc_path(out: &mut String, view: &View, e: &Ellipse, (from, to): (f64, f64), style: &str) {
    let (x, y) = view.map(e.point_at(from));
    let mut d = format!("M{x:.2} {y:.2} ");
    arc_commands(&mut d, view, e, from, to);
    let _ = writeln!(out, "<path d=\"{}\" fill=\"none\" {style}/>", d.trim_end());
}

/// A picture of a window (grey, even-odd) and curves: each object's whole arc dashed, its
/// clipped region filled green and its visible arcs in red, under `title`; y flipped so up is up.
pub fn curves_svg(window: &Polygons, items: &[CurvePicture<'_>], title: &str) -> String {
    let view = View::new(items.iter().fold(window.bounds(), |b, it| b.union(it.arc.bounds())));
    let mut out = view.open();
    polygons_path(&mut out, &view, window, WINDOW_COLOUR, Some(FillRule::EvenOdd), 0.12, 1.5);
    for it in items {
        let e = it.arc.ellipse();
        let dashed = format!("stroke=\"{CURVE_COLOUR}\" stroke-width=\"1.2\" stroke-dasharray=\"6 4\"");
        arc_path(&mut out, &view, e, (it.arc.start(), it.arc.end()), &dashed);
        if let Some(region) = it.region {
            region_path(&mut out, &view, region);
        }
        let solid = format!("stroke=\"{VISIBLE_COLOUR}\" stroke-width=\"3\" stroke-linecap=\"round\"");
        for &iv in it.visible {
            arc_path(&mut out, &view, e, iv, &solid);
        }
    }
    let filled = items.iter().filter(|i| i.region.is_some()).count();
    let pieces: usize = items.iter().map(|i| i.visible.len()).sum();
    let entries = vec![
        (title.to_owned(), "#ffffff"),
        (format!("window: {} ring(s), {} vertices", window.rings.len(), window.vertex_count()), WINDOW_COLOUR),
        (format!("curves as given (dashed): {}", items.len()), CURVE_COLOUR),
        (format!("clipped filled regions: {filled}"), REGION_COLOUR),
        (format!("visible arcs: {pieces}"), VISIBLE_COLOUR),
    ];
    legend(&mut out, &entries);
    out.push_str("</svg>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::{Point, Rect, Segment};

    fn svg_bounds(w: &Polygons, arc: &EllipseArc) -> clip_core::Rect {
        w.bounds().union(arc.bounds())
    }

    #[test]
    fn arcs_are_svg_arcs_and_regions_are_closed_paths() {
        let w = Polygons::from(Rect::new(0.0, 0.0, 10.0, 10.0));
        let e = Ellipse::circle(Point::new(10.0, 5.0), 2.0).unwrap();
        let arc = EllipseArc::full(e);
        let region = CurveRegion {
            ellipse: e,
            loops: vec![vec![
                BoundaryPiece::Arc { from: PI / 2.0, to: 1.5 * PI },
                BoundaryPiece::Segment(Segment::new(Point::new(10.0, 3.0), Point::new(10.0, 7.0))),
            ]],
        };
        let visible = [(PI / 2.0, 1.5 * PI)];
        let svg = curves_svg(&w, &[CurvePicture { arc: &arc, visible: &visible, region: Some(&region) }], "a & b");
        assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
        // Half a turn, counter-clockwise in the plane: one arc command, flags 0 0, radius 2 scaled.
        let scaled = 2.0 * View::new(svg_bounds(&w, &arc)).scale;
        assert!(svg.contains(&format!("A{scaled:.3} {scaled:.3} 0.0000 0 0 ")), "{svg}");
        assert!(svg.contains("Z\"") && svg.contains("a &amp; b"));
        assert_eq!(svg.matches("stroke-dasharray").count(), 1);
    }
}
