//! Euler–Poincaré operators of architectural complexes (AC §4–7).
//!
//! The vector itself, [`EpVector`] with its bases and expansions, is `gmap_core::ep_vector`'s,
//! re-exported here; this module adds what the architectural complexes need of it:
//!
//! * the polynomial view of AC §6, which maps `X_i` to `X^i` and `Y_j` to `X^{n+1+j}`
//!   ([`EpPolynomial`], [`Poly`]), with the membership tests of AC Prop. 6.1 / Lemma 6.3 and
//!   the closed-form expansions of AC Prop. 6.7 (n even) and Prop. 6.13 (n odd);
//! * the names of the elementary operators ("make edge, kill component", `mekc`, …; see
//!   [`elementary_operators`]).
//!
//! All arithmetic is checked: an overflow is reported as [`EpError::Overflow`], never wrapped.
//!
//! ```
//! use gmap_homology::ep::{EpPolynomial, EpVector};
//! // make an edge and a loop in a surface complex (n = 2)
//! let meml = EpVector::b(2, 1);
//! assert!(meml.is_operator());
//! assert_eq!(meml.to_string(), "X_1 + Y_1");
//! let e = meml.expand_ab().unwrap();
//! assert_eq!(e.delta, vec![0, 1, 0]);
//! assert_eq!(meml.to_poly().expand_ab(2).unwrap(), e);
//! ```

use std::fmt;

pub use gmap_core::ep_vector::{AbExpansion, Coordinates, EpError, EpVector, KlExpansion};

use gmap_core::ep_vector::checked::{add, mul, sign, sub};

/// The polynomial view of a vector (AC (9)): `X_i ↦ X^i`, `Y_j ↦ X^{n+1+j}`.
pub trait EpPolynomial: Sized {
    /// The polynomial of the vector.
    fn to_poly(&self) -> Poly;

    /// The vector of dimension `n` of a polynomial of degree at most `2n + 1`.
    fn from_poly(p: &Poly, n: usize) -> Result<Self, EpError>;
}

impl EpPolynomial for EpVector {
    fn to_poly(&self) -> Poly {
        let mut c = self.dx().to_vec();
        c.extend_from_slice(self.dy());
        Poly::new(c)
    }

    fn from_poly(p: &Poly, n: usize) -> Result<EpVector, EpError> {
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
        EpVector::try_new(c, y)
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
    named(i, &["vertex", "edge", "area", "volume"], |i| format!("{i}-cell"))
}

/// The word for a j-dimensional hole: component, loop, shell, then "j-hole" (AC §7.3).
pub fn hole_name(j: usize) -> String {
    named(j, &["component", "loop", "shell"], |j| format!("{j}-hole"))
}

/// The letter of an i-dimensional element in mnemonics: v, e, a, b (body), then "c<i>".
fn element_code(i: usize) -> String {
    named(i, &["v", "e", "a", "b"], |i| format!("c{i}"))
}

/// The letter of a j-dimensional hole in mnemonics: c, l, s, then "h<j>".
fn hole_code(j: usize) -> String {
    named(j, &["c", "l", "s"], |j| format!("h{j}"))
}

/// `names[k]`, or `beyond(k)` past the named dimensions.
fn named(k: usize, names: &[&str], beyond: impl Fn(usize) -> String) -> String {
    names.get(k).map_or_else(|| beyond(k), |s| s.to_string())
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
}
