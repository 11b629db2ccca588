//! The architectural complex of a G-map's cells (AC Remark 3.3), weighted by signed
//! incidence numbers (BO Def. 9).

use gmap_core::{to_dense_labels, CellDefect, DenseLabels, DenseMap, LabelledGMap};
use thiserror::Error;

use super::{ArchComplex, ArchError, Region, RegionId};
use crate::cellular::incidence::incidence_terms;
use crate::cellular::oriented::{oriented_cells, OrientedCells};
use crate::cellular::precond::{check_preconditions, PreconditionError};

/// Why the cells of a G-map do not give an architectural complex.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum FromMapError {
    /// a cell is not orientable as a compacted cell (condition C1): no signed incidences
    #[error(transparent)]
    Cell(#[from] CellDefect),
    /// the incidences violate AC Def. 3.1 (δ² ≠ 0: a cell whose boundary is not a cycle)
    #[error(transparent)]
    Arch(#[from] ArchError),
    /// a cell is not bounded by a homology sphere (condition C2): the signed incidences
    /// exist but the complex they make has other homology groups than the map
    #[error(transparent)]
    NotCellular(PreconditionError),
}

impl From<PreconditionError> for FromMapError {
    fn from(e: PreconditionError) -> FromMapError {
        match e {
            PreconditionError::C1(d) => FromMapError::Cell(d),
            other => FromMapError::NotCellular(other),
        }
    }
}

/// Signed incidences of the i-cells on the (i-1)-cells of a G-map, split by sign: for
/// each adherent pair (an i-cell and an (i-1)-cell sharing a dart), the number of elements
/// of the face-operator preimage of one fixed element of the (i-1)-cell (BO Def. 4) that lie
/// in the i-cell with sign +1 and with sign -1 (BO Def. 5, 9: `plus + minus` is the
/// unsigned incidence number, `plus - minus` the signed one).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CellIncidence {
    /// the i-cell (numbered as in `DenseMap::cells(i)`)
    pub upper: u32,
    /// the (i-1)-cell (numbered as in `DenseMap::cells(i - 1)`)
    pub lower: u32,
    /// elements with sign +1
    pub plus: u32,
    /// elements with sign -1
    pub minus: u32,
}

impl CellIncidence {
    /// The signed incidence number (BO Def. 9).
    pub fn signed(&self) -> i64 {
        self.plus as i64 - self.minus as i64
    }

    /// The unsigned incidence number (BO Def. 5).
    pub fn unsigned(&self) -> u32 {
        self.plus + self.minus
    }
}

/// Every adherent pair of i-cells and (i-1)-cells of a valid G-map with its incidence
/// counts, sorted by `(upper, lower)`. Needs every i-cell and (i-1)-cell orientable as a
/// compacted cell (condition C1), else returns the defect naming the cell. `1 <= i <= n`.
/// O(N n + terms log terms).
pub fn cell_incidences(map: &DenseMap, i: usize) -> Result<Vec<CellIncidence>, CellDefect> {
    assert!(i >= 1 && i <= map.dim(), "incidences need 1 <= i <= n");
    let upper = oriented_cells(map, i)?;
    let lower = oriented_cells(map, i - 1)?;
    Ok(counted_by_sign(map, &upper, &lower))
}

/// [`cell_incidences`] for every `i = 1..=n` (`result[i - 1]`), orienting the cells of each
/// dimension once. O(N n^2 + terms log terms).
pub fn all_cell_incidences(map: &DenseMap) -> Result<Vec<Vec<CellIncidence>>, CellDefect> {
    let mut out = Vec::with_capacity(map.dim());
    let mut lower = oriented_cells(map, 0)?;
    for i in 1..=map.dim() {
        let upper = oriented_cells(map, i)?;
        out.push(counted_by_sign(map, &upper, &lower));
        lower = upper;
    }
    Ok(out)
}

/// The terms of BO Def. 9 ([`incidence_terms`]) counted by pair and sign; every adherent
/// pair has a term.
fn counted_by_sign(map: &DenseMap, upper: &OrientedCells, lower: &OrientedCells) -> Vec<CellIncidence> {
    let mut terms: Vec<(u32, u32, bool)> =
        incidence_terms(map, upper, lower).into_iter().map(|(lo, up, s)| (up, lo, s > 0)).collect();
    terms.sort_unstable();
    let mut out: Vec<CellIncidence> = Vec::new();
    for (upper, lower, positive) in terms {
        match out.last_mut() {
            Some(c) if (c.upper, c.lower) == (upper, lower) => {}
            _ => out.push(CellIncidence { upper, lower, plus: 0, minus: 0 }),
        }
        let c = out.last_mut().expect("pushed above");
        if positive {
            c.plus += 1;
        } else {
            c.minus += 1;
        }
    }
    out
}

impl ArchComplex {
    /// The architectural complex of the cells of a G-map (AC Remark 3.3): one region per
    /// cell (ids: the 0-cells first, numbered as in `DenseMap::cells`, then the 1-cells, …),
    /// and one entry for each adherent pair of consecutive dimensions, weighted by the
    /// signed incidence number — kept when it is 0 (the cylinder's seam). Needs conditions
    /// C1 and C2 for every dimension ([`check_preconditions`]), under which the complex has
    /// the homology of the map; a cell failing either is the error, named by its dart.
    /// O(N n (n + log N)) below dimension 4 (C2 costs more above, see [`check_preconditions`]).
    pub fn from_map(map: &DenseMap) -> Result<ArchComplex, FromMapError> {
        let n = map.dim();
        let counts = map.cell_counts();
        let mut offset = vec![0u64; n + 2];
        for k in 0..=n {
            offset[k + 1] = offset[k] + counts[k] as u64;
        }
        let mut regions = Vec::with_capacity(offset[n + 1] as usize);
        for (k, &c) in counts.iter().enumerate() {
            regions.extend((0..c as u64).map(|j| Region { id: RegionId(offset[k] + j), dim: k }));
        }
        let cells = check_preconditions(map)?;
        let mut entries = Vec::new();
        for i in 1..=n {
            for ci in counted_by_sign(map, &cells[i], &cells[i - 1]) {
                entries.push((
                    RegionId(offset[i] + ci.upper as u64),
                    RegionId(offset[i - 1] + ci.lower as u64),
                    ci.signed(),
                ));
            }
        }
        Ok(ArchComplex::try_new(n, regions, entries)?)
    }

    /// [`ArchComplex::from_map`] with the labels of the cells kept on their regions:
    /// `labels.get(k, c)` (the labels of `k`-cell `c` of `map.cells(k)`, as
    /// [`gmap_core::to_dense_labels`] numbers them) become those of the region of that cell
    /// ([`ArchComplex::region_labels`]). A real label that is not finite is
    /// [`ArchError::LabelNotFinite`]. O(from_map + number of labels).
    pub fn from_map_with_labels(map: &DenseMap, labels: &DenseLabels) -> Result<ArchComplex, FromMapError> {
        let mut x = ArchComplex::from_map(map)?;
        let mut id = 0u64;
        for k in 0..=map.dim() {
            let count = x.regions_of_dim(k).len();
            for c in 0..count {
                let l = labels.get(k, c);
                if !l.is_empty() {
                    x = x.with_region_labels(RegionId(id + c as u64), l.clone())?;
                }
            }
            id += count as u64;
        }
        Ok(x)
    }

    /// The architectural complex of the cells of a labelled map, each region carrying the
    /// labels of its cell ([`ArchComplex::from_map_with_labels`] on
    /// [`gmap_core::to_dense_labels`]). Region ids number the cells as `from_map` does on
    /// the map's dense form. O(from_map + number of labels).
    ///
    /// ```
    /// use gmap_core::{LabelValue, LabelledGMap};
    /// use gmap_homology::arch::ArchComplex;
    /// // one edge with two free ends, named
    /// let mut m = LabelledGMap::with_attributes(1);
    /// let (a, b) = (m.create_dart(), m.create_dart());
    /// m.link(a, b, 0);
    /// m.set_attribute::<1>(a, [("name", LabelValue::Text("beam".into()))].into_iter().collect());
    /// let x = ArchComplex::from_labelled_map(&m).unwrap();
    /// assert_eq!(x.region_counts(), vec![2, 1]);
    /// assert_eq!(x.region_labels(2).get("name"), Some(&LabelValue::Text("beam".into())));
    /// ```
    pub fn from_labelled_map(g: &LabelledGMap) -> Result<ArchComplex, FromMapError> {
        let (dense, labels, _) = to_dense_labels(g);
        ArchComplex::from_map_with_labels(&dense, &labels)
    }
}
