//! Copying a [`DenseMap`] into an editable [`GMap`] next to what it holds: a disjoint union,
//! the way to put a builder's object (a simplex, a cube, a polygon, an imported mesh) into a
//! map that is being edited.
//!
//! ```
//! use gmap_core::{examples, GMap, MapView};
//! let mut g = GMap::new(3);
//! // the torus of the examples is a 2-map: in the 3-map its darts are 3-free
//! let a = g.append(&examples::torus());
//! let b = g.append(&examples::torus());
//! assert_eq!(g.dart_count(), 16);
//! assert!(g.is_free(a[0], 3));
//! g.sew(a[0], b[0], 3);
//! assert_eq!(MapView::component_count(&g), 1);
//! ```

use crate::attr::Attributes;
use crate::dense::DenseMap;
use crate::edit::{DartId, EditError, GMap};

impl<A: Attributes> GMap<A> {
    /// Copies `m` into this map as new darts, linked as in `m` and free for every `alpha_k`
    /// with `k > m.dim()`, so `m`'s components become components of this map. Returns the
    /// handles: dense dart `k` of `m` is `ids[k]`. A vertex of `m` with a point gets it
    /// (the point of its first dart, in dense order, that has one); no attribute is set.
    ///
    /// Precondition: `m.dim() <= self.dim()` (else [`EditError::BadIndex`] names
    /// `alpha_{m.dim()}`), and `m` is valid (BO Def. 1) so that the copy is. O(N n) for N
    /// darts of `m`.
    pub fn try_append(&mut self, m: &DenseMap) -> Result<Vec<DartId>, EditError> {
        if m.dim() > self.dim() {
            return Err(EditError::BadIndex { alpha: m.dim(), dim: self.dim() });
        }
        self.reserve_darts(m.dart_count());
        let ids: Vec<DartId> = (0..m.dart_count()).map(|_| self.create_dart()).collect();
        if !self.link_copy(m, &ids) {
            // `m` is not involutive: link as `link` does, each link once from its smaller
            // end (a later link frees the partners of an earlier one); a fixed point stays
            // free
            for d in m.darts() {
                for (i, &e) in m.row(d).iter().enumerate() {
                    if (e as usize) > d.index() {
                        self.try_link(ids[d.index()], ids[e as usize], i)?;
                    }
                }
            }
            if m.has_points() {
                for d in m.darts() {
                    let x = ids[d.index()];
                    if let (Some(p), None) = (m.point(d), self.point(x)) {
                        self.set_point(x, Some(p));
                    }
                }
            }
        } else if m.has_points() {
            self.copy_points(m, &ids);
        }
        Ok(ids)
    }

    /// Links the new darts `ids` (all free) as the darts of `m` are linked, in one pass
    /// that also checks that every `alpha_i` of `m` is an involution. Returns false, with
    /// the new darts free again, when one is not. O(N n).
    fn link_copy(&mut self, m: &DenseMap, ids: &[DartId]) -> bool {
        let n = m.dart_count();
        for d in m.darts() {
            for (i, &e) in m.row(d).iter().enumerate() {
                let e = e as usize;
                if e >= n || m.row(crate::ids::Dart::new(e as u32))[i] != d.get() {
                    for &x in ids {
                        for j in 0..=m.dim() {
                            self.link_free(x, x, j);
                        }
                    }
                    return false;
                }
                if e > d.index() {
                    self.link_free(ids[d.index()], ids[e], i);
                }
            }
        }
        true
    }

    /// Gives each vertex of the copy `ids` of `m` (linked as `m` is) the point of its first
    /// dart of `m`, in dense order, that has one. The vertices are found in `m`, whose rows
    /// are contiguous: the copy's vertices are the same sets of darts, the new darts being
    /// free for every `alpha_k` with `k > m.dim()`. O(N n).
    fn copy_points(&mut self, m: &DenseMap, ids: &[DartId]) {
        let mut seen = vec![false; m.dart_count()];
        let mut vertex: Vec<DartId> = Vec::new();
        let mut queue: Vec<u32> = Vec::new();
        for d in m.darts() {
            let Some(p) = m.point(d) else { continue };
            if seen[d.index()] {
                continue;
            }
            seen[d.index()] = true;
            queue.clear();
            queue.push(d.get());
            let mut k = 0;
            while k < queue.len() {
                let row = m.row(crate::ids::Dart::new(queue[k]));
                k += 1;
                for &y in &row[1..] {
                    if !seen[y as usize] {
                        seen[y as usize] = true;
                        queue.push(y);
                    }
                }
            }
            vertex.clear();
            vertex.extend(queue.iter().map(|&x| ids[x as usize]));
            self.set_fresh_point(&vertex, p);
        }
    }

    /// Like [`GMap::try_append`], panicking when `m.dim() > self.dim()`.
    #[track_caller]
    pub fn append(&mut self, m: &DenseMap) -> Vec<DartId> {
        match self.try_append(m) {
            Ok(ids) => ids,
            Err(e) => panic!("{e}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::{examples, Cells, Characteristics, EditError, GMap, MapView};

    #[test]
    fn two_copies_are_two_components_with_the_cells_of_both() {
        let m = examples::klein_bottle();
        let mut g = GMap::new(2);
        let a = g.append(&m);
        let b = g.append(&m);
        assert_eq!(a.len(), m.dart_count());
        assert!(a.iter().all(|x| !b.contains(x)));
        let one = Characteristics::of(&m);
        let two = g.characteristics();
        assert_eq!(two.darts, 2 * one.darts);
        assert_eq!(two.cells, one.cells.iter().map(|c| 2 * c).collect::<Vec<_>>());
        assert_eq!(two.components, 2);
        assert_eq!(two.orientable, one.orientable);
        assert!(two.valid);
    }

    #[test]
    fn the_copy_follows_the_dense_involutions() {
        let m = examples::cylinder();
        let mut g: GMap<((), (), Cells<u8>)> = GMap::with_attributes(3);
        let ids = g.append(&m);
        for d in m.darts() {
            for i in 0..=2 {
                assert_eq!(g.alpha(ids[d.index()], i), ids[m.alpha(d, i).index()]);
            }
            assert!(g.is_free(ids[d.index()], 3));
        }
        assert_eq!(MapView::cell_counts(&g), {
            let mut c = m.cell_counts();
            c.push(m.component_count());
            c
        });
    }

    #[test]
    fn points_go_to_the_vertices() {
        let mut m = crate::DenseMap::new(1, 2);
        m.link(crate::Dart::new(0), crate::Dart::new(1), 0);
        m.set_point(crate::Dart::new(0), Some([1.0, 2.0, 3.0]));
        let mut g = GMap::new(1);
        let ids = g.append(&m);
        assert_eq!(g.point(ids[0]), Some([1.0, 2.0, 3.0]));
        assert_eq!(g.point(ids[1]), None);
        assert_eq!(g.point_count(), 1);
    }

    #[test]
    fn a_vertex_takes_the_point_of_its_first_dart_that_has_one() {
        // a path of two edges: 0-1 and 2-3 by alpha_0, the vertex {1, 2} by alpha_1
        let mut m = crate::DenseMap::new(1, 4);
        m.link(crate::Dart::new(0), crate::Dart::new(1), 0);
        m.link(crate::Dart::new(1), crate::Dart::new(2), 1);
        m.link(crate::Dart::new(2), crate::Dart::new(3), 0);
        m.set_point(crate::Dart::new(2), Some([2.0; 3]));
        m.set_point(crate::Dart::new(3), Some([3.0; 3]));
        let mut g = GMap::new(2);
        let ids = g.append(&m);
        assert_eq!(
            ids.iter().map(|&x| g.point(x)).collect::<Vec<_>>(),
            vec![None, Some([2.0; 3]), Some([2.0; 3]), Some([3.0; 3])]
        );
        assert_eq!(g.point_count(), 2);
        m.set_point(crate::Dart::new(1), Some([1.0; 3]));
        let ids = g.append(&m);
        assert_eq!(g.point(ids[2]), Some([1.0; 3]));
        assert_eq!(g.point_count(), 4);
        g.check_attributes().unwrap();
    }

    #[test]
    fn a_map_that_is_not_involutive_is_linked_link_by_link() {
        // alpha_0 a 3-cycle 0 -> 1 -> 2 -> 0: linking 0-1 then 1-2 frees 0 again
        let m = crate::DenseMap::from_flat_unchecked(0, vec![1, 2, 0]).unwrap();
        let mut g = GMap::new(0);
        let ids = g.append(&m);
        assert!(g.is_free(ids[0], 0));
        assert_eq!(g.alpha(ids[1], 0), ids[2]);
        assert_eq!(g.alpha(ids[2], 0), ids[1]);
    }

    #[test]
    fn a_map_of_higher_dimension_is_refused() {
        let mut g = GMap::new(1);
        assert_eq!(g.try_append(&examples::torus()), Err(EditError::BadIndex { alpha: 2, dim: 1 }));
        assert_eq!(g.dart_count(), 0);
    }
}
