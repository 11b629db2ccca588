//! `gmap.persistence(x, …)`: the persistence diagram of a path, a numpy grey array or a
//! package object, through the facade (`gmap::persistence`, `gmap::persistence_file`) and,
//! for a numpy array, the facade's diagram of an image (`gmap::persistence::image_persistence`,
//! one call that decides between the whole grid and, past the memory limit, the lower stars
//! read from the array in place or from a copy when the copy fits).

use std::path::PathBuf;

use gmap::algebra::persistence::{CellName, Construction, Diagram};
use gmap::persistence::{image_persistence, Pixels};
use gmap::{Input, PersistenceOptions};
use numpy::{PyArray1, PyArrayMethods, PyUntypedArrayMethods, ToPyArray};
use pyo3::prelude::*;
use pyo3::types::{PyList, PyString, PyTuple};

use crate::errors::Failure;
use crate::gmapobj::PyGMap;
use crate::objects::{PyArchComplex, PyCubicalSet, PyImage, PySimplicialComplex};

/// The diagram of a numpy grey array (1 to 8 axes, numbers or booleans), in numpy's axis
/// order, by one facade call that chooses the route and what is copied: a float64
/// C-contiguous array is handed over as it is, another C-contiguous array of numbers or
/// booleans is read pixel by pixel in place, any other layout (Fortran order, a strided or
/// broadcast view) is handed over to be copied, which the facade does only when the copy
/// fits.
fn array_diagram(py: Python<'_>, x: &Bound<'_, PyAny>, o: &PersistenceOptions) -> PyResult<Diagram> {
    let arr = x.downcast::<numpy::PyUntypedArray>()?;
    crate::objects::check_array(x)?;
    let nd = arr.ndim();
    let most = gmap::ops::import::image::MAX_DIM;
    if !(1..=most).contains(&nd) {
        return Err(Failure::input(format!("a grey array has 1 to {most} dimensions, not {nd}")).into());
    }
    let shape = arr.shape().to_vec();
    macro_rules! typed {
        ($($t:ty),*) => {$(
            if let Ok(a) = x.downcast::<numpy::PyArrayDyn<$t>>() {
                let a = a.readonly();
                return diagram_of(py, &shape, &a.as_array(), o);
            }
        )*};
    }
    typed!(f64, f32, u8, u16, u32, u64, i8, i16, i32, i64, bool);
    Err(Failure::input(format!("a grey array holds numbers or booleans, not dtype {}", arr.dtype().str()?)).into())
}

/// A pixel's value as the facade reads it.
trait Grey: Copy + Sync + Sized {
    fn grey(self) -> f64;
    /// The values as they are, when they are already `f64`.
    fn as_f64(_values: &[Self]) -> Option<&[f64]> {
        None
    }
}

impl Grey for f64 {
    fn grey(self) -> f64 {
        self
    }
    fn as_f64(values: &[f64]) -> Option<&[f64]> {
        Some(values)
    }
}

macro_rules! grey_as_f64 {
    ($($t:ty),*) => {$(
        impl Grey for $t {
            fn grey(self) -> f64 {
                self as f64
            }
        }
    )*};
}
grey_as_f64!(f32, u8, u16, u32, u64, i8, i16, i32, i64);

/// A mask is the set of its True pixels, as in `homology(mask)` and `CubicalSet(mask)`:
/// True is 0 (there from the start), False 1 (the persistence of `CubicalSet(mask)`).
impl Grey for bool {
    fn grey(self) -> f64 {
        f64::from(u8::from(!self))
    }
}

/// The diagram of a typed array view, the GIL released: its slice when it is C-contiguous
/// (float64 as it is, other types read pixel by pixel), else its values copied in C order
/// when the facade decides to copy them.
fn diagram_of<T: Grey>(
    py: Python<'_>,
    shape: &[usize],
    a: &numpy::ndarray::ArrayViewD<'_, T>,
    o: &PersistenceOptions,
) -> PyResult<Diagram> {
    let d = match a.as_slice() {
        Some(v) => match T::as_f64(v) {
            Some(values) => py.allow_threads(|| image_persistence(shape, Pixels::Slice(values), o)),
            None => {
                let value = |i: usize| v[i].grey();
                py.allow_threads(|| image_persistence(shape, Pixels::Read(&value), o))
            }
        },
        None => {
            let fill = |out: &mut [f64]| {
                for (o, &x) in out.iter_mut().zip(a.iter()) {
                    *o = x.grey();
                }
            };
            py.allow_threads(|| image_persistence(shape, Pixels::Copied(&fill), o))
        }
    };
    Ok(d.map_err(Failure::from)?)
}

/// The (k, 3) float64 array of (dimension, birth, death).
fn pairs_array<'py>(py: Python<'py>, d: &Diagram) -> PyResult<Bound<'py, PyAny>> {
    let mut flat = Vec::with_capacity(d.pairs.len() * 3);
    for p in &d.pairs {
        flat.extend_from_slice(&[p.dim as f64, p.birth, p.death]);
    }
    Ok(PyArray1::from_vec(py, flat).reshape([d.pairs.len(), 3])?.into_any())
}

/// One cycle as (cells, coefficients): cells an int64 array (m, d) of doubled-grid
/// coordinates for images, a list of vertex-label tuples for simplices, an int64 array of
/// cell numbers (the cell's smallest dart) for G-maps, a list of region ids for
/// architectural complexes.
fn cycle_to_py<'py>(py: Python<'py>, chain: &[(CellName, u32)]) -> PyResult<Bound<'py, PyTuple>> {
    let coefficients: Vec<i64> = chain.iter().map(|(_, k)| i64::from(*k)).collect();
    let coefficients = coefficients.to_pyarray(py).into_any();
    let cells: Bound<'py, PyAny> = match chain.first().map(|(c, _)| c) {
        Some(CellName::Grid(g)) => {
            let d = g.len();
            let mut flat = Vec::with_capacity(chain.len() * d);
            for (c, _) in chain {
                if let CellName::Grid(g) = c {
                    flat.extend(g.iter().map(|&x| x as i64));
                }
            }
            PyArray1::from_vec(py, flat).reshape([chain.len(), d])?.into_any()
        }
        Some(CellName::Simplex(_)) => {
            let l = PyList::empty(py);
            for (c, _) in chain {
                if let CellName::Simplex(s) = c {
                    l.append(PyTuple::new(py, s)?)?;
                }
            }
            l.into_any()
        }
        Some(CellName::Region { .. }) => {
            let ids: Vec<u64> = chain
                .iter()
                .filter_map(|(c, _)| match c {
                    CellName::Region { id, .. } => Some(*id),
                    _ => None,
                })
                .collect();
            PyList::new(py, ids)?.into_any()
        }
        _ => {
            let ids: Vec<i64> = chain
                .iter()
                .map(|(c, _)| match c {
                    CellName::Cell { index, .. } => *index as i64,
                    _ => -1,
                })
                .collect();
            ids.to_pyarray(py).into_any()
        }
    };
    PyTuple::new(py, [cells, coefficients])
}

/// Vertex values from Python: a mapping {label: value}, or a sequence or 1-D array whose
/// entry i is the value of the vertex labelled i.
fn vertex_values(v: &Bound<'_, PyAny>) -> PyResult<gmap::VertexValues> {
    let pairs: Vec<(u64, f64)> = if v.hasattr("items")? {
        let mut pairs = Vec::new();
        for item in v.call_method0("items")?.try_iter()? {
            let (label, value): (u64, f64) = item?
                .extract()
                .map_err(|_| Failure::input("vertex_values: a mapping from non-negative integer labels to numbers"))?;
            pairs.push((label, value));
        }
        pairs
    } else {
        let values: Vec<f64> = v.extract().map_err(|_| {
            Failure::input("vertex_values: a mapping {label: value} or a sequence of numbers indexed by label")
        })?;
        values.into_iter().enumerate().map(|(i, x)| (i as u64, x)).collect()
    };
    Ok(gmap::VertexValues::from_pairs(pairs).map_err(Failure::from)?)
}

/// An input held by a Python object or made from Python values.
enum Held<'a> {
    Borrowed(&'a Input),
    Owned(Box<Input>),
}

impl std::ops::Deref for Held<'_> {
    type Target = Input;
    fn deref(&self) -> &Input {
        match self {
            Held::Borrowed(i) => i,
            Held::Owned(i) => i,
        }
    }
}

/// The simplicial complex `x` holds, if it is one: a SimplicialComplex, or facets given as
/// a list or tuple of sequences of vertex labels (a numpy array is an image).
fn complex_of_py<'a>(x: &'a Bound<'_, PyAny>) -> PyResult<Option<Held<'a>>> {
    if let Ok(s) = x.downcast::<PySimplicialComplex>() {
        return Ok(Some(Held::Borrowed(&s.get().input)));
    }
    if x.is_instance_of::<PyList>() || x.is_instance_of::<PyTuple>() {
        let sc = crate::objects::complex_of(crate::objects::facets_from_py(x)?)?;
        return Ok(Some(Held::Owned(Box::new(sc))));
    }
    Ok(None)
}

/// The diagram of a simplicial complex (a path, a SimplicialComplex, facets) by values
/// given from Python: per vertex (lower star) or per facet.
fn given_values_diagram(
    py: Python<'_>,
    x: &Bound<'_, PyAny>,
    vertex: Option<&Bound<'_, PyAny>>,
    facet: Option<&Bound<'_, PyAny>>,
    o: &PersistenceOptions,
) -> PyResult<Diagram> {
    let is_path = x.is_instance_of::<PyString>() || x.hasattr("__fspath__")?;
    let complex = if is_path { None } else { complex_of_py(x)? };
    match (vertex, facet) {
        (Some(_), Some(_)) => Err(Failure::input("give vertex_values or facet_values, not both").into()),
        (Some(v), None) => {
            let values = vertex_values(v)?;
            if is_path {
                let path: PathBuf = x.extract()?;
                Ok(py.allow_threads(|| gmap::lower_star_file(&path, &values, o)).map_err(Failure::from)?.diagram)
            } else if let Some(input) = &complex {
                Ok(py.allow_threads(|| gmap::lower_star(input, &values, o)).map_err(Failure::from)?)
            } else {
                Err(Failure::input("vertex_values are for a simplicial complex (facets, a SimplicialComplex, a path)")
                    .into())
            }
        }
        (None, Some(f)) => {
            let values: Vec<f64> =
                f.extract().map_err(|_| Failure::input("facet_values: a sequence of numbers, one per facet"))?;
            if x.is_instance_of::<PyList>() || x.is_instance_of::<PyTuple>() {
                // values in the order the facets are given
                let facets = crate::objects::facets_from_py(x)?;
                return Ok(py
                    .allow_threads(|| gmap::persistence::given_facet_persistence(facets, &values, o))
                    .map_err(Failure::from)?);
            }
            let Some(Input::Simplicial(sc)) = complex.as_deref() else {
                return Err(Failure::input(
                    "facet_values are for a simplicial complex (facets or a SimplicialComplex; a .facets file carries them as `: VALUE`)",
                )
                .into());
            };
            if sc.facet_values().is_some() {
                return Err(Failure::input(
                    "this SimplicialComplex has facet_values already (its file's `: VALUE` or its constructor's): give one filtration",
                )
                .into());
            }
            Ok(py.allow_threads(|| gmap::persistence::facet_persistence(sc, &values, o)).map_err(Failure::from)?)
        }
        (None, None) => unreachable!("called with values"),
    }
}

/// persistence(x, *, field=2, construction="T", superlevel=False, periodic=False,
/// cycles=False, label="value", vertex_values=None, facet_values=None)
///
/// The persistence diagram of `x` over Z/field as a (k, 3) float64 numpy array of
/// (dimension, birth, death), sorted by dimension, birth, death; `inf` is the death of an
/// essential class (`-inf` with superlevel=True). `x` is a path (str or os.PathLike: a
/// grey image `.npy`, `.pgm`, `.png`, DIPHA `.complex`, a `.facets` file with a value per
/// facet, a `.gmap` with a numeric label per cell, an architectural complex `.json` with a
/// numeric label per region), a numpy grey array of 1 to 8 axes (numbers or booleans), a
/// GMap whose cells carry the numeric label `label` (an i-cell's value raised to the
/// maximum of its faces'), an ArchComplex whose regions carry it (alike, on the chain
/// complex `homology` computes for it), or a CubicalSet (0 on its cubes, 1 elsewhere).
/// `superlevel` filters from the largest value down (complexes too: a cell lowered to its
/// faces' minimum; with vertex_values a simplex takes its smallest vertex value, the upper
/// star). For images, `construction` is "T" (values on top cells, GUDHI's
/// `top_dimensional_cells`) or "V" (values on vertices, CubicalRipser's default) and
/// `periodic` identifies opposite faces; a complex refuses periodic and construction "V".
/// An image whose diagram would pass the memory limit (`set_max_memory`) is computed from
/// its lower stars, the array read in place (1 to 4 axes, neither periodic nor with
/// cycles; LimitError otherwise, or when its critical cells pass the limit).
///
/// A simplicial complex, given as a SimplicialComplex, as facets (a list or tuple of
/// sequences of vertex labels, read as facets only with vertex_values or facet_values:
/// without them a list is an image of numbers, as a numpy array is) or as the path of one (`.facets`
/// without values, `.lex`), takes `vertex_values`: a mapping {label: value} or a sequence indexed by label; each simplex
/// takes the largest value of its vertices (the lower-star filtration; every vertex needs
/// a value, other labels are ignored). Facets or a SimplicialComplex take `facet_values`
/// instead: one value per facet, in the order given for facets and in the order of its
/// `facets` for a SimplicialComplex (which lists its largest facets first), a face taking the minimum of its
/// facets' values (GUDHI's SimplexTree convention).
///
/// Pairs that live `min_persistence` or less (death − birth, GUDHI's convention) are left
/// out. A float32 array gives float32 pairs (the values are its own), anything else float64.
///
/// With cycles=True the result is `(pairs, cycles)`: `cycles[i]` represents `pairs[i]` as
/// `(cells, coefficients)` in the input's terms: for arrays and images an int64 array
/// (m, d) of cells on the doubled grid in numpy's axis order (pixel (i, j) is the cell
/// (2i+1, 2j+1) in the T-construction, the vertex (2i, 2j) in the V-construction), for
/// `.facets` a list of vertex-label tuples, for maps an int64 array of cells (the smallest
/// dart of each), for architectural complexes a list of region ids; coefficients in
/// 1..field as int64.
#[pyfunction]
#[pyo3(signature = (x, *, field = 2, construction = "T", superlevel = false, periodic = false, cycles = false, label = "value", vertex_values = None, facet_values = None, min_persistence = 0.0))]
#[allow(clippy::too_many_arguments)]
pub fn persistence<'py>(
    py: Python<'py>,
    x: &Bound<'py, PyAny>,
    field: u32,
    construction: &str,
    superlevel: bool,
    periodic: bool,
    cycles: bool,
    label: &str,
    vertex_values: Option<&Bound<'py, PyAny>>,
    facet_values: Option<&Bound<'py, PyAny>>,
    min_persistence: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let construction: Construction = construction
        .parse()
        .map_err(|_| Failure::input(format!("construction {construction:?}: expected 'T' or 'V'")))?;
    let mut o = PersistenceOptions::default();
    (o.field, o.construction, o.superlevel, o.periodic, o.cycles) = (field, construction, superlevel, periodic, cycles);
    o.label = label.to_string();
    let mut diagram = if vertex_values.is_some() || facet_values.is_some() {
        given_values_diagram(py, x, vertex_values, facet_values, &o)?
    } else if x.is_instance_of::<PyString>() || x.hasattr("__fspath__")? {
        let path: PathBuf = x.extract()?;
        py.allow_threads(|| gmap::persistence_file(&path, &o)).map_err(Failure::from)?.diagram
    } else if let Ok(m) = x.downcast::<PyGMap>() {
        let input = crate::gmapobj::read(m)?.input();
        py.allow_threads(|| gmap::persistence(&input, &o)).map_err(Failure::from)?
    } else if let Ok(c) = x.downcast::<PyCubicalSet>() {
        let input = &c.get().input;
        py.allow_threads(|| gmap::persistence(input, &o)).map_err(Failure::from)?
    } else if let Ok(img) = x.downcast::<PyImage>() {
        let input = &img.get().input;
        py.allow_threads(|| gmap::persistence(input, &o)).map_err(Failure::from)?
    } else if let Ok(sc) = x.downcast::<PySimplicialComplex>() {
        let input = &sc.get().input;
        py.allow_threads(|| gmap::persistence(input, &o)).map_err(Failure::from)?
    } else if x.is_instance_of::<PyList>() || x.is_instance_of::<PyTuple>() {
        // without values a nested list is an image of numbers (a complex would need values)
        let np = py.import("numpy")?;
        let arr = np.call_method1("asarray", (x,)).map_err(|e| {
            Failure::input(format!(
                "persistence of a list without vertex_values or facet_values: an image of numbers, and this list is not one ({e})"
            ))
        })?;
        if arr.getattr("dtype")?.getattr("kind")?.extract::<String>()? == "O" {
            return Err(Failure::input(
                "persistence of a list without vertex_values or facet_values: an image of numbers, and this list is ragged (facets need values)",
            )
            .into());
        }
        array_diagram(py, &arr, &o)?
    } else if let Ok(a) = x.downcast::<PyArchComplex>() {
        let input = &a.get().input;
        py.allow_threads(|| gmap::persistence(input, &o)).map_err(Failure::from)?
    } else if x.downcast::<numpy::PyUntypedArray>().is_ok() {
        array_diagram(py, x, &o)?
    } else {
        return Err(Failure::input(format!(
            "persistence of a {}: give a path, a numpy array, a GMap or a CubicalSet",
            x.get_type().name()?
        ))
        .into());
    };
    gmap::persistence::keep_persistent(&mut diagram, min_persistence);
    let mut pairs = pairs_array(py, &diagram)?;
    if x.downcast::<numpy::PyArrayDyn<f32>>().is_ok() {
        // float32 values give float32 pairs (every value of the diagram is one of them)
        pairs = pairs.call_method1("astype", ("float32",))?;
    }
    if !cycles {
        return Ok(pairs);
    }
    let list = PyList::empty(py);
    for c in &diagram.cycles {
        list.append(cycle_to_py(py, c)?)?;
    }
    Ok(PyTuple::new(py, [pairs, list.into_any()])?.into_any())
}
