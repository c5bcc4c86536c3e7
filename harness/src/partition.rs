//! `--partition K/N`: part K of N of a run's cases, so that N jobs of a batch scheduler (a Slurm
//! job array, a Kubernetes Indexed Job, GNU parallel over ssh) each run one part with no
//! coordination, as cargo-nextest's `--partition count:K/N` splits tests.
//!
//! The split is by position in the run's fixed list of cases (for `verify`, workload by workload,
//! case index by case index; for `conformance`, the suite's order): case `j` (from 0) is in part
//! `j mod N + 1`. Every part of the same command line sees the same list, so the parts are
//! disjoint and cover it, and dealing the cases round-robin spreads each workload's costly cases
//! over the parts.

use std::fmt;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

/// Part `k` of `n` (1 ≤ k ≤ n).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Partition {
    /// Which part, from 1.
    pub k: usize,
    /// How many parts.
    pub n: usize,
}

impl Partition {
    /// Whether the case at position `j` (from 0) of the run's list is in this part.
    pub fn keeps(self, j: usize) -> bool {
        j % self.n == self.k - 1
    }
}

impl FromStr for Partition {
    type Err = String;

    /// `K/N`, as `3/8`.
    fn from_str(text: &str) -> Result<Partition, String> {
        let usage = || format!("'{text}' is not a part K/N (K from 1 to N, as 3/8)");
        let (k, n) = text.split_once('/').ok_or_else(usage)?;
        let (k, n): (usize, usize) = (k.trim().parse().map_err(|_| usage())?, n.trim().parse().map_err(|_| usage())?);
        if n == 0 || k == 0 || k > n {
            return Err(usage());
        }
        Ok(Partition { k, n })
    }
}

impl fmt::Display for Partition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.k, self.n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parts_are_disjoint_and_cover_the_cases() {
        let parts: Vec<Partition> = (1..=3).map(|k| format!("{k}/3").parse().unwrap()).collect();
        for j in 0..10 {
            assert_eq!(parts.iter().filter(|p| p.keeps(j)).count(), 1, "case {j}");
        }
        assert!(parts[0].keeps(0) && parts[1].keeps(4) && parts[2].keeps(8));
        assert_eq!(parts[2].to_string(), "3/3");
    }

    #[test]
    fn bad_parts_are_refused_with_the_form() {
        for bad in ["0/3", "4/3", "1/0", "3", "a/b", "-1/3", ""] {
            let e = bad.parse::<Partition>().unwrap_err();
            assert!(e.contains("K/N"), "{bad}: {e}");
        }
    }
}
