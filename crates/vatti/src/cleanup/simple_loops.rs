//! A closed walk split into simple loops at the vertices it visits twice: the last step of the
//! clean-up's walks (the planned turns and the rebuild), so no output ring visits a point twice.

/// Splits a closed walk (point ids) at every vertex it visits twice, handing each simple loop
/// to `emit`. `slot` is scratch space indexed by vertex id, all `usize::MAX` on entry and exit;
/// `stack` is a reused buffer.
pub(crate) fn split_repeats(walk: &[u32], slot: &mut [usize], stack: &mut Vec<u32>, emit: &mut impl FnMut(&[u32])) {
    stack.clear();
    for &v in walk {
        let at = slot[v as usize];
        if at != usize::MAX {
            emit(&stack[at..]);
            for &w in &stack[at + 1..] {
                slot[w as usize] = usize::MAX;
            }
            stack.truncate(at + 1);
        } else {
            slot[v as usize] = stack.len();
            stack.push(v);
        }
    }
    emit(stack);
    for &w in stack.iter() {
        slot[w as usize] = usize::MAX;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn loops(walk: &[u32]) -> Vec<Vec<u32>> {
        let mut slot = vec![usize::MAX; 16];
        let mut out = Vec::new();
        split_repeats(walk, &mut slot, &mut Vec::new(), &mut |l: &[u32]| out.push(l.to_vec()));
        assert!(slot.iter().all(|&s| s == usize::MAX), "slots left as found");
        out
    }

    #[test]
    fn a_walk_splits_at_each_vertex_it_returns_to() {
        // A figure eight through 2: one loop closes when 2 comes back, the rest is the other.
        assert_eq!(loops(&[0, 1, 2, 3, 4, 2, 5]), vec![vec![2, 3, 4], vec![0, 1, 2, 5]]);
        // Nested returns: 3 closes first, then 1.
        assert_eq!(loops(&[0, 1, 2, 3, 4, 3, 5, 1, 6]), vec![vec![3, 4], vec![1, 2, 3, 5], vec![0, 1, 6]]);
        // A simple walk stays whole.
        assert_eq!(loops(&[7, 8, 9]), vec![vec![7, 8, 9]]);
    }
}
