//! Measurement plumbing shared by `reproduce` and `bench`: timing, raw result files, where and on
//! what machine a run happened, peak memory, progress bars.

pub mod cpu_time;
pub mod git_revision;
pub mod out_dir;
pub mod own_time;
pub mod parallel;
pub mod peak_memory;
pub mod progress;
pub mod provenance;
pub mod raw;
pub mod timing;
