//! Where a failure is, read from what the check said: the coordinates it names, or the output
//! ring, vertex, edge, piece or input segment it names by index. For the failure picture.

use clip_core::{Point, Polygons, Segment, VisiblePiece};
use clip_testkit::case_record::FailureMark;

/// The `(x, y)` pairs in `message`, in order, finite ones only.
fn coordinates(message: &str) -> Vec<Point> {
    let mut found = Vec::new();
    let mut rest = message;
    while let Some(open) = rest.find('(') {
        rest = &rest[open + 1..];
        let Some(close) = rest.find(')') else { break };
        if let Some((x, y)) = rest[..close].split_once(", ")
            && let (Ok(x), Ok(y)) = (x.trim().parse::<f64>(), y.trim().parse::<f64>())
            && x.is_finite()
            && y.is_finite()
        {
            found.push(Point::new(x, y));
        }
    }
    found
}

/// The number after `word ` in `message` (`ring 3` gives 3).
fn index_after(message: &str, word: &str) -> Option<usize> {
    let at = message.find(&format!("{word} "))?;
    let digits: String = message[at + word.len() + 1..].chars().take_while(char::is_ascii_digit).collect();
    digits.parse().ok()
}

/// The mark for a coordinate pair, or two joined by ` - ` (an edge).
fn from_coordinates(message: &str) -> Option<FailureMark> {
    match coordinates(message)[..] {
        [a, b, ..] if message.contains(") - (") => Some(FailureMark::Edge(a, b)),
        [a, ..] => Some(FailureMark::Point(a)),
        [] => None,
    }
}

/// Where a polygon check failed: coordinates in the message, else the failing clipper's `output`
/// ring vertex or edge it names (a ring named alone: its first vertex).
pub fn polygon_mark(message: &str, output: Option<&Polygons>) -> Option<FailureMark> {
    if let Some(mark) = from_coordinates(message) {
        return Some(mark);
    }
    let ring = output?.rings.get(index_after(message, "ring")?)?;
    let n = ring.points.len();
    if let Some(v) = index_after(message, "vertex") {
        return ring.points.get(v).map(|&p| FailureMark::Point(p));
    }
    if let Some(e) = index_after(message, "edge").filter(|&e| e < n) {
        return Some(FailureMark::Edge(ring.points[e], ring.points[(e + 1) % n]));
    }
    ring.points.first().map(|&p| FailureMark::Point(p))
}

/// Where a line check failed: the input segment it names (`segment i: ...`), else the failing
/// clipper's piece it names, else coordinates in the message.
pub fn line_mark(message: &str, segments: &[Segment], pieces: Option<&[VisiblePiece]>) -> Option<FailureMark> {
    let edge = |s: Segment| FailureMark::Edge(s.a, s.b);
    if let Some(piece) = index_after(message, "piece").and_then(|k| pieces?.get(k)) {
        return Some(edge(piece.piece));
    }
    if let Some(s) = index_after(message, "segment").and_then(|i| segments.get(i)) {
        return Some(edge(*s));
    }
    from_coordinates(message)
}

#[cfg(test)]
mod tests {
    use clip_core::{BoolOp, FillRule, Rect, Ring};
    use clip_oracle::polygon::{OutputRules, check_polygon_result};
    use clip_testkit::case_record::{line_failure_svg, polygon_failure_svg};

    use super::*;

    #[test]
    fn the_picture_of_a_planted_crossing_names_its_coordinates() {
        let subject = Polygons::from(Rect::new(0.0, 0.0, 10.0, 10.0));
        let clip = Polygons::from(Rect::new(2.0, 2.0, 12.0, 12.0));
        // A bow-tie where the intersection should be: its edges cross at (6, 6).
        let planted = Polygons::new(vec![Ring::new(vec![
            Point::new(2.0, 2.0),
            Point::new(10.0, 10.0),
            Point::new(10.0, 2.0),
            Point::new(2.0, 10.0),
        ])]);
        let failure = check_polygon_result(
            &subject,
            &clip,
            BoolOp::Intersection,
            FillRule::EvenOdd,
            &planted,
            &OutputRules::conventional(1e-9),
        )
        .unwrap_err()
        .to_string();
        let mark = polygon_mark(&failure, Some(&planted));
        assert_eq!(mark, Some(FailureMark::Point(Point::new(6.0, 6.0))), "{failure}");
        let svg = polygon_failure_svg(&subject, &clip, FillRule::EvenOdd, &[("planted", &planted)], &failure, mark);
        assert!(svg.contains("failing point (6, 6)"), "{svg}");
    }

    #[test]
    fn indices_name_output_rings_and_input_segments() {
        let square = Polygons::from(Rect::new(0.0, 0.0, 4.0, 4.0));
        let first = square.rings[0].points[0];
        assert_eq!(
            polygon_mark("invalid output: ring 0 is a hole (depth 1) but runs counter-clockwise", Some(&square)),
            Some(FailureMark::Point(first))
        );
        assert_eq!(polygon_mark("area identity broken: |A⊕B| = |A∪B| − |A∩B|: 1 vs 2", Some(&square)), None);
        let segments = [Segment::new(Point::new(-1.0, 1.0), Point::new(5.0, 3.0))];
        let failure = "segment 0: visible intervals should be [(0.1, 0.8)], got [(0.1, 0.5)]";
        let mark = line_mark(failure, &segments, None);
        assert_eq!(mark, Some(FailureMark::Edge(segments[0].a, segments[0].b)));
        let svg = line_failure_svg(&square, &segments, &[("x", &[])], failure, mark);
        assert!(svg.contains("failing edge (-1, 1) - (5, 3)"), "{svg}");
    }
}
