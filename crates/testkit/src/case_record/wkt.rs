//! WKT text for polygon sets and segment batches, with coordinates that read back exactly.

use clip_core::{Point, Polygons, Ring, Segment, VisiblePiece, nest};
use core::fmt::Write;

/// A coordinate as the shortest text that parses back to the same f64: plain decimals in the
/// usual range, exponent form for very large or very small magnitudes.
pub fn format_coordinate(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 || (1e-5..1e16).contains(&a) { format!("{v}") } else { format!("{v:e}") }
}

fn point(out: &mut String, p: Point) {
    let _ = write!(out, "{} {}", format_coordinate(p.x), format_coordinate(p.y));
}

/// `(x y, ..., x y)` with the first vertex repeated at the end, as WKT closes rings.
fn ring(out: &mut String, r: &Ring) {
    out.push('(');
    for (i, &p) in r.points.iter().chain(r.points.first()).enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        point(out, p);
    }
    out.push(')');
}

/// A polygon set as a WKT `MULTIPOLYGON`. With `nested = false` (inputs), one polygon per ring,
/// in order and with each ring's own orientation, so the ring list is faithful whatever the fill
/// rule. With `nested = true` (conventional output), holes go inside the outers that hold them
/// (clip-core's `nest`).
pub fn polygons_to_wkt(p: &Polygons, nested: bool) -> String {
    if p.is_empty() {
        return "MULTIPOLYGON EMPTY".to_owned();
    }
    let mut out = String::from("MULTIPOLYGON (");
    if nested {
        for (i, np) in nest(p).iter().enumerate() {
            out.push_str(if i > 0 { ", (" } else { "(" });
            ring(&mut out, &np.outer);
            for h in &np.holes {
                out.push_str(", ");
                ring(&mut out, h);
            }
            out.push(')');
        }
    } else {
        for (i, r) in p.rings.iter().enumerate() {
            out.push_str(if i > 0 { ", (" } else { "(" });
            ring(&mut out, r);
            out.push(')');
        }
    }
    out.push(')');
    out
}

/// Segments as a WKT `MULTILINESTRING`, one two-point line per segment, in order.
pub fn segments_to_wkt(s: &[Segment]) -> String {
    if s.is_empty() {
        return "MULTILINESTRING EMPTY".to_owned();
    }
    let mut out = String::from("MULTILINESTRING (");
    for (i, seg) in s.iter().enumerate() {
        out.push_str(if i > 0 { ", (" } else { "(" });
        point(&mut out, seg.a);
        out.push_str(", ");
        point(&mut out, seg.b);
        out.push(')');
    }
    out.push(')');
    out
}

/// A line clipper's pieces as a WKT `MULTILINESTRING` (segment indices are not kept).
pub fn pieces_to_wkt(pieces: &[VisiblePiece]) -> String {
    segments_to_wkt(&pieces.iter().map(|p| p.piece).collect::<Vec<_>>())
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::Rect;

    #[test]
    fn coordinates_round_trip() {
        for v in [0.0, 1.0, -2.5, 0.1, 1e-300, 123456.789, 1e20, f64::MIN_POSITIVE, 1.0 + f64::EPSILON] {
            assert_eq!(format_coordinate(v).parse::<f64>().unwrap(), v);
        }
        assert_eq!(format_coordinate(3.0), "3");
        assert_eq!(format_coordinate(1e-300), "1e-300");
    }

    #[test]
    fn polygons_and_segments() {
        let outer = Rect::new(0.0, 0.0, 4.0, 4.0).to_ring();
        let hole = Rect::new(1.0, 1.0, 2.0, 2.0).to_ring().reversed();
        let p = Polygons::new(vec![hole, outer]);
        assert_eq!(
            polygons_to_wkt(&p, false),
            "MULTIPOLYGON (((1 2, 2 2, 2 1, 1 1, 1 2)), ((0 0, 4 0, 4 4, 0 4, 0 0)))"
        );
        assert_eq!(polygons_to_wkt(&p, true), "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 2, 2 2, 2 1, 1 1, 1 2)))");
        assert_eq!(polygons_to_wkt(&Polygons::empty(), true), "MULTIPOLYGON EMPTY");
        let s = [Segment::new(Point::new(0.0, 0.5), Point::new(1.0, -2.0))];
        assert_eq!(segments_to_wkt(&s), "MULTILINESTRING ((0 0.5, 1 -2))");
        assert_eq!(segments_to_wkt(&[]), "MULTILINESTRING EMPTY");
    }
}
