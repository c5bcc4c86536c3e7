//! The messages of the external clipper protocol (docs/PROTOCOL.md), version [`PROTOCOL_VERSION`].

use clip_core::{BoolOp, FillRule, Point, Polygons, Ring, Segment, WindowKind};
use serde::{Deserialize, Serialize};

/// The protocol version this harness speaks; a handshake declaring another is refused.
pub const PROTOCOL_VERSION: u32 = 1;

/// A point on the wire: `[x, y]`, f64 written shortest-round-trip so it crosses exactly.
pub type WirePoint = [f64; 2];
/// A ring on the wire: its vertices, the closing vertex not repeated.
pub type WireRing = Vec<WirePoint>;

/// The clipper's first line: who it is and what it can do.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Handshake {
    /// The protocol version it speaks.
    pub protocol: u32,
    /// Its own name for itself (library and version), for people.
    pub name: String,
    /// Polygon clipping, if it does that.
    #[serde(default)]
    pub polygon: Option<PolygonDeclaration>,
    /// Line clipping, if it does that.
    #[serde(default)]
    pub line: Option<LineDeclaration>,
}

/// What a polygon clipper declares, in the names docs/DESIGN.md uses.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PolygonDeclaration {
    /// `intersection`, `union`, `difference`, `xor`.
    pub ops: Vec<String>,
    /// `even-odd`, `non-zero`, `positive`, `negative`.
    pub fill_rules: Vec<String>,
    /// `any`, `convex` or `rectangle`.
    pub window: String,
    /// `conventional` (simple rings, outers counter-clockwise, read under non-zero) or `bridged`
    /// (each subject ring clipped on its own, read under the input's rule).
    #[serde(default = "conventional")]
    pub output: String,
}

fn conventional() -> String {
    "conventional".into()
}

/// What a line clipper declares.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LineDeclaration {
    /// `any`, `convex` or `rectangle`.
    pub window: String,
}

/// A polygon request.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PolygonRequest<'a> {
    /// Request number; the reply must carry it.
    pub id: u64,
    /// The operation's name.
    pub op: &'a str,
    /// The fill rule's name.
    pub fill: &'a str,
    /// Subject rings.
    pub subject: Vec<WireRing>,
    /// Clip rings.
    pub clip: Vec<WireRing>,
}

/// A line request: a window and a batch of segments.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LineRequest {
    /// Request number; the reply must carry it.
    pub id: u64,
    /// Window rings (read under even-odd).
    pub window: Vec<WireRing>,
    /// Segments, each `[[x0, y0], [x1, y1]]`.
    pub segments: Vec<[WirePoint; 2]>,
}

/// A visible piece on the wire.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WirePiece {
    /// Index of the input segment in the batch.
    pub segment: usize,
    /// Start of the piece (nearer the segment's start).
    pub from: WirePoint,
    /// End of the piece.
    pub to: WirePoint,
}

/// A reply: the request's id and exactly one of `rings`, `pieces` or `error`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Reply {
    /// The id of the request answered.
    pub id: u64,
    /// The polygon result.
    #[serde(default)]
    pub rings: Option<Vec<WireRing>>,
    /// The line result.
    #[serde(default)]
    pub pieces: Option<Vec<WirePiece>>,
    /// Why the clipper gave no result.
    #[serde(default)]
    pub error: Option<String>,
    /// The clipper's own time for the call, in nanoseconds, without the pipe and JSON.
    #[serde(default)]
    pub time_ns: Option<f64>,
}

/// How a reply line breaks the protocol.
#[derive(Clone, Debug, PartialEq)]
pub enum Violation {
    /// Not JSON, or not a reply's fields.
    NotAReply {
        /// What the JSON reader said.
        problem: String,
        /// The start of the line.
        line: String,
    },
    /// A reply to another request.
    WrongId {
        /// The id in the reply.
        answered: u64,
        /// The id of the request.
        asked: u64,
    },
    /// Not exactly one of `rings`, `pieces` and `error`.
    NotOneResult {
        /// The request's id.
        id: u64,
        /// The start of the line.
        line: String,
    },
    /// A `time_ns` that is not a number of nanoseconds the call could have taken: negative, not
    /// finite, or longer than the round trip it was part of.
    ImpossibleTime {
        /// The request's id.
        id: u64,
        /// The time given.
        time_ns: f64,
        /// The round trip the harness measured, in nanoseconds.
        round_trip_ns: f64,
    },
}

impl Violation {
    /// True when the next line the process writes still answers the next request: the reply was
    /// read whole and only says something impossible.
    pub fn stream_in_step(&self) -> bool {
        matches!(self, Violation::ImpossibleTime { .. })
    }
}

impl std::fmt::Display for Violation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Violation::NotAReply { problem, line } => {
                write!(f, "it answered something that is not a reply ({problem}): {line}")
            }
            Violation::WrongId { answered, asked } => write!(f, "it answered id {answered} to request {asked}"),
            Violation::NotOneResult { id, line } => {
                write!(f, "reply {id} must carry exactly one of rings, pieces and error: {line}")
            }
            Violation::ImpossibleTime { id, time_ns, round_trip_ns } => write!(
                f,
                "reply {id} gives time_ns {time_ns}: a time must be a number of nanoseconds from 0 to the call's \
                 round trip ({round_trip_ns} ns)"
            ),
        }
    }
}

/// Our rings as wire rings.
pub fn to_wire(p: &Polygons) -> Vec<WireRing> {
    p.rings.iter().map(|r| r.points.iter().map(|q| [q.x, q.y]).collect()).collect()
}

/// Wire rings as ours.
pub fn from_wire(rings: &[WireRing]) -> Polygons {
    Polygons::new(rings.iter().map(|r| Ring::new(r.iter().map(|&[x, y]| Point::new(x, y)).collect())).collect())
}

/// Segments as wire pairs.
pub fn segments_to_wire(segments: &[Segment]) -> Vec<[WirePoint; 2]> {
    segments.iter().map(|s| [[s.a.x, s.a.y], [s.b.x, s.b.y]]).collect()
}

/// The operation named `name` in a handshake, or the complaint.
pub fn parse_op(name: &str) -> Result<BoolOp, String> {
    BoolOp::ALL.into_iter().find(|o| o.name() == name).ok_or_else(|| {
        format!(
            "unknown operation '{name}' (known: {})",
            BoolOp::ALL.iter().map(|o| o.name()).collect::<Vec<_>>().join(", ")
        )
    })
}

/// The fill rule named `name` in a handshake, or the complaint.
pub fn parse_fill(name: &str) -> Result<FillRule, String> {
    FillRule::ALL.into_iter().find(|f| f.name() == name).ok_or_else(|| {
        format!(
            "unknown fill rule '{name}' (known: {})",
            FillRule::ALL.iter().map(|f| f.name()).collect::<Vec<_>>().join(", ")
        )
    })
}

/// The window kind named `name` in a handshake, or the complaint.
pub fn parse_window(name: &str) -> Result<WindowKind, String> {
    match name {
        "any" => Ok(WindowKind::Any),
        "convex" => Ok(WindowKind::Convex),
        "rectangle" => Ok(WindowKind::Rectangle),
        _ => Err(format!("unknown window kind '{name}' (known: any, convex, rectangle)")),
    }
}

/// Whether polygon output is bridged, from its declared form, or the complaint.
pub fn parse_output(name: &str) -> Result<bool, String> {
    match name {
        "conventional" => Ok(false),
        "bridged" => Ok(true),
        _ => Err(format!("unknown output form '{name}' (known: conventional, bridged)")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coordinates_cross_the_wire_exactly() {
        let awkward = [0.1 + 0.2, 1.0 / 3.0, -2.5e-300, 1.0e150, f64::MIN_POSITIVE, 123_456_789.123_456_78];
        let ring = Ring::new(awkward.windows(2).map(|w| Point::new(w[0], w[1])).collect());
        let p = Polygons::new(vec![ring]);
        let text = serde_json::to_string(&to_wire(&p)).unwrap();
        let back: Vec<WireRing> = serde_json::from_str(&text).unwrap();
        assert_eq!(from_wire(&back), p);
    }

    #[test]
    fn handshakes_refuse_unknown_keys_and_names() {
        let good = r#"{"protocol":1,"name":"x","polygon":{"ops":["union"],"fill_rules":["even-odd"],"window":"any"}}"#;
        let h: Handshake = serde_json::from_str(good).unwrap();
        assert_eq!(h.polygon.unwrap().output, "conventional");
        let extra = r#"{"protocol":1,"name":"x","curves":true}"#;
        assert!(serde_json::from_str::<Handshake>(extra).unwrap_err().to_string().contains("curves"));
        assert!(parse_op("and").unwrap_err().contains("'and'"));
        assert_eq!(parse_fill("non-zero"), Ok(FillRule::NonZero));
        assert!(parse_window("round").is_err());
        assert!(parse_output("trapezoids").is_err());
    }

    #[test]
    fn replies_take_exactly_the_documented_fields() {
        let r: Reply = serde_json::from_str(r#"{"id":3,"rings":[],"time_ns":120}"#).unwrap();
        assert_eq!((r.id, r.rings.map(|v| v.len()), r.time_ns), (3, Some(0), Some(120.0)));
        assert!(serde_json::from_str::<Reply>(r#"{"id":3,"ring":[]}"#).is_err());
        assert!(serde_json::from_str::<Reply>(r#"{"rings":[]}"#).is_err());
    }
}
