//! Curves on the cells of a surface: the shortest non-contractible cycle (through a vertex
//! or overall), the edge width and the face width of a 2-map, by
//! [`gmap_homology::curves`]; the shortest basis of `H_1` of any input is a homology
//! option ([`crate::HomologyOptions::shortest`], the route planner's `finish`).
//!
//! Cells are named by their smallest dart, as in error messages; a cycle also lists its
//! darts (CGAL's paths of darts: for each step, the dart of the edge at the vertex left).

use gmap_core::{Dart, DenseMap};
use gmap_homology::curves as algo;

pub use algo::{CurveError, Weights};

use crate::error::Result;
use crate::input::Input;

/// A closed walk on a surface's edges.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct Curve {
    /// the sum of its edges' weights
    pub length: f64,
    /// for each step, the dart of its edge at the vertex it leaves
    pub darts: Vec<u64>,
    /// its edges, each by its smallest dart
    pub edges: Vec<u64>,
    /// the vertices passed, each by its smallest dart, the first again last
    pub vertices: Vec<u64>,
}

impl Curve {
    fn of(c: &algo::Cycle, s: &algo::Surface, map: &DenseMap) -> Self {
        let dart = |d: Dart| u64::from(d.get());
        Curve {
            length: c.length,
            darts: c.darts(s, map).into_iter().map(dart).collect(),
            edges: c.edges.iter().map(|&e| dart(s.reps[1][e as usize])).collect(),
            vertices: c.vertices.iter().map(|&v| dart(s.reps[0][v as usize])).collect(),
        }
    }

    /// One line: the length, the number of edges and the darts.
    pub fn to_text(&self) -> String {
        let darts: Vec<String> = self.darts.iter().map(u64::to_string).collect();
        format!("length {} ({} edges), darts {}\n", self.length, self.edges.len(), darts.join(" "))
    }

    /// `{"length", "edges", "darts", "edge_darts", "vertex_darts"}`.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "length": self.length,
            "edges": self.edges.len(),
            "darts": self.darts,
            "edge_darts": self.edges,
            "vertex_darts": self.vertices,
        })
    }
}

/// The face width of a closed surface, with a closed curve realising it.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct FaceWidth {
    /// the fewest faces a non-contractible closed curve meeting the graph at vertices only
    /// passes
    pub width: usize,
    /// the faces passed, each by its smallest dart
    pub faces: Vec<u64>,
    /// the vertices passed, each by its smallest dart (`vertices[k]`, then `faces[k]`)
    pub vertices: Vec<u64>,
}

impl FaceWidth {
    /// One line: the width and the faces passed.
    pub fn to_text(&self) -> String {
        let faces: Vec<String> = self.faces.iter().map(u64::to_string).collect();
        format!("face width {}, faces (by their smallest darts) {}\n", self.width, faces.join(" "))
    }

    /// `{"width", "face_darts", "vertex_darts"}`.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({ "width": self.width, "face_darts": self.faces, "vertex_darts": self.vertices })
    }
}

/// The 2-map of an input (a map, or the G-map of a simplicial complex).
fn surface_map<'a>(input: &'a Input) -> Result<std::borrow::Cow<'a, DenseMap>> {
    input.to_map()
}

/// The vertex of dart `d` of `map`, refused when there is no such dart.
fn vertex_of(map: &DenseMap, d: u64) -> Result<u32> {
    if d >= map.dart_count() as u64 {
        let e = CurveError::NotAPath {
            step: 0,
            dart: u32::try_from(d).unwrap_or(u32::MAX),
            reason: "is not a dart of the map",
        };
        return Err(e.into());
    }
    Ok(map.cells(0).of[d as usize])
}

/// The shortest non-contractible cycle of a 2-map (`None` on a sphere or a disc), through
/// the vertex of dart `through` when given (CGAL's `with_base_point`), with edges weighted
/// by `weights`. Orientable or not, with or without boundary. O(E log V) through a vertex,
/// O(V E log V) overall (refused past [`algo::cycles::CYCLE_WORK_LIMIT`]).
///
/// ```
/// use gmap::{curves, Input, MapInput};
/// let torus = gmap::ops::build::grid(&[6, 4], &[true, true]).unwrap();
/// let input = Input::Map(MapInput::new(torus));
/// let c = curves::shortest_non_contractible_cycle(&input, &curves::Weights::Unit, None).unwrap().unwrap();
/// assert_eq!((c.length, c.edges.len()), (4.0, 4));
/// ```
pub fn shortest_non_contractible_cycle(
    input: &Input,
    weights: &Weights,
    through: Option<u64>,
) -> Result<Option<Curve>> {
    let map = surface_map(input)?;
    let s = algo::Surface::of_map(&map, weights)?;
    let c = match through {
        Some(d) => algo::shortest_non_contractible_cycle_through(&s, vertex_of(&map, d)?)?,
        None => algo::shortest_non_contractible_cycle(&s)?,
    };
    Ok(c.map(|c| Curve::of(&c, &s, &map)))
}

/// The edge width of a 2-map: a non-contractible cycle of the fewest edges (`None` on a
/// sphere or a disc).
pub fn edge_width(input: &Input) -> Result<Option<Curve>> {
    shortest_non_contractible_cycle(input, &Weights::Unit, None)
}

/// The face width of a closed 2-map (`None` on a sphere): half the edge width of its
/// radial graph. Refuses surfaces with boundary.
pub fn face_width(input: &Input) -> Result<Option<FaceWidth>> {
    let map = surface_map(input)?;
    let Some(w) = algo::face_width(&map)? else { return Ok(None) };
    let (v, f) = (map.cells(0), map.cells(2));
    Ok(Some(FaceWidth {
        width: w.width,
        faces: w.faces.iter().map(|&x| u64::from(f.reps[x as usize].get())).collect(),
        vertices: w.vertices.iter().map(|&x| u64::from(v.reps[x as usize].get())).collect(),
    }))
}
