//! How far a timing or ratio could move on another run: a seeded bootstrap over cases and
//! repetitions, so a reader (and `compare`) can tell a change from noise.

use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

use super::timing::{geometric_mean, mean, median};

/// Bootstrap resamples per figure: enough for stable 2.5% and 97.5% percentiles, cheap at the
/// bench's few thousand points.
pub const RESAMPLES: usize = 400;

/// An estimate with its 95% interval.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// The figure itself, from all the data.
    pub estimate: f64,
    /// Lower end.
    pub low: f64,
    /// Upper end.
    pub high: f64,
}

impl Interval {
    /// An interval of one value (no spread known).
    pub fn exact(value: f64) -> Interval {
        Interval { estimate: value, low: value, high: value }
    }

    /// Every end scaled by `k` (a unit change).
    pub fn scaled(self, k: f64) -> Interval {
        Interval { estimate: self.estimate * k, low: self.low * k, high: self.high * k }
    }

    /// Whether the interval lies wholly below `value`.
    pub fn below(&self, value: f64) -> bool {
        self.high < value
    }

    /// Whether the interval lies wholly above `value`.
    pub fn above(&self, value: f64) -> bool {
        self.low > value
    }

    /// Whether all three numbers are finite.
    pub fn is_finite(&self) -> bool {
        self.estimate.is_finite() && self.low.is_finite() && self.high.is_finite()
    }
}

/// One case of a point: the clipper's repetitions and, for a ratio, the baseline's.
pub struct CaseSamples<'a> {
    /// The clipper's times.
    pub times: &'a [f64],
    /// The baseline's times on the same case.
    pub baseline: Option<&'a [f64]>,
}

/// Each case's medians: the clipper's, and the baseline's where there is one.
pub type CaseMedians = [(f64, Option<f64>)];

/// Mean over cases of the clipper's median: a point's time.
pub fn mean_time(medians: &CaseMedians) -> Option<f64> {
    Some(mean(&medians.iter().map(|m| m.0).collect::<Vec<_>>()))
}

/// Geometric mean over cases of the clipper's median over the baseline's: a point's ratio;
/// `None` unless every case has a baseline.
pub fn geometric_mean_ratio(medians: &CaseMedians) -> Option<f64> {
    let r: Option<Vec<f64>> = medians.iter().map(|(t, b)| b.map(|b| t / b)).collect();
    r.map(|r| geometric_mean(&r))
}

/// Arithmetic mean over cases of the clipper's median over the baseline's (how Vatti's paper
/// averages its factors); `None` unless every case has a baseline.
pub fn mean_ratio(medians: &CaseMedians) -> Option<f64> {
    let r: Option<Vec<f64>> = medians.iter().map(|(t, b)| b.map(|b| t / b)).collect();
    r.map(|r| mean(&r))
}

/// `statistic` of the cases' medians with its bootstrap interval: cases resampled with
/// replacement, then each chosen case's repetitions (the clipper's and the baseline's apart), the
/// median of each taken again. `seed` makes it repeatable; derive it from the figure's name
/// ([`seed_of`]) so one figure's interval does not depend on the others. `None` when the
/// statistic has no value on the data.
pub fn bootstrap(
    cases: &[CaseSamples],
    seed: u64,
    statistic: impl Fn(&CaseMedians) -> Option<f64>,
) -> Option<Interval> {
    if cases.is_empty() || cases.iter().any(|c| c.times.is_empty() || c.baseline.is_some_and(<[f64]>::is_empty)) {
        return None;
    }
    let all: Vec<(f64, Option<f64>)> = cases.iter().map(|c| (median(c.times), c.baseline.map(median))).collect();
    let estimate = statistic(&all)?;
    let mut rng = Pcg64::seed_from_u64(seed);
    let mut scratch = Vec::new();
    let mut resample = |rng: &mut Pcg64, values: &[f64]| {
        scratch.clear();
        scratch.extend((0..values.len()).map(|_| values[rng.random_range(0..values.len())]));
        median(&scratch)
    };
    let mut values = Vec::with_capacity(RESAMPLES);
    let mut medians = Vec::with_capacity(cases.len());
    for _ in 0..RESAMPLES {
        medians.clear();
        for _ in 0..cases.len() {
            let case = &cases[rng.random_range(0..cases.len())];
            let t = resample(&mut rng, case.times);
            let b = case.baseline.map(|b| resample(&mut rng, b));
            medians.push((t, b));
        }
        values.extend(statistic(&medians));
    }
    Some(percentiles(estimate, &mut values))
}

/// The estimate with the 2.5% and 97.5% percentiles of its resamples.
fn percentiles(estimate: f64, resamples: &mut [f64]) -> Interval {
    if resamples.is_empty() {
        return Interval::exact(estimate);
    }
    resamples.sort_by(f64::total_cmp);
    let at = |q: f64| resamples[((resamples.len() - 1) as f64 * q).round() as usize];
    Interval { estimate, low: at(0.025).min(estimate), high: at(0.975).max(estimate) }
}

/// A seed from a point's name (FNV-1a): the same point gets the same interval on every report.
pub fn seed_of(name: &str) -> u64 {
    name.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spread_in_the_data_widens_the_interval_and_a_seed_repeats_it() {
        let steady = [100.0; 7];
        let noisy = [60.0, 80.0, 100.0, 120.0, 140.0, 90.0, 110.0];
        let base = [100.0; 7];

        fn case<'a>(times: &'a [f64], base: &'a [f64]) -> CaseSamples<'a> {
            CaseSamples { times, baseline: Some(base) }
        }
        let calm = [case(&steady, &base), case(&steady, &base)];
        assert_eq!(bootstrap(&calm, 1, mean_time), Some(Interval::exact(100.0)));
        assert_eq!(bootstrap(&calm, 1, geometric_mean_ratio), Some(Interval::exact(1.0)));
        let shaky = [case(&noisy, &base), case(&steady, &base)];
        let t = bootstrap(&shaky, 1, mean_time).unwrap();
        assert!(t.low < 100.0 && t.high > 100.0, "{t:?}");
        let r = bootstrap(&shaky, 1, geometric_mean_ratio).unwrap();
        assert!(r.low < 1.0 && r.high > 1.0 && r.estimate == 1.0, "{r:?}");
        assert_eq!(bootstrap(&shaky, 1, geometric_mean_ratio), Some(r), "the same seed, the same interval");
        // Without a baseline on every case there is no ratio.
        let alone = [case(&steady, &base), CaseSamples { times: &steady, baseline: None }];
        assert_eq!(bootstrap(&alone, 1, geometric_mean_ratio), None);
        assert_eq!(bootstrap(&alone, 1, mean_time), Some(Interval::exact(100.0)));
    }
}
