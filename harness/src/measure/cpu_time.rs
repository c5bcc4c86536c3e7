//! CPU time the process's threads have run, so a wall-clock time on a shared machine can be read beside it.

use std::fs;

/// Nanoseconds every thread of this process has spent on a CPU so far, from Linux's
/// `/proc/self/task/*/schedstat`; `None` where that is not available. A thread that ended
/// takes its time with it, so take differences over spans in which the threads stay (rayon's
/// pool keeps its workers).
pub fn process_cpu_ns() -> Option<u64> {
    let mut total = 0u64;
    for task in fs::read_dir("/proc/self/task").ok()? {
        let stat = fs::read_to_string(task.ok()?.path().join("schedstat")).ok()?;
        total += stat.split_whitespace().next()?.parse::<u64>().ok()?;
    }
    Some(total)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grows_while_this_thread_works() {
        let Some(before) = process_cpu_ns() else { return };
        let mut x = 0u64;
        for i in 0..20_000_000u64 {
            x = std::hint::black_box(x.wrapping_add(i * i));
        }
        let after = process_cpu_ns().expect("available a moment ago");
        assert!(after > before, "{before} -> {after} ({x})");
    }
}
