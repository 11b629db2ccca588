//! Lazy walks over an editable [`GMap`]: the darts of an orbit, one dart per cell of a
//! dimension, one dart per cell incident to a cell. Nothing is collected in advance: each
//! iterator holds its queue and its visited set and frees them when dropped, so a caller
//! that stops early pays only for what it looked at.
//!
//! ```
//! use gmap_core::{AlphaSet, GMap};
//! // a square face of a 2-map: 8 darts, 4 vertices, 4 edges
//! let mut m = GMap::new(2);
//! let d: Vec<_> = (0..8).map(|_| m.create_dart()).collect();
//! for k in 0..4 {
//!     m.sew(d[2 * k], d[2 * k + 1], 0);
//!     m.sew(d[2 * k + 1], d[(2 * k + 2) % 8], 1);
//! }
//! assert_eq!(m.orbit_iter(d[0], AlphaSet::of(&[0, 1])).count(), 8);
//! assert_eq!(m.one_dart_per_cell(0).count(), 4);
//! // the vertices of the face of d[0], one dart each
//! assert_eq!(m.one_dart_per_incident_cell(d[0], 2, 0).count(), 4);
//! ```

use std::collections::VecDeque;

use bitvec::vec::BitVec;
use rustc_hash::FxHashSet;
use smallvec::SmallVec;

use crate::alpha::AlphaSet;
use crate::attr::Attributes;
use crate::edit::{DartId, GMap};

/// The darts of an orbit `<set>(d)`, breadth-first from `d` (the order of
/// [`crate::MapView::orbit`]). From [`GMap::orbit_iter`].
pub struct OrbitIter<'a, A: Attributes> {
    map: &'a GMap<A>,
    idx: SmallVec<[usize; 8]>,
    seen: FxHashSet<DartId>,
    queue: VecDeque<DartId>,
}

impl<'a, A: Attributes> OrbitIter<'a, A> {
    pub(crate) fn new(map: &'a GMap<A>, d: DartId, set: AlphaSet) -> Self {
        let idx = set.iter().filter(|&i| i <= map.dim()).collect();
        let mut seen = FxHashSet::default();
        let mut queue = VecDeque::new();
        if map.contains(d) {
            seen.insert(d);
            queue.push_back(d);
        }
        OrbitIter { map, idx, seen, queue }
    }
}

impl<A: Attributes> Iterator for OrbitIter<'_, A> {
    type Item = DartId;

    fn next(&mut self) -> Option<DartId> {
        let x = self.queue.pop_front()?;
        for &i in &self.idx {
            let y = self.map.alpha(x, i);
            if self.seen.insert(y) {
                self.queue.push_back(y);
            }
        }
        Some(x)
    }
}

/// One dart per i-cell of the map, the first of each cell in storage order. From
/// [`GMap::one_dart_per_cell`].
pub struct CellDarts<'a, A: Attributes> {
    map: &'a GMap<A>,
    set: AlphaSet,
    darts: Box<dyn Iterator<Item = DartId> + 'a>,
    visited: BitVec,
}

impl<A: Attributes> Iterator for CellDarts<'_, A> {
    type Item = DartId;

    fn next(&mut self) -> Option<DartId> {
        for d in self.darts.by_ref() {
            if self.visited[self.map.dart_index(d)] {
                continue;
            }
            for y in self.map.orbit_iter(d, self.set) {
                let k = self.map.dart_index(y);
                self.visited.set(k, true);
            }
            return Some(d);
        }
        None
    }
}

/// One dart per j-cell incident to an i-cell: darts of the i-cell, breadth-first, each
/// starting a j-cell not met before. From [`GMap::one_dart_per_incident_cell`].
pub struct IncidentCells<'a, A: Attributes> {
    map: &'a GMap<A>,
    cell: OrbitIter<'a, A>,
    jset: AlphaSet,
    covered: FxHashSet<DartId>,
}

impl<A: Attributes> Iterator for IncidentCells<'_, A> {
    type Item = DartId;

    fn next(&mut self) -> Option<DartId> {
        for x in self.cell.by_ref() {
            if self.covered.contains(&x) {
                continue;
            }
            self.covered.extend(self.map.orbit_iter(x, self.jset));
            return Some(x);
        }
        None
    }
}

impl<A: Attributes> GMap<A> {
    /// The darts of the orbit `<set>(d)`, lazily, breadth-first from `d`; empty for a stale
    /// handle. O(orbit size · |set|) when run to the end.
    pub fn orbit_iter(&self, d: DartId, set: AlphaSet) -> OrbitIter<'_, A> {
        OrbitIter::new(self, d, set)
    }

    /// One dart per i-cell (for `i <= n`; the connected components for `i > n`), lazily,
    /// each the first dart of its cell in storage order. A visited bit per dart index is
    /// held by the iterator and freed with it. O(N n) when run to the end.
    pub fn one_dart_per_cell(&self, i: usize) -> CellDarts<'_, A> {
        let mut visited = BitVec::new();
        visited.resize(self.index_bound(), false);
        CellDarts { map: self, set: AlphaSet::cell(i, self.dim()), darts: Box::new(self.darts()), visited }
    }

    /// One dart per j-cell incident to the i-cell of `d` (the j-cells that share a dart
    /// with it), lazily; each yielded dart lies in both cells. `i == j` yields `d` alone.
    /// Empty for a stale handle. O((size of the i-cell + sizes of the j-cells met) · n)
    /// when run to the end.
    pub fn one_dart_per_incident_cell(&self, d: DartId, i: usize, j: usize) -> IncidentCells<'_, A> {
        let n = self.dim();
        IncidentCells {
            map: self,
            cell: self.orbit_iter(d, AlphaSet::cell(i, n)),
            jset: AlphaSet::cell(j, n),
            covered: FxHashSet::default(),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::{examples, AlphaSet, GMap, MapView};

    #[test]
    fn lazy_walks_agree_with_the_collected_ones() {
        for dense in [examples::fig1_surface(), examples::torus(), examples::klein_bottle(), examples::cylinder()] {
            let (g, _) = GMap::from_dense(&dense);
            let n = g.dim();
            let counts = dense.cell_counts();
            for (i, &count) in counts.iter().enumerate() {
                assert_eq!(g.one_dart_per_cell(i).count(), count, "dimension {i}");
                for d in g.darts() {
                    let lazy: Vec<_> = g.orbit_iter(d, AlphaSet::cell(i, n)).collect();
                    assert_eq!(lazy, MapView::orbit(&g, d, AlphaSet::cell(i, n)));
                }
            }
            // components
            assert_eq!(g.one_dart_per_cell(n + 1).count(), dense.component_count());
        }
    }

    #[test]
    fn incident_cells_of_a_torus() {
        // the torus of the examples: 1 vertex, 2 edges, 1 face
        let (g, _) = GMap::from_dense(&examples::torus());
        let d = g.darts().next().unwrap();
        assert_eq!(g.one_dart_per_incident_cell(d, 2, 1).count(), 2);
        assert_eq!(g.one_dart_per_incident_cell(d, 2, 0).count(), 1);
        assert_eq!(g.one_dart_per_incident_cell(d, 0, 2).count(), 1);
        assert_eq!(g.one_dart_per_incident_cell(d, 1, 1).collect::<Vec<_>>(), vec![d]);
        // stopping early is fine
        assert_eq!(g.one_dart_per_cell(1).next(), Some(d));
    }

    #[test]
    fn stale_handles_walk_nothing() {
        let mut g = GMap::new(1);
        let a = g.create_dart();
        g.remove_dart(a);
        assert_eq!(g.orbit_iter(a, AlphaSet::all(1)).count(), 0);
        assert_eq!(g.one_dart_per_incident_cell(a, 0, 1).count(), 0);
    }
}

#[cfg(test)]
mod orientation_tests {
    use crate::{examples, AlphaSet, EditError, GMap};

    #[test]
    fn orient_and_reverse_a_cylinder() {
        let (mut g, ids) = GMap::from_dense(&examples::cylinder());
        let m = g.reserve_mark();
        let d = ids[0];
        let half = g.orient(m, d).unwrap();
        assert_eq!(2 * half, g.dart_count());
        assert!(g.is_marked(m, d));
        assert!(g.is_orientation(m, d));
        // the dense orientation agrees: same class as the first dart
        let dense = g.to_dense().0.orientation().unwrap();
        for (k, &x) in ids.iter().enumerate() {
            assert_eq!(g.is_marked(m, x), dense[k]);
        }
        g.reverse_orientation(m, d);
        assert!(!g.is_marked(m, d));
        assert!(g.is_orientation(m, d));
        assert_eq!(g.orbit_iter(d, AlphaSet::all(2)).filter(|&x| g.is_marked(m, x)).count(), half);
        // reversing twice is the identity
        g.reverse_orientation(m, d);
        assert!(g.is_marked(m, d));
    }

    #[test]
    fn a_klein_bottle_has_no_orientation() {
        let (mut g, ids) = GMap::from_dense(&examples::klein_bottle());
        let m = g.reserve_mark();
        assert!(matches!(g.orient(m, ids[0]), Err(EditError::NotOrientable { .. })));
        assert!(!g.is_orientation(m, ids[0]));
        // no change on failure
        assert!(g.darts().all(|x| !g.is_marked(m, x)));
    }
}
