//! Euler–Poincaré vectors (AC §4–5): changes of cell counts and Betti numbers.
//!
//! An n-dimensional complex has a *configuration* `(v_0, …, v_n; b_0, …, b_n)`: its cell
//! (region) counts and Betti numbers. The Euler–Poincaré formula (AC Thm. 2.1, Cor. 3.11)
//! says that every configuration lies on the hyperplane `Σ (-1)^i (x_i - y_i) = 0` of
//! `Z^{n+1} × Z^{n+1}` (the *Euler–Poincaré hyperplane*, AC Def. 4.1). A vector of that
//! hyperplane is an *Euler–Poincaré operator*: adding it to a configuration describes a
//! change of the complex that keeps the formula true (AC §5), such as the change made by an
//! Euler operator on a map ([`EpVector::between`] two configurations).
//!
//! [`EpVector`] holds such a vector `(ΔX_0..ΔX_n; ΔY_0..ΔY_n)`. It tests membership in the
//! hyperplane ([`EpVector::is_operator`]) and in the Euler–Poincaré space of non-negative
//! configurations ([`EpVector::is_configuration`]), and expands an operator in the two bases
//! of the paper:
//! * `K_i = X_i - (-1)^i X_0` (i = 1..n) and `L_j = Y_j + (-1)^j X_0` (j = 0..n), AC (4)–(5);
//! * `A_i = X_i - Y_{i-1}` (i = 1..n, make an i-cell and kill an (i-1)-hole) and
//!   `B_j = X_j + Y_j` (j = 0..n, make a j-cell and a j-hole), AC Prop. 5.2, the
//!   *elementary* operators ([`EpVector::expand_ab`], named by [`EpVector::basis_name`]).
//!
//! All arithmetic is checked: an overflow is reported as [`EpError::Overflow`], never wrapped.
//! The polynomial view of AC §6 and the names of the elementary operators live with the
//! architectural complexes, in `gmap_homology::ep`.
//!
//! ```
//! use gmap_core::ep_vector::EpVector;
//! // make an edge and a loop in a surface complex (n = 2)
//! let meml = EpVector::b(2, 1);
//! assert!(meml.is_operator());
//! assert_eq!(meml.to_string(), "X_1 + Y_1");
//! let e = meml.expand_ab().unwrap();
//! assert_eq!(e.delta, vec![0, 1, 0]);
//! assert_eq!(e.recombine(2).unwrap(), meml);
//! // inserting a vertex in an edge: one more vertex, one more edge, same homology
//! let v = EpVector::from_cells(&[1, 1, 0]);
//! assert_eq!(v.basis_name(), "B0 + A1");
//! ```

use std::fmt;

use thiserror::Error;

/// Why an Euler–Poincaré computation failed.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum EpError {
    /// The vector does not satisfy `Σ (-1)^i (x_i - y_i) = 0`; `defect` is that sum.
    #[error("not an Euler-Poincaré operator: the alternating sum Σ(-1)^i(x_i - y_i) is {defect}, not 0")]
    NotOnHyperplane {
        /// the alternating sum
        defect: i128,
    },
    /// The two halves of the vector, or two vectors combined, have different lengths.
    #[error("dimension mismatch: {left} against {right} coordinates")]
    DimensionMismatch {
        /// coordinates on the left
        left: usize,
        /// coordinates on the right
        right: usize,
    },
    /// A polynomial of degree above `2n + 1` cannot be a vector of dimension n.
    #[error("polynomial of degree {degree} does not fit dimension {n} (at most {max})")]
    DegreeTooHigh {
        /// its degree
        degree: usize,
        /// the dimension
        n: usize,
        /// `2n + 1`
        max: usize,
    },
    /// An intermediate value left the range of `i64`.
    #[error("integer overflow in an Euler-Poincaré computation")]
    Overflow,
}

/// An element `(ΔX_0..ΔX_n; ΔY_0..ΔY_n)` of `Z^{n+1} × Z^{n+1}` (AC §4).
///
/// `x[i]` counts i-regions (i-cells) made (negative: killed), `y[j]` counts j-dimensional
/// holes (the j-th Betti number) made. Invariant: `x.len() == y.len() >= 1`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct EpVector {
    x: Vec<i64>,
    y: Vec<i64>,
}

/// Coefficients of an operator in the basis `K_1..K_n, L_0..L_n` (AC (4)–(6)).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct KlExpansion {
    /// `alpha[i - 1]` is the coefficient of `K_i`, i = 1..n
    pub alpha: Vec<i64>,
    /// `beta[j]` is the coefficient of `L_j`, j = 0..n
    pub beta: Vec<i64>,
}

/// Coefficients of an operator in the elementary basis `A_1..A_n, B_0..B_n` (AC Prop. 5.2).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AbExpansion {
    /// `gamma[i - 1]` is the coefficient of `A_i = X_i - Y_{i-1}`, i = 1..n
    pub gamma: Vec<i64>,
    /// `delta[j]` is the coefficient of `B_j = X_j + Y_j`, j = 0..n
    pub delta: Vec<i64>,
}

/// Checked arithmetic of the Euler–Poincaré computations: an overflow is
/// [`EpError::Overflow`], never a wrapped value.
pub mod checked {
    use super::EpError;

    /// `a * b`.
    pub fn mul(a: i64, b: i64) -> Result<i64, EpError> {
        a.checked_mul(b).ok_or(EpError::Overflow)
    }

    /// `a + b`.
    pub fn add(a: i64, b: i64) -> Result<i64, EpError> {
        a.checked_add(b).ok_or(EpError::Overflow)
    }

    /// `a - b`.
    pub fn sub(a: i64, b: i64) -> Result<i64, EpError> {
        a.checked_sub(b).ok_or(EpError::Overflow)
    }

    /// `(-1)^i`.
    pub fn sign(i: usize) -> i64 {
        if i.is_multiple_of(2) {
            1
        } else {
            -1
        }
    }
}

use checked::{add, mul, sign, sub};

impl EpVector {
    /// The zero vector of dimension `n` (`n + 1` coordinates on each side).
    pub fn zero(n: usize) -> Self {
        EpVector { x: vec![0; n + 1], y: vec![0; n + 1] }
    }

    /// A vector from its two halves; they must have the same non-zero length.
    pub fn try_new(x: Vec<i64>, y: Vec<i64>) -> Result<Self, EpError> {
        if x.len() != y.len() || x.is_empty() {
            return Err(EpError::DimensionMismatch { left: x.len(), right: y.len() });
        }
        Ok(EpVector { x, y })
    }

    /// A change of cells with unchanged homology (the `K`-type operators of AC Remark 5.1):
    /// `dx` cells made (negative: removed) per dimension. Panics if `dx` is empty.
    pub fn from_cells(dx: &[i64]) -> Self {
        assert!(!dx.is_empty(), "a configuration has at least dimension 0");
        EpVector { x: dx.to_vec(), y: vec![0; dx.len()] }
    }

    /// The change `after - before` between two configurations, each given as cell counts
    /// and Betti numbers. Panics if the four lengths differ or are 0.
    pub fn between(
        cells_before: &[usize],
        betti_before: &[usize],
        cells_after: &[usize],
        betti_after: &[usize],
    ) -> Self {
        let n1 = cells_before.len();
        assert!(
            n1 > 0 && cells_after.len() == n1 && betti_before.len() == n1 && betti_after.len() == n1,
            "configurations of different dimensions"
        );
        let d = |a: &[usize], b: &[usize]| a.iter().zip(b).map(|(&p, &q)| q as i64 - p as i64).collect();
        EpVector { x: d(cells_before, cells_after), y: d(betti_before, betti_after) }
    }

    /// The unit vector `X_i` ("make an i-dimensional element"). Panics if `i > n`.
    pub fn x_unit(n: usize, i: usize) -> Self {
        assert!(i <= n, "X_{i} does not exist in dimension {n}");
        let mut v = Self::zero(n);
        v.x[i] = 1;
        v
    }

    /// The unit vector `Y_j` ("make a j-dimensional hole"). Panics if `j > n`.
    pub fn y_unit(n: usize, j: usize) -> Self {
        assert!(j <= n, "Y_{j} does not exist in dimension {n}");
        let mut v = Self::zero(n);
        v.y[j] = 1;
        v
    }

    /// `K_i = X_i - (-1)^i X_0`, i = 1..n (AC (4)). Panics if `i == 0` or `i > n`.
    pub fn k(n: usize, i: usize) -> Self {
        assert!((1..=n).contains(&i), "K_{i} does not exist in dimension {n}");
        let mut v = Self::x_unit(n, i);
        v.x[0] -= sign(i);
        v
    }

    /// `L_j = Y_j + (-1)^j X_0`, j = 0..n (AC (5)). Panics if `j > n`.
    pub fn l(n: usize, j: usize) -> Self {
        let mut v = Self::y_unit(n, j);
        v.x[0] += sign(j);
        v
    }

    /// `A_i = X_i - Y_{i-1}`, i = 1..n (AC Prop. 5.2): make an i-element, kill an (i-1)-hole.
    /// Panics if `i == 0` or `i > n`.
    pub fn a(n: usize, i: usize) -> Self {
        assert!((1..=n).contains(&i), "A_{i} does not exist in dimension {n}");
        let mut v = Self::x_unit(n, i);
        v.y[i - 1] = -1;
        v
    }

    /// `B_j = X_j + Y_j`, j = 0..n (AC Prop. 5.2): make a j-element and a j-hole.
    /// Panics if `j > n`.
    pub fn b(n: usize, j: usize) -> Self {
        let mut v = Self::x_unit(n, j);
        v.y[j] = 1;
        v
    }

    /// The dimension n (each half has `n + 1` coordinates).
    pub fn dim(&self) -> usize {
        self.x.len() - 1
    }

    /// The cell part `ΔX_0..ΔX_n`: the change of the number of i-cells.
    pub fn dx(&self) -> &[i64] {
        &self.x
    }

    /// The Betti part `ΔY_0..ΔY_n`: the change of the i-th Betti number.
    pub fn dy(&self) -> &[i64] {
        &self.y
    }

    /// `Σ (-1)^i (x_i - y_i)`, exact (i128 cannot overflow for `n <= 2^60`).
    pub fn euler_defect(&self) -> i128 {
        self.x.iter().zip(&self.y).enumerate().map(|(i, (&a, &b))| sign(i) as i128 * (a as i128 - b as i128)).sum()
    }

    /// Whether the vector lies on the Euler–Poincaré hyperplane (AC Def. 4.1): an operator.
    pub fn is_operator(&self) -> bool {
        self.euler_defect() == 0
    }

    /// [`EpVector::is_operator`] under the name of the hyperplane: whether the change keeps
    /// the Euler–Poincaré formula true.
    pub fn is_on_hyperplane(&self) -> bool {
        self.is_operator()
    }

    /// The change of the Euler characteristic, `Σ (-1)^i ΔX_i`, or `None` on overflow.
    pub fn euler_change(&self) -> Option<i64> {
        self.x.iter().enumerate().try_fold(0i64, |s, (i, &c)| s.checked_add(sign(i).checked_mul(c)?))
    }

    /// Whether the vector lies in the Euler–Poincaré space `𝔼` (AC Def. 4.1): on the
    /// hyperplane with every coordinate non-negative, i.e. a possible configuration.
    pub fn is_configuration(&self) -> bool {
        self.is_operator() && self.x.iter().chain(&self.y).all(|&c| c >= 0)
    }

    /// `Err(NotOnHyperplane)` unless [`EpVector::is_operator`].
    pub fn check_operator(&self) -> Result<(), EpError> {
        match self.euler_defect() {
            0 => Ok(()),
            defect => Err(EpError::NotOnHyperplane { defect }),
        }
    }

    /// `self + k * other`, checked.
    pub fn try_add_scaled(&self, k: i64, other: &EpVector) -> Result<EpVector, EpError> {
        if self.x.len() != other.x.len() {
            return Err(EpError::DimensionMismatch { left: self.x.len(), right: other.x.len() });
        }
        let f = |a: &[i64], b: &[i64]| -> Result<Vec<i64>, EpError> {
            a.iter().zip(b).map(|(&p, &q)| add(p, mul(k, q)?)).collect()
        };
        Ok(EpVector { x: f(&self.x, &other.x)?, y: f(&self.y, &other.y)? })
    }

    /// `self + other`, checked.
    pub fn try_add(&self, other: &EpVector) -> Result<EpVector, EpError> {
        self.try_add_scaled(1, other)
    }

    /// Expansion in `K_i, L_j` (AC (6)): `alpha_i = x_i`, `beta_j = y_j`; the `X_0`
    /// coordinate is then determined by the hyperplane equation. O(n).
    pub fn expand_kl(&self) -> Result<KlExpansion, EpError> {
        self.check_operator()?;
        Ok(KlExpansion { alpha: self.x[1..].to_vec(), beta: self.y.clone() })
    }

    /// Whether the `K/L` coefficients satisfy AC Prop. 4.2: all non-negative and inequality
    /// (7) (the coefficient of `X_0` is non-negative). Equivalent to
    /// [`EpVector::is_configuration`] for operators.
    pub fn satisfies_prop_4_2(&self) -> Result<bool, EpError> {
        let e = self.expand_kl()?;
        if e.alpha.iter().chain(&e.beta).any(|&c| c < 0) {
            return Ok(false);
        }
        let mut s: i128 = 0;
        for (j, &b) in e.beta.iter().enumerate() {
            s += sign(j) as i128 * b as i128;
        }
        for (k, &a) in e.alpha.iter().enumerate() {
            s -= sign(k + 1) as i128 * a as i128;
        }
        Ok(s >= 0)
    }

    /// Expansion in the elementary basis `A_i, B_j` (AC Prop. 5.2), by back substitution:
    /// `δ_0 = x_0`, `γ_i = δ_{i-1} - y_{i-1}`, `δ_i = x_i - γ_i`; the hyperplane equation is
    /// what makes the last equation `δ_n = y_n` hold. O(n). Agrees with the closed forms of
    /// AC Props. 6.7 and 6.13 (`gmap_homology::ep::Poly::expand_ab`).
    pub fn expand_ab(&self) -> Result<AbExpansion, EpError> {
        self.check_operator()?;
        let n = self.dim();
        let mut gamma = Vec::with_capacity(n);
        let mut delta = Vec::with_capacity(n + 1);
        delta.push(self.x[0]);
        for i in 1..=n {
            let g = sub(delta[i - 1], self.y[i - 1])?;
            gamma.push(g);
            delta.push(sub(self.x[i], g)?);
        }
        debug_assert_eq!(delta[n], self.y[n]);
        Ok(AbExpansion { gamma, delta })
    }

    /// The expansion in the elementary basis `A_i, B_j`, or `None` when the vector is not
    /// an operator (or overflows): [`EpVector::expand_ab`] as an option.
    pub fn basis(&self) -> Option<AbExpansion> {
        self.expand_ab().ok()
    }

    /// The vector written in the elementary basis, lowest dimension first, `B_j` before
    /// `A_{j+1}`: `"B0 + A1"` for "make a vertex, make an edge", `"-A2"` for "kill a face,
    /// make a 1-hole", `"0"` for no change, `"off hyperplane"` when the vector is not an
    /// Euler–Poincaré operator.
    pub fn basis_name(&self) -> String {
        let Some(c) = self.basis() else {
            return "off hyperplane".to_string();
        };
        let mut terms: Vec<(i64, String)> = Vec::new();
        for (j, &d) in c.delta.iter().enumerate() {
            if d != 0 {
                terms.push((d, format!("B{j}")));
            }
            if let Some(&g) = c.gamma.get(j).filter(|&&g| g != 0) {
                terms.push((g, format!("A{}", j + 1)));
            }
        }
        if terms.is_empty() {
            return "0".to_string();
        }
        let mut s = String::new();
        for (k, (coef, name)) in terms.iter().enumerate() {
            match (k, *coef < 0) {
                (0, true) => s.push('-'),
                (0, false) => {}
                (_, true) => s.push_str(" - "),
                (_, false) => s.push_str(" + "),
            }
            if coef.unsigned_abs() != 1 {
                s.push_str(&coef.unsigned_abs().to_string());
            }
            s.push_str(name);
        }
        s
    }

    /// The coordinates as `(ΔX_0, …, ΔX_n; ΔY_0, …, ΔY_n)`, e.g. `(1, 1; 0, 0)` (the
    /// [`Display`](fmt::Display) of the vector writes it in the `X_i, Y_j` basis instead).
    pub fn coordinates(&self) -> Coordinates<'_> {
        Coordinates(self)
    }
}

/// The coordinates of an [`EpVector`], written `(1, 1; 0, 0)`: see [`EpVector::coordinates`].
#[derive(Clone, Copy, Debug)]
pub struct Coordinates<'a>(&'a EpVector);

impl fmt::Display for Coordinates<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let list = |v: &[i64]| v.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", ");
        write!(f, "({}; {})", list(&self.0.x), list(&self.0.y))
    }
}

impl KlExpansion {
    /// `Σ alpha_i K_i + Σ beta_j L_j` in dimension n, checked.
    pub fn recombine(&self, n: usize) -> Result<EpVector, EpError> {
        let mut v = EpVector::zero(n);
        for (k, &a) in self.alpha.iter().enumerate() {
            v = v.try_add_scaled(a, &EpVector::k(n, k + 1))?;
        }
        for (j, &b) in self.beta.iter().enumerate() {
            v = v.try_add_scaled(b, &EpVector::l(n, j))?;
        }
        Ok(v)
    }
}

impl AbExpansion {
    /// `Σ gamma_i A_i + Σ delta_j B_j` in dimension n, checked.
    pub fn recombine(&self, n: usize) -> Result<EpVector, EpError> {
        let mut v = EpVector::zero(n);
        for (k, &g) in self.gamma.iter().enumerate() {
            v = v.try_add_scaled(g, &EpVector::a(n, k + 1))?;
        }
        for (j, &d) in self.delta.iter().enumerate() {
            v = v.try_add_scaled(d, &EpVector::b(n, j))?;
        }
        Ok(v)
    }
}

fn term(f: &mut fmt::Formatter<'_>, first: &mut bool, c: i64, name: &str, idx: usize) -> fmt::Result {
    if c == 0 {
        return Ok(());
    }
    let mag = c.unsigned_abs();
    if *first {
        if c < 0 {
            write!(f, "-")?;
        }
    } else {
        write!(f, " {} ", if c < 0 { '-' } else { '+' })?;
    }
    *first = false;
    if mag != 1 {
        write!(f, "{mag}")?;
    }
    write!(f, "{name}_{idx}")
}

impl fmt::Display for EpVector {
    /// Writes `3X_0 + 2Y_0 - Y_1`; the zero vector is `0`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut first = true;
        for (i, &c) in self.x.iter().enumerate() {
            term(f, &mut first, c, "X", i)?;
        }
        for (j, &c) in self.y.iter().enumerate() {
            term(f, &mut first, c, "Y", j)?;
        }
        if first {
            write!(f, "0")?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display_of_example_8_21() {
        let v = EpVector::try_new(vec![3, 0, 0], vec![2, -1, 0]).unwrap();
        assert_eq!(v.to_string(), "3X_0 + 2Y_0 - Y_1");
        assert!(v.is_operator());
        assert_eq!(EpVector::zero(1).to_string(), "0");
        assert_eq!(EpVector::from_cells(&[1, 1]).coordinates().to_string(), "(1, 1; 0, 0)");
    }

    #[test]
    fn overflow_is_reported() {
        let v = EpVector::try_new(vec![i64::MAX, 0], vec![i64::MAX, 0]).unwrap();
        assert_eq!(v.try_add(&v), Err(EpError::Overflow));
    }

    #[test]
    fn basis_names() {
        // A_1 = X_1 - Y_0: an edge joining two parts; B_1 = X_1 + Y_1: an edge closing a loop
        assert_eq!(EpVector::a(2, 1).basis_name(), "A1");
        assert_eq!(EpVector::b(2, 1).basis_name(), "B1");
        // kill an edge and a face: -(B_1 + A_2)
        assert_eq!(EpVector::from_cells(&[0, -1, -1]).basis_name(), "-B1 - A2");
        // L_2 = Y_2 + X_0 = B_0 + A_1 - B_1 - A_2 + B_2
        let c = EpVector::l(2, 2).basis().unwrap();
        assert_eq!((c.gamma, c.delta), (vec![1, -1], vec![1, -1, 1]));
        let off = EpVector::from_cells(&[1, 0, 0]);
        assert!(!off.is_on_hyperplane());
        assert_eq!(off.euler_defect(), 1);
        assert_eq!(off.basis_name(), "off hyperplane");
        assert_eq!(EpVector::zero(2).basis_name(), "0");
        assert_eq!(EpVector::from_cells(&[2, 2, 0]).basis_name(), "2B0 + 2A1");
    }

    #[test]
    fn between_two_configurations() {
        let v = EpVector::between(&[4, 4, 1], &[1, 0, 0], &[1, 2, 1], &[1, 2, 1]);
        assert_eq!((v.dx(), v.dy()), (&[-3, -2, 0][..], &[0, 2, 1][..]));
        assert!(v.is_on_hyperplane());
        assert_eq!(v.try_add_scaled(-1, &v), Ok(EpVector::zero(2)));
        assert_eq!(v.euler_change(), Some(-1));
    }
}
