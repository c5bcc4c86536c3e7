//! An external clipper behind clip-core's traits: a pool of its processes (one per worker thread
//! that calls it), each request answered by one of them; a process that fails is dropped and a
//! fresh one started for the next call.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use clip_core::{
    BoolOp, ClipError, FillRule, LineCapabilities, LineClipper, Operand, Point, PolygonCapabilities, PolygonClipper,
    Polygons, PreparedWindow, Segment, VisiblePiece, validate_polygons, validate_segments, validate_window,
};

use super::process::{Worker, clipped};
use super::protocol::{Handshake, LineRequest, PolygonRequest, Reply, WireRing, from_wire, segments_to_wire, to_wire};
use super::spec::ExternalSpec;
use crate::measure::own_time::OwnTime;

/// The processes of one external clipper.
pub struct Pool {
    name: &'static str,
    spec: ExternalSpec,
    handshake: Handshake,
    timeout: Duration,
    idle: Mutex<Vec<Worker>>,
    next_id: AtomicU64,
    /// Own times reported in replies.
    pub own_time: Arc<OwnTime>,
}

impl Pool {
    /// A pool holding the process that gave `handshake`.
    pub fn new(name: &'static str, spec: ExternalSpec, first: Worker, handshake: Handshake, timeout: Duration) -> Pool {
        Pool {
            name,
            spec,
            handshake,
            timeout,
            idle: Mutex::new(vec![first]),
            next_id: AtomicU64::new(1),
            own_time: Arc::new(OwnTime::default()),
        }
    }

    fn failed(&self, reason: String) -> ClipError {
        ClipError::Failed { clipper: self.name, reason }
    }

    /// Sends the request `make(id)` to an idle process (starting one if none is idle) and
    /// returns its reply when that is well-formed and answers `id`. A process that fails is
    /// dropped, which kills it; the error says how it failed.
    fn call(&self, make: impl FnOnce(u64) -> Result<String, serde_json::Error>) -> Result<Reply, ClipError> {
        let id = self.next_id.fetch_add(1, Ordering::Relaxed);
        let request = make(id).map_err(|e| self.failed(format!("the request could not be written as JSON: {e}")))?;
        let idle = self.idle.lock().ok().and_then(|mut v| v.pop());
        let mut worker = match idle {
            Some(w) => w,
            None => self.restart()?,
        };
        let text = worker.exchange(&request, self.timeout).map_err(|e| self.failed(e))?;
        let reply: Reply = serde_json::from_str(&text)
            .map_err(|e| self.failed(format!("it answered something that is not a reply ({e}): {}", clipped(&text))))?;
        if reply.id != id {
            return Err(self.failed(format!("it answered id {} to request {id}", reply.id)));
        }
        let parts = usize::from(reply.rings.is_some())
            + usize::from(reply.pieces.is_some())
            + usize::from(reply.error.is_some());
        if parts != 1 {
            return Err(self
                .failed(format!("reply {id} must carry exactly one of rings, pieces and error: {}", clipped(&text))));
        }
        if let Ok(mut idle) = self.idle.lock() {
            idle.push(worker);
        }
        self.own_time.record(reply.time_ns);
        Ok(reply)
    }

    fn restart(&self) -> Result<Worker, ClipError> {
        let (worker, handshake) =
            Worker::start(&self.spec, self.timeout).map_err(|e| self.failed(format!("restarting it: {e}")))?;
        if handshake != self.handshake {
            return Err(self.failed("restarted, it declared a different handshake than at the start".into()));
        }
        Ok(worker)
    }
}

/// An external polygon clipper.
pub struct ExternalPolygon {
    /// Its processes.
    pub pool: Arc<Pool>,
    /// What its handshake declared.
    pub capabilities: PolygonCapabilities,
}

impl PolygonClipper for ExternalPolygon {
    fn name(&self) -> &'static str {
        self.pool.name
    }

    fn capabilities(&self) -> PolygonCapabilities {
        self.capabilities
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        self.capabilities.check(self.pool.name, op, fill)?;
        validate_polygons(subject, Operand::Subject)?;
        validate_polygons(clip, Operand::Clip)?;
        if !self.capabilities.window.accepts(clip) {
            return Err(ClipError::Unsupported {
                clipper: self.pool.name,
                what: format!("this clip operand (it takes {:?} windows only)", self.capabilities.window),
            });
        }
        let reply = self.pool.call(|id| {
            serde_json::to_string(&PolygonRequest {
                id,
                op: op.name(),
                fill: fill.name(),
                subject: to_wire(subject),
                clip: to_wire(clip),
            })
        })?;
        match (reply.rings, reply.error, reply.pieces) {
            (Some(rings), _, _) => Ok(from_wire(&rings)),
            (_, Some(error), _) => Err(self.pool.failed(format!("it answered with an error: {error}"))),
            _ => Err(self.pool.failed(format!("reply {} carries pieces, not rings", reply.id))),
        }
    }
}

/// An external line clipper.
pub struct ExternalLine {
    /// Its processes.
    pub pool: Arc<Pool>,
    /// What its handshake declared.
    pub capabilities: LineCapabilities,
}

impl LineClipper for ExternalLine {
    fn name(&self) -> &'static str {
        self.pool.name
    }

    fn capabilities(&self) -> LineCapabilities {
        self.capabilities
    }

    fn prepare(&self, window: &Polygons) -> Result<Box<dyn PreparedWindow>, ClipError> {
        validate_window(window)?;
        if !self.capabilities.window.accepts(window) {
            return Err(ClipError::Unsupported {
                clipper: self.pool.name,
                what: format!("this window (it takes {:?} windows only)", self.capabilities.window),
            });
        }
        Ok(Box::new(ExternalWindow { pool: Arc::clone(&self.pool), window: to_wire(window) }))
    }
}

/// A window kept as wire rings; every batch sends it along.
struct ExternalWindow {
    pool: Arc<Pool>,
    window: Vec<WireRing>,
}

impl PreparedWindow for ExternalWindow {
    fn clip_batch(&self, segments: &[Segment], out: &mut Vec<VisiblePiece>) -> Result<(), ClipError> {
        validate_segments(segments)?;
        let reply = self.pool.call(|id| {
            serde_json::to_string(&LineRequest {
                id,
                window: self.window.clone(),
                segments: segments_to_wire(segments),
            })
        })?;
        match (reply.pieces, reply.error) {
            (Some(pieces), _) => {
                out.extend(pieces.iter().map(|p| VisiblePiece {
                    segment: p.segment,
                    piece: Segment::new(Point::new(p.from[0], p.from[1]), Point::new(p.to[0], p.to[1])),
                }));
                Ok(())
            }
            (_, Some(error)) => Err(self.pool.failed(format!("it answered with an error: {error}"))),
            _ => Err(self.pool.failed(format!("reply {} carries rings, not pieces", reply.id))),
        }
    }
}
