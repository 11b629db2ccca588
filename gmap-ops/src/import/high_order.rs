//! Cells of higher order (quadratic and above) read as their corner cells.
//!
//! Gmsh and VTK list the corners of a higher-order cell first, in the order of the linear
//! cell of the same shape, then the nodes on its edges, faces and inside. A reader keeps the
//! corners as the cell and the other nodes' coordinates as the cell's label
//! [`HIGH_ORDER_LABEL`] (a text `x y z, x y z, …` in the file's order), so nothing of the
//! file is dropped without a word. Types without corners (Gmsh's one-node elements of order
//! 0, polygons, polyhedra and XFEM elements) are refused by name.

use gmap_core::{LabelValue, Point};

use crate::mesh::{CellKind, DataArray, MeshCell};

/// The label holding the other nodes of a higher-order cell.
pub const HIGH_ORDER_LABEL: &str = "high_order.nodes";

/// Gmsh's element types with corners: (type, nodes, the corner cell), as Gmsh 4.15's
/// `gmsh.model.mesh.getElementProperties` gives them (its number of nodes, and its number of
/// primary nodes the corners' count).
const GMSH_TYPES: &[(i64, usize, CellKind)] = {
    use CellKind::*;
    &[
        (1, 2, Line),
        (2, 3, Triangle),
        (3, 4, Quad),
        (4, 4, Tetra),
        (5, 8, Hexahedron),
        (6, 6, Wedge),
        (7, 5, Pyramid),
        (8, 3, Line),
        (9, 6, Triangle),
        (10, 9, Quad),
        (11, 10, Tetra),
        (12, 27, Hexahedron),
        (13, 18, Wedge),
        (14, 14, Pyramid),
        (15, 1, Vertex),
        (16, 8, Quad),
        (17, 20, Hexahedron),
        (18, 15, Wedge),
        (19, 13, Pyramid),
        (20, 9, Triangle),
        (21, 10, Triangle),
        (22, 12, Triangle),
        (23, 15, Triangle),
        (24, 15, Triangle),
        (25, 21, Triangle),
        (26, 4, Line),
        (27, 5, Line),
        (28, 6, Line),
        (29, 20, Tetra),
        (30, 35, Tetra),
        (31, 56, Tetra),
        (32, 22, Tetra),
        (33, 28, Tetra),
        (36, 16, Quad),
        (37, 25, Quad),
        (38, 36, Quad),
        (39, 12, Quad),
        (40, 16, Quad),
        (41, 20, Quad),
        (42, 28, Triangle),
        (43, 36, Triangle),
        (44, 45, Triangle),
        (45, 55, Triangle),
        (46, 66, Triangle),
        (47, 49, Quad),
        (48, 64, Quad),
        (49, 81, Quad),
        (50, 100, Quad),
        (51, 121, Quad),
        (52, 18, Triangle),
        (53, 21, Triangle),
        (54, 24, Triangle),
        (55, 27, Triangle),
        (56, 30, Triangle),
        (57, 24, Quad),
        (58, 28, Quad),
        (59, 32, Quad),
        (60, 36, Quad),
        (61, 40, Quad),
        (62, 7, Line),
        (63, 8, Line),
        (64, 9, Line),
        (65, 10, Line),
        (66, 11, Line),
        (71, 84, Tetra),
        (72, 120, Tetra),
        (73, 165, Tetra),
        (74, 220, Tetra),
        (75, 286, Tetra),
        (79, 34, Tetra),
        (80, 40, Tetra),
        (81, 46, Tetra),
        (82, 52, Tetra),
        (83, 58, Tetra),
        (92, 64, Hexahedron),
        (93, 125, Hexahedron),
        (94, 216, Hexahedron),
        (95, 343, Hexahedron),
        (96, 512, Hexahedron),
        (97, 729, Hexahedron),
        (98, 1000, Hexahedron),
        (99, 32, Hexahedron),
        (100, 44, Hexahedron),
        (101, 56, Hexahedron),
        (102, 68, Hexahedron),
        (103, 80, Hexahedron),
        (104, 92, Hexahedron),
        (105, 104, Hexahedron),
        (118, 30, Pyramid),
        (119, 55, Pyramid),
        (120, 91, Pyramid),
        (121, 140, Pyramid),
        (122, 204, Pyramid),
        (123, 285, Pyramid),
        (124, 385, Pyramid),
        (125, 21, Pyramid),
        (126, 29, Pyramid),
        (127, 37, Pyramid),
        (128, 45, Pyramid),
        (129, 53, Pyramid),
        (130, 61, Pyramid),
        (131, 69, Pyramid),
        (137, 16, Tetra),
    ]
};

/// The corner cell and the number of nodes of a Gmsh element type, or why it is not read.
pub(crate) fn gmsh_type(t: i64) -> Result<(CellKind, usize), String> {
    if let Some(&(_, n, k)) = GMSH_TYPES.iter().find(|r| r.0 == t) {
        return Ok((k, n));
    }
    Err(match t {
        34 | 69 => format!("element type {t} (a polygon) is not read: its corners are not listed apart"),
        35 => "element type 35 (a polyhedron) is not read: its faces are not listed".into(),
        84..=89 | 132 => format!("element type {t} (one node, order 0) is not read: it has no corner cell"),
        133..=136 => format!("element type {t} (XFEM) is not read: it has no corner cell"),
        _ => format!("element type {t} is not a Gmsh element type with corners (1 to 137: lines, triangles, quadrangles, tetrahedra, hexahedra, prisms, pyramids of any order, points)"),
    })
}

/// The corner cell of a VTK higher-order type (quadratic 21–37, Lagrange 68–74, Bézier
/// 75–81), with its number of points when fixed, and the type's name.
pub(crate) fn vtk_type(t: i64) -> Option<(CellKind, Option<usize>, &'static str)> {
    use CellKind::*;
    Some(match t {
        21 => (Line, Some(3), "quadratic edge"),
        22 => (Triangle, Some(6), "quadratic triangle"),
        23 => (Quad, Some(8), "quadratic quad"),
        24 => (Tetra, Some(10), "quadratic tetra"),
        25 => (Hexahedron, Some(20), "quadratic hexahedron"),
        26 => (Wedge, Some(15), "quadratic wedge"),
        27 => (Pyramid, Some(13), "quadratic pyramid"),
        28 => (Quad, Some(9), "biquadratic quad"),
        29 => (Hexahedron, Some(27), "triquadratic hexahedron"),
        30 => (Quad, Some(6), "quadratic linear quad"),
        31 => (Wedge, Some(12), "quadratic linear wedge"),
        32 => (Wedge, Some(18), "biquadratic quadratic wedge"),
        33 => (Hexahedron, Some(24), "biquadratic quadratic hexahedron"),
        34 => (Triangle, Some(7), "biquadratic triangle"),
        35 => (Line, Some(4), "cubic line"),
        36 => (Polygon, None, "quadratic polygon"),
        37 => (Pyramid, Some(19), "triquadratic pyramid"),
        68 | 75 => (Line, None, "Lagrange or Bezier curve"),
        69 | 76 => (Triangle, None, "Lagrange or Bezier triangle"),
        70 | 77 => (Quad, None, "Lagrange or Bezier quadrilateral"),
        71 | 78 => (Tetra, None, "Lagrange or Bezier tetrahedron"),
        72 | 79 => (Hexahedron, None, "Lagrange or Bezier hexahedron"),
        73 | 80 => (Wedge, None, "Lagrange or Bezier wedge"),
        74 | 81 => (Pyramid, None, "Lagrange or Bezier pyramid"),
        _ => return None,
    })
}

/// Cuts a higher-order cell to its corners (`nodes` of the whole cell; for a quadratic
/// polygon the first half), returning the label of its other nodes.
pub(crate) fn to_corners(cell: &mut MeshCell, points: &[Point]) -> Result<LabelValue, String> {
    let corners = match cell.kind.points() {
        Some(k) => k,
        None if cell.nodes.len().is_multiple_of(2) && cell.nodes.len() >= 6 => cell.nodes.len() / 2,
        None => return Err(format!("{} points: a quadratic polygon has an even number, 6 or more", cell.nodes.len())),
    };
    if cell.nodes.len() <= corners {
        return Err(format!(
            "{} points: a higher-order {} has more than its {corners} corners",
            cell.nodes.len(),
            cell.kind
        ));
    }
    let mut text = String::new();
    for &v in &cell.nodes[corners..] {
        let p = points.get(v as usize).ok_or_else(|| format!("point {v} is not in the file"))?;
        if !text.is_empty() {
            text.push_str(", ");
        }
        text.push_str(&format!("{} {} {}", p[0], p[1], p[2]));
    }
    cell.nodes.truncate(corners);
    Ok(LabelValue::Text(text))
}

/// The cell data array of the other nodes, when a cell has some.
pub(crate) fn label_array(values: Vec<Option<LabelValue>>) -> Option<DataArray> {
    values.iter().any(Option::is_some).then(|| DataArray { name: HIGH_ORDER_LABEL.into(), values })
}
