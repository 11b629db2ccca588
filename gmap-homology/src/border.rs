//! The cellular border operator (BO Def. 10) as sparse matrices.
//!
//! For each dimension i the matrix `∂_i` has one row per (i-1)-cell, one column per i-cell,
//! and the signed incidence numbers (BO Def. 9) as entries. It is built in O(N) per
//! dimension without a per-pair search: for every (i-1)-cell pick one element of `B_{i-1}`
//! (the `<alpha_i..alpha_n>`-orbit of its smallest dart), walk it once, and for each element
//! `e` of `B_i` met there (each `<alpha_{i+1}..alpha_n>`-orbit, once) add `sign_i(e) ·
//! sign_{i-1}` to the entry (cell of `e`, that (i-1)-cell). This is exactly the sum of
//! BO Def. 9 over the face-operator preimage, for all i-cells at once, multi-incidences
//! included. [`crate::incidence::Incidence`] answers the same question pair by pair.

use bitvec::vec::BitVec;
use gmap_core::{AlphaSet, DenseMap};

use crate::chain::{ChainComplex, ChainError};
use crate::precond::{check_preconditions, OrientedCells, PreconditionError};
use crate::sparse::SparseMatrix;

/// The cellular chain complex of a map: the border operator, with each cell named by its
/// smallest dart.
#[derive(Clone, Debug)]
pub struct CellularComplex {
    /// `∂_1..∂_n` over the cells
    pub chain: ChainComplex,
    /// `reps[k][j]`: the smallest dart of k-cell `j`
    pub reps: Vec<Vec<u32>>,
}

/// Builds the border operator of `map` after checking C1 and C2 on every cell.
/// O(N n^2) plus, for dimensions 4 and up, the C2 check of each compacted cell.
///
/// ```
/// use gmap_homology::{cellular_complex, homology_z};
/// let torus = gmap_core::examples::torus();
/// let c = cellular_complex(&torus).unwrap();
/// assert_eq!(c.chain.counts(), &[1, 2, 1]);
/// assert_eq!(homology_z(&c.chain).unwrap().betti, vec![1, 2, 1]);
/// // the Klein bottle: its cells are orientable, so the method applies
/// let klein = gmap_core::examples::klein_bottle();
/// assert_eq!(homology_z(&cellular_complex(&klein).unwrap().chain).unwrap().to_string(), "(Z, Z + Z/2, 0)");
/// ```
pub fn cellular_complex(map: &DenseMap) -> Result<CellularComplex, PreconditionError> {
    let oriented = check_preconditions(map)?;
    Ok(border_from_oriented(map, &oriented))
}

/// The border operator from already oriented cells of every dimension (C1 and C2 assumed).
pub fn border_from_oriented(map: &DenseMap, oriented: &[OrientedCells]) -> CellularComplex {
    let n = map.dim();
    let w = n + 1;
    let a = map.flat();
    let counts: Vec<usize> = oriented.iter().map(|c| c.cells.len()).collect();
    let mut mats = Vec::with_capacity(n);
    let mut seen: BitVec = BitVec::repeat(false, map.dart_count());
    let mut orbit: Vec<u32> = Vec::new();
    for i in 1..=n {
        // B_i elements: a dart is the representative of its <alpha_{i+1..n}>-orbit when it is
        // the smallest dart there
        let b_rep: Option<Vec<u32>> = if i == n { None } else { Some(map.partition(AlphaSet::above(i, n)).of) };
        let mut b_seen: Vec<bool> = Vec::new();
        if b_rep.is_some() {
            b_seen = vec![false; map.dart_count()];
        }
        let upper = &oriented[i];
        let lower = &oriented[i - 1];
        let mut trip: Vec<(usize, usize, i64)> = Vec::new();
        for (row, &d0) in lower.cells.reps.iter().enumerate() {
            // walk <alpha_i..alpha_n>(d0)
            orbit.clear();
            orbit.push(d0);
            seen.set(d0 as usize, true);
            let mut k = 0;
            while k < orbit.len() {
                let x = orbit[k] as usize;
                k += 1;
                for j in i..w {
                    let y = a[x * w + j];
                    if !seen[y as usize] {
                        seen.set(y as usize, true);
                        orbit.push(y);
                    }
                }
            }
            let s = lower.sign(d0);
            for &x in &orbit {
                seen.set(x as usize, false);
                let first = match &b_rep {
                    None => true,
                    Some(of) => {
                        let e = of[x as usize] as usize;
                        !std::mem::replace(&mut b_seen[e], true)
                    }
                };
                if first {
                    trip.push((row, upper.cells.of[x as usize] as usize, upper.sign(x) * s));
                }
            }
        }
        let m = SparseMatrix::try_from_triplets(counts[i - 1], counts[i], &trip)
            .expect("indices come from partitions of the same map");
        mats.push(m);
    }
    let chain = ChainComplex::try_new_unchecked_dd(counts, mats).expect("shapes follow the cell counts");
    debug_assert_eq!(chain.check_dd(), Ok::<(), ChainError>(()), "∂∂ = 0 under C1");
    let reps = oriented.iter().map(|c| c.cells.reps.clone()).collect();
    CellularComplex { chain, reps }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::homology::homology_z;
    use crate::incidence::Incidence;
    use gmap_core::{examples, Dart};

    #[test]
    fn matrix_agrees_with_pairwise_incidence() {
        for m in [examples::cylinder(), examples::torus(), examples::klein_bottle()] {
            let c = cellular_complex(&m).unwrap();
            c.chain.check_dd().unwrap();
            let oriented: Vec<_> = (0..=2).map(|i| crate::precond::oriented_cells(&m, i).unwrap()).collect();
            for i in 1..=2 {
                let inc = Incidence::new(&m, i);
                for (col, &cd) in c.reps[i].iter().enumerate() {
                    for (row, &fd) in c.reps[i - 1].iter().enumerate() {
                        let want = inc.signed_with(&oriented[i], &oriented[i - 1], Dart(cd), Dart(fd));
                        assert_eq!(c.chain.boundary(i).get(row, col), want);
                    }
                }
            }
        }
    }

    #[test]
    fn cylinder_homology() {
        let c = cellular_complex(&examples::cylinder()).unwrap();
        assert_eq!(c.chain.counts(), &[2, 3, 1]);
        let h = homology_z(&c.chain).unwrap();
        assert_eq!(h.betti, vec![1, 1, 0]);
    }
}
