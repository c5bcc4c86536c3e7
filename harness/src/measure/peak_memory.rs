//! Peak resident memory of one operation, from Linux's /proc (no unsafe code): of this process,
//! or of an external clipper's (a process of its own, started by this one).
//!
//! Writing "5" to /proc/PID/clear_refs resets the peak resident set size (VmHWM) to the current
//! one; after the operation, VmHWM minus the resident size before it is the operation's peak
//! extra memory. Elsewhere (or when /proc is read-only) [`PeakMemory::start`] returns `None`
//! and the result files say the figure is unavailable.

use clip_core::{BoolOp, FillRule, Polygons};

/// A peak-memory probe started just before an operation.
#[derive(Clone, Debug)]
pub struct PeakMemory {
    /// `/proc/self` or `/proc/PID`.
    process: String,
    rss_before_kib: u64,
}

/// A clipper that runs in a process of its own (an external one): its peak memory for one call is
/// that process's, read by [`PeakMemory::of_process`] in a process started for the call.
pub trait OwnProcessMemory: Send + Sync {
    /// (resident KiB before the call, peak KiB above it), or why it could not be measured.
    fn peak_of_call(
        &self,
        subject: &Polygons,
        clip: &Polygons,
        op: BoolOp,
        fill: FillRule,
    ) -> Result<(u64, u64), String>;
}

impl PeakMemory {
    /// Resets this process's peak counter; `None` when that is not possible here.
    pub fn start() -> Option<PeakMemory> {
        PeakMemory::reset("/proc/self".to_owned())
    }

    /// Resets the peak counter of process `pid` (one this process started); `None` when that is
    /// not possible here.
    pub fn of_process(pid: u32) -> Option<PeakMemory> {
        PeakMemory::reset(format!("/proc/{pid}"))
    }

    fn reset(process: String) -> Option<PeakMemory> {
        std::fs::write(format!("{process}/clear_refs"), b"5").ok()?;
        let rss_before_kib = status_kib(&process, "VmRSS")?;
        Some(PeakMemory { process, rss_before_kib })
    }

    /// Resident size when the probe started, in KiB.
    pub fn rss_before_kib(&self) -> u64 {
        self.rss_before_kib
    }

    /// Peak resident memory above the starting size since the probe started, in KiB.
    pub fn extra_kib(&self) -> Option<u64> {
        Some(status_kib(&self.process, "VmHWM")?.saturating_sub(self.rss_before_kib))
    }
}

/// A `kB` field of `PROCESS/status`.
fn status_kib(process: &str, field: &str) -> Option<u64> {
    let status = std::fs::read_to_string(format!("{process}/status")).ok()?;
    let line = status.lines().find(|l| l.starts_with(field) && l[field.len()..].starts_with(':'))?;
    line[field.len() + 1..].split_whitespace().next()?.parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_big_allocation_shows_when_the_probe_works() {
        let Some(probe) = PeakMemory::start() else { return };
        let block = vec![1u8; 64 << 20];
        std::hint::black_box(&block);
        let extra = probe.extra_kib().unwrap();
        drop(block);
        assert!(extra >= 60 << 10, "{extra} KiB");
    }
}
