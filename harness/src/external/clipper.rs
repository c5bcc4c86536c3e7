//! An external clipper behind clip-core's traits: a pool of its processes (one per worker thread
//! that calls it), each request answered by one of them; a process that fails is killed and its
//! replacement started at once, in the background, while the run goes on.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Condvar, Mutex};
use std::thread;
use std::time::{Duration, Instant};

use clip_core::{
    BoolOp, ClipError, FailureKind, FillRule, LineCapabilities, LineClipper, Operand, Point, PolygonCapabilities,
    PolygonClipper, Polygons, PreparedWindow, Segment, VisiblePiece, validate_polygons, validate_segments,
    validate_window,
};

use super::process::{Worker, clipped};
use super::protocol::{
    Handshake, LineRequest, PolygonRequest, Reply, Violation, WireRing, from_wire, segments_to_wire, to_wire,
};
use super::spec::ExternalSpec;
use crate::measure::own_time::OwnTime;
use crate::measure::peak_memory::{OwnProcessMemory, PeakMemory};

/// The processes of one external clipper.
pub struct Pool {
    name: &'static str,
    spec: ExternalSpec,
    handshake: Handshake,
    timeout: Duration,
    workers: Mutex<Workers>,
    /// Signalled when a process is put back idle or a start ends.
    changed: Condvar,
    next_id: AtomicU64,
    /// Own times reported in replies.
    pub own_time: Arc<OwnTime>,
}

/// The idle processes, and how many are being started.
#[derive(Default)]
struct Workers {
    idle: Vec<Worker>,
    starting: usize,
}

impl Pool {
    /// A pool holding the process that gave `handshake`.
    pub fn new(name: &'static str, spec: ExternalSpec, first: Worker, handshake: Handshake, timeout: Duration) -> Pool {
        Pool {
            name,
            spec,
            handshake,
            timeout,
            workers: Mutex::new(Workers { idle: vec![first], starting: 0 }),
            changed: Condvar::new(),
            next_id: AtomicU64::new(1),
            own_time: Arc::new(OwnTime::default()),
        }
    }

    fn failed(&self, kind: FailureKind, reason: String) -> ClipError {
        ClipError::Failed { clipper: self.name, kind, reason }
    }

    /// Sends the request `make(id)` to an idle process (waiting for one being started, or
    /// starting one if none is) and returns its reply when that is well-formed, answers `id` and
    /// reports a possible time. A process that fails is killed and a replacement started in the
    /// background, so the run goes on meanwhile; the error says how it failed.
    fn call(self: &Arc<Self>, make: impl FnOnce(u64) -> Result<String, serde_json::Error>) -> Result<Reply, ClipError> {
        let (id, request) = self.numbered(make)?;
        let mut worker = self.take()?;
        let sent = Instant::now();
        let text = match worker.exchange(&request, self.timeout) {
            Ok(text) => text,
            Err((kind, why)) => {
                self.replace(worker);
                return Err(self.failed(kind, why));
            }
        };
        let round_trip = sent.elapsed();
        let reply = match checked_reply(&text, id, round_trip) {
            Ok(reply) => reply,
            Err(violation) => {
                // A reply that is read but says something impossible leaves the stream in step.
                if violation.stream_in_step() {
                    self.put_back(worker);
                } else {
                    self.replace(worker);
                }
                return Err(self.failed(FailureKind::Garbled, violation.to_string()));
            }
        };
        self.put_back(worker);
        self.own_time.record(reply.time_ns);
        Ok(reply)
    }

    /// An idle process: one put back, one being started in the background once it is ready, or
    /// else one started here.
    fn take(&self) -> Result<Worker, ClipError> {
        let mut workers = self.lock();
        loop {
            if let Some(w) = workers.idle.pop() {
                return Ok(w);
            }
            if workers.starting == 0 {
                break;
            }
            workers = match self.changed.wait(workers) {
                Ok(w) => w,
                Err(poisoned) => poisoned.into_inner(),
            };
        }
        workers.starting += 1;
        drop(workers);
        let started = self.start();
        self.lock().starting -= 1;
        self.changed.notify_all();
        started
    }

    /// The next request id and the request `make` writes for it.
    fn numbered(
        &self,
        make: impl FnOnce(u64) -> Result<String, serde_json::Error>,
    ) -> Result<(u64, String), ClipError> {
        let id = self.next_id.fetch_add(1, Ordering::Relaxed);
        let request = make(id).map_err(|e| {
            self.failed(FailureKind::Internal, format!("the request could not be written as JSON: {e}"))
        })?;
        Ok((id, request))
    }

    /// [`Pool::call`] in a process started for it and ended after it, with that process's
    /// resident size before the call and peak above it, in KiB: a fresh process, so that memory
    /// kept from earlier calls does not hide the peak. A failure leaves the pool as it was.
    fn call_in_fresh_process(
        &self,
        make: impl FnOnce(u64) -> Result<String, serde_json::Error>,
    ) -> Result<(Reply, (u64, u64)), ClipError> {
        let (id, request) = self.numbered(make)?;
        let mut worker = self.start()?;
        let unavailable = || self.failed(FailureKind::Internal, "its peak memory cannot be read here".into());
        let peak = PeakMemory::of_process(worker.pid()).ok_or_else(unavailable)?;
        let sent = Instant::now();
        let text = worker.exchange(&request, self.timeout).map_err(|(kind, why)| self.failed(kind, why))?;
        let round_trip = sent.elapsed();
        // Read before the process is let go: its counters go with it.
        let extra = peak.extra_kib().ok_or_else(unavailable)?;
        let reply =
            checked_reply(&text, id, round_trip).map_err(|v| self.failed(FailureKind::Garbled, v.to_string()))?;
        Ok((reply, (peak.rss_before_kib(), extra)))
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Workers> {
        self.workers.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
    }

    fn put_back(&self, worker: Worker) {
        self.lock().idle.push(worker);
        self.changed.notify_all();
    }

    /// Kills a process that failed and starts its replacement on another thread: only the
    /// process that failed is replaced, and the calls of the run go on while it starts.
    fn replace(self: &Arc<Self>, failed: Worker) {
        self.lock().starting += 1;
        let pool = Arc::clone(self);
        thread::spawn(move || {
            failed.kill();
            let started = pool.start();
            let mut workers = pool.lock();
            workers.starting -= 1;
            // A start that fails here is tried again by the next call, which reports it.
            if let Ok(w) = started {
                workers.idle.push(w);
            }
            drop(workers);
            pool.changed.notify_all();
        });
    }

    fn start(&self) -> Result<Worker, ClipError> {
        let (worker, handshake) = Worker::started(&self.spec, self.timeout)
            .map_err(|(kind, e)| self.failed(kind, format!("restarting it: {e}")))?;
        if handshake != self.handshake {
            return Err(self.failed(
                FailureKind::Garbled,
                "restarted, it declared a different handshake than at the start".into(),
            ));
        }
        Ok(worker)
    }

    /// Waits until no process is being started and returns how many are idle (tests watch the
    /// replacement of a failed process with it).
    #[cfg(test)]
    fn settled_idle(&self) -> usize {
        let mut workers = self.lock();
        while workers.starting > 0 {
            workers = match self.changed.wait(workers) {
                Ok(w) => w,
                Err(poisoned) => poisoned.into_inner(),
            };
        }
        workers.idle.len()
    }
}

/// The reply `text` to request `id`, checked: a reply (JSON with the documented fields), to `id`,
/// carrying exactly one result, and a time, if any, that fits in the `round_trip` it was part of.
fn checked_reply(text: &str, id: u64, round_trip: Duration) -> Result<Reply, Violation> {
    let reply: Reply =
        serde_json::from_str(text).map_err(|e| Violation::NotAReply { problem: e.to_string(), line: clipped(text) })?;
    if reply.id != id {
        return Err(Violation::WrongId { answered: reply.id, asked: id });
    }
    let parts =
        usize::from(reply.rings.is_some()) + usize::from(reply.pieces.is_some()) + usize::from(reply.error.is_some());
    if parts != 1 {
        return Err(Violation::NotOneResult { id, line: clipped(text) });
    }
    if let Some(ns) = reply.time_ns {
        let limit = round_trip.as_nanos() as f64;
        if !(ns.is_finite() && ns >= 0.0 && ns <= limit) {
            return Err(Violation::ImpossibleTime { id, time_ns: ns, round_trip_ns: limit });
        }
    }
    Ok(reply)
}

/// An external polygon clipper.
#[derive(Clone)]
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
        self.admit(subject, clip, op, fill)?;
        let reply = self.pool.call(|id| polygon_request(id, subject, clip, op, fill))?;
        self.rings(reply)
    }
}

impl ExternalPolygon {
    /// The checks every call passes before it is sent: what the handshake declared, and valid
    /// operands.
    fn admit(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<(), ClipError> {
        self.capabilities.check(self.pool.name, op, fill)?;
        validate_polygons(subject, Operand::Subject)?;
        validate_polygons(clip, Operand::Clip)?;
        if !self.capabilities.window.accepts(clip) {
            return Err(ClipError::Unsupported {
                clipper: self.pool.name,
                what: format!("this clip operand (it takes {:?} windows only)", self.capabilities.window),
            });
        }
        Ok(())
    }

    /// The result a reply carries, or the failure it says.
    fn rings(&self, reply: Reply) -> Result<Polygons, ClipError> {
        match (reply.rings, reply.error, reply.pieces) {
            (Some(rings), _, _) => Ok(from_wire(&rings)),
            (_, Some(error), _) => {
                Err(self.pool.failed(FailureKind::Declined, format!("it answered with an error: {error}")))
            }
            _ => Err(self.pool.failed(FailureKind::Garbled, format!("reply {} carries pieces, not rings", reply.id))),
        }
    }
}

/// A polygon request as its JSON line.
fn polygon_request(
    id: u64,
    subject: &Polygons,
    clip: &Polygons,
    op: BoolOp,
    fill: FillRule,
) -> Result<String, serde_json::Error> {
    serde_json::to_string(&PolygonRequest {
        id,
        op: op.name(),
        fill: fill.name(),
        subject: to_wire(subject),
        clip: to_wire(clip),
    })
}

/// The process's peak includes reading the request and writing the answer, and whatever its
/// runtime (a JavaScript or Java heap) takes on its own: an upper bound on the library's need.
impl OwnProcessMemory for ExternalPolygon {
    fn peak_of_call(
        &self,
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
    ) -> Result<(u64, u64), String> {
        self.admit(subject, clip, op, fill).map_err(|e| e.to_string())?;
        let (reply, peak) = self
            .pool
            .call_in_fresh_process(|id| polygon_request(id, subject, clip, op, fill))
            .map_err(|e| e.to_string())?;
        self.rings(reply).map_err(|e| e.to_string())?;
        Ok(peak)
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
            (_, Some(error)) => {
                Err(self.pool.failed(FailureKind::Declined, format!("it answered with an error: {error}")))
            }
            _ => Err(self.pool.failed(FailureKind::Garbled, format!("reply {} carries rings, not pieces", reply.id))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::Rect;

    /// The broken test clipper (harness/tests/broken_clipper.py) with a state file of its own.
    fn broken(name: &str, faults: &str) -> ExternalSpec {
        let dir = std::env::temp_dir().join(format!("clipbench-pool-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/broken_clipper.py");
        let mut command = vec!["python3".to_owned(), script.to_owned(), dir.join("requests").display().to_string()];
        command.extend(faults.split(' ').map(str::to_owned));
        ExternalSpec { name: "broken".into(), command, dir: None, file: None, library: None, language: None }
    }

    /// A pool of the clipper `spec` with its first process started.
    fn started(spec: ExternalSpec, timeout: Duration) -> Arc<Pool> {
        let (first, handshake) = Worker::start(&spec, timeout).unwrap();
        Arc::new(Pool::new("broken", spec, first, handshake, timeout))
    }

    fn request(id: u64) -> Result<String, serde_json::Error> {
        let square = to_wire(&Polygons::from(Rect::new(0.0, 0.0, 2.0, 2.0)));
        serde_json::to_string(&PolygonRequest {
            id,
            op: "intersection",
            fill: "even-odd",
            subject: square.clone(),
            clip: square,
        })
    }

    /// A call that timed out cost its time limit plus a restart and handshake, paid by the next
    /// call (issue 28): the hung process is killed and its replacement started at once, on
    /// another thread, while the run goes on; only that process is replaced.
    #[test]
    fn a_hung_process_is_replaced_before_the_next_call_asks_for_one() {
        // Long enough for Python to start and shake hands on a loaded machine.
        let pool = started(broken("hang", "0 1 0 0"), Duration::from_secs(5));
        let Err(ClipError::Failed { kind, reason, .. }) = pool.call(request) else { panic!("request 1 hangs") };
        assert_eq!(kind, FailureKind::Hung, "{reason}");
        // No call has asked for a process since; one is ready all the same, and only one.
        assert_eq!(pool.settled_idle(), 1);
        let reply = pool.call(request).expect("the replacement answers");
        assert_eq!(reply.rings.map(|r| r.len()), Some(1));
        assert_eq!(pool.settled_idle(), 1);
    }

    /// An answer with an error keeps its process, as does an impossible time: the stream is in step.
    #[test]
    fn an_impossible_time_fails_the_call_and_keeps_the_process() {
        let pool = started(broken("time", "0 0 0 0 1"), Duration::from_secs(20));
        let Err(ClipError::Failed { kind, reason, .. }) = pool.call(request) else { panic!("request 1 lies") };
        assert_eq!(kind, FailureKind::Garbled);
        assert!(reason.contains("time_ns -5"), "{reason}");
        assert_eq!(pool.settled_idle(), 1);
        assert!(pool.call(request).is_ok());
    }

    /// The peak memory of a call is read in a process started for it, which then goes: the
    /// pool's own process is neither used nor replaced.
    #[test]
    fn a_call_in_a_fresh_process_reads_that_process_memory_and_leaves_the_pool_alone() {
        let pool = started(broken("memory", "0 0 0 0"), Duration::from_secs(20));
        let clipper = ExternalPolygon {
            pool: Arc::clone(&pool),
            capabilities: PolygonCapabilities::window_clipper(clip_core::WindowKind::Rectangle),
        };
        let square = Polygons::from(Rect::new(0.0, 0.0, 2.0, 2.0));
        match clipper.peak_of_call(&square, &square, BoolOp::Intersection, FillRule::EvenOdd) {
            // A Python process holds megabytes before the call.
            Ok((before, _extra)) => assert!(before > 1024, "{before} KiB"),
            Err(why) => assert!(why.contains("cannot be read here"), "{why}"),
        }
        assert_eq!(pool.settled_idle(), 1);
        assert_eq!(pool.next_id.load(Ordering::Relaxed), 2);
    }

    #[test]
    fn replies_are_checked_for_id_parts_and_a_possible_time() {
        let trip = Duration::from_millis(2);
        assert!(checked_reply(r#"{"id":4,"rings":[],"time_ns":1000}"#, 4, trip).is_ok());
        let bad = |text: &str| checked_reply(text, 4, trip).unwrap_err();
        assert!(matches!(bad(r#"{"id":5,"rings":[]}"#), Violation::WrongId { answered: 5, asked: 4 }));
        assert!(matches!(bad(r#"{"id":4,"rings":[],"error":"x"}"#), Violation::NotOneResult { .. }));
        assert!(matches!(bad("nope"), Violation::NotAReply { .. }));
        for time in ["-5", "3e6", "1e300"] {
            let v = bad(&format!(r#"{{"id":4,"rings":[],"time_ns":{time}}}"#));
            assert!(matches!(v, Violation::ImpossibleTime { .. }) && v.stream_in_step(), "{time}: {v}");
        }
    }
}
