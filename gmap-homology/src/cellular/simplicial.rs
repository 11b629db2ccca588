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

use gmap_core::{AlphaSet, Dart, DenseMap};

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
