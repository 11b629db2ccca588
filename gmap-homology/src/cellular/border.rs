//! The cellular border operator (BO Def. 10) as sparse matrices.
//!
//! For each dimension i the matrix `∂_i` has one row per (i-1)-cell, one column per i-cell,
//! and the signed incidence numbers (BO Def. 9) as entries. It is built in O(N) per
//! dimension without a per-pair search: for every (i-1)-cell pick one element of `B_{i-1}`
//! (the `<alpha_i..alpha_n>`-orbit of its smallest dart), walk it once, and for each element
//! `e` of `B_i` met there (each `<alpha_{i+1}..alpha_n>`-orbit, once) add `sign_i(e) ·
//! sign_{i-1}` to the entry (cell of `e`, that (i-1)-cell). This is exactly the sum of
//! BO Def. 9 over the face-operator preimage, for all i-cells at once, multi-incidences
//! included. [`crate::cellular::incidence::Incidence`] answers the same question pair by pair.

use gmap_core::{parallel, Dart, DenseMap};

use crate::cellular::incidence::incidence_terms;
use crate::cellular::oriented::OrientedCells;
use crate::engine::chain::{ChainComplex, ChainError};
use crate::engine::sparse::SparseMatrix;

/// The cellular chain complex of a map: the border operator, with each cell named by its
/// smallest dart.
#[derive(Clone, Debug)]
pub struct CellularComplex {
    /// `∂_1..∂_n` over the cells
    pub chain: ChainComplex,
    /// `reps[k][j]`: the smallest dart of k-cell `j`
    pub reps: Vec<Vec<Dart>>,
}

/// The border operator from already oriented cells of every dimension (C1 and C2 assumed).
///
/// Three dimensions have a local formula, read off one dart or one small orbit at a time
/// (each is BO Def. 9 counted from the other side, and agrees with the orbit walk, as the
/// tests check):
///
/// * `∂_1`: an edge has exactly two ends (`<alpha_2..alpha_n>`-orbits swapped by `alpha_0`;
///   one end would contradict C1) and a vertex is a single element of `B_0`, so the column
///   of the edge of dart `r` is `+[vertex of r] - [vertex of alpha_0(r)]`;
/// * `∂_n`: an element of `B_{n-1}` is the `alpha_n`-orbit `{r, alpha_n(r)}` of one dart of
///   the (n-1)-cell, and each of its darts is an element of `B_n`;
/// * `∂_2` of a 3-map: a face meets an edge in `<alpha_0, alpha_3>`-orbits (the sides of the
///   face along the edge); each has one `alpha_3`-pair at each end of the edge, so counting
///   pairs at one end is counting these orbits, each found at its smallest dart.
///
/// Other dimensions (maps of dimension 4 and more) walk one element of `B_{i-1}` per
/// (i-1)-cell. O(N n) for the walks, O(N) for the local formulas, plus O(nnz + cells) to
/// sort the entries by two counting passes.
pub fn border_from_oriented(map: &DenseMap, oriented: &[OrientedCells]) -> CellularComplex {
    let n = map.dim();
    let counts: Vec<usize> = oriented.iter().map(|c| c.cells.len()).collect();
    let matrix = |i: usize| {
        if i == 1 {
            ends(map, &oriented[1], &oriented[0])
        } else if i == n {
            pairs(map, &oriented[n], &oriented[n - 1])
        } else if i == 2 && n == 3 {
            sides(map, &oriented[2], &oriented[1])
        } else {
            let entries = incidence_terms(map, &oriented[i], &oriented[i - 1]);
            SparseMatrix::try_from_entries(counts[i - 1], counts[i], &entries)
                .expect("indices come from partitions of the same map; entries are small")
        }
    };
    // one task per dimension, on as many threads as the setting allows (∂_2, the largest
    // in 3D, is taken second, so it starts at once on a second thread)
    let mats: Vec<SparseMatrix> = parallel::map_tasks(n, map.dart_count(), |t| matrix(t + 1));
    let chain = ChainComplex::try_new_unchecked_dd(counts, mats).expect("shapes follow the cell counts");
    debug_assert_eq!(chain.check_dd(), Ok::<(), ChainError>(()), "∂∂ = 0 under C1");
    let reps = oriented.iter().map(|c| c.cells.reps.clone()).collect();
    CellularComplex { chain, reps }
}

/// The border operator by the orbit walks of BO Def. 9 in every dimension: the reference
/// the local formulas of [`border_from_oriented`] are tested against. O(N n) per dimension.
pub fn border_by_walks(map: &DenseMap, oriented: &[OrientedCells]) -> CellularComplex {
    let n = map.dim();
    let counts: Vec<usize> = oriented.iter().map(|c| c.cells.len()).collect();
    let mats = (1..=n)
        .map(|i| {
            let e = incidence_terms(map, &oriented[i], &oriented[i - 1]);
            SparseMatrix::try_from_entries(counts[i - 1], counts[i], &e).expect("indices from partitions")
        })
        .collect();
    let chain = ChainComplex::try_new_unchecked_dd(counts, mats).expect("shapes follow the cell counts");
    let reps = oriented.iter().map(|c| c.cells.reps.clone()).collect();
    CellularComplex { chain, reps }
}

/// `∂_1` by the two ends of each edge, column by column.
pub(crate) fn ends(map: &DenseMap, edges: &OrientedCells, vertices: &OrientedCells) -> SparseMatrix {
    let nnz = 2 * edges.cells.len();
    SparseMatrix::try_from_column_fn(vertices.cells.len(), edges.cells.len(), nnz, |e, col| {
        let r = edges.cells.reps[e].get();
        let other = map.alpha(Dart::new(r), 0).get();
        for x in [r, other] {
            col.push((vertices.cells.of[x as usize], edges.sign(x) * vertices.sign(x)));
        }
    })
    .expect("indices come from partitions of the same map; entries are small")
}

/// `∂_n` by the `alpha_n`-pair of one dart of each (n-1)-cell: its rows (the columns of its
/// transpose) one by one, then transposed.
pub(crate) fn pairs(map: &DenseMap, top: &OrientedCells, facets: &OrientedCells) -> SparseMatrix {
    let n = map.dim();
    let nnz = 2 * facets.cells.len();
    SparseMatrix::try_from_column_fn(top.cells.len(), facets.cells.len(), nnz, |f, row| {
        let r = facets.cells.reps[f].get();
        let other = map.alpha(Dart::new(r), n).get();
        row.push((top.cells.of[r as usize], top.sign(r) * facets.sign(r)));
        if other != r {
            row.push((top.cells.of[other as usize], top.sign(other) * facets.sign(other)));
        }
    })
    .expect("indices come from partitions of the same map; entries are small")
    .transpose()
}

/// `∂_2` of a 3-map by the `<alpha_0, alpha_3>`-orbits, face by face: each orbit
/// `{x, alpha_0 x, alpha_3 x, alpha_0 alpha_3 x}` has one `alpha_0`-pair in each side of its
/// face, so walking one side (the `<alpha_0, alpha_1>`-ring of the face's smallest dart) meets
/// every orbit of the face once at a positive dart; on a face folded onto itself both pairs
/// lie on that ring, and the orbit is counted at the smaller positive dart. The value is
/// the same at every dart of an orbit (`alpha_0` flips both signs, `alpha_3` keeps both).
/// Built column by column. C1 assumed (no free dart in a face side).
pub(crate) fn sides(map: &DenseMap, faces: &OrientedCells, edges: &OrientedCells) -> SparseMatrix {
    let rows: &[[u32; 4]] = map.flat().as_chunks::<4>().0;
    // a face side's positive darts: half its ring, a quarter of a face with two sides
    let nnz = map.dart_count() / 4;
    SparseMatrix::try_from_column_fn(edges.cells.len(), faces.cells.len(), nnz, |f, col| {
        let r = faces.cells.reps[f].get();
        let a3 = rows[r as usize][3];
        let s = faces.sign(r);
        // the ring's positive darts; the face is folded when alpha_3 maps the ring to itself
        let mut folded = false;
        let mut x = r;
        loop {
            folded |= x == a3 && a3 != r;
            x = rows[rows[x as usize][0] as usize][1];
            if x == r {
                break;
            }
        }
        let mut x = r;
        loop {
            if !folded || rows[x as usize][3] >= x {
                col.push((edges.cells.of[x as usize], s * edges.sign(x)));
            }
            x = rows[rows[x as usize][0] as usize][1];
            if x == r {
                break;
            }
        }
    })
    .expect("indices come from partitions of the same map; entries are small")
}

#[cfg(test)]
mod tests;
