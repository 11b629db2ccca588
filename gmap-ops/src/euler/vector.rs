//! Euler–Poincaré vectors (AC §4–5).
//!
//! The configuration of an n-dimensional complex is the point
//! `(V_0, …, V_n; b_0, …, b_n)` of its cell counts and Betti numbers. The Euler–Poincaré
//! formula says that every configuration lies on the hyperplane
//! `Σ (-1)^i (V_i - b_i) = 0` (AC Def. 4.1), so the change made by an operator — the
//! difference of two configurations, an *Euler–Poincaré operator* — lies on it too.
//! [`EpVector`] is that difference. AC Prop. 5.2 gives a basis of the hyperplane,
//! `A_i = X_i - Y_{i-1}` (make an i-cell, kill an (i-1)-hole) for `i = 1..=n` and
//! `B_j = X_j + Y_j` (make a j-cell and a j-hole) for `j = 0..=n`;
//! [`EpVector::basis`] writes a vector in it and [`EpVector::basis_name`] prints it.

use std::fmt;

/// A change of configuration: `dx[i]` is the change in the number of i-cells and
/// `dy[j]` the change of the j-th Betti number (AC §4). Both have length `n + 1`.
///
/// ```
/// use gmap_ops::euler::EpVector;
/// // inserting a vertex in an edge: one more vertex, one more edge, same homology
/// let v = EpVector::from_cells(&[1, 1, 0]);
/// assert!(v.is_on_hyperplane());
/// assert_eq!(v.basis_name(), "B0 + A1");
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct EpVector {
    /// change of the number of i-cells, `i = 0..=n`
    pub dx: Vec<i64>,
    /// change of the i-th Betti number, `i = 0..=n`
    pub dy: Vec<i64>,
}

/// The coordinates of an [`EpVector`] in the basis of AC Prop. 5.2.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EpBasis {
    /// coefficient of `A_i = X_i - Y_{i-1}`, indexed by `i = 1..=n` (entry 0 is always 0)
    pub a: Vec<i64>,
    /// coefficient of `B_j = X_j + Y_j`, `j = 0..=n`
    pub b: Vec<i64>,
}

impl EpVector {
    /// The zero vector of dimension `n` (no change).
    pub fn zero(n: usize) -> Self {
        EpVector { dx: vec![0; n + 1], dy: vec![0; n + 1] }
    }

    /// A change of cells with unchanged homology (the `K`-type operators of AC Remark 5.1).
    pub fn from_cells(dx: &[i64]) -> Self {
        EpVector { dx: dx.to_vec(), dy: vec![0; dx.len()] }
    }

    /// The difference `after - before` of two configurations, each given as cell counts
    /// and Betti numbers. Panics if the lengths differ.
    pub fn between(
        cells_before: &[usize],
        betti_before: &[usize],
        cells_after: &[usize],
        betti_after: &[usize],
    ) -> Self {
        assert!(
            cells_before.len() == cells_after.len()
                && betti_before.len() == betti_after.len()
                && cells_before.len() == betti_before.len(),
            "configurations of different dimensions"
        );
        let d = |a: &[usize], b: &[usize]| a.iter().zip(b).map(|(&x, &y)| y as i64 - x as i64).collect();
        EpVector { dx: d(cells_before, cells_after), dy: d(betti_before, betti_after) }
    }

    /// The dimension n (the vectors have `n + 1` entries).
    pub fn dim(&self) -> usize {
        self.dx.len().saturating_sub(1)
    }

    /// `Σ (-1)^i (dx_i - dy_i)`: zero exactly on the Euler–Poincaré hyperplane.
    pub fn defect(&self) -> i64 {
        let s = |v: &[i64]| v.iter().enumerate().map(|(i, &x)| if i.is_multiple_of(2) { x } else { -x }).sum::<i64>();
        s(&self.dx) - s(&self.dy)
    }

    /// Whether the vector lies on the Euler–Poincaré hyperplane (AC Def. 4.1).
    pub fn is_on_hyperplane(&self) -> bool {
        self.dx.len() == self.dy.len() && self.defect() == 0
    }

    /// The change of the Euler characteristic, `Σ (-1)^i dx_i`.
    pub fn euler_change(&self) -> i64 {
        self.dx.iter().enumerate().map(|(i, &x)| if i.is_multiple_of(2) { x } else { -x }).sum()
    }

    /// The sum of two changes (operators compose by addition, AC §5).
    pub fn add(&self, other: &EpVector) -> EpVector {
        let n = self.dx.len().max(other.dx.len());
        let get = |v: &[i64], i: usize| v.get(i).copied().unwrap_or(0);
        EpVector {
            dx: (0..n).map(|i| get(&self.dx, i) + get(&other.dx, i)).collect(),
            dy: (0..n).map(|i| get(&self.dy, i) + get(&other.dy, i)).collect(),
        }
    }

    /// The inverse change.
    pub fn neg(&self) -> EpVector {
        EpVector { dx: self.dx.iter().map(|x| -x).collect(), dy: self.dy.iter().map(|x| -x).collect() }
    }

    /// The coordinates in the basis `A_i, B_j` of AC Prop. 5.2, or `None` when the vector is
    /// off the hyperplane. Solved from `b_0 = dx_0`, `a_i = b_{i-1} - dy_{i-1}`,
    /// `b_i = dx_i - a_i`; the last equation `b_n = dy_n` holds exactly on the hyperplane. O(n).
    pub fn basis(&self) -> Option<EpBasis> {
        if !self.is_on_hyperplane() || self.dx.is_empty() {
            return None;
        }
        let n = self.dim();
        let mut a = vec![0i64; n + 1];
        let mut b = vec![0i64; n + 1];
        b[0] = self.dx[0];
        for i in 1..=n {
            a[i] = b[i - 1] - self.dy[i - 1];
            b[i] = self.dx[i] - a[i];
        }
        debug_assert_eq!(b[n], self.dy[n]);
        Some(EpBasis { a, b })
    }

    /// The vector written in the basis of AC Prop. 5.2, e.g. `"B0 + A1"` for "make vertex,
    /// make edge" or `"-A2"` for "kill a face, make a 1-hole". `"0"` for no change;
    /// `"off hyperplane"` when the vector is not an Euler–Poincaré operator.
    pub fn basis_name(&self) -> String {
        let Some(c) = self.basis() else {
            return "off hyperplane".to_string();
        };
        let mut terms: Vec<(i64, String)> = Vec::new();
        for i in 0..c.b.len() {
            if c.b[i] != 0 {
                terms.push((c.b[i], format!("B{i}")));
            }
            if i + 1 < c.a.len() && c.a[i + 1] != 0 {
                terms.push((c.a[i + 1], format!("A{}", i + 1)));
            }
        }
        if terms.is_empty() {
            return "0".to_string();
        }
        let mut s = String::new();
        for (k, (coef, name)) in terms.iter().enumerate() {
            let mag = coef.abs();
            let body = if mag == 1 { name.clone() } else { format!("{mag}{name}") };
            if k == 0 {
                if *coef < 0 {
                    s.push('-');
                }
            } else {
                s.push_str(if *coef < 0 { " - " } else { " + " });
            }
            s.push_str(&body);
        }
        s
    }
}

impl fmt::Display for EpVector {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let j = |v: &[i64]| v.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", ");
        write!(f, "({}; {})", j(&self.dx), j(&self.dy))
    }
}

/// What an Euler operator did: its classical name (`"mve"`, `"kef"`, …), its
/// Euler–Poincaré vector and the vector's name in the basis of AC Prop. 5.2.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EulerOp {
    /// the operator's mnemonic, in the style of AC §5 and EO §3.2 (`m`ake / `k`ill,
    /// `v`ertex, `e`dge, `f`ace, `s`olid; `c<i>` for an i-cell beyond dimension 3)
    pub name: String,
    /// the change of cells and Betti numbers
    pub vector: EpVector,
}

impl EulerOp {
    /// A record from a name and a vector.
    pub fn new(name: impl Into<String>, vector: EpVector) -> Self {
        EulerOp { name: name.into(), vector }
    }

    /// The vector in the basis of AC Prop. 5.2 (see [`EpVector::basis_name`]).
    pub fn basis_name(&self) -> String {
        self.vector.basis_name()
    }
}

/// The letter of an i-cell in operator names: `v`, `e`, `f`, `s`, then `c<i>`.
pub fn cell_letter(i: usize) -> String {
    match i {
        0 => "v".into(),
        1 => "e".into(),
        2 => "f".into(),
        3 => "s".into(),
        _ => format!("c{i}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn basis_round_trip() {
        // A_1 = X_1 - Y_0: an edge joining two parts
        let v = EpVector { dx: vec![0, 1, 0], dy: vec![-1, 0, 0] };
        assert_eq!(v.basis_name(), "A1");
        // B_1 = X_1 + Y_1: an edge closing a loop
        let v = EpVector { dx: vec![0, 1, 0], dy: vec![0, 1, 0] };
        assert_eq!(v.basis_name(), "B1");
        // kill edge and face: -(A_2 + B_1)
        let v = EpVector::from_cells(&[0, -1, -1]);
        assert_eq!(v.basis_name(), "-B1 - A2");
        // L_2 = Y_2 + X_0 is B_0 + A_1 + B_1 + A_2 + B_2 ... check the decomposition solves it
        let v = EpVector { dx: vec![1, 0, 0], dy: vec![0, 0, 1] };
        let c = v.basis().unwrap();
        assert_eq!(c.b, vec![1, -1, 1]);
        assert_eq!(c.a, vec![0, 1, -1]);
        let off = EpVector::from_cells(&[1, 0, 0]);
        assert!(!off.is_on_hyperplane());
        assert_eq!(off.defect(), 1);
        assert_eq!(off.basis_name(), "off hyperplane");
        assert_eq!(EpVector::zero(2).basis_name(), "0");
        assert_eq!(format!("{}", EpVector::from_cells(&[1, 1])), "(1, 1; 0, 0)");
    }

    #[test]
    fn between_and_sums() {
        let v = EpVector::between(&[4, 4, 1], &[1, 0, 0], &[1, 2, 1], &[1, 2, 1]);
        assert_eq!(v.dx, vec![-3, -2, 0]);
        assert_eq!(v.dy, vec![0, 2, 1]);
        assert!(v.is_on_hyperplane());
        assert_eq!(v.add(&v.neg()), EpVector::zero(2));
        assert_eq!(v.euler_change(), -1);
    }
}
