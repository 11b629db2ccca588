//! [`MapView`]: the generic access to a G-map, for code written once over both
//! representations (as petgraph's `visit` traits over its graphs).
//!
//! A representation provides its dimension, its darts, `alpha_i` and a dense snapshot. The
//! whole-map questions (validity, cells of a dimension, darts of a cell, counts, components,
//! orientation, complete boundaries, the Euler characteristic) are not in the trait: they
//! are inherent methods with the same names and answers on [`DenseMap`] and on [`GMap`](crate::GMap),
//! the latter running the dense kernel on one snapshot ([`GMap::to_dense_map`](crate::GMap::to_dense_map)).
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
