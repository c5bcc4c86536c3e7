//! Peak resident memory of one operation, from Linux's /proc/self (no unsafe code).
//!
//! Writing "5" to /proc/self/clear_refs resets the peak resident set size (VmHWM) to the current
//! one; after the operation, VmHWM minus the resident size before it is the operation's peak
//! extra memory. Elsewhere (or when /proc is read-only) [`PeakMemory::start`] returns `None`
//! and the result files say the figure is unavailable.

/// A peak-memory probe started just before an operation.
#[derive(Clone, Copy, Debug)]
pub struct PeakMemory {
    rss_before_kib: u64,
}

impl PeakMemory {
    /// Resets the kernel's peak counter; `None` when that is not possible here.
    pub fn start() -> Option<PeakMemory> {
        std::fs::write("/proc/self/clear_refs", b"5").ok()?;
        let rss_before_kib = status_kib("VmRSS")?;
        Some(PeakMemory { rss_before_kib })
    }

    /// Resident size when the probe started, in KiB.
    pub fn rss_before_kib(&self) -> u64 {
        self.rss_before_kib
    }

    /// Peak resident memory above the starting size since [`PeakMemory::start`], in KiB.
    pub fn extra_kib(&self) -> Option<u64> {
        Some(status_kib("VmHWM")?.saturating_sub(self.rss_before_kib))
    }
}

/// A `kB` field of /proc/self/status.
fn status_kib(field: &str) -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
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
