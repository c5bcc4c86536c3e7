//! The times an external clipper reports for its own calls (the `time_ns` of its replies), beside
//! the round trips the harness times: bench shows both.

use std::sync::Mutex;

/// The clipper's own times for calls since the last [`OwnTime::take`] (bench reads them).
#[derive(Debug, Default)]
pub struct OwnTime {
    tally: Mutex<OwnTally>,
}

#[derive(Debug, Default)]
struct OwnTally {
    ns: f64,
    reported: u64,
    unreported: u64,
}

impl OwnTime {
    /// Adds one call's own time, as its reply gave it (`None`, negative or not finite: unreported).
    pub fn record(&self, time_ns: Option<f64>) {
        if let Ok(mut t) = self.tally.lock() {
            match time_ns.filter(|t| t.is_finite() && *t >= 0.0) {
                Some(ns) => {
                    t.ns += ns;
                    t.reported += 1;
                }
                None => t.unreported += 1,
            }
        }
    }

    /// The mean own time per call since the last take, when every call reported one; resets.
    pub fn take(&self) -> Option<f64> {
        let mut t = self.tally.lock().ok()?;
        let tally = std::mem::take(&mut *t);
        (tally.reported > 0 && tally.unreported == 0).then(|| tally.ns / tally.reported as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_mean_is_taken_only_when_every_call_reported_and_taking_resets() {
        let own = OwnTime::default();
        assert_eq!(own.take(), None, "no calls");
        own.record(Some(100.0));
        own.record(Some(300.0));
        assert_eq!(own.take(), Some(200.0));
        assert_eq!(own.take(), None, "reset by the take");
        for unreported in [None, Some(-1.0), Some(f64::NAN)] {
            own.record(Some(100.0));
            own.record(unreported);
            assert_eq!(own.take(), None, "{unreported:?}");
        }
    }
}
