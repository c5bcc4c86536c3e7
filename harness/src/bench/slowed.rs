//! Test only: the environment variable [`VARIABLE`] (`NAME:MICROSECONDS`) makes one clipper wait
//! that long before every call, so `compare`'s test can time a regression it knows is there. The
//! name says it is for tests; when set, bench warns on standard error and records it in
//! bench.meta.json, so a slowed run cannot pass for a real one.

use std::time::Duration;

use clip_core::{BoolOp, ClipError, FillRule, PolygonCapabilities, PolygonClipper, Polygons, Trapezoid};

use crate::cli_error::CliError;
use crate::registry::Registry;

/// The variable's name.
pub const VARIABLE: &str = "CLIPBENCH_TEST_ONLY_SLOW_CLIPPER";

/// A clipper that waits before each call.
struct Slowed {
    inner: Box<dyn PolygonClipper>,
    delay: Duration,
}

impl PolygonClipper for Slowed {
    fn name(&self) -> &'static str {
        self.inner.name()
    }

    fn capabilities(&self) -> PolygonCapabilities {
        self.inner.capabilities()
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        std::thread::sleep(self.delay);
        self.inner.clip(subject, clip, op, fill)
    }

    fn clip_trapezoids(
        &self,
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
    ) -> Result<Vec<Trapezoid>, ClipError> {
        std::thread::sleep(self.delay);
        self.inner.clip_trapezoids(subject, clip, op, fill)
    }
}

/// Slows the clipper [`VARIABLE`] names, if it is set; the note for the sidecar when it did.
pub fn apply(registry: &mut Registry) -> Result<Option<String>, CliError> {
    let Some(value) = std::env::var_os(VARIABLE) else { return Ok(None) };
    let value = value.to_string_lossy().into_owned();
    let bad = |why: &str| CliError::usage(format!("{VARIABLE}={value}: {why} (expected NAME:MICROSECONDS)"));
    let (name, micros) = value.split_once(':').ok_or_else(|| bad("no ':'"))?;
    let micros: u64 = micros.parse().map_err(|_| bad("the delay is not a whole number of microseconds"))?;
    let at = registry.polygon.iter().position(|e| e.clipper.name() == name).ok_or_else(|| bad("no such clipper"))?;
    let mut entry = registry.polygon.remove(at);
    entry.clipper = Box::new(Slowed { inner: entry.clipper, delay: Duration::from_micros(micros) });
    registry.polygon.insert(at, entry);
    let note =
        format!("TEST ONLY: {VARIABLE} slowed {name} by {micros} µs per call; these times are not the clipper's own.");
    eprintln!("clipbench: warning: {note}");
    Ok(Some(note))
}
