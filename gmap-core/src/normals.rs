//! Geometry of a linear cell complex that CGAL's `Linear_cell_complex` offers beyond
//! barycentres: normals of faces and vertices (`compute_normal_of_cell_2`,
//! `compute_normal_of_cell_0`), and the dual of a closed map with a point at the barycentre
//! of every top cell (`dual_points_at_barycenter`).
//!
//! ```
//! use gmap_core::GMap;
//! let mut g = GMap::new(2);
//! let d = g.make_quadrangle([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
//! assert_eq!(g.compute_normal_of_cell_2(d), Some([0.0, 0.0, 1.0]));
//! assert_eq!(g.compute_normal_of_cell_0(d), Some([0.0, 0.0, 1.0]));
//! // the dual of a closed tetrahedron surface: four vertices at the faces' barycentres
//! let mut t = GMap::new(2);
//! t.make_tetrahedron([[0.0, 0.0, 0.0], [3.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 3.0]]);
//! let dual = t.dual_points_at_barycenter().unwrap();
//! assert_eq!(dual.cell_counts(), vec![4, 6, 4]);
//! assert_eq!(dual.point_count(), 4);
//! ```

use thiserror::Error;

use crate::alpha::AlphaSet;
use crate::attr::Attributes;
use crate::edit::{DartId, EditError, GMap};
use crate::ids::Point;

/// Why a normal or a dual with points cannot be computed.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum GeometryError {
    /// A handle or an index is wrong.
    #[error(transparent)]
    Edit(#[from] EditError),
    /// The map has a boundary: the dual of a map exists only without free darts.
    #[error("dart {dart:?} is {alpha}-free: the map has a boundary and no dual")]
    Boundary {
        /// a free dart
        dart: DartId,
        /// the involution it is free for
        alpha: usize,
    },
    /// A vertex of the cell has no point.
    #[error("the vertex of dart {0:?} has no point")]
    NoPoint(DartId),
}

fn unit(v: Point) -> Option<Point> {
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    (len > 0.0 && len.is_finite()).then(|| [v[0] / len, v[1] / len, v[2] / len])
}

impl<A: Attributes> GMap<A> {
    /// The unit normal of the face of `d` (CGAL's `compute_normal_of_cell_2`): Newell's sum
    /// of the cross products of the face's consecutive corner points, walking the face by
    /// [`GMap::next`] from `d` (the orientation of `d` gives the sign), normalised. `None`
    /// when a corner has no point, the face is degenerate (zero area) or `n < 1`.
    /// O(face size).
    ///
    /// # Panics
    /// On a stale handle; [`GMap::try_compute_normal_of_cell_2`] returns the error.
    #[track_caller]
    pub fn compute_normal_of_cell_2(&self, d: DartId) -> Option<Point> {
        self.try_compute_normal_of_cell_2(d).unwrap_or_else(|e| match e {
            GeometryError::Edit(e) => panic!("{e}"),
            _ => None,
        })
    }

    /// [`GMap::compute_normal_of_cell_2`], or why not: a stale handle, a corner without a
    /// point ([`GeometryError::NoPoint`]); `Ok(None)` for a degenerate face.
    pub fn try_compute_normal_of_cell_2(&self, d: DartId) -> Result<Option<Point>, GeometryError> {
        self.try_alpha(d, 0)?;
        if self.dim() < 1 {
            return Ok(None);
        }
        let mut corners: Vec<Point> = Vec::new();
        let mut x = d;
        let limit = self.orbit(d, AlphaSet::of(&[0, 1])).len();
        for _ in 0..limit {
            corners.push(self.point(x).ok_or(GeometryError::NoPoint(x))?);
            let y = self.alpha(x, 0);
            if y == x || self.is_free(y, 1) {
                // an open face: its last corner closes the polygon
                if y != x {
                    corners.push(self.point(y).ok_or(GeometryError::NoPoint(y))?);
                }
                break;
            }
            x = self.alpha(y, 1);
            if x == d {
                break;
            }
        }
        let mut n = [0.0; 3];
        for (k, &p) in corners.iter().enumerate() {
            let q = corners[(k + 1) % corners.len()];
            n[0] += (p[1] - q[1]) * (p[2] + q[2]);
            n[1] += (p[2] - q[2]) * (p[0] + q[0]);
            n[2] += (p[0] - q[0]) * (p[1] + q[1]);
        }
        Ok(unit(n))
    }

    /// The unit normal at the vertex of `d` (CGAL's `compute_normal_of_cell_0`): the mean of
    /// the normals of the faces around it (one per face, oriented by the darts of the
    /// vertex that are on one side, those of `d`'s orientation class), normalised. `None`
    /// when no face around it has a normal. O(size of the faces around · n).
    ///
    /// # Panics
    /// On a stale handle; [`GMap::try_compute_normal_of_cell_0`] returns the error.
    #[track_caller]
    pub fn compute_normal_of_cell_0(&self, d: DartId) -> Option<Point> {
        self.try_compute_normal_of_cell_0(d).unwrap_or_else(|e| match e {
            GeometryError::Edit(e) => panic!("{e}"),
            _ => None,
        })
    }

    /// [`GMap::compute_normal_of_cell_0`], or why not (a stale handle, a corner without a
    /// point).
    pub fn try_compute_normal_of_cell_0(&self, d: DartId) -> Result<Option<Point>, GeometryError> {
        self.try_alpha(d, 0)?;
        let n = self.dim();
        // the darts of the vertex reached from d by an even number of steps keep d's
        // orientation; one of them per face
        let steps: Vec<usize> = (1..=n.min(2)).collect();
        let mut same = vec![d];
        let mut seen = std::collections::HashSet::from([d]);
        let mut k = 0;
        while k < same.len() {
            let x = same[k];
            k += 1;
            for &i in &steps {
                for &j in &steps {
                    let y = self.alpha(self.alpha(x, i), j);
                    if seen.insert(y) {
                        same.push(y);
                    }
                }
            }
        }
        let mut faces = std::collections::HashSet::new();
        let mut sum = [0.0; 3];
        let mut any = false;
        for x in same {
            if !faces.insert(self.orbit(x, AlphaSet::of(&[0, 1])).into_iter().min().unwrap_or(x)) {
                continue;
            }
            if let Some(v) = self.try_compute_normal_of_cell_2(x)? {
                any = true;
                for c in 0..3 {
                    sum[c] += v[c];
                }
            }
        }
        Ok(if any { unit(sum) } else { None })
    }

    /// The dual of a map without boundary with a point at the barycentre of every n-cell
    /// (CGAL's `dual_points_at_barycenter`): the same darts with `alpha_i` and
    /// `alpha_{n-i}` swapped, the dual vertex of each n-cell placed at the mean of its
    /// vertices' points ([`GMap::barycenter`]). Refused with [`GeometryError::Boundary`]
    /// when a dart is free and [`GeometryError::NoPoint`] when a vertex has no point.
    /// O(N n).
    pub fn dual_points_at_barycenter(&self) -> Result<GMap, GeometryError> {
        let n = self.dim();
        for d in self.darts() {
            if let Some(i) = (0..=n).find(|&i| self.is_free(d, i)) {
                return Err(GeometryError::Boundary { dart: d, alpha: i });
            }
        }
        let (dense, ids) = self.to_dense_with_ids();
        let (mut dual, new_ids) = GMap::from_dense(&dense.dual());
        for (k, &old) in ids.iter().enumerate() {
            let x = new_ids[k];
            if dual.point(x).is_none() {
                let p = self.barycenter(old, n).ok_or(GeometryError::NoPoint(old))?;
                dual.set_point(x, Some(p));
            }
        }
        Ok(dual)
    }
}
