//! Circuits, cocircuits and the topological edit check (TM §VI, (7:5), (7:6), §XI).

use thiserror::Error;

use super::{SignedSet, TmModel};

/// A violation of the topological edit check (TM §XI), naming the cell and the condition
/// ((7:5) for a boundary, (7:6) for a coboundary) and where it fails.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum TmDefect {
    /// TM (7:5) fails: the boundary of a k-cell is not a (k-1)-circuit. `at` occurs `plus`
    /// times positively and `minus` times negatively in the boundary of that boundary (for
    /// k = 1: `at` is the cell itself and plus/minus are the summed occurrences of its end
    /// vertices, the fictitious boundary of TM §VI).
    #[error(
        "TM (7:5): the boundary of {dim}-cell {cell} is not a circuit: cell {at} occurs +{plus}/-{minus} times in its boundary"
    )]
    BoundaryNotCircuit {
        /// the cell (its id)
        cell: u64,
        /// its dimension
        dim: usize,
        /// where the circuit condition fails (a cell id)
        at: u64,
        /// positive occurrences
        plus: u64,
        /// negative occurrences
        minus: u64,
    },
    /// TM (7:6) fails: the coboundary of a k-cell is not a (k+1)-cocircuit (dual of the
    /// above; for k = n - 1, `at` is the cell itself and the n-cells cobounding it do not
    /// pair up with opposite orientations: a free face, or two n-cells on the same side).
    #[error("TM (7:6): the coboundary of {dim}-cell {cell} is not a cocircuit: cell {at} occurs +{plus}/-{minus} times in its coboundary")]
    CoboundaryNotCocircuit {
        /// the cell (its id)
        cell: u64,
        /// its dimension
        dim: usize,
        /// where the cocircuit condition fails (a cell id)
        at: u64,
        /// positive occurrences
        plus: u64,
        /// negative occurrences
        minus: u64,
    },
}

impl TmDefect {
    /// The condition of the paper that fails: `"(7:5)"` or `"(7:6)"`.
    pub fn condition(&self) -> &'static str {
        match self {
            TmDefect::BoundaryNotCircuit { .. } => "(7:5)",
            TmDefect::CoboundaryNotCocircuit { .. } => "(7:6)",
        }
    }

    /// The id of the offending cell.
    pub fn cell(&self) -> u64 {
        match *self {
            TmDefect::BoundaryNotCircuit { cell, .. } | TmDefect::CoboundaryNotCocircuit { cell, .. } => cell,
        }
    }

    /// The dimension of the offending cell.
    pub fn dim(&self) -> usize {
        match *self {
            TmDefect::BoundaryNotCircuit { dim, .. } | TmDefect::CoboundaryNotCocircuit { dim, .. } => dim,
        }
    }
}

impl TmModel {
    /// Whether a set of k-cells is a k-circuit, an element of `Z^k` (TM §VI): every
    /// (k-1)-cell occurs in its boundary as often positively as negatively; for k = 0, the
    /// coefficients sum to zero (the fictitious boundary). O(Σ boundary sizes).
    pub fn is_circuit(&self, s: &SignedSet, k: usize) -> bool {
        if k == 0 {
            let (p, m) = s.totals();
            return p == m;
        }
        self.boundary(s).iter().all(|(_, p, m)| p == m)
    }

    /// Whether a set of k-cells is a k-cocircuit, an element of `Y^k`: every (k+1)-cell
    /// occurs in its coboundary as often with each sign; for k = n, the coefficients sum to
    /// zero (pairs of oppositely oriented n-cells, TM §VI).
    pub fn is_cocircuit(&self, s: &SignedSet, k: usize) -> bool {
        if k == self.dim() {
            let (p, m) = s.totals();
            return p == m;
        }
        self.coboundary(s).iter().all(|(_, p, m)| p == m)
    }

    /// The topological edit check (TM §XI): for every cell c of dimension k, `B(c)` is a
    /// (k-1)-circuit (k >= 1, (7:5)) and `G(c)` a (k+1)-cocircuit (k < n, (7:6)).
    /// Boundaries are checked first, then coboundaries; returns the first cell that fails,
    /// in index order, with the place where it fails. All defects: [`TmModel::edit_defects`].
    ///
    /// Away from the two ends the conditions meet: `at` is unbalanced in `B(B(c))` exactly
    /// when `c` is unbalanced in `G(G(at))` (the same products of incidences), so a k-cell
    /// failing (7:5) at a (k-2)-cell comes with that cell failing (7:6). The ends stand
    /// alone: (7:5) on 1-cells (each edge has a from and a to vertex) and (7:6) on
    /// (n-1)-cells (each has an n-cell on each side; free faces of an open model and
    /// twisted gluings fail it; [`TmModel::try_close_with_exterior`] closes an open model).
    /// O(Σ |B²(c)| + |G²(c)|).
    pub fn edit_check(&self) -> Result<(), TmDefect> {
        match self.defects(true).into_iter().next() {
            Some(d) => Err(d),
            None => Ok(()),
        }
    }

    /// Every defect of the edit check: at most one per cell and condition (the first place
    /// where it fails), in the order of [`TmModel::edit_check`] (all (7:5) defects by cell
    /// index, then all (7:6) defects). Empty exactly when the edit check passes.
    pub fn edit_defects(&self) -> Vec<TmDefect> {
        self.defects(false)
    }

    fn defects(&self, first_only: bool) -> Vec<TmDefect> {
        let mut out = Vec::new();
        for c in 0..self.len() {
            let k = self.cell_dim(c);
            if k == 0 {
                continue;
            }
            if let Some((at, plus, minus)) = self.unbalanced(c, k == 1, |x| self.boundary(x)) {
                out.push(TmDefect::BoundaryNotCircuit { cell: self.id(c), dim: k, at: self.id(at), plus, minus });
                if first_only {
                    return out;
                }
            }
        }
        for c in 0..self.len() {
            let k = self.cell_dim(c);
            if k >= self.dim() {
                continue;
            }
            if let Some((at, plus, minus)) = self.unbalanced(c, k + 1 == self.dim(), |x| self.coboundary(x)) {
                out.push(TmDefect::CoboundaryNotCocircuit { cell: self.id(c), dim: k, at: self.id(at), plus, minus });
                if first_only {
                    return out;
                }
            }
        }
        out
    }

    /// Where the image of cell `c` under `step` is not a circuit: with `ends`, the image is
    /// a set of end cells whose coefficients must cancel (reported at `c` itself); else the
    /// first cell occurring unequally often with each sign in the image of the image.
    fn unbalanced(&self, c: usize, ends: bool, step: impl Fn(&SignedSet) -> SignedSet) -> Option<(usize, u64, u64)> {
        let image = step(&SignedSet::cell(c));
        if ends {
            let (p, m) = image.totals();
            (p != m).then_some((c, p, m))
        } else {
            step(&image).iter().find(|&(_, p, m)| p != m)
        }
    }
}
