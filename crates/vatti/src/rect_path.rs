//! The rectangle path (the paper's Extensions: "the algorithm can be optimized for rectangular
//! clip bounds"): for ∩ with one axis-aligned rectangle, the subject's rings are cut to it side
//! by side (Sutherland-Hodgman against each side's half-plane, which keeps every winding number
//! inside that half-plane), so the sweep sees neither the rectangle nor any subject edge outside
//! it, and searches no crossings with the rectangle's sides.

use clip_core::{BoolOp, FillRule, Point, Polygons, Rect, Ring};

/// The rectangle the clip operand is (one ring, four corners, positive area) and whether it is
/// inside under `fill`; `None` when the clip is anything else.
pub(crate) fn rectangle_clip(clip: &Polygons, op: BoolOp, fill: FillRule) -> Option<(Rect, bool)> {
    if op != BoolOp::Intersection {
        return None;
    }
    let [ring] = clip.rings.as_slice() else { return None };
    // A longer ring is a rectangle only through repeated vertices: it takes the general path.
    if ring.points.len() > 16 {
        return None;
    }
    let r = ring.as_rect()?;
    let winding = if ring.signed_area() > 0.0 { 1 } else { -1 };
    Some((r, fill.is_inside(winding)))
}

/// The subject cut to rectangle `r`: the same winding number at every point strictly inside `r`
/// (crossings with its sides rounded to f64, as the sweep rounds them), nothing outside it.
/// Each ring streams through the four sides as Sutherland and Hodgman's re-entrant pipeline, so
/// no pass holds a copy of a big ring: a million-vertex star cut to a small box allocates only
/// what reaches the box.
pub(crate) fn cut_to_rectangle(subject: &Polygons, r: Rect) -> Polygons {
    let sides = [Side::Left(r.min.x), Side::Right(r.max.x), Side::Bottom(r.min.y), Side::Top(r.max.y)];
    let rings = subject
        .rings
        .iter()
        .filter_map(|ring| {
            let mut pipeline = sides.map(Stage::new);
            let mut out = Vec::new();
            for &p in &ring.points {
                feed(&mut pipeline, 0, p, &mut out);
            }
            for k in 0..pipeline.len() {
                // The closing edge from a stage's last point back to its first.
                if let Some(first) = pipeline[k].first {
                    feed(&mut pipeline, k, first, &mut out);
                }
            }
            (out.len() >= 3).then_some(Ring { points: out })
        })
        .collect();
    Polygons::new(rings)
}

/// One side's place in the pipeline: the first point it saw and the last, with its side.
#[derive(Clone, Copy)]
struct Stage {
    side: Side,
    first: Option<Point>,
    prev: Point,
    prev_kept: bool,
}

impl Stage {
    fn new(side: Side) -> Stage {
        Stage { side, first: None, prev: Point::ZERO, prev_kept: false }
    }
}

/// Point `p` into stage `k`: the edge from the stage's previous point to `p` cut to its side,
/// what is kept passed on to the next stage (the last stage writes to `out`).
fn feed(pipeline: &mut [Stage; 4], k: usize, p: Point, out: &mut Vec<Point>) {
    let Some(stage) = pipeline.get_mut(k) else {
        out.push(p);
        return;
    };
    let kept = stage.side.keeps(p);
    let (side, prev, prev_kept) = (stage.side, stage.prev, stage.prev_kept);
    (stage.prev, stage.prev_kept) = (p, kept);
    if stage.first.is_none() {
        stage.first = Some(p);
        return;
    }
    match (prev_kept, kept) {
        (true, true) => feed(pipeline, k + 1, p, out),
        (true, false) => feed(pipeline, k + 1, side.crossing(prev, p), out),
        (false, true) => {
            feed(pipeline, k + 1, side.crossing(prev, p), out);
            feed(pipeline, k + 1, p, out);
        }
        (false, false) => {}
    }
}

/// One side of the rectangle: the half-plane that keeps what is on the rectangle's side of it.
#[derive(Clone, Copy)]
enum Side {
    Left(f64),
    Right(f64),
    Bottom(f64),
    Top(f64),
}

impl Side {
    #[inline]
    fn keeps(self, p: Point) -> bool {
        match self {
            Side::Left(x) => p.x >= x,
            Side::Right(x) => p.x <= x,
            Side::Bottom(y) => p.y >= y,
            Side::Top(y) => p.y <= y,
        }
    }

    /// Where edge `a b` (one end kept, one not) crosses the side's line: on it exactly, the other
    /// coordinate rounded and clamped between the ends. Computed from the lower end in
    /// lexicographic order, so an edge and its reverse cross at the same point.
    fn crossing(self, a: Point, b: Point) -> Point {
        let (p, q) = if (a.x, a.y) <= (b.x, b.y) { (a, b) } else { (b, a) };
        let along_x = |x: f64| {
            let y = p.y + (x - p.x) / (q.x - p.x) * (q.y - p.y);
            Point::new(x, y.clamp(p.y.min(q.y), p.y.max(q.y)))
        };
        let along_y = |y: f64| {
            let x = p.x + (y - p.y) / (q.y - p.y) * (q.x - p.x);
            Point::new(x.clamp(p.x.min(q.x), p.x.max(q.x)), y)
        };
        match self {
            Side::Left(x) | Side::Right(x) => along_x(x),
            Side::Bottom(y) | Side::Top(y) => along_y(y),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_intersection_with_one_rectangle_takes_the_path() {
        let rect = Polygons::from(Rect::new(0.0, 0.0, 2.0, 1.0));
        assert_eq!(
            rectangle_clip(&rect, BoolOp::Intersection, FillRule::NonZero),
            Some((Rect::new(0.0, 0.0, 2.0, 1.0), true))
        );
        assert_eq!(rectangle_clip(&rect, BoolOp::Intersection, FillRule::Negative).map(|c| c.1), Some(false));
        assert!(rectangle_clip(&rect, BoolOp::Union, FillRule::NonZero).is_none());
        let two = Polygons::new(vec![rect.rings[0].clone(), rect.rings[0].clone()]);
        assert!(rectangle_clip(&two, BoolOp::Intersection, FillRule::NonZero).is_none());
        // Found by the window_clippers fuzz corpus: an L-shaped spike, no area, three corners.
        let p = |x, y| Point::new(x, y);
        let spike = Polygons::from(Ring::new(vec![p(0.0, 6.0), p(0.0, 0.0), p(6.0, 0.0), p(0.0, 0.0)]));
        assert!(rectangle_clip(&spike, BoolOp::Intersection, FillRule::EvenOdd).is_none());
    }

    #[test]
    fn a_ring_around_the_rectangle_becomes_its_border() {
        let around = Polygons::from(Rect::new(-5.0, -5.0, 5.0, 5.0));
        let cut = cut_to_rectangle(&around, Rect::new(0.0, 0.0, 1.0, 1.0));
        assert_eq!(cut.signed_area(), 1.0);
        let beside = Polygons::from(Rect::new(3.0, 3.0, 5.0, 5.0));
        assert!(cut_to_rectangle(&beside, Rect::new(0.0, 0.0, 1.0, 1.0)).rings.is_empty());
    }
}
