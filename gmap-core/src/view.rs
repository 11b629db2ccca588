//! [`MapView`]: what every representation of a G-map offers, so that whole-map questions
//! (validity, cell counts, components, orientation, complete boundaries) can be asked of
//! the editable [`GMap`] as well as of the [`DenseMap`] snapshot.
//!
//! A representation provides four things — its dimension, its darts, `alpha_i` and a
//! dense snapshot — and gets the rest. Orbits are walked through `alpha` with an explicit
//! queue; the whole-map algorithms run on the snapshot, which for a [`DenseMap`] is the map
//! itself (no copy) and for a [`GMap`] is [`GMap::to_dense`] (one O(N n) pass per call: ask
//! several questions of one `to_dense()` when that matters).
//!
//! Darts named in the errors of the provided methods are snapshot darts: for a [`GMap`],
//! dart `k` is the `k`-th of [`GMap::darts`].
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
//! assert_eq!(MapView::cell_counts(&g), vec![3, 3, 1]);
//! assert_eq!(MapView::euler_characteristic(&g), 1);
//! assert!(MapView::is_orientable(&g));
//! assert_eq!(MapView::orbit(&g, d[0], AlphaSet::cell(2, 2)).len(), 6);
//! ```

use std::hash::Hash;

use rustc_hash::FxHashSet;

use crate::alpha::AlphaSet;
use crate::dense::DenseMap;
#[cfg(doc)]
use crate::edit::GMap;
use crate::error::{BoundaryDefect, OrientationConflict, ValidityError};
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

    /// Whether `d` is i-free (`alpha_i(d) = d`).
    fn is_free(&self, d: Self::Dart, i: usize) -> bool {
        self.alpha(d, i) == d
    }

    /// The orbit `<set>(d)` in breadth-first order from `d` (involutions above `dim()`
    /// ignored). O(orbit size × |set|).
    fn orbit(&self, d: Self::Dart, set: AlphaSet) -> Vec<Self::Dart> {
        let idx: Vec<usize> = set.iter().filter(|&i| i <= self.dim()).collect();
        let mut seen: FxHashSet<Self::Dart> = FxHashSet::default();
        seen.insert(d);
        let mut out = vec![d];
        let mut k = 0;
        while k < out.len() {
            let x = out[k];
            k += 1;
            for &i in &idx {
                let y = self.alpha(x, i);
                if seen.insert(y) {
                    out.push(y);
                }
            }
        }
        out
    }

    /// The darts of the i-cell of `d` (BO Def. 2).
    fn cell_darts(&self, d: Self::Dart, i: usize) -> Vec<Self::Dart> {
        self.orbit(d, AlphaSet::cell(i, self.dim()))
    }

    /// Checks BO Def. 1, naming the first violation. See [`DenseMap::validate`].
    fn validate(&self) -> Result<(), ValidityError> {
        self.with_dense(|m| m.validate())
    }

    /// Number of i-cells for `i = 0..=n`. See [`DenseMap::cell_counts`].
    fn cell_counts(&self) -> Vec<usize> {
        self.with_dense(|m| m.cell_counts())
    }

    /// The alternating sum of [`cell_counts`](MapView::cell_counts).
    fn euler_characteristic(&self) -> i64 {
        self.with_dense(|m| m.euler_characteristic())
    }

    /// Number of connected components.
    fn component_count(&self) -> usize {
        self.with_dense(|m| m.component_count())
    }

    /// Whether the map is orientable (BO Def. 7).
    fn is_orientable(&self) -> bool {
        self.with_dense(|m| m.is_orientable())
    }

    /// The first orientation conflict, if any (BO Def. 7, 8).
    fn check_orientable(&self) -> Result<(), OrientationConflict> {
        self.with_dense(|m| m.orientation().map(|_| ()))
    }

    /// Checks BO Def. 6 (complete boundaries). See [`DenseMap::check_complete_boundaries`].
    fn check_complete_boundaries(&self) -> Result<(), BoundaryDefect> {
        self.with_dense(|m| m.check_complete_boundaries())
    }
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

    fn orbit(&self, d: Dart, set: AlphaSet) -> Vec<Dart> {
        DenseMap::orbit(self, d, set)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::edit::{DartId, GMap};

    /// The same questions asked of both representations give the same answers.
    fn agree(m: &DenseMap) {
        let (g, ids) = GMap::from_dense(m);
        assert_eq!(MapView::cell_counts(&g), m.cell_counts());
        assert_eq!(MapView::component_count(&g), m.component_count());
        assert_eq!(MapView::is_orientable(&g), m.is_orientable());
        assert_eq!(MapView::validate(&g), m.validate());
        assert_eq!(MapView::check_complete_boundaries(&g).is_ok(), m.has_complete_boundaries());
        for d in m.darts() {
            for i in 0..=m.dim() {
                let a: Vec<DartId> = MapView::cell_darts(&g, ids[d.index()], i);
                let b: Vec<Dart> = MapView::cell_darts(m, d, i);
                assert_eq!(a.len(), b.len());
                assert_eq!(MapView::is_free(&g, ids[d.index()], i), MapView::is_free(m, d, i));
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
