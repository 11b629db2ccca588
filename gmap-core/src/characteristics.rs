//! [`Characteristics`]: the summary of a map that CGAL users read first — darts, cells per
//! dimension, connected components, orientability and validity — printed in the shape of
//! CGAL's `display_characteristics` followed by its examples' `, valid=` flag.
//!
//! ```
//! use gmap_core::{examples, Characteristics};
//! let c = Characteristics::of(&examples::torus());
//! assert_eq!(c.cells, vec![1, 2, 1]);
//! assert_eq!(
//!     c.to_string(),
//!     "#Darts=8, #0-cells=1, #1-cells=2, #2-cells=1, #ccs=1, orientable=true, valid=1"
//! );
//! ```

use std::fmt;

use crate::attr::Attributes;
use crate::dense::DenseMap;
use crate::edit::GMap;
use crate::map_view::MapView;

/// Darts, cells per dimension, components, orientability and validity of a map, computed
/// together on one dense snapshot. See the [module docs](self).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Characteristics {
    /// Number of darts.
    pub darts: usize,
    /// Number of i-cells for `i = 0..=n` (BO Def. 2).
    pub cells: Vec<usize>,
    /// Number of connected components.
    pub components: usize,
    /// Whether every component is orientable (BO Def. 7).
    pub orientable: bool,
    /// Whether the involutions satisfy BO Def. 1 ([`DenseMap::validate`]).
    pub valid: bool,
}

impl Characteristics {
    /// The characteristics of a dense map. O(N n) for N darts in dimension n: one
    /// union-find pass for the cells and components, one for orientability, one validation.
    pub fn of_dense(m: &DenseMap) -> Self {
        let (cells, components) = m.cell_counts_and_components();
        Characteristics {
            darts: m.dart_count(),
            cells,
            components,
            orientable: m.is_orientable(),
            valid: m.validate().is_ok(),
        }
    }

    /// The characteristics of any representation, computed on its dense snapshot
    /// ([`MapView::with_dense`]; for an editable map that is one extra O(N n) copy).
    pub fn of<M: MapView>(m: &M) -> Self {
        m.with_dense(Self::of_dense)
    }
}

impl<A: Attributes> GMap<A> {
    /// The characteristics of the map ([`Characteristics`]), its validity covering the
    /// involutions (BO Def. 1) and the attributes and points
    /// ([`GMap::check_attributes`]), as CGAL's `is_valid` covers both. O(N n) plus one
    /// dense snapshot.
    pub fn characteristics(&self) -> Characteristics {
        let mut c = Characteristics::of(self);
        c.valid = c.valid && self.check_attributes().is_ok();
        c
    }
}

/// `#Darts=N, #0-cells=…, …, #n-cells=…, #ccs=C, orientable=true|false, valid=1|0`: CGAL's
/// `display_characteristics` of a generalized map, with the validity flag its example
/// programs append (printed, as C++ prints a `bool`, as 1 or 0).
impl fmt::Display for Characteristics {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "#Darts={}", self.darts)?;
        for (i, n) in self.cells.iter().enumerate() {
            write!(f, ", #{i}-cells={n}")?;
        }
        write!(f, ", #ccs={}, orientable={}, valid={}", self.components, self.orientable, u8::from(self.valid))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::examples;

    #[test]
    fn klein_bottle_is_not_orientable() {
        let c = Characteristics::of(&examples::klein_bottle());
        assert!(!c.orientable);
        assert!(c.valid);
        assert_eq!(c.components, 1);
        assert_eq!(c.cells.len(), 3);
    }

    #[test]
    fn an_invalid_map_prints_valid_0() {
        // two darts linked by alpha_0 and alpha_2 but alpha_2 fixes one of them: not an
        // involution, so validation fails
        let mut m = DenseMap::new(2, 3);
        m.link(crate::Dart::new(0), crate::Dart::new(1), 0);
        m.link(crate::Dart::new(1), crate::Dart::new(2), 2);
        let c = Characteristics::of(&m);
        assert!(!c.valid);
        assert!(c.to_string().ends_with(", valid=0"));
    }

    #[test]
    fn disagreeing_attributes_make_a_gmap_invalid() {
        // two darts with different vertex labels, put on one vertex by a link that does
        // not reconcile: the involutions are fine, the attributes are not
        let mut g: GMap<(crate::Cells<i32>,)> = GMap::with_attributes(1);
        let (a, b) = (g.create_dart(), g.create_dart());
        g.set_attribute::<0>(a, 1);
        g.set_attribute::<0>(b, 2);
        assert!(g.characteristics().valid);
        g.link(a, b, 1);
        let c = g.characteristics();
        assert_eq!(c.cells, vec![1, 2]);
        assert!(!c.valid);
        g.reconcile_attributes(&[a, b]);
        assert!(g.characteristics().valid);
    }

    #[test]
    fn the_empty_map_has_no_cells() {
        let c = Characteristics::of(&DenseMap::new(1, 0));
        assert_eq!(c.to_string(), "#Darts=0, #0-cells=0, #1-cells=0, #ccs=0, orientable=true, valid=1");
    }
}
