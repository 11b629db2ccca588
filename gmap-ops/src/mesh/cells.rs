//! [`Mesh`], its cells and their checks (see the [module documentation](super)); the map
//! is built in [`to_map`](super::to_map).

use std::fmt;

use gmap_core::{DenseMap, LabelValue, Point};
use rustc_hash::FxHashMap;
use smallvec::SmallVec;

use super::error::MeshError;

/// The linear cell types of VTK and Gmsh that a mesh holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum CellKind {
    /// one point (VTK 1, Gmsh 15)
    Vertex,
    /// a segment (VTK 3, Gmsh 1)
    Line,
    /// VTK 5, Gmsh 2
    Triangle,
    /// VTK 9, Gmsh 3
    Quad,
    /// a polygon of any number of corners (VTK 7)
    Polygon,
    /// VTK 10, Gmsh 4
    Tetra,
    /// VTK 12, Gmsh 5: corners 0-3 one face, 4-7 the opposite one, `k + 4` above `k`
    Hexahedron,
    /// VTK 13, Gmsh 6: triangles 0-2 and 3-5, `k + 3` above `k`
    Wedge,
    /// VTK 14, Gmsh 7: the quadrangle 0-3 and the apex 4
    Pyramid,
    /// a polyhedron given by its faces (VTK 42)
    Polyhedron,
}

impl CellKind {
    /// The VTK cell type, and the kind of a VTK type this crate reads.
    pub fn from_vtk(t: i64) -> Option<CellKind> {
        Some(match t {
            1 => CellKind::Vertex,
            3 => CellKind::Line,
            5 => CellKind::Triangle,
            7 => CellKind::Polygon,
            9 => CellKind::Quad,
            10 => CellKind::Tetra,
            12 => CellKind::Hexahedron,
            13 => CellKind::Wedge,
            14 => CellKind::Pyramid,
            42 => CellKind::Polyhedron,
            _ => return None,
        })
    }

    /// The dimension of the cells of this kind.
    pub fn dim(self) -> usize {
        match self {
            CellKind::Vertex => 0,
            CellKind::Line => 1,
            CellKind::Triangle | CellKind::Quad | CellKind::Polygon => 2,
            _ => 3,
        }
    }

    /// The number of points of a cell of this kind, `None` when it varies.
    pub fn points(self) -> Option<usize> {
        Some(match self {
            CellKind::Vertex => 1,
            CellKind::Line => 2,
            CellKind::Triangle => 3,
            CellKind::Quad | CellKind::Tetra => 4,
            CellKind::Hexahedron => 8,
            CellKind::Wedge => 6,
            CellKind::Pyramid => 5,
            CellKind::Polygon | CellKind::Polyhedron => return None,
        })
    }

    /// The faces of a volume of a fixed kind, as corner numbers.
    pub(crate) fn faces(self) -> &'static [&'static [usize]] {
        match self {
            CellKind::Tetra => &[&[0, 1, 2], &[0, 3, 1], &[1, 3, 2], &[2, 3, 0]],
            CellKind::Hexahedron => {
                &[&[0, 3, 2, 1], &[4, 5, 6, 7], &[0, 1, 5, 4], &[1, 2, 6, 5], &[2, 3, 7, 6], &[3, 0, 4, 7]]
            }
            CellKind::Wedge => &[&[0, 1, 2], &[3, 5, 4], &[0, 3, 4, 1], &[1, 4, 5, 2], &[2, 5, 3, 0]],
            CellKind::Pyramid => &[&[0, 3, 2, 1], &[0, 1, 4], &[1, 2, 4], &[2, 3, 4], &[3, 0, 4]],
            _ => &[],
        }
    }
}

impl fmt::Display for CellKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            CellKind::Vertex => "vertex",
            CellKind::Line => "line",
            CellKind::Triangle => "triangle",
            CellKind::Quad => "quadrangle",
            CellKind::Polygon => "polygon",
            CellKind::Tetra => "tetrahedron",
            CellKind::Hexahedron => "hexahedron",
            CellKind::Wedge => "wedge",
            CellKind::Pyramid => "pyramid",
            CellKind::Polyhedron => "polyhedron",
        })
    }
}

/// One cell: its kind, its points, and for a polyhedron its faces.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshCell {
    /// the cell type
    pub kind: CellKind,
    /// its points (indices into [`Mesh::points`]) in the type's order; for a polyhedron, its
    /// distinct points
    pub nodes: Vec<u32>,
    /// a polyhedron's faces, each a cycle of point indices (empty for other kinds)
    pub faces: Vec<Vec<u32>>,
}

/// A named array of values, one per point or per cell (`None`: no value there).
#[derive(Clone, Debug, PartialEq)]
pub struct DataArray {
    /// the label name
    pub name: String,
    /// one value per point or cell
    pub values: Vec<Option<LabelValue>>,
}

/// An unstructured mesh as read from a file (see the [module documentation](super)).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// the points
    pub points: Vec<Point>,
    /// the cells, in file order
    pub cells: Vec<MeshCell>,
    /// data on the points: labels of the 0-cells
    pub point_data: Vec<DataArray>,
    /// data on the cells: labels of the cells
    pub cell_data: Vec<DataArray>,
}

impl Mesh {
    /// The largest dimension of the cells, `None` without cells.
    pub fn top_dim(&self) -> Option<usize> {
        self.cells.iter().map(|c| c.kind.dim()).max()
    }

    /// Checks every cell on its own: point indices in range, the right number of points,
    /// no point twice, polygons of 3 corners or more, polyhedra whose faces close.
    pub(crate) fn check_cells(&self) -> Result<(), MeshError> {
        let n = self.points.len();
        for (i, c) in self.cells.iter().enumerate() {
            let bad = |reason: String| MeshError::BadCell { cell: i, kind: c.kind.to_string(), reason };
            if let Some(&v) = c.nodes.iter().chain(c.faces.iter().flatten()).find(|&&v| v as usize >= n) {
                return Err(MeshError::NoSuchVertex { cell: i, vertex: v as u64, points: n });
            }
            if let Some(k) = c.kind.points() {
                if c.nodes.len() != k {
                    return Err(bad(format!("{} points, a {} has {k}", c.nodes.len(), c.kind)));
                }
            }
            if c.kind == CellKind::Polygon && c.nodes.len() < 3 {
                return Err(bad(format!("{} points, a polygon needs 3 or more", c.nodes.len())));
            }
            let twice = |xs: &[u32]| -> Option<u32> {
                let mut s: SmallVec<[u32; 8]> = xs.iter().copied().collect();
                s.sort_unstable();
                s.windows(2).find(|w| w[0] == w[1]).map(|w| w[0])
            };
            if let Some(v) = twice(&c.nodes) {
                return Err(bad(format!("point {v} appears twice")));
            }
            if c.kind == CellKind::Polyhedron {
                if c.faces.len() < 2 {
                    return Err(bad(format!("{} faces, a polyhedron needs 2 or more", c.faces.len())));
                }
                let mut edges: FxHashMap<(u32, u32), u32> = FxHashMap::default();
                for f in &c.faces {
                    if f.len() < 3 {
                        return Err(bad(format!("a face of {} points", f.len())));
                    }
                    if let Some(v) = twice(f) {
                        return Err(bad(format!("point {v} appears twice in a face")));
                    }
                    for j in 0..f.len() {
                        let (a, b) = (f[j], f[(j + 1) % f.len()]);
                        *edges.entry((a.min(b), a.max(b))).or_default() += 1;
                    }
                }
                let mut odd: Vec<((u32, u32), u32)> = edges.into_iter().filter(|&(_, k)| k != 2).collect();
                odd.sort_unstable();
                if let Some(&((a, b), k)) = odd.first() {
                    return Err(bad(format!(
                        "its edge {a}-{b} lies in {k} of its faces (the faces must close: two each)"
                    )));
                }
            }
        }
        Ok(())
    }
}

/// Refuses a point that is two 0-cells or more of the map, and (in dimension 3) an edge that
/// is two 1-cells or more: the cells around them meet only there. O(N n).
pub(crate) fn check_pinched(dense: &DenseMap, vert: &[u32], top: usize) -> Result<(), MeshError> {
    let check = |i: usize, what: &'static str| -> Result<(), MeshError> {
        let cells = dense.cells(i);
        let mut count: FxHashMap<(u32, u32), usize> = FxHashMap::default();
        for r in &cells.reps {
            let v = vert[r.index()];
            let key = if i == 0 {
                (v, v)
            } else {
                let w = vert[dense.alpha(*r, 0).index()];
                (v.min(w), v.max(w))
            };
            *count.entry(key).or_default() += 1;
        }
        let mut worst: Vec<((u32, u32), usize)> = count.into_iter().filter(|&(_, n)| n > 1).collect();
        worst.sort_unstable();
        if let Some(&((a, b), pieces)) = worst.first() {
            let vertices = if i == 0 { vec![a as u64] } else { vec![a as u64, b as u64] };
            return Err(MeshError::Pinched { what, vertices, pieces });
        }
        Ok(())
    };
    if top >= 2 {
        check(0, "point")?;
    }
    if top >= 3 {
        check(1, "edge")?;
    }
    Ok(())
}
