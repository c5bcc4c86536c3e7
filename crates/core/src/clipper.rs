//! The interfaces the harness registers clippers behind.

use crate::{BoolOp, ClipError, FillRule, Polygons, Segment, Trapezoid};

/// The windows a clipper can take.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum WindowKind {
    /// Any polygons (for polygon clippers: any clip operand; for line clippers: any rings read
    /// under even-odd).
    Any,
    /// One convex ring, either orientation.
    Convex,
    /// One axis-aligned rectangle.
    Rectangle,
}

impl WindowKind {
    /// True when `window` is of this kind (checked exactly).
    pub fn accepts(self, window: &Polygons) -> bool {
        match self {
            WindowKind::Any => true,
            WindowKind::Convex => crate::convex_window(window, "").is_ok(),
            WindowKind::Rectangle => crate::rect_window(window, "").is_ok(),
        }
    }
}

/// How a polygon clipper's output is to be read (docs/DESIGN.md, "Polygon output" and "Window
/// clippers and bridges").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OutputForm {
    /// Conventional output, read under non-zero, whatever the input.
    Conventional,
    /// Each subject ring clipped on its own and kept in its orientation: read under the input's
    /// fill rule; rings may overlap (Sutherland-Hodgman, four-state, Clipper2's RectClip).
    InputRule,
    /// Winding numbers kept, so read under the input's fill rule; and conventional output when
    /// the subject is itself in conventional form and the rule reads it as its winding-1 region
    /// (any rule but negative): `sutherland-hodgman-split`.
    ConventionalForConventionalSubject,
}

/// What a polygon clipper can do, so the harness runs it only where it applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PolygonCapabilities {
    /// Operations it performs.
    pub ops: &'static [BoolOp],
    /// Fill rules it reads its operands under.
    pub fill_rules: &'static [FillRule],
    /// Which clip operands it takes.
    pub window: WindowKind,
    /// True when [`PolygonClipper::clip_trapezoids`] works.
    pub trapezoids: bool,
    /// True when its output may keep zero-width bridges along the window (Sutherland-Hodgman,
    /// the four-state clipper): such output is compared by region, not checked for simplicity.
    pub bridges: bool,
    /// How its output is read.
    pub output: OutputForm,
}

impl PolygonCapabilities {
    /// A general clipper: all four operations under all four fill rules, any clip operand,
    /// conventional polygon output, no trapezoids.
    pub const GENERAL: PolygonCapabilities = PolygonCapabilities {
        ops: &BoolOp::ALL,
        fill_rules: &FillRule::ALL,
        window: WindowKind::Any,
        trapezoids: false,
        bridges: false,
        output: OutputForm::Conventional,
    };

    /// A window clipper (Sutherland-Hodgman, four-state, Clipper2's RectClip): intersection
    /// with a `window` of the given kind under any fill rule, its output read under the input's
    /// rule because each subject ring is clipped on its own (and may keep bridges).
    pub const fn window_clipper(window: WindowKind) -> PolygonCapabilities {
        PolygonCapabilities {
            ops: &[BoolOp::Intersection],
            fill_rules: &FillRule::ALL,
            window,
            trapezoids: false,
            bridges: true,
            output: OutputForm::InputRule,
        }
    }

    /// True when the clipper does `op` under `fill`.
    pub fn supports(&self, op: BoolOp, fill: FillRule) -> bool {
        self.ops.contains(&op) && self.fill_rules.contains(&fill)
    }

    /// `Ok` when the clipper does `op` under `fill`, else the [`ClipError::Unsupported`] it
    /// returns: the guard at the top of every [`PolygonClipper::clip`].
    pub fn check(&self, clipper: &'static str, op: BoolOp, fill: FillRule) -> Result<(), ClipError> {
        if !self.ops.contains(&op) {
            return Err(ClipError::Unsupported { clipper, what: format!("the {op} operation") });
        }
        if !self.fill_rules.contains(&fill) {
            return Err(ClipError::Unsupported { clipper, what: format!("the {fill} fill rule") });
        }
        Ok(())
    }
}

/// A boolean operation on polygon sets.
pub trait PolygonClipper: Send + Sync {
    /// The registry name (`vatti`, `sutherland-hodgman`, ...).
    fn name(&self) -> &'static str;

    /// What it can do.
    fn capabilities(&self) -> PolygonCapabilities;

    /// `subject op clip`, both read under `fill`. Output follows docs/DESIGN.md's convention unless
    /// [`PolygonCapabilities::bridges`] says otherwise.
    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError>;

    /// The same region as horizontal trapezoids, for clippers whose capabilities say so.
    fn clip_trapezoids(
        &self,
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
    ) -> Result<Vec<Trapezoid>, ClipError> {
        let _ = (subject, clip, op, fill);
        Err(ClipError::Unsupported { clipper: self.name(), what: "trapezoid output".into() })
    }
}

/// What a line clipper can do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LineCapabilities {
    /// Which windows it takes.
    pub window: WindowKind,
}

/// A visible piece of an input segment: `segment` indexes the batch, `piece` runs in the input
/// segment's direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VisiblePiece {
    /// Index of the input segment in the batch.
    pub segment: usize,
    /// The visible part, directed like the input.
    pub piece: Segment,
}

/// A line clipper: per-window work once in [`LineClipper::prepare`], then batches of segments.
pub trait LineClipper: Send + Sync {
    /// The registry name (`cyrus-beck`, `liu`, `virtual-box`, ...).
    fn name(&self) -> &'static str;

    /// What it can do.
    fn capabilities(&self) -> LineCapabilities;

    /// Does the per-window work (bounding boxes, codes, edge tables) once.
    fn prepare(&self, window: &Polygons) -> Result<Box<dyn PreparedWindow>, ClipError>;
}

/// A window ready to clip segments against.
pub trait PreparedWindow: Send + Sync {
    /// Clips every segment of the batch, appending the visible pieces to `out`: by segment in
    /// input order, and within a segment by increasing parameter. Follows docs/DESIGN.md's closed-set
    /// rule: maximal closed intervals of positive length, merged, isolated touch points dropped.
    /// A non-finite endpoint fails the whole batch with [`ClipError::NonFinite`].
    fn clip_batch(&self, segments: &[Segment], out: &mut Vec<VisiblePiece>) -> Result<(), ClipError>;
}
