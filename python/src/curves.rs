//! Curves on a surface (facade `gmap::curves`): `shortest_non_contractible_cycle`,
//! `edge_width`, `face_width`; and the `generators="shortest"` value of `homology`.

use std::path::PathBuf;

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

use gmap::curves::{self, Curve, Weights};
use gmap::{HomologyOptions, Input};

use crate::errors::Failure;
use crate::gmapobj::PyGMap;

/// Sets `o.generators` and `o.shortest` from `generators=`: a bool, or `"shortest"`.
pub fn generators_option(generators: Option<&Bound<'_, PyAny>>, o: &mut HomologyOptions) -> PyResult<()> {
    let Some(generators) = generators else { return Ok(()) };
    if let Ok(s) = generators.extract::<String>() {
        return match s.as_str() {
            "shortest" => {
                (o.generators, o.shortest) = (true, true);
                Ok(())
            }
            other => Err(Failure::input(format!("generators={other:?}: give True, False or \"shortest\"")).into()),
        };
    }
    o.generators =
        generators.extract::<bool>().map_err(|_| Failure::input("generators: give True, False or \"shortest\""))?;
    Ok(())
}

/// The input of a path or a GMap.
fn input_of(x: &Bound<'_, PyAny>) -> PyResult<Input> {
    if let Ok(m) = x.downcast::<PyGMap>() {
        return Ok(m.borrow_mut().homology_input()?);
    }
    if x.is_instance_of::<PyString>() || x.hasattr("__fspath__")? {
        let path: PathBuf = x.extract()?;
        return Ok(gmap::open(&path).map_err(Failure::from)?);
    }
    Err(Failure::input("curves are computed on a GMap or on the path of a file of a 2-map").into())
}

/// `"unit"`, `"length"` or one weight per edge (in the order of the edges' smallest darts).
fn weights_of(w: &Bound<'_, PyAny>) -> PyResult<Weights> {
    if let Ok(s) = w.extract::<String>() {
        return match s.as_str() {
            "unit" => Ok(Weights::Unit),
            "length" => Ok(Weights::Length),
            other => {
                Err(Failure::input(format!("weights={other:?}: give \"unit\", \"length\" or one number per edge"))
                    .into())
            }
        };
    }
    let v: Vec<f64> =
        w.extract().map_err(|_| Failure::input("weights: give \"unit\", \"length\" or one number per edge"))?;
    Ok(Weights::PerEdge(v))
}

/// A curve as a dict: `length`, `darts`, `edge_darts`, `vertex_darts`.
fn curve_dict<'py>(py: Python<'py>, c: &Curve) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("length", c.length)?;
    d.set_item("darts", c.darts.clone())?;
    d.set_item("edge_darts", c.edges.clone())?;
    d.set_item("vertex_darts", c.vertices.clone())?;
    Ok(d)
}

/// shortest_non_contractible_cycle(x, *, weights="unit", through=None)
///
/// The shortest non-contractible cycle of the surface `x` (a GMap of dimension 2, or the
/// path of a file of one), through the vertex of dart `through` when given, as a dict
/// (`length`, `darts`: the dart of each step at the vertex it leaves, `edge_darts`,
/// `vertex_darts`: cells by their smallest darts), or None when every closed curve is
/// contractible. `weights`: "unit" (count edges), "length" (the points' distances) or a
/// list of one weight per edge.
#[pyfunction]
#[pyo3(signature = (x, *, weights = None, through = None))]
pub fn shortest_non_contractible_cycle<'py>(
    py: Python<'py>,
    x: &Bound<'py, PyAny>,
    weights: Option<&Bound<'py, PyAny>>,
    through: Option<u64>,
) -> PyResult<Option<Bound<'py, PyDict>>> {
    let input = input_of(x)?;
    let w = weights.map(weights_of).transpose()?.unwrap_or(Weights::Unit);
    let c = py.allow_threads(|| curves::shortest_non_contractible_cycle(&input, &w, through)).map_err(Failure::from)?;
    c.map(|c| curve_dict(py, &c)).transpose()
}

/// edge_width(x): a non-contractible cycle of the fewest edges of the surface `x` (a dict as
/// shortest_non_contractible_cycle gives), or None.
#[pyfunction]
pub fn edge_width<'py>(py: Python<'py>, x: &Bound<'py, PyAny>) -> PyResult<Option<Bound<'py, PyDict>>> {
    let input = input_of(x)?;
    let c = py.allow_threads(|| curves::edge_width(&input)).map_err(Failure::from)?;
    c.map(|c| curve_dict(py, &c)).transpose()
}

/// face_width(x): the face width of the closed surface `x`, as a dict (`width`,
/// `face_darts`, `vertex_darts`: the faces and vertices a curve realising it passes), or
/// None on a sphere. A surface with boundary raises PreconditionError.
#[pyfunction]
pub fn face_width<'py>(py: Python<'py>, x: &Bound<'py, PyAny>) -> PyResult<Option<Bound<'py, PyDict>>> {
    let input = input_of(x)?;
    let w = py.allow_threads(|| curves::face_width(&input)).map_err(Failure::from)?;
    let Some(w) = w else { return Ok(None) };
    let d = PyDict::new(py);
    d.set_item("width", w.width)?;
    d.set_item("face_darts", w.faces.clone())?;
    d.set_item("vertex_darts", w.vertices.clone())?;
    Ok(Some(d))
}

/// A path given as a list of numbers: darts, or vertices when `vertices`.
fn path_spec(p: Vec<u64>, vertices: bool) -> gmap::homotopy::PathSpec {
    if vertices {
        gmap::homotopy::PathSpec::Vertices(p)
    } else {
        gmap::homotopy::PathSpec::Darts(p)
    }
}

/// The surface `x` preprocessed for homotopy tests.
fn paths_of(py: Python<'_>, x: &Bound<'_, PyAny>) -> PyResult<gmap::homotopy::Paths> {
    let input = input_of(x)?;
    Ok(py.allow_threads(|| gmap::homotopy::Paths::new(&input)).map_err(Failure::from)?)
}

/// is_contractible(x, path, *, vertices=False)
///
/// Whether the closed path `path` on the surface `x` (a GMap of dimension 2, or the path of
/// a file of one) is contractible. `path`: for each step, a dart of its edge at the vertex
/// it leaves; or, with vertices=True, the vertices passed (numbered as the map numbers
/// them), consecutive ones joined by exactly one edge. A sequence that is not a path, or a
/// path that is not closed, raises naming the step.
#[pyfunction]
#[pyo3(signature = (x, path, *, vertices = false))]
pub fn is_contractible(py: Python<'_>, x: &Bound<'_, PyAny>, path: Vec<u64>, vertices: bool) -> PyResult<bool> {
    let s = paths_of(py, x)?;
    Ok(s.is_contractible(&path_spec(path, vertices)).map_err(Failure::from)?)
}

/// are_freely_homotopic(x, p, q, *, vertices=False)
///
/// Whether the closed paths `p` and `q` (as for is_contractible) are freely homotopic.
/// Raises PreconditionError where this implementation cannot decide (docs/CURVES.md).
#[pyfunction]
#[pyo3(signature = (x, p, q, *, vertices = false))]
pub fn are_freely_homotopic(
    py: Python<'_>,
    x: &Bound<'_, PyAny>,
    p: Vec<u64>,
    q: Vec<u64>,
    vertices: bool,
) -> PyResult<bool> {
    let s = paths_of(py, x)?;
    Ok(s.are_freely_homotopic(&path_spec(p, vertices), &path_spec(q, vertices)).map_err(Failure::from)?)
}

/// are_homotopic_with_fixed_endpoints(x, p, q, *, vertices=False)
///
/// Whether the paths `p` and `q`, with the same start and end, are homotopic with their
/// ends fixed.
#[pyfunction]
#[pyo3(signature = (x, p, q, *, vertices = false))]
pub fn are_homotopic_with_fixed_endpoints(
    py: Python<'_>,
    x: &Bound<'_, PyAny>,
    p: Vec<u64>,
    q: Vec<u64>,
    vertices: bool,
) -> PyResult<bool> {
    let s = paths_of(py, x)?;
    Ok(s.are_homotopic_with_fixed_endpoints(&path_spec(p, vertices), &path_spec(q, vertices)).map_err(Failure::from)?)
}

/// is_homotopic_to_simple_cycle(x, path, *, vertices=False)
///
/// Whether the closed path `path` is homotopic to a simple closed curve; decided on the
/// sphere, the projective plane, the torus and for contractible paths, raises
/// PreconditionError otherwise.
#[pyfunction]
#[pyo3(signature = (x, path, *, vertices = false))]
pub fn is_homotopic_to_simple_cycle(
    py: Python<'_>,
    x: &Bound<'_, PyAny>,
    path: Vec<u64>,
    vertices: bool,
) -> PyResult<bool> {
    let s = paths_of(py, x)?;
    Ok(s.is_homotopic_to_simple_cycle(&path_spec(path, vertices)).map_err(Failure::from)?)
}
