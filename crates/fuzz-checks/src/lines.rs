//! The `line_clippers` target: every line clipper of this project on a window from the bytes,
//! with segments through its vertices, along its edges and between grid points, checked by the
//! exact line oracle.

use arbitrary::{Arbitrary, Unstructured};
use clip_core::{LineClipper, Point, Polygons, Segment, VisiblePiece, validate_segments, validate_window};
use clip_cyrus_beck::{CyrusBeck, Liu};
use clip_oracle::line::{LINE_T_TOLERANCE, check_line_batch};
use clip_virtual_box::VirtualBox;

use crate::Outcome;
use crate::shape::{Builder, Frame};
use crate::windows::{WindowSpec, window};

/// Most segments in a batch.
pub const MAX_SEGMENTS: usize = 48;

/// How a segment is made; vertex and edge indices are taken modulo the window's vertex count.
#[derive(Arbitrary, Clone, Copy, Debug, PartialEq)]
pub enum SegmentSpec {
    /// Between two grid points.
    Grid((i8, i8), (i8, i8)),
    /// Through a window vertex: from `v − before·d` to `v + after·d`, `d` in grid steps (a
    /// segment ending on the vertex when `before` or `after` is 0).
    ThroughVertex {
        /// Which vertex.
        vertex: u8,
        /// `d`'s x, in grid steps (-8..=8).
        dx: i8,
        /// `d`'s y, in grid steps (-8..=8).
        dy: i8,
        /// How many `d`s before the vertex the segment starts (0..=3).
        before: u8,
        /// How many `d`s after the vertex it ends (0..=3).
        after: u8,
    },
    /// On the line of a window edge, from `t0/4` to `t1/4` of the way along it: along the edge,
    /// past its ends, or overlapping it in part.
    AlongEdge {
        /// Which edge.
        edge: u8,
        /// Where the segment starts, in quarters of the edge (-8..=8).
        t0: i8,
        /// Where it ends, in quarters of the edge (-8..=8).
        t1: i8,
    },
    /// From one window vertex to another: chords and diagonals.
    VertexToVertex(u8, u8),
    /// Any coordinates at all: a typed error unless finite and in range.
    Raw(f64, f64, f64, f64),
}

/// What the bytes decode to.
#[derive(Arbitrary, Clone, Debug, PartialEq)]
pub struct LineInput {
    /// The grid everything is built on.
    pub frame: Frame,
    /// The window.
    pub window: WindowSpec,
    /// The segments.
    pub segments: Vec<SegmentSpec>,
}

/// A decoded case.
#[derive(Clone, Debug, PartialEq)]
pub struct LineCase {
    /// The window (read under even-odd).
    pub window: Polygons,
    /// The segments.
    pub segments: Vec<Segment>,
}

fn segment(b: &Builder, vertices: &[Point], spec: SegmentSpec) -> Segment {
    let s = b.step();
    let vertex = |k: u8| vertices[usize::from(k) % vertices.len()];
    match spec {
        SegmentSpec::Grid((i, j), (k, l)) => Segment::new(b.grid_point(i, j), b.grid_point(k, l)),
        SegmentSpec::Raw(ax, ay, bx, by) => Segment::new(Point::new(ax, ay), Point::new(bx, by)),
        _ if vertices.is_empty() => Segment::new(b.grid_point(0, 0), b.grid_point(1, 1)),
        SegmentSpec::ThroughVertex { vertex: k, dx, dy, before, after } => {
            let (v, d) = (vertex(k), Point::new(f64::from(dx % 9) * s, f64::from(dy % 9) * s));
            let (before, after) = (f64::from(before % 4), f64::from(after % 4));
            Segment::new(
                Point::new(v.x - before * d.x, v.y - before * d.y),
                Point::new(v.x + after * d.x, v.y + after * d.y),
            )
        }
        SegmentSpec::AlongEdge { edge, t0, t1 } => {
            let i = usize::from(edge) % vertices.len();
            let (p, q) = (vertices[i], vertices[(i + 1) % vertices.len()]);
            Segment::new(p.lerp(q, f64::from(t0 % 9) / 4.0), p.lerp(q, f64::from(t1 % 9) / 4.0))
        }
        SegmentSpec::VertexToVertex(i, j) => Segment::new(vertex(i), vertex(j)),
    }
}

/// Decodes the bytes as libFuzzer hands them to the target (`None`: too short to decode).
pub fn decode(data: &[u8]) -> Option<LineCase> {
    let input = LineInput::arbitrary_take_rest(Unstructured::new(data)).ok()?;
    let mut b = Builder::new(input.frame);
    let window = window(&mut b, &input.window);
    let vertices: Vec<Point> = window.points().copied().collect();
    let segments = input.segments.iter().take(MAX_SEGMENTS).map(|&spec| segment(&b, &vertices, spec)).collect();
    Some(LineCase { window, segments })
}

/// The target: decodes and checks.
pub fn check_bytes(data: &[u8]) -> Result<(), String> {
    decode(data).map_or(Ok(()), |case| check(&case).map(|_| ()))
}

/// The line clippers under test, by registry name.
pub fn clippers() -> [Box<dyn LineClipper>; 4] {
    [Box::new(CyrusBeck), Box::new(Liu), Box::new(VirtualBox::NEW2), Box::new(VirtualBox::NEW1)]
}

/// Each clipper must refuse a window it does not take (or an invalid one) in `prepare`, and a
/// batch with a non-finite or out-of-range endpoint in `clip_batch`, with typed errors; otherwise
/// its pieces must pass `check_line_batch` at `LINE_T_TOLERANCE`. Returns the pieces.
pub fn check(case: &LineCase) -> Result<Outcome, String> {
    let LineCase { window, segments } = case;
    let window_valid = validate_window(window);
    let segments_valid = validate_segments(segments);
    let mut outputs = Vec::new();
    for clipper in clippers() {
        let name = clipper.name();
        let takes = window_valid.is_ok() && clipper.capabilities().window.accepts(window);
        let prepared = match (takes, clipper.prepare(window)) {
            (false, Err(_)) => continue,
            (false, Ok(_)) => return Err(format!("{name}: prepared a window it does not take ({window_valid:?})")),
            (true, Err(e)) => return Err(format!("{name}: refused a valid window: {e}")),
            (true, Ok(p)) => p,
        };
        let mut pieces: Vec<VisiblePiece> = Vec::new();
        match (&segments_valid, prepared.clip_batch(segments, &mut pieces)) {
            (Err(_), Err(_)) => continue,
            (Err(why), Ok(())) => return Err(format!("{name}: clipped an invalid batch ({why})")),
            (Ok(()), Err(e)) => return Err(format!("{name}: refused valid segments: {e}")),
            (Ok(()), Ok(())) => {
                check_line_batch(window, segments, &pieces, LINE_T_TOLERANCE).map_err(|f| format!("{name}: {f}"))?
            }
        }
        outputs.push((name, pieces));
    }
    Ok(if outputs.is_empty() { Outcome::Refused } else { Outcome::Lines(outputs) })
}
