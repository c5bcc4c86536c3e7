//! clip-testkit: seeded workloads, exact oracles and a shrinker.

pub mod polygon_oracle;
pub mod workload;

#[cfg(feature = "peers")]
pub mod peers;
