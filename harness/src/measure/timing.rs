//! Timing one call and summarising repetitions by their median.

use std::hint::black_box;
use std::time::{Duration, Instant};

/// Runs `f` once and returns its result and the wall-clock time it took.
#[inline(never)]
pub fn timed<T>(f: impl FnOnce() -> T) -> (T, Duration) {
    let start = Instant::now();
    let value = black_box(f());
    (value, start.elapsed())
}

/// Runs `f` `iterations` times back to back and returns the time per call in nanoseconds; each
/// result passes through [`black_box`] so no call is optimised away.
#[inline(never)]
pub fn per_call_ns<T>(iterations: u32, mut f: impl FnMut() -> T) -> f64 {
    let iterations = iterations.max(1);
    let start = Instant::now();
    for _ in 0..iterations {
        black_box(f());
    }
    start.elapsed().as_nanos() as f64 / f64::from(iterations)
}

/// How many back-to-back calls make one measurement last about `target`, given one call took
/// `single`: short calls are repeated so timer resolution and loop overhead stay negligible.
pub fn iterations_for(single: Duration, target: Duration) -> u32 {
    if single >= target {
        return 1;
    }
    let ratio = target.as_nanos() / single.as_nanos().max(1);
    u32::try_from(ratio).unwrap_or(u32::MAX).clamp(1, 100_000)
}

/// The median of `values` (the mean of the two middle ones for an even count); NaN when empty.
pub fn median(values: &[f64]) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let mid = sorted.len() / 2;
    if sorted.len() % 2 == 1 { sorted[mid] } else { 0.5 * (sorted[mid - 1] + sorted[mid]) }
}

/// The arithmetic mean of `values`; NaN when empty.
pub fn mean(values: &[f64]) -> f64 {
    if values.is_empty() { f64::NAN } else { values.iter().sum::<f64>() / values.len() as f64 }
}

/// The geometric mean of positive `values`; NaN when empty.
pub fn geometric_mean(values: &[f64]) -> f64 {
    if values.is_empty() { f64::NAN } else { (values.iter().map(|v| v.ln()).sum::<f64>() / values.len() as f64).exp() }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_of_odd_and_even_counts() {
        assert_eq!(median(&[5.0, 1.0, 3.0]), 3.0);
        assert_eq!(median(&[4.0, 1.0, 3.0, 2.0]), 2.5);
        assert!(median(&[]).is_nan());
    }

    #[test]
    fn means() {
        assert_eq!(mean(&[1.0, 2.0, 6.0]), 3.0);
        assert!((geometric_mean(&[1.0, 4.0]) - 2.0).abs() < 1e-12);
    }

    #[test]
    fn short_calls_are_repeated_long_ones_are_not() {
        assert_eq!(iterations_for(Duration::from_micros(10), Duration::from_millis(1)), 100);
        assert_eq!(iterations_for(Duration::from_millis(5), Duration::from_millis(1)), 1);
        assert_eq!(iterations_for(Duration::ZERO, Duration::from_millis(1)), 100_000);
    }
}
