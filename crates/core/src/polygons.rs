//! A set of rings read together under a fill rule: one operand of a boolean operation.

use crate::{Point, Rect, Ring};

/// A region given by rings read under a [`crate::FillRule`]: any mix of outers, holes, several
/// parts, overlapping or self-intersecting rings. Clipper output follows docs/DESIGN.md's convention
/// instead: simple, non-crossing rings, outers counter-clockwise and holes clockwise.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Polygons {
    /// The rings, in no particular order.
    pub rings: Vec<Ring>,
}

impl Polygons {
    /// The empty region.
    pub const fn empty() -> Polygons {
        Polygons { rings: Vec::new() }
    }

    /// Makes a region from rings.
    pub fn new(rings: Vec<Ring>) -> Polygons {
        Polygons { rings }
    }

    /// True when there is no ring.
    pub fn is_empty(&self) -> bool {
        self.rings.is_empty()
    }

    /// Total number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.rings.iter().map(Ring::len).sum()
    }

    /// Every vertex of every ring.
    pub fn points(&self) -> impl Iterator<Item = &Point> {
        self.rings.iter().flat_map(|r| r.points.iter())
    }

    /// Every edge of every ring.
    pub fn edges(&self) -> impl Iterator<Item = crate::Segment> + '_ {
        self.rings.iter().flat_map(Ring::edges)
    }

    /// The bounding box of all rings.
    pub fn bounds(&self) -> Rect {
        Rect::bounding(self.points())
    }

    /// The region mirrored across the line y = x (every point's x and y exchanged), each ring
    /// walked the other way. A mirror alone reverses orientation; the walk undoes that, so every
    /// point of the mirrored region has the winding number of its original, and the same fill
    /// rule reads both alike. Exact (no arithmetic), and its own inverse.
    pub fn transposed(&self) -> Polygons {
        let ring = |r: &Ring| Ring { points: r.points.iter().rev().map(|p| Point::new(p.y, p.x)).collect() };
        Polygons { rings: self.rings.iter().map(ring).collect() }
    }

    /// Sum of the rings' signed areas. For output that follows the convention (outers
    /// counter-clockwise, holes clockwise, no overlaps) this is the area of the region.
    pub fn signed_area(&self) -> f64 {
        self.rings.iter().map(Ring::signed_area).sum()
    }
}

impl From<Ring> for Polygons {
    fn from(ring: Ring) -> Polygons {
        Polygons { rings: vec![ring] }
    }
}

impl From<Vec<Ring>> for Polygons {
    fn from(rings: Vec<Ring>) -> Polygons {
        Polygons { rings }
    }
}

impl From<Rect> for Polygons {
    fn from(rect: Rect) -> Polygons {
        Polygons { rings: vec![rect.to_ring()] }
    }
}
