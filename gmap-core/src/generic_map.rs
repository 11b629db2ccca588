//! The rest of CGAL's `GenericMap` and `Generalized_map` vocabulary on [`GMap`]: isolated
//! edges, emptying a map, the walks `next`, `previous`, `opposite<i>`,
//! `other_orientation`, degrees and codegrees of cells, and the shape tests
//! `is_face_combinatorial_polygon` and `is_volume_combinatorial_hexahedron`.
//!
//! | CGAL | here | precondition / predicate |
//! | --- | --- | --- |
//! | `make_edge()` | [`GMap::make_edge`], [`GMap::try_make_edge`] | `n >= 1` |
//! | LCC `make_segment(p0, p1, true)` | [`GMap::make_segment_closed`], [`GMap::try_make_segment_closed`] | `n >= 2` |
//! | `clear()` | [`GMap::clear`] | — |
//! | `next(d)`, `previous(d)` | [`GMap::next`], [`GMap::previous`] (and `try_`) | `n >= 1` |
//! | `opposite<i>(d)`, `opposite(d)` | [`GMap::opposite`] (and `try_`) | `i <= n` |
//! | `other_orientation(d)` | [`GMap::other_orientation`] (and `try_`) | — |
//! | `degree<i>(d)`, `codegree<i>(d)` | [`GMap::degree`], [`GMap::codegree`] (and `try_`) | `i < n`, `1 <= i <= n` |
//! | `is_face_combinatorial_polygon(d, k)` | [`GMap::is_face_combinatorial_polygon`] | `n >= 1` |
//! | `is_volume_combinatorial_hexahedron(d)` | [`GMap::is_volume_combinatorial_hexahedron`] | `n >= 2` |
//!
//! A stale handle is refused by the `try_` forms with [`EditError::NoSuchDart`] and makes
//! the plain forms panic, like the rest of [`GMap`].
//!
//! ```
//! use gmap_core::GMap;
//! let mut g = GMap::new(3);
//! let e = g.make_edge();
//! assert_eq!((g.dart_count(), g.cell_counts()), (2, vec![2, 1, 1, 1]));
//! let h = g.make_combinatorial_hexahedron();
//! assert!(g.is_volume_combinatorial_hexahedron(h));
//! assert!(g.is_face_combinatorial_polygon(h, 4));
//! assert_eq!(g.degree(h, 0), 3);      // three edges at a corner of a cube
//! assert_eq!(g.codegree(h, 3), 6);    // six faces around its volume
//! assert_eq!(g.next(g.next(g.next(g.next(h)))), h);
//! assert_eq!(g.other_orientation(e), g.alpha(e, 0));
//! g.clear();
//! assert_eq!(g.dart_count(), 0);
//! ```

use rustc_hash::FxHashSet as HashSet;

use crate::alpha::AlphaSet;
use crate::attr::Attributes;
use crate::edit::{DartId, EditError, GMap};
use crate::points::{IntoPoint, MakeError};

/// Panics with the error of a `try_` form.
#[track_caller]
fn refuse<T>(r: Result<T, EditError>) -> T {
    r.unwrap_or_else(|e| panic!("{e}"))
}

impl<A: Attributes> GMap<A> {
    /// An isolated edge without points (CGAL's `make_edge`): two darts linked by `alpha_0`,
    /// two vertices, one edge. Returns one of its darts. O(n).
    ///
    /// # Panics
    /// On a 0-map; [`GMap::try_make_edge`] returns the error.
    #[track_caller]
    pub fn make_edge(&mut self) -> DartId {
        self.try_make_edge().unwrap_or_else(|e| panic!("{e}"))
    }

    /// [`GMap::make_edge`], or [`MakeError::Dimension`] on a 0-map.
    pub fn try_make_edge(&mut self) -> Result<DartId, MakeError> {
        if self.dim() < 1 {
            return Err(MakeError::Dimension { what: "edge", needs: 1, dim: self.dim() });
        }
        let (a, b) = (self.create_dart(), self.create_dart());
        self.link(a, b, 0);
        Ok(a)
    }

    /// The closed form of [`GMap::make_segment`] (the linear cell complex's
    /// `make_segment(p0, p1, true)`): the segment from `p0` to `p1` with both sides, four
    /// darts, no dart 2-free — two vertices, one edge, the two sides two 2-cells. Returns
    /// the dart at `p0` on the first side. O(n).
    ///
    /// # Panics
    /// Below dimension 2; [`GMap::try_make_segment_closed`] returns the error.
    #[track_caller]
    pub fn make_segment_closed(&mut self, p: [impl IntoPoint; 2]) -> DartId {
        self.try_make_segment_closed(p).unwrap_or_else(|e| panic!("{e}"))
    }

    /// [`GMap::make_segment_closed`], or [`MakeError::Dimension`] below dimension 2.
    pub fn try_make_segment_closed(&mut self, p: [impl IntoPoint; 2]) -> Result<DartId, MakeError> {
        if self.dim() < 2 {
            return Err(MakeError::Dimension { what: "closed segment", needs: 2, dim: self.dim() });
        }
        let [p0, p1] = p.map(IntoPoint::into_point);
        let d: Vec<DartId> = (0..4).map(|_| self.create_dart()).collect();
        self.link(d[0], d[1], 0);
        self.link(d[2], d[3], 0);
        self.link(d[0], d[2], 2);
        self.link(d[1], d[3], 2);
        self.set_point(d[0], Some(p0));
        self.set_point(d[1], Some(p1));
        Ok(d[0])
    }

    /// Removes every dart, with its attributes and points (CGAL's `clear`); marks stay
    /// reserved. O(N n).
    pub fn clear(&mut self) {
        let all: Vec<DartId> = self.darts().collect();
        for d in all {
            self.remove_dart(d);
        }
    }

    /// CGAL's `next(d)` on a generalized map: `alpha_1(alpha_0(d))`, the dart of the next
    /// edge of the face, on the same side. O(1).
    ///
    /// # Panics
    /// On a stale handle or a 0-map; [`GMap::try_next`] returns the error.
    #[track_caller]
    pub fn next(&self, d: DartId) -> DartId {
        refuse(self.try_next(d))
    }

    /// [`GMap::next`], or the error for a stale handle or a 0-map.
    pub fn try_next(&self, d: DartId) -> Result<DartId, EditError> {
        self.try_alpha_word(d, &[0, 1])
    }

    /// CGAL's `previous(d)`: `alpha_0(alpha_1(d))`, the inverse of [`GMap::next`] on a face
    /// without free darts. O(1).
    ///
    /// # Panics
    /// Like [`GMap::next`]; [`GMap::try_previous`] returns the error.
    #[track_caller]
    pub fn previous(&self, d: DartId) -> DartId {
        refuse(self.try_previous(d))
    }

    /// [`GMap::previous`], or the error for a stale handle or a 0-map.
    pub fn try_previous(&self, d: DartId) -> Result<DartId, EditError> {
        self.try_alpha_word(d, &[1, 0])
    }

    /// CGAL's `opposite<i>(d)`: `alpha_i(alpha_0(d))`, the dart of the same orientation
    /// across the i-cell boundary (`i = 2`: the opposite dart of the edge in the
    /// neighbouring face). O(1).
    ///
    /// # Panics
    /// On a stale handle or `i > n`; [`GMap::try_opposite`] returns the error.
    #[track_caller]
    pub fn opposite(&self, d: DartId, i: usize) -> DartId {
        refuse(self.try_opposite(d, i))
    }

    /// [`GMap::opposite`], or the error for a stale handle or `i > n`.
    pub fn try_opposite(&self, d: DartId, i: usize) -> Result<DartId, EditError> {
        self.try_alpha_word(d, &[0, i])
    }

    /// CGAL's `other_orientation(d)`: `alpha_0(d)`, the dart of the same edge, face, …
    /// with the other orientation. O(1).
    ///
    /// # Panics
    /// On a stale handle; [`GMap::try_other_orientation`] returns the error.
    #[track_caller]
    pub fn other_orientation(&self, d: DartId) -> DartId {
        refuse(self.try_other_orientation(d))
    }

    /// [`GMap::other_orientation`], or the error for a stale handle.
    pub fn try_other_orientation(&self, d: DartId) -> Result<DartId, EditError> {
        self.try_alpha(d, 0)
    }

    /// The number of distinct `j`-cells meeting the darts of the i-cell of `d`.
    fn incident_count(&self, d: DartId, i: usize, j: usize) -> usize {
        let mut seen: HashSet<DartId> = HashSet::default();
        let mut count = 0;
        for x in self.cell_darts(d, i) {
            if seen.insert(x) {
                count += 1;
                seen.extend(self.cell_darts(x, j));
            }
        }
        count
    }

    /// CGAL's `degree<i>(d)`: the number of distinct (i+1)-cells incident to the i-cell of
    /// `d`, `i < n` (the edges at a vertex, the faces around an edge, …). O(s · n), s the
    /// size of the (i+1)-cells around.
    ///
    /// # Panics
    /// On a stale handle or `i >= n`; [`GMap::try_degree`] returns the error.
    #[track_caller]
    pub fn degree(&self, d: DartId, i: usize) -> usize {
        refuse(self.try_degree(d, i))
    }

    /// [`GMap::degree`], or the error: [`EditError::NoSuchDart`], or
    /// [`EditError::NoSuchCells`] when `i + 1 > n`.
    pub fn try_degree(&self, d: DartId, i: usize) -> Result<usize, EditError> {
        self.try_alpha(d, 0)?;
        if i >= self.dim() {
            return Err(EditError::NoSuchCells { cell: i + 1, dim: self.dim() });
        }
        Ok(self.incident_count(d, i, i + 1))
    }

    /// CGAL's `codegree<i>(d)`: the number of distinct (i-1)-cells incident to the i-cell
    /// of `d`, `1 <= i <= n` (the vertices of an edge, the edges of a face, …).
    /// O(s · n), s the size of the cell.
    ///
    /// # Panics
    /// On a stale handle, `i = 0` or `i > n`; [`GMap::try_codegree`] returns the error.
    #[track_caller]
    pub fn codegree(&self, d: DartId, i: usize) -> usize {
        refuse(self.try_codegree(d, i))
    }

    /// [`GMap::codegree`], or the error: [`EditError::NoSuchDart`], or
    /// [`EditError::NoSuchCells`] when `i = 0` or `i > n`.
    pub fn try_codegree(&self, d: DartId, i: usize) -> Result<usize, EditError> {
        self.try_alpha(d, 0)?;
        if i == 0 || i > self.dim() {
            return Err(EditError::NoSuchCells { cell: i, dim: self.dim() });
        }
        Ok(self.incident_count(d, i, i - 1))
    }

    /// CGAL's `is_face_combinatorial_polygon(d, k)`: the face of `d` (its orbit under
    /// `alpha_0`, `alpha_1`) is a closed polygon of `k` edges — `2k` darts, none 0- or
    /// 1-free, and `k` steps of [`GMap::next`] come back to `d`. False for a stale handle
    /// or a 0-map. O(k).
    pub fn is_face_combinatorial_polygon(&self, d: DartId, k: usize) -> bool {
        if !self.contains(d) || self.dim() < 1 || k == 0 {
            return false;
        }
        let mut x = d;
        for step in 0..k {
            if self.is_free(x, 0) || self.is_free(self.alpha(x, 0), 1) {
                return false;
            }
            x = self.next(x);
            if x == d && step + 1 < k {
                return false;
            }
        }
        x == d && self.orbit(d, AlphaSet::of(&[0, 1])).len() == 2 * k
    }

    /// CGAL's `is_volume_combinatorial_hexahedron(d)`: the volume of `d` (its orbit under
    /// `alpha_0`, `alpha_1`, `alpha_2`) is a closed combinatorial cube — 48 darts, none 0-, 1-
    /// or 2-free, six faces that are quadrangles, twelve edges, eight vertices of degree 3.
    /// False for a stale handle or below dimension 2. O(48 n).
    pub fn is_volume_combinatorial_hexahedron(&self, d: DartId) -> bool {
        if !self.contains(d) || self.dim() < 2 {
            return false;
        }
        let volume = self.orbit(d, AlphaSet::of(&[0, 1, 2]));
        if volume.len() != 48 || volume.iter().any(|&x| (0..3).any(|j| self.is_free(x, j))) {
            return false;
        }
        let count = |set: AlphaSet, size: usize| {
            let mut seen: HashSet<DartId> = HashSet::default();
            let mut cells = 0;
            for &x in &volume {
                if seen.insert(x) {
                    let orbit = self.orbit(x, set);
                    if orbit.len() != size {
                        return None;
                    }
                    cells += 1;
                    seen.extend(orbit);
                }
            }
            Some(cells)
        };
        count(AlphaSet::of(&[0, 1]), 8) == Some(6)
            && count(AlphaSet::of(&[0, 2]), 4) == Some(12)
            && count(AlphaSet::of(&[1, 2]), 6) == Some(8)
    }
}
