//! One case of an external suite, in a form every suite shares: the inputs, and what the suite
//! expects of the answer.

use clip_core::{BoolOp, FillRule, Polygons, Segment};

/// A named case of a suite.
#[derive(Clone, Debug, PartialEq)]
pub struct SuiteCase {
    /// The name `--case` selects it by: a record number, or `file/operation`.
    pub name: String,
    /// What to run and how to judge it.
    pub input: CaseInput,
}

/// What a case asks for.
#[derive(Clone, Debug, PartialEq)]
pub enum CaseInput {
    /// A boolean operation on polygons.
    Polygon {
        /// Subject operand.
        subject: Polygons,
        /// Clip operand.
        clip: Polygons,
        /// The operation.
        op: BoolOp,
        /// The fill rule of both operands.
        fill: FillRule,
        /// How the answer is judged.
        expected: PolygonExpectation,
    },
    /// Line clipping, judged by the exact line oracle.
    Line {
        /// The window (even-odd).
        window: Polygons,
        /// The segments (the edges of the suite's polylines).
        segments: Vec<Segment>,
    },
    /// A case that is not of a kind the clippers do (reported as skipped).
    NotApplicable(String),
    /// A case that could not be read (reported as each clipper's failure).
    Malformed(String),
}

/// How a polygon answer is judged.
#[derive(Clone, Debug, PartialEq)]
pub enum PolygonExpectation {
    /// Clipper2's stored area and path count, with the tolerances of its own test.
    Clipper2 {
        /// Record number (the tolerances depend on it).
        number: usize,
        /// Stored area (not checked when 0 or less).
        area: i64,
        /// Stored path count (not checked when 0 or less).
        count: i64,
    },
    /// The same region as this expected result (read under even-odd).
    Region(Polygons),
}
