//! Bytes that decode to a given case: real polygons written as `Vertex::Raw` steps in the
//! byte format `arbitrary` reads (little-endian numbers, a `u32` choosing an enum's variant, a
//! "one more" byte before each element of a list), to seed the corpora from real cases. The
//! tests decode what is encoded, so a change of format in `arbitrary` shows there.

use clip_core::{FillRule, Polygons, Segment};

/// The bytes `arbitrary` reads as variant `index` of an enum of `count` variants.
fn variant(out: &mut Vec<u8>, index: u64, count: u64) {
    let v = ((index << 32).div_ceil(count)) as u32;
    out.extend(v.to_le_bytes());
}

/// `Frame { step: Step::One, offset: Offset::Zero }`: raw vertices carry their own coordinates.
fn frame(out: &mut Vec<u8>) {
    variant(out, 0, 7);
    variant(out, 0, 6);
}

/// `Vertex::Raw(x, y)`, the last of the 8 variants.
fn raw(out: &mut Vec<u8>, x: f64, y: f64) {
    variant(out, 7, 8);
    out.extend(x.to_le_bytes());
    out.extend(y.to_le_bytes());
}

/// A `ShapeSpec` of raw vertices, as a field that is not the last.
fn shape(out: &mut Vec<u8>, p: &Polygons) {
    for ring in &p.rings {
        out.push(1);
        for q in &ring.points {
            out.push(1);
            raw(out, q.x, q.y);
        }
        out.push(0);
        out.push(0); // not reversed
    }
    out.push(0);
}

fn fill_rule(out: &mut Vec<u8>, fill: FillRule) {
    let index = match fill {
        FillRule::EvenOdd => 0,
        FillRule::NonZero => 1,
        FillRule::Positive => 2,
        FillRule::Negative => 3,
    };
    variant(out, index, 4);
}

/// Bytes the `vatti` target decodes to `subject`, `clip` and `fill`.
pub fn vatti(subject: &Polygons, clip: &Polygons, fill: FillRule) -> Vec<u8> {
    let mut out = Vec::new();
    frame(&mut out);
    shape(&mut out, subject);
    shape(&mut out, clip);
    fill_rule(&mut out, fill);
    out
}

/// Bytes the `window_clippers` target decodes to `subject` against the convex hull of `window`'s
/// vertices (counter-clockwise), under `fill`.
pub fn window_clippers(subject: &Polygons, window: &Polygons, fill: FillRule) -> Vec<u8> {
    let mut out = Vec::new();
    frame(&mut out);
    shape(&mut out, subject);
    variant(&mut out, 0, 3); // WindowSpec::Hull
    shape(&mut out, window);
    out.push(0); // not reversed
    fill_rule(&mut out, fill);
    out
}

/// Bytes the `line_clippers` target decodes to `window` (as it is) and `segments`.
pub fn line_clippers(window: &Polygons, segments: &[Segment]) -> Vec<u8> {
    let mut out = Vec::new();
    frame(&mut out);
    variant(&mut out, 2, 3); // WindowSpec::Raw
    shape(&mut out, window);
    for s in segments {
        out.push(1);
        variant(&mut out, 4, 5); // SegmentSpec::Raw
        for v in [s.a.x, s.a.y, s.b.x, s.b.y] {
            out.extend(v.to_le_bytes());
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{lines, vatti as vatti_target, windows};
    use clip_core::{Point, Ring};
    use clip_testkit::workload::convex_hull;

    fn square(x: f64, y: f64, s: f64) -> Polygons {
        let p = |a, b| Point::new(a, b);
        Polygons::from(Ring::new(vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]))
    }

    #[test]
    fn encoded_cases_decode_to_themselves() {
        let a = Polygons::new(vec![square(0.0, 0.0, 4.0).rings[0].clone(), square(1.0, 1.0, 1.0).rings[0].reversed()]);
        let b = square(1e9 + 0.1, -2.5, 3.0);
        for fill in FillRule::ALL {
            let case = vatti_target::decode(&vatti(&a, &b, fill)).unwrap();
            assert_eq!((case.subject, case.clip, case.fill), (a.clone(), b.clone(), fill));
            let case = windows::decode(&window_clippers(&a, &b, fill)).unwrap();
            let hull = Polygons::from(Ring::new(convex_hull(&b.rings[0].points)));
            assert_eq!((case.subject, case.window, case.fill), (a.clone(), hull, fill));
        }
        let segments = [
            Segment::new(Point::new(-1.0, 0.5), Point::new(9.0, 0.25)),
            Segment::new(b.rings[0].points[0], b.rings[0].points[0]),
        ];
        let case = lines::decode(&line_clippers(&a, &segments)).unwrap();
        assert_eq!((case.window, case.segments), (a, segments.to_vec()));
    }
}
