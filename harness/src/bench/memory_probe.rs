//! Peak memory of one call, measured in a fresh child process: in the benchmarking process the
//! allocator reuses memory freed by earlier cases, so the resident peak would hide most of it.

use std::process::{Command, ExitCode};

use clip_core::{BoolOp, FillRule, WindowKind};
use clip_testkit::workload::polygon_case_sized;

use crate::cli_error::CliError;
use crate::measure::peak_memory::PeakMemory;
use crate::registry::Registry;

/// What one probe measures.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Probe {
    /// clip-testkit workload.
    pub workload: String,
    /// Window kind of the case.
    pub window: WindowKind,
    /// Case index.
    pub index: usize,
    /// Subject edges.
    pub size: usize,
    /// Registry name of the clipper.
    pub clipper: String,
    /// The operation.
    pub op: BoolOp,
    /// The fill rule the call reads its operands under (as timed).
    pub fill: FillRule,
}

impl Probe {
    /// The probe as one command-line word: `workload/window/index/size/clipper/op/fill`.
    pub fn spec(&self) -> String {
        let window = match self.window {
            WindowKind::Any => "any",
            WindowKind::Convex => "convex",
            WindowKind::Rectangle => "rectangle",
        };
        format!(
            "{}/{window}/{}/{}/{}/{}/{}",
            self.workload,
            self.index,
            self.size,
            self.clipper,
            self.op.name(),
            self.fill.name()
        )
    }

    /// Reads [`Probe::spec`] back.
    pub fn parse(spec: &str) -> Option<Probe> {
        let parts: Vec<&str> = spec.split('/').collect();
        let [workload, window, index, size, clipper, op, fill] = parts[..] else { return None };
        let window = match window {
            "any" => WindowKind::Any,
            "convex" => WindowKind::Convex,
            "rectangle" => WindowKind::Rectangle,
            _ => return None,
        };
        Some(Probe {
            workload: workload.to_owned(),
            window,
            index: index.parse().ok()?,
            size: size.parse().ok()?,
            clipper: clipper.to_owned(),
            op: op.parse().ok()?,
            fill: fill.parse().ok()?,
        })
    }

    /// Runs the probe in a child `clipbench bench --memory-probe` and returns (resident KiB
    /// before the call, peak KiB above it); `None` when that is not possible here.
    pub fn run_in_child(&self, seed: u64) -> Option<(u64, u64)> {
        let exe = std::env::current_exe().ok()?;
        let seed = seed.to_string();
        let output =
            Command::new(exe).args(["bench", "--seed", &seed, "--memory-probe", &self.spec()]).output().ok()?;
        if !output.status.success() {
            return None;
        }
        let text = String::from_utf8_lossy(&output.stdout);
        let mut words = text.split_whitespace().map(str::parse::<u64>);
        Some((words.next()?.ok()?, words.next()?.ok()?))
    }
}

/// The child's side: builds the case, resets the peak, makes the call and prints
/// `rss_before_kib peak_extra_kib`.
pub fn child(spec: &str, seed: u64, registry: &Registry) -> Result<ExitCode, CliError> {
    let probe = Probe::parse(spec).ok_or_else(|| CliError::usage(format!("bad memory probe '{spec}'")))?;
    let entry = registry
        .find_polygon(&probe.clipper)
        .ok_or_else(|| CliError::usage(format!("memory probe: unknown clipper '{}'", probe.clipper)))?;
    let case = polygon_case_sized(&probe.workload, seed, probe.index, probe.size, probe.window)
        .map_err(|e| CliError::usage(e.to_string()))?;
    let peak = PeakMemory::start().ok_or_else(|| CliError::failed("peak memory is not available here"))?;
    let result = entry.clipper.clip(&case.subject, &case.clip, probe.op, probe.fill);
    let extra = peak.extra_kib().ok_or_else(|| CliError::failed("peak memory is not available here"))?;
    result.map_err(|e| CliError::failed(format!("memory probe: {e}")))?;
    println!("{} {extra}", peak.rss_before_kib());
    Ok(ExitCode::SUCCESS)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn specs_round_trip() {
        let p = Probe {
            workload: "large".into(),
            window: WindowKind::Rectangle,
            index: 1,
            size: 100_000,
            clipper: "virtual-box-no45".into(),
            op: BoolOp::Difference,
            fill: FillRule::NonZero,
        };
        assert_eq!(p.spec(), "large/rectangle/1/100000/virtual-box-no45/difference/non-zero");
        assert_eq!(Probe::parse(&p.spec()), Some(p));
        assert_eq!(Probe::parse("large/any/x/1/vatti/union/even-odd"), None);
        assert_eq!(Probe::parse("large/any/1/1/vatti/union"), None);
    }
}
