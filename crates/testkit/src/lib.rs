//! clip-testkit: seeded workloads, exact oracles and a shrinker.
