//! Representative cycles: one chain of cells for each cyclic summand of each `H_k`.
//!
//! Two stages:
//!
//! 1. the fill-free reduction of `morse` (private) (collapses, coreductions, critical cells)
//!    shrinks the complex — on manifolds and cube grids to as many cells as the Betti
//!    numbers — and records the pairs it eliminated;
//! 2. on the small complex left, Smith normal form of `∂_{k+1}` with the row operations
//!    tracked gives a basis `P` of `C_k` in which the boundaries are `d_i P_i` (i < rank).
//!    Each `P_i` with `|d_i| > 1` is a cycle generating a summand `Z/d_i`; the cycles in the
//!    span of the remaining columns, found as the integer kernel of `∂_k P_{≥ rank}` by column
//!    reduction, generate the free part.
//!
//! Each cycle found is then lifted back through the eliminated pairs (the chain map of each
//! reduction, `morse` (private)) to a chain of the input's cells in the same class, and checked
//! to be a cycle of the input before it is returned. A cell of the small complex on no entry
//! (its boundary zero, in no boundary) is a generator by itself; stage 2 sees the others. It
//! is dense — O(m^3) for m cells of a dimension — so it is limited to
//! [`GENERATOR_CELL_LIMIT`] cells with entries per dimension *after* stage 1; stage 1 is
//! near-linear, and the lifting costs the log of stage 1 per generator.

#![allow(clippy::needless_range_loop)] // row and column operations index two rows at once

use crate::engine::chain::ChainComplex;
use crate::engine::field::Prime;
use crate::engine::homology::HomologyError;
use crate::engine::morse::{lift, prereduce};
use crate::engine::natural::Natural;
use crate::engine::ring::{Euclid, ZBig, Zi64, Zp};
use crate::engine::snf::smith_tracked;

/// Largest number of cells with entries in one dimension of the reduced complex for which
/// generators are computed (the dense stage's size; cells on no entry do not count).
pub const GENERATOR_CELL_LIMIT: usize = 2000;

/// The most steps of lifting (a generator times the eliminated pairs of its dimension) done
/// before [`HomologyError::GeneratorsLiftTooLong`]: about ten seconds.
pub const LIFT_WORK_LIMIT: u128 = 10_000_000_000;

/// A representative cycle of one cyclic summand of `H_dim`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Generator {
    /// the dimension k of the homology group
    pub dim: usize,
    /// the order of the summand: 0 for `Z` (or the field), `t > 1` for `Z/t`, exact at
    /// any size
    pub order: Natural,
    /// the cycle: `(k-cell index, coefficient)`, non-zero coefficients, increasing cells
    pub chain: Vec<(u32, i64)>,
}

/// Representative cycles of all summands of `H_0..H_n`, over `Z` (`field = None`) or over
/// `Z/p`: `betti[k]` free ones and one per torsion coefficient, in that order per dimension.
/// Over `Z/p` the coefficients are given in `0..p`.
///
/// ```
/// use gmap_homology::{cellular_complex, generators::generators};
/// let c = cellular_complex(&gmap_core::examples::klein_bottle()).unwrap();
/// let g = generators(&c.chain, None).unwrap();
/// let orders: Vec<(usize, u64)> = g.iter().map(|x| (x.dim, x.order.to_u64().unwrap())).collect();
/// assert_eq!(orders, vec![(0, 0), (1, 0), (1, 2)]);
/// ```
pub fn generators(c: &ChainComplex, field: Option<u64>) -> Result<Vec<Generator>, HomologyError> {
    generators_within(c, field, GENERATOR_CELL_LIMIT)
}

/// [`generators`] with another limit on the cells with entries per dimension of the reduced complex
/// (the dense elimination costs O(cells³) per dimension: 2,000 cells take well under a
/// second, 20,000 minutes).
pub fn generators_within(c: &ChainComplex, field: Option<u64>, limit: usize) -> Result<Vec<Generator>, HomologyError> {
    match field {
        // machine words first; big integers where they overflow (a torsion coefficient or an
        // intermediate entry past `i64`)
        None => match reduced_then_lifted(&Zi64, c, limit) {
            Err(HomologyError::GeneratorOverflow) => reduced_then_lifted(&ZBig, c, limit),
            other => other,
        },
        Some(p) => {
            let p = Prime::new(p).ok_or(HomologyError::NotPrime(p))?.get();
            reduced_then_lifted(&Zp { p }, c, limit)
        }
    }
}

/// Stage 1, stage 2 on what is left, and the lifting with its cycle check.
fn reduced_then_lifted<R: Euclid>(ring: &R, c: &ChainComplex, limit: usize) -> Result<Vec<Generator>, HomologyError> {
    let pre = prereduce(ring, c, true).or_else(|| prereduce(ring, c, false)).ok_or(HomologyError::GeneratorOverflow)?;
    let (linked, isolated) = split_isolated(&pre.chain)?;
    for k in 0..linked.complex.counts().len() {
        if linked.complex.count(k) > limit {
            return Err(HomologyError::GeneratorsTooLarge { dim: k, cells: linked.complex.count(k), limit });
        }
    }
    // the cells on no entry are cycles that bound nothing, a free summand each; the dense
    // stage sees the others only
    let dense = compute(ring, &linked.complex).unwrap_or(Err(HomologyError::GeneratorOverflow))?;
    let mut small: Vec<Generator> = Vec::with_capacity(dense.len() + isolated.iter().map(Vec::len).sum::<usize>());
    for (k, cells) in isolated.iter().enumerate() {
        small.extend(cells.iter().map(|&j| Generator { dim: k, order: Natural::from(0u64), chain: vec![(j, 1)] }));
        small.extend(dense.iter().filter(|g| g.dim == k && g.order == 0).map(|g| linked.renumbered(g)));
        small.extend(dense.iter().filter(|g| g.dim == k && g.order != 0).map(|g| linked.renumbered(g)));
    }
    // each lifting walks back over the pairs of its dimension: refused up front past a few
    // seconds of that work rather than run for hours
    let pairs = pre.pairs_per_dimension();
    let work: u128 = small.iter().map(|g| pairs.get(g.dim).copied().unwrap_or(0) as u128).sum();
    if work > LIFT_WORK_LIMIT {
        return Err(HomologyError::GeneratorsLiftTooLong { generators: small.len(), steps: work });
    }
    let mut out = Vec::with_capacity(small.len());
    for g in small {
        let chain: Vec<(u32, R::E)> = g.chain.iter().map(|&(j, v)| (j, ring.of_i64(v))).collect();
        let pairs_k = pairs.get(g.dim).copied().unwrap_or(0);
        let lifted = lift(ring, c, &pre, g.dim, pairs_k, &chain).ok_or(HomologyError::GeneratorOverflow)?;
        if !is_cycle(ring, c, g.dim, &lifted).ok_or(HomologyError::GeneratorOverflow)? {
            return Err(HomologyError::Internal("a lifted generator is not a cycle"));
        }
        let mut ints = Vec::with_capacity(lifted.len());
        for (j, v) in lifted {
            ints.push((j, ring.to_i64(&v).ok_or(HomologyError::GeneratorOverflow)?));
        }
        out.push(Generator { dim: g.dim, order: g.order, chain: ints });
    }
    Ok(out)
}

/// The part of a complex whose cells have an entry (in their column or their row), with the
/// numbers they have in the whole.
struct Linked {
    complex: ChainComplex,
    /// `ids[k][i]`: the number in the whole of the part's k-cell i
    ids: Vec<Vec<u32>>,
}

impl Linked {
    /// A generator of the part, its cells numbered as in the whole.
    fn renumbered(&self, g: &Generator) -> Generator {
        let chain = g.chain.iter().map(|&(i, v)| (self.ids[g.dim][i as usize], v)).collect();
        Generator { dim: g.dim, order: g.order.clone(), chain }
    }
}

/// Splits a complex into the cells with an entry, as a complex of their own, and the others
/// (`isolated[k]`, increasing): the homology is that of the part plus a free summand per
/// isolated cell. O(cells + entries).
fn split_isolated(c: &ChainComplex) -> Result<(Linked, Vec<Vec<u32>>), HomologyError> {
    let n1 = c.counts().len();
    let mut touched: Vec<Vec<bool>> = c.counts().iter().map(|&m| vec![false; m]).collect();
    for k in 1..n1 {
        let b = c.boundary(k);
        for j in 0..b.cols() {
            let (rows, _) = b.col(j);
            if !rows.is_empty() {
                touched[k][j] = true;
                for &r in rows {
                    touched[k - 1][r as usize] = true;
                }
            }
        }
    }
    let mut ids: Vec<Vec<u32>> = Vec::with_capacity(n1);
    let mut isolated: Vec<Vec<u32>> = Vec::with_capacity(n1);
    let mut new_index: Vec<Vec<u32>> = Vec::with_capacity(n1);
    for t in &touched {
        let (mut kept, mut alone, mut index) = (Vec::new(), Vec::new(), vec![u32::MAX; t.len()]);
        for (j, &x) in t.iter().enumerate() {
            if x {
                index[j] = kept.len() as u32;
                kept.push(j as u32);
            } else {
                alone.push(j as u32);
            }
        }
        ids.push(kept);
        isolated.push(alone);
        new_index.push(index);
    }
    let mut boundaries = Vec::with_capacity(n1.saturating_sub(1));
    for k in 1..n1 {
        let b = c.boundary(k);
        let columns: Vec<Vec<(u32, i64)>> = ids[k]
            .iter()
            .map(|&j| {
                let (rows, values) = b.col(j as usize);
                rows.iter().zip(values).map(|(&r, &v)| (new_index[k - 1][r as usize], v)).collect()
            })
            .collect();
        let m = crate::engine::sparse::SparseMatrix::try_from_columns(ids[k - 1].len(), &columns)
            .map_err(|_| HomologyError::Internal("the part of the reduced complex with entries"))?;
        boundaries.push(m);
    }
    let complex = ChainComplex::try_new_unchecked_dd(ids.iter().map(Vec::len).collect(), boundaries)
        .map_err(|_| HomologyError::Internal("the part of the reduced complex with entries"))?;
    Ok((Linked { complex, ids }, isolated))
}

/// Whether a k-chain of `c` has zero boundary over the ring. `None` on overflow.
/// O(e log e) for the e entries of the chain's cells.
fn is_cycle<R: Euclid>(ring: &R, c: &ChainComplex, k: usize, chain: &[(u32, R::E)]) -> Option<bool> {
    if k == 0 {
        return Some(true);
    }
    let m = c.boundary(k);
    let mut terms: Vec<(u32, R::E)> = Vec::new();
    for (j, v) in chain {
        let (ri, rv) = m.col(*j as usize);
        for (&r, &x) in ri.iter().zip(rv) {
            terms.push((r, ring.sub_mul(&ring.of_i64(0), &ring.of_i64(-x), v)?));
        }
    }
    terms.sort_unstable_by_key(|t| t.0);
    let mut i = 0;
    while i < terms.len() {
        let mut sum = ring.of_i64(0);
        let row = terms[i].0;
        while i < terms.len() && terms[i].0 == row {
            sum = ring.sub_mul(&sum, &ring.of_i64(-1), &terms[i].1)?;
            i += 1;
        }
        if !ring.is_zero(&sum) {
            return Some(false);
        }
    }
    Some(true)
}

fn dense<R: Euclid>(ring: &R, c: &ChainComplex, k: usize) -> Vec<Vec<R::E>> {
    let m = c.boundary(k);
    let mut a = vec![vec![ring.of_i64(0); m.cols()]; m.rows()];
    for (i, j, v) in m.iter() {
        a[i][j] = ring.of_i64(v);
    }
    a
}

fn compute<R: Euclid>(ring: &R, c: &ChainComplex) -> Option<Result<Vec<Generator>, HomologyError>> {
    let n1 = c.counts().len();
    let zero = ring.of_i64(0);
    let mut out = Vec::new();
    for k in 0..n1 {
        let m = c.count(k);
        // basis P of C_k (by columns) adapted to the image of ∂_{k+1}
        let mut p: Vec<Vec<R::E>> = (0..m).map(|j| (0..m).map(|i| ring.of_i64(i64::from(i == j))).collect()).collect();
        let diag = if k + 1 < n1 {
            let a = dense(ring, c, k + 1);
            let cols = c.count(k + 1);
            smith_tracked(ring, a, cols, Some(&mut p))?
        } else {
            Vec::new()
        };
        let r = diag.len();
        // free part: kernel of ∂_k restricted to span(P_r..P_m)
        let rest = m - r;
        let mut t: Vec<Vec<R::E>> =
            (0..rest).map(|j| (0..rest).map(|i| ring.of_i64(i64::from(i == j))).collect()).collect();
        let mut mcols: Vec<Vec<R::E>> = Vec::with_capacity(rest);
        if k >= 1 {
            let b = c.boundary(k);
            for col in &p[r..] {
                let mut v = vec![zero.clone(); b.rows()];
                for (i, j, x) in b.iter() {
                    if !ring.is_zero(&col[j]) {
                        let xe = ring.of_i64(x);
                        let nx = ring.sub_mul(&v[i], &ring.sub_mul(&zero, &xe, &ring.of_i64(1))?, &col[j])?;
                        v[i] = nx;
                    }
                }
                mcols.push(v);
            }
        } else {
            mcols = vec![Vec::new(); rest];
        }
        let rows = if k >= 1 { c.count(k - 1) } else { 0 };
        // column reduction of mcols (rest columns of length rows), tracking t
        let mut piv = 0;
        for row in 0..rows {
            loop {
                // smallest non-zero entry in this row among columns piv..
                let mut best: Option<usize> = None;
                for j in piv..rest {
                    if !ring.is_zero(&mcols[j][row])
                        && best.is_none_or(|b| ring.abs_cmp(&mcols[j][row], &mcols[b][row]).is_lt())
                    {
                        best = Some(j);
                    }
                }
                let Some(bj) = best else { break };
                mcols.swap(piv, bj);
                t.swap(piv, bj);
                let mut done = true;
                for j in piv + 1..rest {
                    if ring.is_zero(&mcols[j][row]) {
                        continue;
                    }
                    let (q, _) = ring.div_rem(&mcols[j][row], &mcols[piv][row])?;
                    for i in 0..rows {
                        let v = ring.sub_mul(&mcols[j][i], &q, &mcols[piv][i])?;
                        mcols[j][i] = v;
                    }
                    for i in 0..rest {
                        let v = ring.sub_mul(&t[j][i], &q, &t[piv][i])?;
                        t[j][i] = v;
                    }
                    if !ring.is_zero(&mcols[j][row]) {
                        done = false;
                    }
                }
                if done {
                    piv += 1;
                    break;
                }
            }
            if piv == rest {
                break;
            }
        }
        for tj in &t[piv..] {
            // z = P[:, r..] · t_j
            let mut z = vec![zero.clone(); m];
            for (s, coef) in tj.iter().enumerate() {
                if ring.is_zero(coef) {
                    continue;
                }
                for i in 0..m {
                    let v = ring.sub_mul(&z[i], &ring.sub_mul(&zero, coef, &ring.of_i64(1))?, &p[r + s][i])?;
                    z[i] = v;
                }
            }
            out.push((k, Natural::from(0u64), z));
        }
        for (i, d) in diag.iter().enumerate() {
            if !ring.is_unit(d) {
                out.push((k, ring.abs_natural(d), p[i].clone()));
            }
        }
    }
    // order: per dimension free generators first, then torsion (already so); check cycles
    let mut res = Vec::with_capacity(out.len());
    for (k, order, mut z) in out {
        if k + 1 < n1 {
            reduce_by_single_boundaries(ring, c.boundary(k + 1), &mut z)?;
        }
        if k >= 1 {
            let b = c.boundary(k);
            let mut v = vec![zero.clone(); b.rows()];
            for (i, j, x) in b.iter() {
                let nx = ring.sub_mul(&v[i], &ring.sub_mul(&zero, &ring.of_i64(x), &ring.of_i64(1))?, &z[j])?;
                v[i] = nx;
            }
            if v.iter().any(|x| !ring.is_zero(x)) {
                return Some(Err(HomologyError::Internal("a generator is not a cycle")));
            }
        }
        let mut chain = Vec::new();
        for (i, x) in z.iter().enumerate() {
            if !ring.is_zero(x) {
                chain.push((i as u32, ring.to_i64(x)?));
            }
        }
        res.push(Generator { dim: k, order, chain });
    }
    Some(Ok(res))
}

/// Makes the coefficients of a cycle small without changing its class: where a column of
/// `∂_{k+1}` is `m e_r` (one non-zero entry), `m e_r` is a boundary and the coefficient of
/// `e_r` is reduced modulo `m`. The tracked Smith form gives a torsion generator of `Z/N`
/// coefficients of the size of `N`; on a sum of cyclic summands (a union of lens spaces) this
/// brings them back below the orders of the summands. O(entries of `∂_{k+1}`); `None` on
/// overflow.
fn reduce_by_single_boundaries<R: Euclid>(
    ring: &R,
    b: &crate::engine::sparse::SparseMatrix,
    z: &mut [R::E],
) -> Option<()> {
    for j in 0..b.cols() {
        let (ri, rv) = b.col(j);
        if let ([r], [m]) = (ri, rv) {
            let r = *r as usize;
            if !ring.is_zero(&z[r]) {
                z[r] = ring.div_rem(&z[r], &ring.of_i64(*m))?.1;
            }
        }
    }
    Some(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cellular::checked::cellular_complex;
    use crate::engine::homology::homology_z;
    use gmap_core::examples;

    #[test]
    fn counts_match_the_groups() {
        for m in [examples::torus(), examples::cylinder(), examples::klein_bottle(), examples::fig1_curve()] {
            let c = cellular_complex(&m).unwrap().chain;
            let h = homology_z(&c).unwrap();
            let g = generators(&c, None).unwrap();
            for k in 0..h.betti.len() {
                let free = g.iter().filter(|x| x.dim == k && x.order == 0).count();
                let tors: Vec<Natural> =
                    g.iter().filter(|x| x.dim == k && x.order != 0).map(|x| x.order.clone()).collect();
                assert_eq!(free, h.betti[k]);
                assert_eq!(tors, h.torsion[k]);
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]
        /// On random 2-complexes (closures of triangles on seven vertices) the generators
        /// match the groups over Z and Z/2; each was checked to be a cycle of the input after
        /// lifting (an error otherwise).
        #[test]
        fn random_complexes(tris in proptest::collection::vec((0u32..7, 0u32..7, 0u32..7), 0..18)) {
            let c = crate::engine::homology::tests::random_complex(&tris);
            for field in [None, Some(2)] {
                let h = match field {
                    None => homology_z(&c).unwrap(),
                    Some(p) => crate::engine::homology::homology_zp(&c, p).unwrap(),
                };
                let g = generators(&c, field).unwrap();
                for k in 0..h.betti.len() {
                    proptest::prop_assert_eq!(g.iter().filter(|x| x.dim == k && x.order == 0).count(), h.betti[k]);
                }
            }
        }
    }

    #[test]
    fn klein_bottle_torsion_generator_is_a_loop() {
        let c = cellular_complex(&examples::klein_bottle()).unwrap().chain;
        let g = generators(&c, None).unwrap();
        let t = g.iter().find(|x| x.order == 2).unwrap();
        assert_eq!(t.dim, 1);
        assert_eq!(t.chain.len(), 1);
        assert_eq!(t.chain[0].1.abs(), 1);
        // over Z/2 the Klein bottle has H_1 of dimension 2 and no torsion
        let g2 = generators(&c, Some(2)).unwrap();
        assert_eq!(g2.iter().filter(|x| x.dim == 1).count(), 2);
    }
}
