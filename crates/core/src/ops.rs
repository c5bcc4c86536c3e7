//! The boolean operations and the fill rules that decide what a set of rings covers.

use core::fmt;
use core::str::FromStr;

/// A boolean operation on two regions, subject `A` and clip `B`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum BoolOp {
    /// `A ∩ B`.
    Intersection,
    /// `A ∪ B`.
    Union,
    /// `A − B`.
    Difference,
    /// `A ⊕ B`: in exactly one of them.
    Xor,
}

impl BoolOp {
    /// All four, in a fixed order.
    pub const ALL: [BoolOp; 4] = [BoolOp::Intersection, BoolOp::Union, BoolOp::Difference, BoolOp::Xor];

    /// Whether a point inside `A` (`in_a`) and/or inside `B` (`in_b`) is in the result.
    #[inline]
    pub fn apply(self, in_a: bool, in_b: bool) -> bool {
        match self {
            BoolOp::Intersection => in_a && in_b,
            BoolOp::Union => in_a || in_b,
            BoolOp::Difference => in_a && !in_b,
            BoolOp::Xor => in_a != in_b,
        }
    }

    /// True when swapping the operands leaves the result unchanged.
    #[inline]
    pub fn is_symmetric(self) -> bool {
        !matches!(self, BoolOp::Difference)
    }

    /// The lower-case name used on the command line and in result files.
    pub fn name(self) -> &'static str {
        match self {
            BoolOp::Intersection => "intersection",
            BoolOp::Union => "union",
            BoolOp::Difference => "difference",
            BoolOp::Xor => "xor",
        }
    }
}

/// How a winding number decides membership of a region.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum FillRule {
    /// Inside when the winding number is odd.
    EvenOdd,
    /// Inside when the winding number is not zero.
    NonZero,
    /// Inside when the winding number is positive.
    Positive,
    /// Inside when the winding number is negative.
    Negative,
}

impl FillRule {
    /// All four, in a fixed order.
    pub const ALL: [FillRule; 4] = [FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive, FillRule::Negative];

    /// Whether a point of winding number `w` is inside.
    #[inline]
    pub fn is_inside(self, w: i32) -> bool {
        match self {
            FillRule::EvenOdd => w & 1 != 0,
            FillRule::NonZero => w != 0,
            FillRule::Positive => w > 0,
            FillRule::Negative => w < 0,
        }
    }

    /// The lower-case name used on the command line and in result files.
    pub fn name(self) -> &'static str {
        match self {
            FillRule::EvenOdd => "even-odd",
            FillRule::NonZero => "non-zero",
            FillRule::Positive => "positive",
            FillRule::Negative => "negative",
        }
    }
}

impl fmt::Display for BoolOp {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl fmt::Display for FillRule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A name that is not an operation or fill rule; it lists the valid ones.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown {what} '{given}' (expected one of: {valid})")]
pub struct UnknownName {
    pub(crate) what: &'static str,
    pub(crate) given: String,
    pub(crate) valid: &'static str,
}

impl FromStr for BoolOp {
    type Err = UnknownName;
    fn from_str(s: &str) -> Result<BoolOp, UnknownName> {
        match s.to_ascii_lowercase().as_str() {
            "intersection" | "and" | "intersect" => Ok(BoolOp::Intersection),
            "union" | "or" => Ok(BoolOp::Union),
            "difference" | "diff" | "minus" => Ok(BoolOp::Difference),
            "xor" => Ok(BoolOp::Xor),
            _ => Err(UnknownName {
                what: "operation",
                given: s.to_owned(),
                valid: "intersection, union, difference, xor",
            }),
        }
    }
}

impl FromStr for FillRule {
    type Err = UnknownName;
    fn from_str(s: &str) -> Result<FillRule, UnknownName> {
        match s.to_ascii_lowercase().replace('_', "-").as_str() {
            "even-odd" | "evenodd" => Ok(FillRule::EvenOdd),
            "non-zero" | "nonzero" => Ok(FillRule::NonZero),
            "positive" => Ok(FillRule::Positive),
            "negative" => Ok(FillRule::Negative),
            _ => Err(UnknownName {
                what: "fill rule",
                given: s.to_owned(),
                valid: "even-odd, non-zero, positive, negative",
            }),
        }
    }
}
