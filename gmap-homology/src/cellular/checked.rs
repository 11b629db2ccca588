//! The checked entry points of the cellular method: the conditions of [`crate::precond`]
//! first, then the raw builders of [`crate::border`] and [`crate::simplicial`].

use bitvec::vec::BitVec;
use gmap_core::{parallel, Attributes, DenseMap, GMap, Partition};

use crate::cellular::border::{border_from_oriented, ends, pairs, sides, CellularComplex};
use crate::cellular::precond::{
    check_chi, check_faces_unfolded, check_preconditions, chi_of_volumes, OrientedCells, PreconditionError,
};
use crate::cellular::simplicial::{simplicial_complex_with_simplices, tau_matrix, ChainMapTau};
use crate::engine::chain::ChainComplex;
use crate::engine::homology::{homology_z, Homology, HomologyError};

/// Builds the border operator of `map` after checking C1 and C2 on every cell.
/// O(N n^2) plus, for dimensions 4 and up, the homology of one compacted cell per
/// isomorphism class (C2).
///
/// ```
/// use gmap_homology::{cellular_complex, homology_z};
/// let torus = gmap_core::examples::torus();
/// let c = cellular_complex(&torus).unwrap();
/// assert_eq!(c.chain.counts(), &[1, 2, 1]);
/// assert_eq!(homology_z(&c.chain).unwrap().betti, vec![1, 2, 1]);
/// // the Klein bottle: its cells are orientable, so the method applies
/// let klein = gmap_core::examples::klein_bottle();
/// assert_eq!(homology_z(&cellular_complex(&klein).unwrap().chain).unwrap().to_string(), "(Z, Z + Z/2, 0)");
/// ```
///
/// A 3-map whose cells have the shapes of the ring walks ([`DenseMap::oriented_cells_3d_of`])
/// is taken two dimensions at a time, so that at most two partitions of the darts are held
/// at once (`cellular_complex_3`); other maps check every dimension first
/// ([`check_preconditions`]), then build the border.
pub fn cellular_complex(map: &DenseMap) -> Result<CellularComplex, PreconditionError> {
    cellular_complex_staged(map, &mut |_| {})
}

/// [`cellular_complex`], calling `stage` with a short name as each of its stages starts (to
/// report progress, or to measure each stage's time and memory).
///
/// ```
/// use gmap_homology::cellular::checked::cellular_complex_staged;
/// let mut names = Vec::new();
/// let c = cellular_complex_staged(&gmap_core::examples::torus(), &mut |s| names.push(s)).unwrap();
/// assert_eq!(c.chain.counts(), &[1, 2, 1]);
/// assert_eq!(names, ["cells and C1/C2", "border"]);
/// ```
pub fn cellular_complex_staged(
    map: &DenseMap,
    stage: &mut dyn FnMut(&'static str),
) -> Result<CellularComplex, PreconditionError> {
    if let Some(c) = cellular_complex_3(map, stage) {
        return c;
    }
    stage("cells and C1/C2");
    let oriented = check_preconditions(map)?;
    stage("border");
    Ok(border_from_oriented(map, &oriented))
}

/// The cellular complex of a 3-map in two phases, each a few tasks on the threads of
/// [`gmap_core::parallel`]:
///
/// 1. the volumes and the faces; then, side by side, the Euler characteristic of each volume
///    (C2), the fold check of the faces (no self-bending) and `∂_3`; the partition of the
///    darts into volumes and into faces is dropped (the faces keep their smallest darts and
///    their orientation bits);
/// 2. the edges and the vertices; then `∂_2` and `∂_1` side by side.
///
/// The verdicts come in the order of [`check_preconditions`]: C1 in every dimension, then
/// C2, then the folds. `None` when a cell is not of the shapes of the ring walks: C1 fails
/// somewhere, and the caller's [`check_preconditions`] names the cell. The complex is that
/// of [`border_from_oriented`]. O(N α(N)); besides the map and the matrices, at most two
/// partitions (4 bytes per dart each) and their orientation bits are held.
fn cellular_complex_3(
    map: &DenseMap,
    stage: &mut dyn FnMut(&'static str),
) -> Option<Result<CellularComplex, PreconditionError>> {
    if map.dim() != 3 {
        return None;
    }
    stage("volumes and faces");
    let oriented = |dim: usize, (cells, positive): (Partition, BitVec)| OrientedCells { dim, cells, positive };
    let darts = map.dart_count();
    let mut hi = map.oriented_cells_3d_of(&[3, 2])?.into_iter();
    let (volumes, mut faces) = (oriented(3, hi.next()?), oriented(2, hi.next()?));
    stage("C2, folds and ∂3");
    let (chi, (unfolded, d3)) = parallel::join(
        darts,
        || chi_of_volumes(map, &volumes),
        || parallel::join(darts, || check_faces_unfolded(map, &faces), || pairs(map, &volumes, &faces)),
    );
    let counts_hi = [faces.cells.len(), volumes.cells.len()];
    let volume_reps = volumes.cells.reps.clone();
    drop(volumes);
    faces.cells.of = Vec::new();
    stage("edges and vertices");
    let mut lo = map.oriented_cells_3d_of(&[1, 0])?.into_iter();
    let (edges, vertices) = (oriented(1, lo.next()?), oriented(0, lo.next()?));
    if let Err(e) = check_chi(&chi, &volume_reps).and(unfolded) {
        return Some(Err(e));
    }
    stage("∂2 and ∂1");
    let counts = vec![vertices.cells.len(), edges.cells.len(), counts_hi[0], counts_hi[1]];
    let (d1, d2) = parallel::join(darts, || ends(map, &edges, &vertices), || sides(map, &faces, &edges));
    let mats = vec![d1, d2, d3];
    let chain = ChainComplex::try_new_unchecked_dd(counts, mats).expect("shapes follow the cell counts");
    debug_assert_eq!(chain.check_dd(), Ok(()), "∂∂ = 0 under C1");
    let reps = vec![vertices.cells.reps, edges.cells.reps, faces.cells.reps, volume_reps];
    Some(Ok(CellularComplex { chain, reps }))
}

/// Why the cellular homology of an editable map could not be computed: a cell fails C1/C2,
/// or the reduction failed.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum GMapHomologyError {
    /// A cell fails condition C1 or C2 (its darts are numbered as in `GMap::to_dense_map`).
    #[error(transparent)]
    Precondition(#[from] PreconditionError),
    /// The homology computation failed.
    #[error(transparent)]
    Homology(#[from] HomologyError),
}

/// The integer homology of an editable [`GMap`] (any attributes), through its cells: one
/// [`GMap::to_dense_map`] snapshot, [`cellular_complex`], [`homology_z`]. Darts named in errors
/// are snapshot darts (the k-th of `GMap::darts`). O(N n²) plus the reduction.
///
/// ```
/// use gmap_core::GMap;
/// use gmap_homology::gmap_homology;
/// let (torus, _) = GMap::from_dense(&gmap_core::examples::torus());
/// assert_eq!(gmap_homology(&torus).unwrap().to_string(), "(Z, Z^2, Z)");
/// ```
pub fn gmap_homology<A: Attributes>(map: &GMap<A>) -> Result<Homology, GMapHomologyError> {
    let (dense, _) = map.to_dense_with_ids();
    Ok(homology_z(&cellular_complex(&dense)?.chain)?)
}
/// τ (BO §6) for `map`, after the cellular method's checks ([`check_preconditions`]: C1,
/// C2 and no self-bending), which are its precondition: where they fail, the error names
/// the cell. O(2^n N n) for the counterpart, O(N n) for τ itself.
///
/// ```
/// use gmap_homology::chain_map_tau;
/// let torus = gmap_core::examples::torus();
/// let t = chain_map_tau(&torus).unwrap();
/// assert_eq!(t.check_commutes(), Ok(()));
/// // the face of the torus goes to its 8 triangles with vertices {0, 1, 2}
/// assert_eq!(t.tau[2].nnz(), 8);
/// ```
pub fn chain_map_tau(map: &DenseMap) -> Result<ChainMapTau, PreconditionError> {
    let oriented = check_preconditions(map)?;
    let cellular = border_from_oriented(map, &oriented);
    let simplicial = simplicial_complex_with_simplices(map);
    let tau = (0..=map.dim()).map(|i| tau_matrix(map, &oriented[i], simplicial.chain.count(i))).collect();
    Ok(ChainMapTau { cellular, simplicial, tau })
}
