//! Sentences the report derives from figures with intervals: a point counts for a claim ("faster
//! at k of n sizes") only when its whole interval supports it; the rest are called
//! indistinguishable.

use crate::measure::interval::Interval;

/// How many points an interval puts on each side of a reference, and how many it cannot place.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Sides {
    /// Wholly on the faster side.
    pub faster: usize,
    /// Wholly on the slower side.
    pub slower: usize,
    /// Interval crossing the reference.
    pub indistinguishable: usize,
}

impl Sides {
    /// Time ratios to a reference of 1: below 1 is faster.
    pub fn of_time_ratios<'a>(ratios: impl IntoIterator<Item = &'a Interval>) -> Sides {
        Sides::count(ratios, |i| i.below(1.0), |i| i.above(1.0))
    }

    /// Speed-up factors (the other's time over this one's): above 1 is faster.
    pub fn of_speedups<'a>(factors: impl IntoIterator<Item = &'a Interval>) -> Sides {
        Sides::count(factors, |i| i.above(1.0), |i| i.below(1.0))
    }

    fn count<'a>(
        figures: impl IntoIterator<Item = &'a Interval>,
        faster: impl Fn(&Interval) -> bool,
        slower: impl Fn(&Interval) -> bool,
    ) -> Sides {
        let mut sides = Sides::default();
        for i in figures.into_iter().filter(|i| i.is_finite()) {
            if faster(i) {
                sides.faster += 1;
            } else if slower(i) {
                sides.slower += 1;
            } else {
                sides.indistinguishable += 1;
            }
        }
        sides
    }

    /// Points counted.
    pub fn total(&self) -> usize {
        self.faster + self.slower + self.indistinguishable
    }

    /// "faster at 2 of 6 sizes, slower at 1, indistinguishable at 3 (95% intervals)": `what`
    /// names the points (`sizes`).
    pub fn sentence(&self, what: &str) -> String {
        format!(
            "faster at {} of {} {what}, slower at {}, indistinguishable at {} (95% intervals)",
            self.faster,
            self.total(),
            self.slower,
            self.indistinguishable
        )
    }
}

/// How a figure moves from interval `a` to interval `b`: it grows or falls only when the two
/// intervals do not overlap.
pub fn trend(a: &Interval, b: &Interval) -> &'static str {
    if b.low > a.high {
        "grows"
    } else if b.high < a.low {
        "falls"
    } else {
        "does not move beyond its intervals"
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_whose_interval_crosses_one_is_counted_on_neither_side() {
        let i = |low, estimate, high| Interval { estimate, low, high };
        let ratios = [i(0.7, 0.8, 0.9), i(0.9, 0.95, 1.02), i(1.1, 1.2, 1.3), i(0.5, 0.9, 1.5)];
        let sides = Sides::of_time_ratios(&ratios);
        assert_eq!(sides, Sides { faster: 1, slower: 1, indistinguishable: 2 });
        assert_eq!(
            sides.sentence("sizes"),
            "faster at 1 of 4 sizes, slower at 1, indistinguishable at 2 (95% intervals)"
        );
        // The same figures read as speed-ups swap sides.
        assert_eq!(Sides::of_speedups(&ratios), Sides { faster: 1, slower: 1, indistinguishable: 2 });
        assert_eq!(Sides::of_speedups(&ratios[..1]), Sides { faster: 0, slower: 1, indistinguishable: 0 });
    }
}
