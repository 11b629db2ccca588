//! Building a map in bulk, as a mesh reader does: the darts of a dense map copied in one
//! pass, then the values of whole cells (points, attributes) given by an id per dart, with
//! no walk per cell and no sew.

use super::*;

impl<A: Attributes> GMap<A> {
    /// The map of the darts of `m`, in order: dense dart `k` is the live dart of index
    /// `k + 1` ([`GMap::dart_index`]; index 0 is never a dart), the `k`-th of
    /// [`GMap::darts`]. The involutions are copied as they are (an invalid `m` gives an
    /// invalid map: validate `m` first when it may be); points of `m` are not copied and no
    /// attribute is set. O(N n), two writes per word, no handle lookup.
    pub fn from_dense_rows(m: &DenseMap) -> Self {
        let mut g = Self::with_attributes(m.dim());
        let w = m.dim() + 1;
        let first = g.create_block(m.dart_count());
        for (k, row) in m.flat().chunks_exact(w).enumerate() {
            for (i, &e) in row.iter().enumerate() {
                g.darts.set_slot_alpha(first + k, i, first + e as usize);
            }
        }
        g
    }

    /// The handle of the live dart of index `k` ([`GMap::dart_index`]), `None` when no live
    /// dart has that index. O(1).
    pub fn dart_at(&self, k: usize) -> Option<DartId> {
        (k > 0 && k < self.darts.bound() && self.darts.slot_live(k)).then(|| self.darts.slot_id(k as u32))
    }

    /// Gives every vertex its point from an id per dart: the dart of index `k`
    /// ([`GMap::dart_index`]) is at `points[ids[k]]` (`u32::MAX`: no point). `ids` has
    /// [`GMap::index_bound`] entries (those of indices without a live dart are ignored); the
    /// map must have no point yet, and the darts of a vertex must have the same id (two
    /// vertices with the same id would share one point value, which the caller rules out:
    /// [`GMap::check_attributes`] reports it). Errors (and no change): points set already, a
    /// length or an id out of range, two darts of one vertex with different ids. Returns the
    /// number of vertices given a point. O(N n).
    pub fn set_points_by_ids(&mut self, ids: &[u32], points: &[Point]) -> Result<usize, AttributeDefect> {
        let topo = Topo { dim: self.dim, darts: &self.darts };
        self.points.set_by_ids(&topo, 0, ids, points.iter().map(|&p| Some(p)).collect())
    }

    /// Gives every I-cell its value from an id per dart, as [`GMap::set_points_by_ids`] does
    /// for points: the dart of index `k` takes `values[ids[k]]` (`u32::MAX`, or a `None`
    /// value: no attribute). The slot must hold no value yet and the darts of an I-cell the
    /// same id. Errors (and no change): `I > n`, values set already, a length or an id out
    /// of range, two darts of one I-cell with different ids. Returns the number of values
    /// set. O(N n).
    pub fn set_attributes_by_ids<const I: usize>(
        &mut self,
        ids: &[u32],
        values: Vec<Option<<A as AttributeAt<I>>::Value>>,
    ) -> Result<usize, AttributeDefect>
    where
        A: AttributeAt<I>,
    {
        if I > self.dim {
            return Err(AttributeDefect::BadIds {
                dim: I,
                reason: format!("there are no {I}-cells in a map of dimension {}", self.dim),
            });
        }
        let topo = Topo { dim: self.dim, darts: &self.darts };
        self.attrs.cells_mut().set_by_ids(&topo, I, ids, values)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::attr::Cells;

    /// A square as a 2-map: dense darts `2k`, `2k + 1` on the side from corner `k` to
    /// corner `k + 1` (corner of dart `j`: `ceil(j / 2) mod 4`).
    fn square() -> DenseMap {
        let mut m = DenseMap::new(2, 8);
        for k in 0..4u32 {
            m.link(Dart::new(2 * k), Dart::new(2 * k + 1), 0);
            m.link(Dart::new(2 * k + 1), Dart::new((2 * k + 2) % 8), 1);
        }
        m
    }

    #[test]
    fn the_rows_of_a_dense_map_become_the_darts_in_order() {
        let m = square();
        let g: GMap = GMap::from_dense_rows(&m);
        assert_eq!(g.dart_count(), 8);
        assert_eq!(g.dart_at(0), None);
        assert_eq!(g.dart_at(9), None);
        for d in m.darts() {
            let x = g.dart_at(d.index() + 1).unwrap();
            assert_eq!(g.dart_index(x), d.index() + 1);
            for i in 0..=2 {
                assert_eq!(g.dart_index(g.alpha(x, i)), m.alpha(d, i).index() + 1);
            }
        }
        assert_eq!(g.to_dense_map(), m);
        assert_eq!(g.darts().map(|d| g.dart_index(d)).collect::<Vec<_>>(), (1..=8).collect::<Vec<_>>());
    }

    #[test]
    fn points_and_attributes_by_ids_reach_every_dart_of_their_cell() {
        let m = square();
        let mut g: GMap<((), Cells<&'static str>, Cells<u8>)> = GMap::from_dense_rows(&m);
        let corner = |j: usize| (j.div_ceil(2) % 4) as u32;
        // index 0 is no dart; corner ids per dart
        let mut ids = vec![u32::MAX; 9];
        for j in 0..8 {
            ids[j + 1] = corner(j);
        }
        let pts = [[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.]];
        assert_eq!(g.set_points_by_ids(&ids, &pts), Ok(4));
        for j in 0..8 {
            assert_eq!(g.point(g.dart_at(j + 1).unwrap()), Some(pts[corner(j) as usize]));
        }
        // a second time: refused
        assert!(matches!(g.set_points_by_ids(&ids, &pts), Err(AttributeDefect::BadIds { dim: 0, .. })));
        // edges: side k holds darts 2k, 2k + 1; side 3 gets no value
        let mut sides = vec![u32::MAX; 9];
        for j in 0..8 {
            sides[j + 1] = (j / 2) as u32;
        }
        assert_eq!(g.set_attributes_by_ids::<1>(&sides, vec![Some("a"), Some("b"), Some("c"), None]), Ok(3));
        assert_eq!(g.attribute::<1>(g.dart_at(2).unwrap()), Some(&"a"));
        assert_eq!(g.attribute::<1>(g.dart_at(5).unwrap()), Some(&"c"));
        assert_eq!(g.attribute::<1>(g.dart_at(8).unwrap()), None);
        // the face: one id on every dart
        let mut face = vec![0u32; 9];
        face[0] = u32::MAX;
        assert_eq!(g.set_attributes_by_ids::<2>(&face, vec![Some(7)]), Ok(1));
        g.check_attributes().unwrap();
        assert_eq!(g.attribute_count::<2>(), 1);
        // refusals, with no change: ids that differ inside a cell, an id past the values,
        // a wrong length
        let mut h: GMap<((), Cells<&'static str>)> = GMap::from_dense_rows(&m);
        let mut split = sides.clone();
        split[2] = 3;
        assert_eq!(
            h.set_attributes_by_ids::<1>(&split, vec![Some("a"); 4]).unwrap_err().to_string(),
            "1-cell values by dart: dart indices 1 and 2 are neighbours by alpha_0 in one 1-cell but have the ids 0 and 3"
        );
        assert_eq!(
            h.set_attributes_by_ids::<1>(&sides, vec![Some("a"); 2]).unwrap_err().to_string(),
            "1-cell values by dart: dart index 5 has the id 2, past the 2 values"
        );
        assert_eq!(
            h.set_attributes_by_ids::<1>(&sides[..4], vec![Some("a"); 4]).unwrap_err().to_string(),
            "1-cell values by dart: 4 ids for 9 dart indices"
        );
        assert_eq!(h.attribute_count::<1>(), 0);
        type Volumes = ((), Cells<u8>, Cells<u8>, Cells<u8>);
        let mut v: GMap<Volumes> = GMap::from_dense_rows(&m);
        assert_eq!(
            v.set_attributes_by_ids::<3>(&face, vec![Some(1)]).unwrap_err().to_string(),
            "3-cell values by dart: there are no 3-cells in a map of dimension 2"
        );
    }
}
