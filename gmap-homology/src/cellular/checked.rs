//! The checked entry points of the cellular method: the conditions of [`crate::precond`]
//! first, then the raw builders of [`crate::border`] and [`crate::simplicial`].

use gmap_core::{Attributes, DenseMap, GMap};

use crate::cellular::border::{border_from_oriented, CellularComplex};
use crate::cellular::precond::{check_preconditions, PreconditionError};
use crate::cellular::simplicial::{simplicial_complex_with_simplices, tau_matrix, ChainMapTau};
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
pub fn cellular_complex(map: &DenseMap) -> Result<CellularComplex, PreconditionError> {
    let oriented = check_preconditions(map)?;
    Ok(border_from_oriented(map, &oriented))
}

/// Why the cellular homology of an editable map could not be computed: a cell fails C1/C2,
/// or the reduction failed.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum GMapHomologyError {
    /// A cell fails condition C1 or C2 (its darts are numbered as in `GMap::to_dense`).
    #[error(transparent)]
    Precondition(#[from] PreconditionError),
    /// The homology computation failed.
    #[error(transparent)]
    Homology(#[from] HomologyError),
}

/// The integer homology of an editable [`GMap`] (any attributes), through its cells: one
/// [`GMap::to_dense`] snapshot, [`cellular_complex`], [`homology_z`]. Darts named in errors
/// are snapshot darts (the k-th of `GMap::darts`). O(N n²) plus the reduction.
///
/// ```
/// use gmap_core::GMap;
/// use gmap_homology::gmap_homology;
/// let (torus, _) = GMap::from_dense(&gmap_core::examples::torus());
/// assert_eq!(gmap_homology(&torus).unwrap().to_string(), "(Z, Z^2, Z)");
/// ```
pub fn gmap_homology<A: Attributes>(map: &GMap<A>) -> Result<Homology, GMapHomologyError> {
    let (dense, _) = map.to_dense();
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
