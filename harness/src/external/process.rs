//! One running external clipper process: start, handshake, one request and its reply within a
//! time limit. Any failure leaves the process unusable; its owner drops it (which kills it).

use std::collections::VecDeque;
use std::io::{BufRead, BufReader, Read, Write};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError};
use std::sync::{Arc, Mutex};
use std::thread;
use std::time::{Duration, Instant};

use clip_core::FailureKind;

use super::protocol::Handshake;
use super::spec::ExternalSpec;

/// Longest line accepted from a clipper (a result of millions of vertices fits).
const MAX_LINE_BYTES: u64 = 1 << 30;
/// Lines of the clipper's standard error kept to quote when it fails.
const STDERR_LINES: usize = 12;
/// Characters kept of each such line.
const STDERR_LINE_CHARS: usize = 300;
/// How long a process that closed its output gets to exit before it is killed.
const EXIT_GRACE: Duration = Duration::from_millis(500);

/// A running clipper process.
pub struct Worker {
    child: Child,
    stdin: Option<ChildStdin>,
    lines: Receiver<Result<String, (FailureKind, String)>>,
    stderr: Arc<Mutex<VecDeque<String>>>,
}

impl Worker {
    /// Starts the command and reads its handshake line; the error says what went wrong in the
    /// clipper's own words where it gave any.
    pub fn start(spec: &ExternalSpec, timeout: Duration) -> Result<(Worker, Handshake), String> {
        Worker::started(spec, timeout).map_err(|(_, why)| why)
    }

    /// [`Worker::start`], the error with how the process failed.
    pub fn started(spec: &ExternalSpec, timeout: Duration) -> Result<(Worker, Handshake), (FailureKind, String)> {
        let mut command = Command::new(&spec.command[0]);
        command.args(&spec.command[1..]).stdin(Stdio::piped()).stdout(Stdio::piped()).stderr(Stdio::piped());
        if let Some(dir) = &spec.dir {
            command.current_dir(dir);
        }
        let mut child = command
            .spawn()
            .map_err(|e| (FailureKind::Crashed, format!("cannot start {}: {e}", super::spec::shown(&spec.command))))?;
        let (Some(stdin), Some(stdout), Some(stderr)) = (child.stdin.take(), child.stdout.take(), child.stderr.take())
        else {
            let _ = child.kill();
            return Err((FailureKind::Crashed, "its standard streams could not be connected".into()));
        };
        let mut worker = Worker { child, stdin: Some(stdin), lines: read_lines(stdout), stderr: keep_tail(stderr) };
        let line = worker.next_line(timeout).map_err(|(kind, e)| (kind, format!("at the handshake, {e}")))?;
        let handshake: Handshake = serde_json::from_str(&line).map_err(|e| {
            let why =
                format!("its handshake is not a protocol handshake ({e}): {}{}", clipped(&line), worker.stderr_words());
            (FailureKind::Garbled, why)
        })?;
        Ok((worker, handshake))
    }

    /// Sends one request line and returns the next line the clipper writes; the error says how
    /// the process failed.
    pub fn exchange(&mut self, request: &str, timeout: Duration) -> Result<String, (FailureKind, String)> {
        let sent = match self.stdin.as_mut() {
            Some(stdin) => {
                stdin.write_all(request.as_bytes()).and_then(|()| stdin.write_all(b"\n")).and_then(|()| stdin.flush())
            }
            None => return Err((FailureKind::Crashed, "its input is closed".into())),
        };
        if let Err(e) = sent {
            // It died before reading: say how, from its exit.
            return Err((FailureKind::Crashed, format!("the request could not be written ({e}); {}", self.death())));
        }
        self.next_line(timeout)
    }

    /// The next line of output, within `timeout`.
    fn next_line(&mut self, timeout: Duration) -> Result<String, (FailureKind, String)> {
        match self.lines.recv_timeout(timeout) {
            Ok(Ok(line)) => Ok(line),
            Ok(Err((kind, problem))) => Err((kind, format!("{problem}; {}", self.death()))),
            Err(RecvTimeoutError::Disconnected) => Err((FailureKind::Crashed, self.death())),
            Err(RecvTimeoutError::Timeout) => {
                let _ = self.child.kill();
                let _ = self.child.wait();
                let why = format!("no answer within {:.1} s (killed){}", timeout.as_secs_f64(), self.stderr_words());
                Err((FailureKind::Hung, why))
            }
        }
    }

    /// Its process id.
    pub fn pid(&self) -> u32 {
        self.child.id()
    }

    /// Ends the process now, without the grace a well-behaved one gets at the end of a run: it
    /// failed, and its replacement is wanted.
    pub fn kill(mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
        self.stdin = None;
    }

    /// How the process ended (waiting briefly, then killing it), with its last words on stderr.
    fn death(&mut self) -> String {
        let deadline = Instant::now() + EXIT_GRACE;
        let status = loop {
            match self.child.try_wait() {
                Ok(Some(status)) => break format!("it exited ({status})"),
                Ok(None) if Instant::now() < deadline => thread::sleep(Duration::from_millis(10)),
                _ => {
                    let _ = self.child.kill();
                    let _ = self.child.wait();
                    break "it closed its output and was killed".to_owned();
                }
            }
        };
        // Give the stderr reader a moment to take the last lines.
        thread::sleep(Duration::from_millis(20));
        format!("{status}{}", self.stderr_words())
    }

    /// `; stderr: ...` with the last lines it wrote there, or nothing.
    fn stderr_words(&self) -> String {
        let tail = self.stderr.lock().map(|t| t.iter().cloned().collect::<Vec<_>>().join(" | ")).unwrap_or_default();
        if tail.is_empty() { String::new() } else { format!("; its stderr: {tail}") }
    }
}

impl Drop for Worker {
    /// Closes its input (a well-behaved clipper exits on end of input) and reaps it, killing it
    /// if it does not exit within a moment.
    fn drop(&mut self) {
        self.stdin = None;
        let deadline = Instant::now() + EXIT_GRACE;
        while Instant::now() < deadline {
            if let Ok(Some(_)) = self.child.try_wait() {
                return;
            }
            thread::sleep(Duration::from_millis(5));
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// A thread reading stdout line by line into a channel; an error (end of output, an over-long
/// line, bytes that are not UTF-8) is sent once and ends it.
fn read_lines(stdout: impl Read + Send + 'static) -> Receiver<Result<String, (FailureKind, String)>> {
    let (send, receive) = mpsc::channel();
    thread::spawn(move || {
        let mut reader = BufReader::new(stdout);
        loop {
            let mut buf = Vec::new();
            let read = (&mut reader).take(MAX_LINE_BYTES + 1).read_until(b'\n', &mut buf);
            let item = match read {
                Ok(0) => Err((FailureKind::Crashed, "it closed its output".to_owned())),
                Ok(_) if buf.last() != Some(&b'\n') && buf.len() as u64 > MAX_LINE_BYTES => {
                    Err((FailureKind::Garbled, format!("it wrote a line longer than {MAX_LINE_BYTES} bytes")))
                }
                Ok(_) => String::from_utf8(buf)
                    .map(|s| s.trim_end_matches(['\n', '\r']).to_owned())
                    .map_err(|_| (FailureKind::Garbled, "it wrote bytes that are not UTF-8".to_owned())),
                Err(e) => Err((FailureKind::Crashed, format!("its output could not be read ({e})"))),
            };
            let last = item.is_err();
            if send.send(item).is_err() || last {
                return;
            }
        }
    });
    receive
}

/// A thread keeping the last lines of stderr.
fn keep_tail(stderr: impl Read + Send + 'static) -> Arc<Mutex<VecDeque<String>>> {
    let tail = Arc::new(Mutex::new(VecDeque::new()));
    let kept = Arc::clone(&tail);
    thread::spawn(move || {
        for line in BufReader::new(stderr).lines() {
            let Ok(line) = line else { return };
            let line: String = line.chars().take(STDERR_LINE_CHARS).collect();
            if line.trim().is_empty() {
                continue;
            }
            if let Ok(mut t) = kept.lock() {
                if t.len() == STDERR_LINES {
                    t.pop_front();
                }
                t.push_back(line);
            }
        }
    });
    tail
}

/// The start of a line, for messages.
pub fn clipped(line: &str) -> String {
    const SHOWN: usize = 120;
    if line.chars().count() <= SHOWN {
        format!("'{line}'")
    } else {
        format!("'{}...' ({} bytes)", line.chars().take(SHOWN).collect::<String>(), line.len())
    }
}
