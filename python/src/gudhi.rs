//! The calls `gmap.gudhi` (python/gmap/gudhi.py) makes: an image's or a list of simplices'
//! diagram with the cells that give each pair its birth and death, through the facade
//! (`gmap::persistence::axes_periodic_persistence`, `given_facet_persistence`,
//! `keep_persistent`).

use gmap::algebra::persistence::{CellName, Construction, Diagram};
use gmap::PersistenceOptions;
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};

use crate::errors::Failure;

/// A cell as a tuple: doubled-grid coordinates (numpy's axis order) or vertex labels.
fn cell_tuple<'py>(py: Python<'py>, c: &CellName) -> PyResult<Bound<'py, PyAny>> {
    Ok(match c {
        CellName::Grid(g) => PyTuple::new(py, g)?.into_any(),
        CellName::Simplex(s) => PyTuple::new(py, s)?.into_any(),
        other => return Err(Failure::input(format!("no GUDHI name for the cell {other}")).into()),
    })
}

/// `(pairs, births, deaths, cycles)`: the (k, 3) array of (dimension, birth, death), and
/// when cells were asked for, the birth cell and the death cell (None if essential) of
/// each pair as tuples and its cycle as a list of (cell, coefficient) (else empty lists).
fn result<'py>(py: Python<'py>, d: &Diagram) -> PyResult<Bound<'py, PyTuple>> {
    let mut flat = Vec::with_capacity(d.pairs.len() * 3);
    for p in &d.pairs {
        flat.extend_from_slice(&[p.dim as f64, p.birth, p.death]);
    }
    let pairs = PyArray1::from_vec(py, flat).reshape([d.pairs.len(), 3])?.into_any();
    let (births, deaths) = (PyList::empty(py), PyList::empty(py));
    for (b, e) in &d.cells {
        births.append(cell_tuple(py, b)?)?;
        match e {
            Some(e) => deaths.append(cell_tuple(py, e)?)?,
            None => deaths.append(py.None())?,
        }
    }
    let cycles = PyList::empty(py);
    for chain in &d.cycles {
        let c = PyList::empty(py);
        for (cell, k) in chain {
            c.append((cell_tuple(py, cell)?, *k))?;
        }
        cycles.append(c)?;
    }
    PyTuple::new(py, [pairs, births.into_any(), deaths.into_any(), cycles.into_any()])
}

fn options(field: u32, superlevel: bool, cells: bool) -> PersistenceOptions {
    let mut o = PersistenceOptions::default();
    (o.field, o.superlevel, o.cycles) = (field, superlevel, cells);
    o
}

/// _image_pairs(values, construction, periodic, field, superlevel, min_persistence, cells)
///
/// The diagram of a float64 C-contiguous array with axis k wrapping when periodic[k].
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn _image_pairs<'py>(
    py: Python<'py>,
    values: PyReadonlyArrayDyn<'py, f64>,
    construction: &str,
    periodic: Vec<bool>,
    field: u32,
    superlevel: bool,
    min_persistence: f64,
    cells: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    let mut o = options(field, superlevel, cells);
    o.construction = construction
        .parse::<Construction>()
        .map_err(|_| Failure::input(format!("construction {construction:?}: expected 'T' or 'V'")))?;
    let shape = values.shape().to_vec();
    let v = values.as_slice().map_err(|_| Failure::input("the values must be a C-contiguous float64 array"))?;
    let mut d = py
        .allow_threads(|| gmap::persistence::axes_periodic_persistence(&shape, v, &periodic, &o))
        .map_err(Failure::from)?;
    gmap::persistence::keep_persistent(&mut d, min_persistence);
    result(py, &d)
}

/// _simplex_pairs(simplices, values, field, min_persistence, cells)
///
/// The diagram of the complex of `simplices`, `values[k]` on `simplices[k]` (a face
/// taking the minimum of the values of the simplices it is a face of).
#[pyfunction]
pub fn _simplex_pairs<'py>(
    py: Python<'py>,
    simplices: Vec<Vec<u64>>,
    values: Vec<f64>,
    field: u32,
    min_persistence: f64,
    cells: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    let o = options(field, false, cells);
    let mut d = py
        .allow_threads(|| gmap::persistence::given_facet_persistence(simplices, &values, &o))
        .map_err(Failure::from)?;
    gmap::persistence::keep_persistent(&mut d, min_persistence);
    result(py, &d)
}

/// _perseus_cubical(path) -> (values, sizes, periodic)
///
/// A Perseus cubical file: the top cells' values (float64, the first axis fastest), the
/// sizes and which axes wrap.
#[pyfunction]
pub fn _perseus_cubical<'py>(py: Python<'py>, path: std::path::PathBuf) -> PyResult<Bound<'py, PyTuple>> {
    let p = py.allow_threads(|| gmap::persistence::perseus_cubical(&path)).map_err(Failure::from)?;
    let values = PyArray1::from_vec(py, p.values).into_any();
    let sizes = PyTuple::new(py, &p.sizes)?.into_any();
    let periodic = PyTuple::new(py, &p.periodic)?.into_any();
    PyTuple::new(py, [values, sizes, periodic])
}
