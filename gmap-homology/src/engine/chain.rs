//! [`ChainComplex`]: free abelian groups `C_0..C_n` on cells and boundary matrices between them.

use thiserror::Error;

use crate::engine::sparse::SparseMatrix;

/// Why matrices do not form a chain complex.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum ChainError {
    /// `boundaries.len()` is not `counts.len() - 1`.
    #[error("{counts} cell counts need {} boundary matrices, got {boundaries}", .counts.saturating_sub(1))]
    WrongLength {
        /// number of cell counts given
        counts: usize,
        /// number of matrices given
        boundaries: usize,
    },
    /// `∂_k` is not `count(k-1) × count(k)`.
    #[error("boundary ∂_{k} is {rows}x{cols}, expected {expected_rows}x{expected_cols}")]
    WrongShape {
        /// the dimension k of ∂_k
        k: usize,
        /// rows found
        rows: usize,
        /// columns found
        cols: usize,
        /// rows expected (number of (k-1)-cells)
        expected_rows: usize,
        /// columns expected (number of k-cells)
        expected_cols: usize,
    },
    /// `∂_{k-1} ∂_k` is not zero: the first non-zero entry.
    #[error("∂_{} ∂_{k} is not zero: entry ({row}, {col}) is {value}", .k - 1)]
    NotComplex {
        /// the dimension k
        k: usize,
        /// a (k-2)-cell
        row: usize,
        /// a k-cell
        col: usize,
        /// the value of the product there
        value: i64,
    },
    /// The product `∂_{k-1} ∂_k` overflowed `i64` while being checked.
    #[error("checking ∂_{} ∂_{k} overflowed i64", .k - 1)]
    Overflow {
        /// the dimension k
        k: usize,
    },
}

/// A finite chain complex of free abelian groups: `C_k` has one generator per k-cell
/// (`counts[k]` of them) and `∂_k : C_k → C_{k-1}` (k = 1..=n) is a sparse integer matrix
/// whose column `j` is the boundary of k-cell `j`. `∂_0` is zero and not stored.
///
/// Invariants (checked by [`ChainComplex::try_new`]): shapes agree with the counts and
/// `∂_{k-1} ∂_k = 0` for every k.
///
/// ```
/// use gmap_homology::{ChainComplex, SparseMatrix, homology_z};
/// // a circle: one vertex, one edge whose two ends are that vertex (signs cancel)
/// let d1 = SparseMatrix::zeros(1, 1);
/// let c = ChainComplex::try_new(vec![1, 1], vec![d1]).unwrap();
/// let h = homology_z(&c).unwrap();
/// assert_eq!(h.betti, vec![1, 1]);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ChainComplex {
    counts: Vec<usize>,
    boundaries: Vec<SparseMatrix>,
}

impl ChainComplex {
    /// Builds a complex from cell counts and `boundaries[k - 1] = ∂_k`, checking shapes
    /// and `∂∂ = 0`. O(total work of the sparse products).
    pub fn try_new(counts: Vec<usize>, boundaries: Vec<SparseMatrix>) -> Result<Self, ChainError> {
        let c = Self::try_new_unchecked_dd(counts, boundaries)?;
        c.check_dd()?;
        Ok(c)
    }

    /// Builds a complex checking only the shapes; call [`ChainComplex::check_dd`] before
    /// relying on `∂∂ = 0`. O(n).
    pub fn try_new_unchecked_dd(counts: Vec<usize>, boundaries: Vec<SparseMatrix>) -> Result<Self, ChainError> {
        if counts.is_empty() && boundaries.is_empty() {
            return Ok(ChainComplex { counts, boundaries });
        }
        if boundaries.len() + 1 != counts.len() {
            return Err(ChainError::WrongLength { counts: counts.len(), boundaries: boundaries.len() });
        }
        for (idx, b) in boundaries.iter().enumerate() {
            let k = idx + 1;
            if b.rows() != counts[k - 1] || b.cols() != counts[k] {
                return Err(ChainError::WrongShape {
                    k,
                    rows: b.rows(),
                    cols: b.cols(),
                    expected_rows: counts[k - 1],
                    expected_cols: counts[k],
                });
            }
        }
        Ok(ChainComplex { counts, boundaries })
    }

    /// Checks `∂_{k-1} ∂_k = 0` for every k, reporting the first non-zero entry.
    pub fn check_dd(&self) -> Result<(), ChainError> {
        for k in 2..self.counts.len() {
            let p = self.boundary(k - 1).checked_mul(self.boundary(k)).ok_or(ChainError::Overflow { k })?;
            let first = p.iter().next();
            if let Some((row, col, value)) = first {
                return Err(ChainError::NotComplex { k, row, col, value });
            }
        }
        Ok(())
    }

    /// The top dimension n (`counts.len() - 1`); 0 for an empty complex.
    pub fn dim(&self) -> usize {
        self.counts.len().saturating_sub(1)
    }

    /// Whether the complex has no dimension at all.
    pub fn is_empty(&self) -> bool {
        self.counts.is_empty()
    }

    /// Number of k-cells (0 beyond the top dimension).
    pub fn count(&self, k: usize) -> usize {
        self.counts.get(k).copied().unwrap_or(0)
    }

    /// The cell counts `[count(0), …, count(n)]`.
    pub fn counts(&self) -> &[usize] {
        &self.counts
    }

    /// `∂_k` for `1 <= k <= n`. Panics outside that range.
    pub fn boundary(&self, k: usize) -> &SparseMatrix {
        assert!(k >= 1 && k <= self.boundaries.len(), "no boundary matrix ∂_{k}");
        &self.boundaries[k - 1]
    }

    /// All boundary matrices, `∂_1..∂_n`.
    pub fn boundaries(&self) -> &[SparseMatrix] {
        &self.boundaries
    }

    /// The Euler characteristic `Σ (-1)^k count(k)`.
    pub fn euler_characteristic(&self) -> i64 {
        self.counts.iter().enumerate().map(|(k, &c)| if k % 2 == 0 { c as i64 } else { -(c as i64) }).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shapes_and_dd_checked() {
        let d1 = SparseMatrix::try_from_triplets(2, 1, &[(0, 0, -1), (1, 0, 1)]).unwrap();
        let d2 = SparseMatrix::try_from_triplets(1, 1, &[(0, 0, 1)]).unwrap();
        assert_eq!(
            ChainComplex::try_new(vec![2, 1, 1], vec![d1.clone(), d2]),
            Err(ChainError::NotComplex { k: 2, row: 0, col: 0, value: -1 })
        );
        assert!(matches!(
            ChainComplex::try_new(vec![3, 1], vec![d1.clone()]),
            Err(ChainError::WrongShape { k: 1, rows: 2, .. })
        ));
        let c = ChainComplex::try_new(vec![2, 1], vec![d1]).unwrap();
        assert_eq!(c.euler_characteristic(), 1);
        assert_eq!(c.dim(), 1);
    }
}
