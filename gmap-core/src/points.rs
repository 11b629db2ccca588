//! The linear cell complex: a [`GMap`] whose vertices carry points of R³ (the built-in point
//! slot, [`GMap::point`]), with CGAL's constructors with coordinates, barycentres of cells,
//! affine transformations and bounding boxes.
//!
//! Points are `[f64; 3]` ([`Point`]). A planar user gives `[x, y]` and gets `z = 0`: every
//! constructor takes anything that is [`IntoPoint`], which `[f64; 3]` and `[f64; 2]` are.
//!
//! ## Constructors
//!
//! Each adds an isolated object to the map, whatever it already holds, and returns one dart
//! of it, as CGAL's `make_*` do; the `try_` forms return a [`MakeError`] (a map of too small
//! a dimension, a polygon without sides) and change nothing then.
//!
//! | constructor | object | darts | needs dimension |
//! | --- | --- | --- | --- |
//! | [`GMap::make_segment`] | an edge | 2 | 1 |
//! | [`GMap::make_polygon`], [`GMap::make_triangle`], [`GMap::make_quadrangle`] | a k-gon | 2k | 1 |
//! | [`GMap::make_tetrahedron`] | four triangles 2-sewn | 24 | 2 |
//! | [`GMap::make_prism`] | two k-gons and k quadrangles 2-sewn | 12k | 2 |
//! | [`GMap::make_hexahedron`] | six quadrangles 2-sewn | 48 | 2 |
//!
//! [`GMap::make_combinatorial_polygon`], [`GMap::make_combinatorial_tetrahedron`] and
//! [`GMap::make_combinatorial_hexahedron`] make the same objects without points.
//!
//! The dart returned is a flag (vertex, edge, face) named in each constructor's docs, the
//! one CGAL's documentation names, so that a walk written for CGAL (`next`, `opposite`,
//! `other_orientation` are words in the involutions) reaches the same cells here.
//!
//! ```
//! use gmap_core::GMap;
//! let mut g = GMap::new(3);
//! let t = g.make_tetrahedron([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
//! assert_eq!(g.dart_count(), 24);
//! assert_eq!(g.point(t), Some([0.0, 0.0, 0.0]));
//! // the centre of the tetrahedron (its 3-cell) and of its first face
//! assert_eq!(g.barycenter(t, 3), Some([0.25, 0.25, 0.25]));
//! assert_eq!(g.barycenter(t, 2), Some([1.0 / 3.0, 1.0 / 3.0, 0.0]));
//! g.translate([1.0, 2.0, 3.0]);
//! assert_eq!(g.bounding_box(), Some([[1.0, 2.0, 3.0], [2.0, 3.0, 4.0]]));
//! ```

use std::sync::OnceLock;

use rustc_hash::{FxHashMap, FxHashSet};
use smallvec::SmallVec;
use thiserror::Error;

use crate::alpha::AlphaSet;
use crate::attr::{AttrId, Attributes};
use crate::edit::{DartId, EditError, GMap};
use crate::ids::Point;

/// A point given to a constructor: `[x, y, z]`, or `[x, y]` for `[x, y, 0]`.
pub trait IntoPoint {
    /// The point of R³.
    fn into_point(self) -> Point;
}

impl IntoPoint for [f64; 3] {
    fn into_point(self) -> Point {
        self
    }
}

impl IntoPoint for [f64; 2] {
    fn into_point(self) -> Point {
        [self[0], self[1], 0.0]
    }
}

/// Why a constructor of [`crate::points`] refused: nothing was added to the map.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum MakeError {
    /// The object needs involutions the map does not have.
    #[error("a {what} needs a map of dimension at least {needs}, this map has dimension {dim}")]
    Dimension {
        /// the object asked for
        what: &'static str,
        /// the smallest dimension that holds it
        needs: usize,
        /// the map's dimension
        dim: usize,
    },
    /// A polygon or a prism with too few sides.
    #[error("a {what} needs at least {least} sides, {sides} were given")]
    TooFewSides {
        /// the object asked for
        what: &'static str,
        /// the smallest number of sides
        least: usize,
        /// the number given
        sides: usize,
    },
    /// A prism whose top and bottom polygons have different numbers of corners.
    #[error("a prism needs as many top corners as bottom corners ({bottom} at the bottom, {top} at the top)")]
    PrismSides {
        /// corners of the bottom polygon
        bottom: usize,
        /// corners of the top polygon
        top: usize,
    },
    /// The object would have more darts than a map holds.
    #[error("a {what} of {sides} sides would have more darts than a map holds")]
    TooLarge {
        /// the object asked for
        what: &'static str,
        /// the number of sides asked for
        sides: usize,
    },
}

/// An affine map of R³, `p ↦ M p + t`, stored as the 3×4 matrix `[M | t]` (row `r` is
/// `[m_r0, m_r1, m_r2, t_r]`). Apply it to a map with [`GMap::transform`]:
/// `g.transform(|p| a.apply(p))`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Affine(pub [[f64; 4]; 3]);

impl Affine {
    /// The identity.
    pub const IDENTITY: Affine = Affine([[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]]);

    /// The translation by `v`.
    pub fn translation(v: [f64; 3]) -> Affine {
        let mut a = Affine::IDENTITY;
        for (row, x) in a.0.iter_mut().zip(v) {
            row[3] = x;
        }
        a
    }

    /// The scaling by `s[k]` along axis `k`, fixing the origin.
    pub fn scaling(s: [f64; 3]) -> Affine {
        let mut a = Affine([[0.0; 4]; 3]);
        for (k, x) in s.into_iter().enumerate() {
            a.0[k][k] = x;
        }
        a
    }

    /// The rotation by `angle` radians about the z axis (counterclockwise seen from +z).
    pub fn rotation_z(angle: f64) -> Affine {
        let (s, c) = angle.sin_cos();
        Affine([[c, -s, 0.0, 0.0], [s, c, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]])
    }

    /// `M p + t`.
    pub fn apply(&self, p: Point) -> Point {
        let r = |row: &[f64; 4]| row[0] * p[0] + row[1] * p[1] + row[2] * p[2] + row[3];
        [r(&self.0[0]), r(&self.0[1]), r(&self.0[2])]
    }

    /// `self ∘ other`: first `other`, then `self`.
    pub fn then_after(&self, other: &Affine) -> Affine {
        let mut out = [[0.0; 4]; 3];
        for (r, row) in out.iter_mut().enumerate() {
            for (c, x) in row.iter_mut().enumerate() {
                *x = (0..3).map(|k| self.0[r][k] * other.0[k][c]).sum::<f64>();
            }
            row[3] += self.0[r][3];
        }
        Affine(out)
    }
}

/// The corners of the side faces, bottom and top of a prism over `k` corners: bottom corner
/// `j` is `j`, the top corner above it is `k + j`. The first face is the side
/// `(b_0, t_0, t_1, b_1)`.
fn prism_faces(k: usize) -> Vec<Vec<usize>> {
    let mut faces: Vec<Vec<usize>> = (0..k).map(|j| vec![j, k + j, k + (j + 1) % k, (j + 1) % k]).collect();
    faces.push((0..k).collect());
    faces.push((k..2 * k).collect());
    faces
}

/// A closed surface of polygons laid out once by [`GMap::add_faces`]'s rule and copied
/// into maps as a block: the constructors of fixed shape (the hexahedron) make their darts
/// from it without hashing edges, and give each corner its point without walking it.
struct Template {
    /// `alpha_0, alpha_1, alpha_2` of each dart, by dart number (creation order)
    rows: Vec<[u32; 3]>,
    /// the darts of each corner: the whole vertex while the copy is 3-free
    corners: Vec<Vec<u32>>,
}

impl Template {
    /// The template of [`GMap::add_faces`] on `faces` (same dart numbers, same links).
    /// Precondition: as `add_faces`, and every edge used by exactly two faces.
    fn from_faces(corners: usize, faces: &[Vec<usize>]) -> Template {
        let mut rows: Vec<[u32; 3]> = Vec::new();
        let mut at: Vec<Vec<u32>> = vec![Vec::new(); corners];
        let mut open: FxHashMap<(usize, usize), u32> = FxHashMap::default();
        for face in faces {
            let (k, base) = (face.len(), rows.len() as u32);
            rows.extend((0..2 * k as u32).map(|j| [base + j; 3]));
            for j in 0..k {
                let (u, v) = (face[j], face[(j + 1) % k]);
                let (a, b) = (base + 2 * j as u32, base + 2 * j as u32 + 1);
                let c = base + ((2 * j + 2) % (2 * k)) as u32;
                rows[a as usize][0] = b;
                rows[b as usize][0] = a;
                rows[b as usize][1] = c;
                rows[c as usize][1] = b;
                for (x, key) in [(a, (u, v)), (b, (v, u))] {
                    at[key.0].push(x);
                    match open.remove(&key) {
                        Some(y) => {
                            rows[x as usize][2] = y;
                            rows[y as usize][2] = x;
                        }
                        None => {
                            open.insert(key, x);
                        }
                    }
                }
            }
        }
        Template { rows, corners: at }
    }

    /// The hexahedron of [`GMap::make_hexahedron`]: the prism over a square.
    fn hexahedron() -> &'static Template {
        static HEX: OnceLock<Template> = OnceLock::new();
        HEX.get_or_init(|| Template::from_faces(8, &prism_faces(4)))
    }
}

/// The faces of a tetrahedron on corners `0..4`, the first one `(0, 1, 2)`.
const TETRAHEDRON: [[usize; 3]; 4] = [[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]];

/// The largest number of darts a constructor makes in one call.
const MAX_DARTS: usize = (u32::MAX - 2) as usize;

impl<A: Attributes> GMap<A> {
    /// Checks that the map has `alpha_needs`.
    fn needs(&self, what: &'static str, needs: usize) -> Result<(), MakeError> {
        if self.dim() < needs {
            return Err(MakeError::Dimension { what, needs, dim: self.dim() });
        }
        Ok(())
    }

    /// Copies `t` into the map as new darts, corner `c` at `points[c]` when points are
    /// given; returns the copy of dart 0. Precondition: dimension `>= 2`. O(darts · n), no
    /// hashing and no vertex walk.
    fn instantiate(&mut self, t: &Template, points: Option<&[Point]>) -> DartId {
        let first = self.create_block(t.rows.len());
        for (k, row) in t.rows.iter().enumerate() {
            for (i, &e) in row.iter().enumerate() {
                if e as usize > k {
                    self.link_block(first + k, first + e as usize, i);
                }
            }
        }
        if let Some(points) = points {
            let mut vertex: SmallVec<[DartId; 8]> = SmallVec::new();
            for (darts, &p) in t.corners.iter().zip(points) {
                vertex.clear();
                vertex.extend(darts.iter().map(|&x| self.block_dart(first + x as usize)));
                self.set_fresh_point(&vertex, p);
            }
        }
        self.block_dart(first)
    }

    /// Adds a closed polygon for every face (a cycle of corner numbers), then `alpha_2`-links
    /// the darts of two faces that have the same corner on the same edge. Returns the dart of
    /// the first face at its first corner on the edge to its second corner, and one dart per
    /// corner. Precondition (checked by the callers): dimension at least 2, every face has at least 3 corners, no edge is used twice by one face.
    /// O(total corners · n).
    fn add_faces(&mut self, corners: usize, faces: &[Vec<usize>]) -> (DartId, Vec<Option<DartId>>) {
        let mut at: Vec<Option<DartId>> = vec![None; corners];
        let mut open: FxHashMap<(usize, usize), DartId> = FxHashMap::default();
        let mut first = None;
        for face in faces {
            let k = face.len();
            let darts: Vec<DartId> = (0..2 * k).map(|_| self.create_dart()).collect();
            for j in 0..k {
                let (u, v) = (face[j], face[(j + 1) % k]);
                let (a, b) = (darts[2 * j], darts[2 * j + 1]);
                self.link(a, b, 0);
                self.link(b, darts[(2 * j + 2) % (2 * k)], 1);
                for (x, key) in [(a, (u, v)), (b, (v, u))] {
                    at[key.0].get_or_insert(x);
                    match open.remove(&key) {
                        Some(y) => self.link(x, y, 2),
                        None => {
                            open.insert(key, x);
                        }
                    }
                }
            }
            first.get_or_insert(darts[0]);
        }
        (first.expect("at least one face"), at)
    }

    /// Sets the point of every corner that has a dart.
    fn place(&mut self, at: &[Option<DartId>], points: &[Point]) {
        for (d, &p) in at.iter().zip(points) {
            if let Some(d) = *d {
                self.set_point(d, Some(p));
            }
        }
    }

    /// An isolated edge from `p0` to `p1` (two darts linked by `alpha_0`); returns the dart at
    /// `p0`. Precondition: dimension `>= 1`. O(n).
    ///
    /// # Panics
    /// On a 0-map; [`GMap::try_make_segment`] returns the error.
    #[track_caller]
    pub fn make_segment(&mut self, p: [impl IntoPoint; 2]) -> DartId {
        self.try_make_segment(p).unwrap_or_else(|e| panic!("{e}"))
    }

    /// [`GMap::make_segment`], or [`MakeError::Dimension`] on a 0-map.
    pub fn try_make_segment(&mut self, p: [impl IntoPoint; 2]) -> Result<DartId, MakeError> {
        self.needs("segment", 1)?;
        let [p0, p1] = p.map(IntoPoint::into_point);
        let (a, b) = (self.create_dart(), self.create_dart());
        self.link(a, b, 0);
        self.set_point(a, Some(p0));
        self.set_point(b, Some(p1));
        Ok(a)
    }

    /// An isolated polygon without points, of `k` corners (`2k` darts, its border 2-free): the
    /// dart returned is at corner 0 on the edge to corner 1, and `alpha_1 ∘ alpha_0` (CGAL's
    /// `next`) walks the corners in order. Precondition: dimension `>= 1`, `k >= 1` (k = 1, 2:
    /// a monogon, a digon). O(k n).
    ///
    /// # Panics
    /// When the precondition fails; [`GMap::try_make_combinatorial_polygon`] returns the error.
    #[track_caller]
    pub fn make_combinatorial_polygon(&mut self, k: usize) -> DartId {
        self.try_make_combinatorial_polygon(k).unwrap_or_else(|e| panic!("{e}"))
    }

    /// [`GMap::make_combinatorial_polygon`], or the error: [`MakeError::Dimension`],
    /// [`MakeError::TooFewSides`] for `k = 0`, [`MakeError::TooLarge`].
    pub fn try_make_combinatorial_polygon(&mut self, k: usize) -> Result<DartId, MakeError> {
        self.needs("polygon", 1)?;
        if k == 0 {
            return Err(MakeError::TooFewSides { what: "polygon", least: 1, sides: 0 });
        }
        if k.checked_mul(2).is_none_or(|d| d > MAX_DARTS) {
            return Err(MakeError::TooLarge { what: "polygon", sides: k });
        }
        let darts: Vec<DartId> = (0..2 * k).map(|_| self.create_dart()).collect();
        for j in 0..k {
            self.link(darts[2 * j], darts[2 * j + 1], 0);
            self.link(darts[2 * j + 1], darts[(2 * j + 2) % (2 * k)], 1);
        }
        Ok(darts[0])
    }

    /// An isolated polygon with the given corners, in order: the combinatorial polygon of
    /// [`GMap::make_combinatorial_polygon`] with corner `j` at `points[j]`. Returns the dart
    /// at `points[0]` on the edge to `points[1]`. Precondition: dimension `>= 1`, at least one
    /// point. O(k n).
    ///
    /// # Panics
    /// When the precondition fails; [`GMap::try_make_polygon`] returns the error.
    #[track_caller]
    pub fn make_polygon<P: IntoPoint + Copy>(&mut self, points: &[P]) -> DartId {
        self.try_make_polygon(points).unwrap_or_else(|e| panic!("{e}"))
    }

    /// [`GMap::make_polygon`], or the error of [`GMap::try_make_combinatorial_polygon`].
    pub fn try_make_polygon<P: IntoPoint + Copy>(&mut self, points: &[P]) -> Result<DartId, MakeError> {
        let d = self.try_make_combinatorial_polygon(points.len())?;
        let mut x = d;
        for p in points {
            self.set_point(x, Some(p.into_point()));
            x = self.alpha(self.alpha(x, 0), 1);
        }
        Ok(d)
    }

    /// The triangle `p0 p1 p2` ([`GMap::make_polygon`] of three points); returns the dart at
    /// `p0` on the edge `[p0, p1]`. Precondition: dimension `>= 1`. O(n).
    ///
    /// # Panics
    /// On a 0-map; [`GMap::try_make_polygon`] returns the error.
    #[track_caller]
    pub fn make_triangle<P: IntoPoint + Copy>(&mut self, p: [P; 3]) -> DartId {
        self.make_polygon(&p)
    }

    /// The quadrangle `p0 p1 p2 p3` ([`GMap::make_polygon`] of four points); returns the dart
    /// at `p0` on the edge `[p0, p1]`. Precondition: dimension `>= 1`. O(n).
    ///
    /// # Panics
    /// On a 0-map; [`GMap::try_make_polygon`] returns the error.
    #[track_caller]
    pub fn make_quadrangle<P: IntoPoint + Copy>(&mut self, p: [P; 4]) -> DartId {
        self.make_polygon(&p)
    }

    /// An isolated tetrahedron without points: four triangles 2-sewn, 24 darts, its faces
    /// 3-free. Corners are numbered as in [`GMap::make_tetrahedron`], and the same dart is
    /// returned. Precondition: dimension `>= 2`. O(n).
    ///
    /// # Panics
    /// On a map of dimension below 2; [`GMap::try_make_combinatorial_tetrahedron`] returns the
    /// error.
    #[track_caller]
    pub fn make_combinatorial_tetrahedron(&mut self) -> DartId {
        self.try_make_combinatorial_tetrahedron().unwrap_or_else(|e| panic!("{e}"))
    }

    /// [`GMap::make_combinatorial_tetrahedron`], or [`MakeError::Dimension`].
    pub fn try_make_combinatorial_tetrahedron(&mut self) -> Result<DartId, MakeError> {
        self.needs("tetrahedron", 2)?;
        let faces: Vec<Vec<usize>> = TETRAHEDRON.iter().map(|f| f.to_vec()).collect();
        Ok(self.add_faces(4, &faces).0)
    }

    /// The tetrahedron with corners `p0 p1 p2 p3`: returns the dart at `p0` on the edge
    /// `[p0, p1]` in the face `p0 p1 p2` (CGAL's `make_tetrahedron`). Precondition: dimension
    /// `>= 2`. O(n).
    ///
    /// # Panics
    /// On a map of dimension below 2; [`GMap::try_make_tetrahedron`] returns the error.
    #[track_caller]
    pub fn make_tetrahedron<P: IntoPoint>(&mut self, p: [P; 4]) -> DartId {
        self.try_make_tetrahedron(p).unwrap_or_else(|e| panic!("{e}"))
    }

    /// [`GMap::make_tetrahedron`], or [`MakeError::Dimension`].
    pub fn try_make_tetrahedron<P: IntoPoint>(&mut self, p: [P; 4]) -> Result<DartId, MakeError> {
        self.needs("tetrahedron", 2)?;
        let faces: Vec<Vec<usize>> = TETRAHEDRON.iter().map(|f| f.to_vec()).collect();
        let (d, at) = self.add_faces(4, &faces);
        self.place(&at, &p.map(IntoPoint::into_point));
        Ok(d)
    }

    /// The prism over a k-gon: the bottom polygon `bottom[0..k]`, the top one `top[0..k]` with
    /// `top[j]` above `bottom[j]`, and k quadrangles `bottom[j] top[j] top[j+1] bottom[j+1]`
    /// 2-sewn to them (`12 k` darts, its faces 3-free). Returns the dart at `bottom[0]` on the
    /// edge `[bottom[0], top[0]]` in the face `bottom[0] top[0] top[1] bottom[1]`; k = 3 is the
    /// triangular prism, k = 4 the hexahedron. Precondition: dimension `>= 2`, `k >= 3`, as
    /// many top corners as bottom corners. O(k n).
    ///
    /// # Panics
    /// When the precondition fails; [`GMap::try_make_prism`] returns the error.
    #[track_caller]
    pub fn make_prism<P: IntoPoint + Copy>(&mut self, bottom: &[P], top: &[P]) -> DartId {
        self.try_make_prism(bottom, top).unwrap_or_else(|e| panic!("{e}"))
    }

    /// [`GMap::make_prism`], or the error: [`MakeError::Dimension`],
    /// [`MakeError::PrismSides`], [`MakeError::TooFewSides`], [`MakeError::TooLarge`].
    pub fn try_make_prism<P: IntoPoint + Copy>(&mut self, bottom: &[P], top: &[P]) -> Result<DartId, MakeError> {
        self.needs("prism", 2)?;
        let k = bottom.len();
        if top.len() != k {
            return Err(MakeError::PrismSides { bottom: k, top: top.len() });
        }
        if k < 3 {
            return Err(MakeError::TooFewSides { what: "prism", least: 3, sides: k });
        }
        if k.checked_mul(12).is_none_or(|d| d > MAX_DARTS) {
            return Err(MakeError::TooLarge { what: "prism", sides: k });
        }
        let (d, at) = self.add_faces(2 * k, &prism_faces(k));
        let points: Vec<Point> = bottom.iter().chain(top).map(|p| p.into_point()).collect();
        self.place(&at, &points);
        Ok(d)
    }

    /// An isolated hexahedron without points: six quadrangles 2-sewn, 48 darts, its faces
    /// 3-free; corners and the dart returned as in [`GMap::make_hexahedron`]. Precondition:
    /// dimension `>= 2`. O(n).
    ///
    /// # Panics
    /// On a map of dimension below 2; [`GMap::try_make_combinatorial_hexahedron`] returns the
    /// error.
    #[track_caller]
    pub fn make_combinatorial_hexahedron(&mut self) -> DartId {
        self.try_make_combinatorial_hexahedron().unwrap_or_else(|e| panic!("{e}"))
    }

    /// [`GMap::make_combinatorial_hexahedron`], or [`MakeError::Dimension`].
    pub fn try_make_combinatorial_hexahedron(&mut self) -> Result<DartId, MakeError> {
        self.needs("hexahedron", 2)?;
        Ok(self.instantiate(Template::hexahedron(), None))
    }

    /// The hexahedron with corners `p[0..8]` in CGAL's order: `p0 p1 p2 p3` is one face, and
    /// `p5, p6, p7, p4` are the corners joined to `p0, p1, p2, p3` by an edge (so the side
    /// faces are `p0 p5 p6 p1`, `p1 p6 p7 p2`, `p2 p7 p4 p3`, `p3 p4 p5 p0` and the opposite
    /// face is `p5 p6 p7 p4`). Returns the dart at `p0` on the edge `[p0, p5]` in the face
    /// `p0 p5 p6 p1`, the one CGAL's `make_hexahedron` returns. Precondition: dimension
    /// `>= 2`. O(n).
    ///
    /// ```
    /// use gmap_core::GMap;
    /// let mut g = GMap::new(3);
    /// let p = [[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.],
    ///          [0., 1., 1.], [0., 0., 1.], [1., 0., 1.], [1., 1., 1.]];
    /// let d = g.make_hexahedron(p);
    /// assert_eq!(g.point(g.alpha(d, 0)), Some(p[5]));
    /// assert_eq!(g.barycenter(d, 3), Some([0.5, 0.5, 0.5]));
    /// assert_eq!(g.barycenter(d, 2), Some([0.5, 0.0, 0.5]));
    /// ```
    ///
    /// # Panics
    /// On a map of dimension below 2; [`GMap::try_make_hexahedron`] returns the error.
    #[track_caller]
    pub fn make_hexahedron<P: IntoPoint + Copy>(&mut self, p: [P; 8]) -> DartId {
        self.try_make_hexahedron(p).unwrap_or_else(|e| panic!("{e}"))
    }

    /// [`GMap::make_hexahedron`], or [`MakeError::Dimension`].
    pub fn try_make_hexahedron<P: IntoPoint + Copy>(&mut self, p: [P; 8]) -> Result<DartId, MakeError> {
        self.needs("hexahedron", 2)?;
        // the prism's corners: the bottom p0..p3, then the top above them
        let corners = [0, 1, 2, 3, 5, 6, 7, 4].map(|k| p[k].into_point());
        Ok(self.instantiate(Template::hexahedron(), Some(&corners)))
    }

    /// The points of the distinct vertices met by the orbit `<set>(d)`, once per vertex;
    /// `None` when a vertex has no point. O(orbit size · n).
    fn vertex_points(&self, d: DartId, set: AlphaSet) -> Option<Vec<Point>> {
        let mut seen: FxHashSet<AttrId> = FxHashSet::default();
        let mut out = Vec::new();
        for x in self.orbit_iter(d, set) {
            if seen.insert(self.point_id(x)?) {
                out.push(self.point(x)?);
            }
        }
        Some(out)
    }

    /// The barycentre of the i-cell of `d`: the mean of the points of its distinct vertices
    /// (each vertex counted once, however many darts of the cell it has), as CGAL's
    /// `barycenter<i>`. `None` when a vertex of the cell has no point. For `i = 0` it is the
    /// vertex's point. Vertices are told apart by the handles of their points, one per vertex
    /// while the points are consistent ([`GMap::check_attributes`]), so no vertex orbit is
    /// walked. O(cell size · n).
    ///
    /// # Panics
    /// On a stale handle or `i > n`; [`GMap::try_barycenter`] returns the error.
    #[track_caller]
    pub fn barycenter(&self, d: DartId, i: usize) -> Option<Point> {
        self.try_barycenter(d, i).unwrap_or_else(|e| panic!("{e}"))
    }

    /// [`GMap::barycenter`], or [`EditError::NoSuchDart`] for a stale handle and
    /// [`EditError::NoSuchCells`] for `i > n`.
    pub fn try_barycenter(&self, d: DartId, i: usize) -> Result<Option<Point>, EditError> {
        self.cell_checked(d, i)?;
        let Some(points) = self.vertex_points(d, AlphaSet::cell(i, self.dim())) else {
            return Ok(None);
        };
        let mut sum = [0.0; 3];
        for p in &points {
            for k in 0..3 {
                sum[k] += p[k];
            }
        }
        let n = points.len() as f64;
        Ok(Some(sum.map(|s| s / n)))
    }

    /// Checks a live dart and `i <= n`, naming the cells.
    fn cell_checked(&self, d: DartId, i: usize) -> Result<(), EditError> {
        if !self.contains(d) {
            return Err(EditError::NoSuchDart(d));
        }
        if i > self.dim() {
            return Err(EditError::NoSuchCells { cell: i, dim: self.dim() });
        }
        Ok(())
    }

    /// Applies `f` to the point of every vertex of the orbit `<set>(d)` that has one, once
    /// per vertex.
    fn transform_orbit(&mut self, d: DartId, set: AlphaSet, f: &mut impl FnMut(Point) -> Point) {
        let mut seen: FxHashSet<AttrId> = FxHashSet::default();
        let ids: Vec<AttrId> =
            self.orbit_iter(d, set).filter_map(|x| self.point_id(x)).filter(|&id| seen.insert(id)).collect();
        for id in ids {
            if let Some(p) = self.point_by_id_mut(id) {
                *p = f(*p);
            }
        }
    }

    /// Replaces the point `p` of every vertex by `f(p)`, once per vertex (vertices without a
    /// point are left alone). With an [`Affine`] `a`: `g.transform(|p| a.apply(p))`.
    /// O(N n).
    pub fn transform(&mut self, mut f: impl FnMut(Point) -> Point) {
        let mut seen: FxHashSet<AttrId> = FxHashSet::default();
        let ids: Vec<AttrId> = self.darts().filter_map(|x| self.point_id(x)).filter(|&id| seen.insert(id)).collect();
        for id in ids {
            if let Some(p) = self.point_by_id_mut(id) {
                *p = f(*p);
            }
        }
    }

    /// [`GMap::transform`] restricted to the vertices of the i-cell of `d` (`i = n + 1`: the
    /// connected component of `d`). A vertex shared with other cells moves for them too.
    /// O(cell size · n).
    ///
    /// # Panics
    /// On a stale handle or `i > n + 1`; [`GMap::try_transform_cell`] returns the error.
    #[track_caller]
    pub fn transform_cell(&mut self, d: DartId, i: usize, f: impl FnMut(Point) -> Point) {
        self.try_transform_cell(d, i, f).unwrap_or_else(|e| panic!("{e}"))
    }

    /// [`GMap::transform_cell`], or [`EditError::NoSuchDart`] / [`EditError::NoSuchCells`]
    /// (and no change).
    pub fn try_transform_cell(
        &mut self,
        d: DartId,
        i: usize,
        mut f: impl FnMut(Point) -> Point,
    ) -> Result<(), EditError> {
        let set = if i == self.dim() + 1 {
            if !self.contains(d) {
                return Err(EditError::NoSuchDart(d));
            }
            AlphaSet::all(self.dim())
        } else {
            self.cell_checked(d, i)?;
            AlphaSet::cell(i, self.dim())
        };
        self.transform_orbit(d, set, &mut f);
        Ok(())
    }

    /// Translates every point by `v`. O(N n).
    pub fn translate(&mut self, v: [f64; 3]) {
        self.transform(|p| [p[0] + v[0], p[1] + v[1], p[2] + v[2]]);
    }

    /// Translates the points of the vertices of the i-cell of `d` by `v` (`i = n + 1`: the
    /// connected component), as [`GMap::transform_cell`]. O(cell size · n).
    ///
    /// # Panics
    /// On a stale handle or `i > n + 1`; [`GMap::try_transform_cell`] returns the error.
    #[track_caller]
    pub fn translate_cell(&mut self, d: DartId, i: usize, v: [f64; 3]) {
        self.transform_cell(d, i, |p| [p[0] + v[0], p[1] + v[1], p[2] + v[2]]);
    }

    /// The smallest box `[min, max]` holding every point, or `None` when no vertex has a
    /// point. O(N).
    pub fn bounding_box(&self) -> Option<[Point; 2]> {
        let mut bbox: Option<[Point; 2]> = None;
        for d in self.darts() {
            if let Some(p) = self.point(d) {
                let b = bbox.get_or_insert([p, p]);
                for k in 0..3 {
                    b[0][k] = b[0][k].min(p[k]);
                    b[1][k] = b[1][k].max(p[k]);
                }
            }
        }
        bbox
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Cells;

    const CUBE: [[f64; 3]; 8] = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 1.0, 1.0],
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 1.0],
        [1.0, 1.0, 1.0],
    ];

    #[test]
    fn constructors_make_the_cells_of_their_object() {
        let mut g = GMap::new(3);
        let s = g.make_segment([[0.0, 0.0], [1.0, 0.0]]);
        assert_eq!(g.point(g.alpha(s, 0)), Some([1.0, 0.0, 0.0]));
        g.make_triangle([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        g.make_quadrangle(CUBE[..4].try_into().unwrap());
        g.make_tetrahedron([CUBE[0], CUBE[1], CUBE[3], CUBE[5]]);
        g.make_prism(&CUBE[..3], &CUBE[5..8]);
        g.make_hexahedron(CUBE);
        g.make_combinatorial_polygon(5);
        g.make_combinatorial_tetrahedron();
        g.make_combinatorial_hexahedron();
        g.validate().unwrap();
        assert_eq!(g.dart_count(), 2 + 6 + 8 + 24 + 36 + 48 + 10 + 24 + 48);
        // per object: vertices, edges, faces, volumes (one component each)
        let objects = [[2, 1, 1, 1], [3, 3, 1, 1], [4, 4, 1, 1], [4, 6, 4, 1], [6, 9, 5, 1], [8, 12, 6, 1]];
        let combinatorial = [[5, 5, 1, 1], [4, 6, 4, 1], [8, 12, 6, 1]];
        let mut want = vec![0; 4];
        for o in objects.iter().chain(&combinatorial) {
            for k in 0..4 {
                want[k] += o[k];
            }
        }
        assert_eq!(g.cell_counts(), want);
        assert_eq!(g.component_count(), 9);
        // only the objects with coordinates have points: one per vertex
        assert_eq!(g.point_count(), 2 + 3 + 4 + 4 + 6 + 8);
    }

    #[test]
    fn the_returned_darts_are_the_flags_cgal_names() {
        let mut g = GMap::new(3);
        let d = g.make_hexahedron(CUBE);
        let t = g.make_tetrahedron([CUBE[0], CUBE[1], CUBE[3], CUBE[5]]);
        let pts = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 3.0], [0.0, 1.0]];
        let mut x = g.make_polygon(&pts);
        let next = |x: DartId| g.alpha(g.alpha(x, 0), 1);
        // p0, edge [p0, p5], face p0 p5 p6 p1
        assert_eq!(g.point(d), Some(CUBE[0]));
        assert_eq!(g.point(g.alpha(d, 0)), Some(CUBE[5]));
        assert_eq!(g.point(next(next(d))), Some(CUBE[6]));
        assert_eq!(g.point(next(next(next(d)))), Some(CUBE[1]));
        assert_eq!(g.point(g.alpha(t, 0)), Some(CUBE[1]));
        assert_eq!(g.point(next(next(t))), Some(CUBE[3]));
        // the polygon's darts walk its corners in order
        for p in pts {
            assert_eq!(g.point(x), Some(p.into_point()));
            x = next(x);
        }
    }

    #[test]
    fn refusals_change_nothing() {
        let mut g = GMap::new(1);
        assert_eq!(
            g.try_make_combinatorial_hexahedron(),
            Err(MakeError::Dimension { what: "hexahedron", needs: 2, dim: 1 })
        );
        assert_eq!(
            g.try_make_combinatorial_polygon(0),
            Err(MakeError::TooFewSides { what: "polygon", least: 1, sides: 0 })
        );
        assert_eq!(
            g.try_make_combinatorial_polygon(usize::MAX),
            Err(MakeError::TooLarge { what: "polygon", sides: usize::MAX })
        );
        let mut h = GMap::new(2);
        assert_eq!(h.try_make_prism(&CUBE[..3], &CUBE[..4]), Err(MakeError::PrismSides { bottom: 3, top: 4 }));
        assert_eq!(
            h.try_make_prism(&CUBE[..2], &CUBE[2..4]),
            Err(MakeError::TooFewSides { what: "prism", least: 3, sides: 2 })
        );
        assert_eq!(
            GMap::new(0).try_make_segment([[0.0; 3]; 2]),
            Err(MakeError::Dimension { what: "segment", needs: 1, dim: 0 })
        );
        assert_eq!(g.dart_count() + h.dart_count(), 0);
    }

    #[test]
    fn barycentres_count_each_vertex_once() {
        let mut g = GMap::new(3);
        let d = g.make_hexahedron(CUBE);
        assert_eq!(g.barycenter(d, 0), Some(CUBE[0]));
        assert_eq!(g.barycenter(d, 1), Some([0.0, 0.0, 0.5]));
        assert_eq!(g.barycenter(d, 2), Some([0.5, 0.0, 0.5]));
        assert_eq!(g.barycenter(d, 3), Some([0.5, 0.5, 0.5]));
        assert_eq!(g.try_barycenter(d, 4), Err(EditError::NoSuchCells { cell: 4, dim: 3 }));
        // a vertex without a point: no barycentre of the cells around it
        let c = g.make_combinatorial_hexahedron();
        assert_eq!(g.barycenter(c, 3), None);
        g.set_point(c, Some([1.0, 1.0, 1.0]));
        assert_eq!(g.barycenter(c, 0), Some([1.0, 1.0, 1.0]));
        assert_eq!(g.barycenter(c, 1), None);
        g.remove_dart(c);
        assert_eq!(g.try_barycenter(c, 0), Err(EditError::NoSuchDart(c)));
    }

    #[test]
    fn transforms_move_each_vertex_once() {
        let mut g: GMap<((), (), Cells<u8>)> = GMap::with_attributes(3);
        let a = g.make_hexahedron(CUBE);
        let b = g.make_tetrahedron([CUBE[0], CUBE[1], CUBE[3], CUBE[5]]);
        g.translate_cell(b, 4, [10.0, 0.0, 0.0]);
        assert_eq!(g.barycenter(b, 3), Some([10.25, 0.25, 0.25]));
        assert_eq!(g.barycenter(a, 3), Some([0.5, 0.5, 0.5]));
        // moving one face of the cube moves its four vertices, shared with the other faces
        g.translate_cell(a, 2, [0.0, -1.0, 0.0]);
        assert_eq!(g.barycenter(a, 3), Some([0.5, 0.0, 0.5]));
        let r = Affine::rotation_z(std::f64::consts::FRAC_PI_2).then_after(&Affine::scaling([2.0, 2.0, 2.0]));
        assert_eq!(Affine::IDENTITY.then_after(&r), r);
        g.transform(|p| Affine::translation([1.0, 0.0, 0.0]).apply(p));
        assert_eq!(g.bounding_box(), Some([[1.0, -1.0, 0.0], [12.0, 1.0, 1.0]]));
        let before = g.barycenter(a, 3).unwrap();
        g.transform_cell(a, 4, |p| r.apply(p));
        let after = g.barycenter(a, 3).unwrap();
        let want = [-2.0 * before[1], 2.0 * before[0], 2.0 * before[2]];
        for k in 0..3 {
            assert!((after[k] - want[k]).abs() < 1e-12, "{after:?} {want:?}");
        }
        assert_eq!(g.try_transform_cell(a, 5, |p| p), Err(EditError::NoSuchCells { cell: 5, dim: 3 }));
        g.validate().unwrap();
        assert_eq!(GMap::new(2).bounding_box(), None);
    }
}
