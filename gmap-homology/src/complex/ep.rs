//! Euler–Poincaré operators (AC §4–7).
//!
//! An n-dimensional complex has a *configuration* `(v_0, …, v_n; b_0, …, b_n)`: its region
//! counts and Betti numbers. The Euler–Poincaré formula (AC Thm. 2.1, Cor. 3.11) says that
//! every configuration lies on the hyperplane `Σ (-1)^i (x_i - y_i) = 0` of
//! `Z^{n+1} × Z^{n+1}` (the *Euler–Poincaré hyperplane*, AC Def. 4.1). A vector of that
//! hyperplane is an *Euler–Poincaré operator*: adding it to a configuration describes a
//! change of the complex that keeps the formula true (AC §5).
//!
//! [`EpVector`] holds such a vector `(ΔX_0..ΔX_n; ΔY_0..ΔY_n)`. It tests membership in the
//! hyperplane ([`EpVector::is_operator`]) and in the Euler–Poincaré space of non-negative
//! configurations ([`EpVector::is_configuration`]), and expands an operator in the two bases
//! of the paper:
//! * `K_i = X_i - (-1)^i X_0` (i = 1..n) and `L_j = Y_j + (-1)^j X_0` (j = 0..n), AC (4)–(5);
//! * `A_i = X_i - Y_{i-1}` (i = 1..n) and `B_j = X_j + Y_j` (j = 0..n), AC Prop. 5.2, whose
//!   members are the *elementary* operators ("make edge, kill component", "make vertex and
//!   component", …; see [`elementary_operators`]).
//!
//! The polynomial view (AC §6) maps `X_i` to `X^i` and `Y_j` to `X^{n+1+j}`; [`Poly`]
//! implements it with the membership tests of AC Prop. 6.1 / Lemma 6.3 and the closed-form
//! expansions of AC Prop. 6.7 (n even) and Prop. 6.13 (n odd).
//!
//! All arithmetic is checked: an overflow is reported as [`EpError::Overflow`], never wrapped.
//!
//! ```
//! use gmap_homology::ep::EpVector;
//! // make an edge and a loop in a surface complex (n = 2)
//! let meml = EpVector::b(2, 1);
//! assert!(meml.is_operator());
//! assert_eq!(meml.to_string(), "X_1 + Y_1");
//! let e = meml.expand_ab().unwrap();
//! assert_eq!(e.delta, vec![0, 1, 0]);
//! assert_eq!(e.recombine(2).unwrap(), meml);
//! ```

use std::fmt;

use thiserror::Error;

/// Why an Euler–Poincaré computation failed.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
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

fn mul(a: i64, b: i64) -> Result<i64, EpError> {
    a.checked_mul(b).ok_or(EpError::Overflow)
}

fn add(a: i64, b: i64) -> Result<i64, EpError> {
    a.checked_add(b).ok_or(EpError::Overflow)
}

fn sub(a: i64, b: i64) -> Result<i64, EpError> {
    a.checked_sub(b).ok_or(EpError::Overflow)
}

fn sign(i: usize) -> i64 {
    if i.is_multiple_of(2) {
        1
    } else {
        -1
    }
}

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

    /// The region part `ΔX_0..ΔX_n`.
    pub fn x(&self) -> &[i64] {
        &self.x
    }

    /// The Betti part `ΔY_0..ΔY_n`.
    pub fn y(&self) -> &[i64] {
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
    /// [`Poly::expand_ab`] (AC Props. 6.7, 6.13).
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

    /// The polynomial of AC (9): `X_i ↦ X^i`, `Y_j ↦ X^{n+1+j}`.
    pub fn to_poly(&self) -> Poly {
        let mut c = self.x.clone();
        c.extend_from_slice(&self.y);
        Poly::new(c)
    }

    /// The vector of dimension `n` of a polynomial of degree at most `2n + 1`.
    pub fn from_poly(p: &Poly, n: usize) -> Result<EpVector, EpError> {
        if let Some(d) = p.degree() {
            if d > 2 * n + 1 {
                return Err(EpError::DegreeTooHigh { degree: d, n, max: 2 * n + 1 });
            }
        }
        let mut c = vec![0i64; 2 * n + 2];
        for (i, &a) in p.coeffs().iter().enumerate() {
            c[i] = a;
        }
        let y = c.split_off(n + 1);
        Ok(EpVector { x: c, y })
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

/// An integer polynomial `Σ c_i X^i` (AC §6), coefficients from degree 0 up, with no
/// trailing zeros (the zero polynomial has no coefficient).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Poly(Vec<i64>);

impl Poly {
    /// The polynomial with these coefficients (trailing zeros are dropped).
    pub fn new(mut c: Vec<i64>) -> Self {
        while c.last() == Some(&0) {
            c.pop();
        }
        Poly(c)
    }

    /// The monomial `X^k`.
    pub fn monomial(k: usize) -> Self {
        let mut c = vec![0; k + 1];
        c[k] = 1;
        Poly(c)
    }

    /// The coefficients, lowest degree first.
    pub fn coeffs(&self) -> &[i64] {
        &self.0
    }

    /// The coefficient of `X^k` (0 beyond the degree).
    pub fn coeff(&self, k: usize) -> i64 {
        self.0.get(k).copied().unwrap_or(0)
    }

    /// The degree, `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.0.len().checked_sub(1)
    }

    /// `F(-1)`, checked.
    pub fn at_minus_one(&self) -> Result<i64, EpError> {
        let mut s = 0i64;
        for (i, &c) in self.0.iter().enumerate() {
            s = add(s, mul(sign(i), c)?)?;
        }
        Ok(s)
    }

    /// The product, checked. O(deg² ).
    pub fn try_mul(&self, other: &Poly) -> Result<Poly, EpError> {
        if self.0.is_empty() || other.0.is_empty() {
            return Ok(Poly(Vec::new()));
        }
        let mut c = vec![0i64; self.0.len() + other.0.len() - 1];
        for (i, &a) in self.0.iter().enumerate() {
            for (j, &b) in other.0.iter().enumerate() {
                c[i + j] = add(c[i + j], mul(a, b)?)?;
            }
        }
        Ok(Poly::new(c))
    }

    /// The sum, checked.
    pub fn try_add(&self, other: &Poly) -> Result<Poly, EpError> {
        let len = self.0.len().max(other.0.len());
        let c = (0..len).map(|k| add(self.coeff(k), other.coeff(k))).collect::<Result<Vec<_>, _>>()?;
        Ok(Poly::new(c))
    }

    /// Division by `X + 1`: the quotient and the remainder `F(-1)` (synthetic division).
    pub fn div_by_x_plus_one(&self) -> Result<(Poly, i64), EpError> {
        if self.0.is_empty() {
            return Ok((Poly(Vec::new()), 0));
        }
        let d = self.0.len() - 1;
        let mut q = vec![0i64; d];
        let mut carry = 0i64;
        for k in (0..=d).rev() {
            let v = add(self.0[k], carry)?;
            if k == 0 {
                return Ok((Poly::new(q), v));
            }
            q[k - 1] = v;
            carry = v.checked_neg().ok_or(EpError::Overflow)?;
        }
        unreachable!("the loop returns at k = 0")
    }

    /// Membership of the polynomial of an n-vector in `f(𝔈) = 𝔍` (AC Prop. 6.1, Lemma 6.3):
    /// for n even, `F(-1) = 0` (F is a multiple of `X + 1`); for n odd,
    /// `F - 2 Σ_{i<=n} (-1)^i α_i` is divisible by `X + 1`. Fails if the degree exceeds `2n+1`.
    pub fn is_operator(&self, n: usize) -> Result<bool, EpError> {
        if let Some(d) = self.degree() {
            if d > 2 * n + 1 {
                return Err(EpError::DegreeTooHigh { degree: d, n, max: 2 * n + 1 });
            }
        }
        if n.is_multiple_of(2) {
            Ok(self.div_by_x_plus_one()?.1 == 0)
        } else {
            let mut s = 0i64;
            for i in 0..=n {
                s = add(s, mul(sign(i), self.coeff(i))?)?;
            }
            let shifted = self.try_add(&Poly::new(vec![mul(-2, s)?]))?;
            Ok(shifted.div_by_x_plus_one()?.1 == 0)
        }
    }

    /// The expansion of an operator polynomial in `A_i, B_j` by the closed forms of
    /// AC Prop. 6.7 (n even) and Prop. 6.13 (n odd):
    /// `γ_i = (-1)^i Σ_{ℓ=i}^{n} (-1)^ℓ (α_ℓ - α_{n+1+ℓ})`, `δ_j = α_j - γ_j` (1 <= j < n),
    /// `δ_0 = α_0`, `δ_n = α_{2n+1}`. Fails unless [`Poly::is_operator`]. O(n²).
    pub fn expand_ab(&self, n: usize) -> Result<AbExpansion, EpError> {
        if !self.is_operator(n)? {
            let v = EpVector::from_poly(self, n)?;
            return Err(EpError::NotOnHyperplane { defect: v.euler_defect() });
        }
        let a = |k: usize| self.coeff(k);
        let mut gamma = Vec::with_capacity(n);
        for i in 1..=n {
            let mut s = 0i64;
            for l in i..=n {
                s = add(s, mul(sign(l), sub(a(l), a(n + 1 + l))?)?)?;
            }
            gamma.push(mul(sign(i), s)?);
        }
        let mut delta = Vec::with_capacity(n + 1);
        delta.push(a(0));
        for j in 1..n {
            delta.push(sub(a(j), gamma[j - 1])?);
        }
        if n > 0 {
            delta.push(a(2 * n + 1));
        }
        Ok(AbExpansion { gamma, delta })
    }
}

impl fmt::Display for Poly {
    /// Writes `1 - X^2 + 3X^5`; the zero polynomial is `0`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut first = true;
        for (k, &c) in self.0.iter().enumerate() {
            if c == 0 {
                continue;
            }
            let mag = c.unsigned_abs();
            if first {
                if c < 0 {
                    write!(f, "-")?;
                }
            } else {
                write!(f, " {} ", if c < 0 { '-' } else { '+' })?;
            }
            first = false;
            match k {
                0 => write!(f, "{mag}")?,
                _ => {
                    if mag != 1 {
                        write!(f, "{mag}")?;
                    }
                    if k == 1 {
                        write!(f, "X")?;
                    } else {
                        write!(f, "X^{k}")?;
                    }
                }
            }
        }
        if first {
            write!(f, "0")?;
        }
        Ok(())
    }
}

/// Which elementary operator of AC Prop. 5.2.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Elementary {
    /// `A_i = X_i - Y_{i-1}`, i >= 1: make an i-element, kill an (i-1)-hole
    A(usize),
    /// `B_j = X_j + Y_j`: make a j-element and a j-hole
    B(usize),
}

/// One elementary Euler–Poincaré operator with its names (AC §7).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ElementaryOperator {
    /// which one
    pub which: Elementary,
    /// its vector
    pub vector: EpVector,
    /// mnemonic in the style of Euler operators: `mvmc`, `meml`, `mekc`, …
    pub mnemonic: String,
    /// description in words: "make edge, kill component"
    pub description: String,
}

/// The word for an i-dimensional element: vertex, edge, area, volume, then "i-cell".
pub fn element_name(i: usize) -> String {
    match i {
        0 => "vertex".into(),
        1 => "edge".into(),
        2 => "area".into(),
        3 => "volume".into(),
        _ => format!("{i}-cell"),
    }
}

/// The word for a j-dimensional hole: component, loop, shell, then "j-hole" (AC §7.3).
pub fn hole_name(j: usize) -> String {
    match j {
        0 => "component".into(),
        1 => "loop".into(),
        2 => "shell".into(),
        _ => format!("{j}-hole"),
    }
}

fn element_code(i: usize) -> String {
    match i {
        0 => "v".into(),
        1 => "e".into(),
        2 => "a".into(),
        3 => "b".into(),
        _ => format!("c{i}"),
    }
}

fn hole_code(j: usize) -> String {
    match j {
        0 => "c".into(),
        1 => "l".into(),
        2 => "s".into(),
        _ => format!("h{j}"),
    }
}

impl ElementaryOperator {
    /// The operator `which` in dimension `n`. Panics if the index is out of range.
    pub fn new(n: usize, which: Elementary) -> Self {
        match which {
            Elementary::A(i) => ElementaryOperator {
                which,
                vector: EpVector::a(n, i),
                mnemonic: format!("m{}k{}", element_code(i), hole_code(i - 1)),
                description: format!("make {}, kill {}", element_name(i), hole_name(i - 1)),
            },
            Elementary::B(j) => ElementaryOperator {
                which,
                vector: EpVector::b(n, j),
                mnemonic: format!("m{}m{}", element_code(j), hole_code(j)),
                description: format!("make {} and {}", element_name(j), hole_name(j)),
            },
        }
    }
}

/// The `2n + 1` elementary operators of dimension n (AC Prop. 5.2, §7): `A_1..A_n`, then
/// `B_0..B_n`. Mnemonics use v/e/a/b (vertex, edge, area, body) for elements and c/l/s
/// (component, loop, shell) for holes: `mvmc = X_0 + Y_0`, `meml = X_1 + Y_1`,
/// `mekc = X_1 - Y_0`.
pub fn elementary_operators(n: usize) -> Vec<ElementaryOperator> {
    let mut v: Vec<ElementaryOperator> = (1..=n).map(|i| ElementaryOperator::new(n, Elementary::A(i))).collect();
    v.extend((0..=n).map(|j| ElementaryOperator::new(n, Elementary::B(j))));
    v
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
    }

    #[test]
    fn division_by_x_plus_one() {
        // 1 + X^3 = (1 + X)(1 - X + X^2)
        let (q, r) = Poly::new(vec![1, 0, 0, 1]).div_by_x_plus_one().unwrap();
        assert_eq!(q, Poly::new(vec![1, -1, 1]));
        assert_eq!(r, 0);
        // 1 - X = -(1 + X) + 2
        let (q, r) = Poly::new(vec![1, -1]).div_by_x_plus_one().unwrap();
        assert_eq!(q, Poly::new(vec![-1]));
        assert_eq!(r, 2);
    }

    #[test]
    fn overflow_is_reported() {
        let v = EpVector::try_new(vec![i64::MAX, 0], vec![i64::MAX, 0]).unwrap();
        assert_eq!(v.try_add(&v), Err(EpError::Overflow));
    }
}
