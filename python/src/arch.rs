//! Architectural complexes from Python as from the command line: opening with `snap=`,
//! homology with `topological=`, the TM edit check and views, rooms from walls (facade
//! `gmap::open_with`, `gmap::homology`, `gmap::tm_check`, `gmap::tm_views`,
//! `gmap::rooms_of`). The Python wrappers are in `gmap/__init__.py`.

use std::path::PathBuf;

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::errors::Failure;
use crate::objects::PyArchComplex;
use gmap::{HomologyOptions, Input};

/// The input of an ArchComplex, or of the file at a path.
fn input_of(py: Python<'_>, x: &Bound<'_, PyAny>) -> PyResult<Option<Input>> {
    if x.downcast::<PyArchComplex>().is_ok() {
        return Ok(None);
    }
    let path: PathBuf =
        x.extract().map_err(|_| Failure::input("expected an ArchComplex or a path to a .json or map file"))?;
    Ok(Some(py.allow_threads(|| gmap::open(&path)).map_err(Failure::from)?))
}

/// _open_arch(path, snap): the architectural complex of a `.json` file, its points welded
/// and its cells split within `snap`; returns it with the lines saying what was done.
#[pyfunction]
#[pyo3(signature = (path, snap))]
pub fn _open_arch(py: Python<'_>, path: PathBuf, snap: f64) -> PyResult<(PyArchComplex, Vec<String>)> {
    let o = gmap::OpenOptions::max_darts(None).with_snap(Some(snap));
    let input = py.allow_threads(|| gmap::open_with(&path, &o)).map_err(Failure::from)?;
    if !matches!(input, Input::Arch(_)) {
        return Err(
            Failure::input(format!("{}: snap= applies to a .json architectural complex", path.display())).into()
        );
    }
    let notes = input.notes().to_vec();
    Ok((PyArchComplex { input }, notes))
}

/// _arch_homology(x, topological, generators, field): the homology of an ArchComplex (or a
/// `.json` path) as `gmap homology [--topological]` computes it.
#[pyfunction]
#[pyo3(signature = (x, topological, generators, field))]
pub fn _arch_homology(
    py: Python<'_>,
    x: &Bound<'_, PyAny>,
    topological: bool,
    generators: bool,
    field: Option<u64>,
) -> PyResult<crate::PyHomology> {
    let mut o = HomologyOptions::default();
    (o.topological, o.generators, o.field) = (topological, generators, field);
    match input_of(py, x)? {
        Some(input) => crate::facade(py, &input, &o),
        None => crate::facade(py, &x.downcast::<PyArchComplex>()?.get().input, &o),
    }
}

/// _tm_check(x): the TM edit check (topological and metrical) of an ArchComplex or a file,
/// as a dict: `dim`, `counts`, `defects`, `closed` (None or the defects once closed by the
/// exterior), `metric` (None or `(tolerance, defects)`), `passes`, `text`.
#[pyfunction]
pub fn _tm_check<'py>(py: Python<'py>, x: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
    let c = if let Ok(a) = x.downcast::<PyArchComplex>() {
        let input = &a.get().input;
        py.allow_threads(|| gmap::tm_check(input))
    } else {
        let path: PathBuf = x.extract()?;
        py.allow_threads(|| gmap::tm_check_file(&path))
    }
    .map_err(Failure::from)?;
    let d = PyDict::new(py);
    d.set_item("dim", c.dim)?;
    d.set_item("counts", c.counts.clone())?;
    d.set_item("defects", c.defects.clone())?;
    d.set_item("closed", c.closed.clone())?;
    d.set_item("metric", c.metric.clone())?;
    d.set_item("passes", c.passes())?;
    d.set_item("text", c.to_text())?;
    Ok(d)
}

/// _tm_views(x, cell): the views of an ArchComplex's (or a file's) (n-1)-cells, or one
/// cell's, as `gmap tm views` prints them.
#[pyfunction]
#[pyo3(signature = (x, cell = None))]
pub fn _tm_views(py: Python<'_>, x: &Bound<'_, PyAny>, cell: Option<String>) -> PyResult<String> {
    let t = match input_of(py, x)? {
        Some(input) => py.allow_threads(|| gmap::tm_views(&input, cell.as_deref())),
        None => {
            let input = &x.downcast::<PyArchComplex>()?.get().input;
            py.allow_threads(|| gmap::tm_views(input, cell.as_deref()))
        }
    };
    Ok(t.map_err(Failure::from)?)
}

/// _rooms(path): the rooms of the faces of an `.off` or `.json` file, as
/// `(complex, [(name, faces, volume, [names of the rooms next to it])])`.
#[pyfunction]
pub fn _rooms<'py>(py: Python<'py>, path: PathBuf) -> PyResult<(PyArchComplex, Bound<'py, PyList>)> {
    let r = py.allow_threads(|| gmap::rooms_of(&path)).map_err(Failure::from)?;
    let rooms = PyList::empty(py);
    for (name, faces, volume, next) in &r.rooms {
        rooms.append((name.clone(), *faces, *volume, next.clone()))?;
    }
    let input = Input::Arch(gmap::input::Sourced::new(r.complex));
    Ok((PyArchComplex { input }, rooms))
}

/// _room_graph(x, via): the room graph (`gmap graph --dual VIA`, facade `gmap::room_graph`)
/// of an ArchComplex or a file, as its JSON text (`nodes`, `edges`; `gmap/arch.py` makes the
/// networkx graph of it). `via` is `faces`, `apertures` or `exterior`.
#[pyfunction]
pub fn _room_graph(py: Python<'_>, x: &Bound<'_, PyAny>, via: &str) -> PyResult<String> {
    let dual = gmap::Dual::parse(via).map_err(|e| pyo3::exceptions::PyValueError::new_err(e.to_string()))?;
    let g = match input_of(py, x)? {
        Some(input) => py.allow_threads(|| gmap::room_graph(&input, dual, None)),
        None => {
            let input = &x.downcast::<PyArchComplex>()?.get().input;
            py.allow_threads(|| gmap::room_graph(input, dual, None))
        }
    };
    Ok(g.map_err(Failure::from)?.to_json())
}
