//! clip-testkit: seeded workloads, exact oracles and a shrinker.

pub mod line_oracle;
pub mod polygon_oracle;
pub mod shrink;
pub mod workload;

#[cfg(feature = "peers")]
pub mod peers;
