//! A cubical set as a legacy VTK unstructured grid of voxels (`.vtk`): one point per corner
//! of its cubes (at the cubes' integer coordinates), one cell per cube — a hexahedron
//! (`VTK_HEXAHEDRON` 12) in dimension 3, a quadrangle (`VTK_QUAD` 9) in dimension 2, a line
//! (`VTK_LINE` 3) in dimension 1, corners in VTK's order (the bottom face counter-clockwise,
//! then the top one), which every VTK reader and ours read — and the cell data `dim`. Sets of dimension above 3 are
//! refused, so are cubical cell complexes with lower cells on no cube. O(cubes · 2^d).

use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::Path;

use super::error::{write_atomic, ExportError};
use crate::import::CubicalSet;

/// The `.vtk` text of the cubes of `set` (module docs).
pub fn cubical_vtk_string(set: &CubicalSet) -> Result<String, ExportError> {
    let d = set.dim();
    // the corners in VTK's order, as bit masks of the axes (bit a: +1 along axis a)
    let (cell_type, order): (u8, &[usize]) = match d {
        1 => (3, &[0, 1]),
        2 => (9, &[0, 1, 3, 2]),
        3 => (12, &[0, 1, 3, 2, 4, 5, 7, 6]),
        _ => return Err(ExportError::DimensionAbove { format: ".vtk (voxels)", max: 3, found: d }),
    };
    set.require_full(".vtk (voxels)").map_err(|e| ExportError::LowerCells { reason: e.to_string() })?;
    let mut points: Vec<[i64; 3]> = Vec::new();
    let mut index: HashMap<[i64; 3], usize> = HashMap::new();
    let mut cells: Vec<Vec<usize>> = Vec::new();
    for cube in set.cubes() {
        let mut corners = Vec::with_capacity(1 << d);
        for &k in order {
            let mut p = [0i64; 3];
            for a in 0..d {
                p[a] = cube[a] + ((k >> a) & 1) as i64;
            }
            let next = points.len();
            let i = *index.entry(p).or_insert(next);
            if i == next {
                points.push(p);
            }
            corners.push(i);
        }
        cells.push(corners);
    }
    let mut s = String::with_capacity(32 * points.len() + 48 * cells.len() + 256);
    let _ = writeln!(
        s,
        "# vtk DataFile Version 3.0\ngmap: a cubical set of dimension {d}, {} cubes\nASCII\nDATASET UNSTRUCTURED_GRID",
        cells.len()
    );
    let _ = writeln!(s, "POINTS {} double", points.len());
    for p in &points {
        let _ = writeln!(s, "{} {} {}", p[0], p[1], p[2]);
    }
    let _ = writeln!(s, "CELLS {} {}", cells.len(), cells.len() * ((1 << d) + 1));
    for c in &cells {
        let ids: Vec<String> = c.iter().map(usize::to_string).collect();
        let _ = writeln!(s, "{} {}", c.len(), ids.join(" "));
    }
    let _ = writeln!(s, "CELL_TYPES {}", cells.len());
    for _ in &cells {
        let _ = writeln!(s, "{cell_type}");
    }
    let _ = writeln!(s, "CELL_DATA {}\nSCALARS dim int 1\nLOOKUP_TABLE default", cells.len());
    for _ in &cells {
        let _ = writeln!(s, "{d}");
    }
    Ok(s)
}

/// Writes [`cubical_vtk_string`] to `path` (through a temporary file and a rename).
pub fn write_cubical_vtk(set: &CubicalSet, path: &Path) -> Result<(), ExportError> {
    write_atomic(path, cubical_vtk_string(set)?.as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_cubes_share_four_corners() {
        let set = CubicalSet::new(vec![0, 0, 0], vec![2, 1, 1], vec![1, 1]).unwrap();
        let s = cubical_vtk_string(&set).unwrap();
        assert!(s.contains("POINTS 12 double\n"), "{s}");
        assert!(s.contains("CELLS 2 18\n8 0 1 2 3 4 5 6 7\n8 1 8 9 2 5 10 11 6\n"), "{s}");
        assert!(s.contains("CELL_TYPES 2\n12\n12\n"), "{s}");
    }
}
