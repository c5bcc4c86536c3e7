//! clip-testkit: seeded workloads, exact oracles and a shrinker.

#[cfg(feature = "peers")]
pub mod peers;
