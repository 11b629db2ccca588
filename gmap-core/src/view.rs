//! [`MapView`]: the generic access to a G-map, for code written once over both
//! representations (as petgraph's `visit` traits over its graphs).
//!
//! A representation provides its dimension, its darts, `alpha_i` and a dense snapshot. The
//! whole-map questions (validity, cells of a dimension, darts of a cell, counts, components,
//! orientation, complete boundaries, the Euler characteristic) are not in the trait: they
//! are inherent methods with the same names and answers on [`DenseMap`] and on [`GMap`],
//! the latter running the dense kernel on one snapshot ([`GMap::to_dense_map`]).
//!
//! ```
//! use gmap_core::{AlphaSet, GMap, MapView};
//! // a triangle as an editable 2-map: six darts, sewn by hand
//! let mut g = GMap::new(2);
//! let d: Vec<_> = (0..6).map(|_| g.create_dart()).collect();
//! for k in 0..3 {
//!     g.sew(d[2 * k], d[2 * k + 1], 0);
//!     g.sew(d[2 * k + 1], d[(2 * k + 2) % 6], 1);
//! }
//! assert!(g.validate().is_ok());
//! assert_eq!(g.cell_counts(), vec![3, 3, 1]);
//! assert_eq!(g.euler_characteristic(), 1);
//! assert!(g.is_orientable());
//! assert_eq!(g.cell_darts(d[0], 2).len(), 6);
//! // the same questions of the dense snapshot, and generic code over both
//! let m = g.to_dense_map();
//! assert_eq!(m.cell_counts(), g.cell_counts());
//! fn darts<M: MapView>(m: &M) -> usize {
//!     m.dart_list().len()
//! }
//! assert_eq!(darts(&g), darts(&m));
//! ```

use std::hash::Hash;

use crate::dense::DenseMap;
#[cfg(doc)]
use crate::edit::GMap;
use crate::ids::Dart;

/// A G-map seen through its involutions. See the [module docs](self).
pub trait MapView {
    /// The dart handle of this representation.
    type Dart: Copy + Eq + Hash;

    /// The dimension n (the involutions are `alpha_0..=alpha_n`).
    fn dim(&self) -> usize;

    /// Number of darts.
    fn dart_count(&self) -> usize;

    /// The darts, in the order the dense snapshot numbers them.
    fn dart_list(&self) -> Vec<Self::Dart>;

    /// `alpha_i(d)`. Precondition: `i <= dim()` and `d` is a dart of the map.
    fn alpha(&self, d: Self::Dart, i: usize) -> Self::Dart;

    /// Runs `f` on a dense snapshot of the map (the map itself for a [`DenseMap`]).
    fn with_dense<R>(&self, f: impl FnOnce(&DenseMap) -> R) -> R;
}

impl MapView for DenseMap {
    type Dart = Dart;

    fn dim(&self) -> usize {
        DenseMap::dim(self)
    }

    fn dart_count(&self) -> usize {
        DenseMap::dart_count(self)
    }

    fn dart_list(&self) -> Vec<Dart> {
        self.darts().collect()
    }

    fn alpha(&self, d: Dart, i: usize) -> Dart {
        DenseMap::alpha(self, d, i)
    }

    fn with_dense<R>(&self, f: impl FnOnce(&DenseMap) -> R) -> R {
        f(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::edit::{DartId, GMap};

    /// The same questions asked of both representations give the same answers.
    fn agree(m: &DenseMap) {
        let (g, ids) = GMap::from_dense(m);
        assert_eq!(g.cell_counts(), m.cell_counts());
        assert_eq!(g.euler_characteristic(), m.euler_characteristic());
        assert_eq!(g.component_count(), m.component_count());
        assert_eq!(g.components(), m.components());
        assert_eq!(g.is_orientable(), m.is_orientable());
        assert_eq!(g.orientation(), m.orientation());
        assert_eq!(g.validate().map_err(|e| e.to_string()), m.validate().map_err(|e| e.to_string()));
        assert_eq!(g.check_complete_boundaries(), m.check_complete_boundaries());
        assert_eq!(g.dart_list(), ids);
        for d in m.darts() {
            for i in 0..=m.dim() {
                assert_eq!(g.cells(i), m.cells(i));
                let a: Vec<DartId> = g.cell_darts(ids[d.index()], i);
                let b: Vec<Dart> = m.cell_darts(d, i);
                assert_eq!(a.len(), b.len());
                assert_eq!(g.is_free(ids[d.index()], i), m.is_free(d, i));
            }
        }
    }

    #[test]
    fn editable_and_dense_agree_on_the_examples() {
        use crate::examples::*;
        for m in [fig1_curve(), fig1_surface(), cylinder(), klein_bottle(), torus()] {
            agree(&m);
        }
    }
}
