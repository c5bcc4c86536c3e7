//! An external clipper for clipbench, protocol version 1 (docs/PROTOCOL.md in the clipbench
//! repository): it reads one JSON request per line on stdin and writes one JSON reply per line
//! on stdout. To test your own clipper, copy this crate, change [`HANDSHAKE_NAME`] and the
//! capabilities in [`handshake`], and replace the body of [`clip`] with a call to your clipper.
//!
//! The clipper wrapped here is geo-booleanop 0.3 (F. Martínez, A. J. Rueda and F. R. Feito, "A
//! new algorithm for computing Boolean operations on polygons", Computers & Geosciences 35(6),
//! 2009), which clipbench does not otherwise register. It reads each operand's rings by parity,
//! so it declares the even-odd fill rule alone. Its limits are its own: it may panic on
//! degenerate input, which this adapter turns into an error reply.

use std::io::{BufRead, Write};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::Instant;

use geo_booleanop::boolean::BooleanOp;
use geo_types::{Coordinate, LineString, MultiPolygon, Polygon};
use serde::{Deserialize, Serialize};
use serde_json::json;

/// The protocol version spoken.
const PROTOCOL_VERSION: u32 = 1;
/// How the clipper names itself in the handshake.
const HANDSHAKE_NAME: &str = "geo-booleanop 0.3 (Martinez-Rueda), clipbench rust example";

/// A point on the wire.
type WirePoint = [f64; 2];
/// A ring on the wire: its vertices, the closing one not repeated.
type WireRing = Vec<WirePoint>;

/// A request: a polygon operation, or (which this clipper does not declare) a line batch.
#[derive(Debug, Deserialize)]
struct Request {
    id: u64,
    op: Option<String>,
    fill: Option<String>,
    #[serde(default)]
    subject: Vec<WireRing>,
    #[serde(default)]
    clip: Vec<WireRing>,
}

/// A reply: the id, and rings or an error; optionally the clipper's own time.
#[derive(Debug, Serialize)]
struct Reply {
    id: u64,
    #[serde(skip_serializing_if = "Option::is_none")]
    rings: Option<Vec<WireRing>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    time_ns: Option<u64>,
}

/// The first line: who this is and what it can do.
fn handshake() -> serde_json::Value {
    json!({
        "protocol": PROTOCOL_VERSION,
        "name": HANDSHAKE_NAME,
        "polygon": {
            "ops": ["intersection", "union", "difference", "xor"],
            "fill_rules": ["even-odd"],
            "window": "any",
            "output": "conventional",
        },
    })
}

/// Each ring as the exterior of its own polygon, so the library sees every ring as given.
fn to_geo(rings: &[WireRing]) -> MultiPolygon<f64> {
    MultiPolygon(
        rings
            .iter()
            .map(|r| {
                let mut coords: Vec<Coordinate<f64>> = r.iter().map(|&[x, y]| Coordinate { x, y }).collect();
                coords.extend(coords.first().copied());
                Polygon::new(LineString(coords), Vec::new())
            })
            .collect(),
    )
}

/// A ring without its closing vertex, turned counter-clockwise (outer) or clockwise (hole).
fn from_geo(ring: &LineString<f64>, counter_clockwise: bool) -> Option<WireRing> {
    let mut points: WireRing = ring.0.iter().map(|c| [c.x, c.y]).collect();
    if points.len() > 1 && points.first() == points.last() {
        points.pop();
    }
    if points.len() < 3 {
        return None;
    }
    let twice_area: f64 = (0..points.len())
        .map(|i| {
            let (p, q) = (points[i], points[(i + 1) % points.len()]);
            p[0] * q[1] - q[0] * p[1]
        })
        .sum();
    if (twice_area > 0.0) != counter_clockwise {
        points.reverse();
    }
    Some(points)
}

/// The clip itself: replace this body with a call to your own clipper. The harness sends only
/// what the handshake declares (here: the four operations under even-odd), and valid input
/// (finite coordinates, rings of at least three distinct points).
fn clip(op: &str, subject: &[WireRing], clip: &[WireRing]) -> Result<Vec<WireRing>, String> {
    let (a, b) = (to_geo(subject), to_geo(clip));
    let result = match op {
        "intersection" => a.intersection(&b),
        "union" => a.union(&b),
        "difference" => a.difference(&b),
        "xor" => a.xor(&b),
        other => return Err(format!("unknown operation '{other}'")),
    };
    let mut rings = Vec::new();
    for polygon in &result.0 {
        rings.extend(from_geo(polygon.exterior(), true));
        rings.extend(polygon.interiors().iter().filter_map(|hole| from_geo(hole, false)));
    }
    Ok(rings)
}

/// Answers one request line; a panic inside the clipper becomes an error reply.
fn answer(line: &str) -> Result<Reply, String> {
    let request: Request = serde_json::from_str(line).map_err(|e| format!("not a request: {e}"))?;
    let mut reply = Reply { id: request.id, rings: None, error: None, time_ns: None };
    let (Some(op), Some(fill)) = (request.op.as_deref(), request.fill.as_deref()) else {
        reply.error = Some("this clipper does polygon requests only".into());
        return Ok(reply);
    };
    if fill != "even-odd" {
        reply.error = Some(format!("fill rule '{fill}' is not supported (even-odd only)"));
        return Ok(reply);
    }
    let start = Instant::now();
    let result = catch_unwind(AssertUnwindSafe(|| clip(op, &request.subject, &request.clip)));
    reply.time_ns = Some(u64::try_from(start.elapsed().as_nanos()).unwrap_or(u64::MAX));
    match result {
        Ok(Ok(rings)) => reply.rings = Some(rings),
        Ok(Err(e)) => reply.error = Some(e),
        Err(panic) => {
            let message = panic
                .downcast_ref::<&str>()
                .map(|s| (*s).to_owned())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            reply.error = Some(format!("the clipper panicked: {message}"));
        }
    }
    Ok(reply)
}

fn main() {
    // Panics are answered as errors; keep their default report off stderr's useful lines.
    std::panic::set_hook(Box::new(|_| {}));
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let mut send = |text: String| writeln!(out, "{text}").and_then(|()| out.flush());
    if send(handshake().to_string()).is_err() {
        return;
    }
    for line in std::io::stdin().lock().lines() {
        let Ok(line) = line else { return };
        if line.trim().is_empty() {
            continue;
        }
        // A line that is not a request has no id to answer: say so on stderr and stop.
        let text = match answer(&line).and_then(|reply| serde_json::to_string(&reply).map_err(|e| e.to_string())) {
            Ok(text) => text,
            Err(e) => {
                eprintln!("clipbench-rust-example: {e}");
                return;
            }
        };
        if send(text).is_err() {
            return;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(x: f64, y: f64, size: f64) -> WireRing {
        vec![[x, y], [x + size, y], [x + size, y + size], [x, y + size]]
    }

    fn area(rings: &[WireRing]) -> f64 {
        rings
            .iter()
            .map(|r| {
                (0..r.len()).map(|i| r[i][0] * r[(i + 1) % r.len()][1] - r[(i + 1) % r.len()][0] * r[i][1]).sum::<f64>()
            })
            .sum::<f64>()
            / 2.0
    }

    #[test]
    fn every_op_on_overlapping_squares() {
        let (a, b) = (vec![square(0.0, 0.0, 2.0)], vec![square(1.0, 1.0, 2.0)]);
        for (op, expected) in [("intersection", 1.0), ("union", 7.0), ("difference", 3.0), ("xor", 6.0)] {
            assert_eq!(area(&clip(op, &a, &b).unwrap()), expected, "{op}");
        }
    }

    #[test]
    fn replies_carry_the_id_and_refuse_what_is_not_declared() {
        let r = answer(r#"{"id":7,"op":"union","fill":"non-zero","subject":[],"clip":[]}"#).unwrap();
        assert_eq!(r.id, 7);
        assert!(r.error.unwrap().contains("non-zero"));
        let r = answer(r#"{"id":8,"op":"union","fill":"even-odd","subject":[[[0,0],[1,0],[0,1]]],"clip":[]}"#).unwrap();
        assert_eq!((r.id, r.rings.map(|v| v.len())), (8, Some(1)));
        assert!(answer("garbage").is_err());
    }
}
