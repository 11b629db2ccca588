//! Smith normal form of a dense integer matrix by working modulo a multiple of its largest
//! invariant factor, so that no entry grows beyond that modulus.
//!
//! Eliminating over `Z` directly ([`crate::engine::snf`]) lets the entries of a dense
//! matrix grow exponentially in its size (a random 140 × 140 matrix of entries in `-3..=3`
//! takes seconds, a 240 × 240 one minutes). Here:
//! 1. the rank `r` of the matrix and a non-singular `r × r` minor are found by elimination
//!    modulo word-size primes whose product exceeds Hadamard's bound `H` on every minor: a
//!    prime where the rank drops divides every `r × r` minor, and they cannot all divide
//!    one that is at most `H`, so the largest rank seen is the rank over `Z`;
//! 2. the determinant `D` of that minor is rebuilt from its residues (Chinese remainders).
//!    The product `d_1 ⋯ d_r` of the invariant factors divides every `r × r` minor, so
//!    each `d_i` divides `D`;
//! 3. the matrix is diagonalised over `Z / M` with `M = 2|D|`, by unimodular row and column
//!    operations (extended gcd), all reduced modulo `M`. The Smith form of `A` reduced
//!    modulo `M` is that of `Z / M`, whose entries are `gcd(d_i, M) = d_i` (since
//!    `d_i ≤ |D| < M`) for `i ≤ r` and `M` (zero) beyond;
//! 4. the diagonal becomes the chain `d_1 | d_2 | …` by gcd / lcm exchanges.
//!
//! Cost: O((rows · cols · r) · (log H / 61)) word operations for steps 1 and 2 and
//! O(rows · cols · r) operations on integers of `log M ≤ log H + 1` bits for step 3.

use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::engine::ring::Zp;

/// The invariant factors `d_1 | … | d_r` (positive, units included) of a dense `rows × cols`
/// matrix given row by row, `r` its rank. `None` only if an internal check fails.
pub(crate) fn smith_diagonal_modular(a: &[Vec<BigInt>], cols: usize) -> Option<Vec<BigInt>> {
    let rows = a.len();
    if rows == 0 || cols == 0 {
        return Some(Vec::new());
    }
    let bound = hadamard_bits(a, cols);
    // primes above 2^61 whose product exceeds 2^(bound + 1)
    let primes = primes_below_2_62(bound as usize / 61 + 2);
    // 1. the rank, and the rows and columns of a non-singular minor
    let mut best: Option<(Vec<usize>, Vec<usize>)> = None;
    for &p in &primes {
        let m = reduce_mod(a, cols, p);
        let (r_rows, r_cols) = echelon_pivots(m, cols, p);
        if best.as_ref().is_none_or(|(br, _)| r_rows.len() > br.len()) {
            best = Some((r_rows, r_cols));
        }
        if best.as_ref().is_some_and(|(br, _)| br.len() == rows.min(cols)) {
            break; // no rank is larger
        }
    }
    let (prow, pcol) = best?;
    let r = prow.len();
    if r == 0 {
        return Some(Vec::new());
    }
    // 2. its determinant, from residues modulo the same primes (their product > 2 H)
    let minor: Vec<Vec<BigInt>> = prow.iter().map(|&i| pcol.iter().map(|&j| a[i][j].clone()).collect()).collect();
    let mut x = BigInt::zero();
    let mut modulus = BigInt::one();
    for &p in &primes {
        let d = det_mod(reduce_mod(&minor, r, p), p);
        // Garner's step: x + modulus * ((d - x) / modulus mod p)
        let xm = mod_u64(&x, p);
        let mm = mod_u64(&modulus, p);
        let k = mul_mod((d + p - xm) % p, inv_mod(mm, p), p);
        x += &modulus * BigInt::from(k);
        modulus *= BigInt::from(p);
    }
    if &x * 2 > modulus {
        x -= &modulus;
    }
    if x.is_zero() {
        return None;
    }
    let m = x.abs() * 2;
    // 3. diagonalise modulo M
    let mut b: Vec<Vec<BigInt>> = a.iter().map(|row| row.iter().map(|v| v.mod_floor(&m)).collect()).collect();
    let mut diag = diagonalise_mod(&mut b, cols, &m);
    // 4. the divisibility chain; zeros are M
    for v in diag.iter_mut() {
        *v = v.gcd(&m);
    }
    invariant_chain(&mut diag);
    let (factors, zeros): (Vec<BigInt>, Vec<BigInt>) = diag.into_iter().partition(|v| v < &m);
    if factors.len() != r || zeros.iter().any(|v| v != &m) {
        return None;
    }
    Some(factors)
}

/// Bits of Hadamard's bound on the absolute value of any minor: the product over the
/// non-zero columns of their Euclidean norms, each at most `2^bits · sqrt(rows)`.
fn hadamard_bits(a: &[Vec<BigInt>], cols: usize) -> u64 {
    let half_log_rows = (usize::BITS - a.len().leading_zeros()) as u64 / 2 + 1;
    let mut total = 0u64;
    for j in 0..cols {
        let bits = a.iter().map(|row| row[j].bits()).max().unwrap_or(0);
        if bits > 0 {
            total = total.saturating_add(bits + half_log_rows);
        }
    }
    total
}

/// `x mod p` in `0..p`.
fn mod_u64(x: &BigInt, p: u64) -> u64 {
    let r = x.mod_floor(&BigInt::from(p));
    r.to_u64().unwrap_or(0)
}

fn reduce_mod(a: &[Vec<BigInt>], cols: usize, p: u64) -> Vec<Vec<u64>> {
    a.iter()
        .map(|row| {
            (0..cols)
                .map(|j| {
                    let v = &row[j];
                    match (v.sign(), v.magnitude().to_u64()) {
                        (Sign::Minus, Some(u)) => (p - u % p) % p,
                        (_, Some(u)) => u % p,
                        _ => mod_u64(v, p),
                    }
                })
                .collect()
        })
        .collect()
}

fn mul_mod(a: u64, b: u64, p: u64) -> u64 {
    Zp { p }.mul(a, b)
}

fn pow_mod(mut a: u64, mut e: u64, p: u64) -> u64 {
    let mut r = 1u64;
    while e > 0 {
        if e & 1 == 1 {
            r = mul_mod(r, a, p);
        }
        a = mul_mod(a, a, p);
        e >>= 1;
    }
    r
}

fn inv_mod(a: u64, p: u64) -> u64 {
    Zp { p }.inv(a)
}

/// Whether `n` is prime: Miller–Rabin with the first twelve primes as bases, exact for
/// every `u64`.
fn is_prime_u64(n: u64) -> bool {
    const BASES: [u64; 12] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37];
    if n < 2 {
        return false;
    }
    for b in BASES {
        if n.is_multiple_of(b) {
            return n == b;
        }
    }
    let s = (n - 1).trailing_zeros();
    let d = (n - 1) >> s;
    'bases: for b in BASES {
        let mut x = pow_mod(b, d, n);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = mul_mod(x, x, n);
            if x == n - 1 {
                continue 'bases;
            }
        }
        return false;
    }
    true
}

/// The `k` largest primes below 2^62 (each above 2^61).
fn primes_below_2_62(k: usize) -> Vec<u64> {
    let mut out = Vec::with_capacity(k);
    let mut n = (1u64 << 62) - 1;
    while out.len() < k {
        if is_prime_u64(n) {
            out.push(n);
        }
        n -= 2;
    }
    out
}

/// Row echelon form modulo `p`: the pivot rows (original indices) and pivot columns.
fn echelon_pivots(mut m: Vec<Vec<u64>>, cols: usize, p: u64) -> (Vec<usize>, Vec<usize>) {
    let rows = m.len();
    let mut order: Vec<usize> = (0..rows).collect();
    let (mut prow, mut pcol) = (Vec::new(), Vec::new());
    let mut t = 0;
    for j in 0..cols {
        if t == rows {
            break;
        }
        let Some(i) = (t..rows).find(|&i| m[i][j] != 0) else { continue };
        m.swap(t, i);
        order.swap(t, i);
        clear_below(&mut m, t, j, p);
        prow.push(order[t]);
        pcol.push(j);
        t += 1;
    }
    (prow, pcol)
}

/// The determinant of a square matrix modulo `p`, in `0..p`.
fn det_mod(mut m: Vec<Vec<u64>>, p: u64) -> u64 {
    let n = m.len();
    let mut det = 1u64;
    for j in 0..n {
        let Some(i) = (j..n).find(|&i| m[i][j] != 0) else { return 0 };
        if i != j {
            m.swap(i, j);
            det = (p - det) % p;
        }
        det = mul_mod(det, m[j][j], p);
        clear_below(&mut m, j, j, p);
    }
    det
}

/// Subtracts multiples of row `t` (pivot in column `j`, non-zero) from the rows below it so
/// that column `j` is zero there, modulo the prime `p`.
fn clear_below(m: &mut [Vec<u64>], t: usize, j: usize, p: u64) {
    let inv = inv_mod(m[t][j], p);
    let (top, rest) = m.split_at_mut(t + 1);
    let pivot = &top[t];
    for row in rest.iter_mut() {
        if row[j] != 0 {
            let f = mul_mod(row[j], inv, p);
            for (x, &y) in row.iter_mut().zip(pivot.iter()).skip(j) {
                *x = (*x + p - mul_mod(f, y, p)) % p;
            }
        }
    }
}

/// Diagonalises `b` (entries in `0..m`) over `Z / m` by unimodular integer operations and
/// returns its diagonal (`min(rows, cols)` entries, zeros included).
fn diagonalise_mod(b: &mut [Vec<BigInt>], cols: usize, m: &BigInt) -> Vec<BigInt> {
    let rows = b.len();
    let n = rows.min(cols);
    let mut diag = Vec::with_capacity(n);
    for t in 0..n {
        // the first non-zero entry of the remaining block, column by column
        let at = (t..cols).find_map(|j| (t..rows).find(|&i| !b[i][j].is_zero()).map(|i| (i, j)));
        let Some((i, j)) = at else {
            diag.extend(std::iter::repeat_n(BigInt::zero(), n - t));
            break;
        };
        b.swap(t, i);
        for row in b.iter_mut() {
            row.swap(t, j);
        }
        loop {
            let column_clean = clear_column(b, t, cols, m);
            if clear_row(b, t, cols, m) && column_clean {
                break;
            }
        }
        diag.push(b[t][t].clone());
    }
    diag
}

/// A unimodular operation on two lines (rows or columns) `p` (the pivot's) and `r` that
/// makes the entry `y` of `r` zero against the entry `x` of `p`.
enum Step {
    /// `r -= q p` when `x` divides `y`
    Sub(BigInt),
    /// `[s u; -y/g x/g]` (determinant 1, `s x + u y = g`), sending `(x, y)` to `(g, 0)`
    Gcd { s: BigInt, u: BigInt, xg: BigInt, yg: BigInt },
}

impl Step {
    fn new(x: &BigInt, y: &BigInt) -> Step {
        if (y % x).is_zero() {
            Step::Sub(y / x)
        } else {
            let e = x.extended_gcd(y);
            Step::Gcd { xg: x / &e.gcd, yg: y / &e.gcd, s: e.x, u: e.y }
        }
    }

    /// The new entries of the two lines at one position, reduced modulo `m`.
    fn apply(&self, p: &BigInt, r: &BigInt, m: &BigInt) -> (Option<BigInt>, BigInt) {
        match self {
            Step::Sub(q) => (None, (r - q * p).mod_floor(m)),
            Step::Gcd { s, u, xg, yg } => (Some((s * p + u * r).mod_floor(m)), (xg * r - yg * p).mod_floor(m)),
        }
    }
}

/// Makes column `t` zero below the pivot by row operations; whether it was already zero.
fn clear_column(b: &mut [Vec<BigInt>], t: usize, cols: usize, m: &BigInt) -> bool {
    let mut clean = true;
    for i in t + 1..b.len() {
        if b[i][t].is_zero() {
            continue;
        }
        clean = false;
        let (top, rest) = b.split_at_mut(t + 1);
        let (pivot_row, row) = (&mut top[t], &mut rest[i - t - 1]);
        let step = Step::new(&pivot_row[t], &row[t]);
        for c in t..cols {
            let (np, nr) = step.apply(&pivot_row[c], &row[c], m);
            if let Some(np) = np {
                pivot_row[c] = np;
            }
            row[c] = nr;
        }
    }
    clean
}

/// Makes row `t` zero right of the pivot by column operations; whether it was already zero.
fn clear_row(b: &mut [Vec<BigInt>], t: usize, cols: usize, m: &BigInt) -> bool {
    let mut clean = true;
    for j in t + 1..cols {
        if b[t][j].is_zero() {
            continue;
        }
        clean = false;
        let step = Step::new(&b[t][t], &b[t][j]);
        for row in b.iter_mut().skip(t) {
            let (np, nr) = step.apply(&row[t], &row[j], m);
            if let Some(np) = np {
                row[t] = np;
            }
            row[j] = nr;
        }
    }
    clean
}

/// Turns a list of positive integers into the invariant factors of the diagonal matrix
/// they make (each dividing the next) by gcd / lcm exchanges. O(k²) gcds, units skipped.
fn invariant_chain(v: &mut [BigInt]) {
    for i in 0..v.len() {
        for j in i + 1..v.len() {
            if v[i].is_one() {
                break;
            }
            if (&v[j] % &v[i]).is_zero() {
                continue;
            }
            let g = v[i].gcd(&v[j]);
            let l = &v[i] / &g * &v[j];
            v[i] = g;
            v[j] = l;
        }
    }
    v.sort();
}

#[cfg(test)]
mod tests;
