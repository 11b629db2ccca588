//! What an Euler operator did: its name and its Euler–Poincaré vector.
//!
//! The vector itself is [`gmap_core::ep_vector::EpVector`] (AC §4–5), the one type the whole
//! workspace uses for changes of cell counts and Betti numbers; re-exported here so that
//! `gmap_ops::euler::EpVector` names it too.

pub use gmap_core::ep_vector::{AbExpansion, EpVector};

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
    fn names_in_the_elementary_basis() {
        // A_1 = X_1 - Y_0: an edge joining two parts
        let v = EpVector::try_new(vec![0, 1, 0], vec![-1, 0, 0]).unwrap();
        assert_eq!(v.basis_name(), "A1");
        // B_1 = X_1 + Y_1: an edge closing a loop
        let v = EpVector::try_new(vec![0, 1, 0], vec![0, 1, 0]).unwrap();
        assert_eq!(v.basis_name(), "B1");
        // mve: one vertex and one edge more, same homology
        let op = EulerOp::new("mve", EpVector::from_cells(&[1, 1, 0]));
        assert_eq!(op.basis_name(), "B0 + A1");
        assert_eq!(cell_letter(4), "c4");
    }
}
