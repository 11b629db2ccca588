//! The oriented cells of a map (condition C1): the raw material of every builder of the
//! cellular complex. It imports nothing of this crate.

use bitvec::vec::BitVec;
use gmap_core::{CellDefect, DenseMap, Partition};

/// The i-cells of a map, oriented as compacted cells (condition C1).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OrientedCells {
    /// the dimension i
    pub dim: usize,
    /// the i-cells: `cells.of[d]` is the cell of dart `d`, numbered by smallest dart
    pub cells: Partition,
    /// a bit per dart: set for the positive class of its compacted cell; the smallest dart
    /// of every cell is positive
    pub positive: BitVec,
}

impl OrientedCells {
    /// `+1` or `-1`: the orientation class of dart `d` in its i-cell.
    #[inline]
    pub fn sign(&self, d: u32) -> i64 {
        if self.positive[d as usize] {
            1
        } else {
            -1
        }
    }
}

/// Partitions the darts into i-cells and orients each one as a compacted cell, in one
/// traversal; fails with the first cell (in order of smallest dart) violating C1.
/// Numbering and signs agree with `DenseMap::cells(i)` and `DenseMap::cell_orientation(i)`.
/// O(N n).
pub fn oriented_cells(map: &DenseMap, i: usize) -> Result<OrientedCells, CellDefect> {
    let (cells, positive) = map.oriented_cells(i)?;
    Ok(OrientedCells { dim: i, cells, positive })
}
