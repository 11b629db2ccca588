//! Homology groups of a [`ChainComplex`] over `Z` and over `Z/p`.
//!
//! Four stages:
//! 0. `morse` (private) pairs cells by collapses and coreductions over the whole complex at
//!    once — fill-free, so the reduced complex is a restriction of the input — and makes a
//!    cell critical where the sweep gets stuck (fill only in critical rows); on manifolds,
//!    cube grids and simplicial counterparts what is left has as many cells as the Betti
//!    numbers;
//! 1. `reduce` (private) eliminates unit pivots dimension by dimension (coreductions and
//!    collapses first, frozen rows when stuck), leaving a small complex on surviving cells;
//! 2. each matrix of that small complex is reduced again with general unit pivots;
//! 3. what is left (entries that are not units) goes through dense Smith normal form.
//!
//! Over `Z` every step runs in checked `i64`; on the first overflow the whole computation
//! is redone with big integers. Every result is checked against the Euler–Poincaré formula
//! `Σ (-1)^k count(k) = Σ (-1)^k β_k`.

pub use super::field::{is_prime, Prime};
use std::fmt;

use thiserror::Error;

use crate::engine::chain::ChainComplex;
use crate::engine::reduce::{eliminate, Col, Mode};
use crate::engine::ring::{Euclid, Ring, ZBig, Zi64, Zp};
use crate::engine::snf::DenseSmith;

pub use crate::engine::natural::Natural;

/// The coefficients of a homology computation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Coefficients {
    /// the integers
    Integers,
    /// the prime field `Z/p`
    Field(u64),
}

impl fmt::Display for Coefficients {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Coefficients::Integers => write!(f, "Z"),
            Coefficients::Field(p) => write!(f, "Z/{p}"),
        }
    }
}

/// Homology groups `H_0..H_n`: `H_k ≅ Z^betti[k] ⊕ Z/t_1 ⊕ … ⊕ Z/t_m` with
/// `torsion[k] = [t_1, …, t_m]` the invariant factors (each > 1, each dividing the next),
/// exact integers of any size ([`Natural`]). Over `Z/p`, `betti[k]` is the dimension of
/// `H_k` and every `torsion[k]` is empty.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Homology {
    /// the coefficients used
    pub coefficients: Coefficients,
    /// rank (or dimension over `Z/p`) of each `H_k`
    pub betti: Vec<usize>,
    /// invariant factors of the torsion of each `H_k`, ascending
    pub torsion: Vec<Vec<Natural>>,
}

impl Homology {
    /// `H_k` written as `Z^2 + Z/2` (`0` for the trivial group; `Z/p` coefficients give
    /// `(Z/p)^d`).
    pub fn group_string(&self, k: usize) -> String {
        let mut parts = Vec::new();
        let b = self.betti.get(k).copied().unwrap_or(0);
        let free = match self.coefficients {
            Coefficients::Integers => "Z".to_string(),
            Coefficients::Field(p) => format!("(Z/{p})"),
        };
        match b {
            0 => {}
            1 => parts.push(free),
            _ => parts.push(format!("{free}^{b}")),
        }
        if let Some(t) = self.torsion.get(k) {
            for x in t {
                parts.push(format!("Z/{x}"));
            }
        }
        if parts.is_empty() {
            "0".to_string()
        } else {
            parts.join(" + ")
        }
    }

    /// The alternating sum of the Betti numbers.
    pub fn euler_characteristic(&self) -> i64 {
        self.betti.iter().enumerate().map(|(k, &b)| if k % 2 == 0 { b as i64 } else { -(b as i64) }).sum()
    }
}

impl fmt::Display for Homology {
    /// `(Z, Z^2 + Z/2, 0)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "(")?;
        for k in 0..self.betti.len() {
            if k > 0 {
                write!(f, ", ")?;
            }
            write!(f, "{}", self.group_string(k))?;
        }
        write!(f, ")")
    }
}

/// Why a homology computation failed.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum HomologyError {
    /// `p` is not a prime (or is too large: at most 2^31).
    #[error("{0} is not a prime number below 2^31: a field of coefficients needs a prime")]
    NotPrime(u64),
    /// The Euler–Poincaré formula failed: an internal error, reported rather than hidden.
    #[error("Euler–Poincaré check failed: cells give {cells}, Betti numbers give {betti}")]
    EulerPoincare {
        /// alternating sum of the cell counts
        cells: i64,
        /// alternating sum of the Betti numbers
        betti: i64,
    },
    /// Generators asked of a complex whose reduction keeps too many cells with entries in
    /// one dimension.
    #[error("generators are computed when the reduced complex keeps at most {limit} cells with entries per dimension; dimension {dim} keeps {cells}")]
    GeneratorsTooLarge {
        /// the dimension
        dim: usize,
        /// its number of cells
        cells: usize,
        /// the limit
        limit: usize,
    },
    /// Generators whose lifting to the input's cells would take too long (each walks back
    /// over the eliminated pairs of its dimension).
    #[error("lifting {generators} generators to the input's cells would take {steps} steps (limit 10^10)")]
    GeneratorsLiftTooLong {
        /// the generators found on the reduced complex
        generators: usize,
        /// their number times the pairs of their dimensions
        steps: u128,
    },
    /// The generator computation overflowed `i64`.
    #[error("a generator's coefficients overflow i64")]
    GeneratorOverflow,
    /// The dense stage would take more than the memory limit (`--max-memory`).
    #[error(transparent)]
    MemoryLimit(#[from] gmap_core::resources::MemoryLimit),
    /// An internal consistency check failed (a bug, reported rather than a wrong group).
    #[error("internal error in the reduction: {0}")]
    Internal(&'static str),
}

/// Ranks and Smith diagonals of the matrices of a complex, plus surviving-cell counts.
struct Ranks<E> {
    /// `rank[k]` = rank of `∂_k` (index 0 unused, 0)
    rank: Vec<usize>,
    /// non-unit part of the Smith diagonal of each `∂_k` (index 0 unused)
    diag: Vec<Vec<E>>,
}

/// The surviving complex after stage 1: counts and matrices `D_k` (columns, rows renumbered).
pub(crate) struct Survivors<E> {
    /// original ids of the surviving k-cells
    pub cells: Vec<Vec<u32>>,
    /// `d[k]` for k >= 1: columns of `D_k` over `cells[k]`, rows indexing `cells[k-1]`
    pub d: Vec<Vec<Col<E>>>,
}

/// Stage 1 over any ring: unit-pivot elimination dimension by dimension.
pub(crate) fn survivors<R: Euclid>(ring: &R, c: &ChainComplex) -> Option<Survivors<R::E>> {
    let pre = match crate::engine::morse::prereduce(ring, c, true) {
        Some(p) => p,
        // the fill of the critical rows overflowed: the pass without critical cells has none
        None => crate::engine::morse::prereduce(ring, c, false)?,
    };
    let mut s = survivors_of(ring, &pre.chain)?;
    for (k, cells) in s.cells.iter_mut().enumerate() {
        for x in cells.iter_mut() {
            *x = pre.ids[k][*x as usize];
        }
    }
    Some(s)
}

/// A piece of a complex reduced apart from the rest ([`reduce_keeping`]): the surviving
/// cells and the boundary between them.
#[derive(Clone, Debug)]
pub struct Reduced {
    /// the reduced piece (cells renumbered)
    pub chain: ChainComplex,
    /// `ids[k][j]`: the input's number of surviving k-cell `j`, increasing
    pub ids: Vec<Vec<u32>>,
}

/// Reduces the cells of `c` that `keep(k, j)` does not name, over `Z`, by collapses and
/// coreductions (the fill-free pass of [`homology_z`], without its setting aside of one
/// vertex per component): the kept cells are never paired and their columns are kept,
/// the others leave in pairs with a unit entry, and a stuck cell stays. The kept cells
/// must be closed under faces, and no cell that is not kept may have a coface outside `c`:
/// then `c` is a piece of a larger complex that shares only its kept cells with the rest,
/// and the reduced piece glued back in its place gives the same homology (the eliminated
/// pairs are pairs of the larger complex too). Where the fill of the kept rows overflows
/// `i64`, the piece is returned as it is. O(entries + cells + fill in the kept rows).
///
/// ```
/// use gmap_homology::homology::reduce_keeping;
/// use gmap_homology::{ChainComplex, SparseMatrix};
/// // a path v0 - v1 - v2 whose two ends are shared: one edge from end to end is left
/// let d1 = SparseMatrix::try_from_triplets(3, 2, &[(0, 0, -1), (1, 0, 1), (1, 1, -1), (2, 1, 1)]).unwrap();
/// let c = ChainComplex::try_new(vec![3, 2], vec![d1]).unwrap();
/// let r = reduce_keeping(&c, |k, j| k == 0 && j != 1);
/// assert_eq!(r.chain.counts(), &[2, 1]);
/// assert_eq!(r.ids[0], vec![0, 2]);
/// assert_eq!(r.chain.boundary(1).col(0).1.iter().sum::<i64>(), 0);
/// ```
pub fn reduce_keeping(c: &ChainComplex, keep: impl Fn(usize, usize) -> bool) -> Reduced {
    match crate::engine::morse::prereduce_keeping(&Zi64, c, keep) {
        Some(r) => Reduced { chain: r.chain, ids: r.ids },
        None => Reduced { chain: c.clone(), ids: c.counts().iter().map(|&m| (0..m as u32).collect()).collect() },
    }
}

/// Stage 1 proper, on the complex left by the fill-free pass.
fn survivors_of<R: Ring>(ring: &R, c: &ChainComplex) -> Option<Survivors<R::E>> {
    let n1 = c.counts().len();
    let mut elim_col: Vec<Vec<bool>> = c.counts().iter().map(|&m| vec![false; m]).collect();
    let mut elim_row: Vec<Vec<bool>> = elim_col.clone();
    let mut remaining: Vec<Vec<(u32, Col<R::E>)>> = vec![Vec::new(); n1];
    for k in 1..n1 {
        let m = c.boundary(k);
        let mut cols: Vec<Col<R::E>> = Vec::with_capacity(m.cols());
        for j in 0..m.cols() {
            let (ri, rv) = m.col(j);
            let mut col = Vec::with_capacity(ri.len());
            for (&r, &v) in ri.iter().zip(rv) {
                if elim_col[k - 1][r as usize] {
                    continue;
                }
                let x = ring.of_i64(v);
                if !ring.is_zero(&x) {
                    col.push((r, x));
                }
            }
            cols.push(col);
        }
        let res = eliminate(ring, m.rows(), cols, Mode::Freeze)?;
        for &(a, b) in &res.pivots {
            elim_row[k - 1][a as usize] = true;
            elim_col[k][b as usize] = true;
        }
        remaining[k] = res.remaining;
    }
    let mut cells: Vec<Vec<u32>> = Vec::with_capacity(n1);
    let mut index: Vec<Vec<u32>> = Vec::with_capacity(n1);
    for k in 0..n1 {
        let mut ids = Vec::new();
        let mut idx = vec![u32::MAX; c.count(k)];
        for x in 0..c.count(k) {
            if !elim_col[k][x] && !elim_row[k][x] {
                idx[x] = ids.len() as u32;
                ids.push(x as u32);
            }
        }
        cells.push(ids);
        index.push(idx);
    }
    let mut d: Vec<Vec<Col<R::E>>> = vec![Vec::new(); n1];
    for k in 1..n1 {
        let mut by_cell: Vec<Option<Col<R::E>>> = vec![None; cells[k].len()];
        for (id, col) in std::mem::take(&mut remaining[k]) {
            let i = index[k][id as usize];
            if i == u32::MAX {
                continue; // removed as a pivot row one dimension up
            }
            let mut out = Vec::with_capacity(col.len());
            for (r, v) in col {
                let ri = index[k - 1][r as usize];
                if ri == u32::MAX {
                    return None;
                }
                out.push((ri, v));
            }
            by_cell[i as usize] = Some(out);
        }
        let mut cols = Vec::with_capacity(by_cell.len());
        for x in by_cell {
            cols.push(x?);
        }
        d[k] = cols;
    }
    Some(Survivors { cells, d })
}

/// Stages 2 and 3: ranks and non-unit Smith diagonals of the surviving matrices (`None` on
/// overflow). The dense block of each matrix is checked against the memory limit before it
/// is allocated: its entries, a working copy and a residue per entry.
fn ranks<R: Ring>(
    ring: &R,
    s: Survivors<R::E>,
    dense: impl Fn(Vec<Vec<R::E>>, usize) -> Option<Vec<R::E>>,
) -> Result<Option<Ranks<R::E>>, HomologyError> {
    let n1 = s.cells.len();
    let mut rank = vec![0usize; n1];
    let mut diag: Vec<Vec<R::E>> = vec![Vec::new(); n1];
    for (k, cols) in s.d.into_iter().enumerate().skip(1) {
        let rows = s.cells[k - 1].len();
        let Some(res) = eliminate(ring, rows, cols, Mode::General) else { return Ok(None) };
        let mut row_ids: Vec<u32> = res.remaining.iter().flat_map(|(_, c)| c.iter().map(|(r, _)| *r)).collect();
        row_ids.sort_unstable();
        row_ids.dedup();
        let dense_cols: Vec<&Col<R::E>> = res.remaining.iter().map(|(_, c)| c).filter(|c| !c.is_empty()).collect();
        let entry = 2 * std::mem::size_of::<R::E>() as u64 + 16;
        let bytes = (row_ids.len() as u64).checked_mul(dense_cols.len() as u64).and_then(|e| e.checked_mul(entry));
        gmap_core::resources::check_memory(&format!("the dense Smith form of ∂_{k}"), bytes)?;
        let mut block = vec![vec![ring.of_i64(0); dense_cols.len()]; row_ids.len()];
        for (j, c) in dense_cols.iter().enumerate() {
            for (r, v) in c.iter() {
                let Ok(i) = row_ids.binary_search(r) else { return Ok(None) };
                block[i][j] = v.clone();
            }
        }
        let d = if block.is_empty() {
            Vec::new()
        } else {
            match dense(block, dense_cols.len()) {
                Some(d) => d,
                None => return Ok(None),
            }
        };
        rank[k] = res.pivots.len() + d.len();
        diag[k] = d.into_iter().filter(|x| !ring.is_unit(x)).collect();
    }
    Ok(Some(Ranks { rank, diag }))
}

fn assemble(
    c: &ChainComplex,
    coefficients: Coefficients,
    surviving: &[usize],
    rank: &[usize],
    torsion: Vec<Vec<Natural>>,
) -> Result<Homology, HomologyError> {
    let n1 = surviving.len();
    let mut betti = Vec::with_capacity(n1);
    for k in 0..n1 {
        let out = rank[k];
        let inn = if k + 1 < n1 { rank[k + 1] } else { 0 };
        let b = surviving[k].checked_sub(out + inn).ok_or(HomologyError::Internal("rank exceeds cell count"))?;
        betti.push(b);
    }
    let h = Homology { coefficients, betti, torsion };
    let cells = c.euler_characteristic();
    let betti_chi = h.euler_characteristic();
    if cells != betti_chi {
        return Err(HomologyError::EulerPoincare { cells, betti: betti_chi });
    }
    Ok(h)
}

fn integer_homology<R: DenseSmith>(ring: &R, c: &ChainComplex) -> Option<Result<Homology, HomologyError>> {
    integer_homology_with(ring, c, true, &mut Stages::default())
}

/// Where [`homology_z_staged`] spent its time: the sparse reduction (the fill-free pass and
/// the elimination that leaves the cells whose boundaries still interact) and the Smith
/// normal form of the dense blocks that survive it. A run that overflows `i64` and starts
/// again with big integers counts both attempts.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stages {
    /// the sparse reduction
    pub reduction: std::time::Duration,
    /// the Smith normal form of what survives the reduction
    pub smith: std::time::Duration,
}

/// [`integer_homology`], optionally without the fill-free pass (to test that pass).
#[allow(clippy::needless_range_loop)]
fn integer_homology_with<R: DenseSmith>(
    ring: &R,
    c: &ChainComplex,
    prereduce: bool,
    stages: &mut Stages,
) -> Option<Result<Homology, HomologyError>> {
    let t = std::time::Instant::now();
    let s = if prereduce { survivors(ring, c) } else { survivors_of(ring, c) };
    stages.reduction += t.elapsed();
    let s = s?;
    let surviving: Vec<usize> = s.cells.iter().map(Vec::len).collect();
    let t = std::time::Instant::now();
    let r = ranks(ring, s, |block, cols| ring.dense_smith(block, cols));
    stages.smith += t.elapsed();
    let r = match r {
        Ok(r) => r?,
        Err(e) => return Some(Err(e)),
    };
    let n1 = surviving.len();
    let mut torsion = vec![Vec::new(); n1];
    for k in 0..n1 {
        if k + 1 < n1 {
            let mut t: Vec<Natural> = r.diag[k + 1].iter().map(|x| ring.abs_natural(x)).collect();
            t.sort_unstable();
            torsion[k] = t;
        }
    }
    Some(assemble(c, Coefficients::Integers, &surviving, &r.rank, torsion))
}

/// Integer homology of a chain complex: Betti numbers and torsion invariant factors.
///
/// Near-linear in the number of matrix entries on manifold-like complexes (see
/// `reduce` (private)); the dense stage is cubic in the size of what survives. Overflow of
/// `i64` anywhere triggers a full recomputation with big integers.
///
/// ```
/// use gmap_homology::{ChainComplex, SparseMatrix, homology_z};
/// // the projective plane as a CW complex: one cell per dimension, ∂_2 = 2, ∂_1 = 0
/// let d1 = SparseMatrix::zeros(1, 1);
/// let d2 = SparseMatrix::try_from_triplets(1, 1, &[(0, 0, 2)]).unwrap();
/// let c = ChainComplex::try_new(vec![1, 1, 1], vec![d1, d2]).unwrap();
/// let h = homology_z(&c).unwrap();
/// assert_eq!(h.betti, vec![1, 0, 0]);
/// assert_eq!(h.torsion, vec![vec![], vec![2], vec![]]);
/// assert_eq!(h.to_string(), "(Z, Z/2, 0)");
/// ```
pub fn homology_z(c: &ChainComplex) -> Result<Homology, HomologyError> {
    if let Some(r) = integer_homology(&Zi64, c) {
        return r;
    }
    integer_homology(&ZBig, c).unwrap_or(Err(HomologyError::Internal("big-integer reduction failed")))
}

/// [`homology_z`], with the time of its two stages ([`Stages`]): what `gmap bench` reports.
///
/// ```
/// use gmap_homology::{homology_z_staged, ChainComplex, SparseMatrix};
/// let d1 = SparseMatrix::zeros(1, 1);
/// let d2 = SparseMatrix::try_from_triplets(1, 1, &[(0, 0, 2)]).unwrap();
/// let c = ChainComplex::try_new(vec![1, 1, 1], vec![d1, d2]).unwrap();
/// let (h, _stages) = homology_z_staged(&c);
/// assert_eq!(h.unwrap().to_string(), "(Z, Z/2, 0)");
/// ```
pub fn homology_z_staged(c: &ChainComplex) -> (Result<Homology, HomologyError>, Stages) {
    let mut stages = Stages::default();
    let h = match integer_homology_with(&Zi64, c, true, &mut stages) {
        Some(r) => r,
        None => integer_homology_with(&ZBig, c, true, &mut stages)
            .unwrap_or(Err(HomologyError::Internal("big-integer reduction failed"))),
    };
    (h, stages)
}

/// Integer homology computed with big integers throughout (slow; for tests of the fall-back).
pub fn homology_z_bigint(c: &ChainComplex) -> Result<Homology, HomologyError> {
    integer_homology(&ZBig, c).unwrap_or(Err(HomologyError::Internal("big-integer reduction failed")))
}

/// Homology over the prime field `Z/p` (`p` prime, below 2^31): dimensions of `H_k`.
///
/// ```
/// use gmap_homology::{ChainComplex, SparseMatrix, homology_zp};
/// let d1 = SparseMatrix::zeros(1, 1);
/// let d2 = SparseMatrix::try_from_triplets(1, 1, &[(0, 0, 2)]).unwrap();
/// let c = ChainComplex::try_new(vec![1, 1, 1], vec![d1, d2]).unwrap();
/// assert_eq!(homology_zp(&c, 2).unwrap().betti, vec![1, 1, 1]);
/// assert_eq!(homology_zp(&c, 3).unwrap().betti, vec![1, 0, 0]);
/// assert!(homology_zp(&c, 4).is_err());
/// ```
pub fn homology_zp(c: &ChainComplex, p: u64) -> Result<Homology, HomologyError> {
    let p = Prime::new(p).ok_or(HomologyError::NotPrime(p))?.get();
    let ring = Zp { p };
    let s = survivors(&ring, c).ok_or(HomologyError::Internal("field reduction failed"))?;
    let surviving: Vec<usize> = s.cells.iter().map(Vec::len).collect();
    // over a field every non-zero entry is a unit, so stage 2 leaves nothing dense
    let r = ranks(&ring, s, |block, _| if block.iter().flatten().all(|&x| x == 0) { Some(Vec::new()) } else { None })?
        .ok_or(HomologyError::Internal("field reduction left a non-zero block"))?;
    let torsion = vec![Vec::new(); surviving.len()];
    assemble(c, Coefficients::Field(p), &surviving, &r.rank, torsion)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::engine::sparse::SparseMatrix;

    /// A complex from cell counts and `(row, col, value)` triplets per boundary matrix.
    pub(crate) fn complex(counts: Vec<usize>, mats: Vec<Vec<(usize, usize, i64)>>) -> ChainComplex {
        let b = mats
            .iter()
            .enumerate()
            .map(|(i, t)| SparseMatrix::try_from_triplets(counts[i], counts[i + 1], t).unwrap())
            .collect();
        ChainComplex::try_new(counts, b).unwrap()
    }

    #[test]
    fn klein_bottle_cw() {
        // one vertex, edges a b, face a b a^-1 b: ∂2 = (0, 2)
        let c = complex(vec![1, 2, 1], vec![vec![], vec![(1, 0, 2)]]);
        let h = homology_z(&c).unwrap();
        assert_eq!(h.betti, vec![1, 1, 0]);
        assert_eq!(h.torsion, vec![vec![], vec![2], vec![]]);
        assert_eq!(h.group_string(1), "Z + Z/2");
        assert_eq!(homology_z_bigint(&c).unwrap(), h);
        assert_eq!(homology_zp(&c, 2).unwrap().betti, vec![1, 2, 1]);
    }

    #[test]
    fn torsion_invariant_factors() {
        // ∂2 = diag(2, 3) on two edges and two faces: Z/6, not Z/2 + Z/3
        let c = complex(vec![1, 2, 2], vec![vec![], vec![(0, 0, 2), (1, 1, 3)]]);
        let h = homology_z(&c).unwrap();
        assert_eq!(h.torsion[1], vec![6]);
        let c = complex(vec![1, 2, 2], vec![vec![], vec![(0, 0, 2), (1, 1, 4)]]);
        assert_eq!(homology_z(&c).unwrap().torsion[1], vec![2, 4]);
    }

    #[test]
    fn overflowing_entries_fall_back_to_big_integers() {
        // ∂2 = [[2, -2^62], [1, 2^62]]: eliminating the unit overflows i64; det = 3 * 2^62
        let big = 1i64 << 62;
        let c = complex(vec![1, 2, 2], vec![vec![], vec![(0, 0, 2), (0, 1, -big), (1, 0, 1), (1, 1, big)]]);
        assert!(integer_homology(&Zi64, &c).is_none());
        let h = homology_z(&c).unwrap();
        assert_eq!(h.betti, vec![1, 0, 0]);
        assert_eq!(h.torsion, vec![vec![], vec![13_835_058_055_282_163_712], vec![]]);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// The fill-free pass changes nothing: random simplicial complexes (triangles on
        /// seven vertices and all their faces) have the same groups with and without it.
        #[test]
        fn prereduction_keeps_the_groups(tris in proptest::collection::vec((0u32..7, 0u32..7, 0u32..7), 0..18)) {
            let c = random_complex(&tris);
            let with = integer_homology_with(&Zi64, &c, true, &mut Stages::default()).unwrap().unwrap();
            let without = integer_homology_with(&Zi64, &c, false, &mut Stages::default()).unwrap().unwrap();
            proptest::prop_assert_eq!(with, without);
        }
    }

    /// The simplicial chain complex of the closure of some triangles.
    pub(crate) fn random_complex(tris: &[(u32, u32, u32)]) -> ChainComplex {
        use std::collections::BTreeSet;
        let mut t: BTreeSet<[u32; 3]> = BTreeSet::new();
        for &(a, b, c) in tris {
            let mut v = [a, b, c];
            v.sort_unstable();
            if v[0] != v[1] && v[1] != v[2] {
                t.insert(v);
            }
        }
        let mut e: BTreeSet<[u32; 2]> = BTreeSet::new();
        let mut vs: BTreeSet<u32> = BTreeSet::new();
        for x in &t {
            e.insert([x[0], x[1]]);
            e.insert([x[1], x[2]]);
            e.insert([x[0], x[2]]);
        }
        for x in &e {
            vs.insert(x[0]);
            vs.insert(x[1]);
        }
        vs.insert(0);
        let vs: Vec<u32> = vs.into_iter().collect();
        let e: Vec<[u32; 2]> = e.into_iter().collect();
        let t: Vec<[u32; 3]> = t.into_iter().collect();
        let vi = |v: u32| vs.binary_search(&v).unwrap();
        let ei = |a: u32, b: u32| e.binary_search(&[a, b]).unwrap();
        let mut d1 = Vec::new();
        for (j, x) in e.iter().enumerate() {
            d1.push((vi(x[0]), j, -1));
            d1.push((vi(x[1]), j, 1));
        }
        let mut d2 = Vec::new();
        for (j, x) in t.iter().enumerate() {
            d2.push((ei(x[1], x[2]), j, 1));
            d2.push((ei(x[0], x[2]), j, -1));
            d2.push((ei(x[0], x[1]), j, 1));
        }
        complex(vec![vs.len(), e.len(), t.len()], vec![d1, d2])
    }

    #[test]
    fn primes() {
        assert!(is_prime(2) && is_prime(3) && is_prime(65537));
        assert!(!is_prime(0) && !is_prime(1) && !is_prime(4) && !is_prime(91));
    }
}
