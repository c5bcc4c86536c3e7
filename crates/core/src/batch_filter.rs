//! Branch-free filtering of a batch's segment indices, for the line clippers' early outs.

/// Keeps the indices in `kept` for which `keep` holds, in order. Each index is written and the
/// length advanced by the test's outcome, with no branch on it: when the stage a segment stops at
/// is random (segments spread over a screen), a per-segment early out mispredicts on a large share
/// of the batch and costs more than the test it skips.
#[inline(always)]
pub fn retain_indices(kept: &mut Vec<usize>, keep: impl Fn(usize) -> bool) {
    let mut n = 0;
    for k in 0..kept.len() {
        let index = kept[k];
        kept[n] = index;
        n += usize::from(keep(index));
    }
    kept.truncate(n);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keeps_the_indices_that_pass_in_order() {
        let mut kept = vec![0, 3, 4, 7, 8, 10];
        retain_indices(&mut kept, |i| i % 2 == 0);
        assert_eq!(kept, vec![0, 4, 8, 10]);
        retain_indices(&mut kept, |_| false);
        assert!(kept.is_empty());
    }
}
