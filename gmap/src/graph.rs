//! The incidence graph (face poset) of any input as an architectural complex, for the
//! `.json`, `.dot` and `.graphml` writers: every face of a simplicial complex (pure or not,
//! manifold or not: a book of three triangles on one edge, a triangle with a dangling edge),
//! every cell of the closure of a cubical set, with the signed incidence numbers of their
//! chain complexes (AC Def. 3.1 holds: ∂∂ = 0). Each region is labelled with its `name`: a
//! simplex by its vertex labels (`[1,2,3]`), a cube by its intervals (`[0,1]x[2,3]x5`).
//!
//! Region ids number the cells dimension by dimension: the vertices first, in the order of
//! the chain complex. O(cells + incidences), after the chain complex.

use gmap_core::{LabelValue, Labels};
use gmap_homology::arch::{ArchComplex, Region, RegionId};
use gmap_homology::ChainComplex;
use gmap_ops::import::{CubicalSet, SimplicialComplex};

use crate::error::{err, Error, ErrorKind, Result};

/// The face poset of a chain complex whose cells are named by `name(k, j)`.
fn from_chain(chain: &ChainComplex, name: impl Fn(usize, usize) -> String) -> Result<ArchComplex> {
    let n = chain.dim();
    let mut first = Vec::with_capacity(n + 1);
    let mut regions = Vec::new();
    for k in 0..=n {
        first.push(regions.len() as u64);
        regions.extend((0..chain.count(k)).map(|j| Region { id: RegionId(first[k] + j as u64), dim: k }));
    }
    let mut entries = Vec::new();
    for k in 1..=n {
        for (i, j, w) in chain.boundary(k).iter() {
            entries.push((RegionId(first[k] + j as u64), RegionId(first[k - 1] + i as u64), w));
        }
    }
    let mut x = ArchComplex::try_new(n, regions, entries).map_err(|e| Error::from_source(ErrorKind::Compute, e))?;
    for (k, &start) in first.iter().enumerate() {
        for j in 0..chain.count(k) {
            let labels: Labels = [("name", LabelValue::Text(name(k, j)))].into_iter().collect();
            x = x
                .with_region_labels(RegionId(start + j as u64), labels)
                .map_err(|e| Error::from_source(ErrorKind::Compute, e))?;
        }
    }
    Ok(x)
}

/// Every face of a simplicial complex, refused past `max_cells` faces (default: what the
/// memory budget holds).
pub(crate) fn simplicial(sc: &SimplicialComplex, max_cells: Option<u64>, file: &str) -> Result<ArchComplex> {
    let limit = max_cells.unwrap_or_else(|| gmap_ops::import::default_max_faces(sc.dim()));
    let faces = gmap_homology::simplices::face_complex_of(sc.facets(), limit, true).map_err(|e| {
        let kind = match e {
            gmap_homology::simplices::FaceError::TooManyFaces { .. } => ErrorKind::Limit,
            _ => ErrorKind::Precondition,
        };
        let e = Error::from_source(kind, e).context(file.to_string());
        if kind == ErrorKind::Limit {
            e.flattened("; raise the limit with --max-cells N")
        } else {
            e
        }
    })?;
    from_chain(&faces.chain, |k, j| {
        format!("[{}]", faces.labels(k, j).iter().map(u64::to_string).collect::<Vec<_>>().join(","))
    })
}

/// Every cell of the closure of a cubical set or cell complex (no collapse).
pub(crate) fn cubical(set: &CubicalSet, periodic: bool, file: &str) -> Result<ArchComplex> {
    let cells = set.lower_cells_in_box();
    let c = gmap_homology::cubical::cubical_cell_complex_with(set.shape(), set.bits(), &cells, periodic, false)
        .map_err(|e| err!(Limit, "{file}: {e}"))?;
    from_chain(&c.chain, |k, j| c.cell_name(k, j, set.min()))
}
