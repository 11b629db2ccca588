//! Signed sets: cells with their positive and negative occurrences kept apart (TM §IV).

use std::collections::BTreeMap;

/// A set of cells with signed multiplicities: for each cell, the number of positive and of
/// negative occurrences, kept apart (TM §IV: "positive and negative occurrences of the same
/// cell are distinguished"). Cells are indices of a [`super::TmModel`].
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SignedSet {
    occ: BTreeMap<usize, (u64, u64)>,
}

impl SignedSet {
    /// The empty set.
    pub fn new() -> Self {
        SignedSet::default()
    }

    /// One positive occurrence of a cell.
    pub fn cell(c: usize) -> Self {
        let mut s = SignedSet::new();
        s.add(c, 1, 0);
        s
    }

    /// Adds `plus` positive and `minus` negative occurrences of `c` (saturating: counts
    /// beyond 2^64 are not meaningful for a model). Adding nothing leaves the set as is.
    pub fn add(&mut self, c: usize, plus: u64, minus: u64) {
        if plus == 0 && minus == 0 {
            return;
        }
        let e = self.occ.entry(c).or_insert((0, 0));
        e.0 = e.0.saturating_add(plus);
        e.1 = e.1.saturating_add(minus);
    }

    /// `(positive, negative)` occurrences of `c`.
    pub fn get(&self, c: usize) -> (u64, u64) {
        self.occ.get(&c).copied().unwrap_or((0, 0))
    }

    /// The net coefficient of `c` as a chain: positive minus negative occurrences.
    pub fn net(&self, c: usize) -> i128 {
        let (p, m) = self.get(c);
        i128::from(p) - i128::from(m)
    }

    /// The cells present, increasing, with their occurrences `(cell, positive, negative)`.
    pub fn iter(&self) -> impl Iterator<Item = (usize, u64, u64)> + '_ {
        self.occ.iter().map(|(&c, &(p, m))| (c, p, m))
    }

    /// Number of distinct cells.
    pub fn len(&self) -> usize {
        self.occ.len()
    }

    /// Whether no cell occurs.
    pub fn is_empty(&self) -> bool {
        self.occ.is_empty()
    }

    /// All positive and all negative occurrences, summed over the cells (saturating).
    pub fn totals(&self) -> (u64, u64) {
        self.iter().fold((0u64, 0u64), |(a, b), (_, p, m)| (a.saturating_add(p), b.saturating_add(m)))
    }

    /// The union with multiplicities added (TM's amalgamation of boundary sets).
    pub fn union(&self, other: &SignedSet) -> SignedSet {
        let mut s = self.clone();
        for (c, p, m) in other.iter() {
            s.add(c, p, m);
        }
        s
    }
}

impl FromIterator<(usize, u64, u64)> for SignedSet {
    /// The set of `(cell, positive, negative)` occurrences, repeated cells added up.
    fn from_iter<I: IntoIterator<Item = (usize, u64, u64)>>(iter: I) -> Self {
        let mut s = SignedSet::new();
        for (c, p, m) in iter {
            s.add(c, p, m);
        }
        s
    }
}
