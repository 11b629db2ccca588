//! Permutation tables shared by the simplicial importer and the cube-grid builder.
//!
//! The permutations of `0..m` are numbered by their rank in lexicographic order (the
//! Lehmer code read as a factorial-base number). A [`PermTable`] stores every permutation
//! and, for each one, the rank of the permutation obtained by swapping two consecutive
//! positions: that is exactly how `alpha_i` acts on the darts of a simplex or a cube.

/// `m!` with overflow checking.
pub(crate) fn factorial(m: usize) -> Option<u64> {
    (1..=m as u64).try_fold(1u64, |acc, k| acc.checked_mul(k))
}

/// All permutations of `0..m` in lexicographic order, with their adjacent-swap ranks.
pub(crate) struct PermTable {
    m: usize,
    /// `perms[p * m + k]`: the element at position `k` of permutation `p`
    perms: Vec<u8>,
    /// `swaps[p * (m - 1) + i]`: rank of `p` with positions `i` and `i + 1` exchanged
    swaps: Vec<u32>,
}

impl PermTable {
    /// Builds the table for `m` elements. O(m! m^2). The caller bounds `m!` beforehand.
    pub(crate) fn new(m: usize) -> Self {
        Self::try_new(m).expect("memory for the permutation table")
    }

    /// The table, or `None` when its memory cannot be had (reserved fallibly).
    pub(crate) fn try_new(m: usize) -> Option<Self> {
        let count = usize::try_from(factorial(m)?).ok()?;
        let mut perms = Vec::new();
        perms.try_reserve_exact(count.checked_mul(m)?).ok()?;
        let mut cur: Vec<u8> = (0..m as u8).collect();
        loop {
            perms.extend_from_slice(&cur);
            if !next_permutation(&mut cur) {
                break;
            }
        }
        let w = m.saturating_sub(1);
        let mut swaps = Vec::new();
        swaps.try_reserve_exact(count.checked_mul(w)?).ok()?;
        let mut tmp = vec![0u8; m];
        for p in 0..count {
            for i in 0..w {
                tmp.copy_from_slice(&perms[p * m..(p + 1) * m]);
                tmp.swap(i, i + 1);
                swaps.push(rank(&tmp) as u32);
            }
        }
        Some(PermTable { m, perms, swaps })
    }

    /// Number of permutations, `m!`.
    pub(crate) fn len(&self) -> usize {
        self.perms.len() / self.m.max(1)
    }

    /// The permutation of rank `p`.
    #[inline]
    pub(crate) fn perm(&self, p: usize) -> &[u8] {
        &self.perms[p * self.m..(p + 1) * self.m]
    }

    /// Rank of permutation `p` with positions `i`, `i + 1` exchanged (`i + 1 < m`).
    #[inline]
    pub(crate) fn swap(&self, p: usize, i: usize) -> u32 {
        self.swaps[p * (self.m - 1) + i]
    }
}

/// Rank of a permutation of `0..m` in lexicographic order. O(m^2).
#[inline]
pub(crate) fn rank(p: &[u8]) -> u64 {
    let m = p.len();
    let mut r = 0u64;
    for i in 0..m {
        let smaller = p[i + 1..].iter().filter(|&&x| x < p[i]).count() as u64;
        r = r * (m - i) as u64 + smaller;
    }
    r
}

/// Advances `p` to the next permutation in lexicographic order; false after the last.
fn next_permutation(p: &mut [u8]) -> bool {
    let m = p.len();
    if m < 2 {
        return false;
    }
    let mut i = m - 1;
    while i > 0 && p[i - 1] >= p[i] {
        i -= 1;
    }
    if i == 0 {
        return false;
    }
    let mut j = m - 1;
    while p[j] <= p[i - 1] {
        j -= 1;
    }
    p.swap(i - 1, j);
    p[i..].reverse();
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranks_follow_lexicographic_order() {
        let t = PermTable::new(4);
        assert_eq!(t.len(), 24);
        for p in 0..t.len() {
            assert_eq!(rank(t.perm(p)), p as u64);
        }
        assert_eq!(t.perm(0), &[0, 1, 2, 3]);
        assert_eq!(t.perm(23), &[3, 2, 1, 0]);
        // [0,1,2,3] with positions 2,3 swapped is [0,1,3,2], rank 1
        assert_eq!(t.swap(0, 2), 1);
        assert_eq!(factorial(12), Some(479_001_600));
        assert_eq!(factorial(21), None);
    }
}
