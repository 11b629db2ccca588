//! The simplicial counterpart of a G-map (BO §6): the oracle for cellular homology.
//!
//! Every dart is an n-simplex with vertices numbered `0..=n` (vertex i stands for the
//! i-cell of the dart's flag). Two darts linked by `alpha_i` share the face without vertex
//! `i`. So the k-simplices with vertex set `S ⊆ {0..n}` (`|S| = k + 1`) are the orbits of
//! `<alpha_j : j ∉ S>`, and the face of such a simplex that omits the m-th element of `S`
//! (in increasing order) is the simplex on `S` minus that element through any of its darts,
//! with sign `(-1)^m`. The result is a Δ-complex whose homology is that of the object for
//! every G-map, whatever its cells look like.
//!
//! Sizes: `Σ_S #orbits`, at most `2^(n+1) N` simplices; time O(2^n N n).
//!
//! [`chain_map_tau`](crate::chain_map_tau) is BO §6's chain map τ from the cellular chains (BO Def. 10) to the
//! chains of this counterpart, with [`ChainMapTau::check_commutes`] testing `c∂ᶜτ = cτ∂ˢ`.

use gmap_core::{AlphaSet, Dart, DenseMap};
use thiserror::Error;

use crate::cellular::border::CellularComplex;
use crate::cellular::oriented::OrientedCells;
use crate::engine::chain::ChainComplex;
use crate::engine::sparse::SparseMatrix;

/// A k-simplex of the simplicial counterpart: its vertex labels and one of its darts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Simplex {
    /// the vertex labels `S` as a bit set (bit i = the i-cell vertex)
    pub labels: u32,
    /// the smallest dart of the `<alpha_j : j ∉ S>`-orbit
    pub dart: Dart,
}

/// The simplicial chain complex with the simplex behind each generator.
#[derive(Clone, Debug)]
pub struct SimplicialComplex {
    /// `∂_1..∂_n`
    pub chain: ChainComplex,
    /// `simplices[k][j]`: the k-simplex of generator j
    pub simplices: Vec<Vec<Simplex>>,
}

/// The subsets of `{0..n}` with `size` elements, as bit sets in increasing order.
fn subsets(n: usize, size: usize) -> Vec<u32> {
    (0u32..(1u32 << (n + 1))).filter(|s| s.count_ones() as usize == size).collect()
}

/// The chain complex of the simplicial counterpart of `map` (BO §6).
///
/// ```
/// use gmap_homology::{homology_z, simplicial_complex};
/// let klein = gmap_core::examples::klein_bottle();
/// let h = homology_z(&simplicial_complex(&klein)).unwrap();
/// assert_eq!(h.to_string(), "(Z, Z + Z/2, 0)");
/// ```
pub fn simplicial_complex(map: &DenseMap) -> ChainComplex {
    simplicial_complex_with_simplices(map).chain
}

/// [`simplicial_complex`], keeping the simplex behind each generator (for generators).
pub fn simplicial_complex_with_simplices(map: &DenseMap) -> SimplicialComplex {
    let n = map.dim();
    let all = AlphaSet::all(n);
    let complement = |s: u32| {
        let mut set = all;
        for i in 0..=n {
            if s & (1 << i) != 0 {
                set = set.without(i);
            }
        }
        set
    };
    // partitions of the previous dimension, with offsets of each subset's block of rows
    let mut prev: Vec<(u32, Vec<u32>, usize)> = Vec::new();
    let mut counts = Vec::with_capacity(n + 1);
    let mut mats = Vec::with_capacity(n);
    let mut simplices = Vec::with_capacity(n + 1);
    for k in 0..=n {
        let mut cur: Vec<(u32, Vec<u32>, usize)> = Vec::new();
        let mut total = 0usize;
        let mut simp = Vec::new();
        for s in subsets(n, k + 1) {
            let p = map.partition(complement(s));
            for &r in &p.reps {
                simp.push(Simplex { labels: s, dart: r });
            }
            let len = p.len();
            cur.push((s, p.of, total));
            total += len;
        }
        if k >= 1 {
            let rows = counts[k - 1];
            let mut col_ptr = Vec::with_capacity(total + 1);
            col_ptr.push(0usize);
            let mut row_idx: Vec<u32> = Vec::with_capacity(total * (k + 1));
            let mut vals: Vec<i64> = Vec::with_capacity(total * (k + 1));
            let mut entries: Vec<(u32, i64)> = Vec::with_capacity(k + 1);
            for x in &simp {
                entries.clear();
                let mut m = 0;
                for i in 0..=n {
                    if x.labels & (1 << i) == 0 {
                        continue;
                    }
                    let face = x.labels & !(1 << i);
                    let (_, of, off) = prev.iter().find(|(t, _, _)| *t == face).expect("face subset present");
                    let row = off + of[x.dart.index()] as usize;
                    entries.push((row as u32, if m % 2 == 0 { 1 } else { -1 }));
                    m += 1;
                }
                entries.sort_unstable_by_key(|e| e.0);
                for &(r, v) in &entries {
                    row_idx.push(r);
                    vals.push(v);
                }
                col_ptr.push(row_idx.len());
            }
            mats.push(
                SparseMatrix::try_from_csc(rows, total, col_ptr, row_idx, vals)
                    .expect("faces with different labels are different simplices"),
            );
        }
        counts.push(total);
        simplices.push(simp);
        prev = cur;
    }
    let chain = ChainComplex::try_new_unchecked_dd(counts, mats).expect("shapes follow the counts");
    debug_assert!(chain.check_dd().is_ok(), "simplicial ∂∂ = 0");
    SimplicialComplex { chain, simplices }
}

/// BO §6's chain map τ of a map whose cells pass the cellular method's checks: the
/// cellular chain complex, the simplicial counterpart, and τ in every dimension.
///
/// BO writes maps on the right: `c∂ᶜτ` is τ applied to the border of `c`. The element
/// `b = <alpha_{i+1}..alpha_n>(d)` of `B_i` (BO Def. 3) is the i-simplex of the counterpart
/// with vertices `{0..i}`; τ sends an oriented i-cell to the sum of the simplices of its
/// elements, each with the sign of its darts in the cell (BO Def. 8, as in
/// [`OrientedCells::sign`]). The simplex is taken with its vertices in decreasing order
/// `i, i-1, …, 0`, that is `(-1)^(i(i+1)/2)` times the generator of
/// [`simplicial_complex`] (vertices in increasing order): in that order the face without
/// vertex `i`, BO's face operator `∂_i` (Def. 4), comes with sign `+1`, so that
/// `∂ˢ ∘ τ = τ ∘ ∂ᶜ` holds with the signed incidence numbers of BO Def. 9 as they are. The
/// other faces of the simplices of a cell cancel in pairs (the darts of `b` and
/// `alpha_k(b)`, `k < i`, have opposite signs).
#[derive(Clone, Debug)]
pub struct ChainMapTau {
    /// the cellular chain complex (BO Def. 10), cells named by their smallest dart
    pub cellular: CellularComplex,
    /// the simplicial counterpart, generators as in [`simplicial_complex_with_simplices`]
    pub simplicial: SimplicialComplex,
    /// `tau[i]`: one row per i-simplex, one column per i-cell, `0 <= i <= n`
    pub tau: Vec<SparseMatrix>,
}

/// Where τ fails to commute with the border operators.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum TauError {
    /// `τ_{i-1} ∂ᶜ_i` and `∂ˢ_i τ_i` differ on the column of an i-cell.
    #[error("BO §6: the border of the {dim}-cell of dart {dart} does not commute with τ (c∂ᶜτ != cτ∂ˢ)")]
    NotCommuting {
        /// the dimension i of the cell
        dim: usize,
        /// the smallest dart of the cell
        dart: Dart,
    },
    /// A product overflowed `i64` (impossible for entries of small incidence numbers).
    #[error("BO §6: the product τ∂ in dimension {dim} overflows")]
    Overflow {
        /// the dimension i
        dim: usize,
    },
}

/// `τ_i`: the element of `B_i` numbered `b` (in the order of its smallest dart) is the
/// simplex on `{0..i}` numbered `b` too, since `{0..i}` is the first vertex set of size
/// `i + 1` in the order of [`simplicial_complex_with_simplices`].
pub(crate) fn tau_matrix(map: &DenseMap, cells: &OrientedCells, rows: usize) -> SparseMatrix {
    let i = cells.dim;
    let orient: i64 = if (i * (i + 1) / 2).is_multiple_of(2) { 1 } else { -1 };
    let b = map.partition(AlphaSet::above(i, map.dim()));
    let entries: Vec<(u32, u32, i64)> = b
        .reps
        .iter()
        .enumerate()
        .map(|(e, &r)| (e as u32, cells.cells.of[r.index()], orient * cells.sign(r.get())))
        .collect();
    SparseMatrix::try_from_entries(rows, cells.cells.len(), &entries)
        .expect("one entry per element of B_i, inside the counts of both complexes")
}

impl ChainMapTau {
    /// Checks `c∂ᶜτ = cτ∂ˢ` (BO §6) for every cell `c`: `τ_{i-1} ∂ᶜ_i = ∂ˢ_i τ_i` for
    /// `1 <= i <= n`, naming the first cell (lowest dimension, then smallest dart) where
    /// they differ. O(nnz) per dimension.
    pub fn check_commutes(&self) -> Result<(), TauError> {
        for i in 1..self.tau.len() {
            let left =
                self.tau[i - 1].checked_mul(self.cellular.chain.boundary(i)).ok_or(TauError::Overflow { dim: i })?;
            let right =
                self.simplicial.chain.boundary(i).checked_mul(&self.tau[i]).ok_or(TauError::Overflow { dim: i })?;
            let column = |m: &SparseMatrix, j: usize| {
                let (r, v) = m.col(j);
                let mut c: Vec<(u32, i64)> = r.iter().copied().zip(v.iter().copied()).filter(|e| e.1 != 0).collect();
                c.sort_unstable();
                c
            };
            if let Some(j) = (0..left.cols()).find(|&j| column(&left, j) != column(&right, j)) {
                return Err(TauError::NotCommuting { dim: i, dart: self.cellular.reps[i][j] });
            }
        }
        Ok(())
    }

    /// The image under τ of a cellular i-chain (one coefficient per i-cell, in the order of
    /// `cellular.reps[i]`): one coefficient per i-simplex. Precondition: `i <= n` and the
    /// chain has one entry per i-cell; otherwise `None`, as on overflow. O(cells + simplices).
    pub fn image(&self, i: usize, chain: &[i64]) -> Option<Vec<i64>> {
        let t = self.tau.get(i)?;
        if chain.len() != t.cols() {
            return None;
        }
        let mut out = vec![0i64; t.rows()];
        for (r, c, v) in t.iter() {
            out[r] = out[r].checked_add(v.checked_mul(chain[c])?)?;
        }
        Some(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::homology::homology_z;
    use gmap_core::examples;

    #[test]
    fn counts_and_groups_of_the_bo_examples() {
        let t = simplicial_complex(&examples::torus());
        t.check_dd().unwrap();
        // 8 darts: 1 + 2 + 1 vertices (one per cell), edges per label pair, 8 triangles
        assert_eq!(t.counts()[0], 4);
        assert_eq!(t.counts()[2], 8);
        assert_eq!(homology_z(&t).unwrap().betti, vec![1, 2, 1]);
        let c = simplicial_complex(&examples::cylinder());
        assert_eq!(homology_z(&c).unwrap().betti, vec![1, 1, 0]);
        let k = simplicial_complex(&examples::klein_bottle());
        assert_eq!(homology_z(&k).unwrap().torsion, vec![vec![], vec![2], vec![]]);
    }
}
