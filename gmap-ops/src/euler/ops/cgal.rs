//! CGAL's names for the Euler operators, for users coming from CGAL's `Generalized_map`
//! and `Linear_cell_complex`.
//!
//! Each function here is the operator of this module under CGAL's name. Like CGAL's, the
//! insertions return a dart of the cell they make; the operators under our names return
//! the [`EulerOp`](crate::euler::EulerOp) record instead. Each has a predicate, and a
//! violated precondition is an [`EulerError`] naming the dart, never a panic or an invalid
//! map. Attributes and vertex points follow every operator as in CGAL: merge hooks when
//! cells merge, split hooks when cells split, one attribute per cell afterwards.
//!
//! | CGAL | here (CGAL's name) | ours | precondition / predicate |
//! | --- | --- | --- | --- |
//! | `insert_cell_0_in_cell_1(d)` | [`insert_cell_0_in_cell_1`] (CGAL's construction: on an edge with a free end the new vertex is that end) | [`try_insert_vertex`], [`try_insert_vertex_at`] (EO's `mve`: on an edge with a free end the new vertex lies between, the missing end stays missing) | [`is_insertable_cell_0_in_cell_1`]: `n >= 1`; [`can_insert_vertex`]: also the edge not folded onto itself |
//! | LCC `insert_barycenter_in_cell<i>(d)` | [`insert_barycenter_in_cell`] (any `1 <= i <= n`; for `i = 1` also [`insert_cell_0_in_cell_1`], which puts the vertex at the middle when both ends have points) | [`try_star_cell`]`(g, d, i, g.barycenter(d, i))` | [`is_insertable_barycenter_in_cell`]: every vertex of the cell has a point |
//! | LCC `insert_point_in_cell<i>(d, p)` | [`insert_point_in_cell`] (any `1 <= i <= n`) | [`try_star_cell`], [`try_insert_vertex_at`] for `i = 1` | [`can_star_cell`]: `1 <= i <= n` |
//! | `insert_cell_0_in_cell_2(d)` | [`insert_cell_0_in_cell_2`] (a new vertex joined to every corner of the face) | [`try_star_face`] | [`is_insertable_cell_0_in_cell_2`] = [`can_star_face`] |
//! | `insert_cell_1_in_cell_2(d1, d2)` | [`insert_cell_1_in_cell_2`] | [`try_insert_edge`] (`mef`) | [`is_insertable_cell_1_in_cell_2`] = [`can_insert_edge`]: `n >= 2`, `d2` at another corner of `d1`'s face |
//! | `insert_dangling_cell_1_in_cell_2(d)` (LCC: `(d, p)`) | [`insert_dangling_cell_1_in_cell_2`] | [`try_insert_dangling_edge`], [`try_insert_dangling_edge_at`] (`mev`) | [`is_insertable_dangling_cell_1_in_cell_2`] = [`can_insert_dangling_edge`]: `n >= 2`, `d` not 1-free |
//! | `insert_cell_1_between_two_cells_2(d1, d2)` (CGAL 6) | [`insert_cell_1_between_two_cells_2`] | [`try_insert_edge_between_faces`] | [`is_insertable_cell_1_between_two_cells_2`] = [`can_insert_edge_between_faces`]: `d1`, `d2` in different faces with matching corners |
//! | `insert_cell_2_in_cell_3(first, last)` | [`insert_cell_2_in_cell_3`] (CGAL's construction along an ordered path, also of 2-free darts) | [`try_split_cell`]`(g, path, 3)` (`mfs`, the darts in any order) | [`is_insertable_cell_2_in_cell_3`]: `n >= 3` and an ordered closed path of darts, one per edge, `alpha_0` of each in the vertex of the next within the volume; or a cut of [`can_split_cell`] |
//! | `remove_cell<i>(d)` | [`remove_cell`], [`try_remove_cell`] (any `0 <= i <= n`) | [`try_remove_cell_keeping_homology`] (`kve`, `kef`, `kfs`, `kev`) | [`is_removable`]: `i <= n`, degree 2 for `i <= n - 2`; [`is_removable_keeping_homology`]: also two distinct interior (i+1)-cells, nothing falls apart |
//! | `contract_cell<i>(d)` | [`contract_cell`], [`try_contract_cell`] (any `1 <= i <= n`) | [`try_contract_cell_keeping_homology`] | [`is_contractible`]: `1 <= i <= n`, dual degree 2 for `i >= 2`; [`is_contractible_keeping_homology`]: also two distinct (i-1)-cells, none on the boundary |
//! | `close<i>()` | — | [`try_close`] | [`can_close`] |
//! | `make_combinatorial_hexahedron()` | [`GMap::make_combinatorial_hexahedron`](gmap_core::GMap::make_combinatorial_hexahedron) | [`GMap::try_append`](gmap_core::GMap::try_append) of [`build::cube`](crate::build::cube)`(3)` | — |
//! | `make_combinatorial_tetrahedron()` | [`GMap::make_combinatorial_tetrahedron`](gmap_core::GMap::make_combinatorial_tetrahedron) | [`GMap::try_append`](gmap_core::GMap::try_append) of [`build::simplex`](crate::build::simplex)`(3)` | — |
//! | LCC `make_hexahedron(p0, …, p7)`, `make_tetrahedron`, `make_triangle`, `make_quadrangle`, `make_segment` | [`GMap::make_hexahedron`](gmap_core::GMap::make_hexahedron) and the other constructors of [`gmap_core::points`] | — | — |
//!
//! `insert_cell_2_in_cell_3` takes CGAL's path: one dart per edge, in order, `alpha_0` of
//! each in the vertex of the next within the volume. It builds the face as CGAL does: its
//! darts are `alpha_2`-linked to the path, and when the path's darts were not 2-free a
//! second copy `alpha_3`-linked to the first takes their old partners (the volume splits
//! when the path separates it). A set of darts in another order is taken as
//! [`try_split_cell`] takes a cut for `i = 3`.
//!
//! ```
//! use gmap_core::GMap;
//! use gmap_ops::build;
//! use gmap_ops::euler::ops::{insert_cell_0_in_cell_1, insert_cell_1_between_two_cells_2, remove_cell};
//! // CGAL's gmap_3_insert: a square hung from a face of a hexahedron by a new edge
//! let mut g = GMap::new(3);
//! let hexahedron = g.try_append(&build::cube(3).unwrap()).unwrap()[0];
//! let square = g.try_append(&build::polygon(4).unwrap()).unwrap()[0];
//! let bridge = insert_cell_1_between_two_cells_2(&mut g, hexahedron, square).unwrap();
//! assert_eq!(g.characteristics().to_string(),
//!     "#Darts=60, #0-cells=12, #1-cells=17, #2-cells=6, #3-cells=1, #ccs=1, orientable=true, valid=1");
//! // a vertex in the middle of the new edge, then removed again
//! let v = insert_cell_0_in_cell_1(&mut g, bridge).unwrap();
//! remove_cell(&mut g, v, 0);
//! assert_eq!(g.dart_count(), 60);
//! ```

use gmap_core::{Attributes, DartId, GMap, Point};

use super::cgal_insert::{dangling_at_free_dart, insert_face_as_cgal, insert_vertex_as_cgal, is_cgal_path};
use super::common::edge_middle;
use super::edges::{dangling_counted, try_insert_edge_between_faces};
use super::split::{edge_cut, split_counted};
use super::EulerError;
#[cfg(doc)]
use super::{
    can_close, can_insert_dangling_edge, can_insert_edge, can_insert_edge_between_faces, can_insert_vertex,
    can_split_cell, contract_cell, is_contractible, is_contractible_keeping_homology, is_removable,
    is_removable_keeping_homology, remove_cell, try_close, try_contract_cell, try_contract_cell_keeping_homology,
    try_insert_dangling_edge, try_insert_dangling_edge_at, try_insert_edge, try_insert_vertex, try_insert_vertex_at,
    try_remove_cell, try_remove_cell_keeping_homology, try_split_cell,
};
#[cfg(doc)]
use super::{
    can_star_cell, can_star_face, insert_barycenter_in_cell, insert_cell_0_in_cell_2, insert_point_in_cell,
    is_insertable_barycenter_in_cell, is_insertable_cell_0_in_cell_2, try_star_cell, try_star_face,
};

/// Whether [`insert_cell_0_in_cell_1`] would succeed: `d` is live and `n >= 1`.
pub fn is_insertable_cell_0_in_cell_1<A: Attributes>(g: &GMap<A>, d: DartId) -> bool {
    g.contains(d) && g.dim() >= 1
}

/// CGAL's `insert_cell_0_in_cell_1`: a vertex in the edge of `d`, built as CGAL builds it —
/// every dart `x` of the edge gets a new dart at `alpha_0(x)`, so an edge with both ends
/// becomes two edges, and on a 0-free dart (a lone dart, an edge with a missing end) the
/// new vertex is the missing end: a lone dart becomes an edge with two vertices (2, 1, …
/// cells, as CGAL's `GMap_test_insertions.h` asserts). Returns `alpha_0(d)`, a dart of the
/// new vertex, placed at the middle of the edge when both ends have points.
///
/// ```
/// use gmap_core::GMap;
/// use gmap_ops::euler::ops::insert_cell_0_in_cell_1;
/// let mut g = GMap::new(3);
/// let d = g.create_dart();
/// let v = insert_cell_0_in_cell_1(&mut g, d).unwrap();
/// assert_eq!(g.alpha(d, 0), v);
/// assert_eq!(g.cell_counts(), vec![2, 1, 1, 1]);
/// ```
///
/// Precondition ([`is_insertable_cell_0_in_cell_1`]): `d` live, `n >= 1`. Attributes: the
/// edge's attribute stays on the part of `d` and a copy goes to the other (split hook);
/// the other cells keep theirs. O(edge size · n).
pub fn insert_cell_0_in_cell_1<A: Attributes>(g: &mut GMap<A>, d: DartId) -> Result<DartId, EulerError> {
    let point = if g.contains(d) { edge_middle(g, d) } else { None };
    insert_vertex_as_cgal(g, d, point)
}

/// Whether [`insert_cell_1_in_cell_2`] would succeed ([`can_insert_edge`]).
pub fn is_insertable_cell_1_in_cell_2<A: Attributes>(g: &GMap<A>, d1: DartId, d2: DartId) -> bool {
    super::can_insert_edge(g, d1, d2)
}

/// CGAL's `insert_cell_1_in_cell_2`: [`try_insert_edge`] across the face of `d1` from the
/// corner of `d1` to the corner of `d2`, returning the new dart `alpha_1(d1)`, a dart of the
/// new edge. Precondition and cost of [`try_insert_edge`].
pub fn insert_cell_1_in_cell_2<A: Attributes>(g: &mut GMap<A>, d1: DartId, d2: DartId) -> Result<DartId, EulerError> {
    let cut = edge_cut(g, d1, d2)?;
    split_counted(g, &cut, 2, None).map(|(_, e)| e)
}

/// Whether [`insert_dangling_cell_1_in_cell_2`] would succeed: [`can_insert_dangling_edge`],
/// or, as CGAL allows, `d` a live 1-free dart of a map of dimension `n >= 2`.
pub fn is_insertable_dangling_cell_1_in_cell_2<A: Attributes>(g: &GMap<A>, d: DartId) -> bool {
    super::can_insert_dangling_edge(g, d) || (g.contains(d) && g.dim() >= 2 && g.is_free(d, 1))
}

/// CGAL's `insert_dangling_cell_1_in_cell_2` (with the point of the new vertex, as the
/// linear cell complex's form takes it; `None` leaves it without one):
/// [`try_insert_dangling_edge_at`], returning the dart of the new edge at the new vertex on
/// the side of `d`; at a 1-free dart (a lone dart, the free end of a path), CGAL's
/// construction: the new edge hangs from `d`'s vertex, `alpha_1`-linked to `d`.
/// Precondition ([`is_insertable_dangling_cell_1_in_cell_2`]) and cost of
/// [`try_insert_dangling_edge`].
pub fn insert_dangling_cell_1_in_cell_2<A: Attributes>(
    g: &mut GMap<A>,
    d: DartId,
    point: Option<Point>,
) -> Result<DartId, EulerError> {
    if g.contains(d) && g.dim() >= 2 && g.is_free(d, 1) {
        return dangling_at_free_dart(g, d, point);
    }
    dangling_counted(g, d, point).map(|(_, tip)| tip)
}

/// Whether [`insert_cell_1_between_two_cells_2`] would succeed
/// ([`can_insert_edge_between_faces`]).
pub fn is_insertable_cell_1_between_two_cells_2<A: Attributes>(g: &GMap<A>, d1: DartId, d2: DartId) -> bool {
    super::can_insert_edge_between_faces(g, d1, d2)
}

/// CGAL 6's `insert_cell_1_between_two_cells_2`: [`try_insert_edge_between_faces`], an
/// edge from the corner of `d1` to the corner of `d2` in another face, the two faces
/// becoming one; returns the new dart `alpha_1(d1)`, a dart of the new edge. Precondition
/// and cost of [`try_insert_edge_between_faces`].
pub fn insert_cell_1_between_two_cells_2<A: Attributes>(
    g: &mut GMap<A>,
    d1: DartId,
    d2: DartId,
) -> Result<DartId, EulerError> {
    try_insert_edge_between_faces(g, d1, d2).map(|r| r.dart)
}

/// Whether [`insert_cell_2_in_cell_3`] would succeed: `n >= 3` and CGAL's ordered path
/// (one dart per edge, `alpha_0` of each in the vertex of the next within the volume,
/// closed; for `n >= 4` free beyond `alpha_3`), or a cut of [`can_split_cell`] with `i = 3`.
pub fn is_insertable_cell_2_in_cell_3<A: Attributes>(g: &GMap<A>, path: &[DartId]) -> bool {
    g.dim() >= 3
        && ((is_cgal_path(g, path) && path.iter().all(|&x| (4..=g.dim()).all(|j| g.is_free(x, j))))
            || super::can_split_cell(g, path, 3))
}

/// CGAL's `insert_cell_2_in_cell_3`: a new face along a closed path of edges (see the
/// module's notes): on 2-free darts it hangs from the path, on a path around a volume it
/// splits it. Returns a dart of the new face (CGAL's: `alpha_0` of the dart at the first
/// path dart; for an unordered cut, `alpha_2(path[0])`).
///
/// ```
/// use gmap_core::GMap;
/// use gmap_ops::euler::ops::insert_cell_2_in_cell_3;
/// // CGAL's GMap_test_insertions.h: a face along the border of a square
/// let mut g = GMap::new(3);
/// let d = g.make_combinatorial_polygon(4);
/// let mut path = vec![d];
/// for _ in 0..3 {
///     let last = *path.last().unwrap();
///     path.push(g.next(last));
/// }
/// insert_cell_2_in_cell_3(&mut g, &path).unwrap();
/// assert_eq!(g.cell_counts(), vec![4, 4, 2, 1]);
/// ```
///
/// Precondition: [`is_insertable_cell_2_in_cell_3`]. Attributes: a volume cut in two keeps
/// its attribute on one part and a copy on the other (split hook); the new face has none.
/// O(path length · n), or the cost of [`try_split_cell`].
pub fn insert_cell_2_in_cell_3<A: Attributes>(g: &mut GMap<A>, path: &[DartId]) -> Result<DartId, EulerError> {
    insert_face_as_cgal(g, path)
}
