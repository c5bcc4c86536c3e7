//! One small stable insertion sort for the short arrays of a small clip.
//!
//! The library's sorts are fast but large (an unstable sort of 21 to 64 keys runs a quicksort
//! with sorting networks, several kilobytes of code per element type): for one small clip the
//! code it touches, not the comparisons, is what costs, since the whole clip's code is about the
//! size of the first-level instruction cache (seventh round in PERFORMANCE.md). Longer arrays
//! still go to the library's sorts.

/// Arrays up to this long are insertion sorted: at most `SMALL² / 2` moves.
pub(crate) const SMALL: usize = 64;

/// Sorts `v` stably by `less` with an insertion sort when it has at most [`SMALL`] elements;
/// false, with `v` untouched, when it is longer (the caller sorts it with the library).
#[inline]
pub(crate) fn insertion_sorted_by<T: Copy>(v: &mut [T], less: impl Fn(&T, &T) -> bool) -> bool {
    if v.len() > SMALL {
        return false;
    }
    for i in 1..v.len() {
        let x = v[i];
        let mut j = i;
        while j > 0 && less(&x, &v[j - 1]) {
            v[j] = v[j - 1];
            j -= 1;
        }
        v[j] = x;
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sorts_stably_like_the_library_up_to_small() {
        // Pairs (key, original index): equal keys must keep their order.
        let mut seed = 12345u64;
        for len in [0, 1, 2, 3, 20, 21, 63, SMALL] {
            let mut v: Vec<(u32, usize)> = (0..len)
                .map(|i| {
                    seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                    ((seed >> 60) as u32, i)
                })
                .collect();
            let mut expected = v.clone();
            expected.sort_by_key(|p| p.0);
            assert!(insertion_sorted_by(&mut v, |a, b| a.0 < b.0));
            assert_eq!(v, expected, "length {len}");
        }
    }

    #[test]
    fn declines_longer_arrays_untouched() {
        let mut v: Vec<u32> = (0..SMALL as u32 + 1).rev().collect();
        let before = v.clone();
        assert!(!insertion_sorted_by(&mut v, |a, b| a < b));
        assert_eq!(v, before);
    }
}
