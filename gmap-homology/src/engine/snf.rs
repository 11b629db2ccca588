//! Dense Smith normal form over `Z`, for the small matrices left after sparse elimination.
//!
//! Generic over the ring so one routine serves checked `i64` (returns `None` on overflow)
//! and big integers (the fall-back). O(r · rows · cols · log(max entry)) for rank r.

#![allow(clippy::needless_range_loop)] // row and column operations index two rows at once

use num_bigint::BigInt;

use crate::engine::ring::{Euclid, ZBig, Zi64, Zp};
use crate::engine::snf_modular::smith_diagonal_modular;

/// The Smith dispatch: how each ring computes the non-zero diagonal of the Smith normal
/// form of a dense matrix given row by row (`None` on overflow). Elimination in the ring
/// ([`smith_diagonal`]) for checked `i64` and `Z/p`; for big integers, elimination modulo a
/// multiple of the largest invariant factor ([`smith_diagonal_modular`]), so no entry grows
/// beyond it (elimination over `Z` lets a dense block's entries explode).
pub(crate) trait DenseSmith: Euclid + Sized {
    /// The non-zero diagonal of the Smith normal form of `a` (`cols` columns).
    fn dense_smith(&self, a: Vec<Vec<Self::E>>, cols: usize) -> Option<Vec<Self::E>> {
        smith_diagonal(self, a, cols)
    }
}

impl DenseSmith for Zi64 {}

impl DenseSmith for Zp {}

impl DenseSmith for ZBig {
    fn dense_smith(&self, a: Vec<Vec<BigInt>>, cols: usize) -> Option<Vec<BigInt>> {
        smith_diagonal_modular(&a, cols)
    }
}

/// The non-zero diagonal of the Smith normal form of a dense `rows × cols` matrix (given
/// row by row): entries `d_1 | d_2 | … | d_r` up to sign, r the rank. `None` on overflow.
pub(crate) fn smith_diagonal<R: Euclid>(ring: &R, a: Vec<Vec<R::E>>, cols: usize) -> Option<Vec<R::E>> {
    smith_tracked(ring, a, cols, None)
}

/// Column `j` of `p` minus `q` times column `i` (`p` stored by columns).
fn col_sub<R: Euclid>(ring: &R, p: &mut [Vec<R::E>], j: usize, q: &R::E, i: usize) -> Option<()> {
    for r in 0..p[j].len() {
        let v = ring.sub_mul(&p[j][r], q, &p[i][r])?;
        p[j][r] = v;
    }
    Some(())
}

/// [`smith_diagonal`], also applying to `left` (a square matrix stored by columns, the
/// basis of the row space) the column operations that undo the row operations: on return,
/// if the input was `A` and `left` was `P`, then `A = P' D V` for some unimodular `V`, with
/// `P'` the returned `left` and `D` the diagonal. So the first `rank` columns of `P'` span,
/// multiplied by the diagonal entries, the column space of `A`.
pub(crate) fn smith_tracked<R: Euclid>(
    ring: &R,
    mut a: Vec<Vec<R::E>>,
    cols: usize,
    mut left: Option<&mut Vec<Vec<R::E>>>,
) -> Option<Vec<R::E>> {
    let rows = a.len();
    let one = ring.of_i64(1);
    let mut diag = Vec::new();
    let mut t = 0;
    while t < rows && t < cols {
        // the smallest non-zero entry of the remaining block goes to (t, t)
        let mut best: Option<(usize, usize)> = None;
        for (i, row) in a.iter().enumerate().skip(t) {
            for (j, x) in row.iter().enumerate().skip(t) {
                if !ring.is_zero(x) && best.is_none_or(|(bi, bj)| ring.abs_cmp(x, &a[bi][bj]).is_lt()) {
                    best = Some((i, j));
                }
            }
        }
        let Some((bi, bj)) = best else { break };
        a.swap(t, bi);
        if let Some(p) = left.as_deref_mut() {
            p.swap(t, bi);
        }
        for row in a.iter_mut() {
            row.swap(t, bj);
        }
        loop {
            // bring the smallest non-zero entry of row t / column t to the pivot
            let mut small = (t, t);
            for i in t + 1..rows {
                if !ring.is_zero(&a[i][t]) && ring.abs_cmp(&a[i][t], &a[small.0][small.1]).is_lt() {
                    small = (i, t);
                }
            }
            for j in t + 1..cols {
                if !ring.is_zero(&a[t][j]) && ring.abs_cmp(&a[t][j], &a[small.0][small.1]).is_lt() {
                    small = (t, j);
                }
            }
            if small.0 != t {
                a.swap(t, small.0);
                if let Some(p) = left.as_deref_mut() {
                    p.swap(t, small.0);
                }
            } else if small.1 != t {
                for row in a.iter_mut() {
                    row.swap(t, small.1);
                }
            }
            let p = a[t][t].clone();
            let mut clean = true;
            for i in t + 1..rows {
                if ring.is_zero(&a[i][t]) {
                    continue;
                }
                let (q, _) = ring.div_rem(&a[i][t], &p)?;
                for j in t..cols {
                    let v = ring.sub_mul(&a[i][j], &q, &a[t][j])?;
                    a[i][j] = v;
                }
                if let Some(l) = left.as_deref_mut() {
                    // row_i -= q row_t  <=>  col_t += q col_i
                    let zero = ring.of_i64(0);
                    let mq = ring.sub_mul(&zero, &q, &one)?;
                    col_sub(ring, l, t, &mq, i)?;
                }
                if !ring.is_zero(&a[i][t]) {
                    clean = false;
                }
            }
            for j in t + 1..cols {
                if ring.is_zero(&a[t][j]) {
                    continue;
                }
                let (q, _) = ring.div_rem(&a[t][j], &p)?;
                for row in a.iter_mut().skip(t) {
                    let v = ring.sub_mul(&row[j], &q, &row[t])?;
                    row[j] = v;
                }
                if !ring.is_zero(&a[t][j]) {
                    clean = false;
                }
            }
            if !clean {
                continue;
            }
            // divisibility: every remaining entry must be a multiple of the pivot
            let mut bad = None;
            'scan: for (i, row) in a.iter().enumerate().skip(t + 1) {
                for x in row.iter().skip(t + 1) {
                    if !ring.is_zero(x) && !ring.is_zero(&ring.div_rem(x, &p)?.1) {
                        bad = Some(i);
                        break 'scan;
                    }
                }
            }
            match bad {
                None => break,
                Some(i) => {
                    for j in t..cols {
                        let v = ring.add(&a[t][j], &a[i][j])?;
                        a[t][j] = v;
                    }
                    if let Some(l) = left.as_deref_mut() {
                        // row_t += row_i  <=>  col_i -= col_t
                        col_sub(ring, l, i, &one, t)?;
                    }
                }
            }
        }
        diag.push(a[t][t].clone());
        t += 1;
    }
    Some(diag)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::ring::{ZBig, Zi64};
    use num_bigint::BigInt;

    #[test]
    fn diagonal_of_known_matrices() {
        let a = vec![vec![2, 4, 4], vec![-6, 6, 12], vec![10, -4, -16]];
        let d: Vec<u64> = smith_diagonal(&Zi64, a, 3).unwrap().iter().map(|x| x.unsigned_abs()).collect();
        assert_eq!(d, vec![2, 6, 12]);
        // diag(2, 3) has Smith form diag(1, 6)
        let d: Vec<u64> =
            smith_diagonal(&Zi64, vec![vec![2, 0], vec![0, 3]], 2).unwrap().iter().map(|x| x.unsigned_abs()).collect();
        assert_eq!(d, vec![1, 6]);
        let big = vec![vec![BigInt::from(4), BigInt::from(0)], vec![BigInt::from(0), BigInt::from(6)]];
        let d: Vec<u64> =
            smith_diagonal(&ZBig, big, 2).unwrap().iter().map(|x| ZBig.abs_natural(x).to_u64().unwrap()).collect();
        assert_eq!(d, vec![2, 12]);
    }
}
