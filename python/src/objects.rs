//! The objects a file can hold besides a G-map — `SimplicialComplex`, `CubicalSet`,
//! `ArchComplex` — and reading and writing files by extension (the command line's
//! `load`, docs/FORMATS.md §2).

use numpy::{PyArray1, PyArrayDescrMethods, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;

use gmap::{Input, Sourced};
use gmap_homology::arch::ArchComplex;
use gmap_ops::import::{CubicalSet, SimplicialComplex};

use crate::errors::{Failure, Kind, Res};
use crate::gmapobj::PyGMap;

/// A finite simplicial complex given by its facets (lists of non-negative integer vertex
/// labels); any complex: mixed dimensions, ridges in any number of facets.
#[pyclass(name = "SimplicialComplex", module = "gmap", frozen)]
pub struct PySimplicialComplex {
    /// always [`Input::Simplicial`]
    pub input: Input,
}

/// A full cubical set: the unit cubes of a box that belong to the set.
#[pyclass(name = "CubicalSet", module = "gmap", frozen)]
pub struct PyCubicalSet {
    /// always [`Input::Cubical`]
    pub input: Input,
    /// the numpy axes are those of the set reversed (it came from a C-ordered array)
    pub reversed: bool,
}

/// An architectural complex (an incidence graph of regions with weights, `.json`).
#[pyclass(name = "ArchComplex", module = "gmap", frozen)]
pub struct PyArchComplex {
    /// always [`Input::Arch`]
    pub input: Input,
}

impl PySimplicialComplex {
    pub fn sc(&self) -> &SimplicialComplex {
        match &self.input {
            Input::Simplicial(s) => s.get(),
            _ => unreachable!("a SimplicialComplex holds a simplicial input"),
        }
    }
}

impl PyCubicalSet {
    pub fn set(&self) -> &CubicalSet {
        match &self.input {
            Input::Cubical(s) => s.get(),
            _ => unreachable!("a CubicalSet holds a cubical input"),
        }
    }
}

impl PyArchComplex {
    pub fn arch(&self) -> &ArchComplex {
        match &self.input {
            Input::Arch(s) => s.get(),
            _ => unreachable!("an ArchComplex holds an architectural complex"),
        }
    }
}

/// What `__reduce__` gives pickle: a constructor and its arguments.
type Reduced<'py, A> = PyResult<(Bound<'py, PyAny>, A)>;

/// Facets from a Python sequence of sequences of ints or a 2-D integer array.
pub fn facets_from_py(x: &Bound<'_, PyAny>) -> PyResult<Vec<Vec<u64>>> {
    if let Ok(a) = x.downcast::<numpy::PyArray2<i64>>() {
        let r = a.readonly();
        let v = r.as_array();
        let mut out = Vec::with_capacity(v.nrows());
        for (f, row) in v.rows().into_iter().enumerate() {
            let mut facet = Vec::with_capacity(row.len());
            for &l in row {
                if l < 0 {
                    return Err(Failure::input(format!(
                        "facet {f}: vertex label {l} is negative (labels are 0..2^64)"
                    ))
                    .into());
                }
                facet.push(l as u64);
            }
            out.push(facet);
        }
        return Ok(out);
    }
    if let Ok(a) = x.downcast::<numpy::PyArray2<u64>>() {
        let r = a.readonly();
        return Ok(r.as_array().rows().into_iter().map(|row| row.to_vec()).collect());
    }
    if let Ok(v) = x.extract::<Vec<Vec<u64>>>() {
        return Ok(v);
    }
    // say which facet and label is wrong
    let seq =
        x.try_iter().map_err(|_| Failure::input("facets must be a sequence of sequences of non-negative ints"))?;
    for (f, facet) in seq.enumerate() {
        let facet = facet?;
        let items =
            facet.try_iter().map_err(|_| Failure::input(format!("facet {f} is not a sequence of vertex labels")))?;
        for l in items {
            let l = l?;
            if l.extract::<u64>().is_err() {
                return Err(Failure::input(format!(
                    "facet {f}: vertex label {} is not an int from 0 to 2^64 - 1",
                    l.repr().map(|r| r.to_string()).unwrap_or_default()
                ))
                .into());
            }
        }
    }
    Err(Failure::input("facets must be a sequence of sequences of non-negative ints").into())
}

/// A simplicial complex from facets, with the reader's messages.
pub fn complex_of(facets: Vec<Vec<u64>>) -> Res<SimplicialComplex> {
    Ok(SimplicialComplex::from_facets(facets)?)
}

#[pymethods]
impl PySimplicialComplex {
    /// SimplicialComplex(facets): facets as a sequence of sequences of non-negative ints or
    /// a 2-D integer array (one facet a row).
    #[new]
    fn py_new(py: Python<'_>, facets: &Bound<'_, PyAny>) -> PyResult<Self> {
        let f = facets_from_py(facets)?;
        let sc = py.allow_threads(|| complex_of(f))?;
        Ok(PySimplicialComplex { input: Input::Simplicial(Sourced::new(sc)) })
    }

    /// The dimension of the largest facets.
    #[getter]
    fn dim(&self) -> usize {
        self.sc().dim()
    }

    /// The facets, each a list of vertex labels as given.
    #[getter]
    fn facets(&self) -> Vec<Vec<u64>> {
        self.sc().facets().map(<[u64]>::to_vec).collect()
    }

    /// The number of facets.
    fn __len__(&self) -> usize {
        self.sc().total_facet_count()
    }

    fn __repr__(&self) -> String {
        format!("<gmap.SimplicialComplex dim={} facets={}>", self.sc().dim(), self.sc().total_facet_count())
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> Reduced<'py, (Vec<Vec<u64>>,)> {
        Ok((slf.get_type().into_any(), (slf.get().facets(),)))
    }

    /// Whether every facet has the top dimension.
    fn is_pure(&self) -> bool {
        self.sc().is_pure()
    }

    /// The G-map of the facets (a pure pseudo-manifold: every ridge in at most two facets),
    /// one dart per flag; PreconditionError otherwise.
    fn to_gmap(&self, py: Python<'_>) -> PyResult<PyGMap> {
        let m = py.allow_threads(|| match &self.input {
            Input::Simplicial(s) => s.to_gmap(),
            _ => unreachable!("a SimplicialComplex holds a simplicial input"),
        });
        Ok(PyGMap::from_dense(&m.map_err(Failure::from)?))
    }

    /// Writes the complex: `.facets` (its facets, one a line); the other formats through
    /// its G-map (`.gmap`, `.moka`, `.off`, `.vtk`, `.dot`, as `gmap convert`).
    fn save(&self, py: Python<'_>, path: std::path::PathBuf) -> PyResult<()> {
        if gmap::input::extension(&path) != "facets" {
            let o = gmap::SaveOptions::default();
            return py.allow_threads(|| gmap::save(&self.input, &path, &o)).map_err(|e| Failure::from(e).into());
        }
        let mut s = String::new();
        for f in self.sc().facets() {
            let words: Vec<String> = f.iter().map(u64::to_string).collect();
            s.push_str(&words.join(" "));
            s.push('\n');
        }
        gmap_core::io::write_atomic(&path, s.as_bytes())
            .map_err(|e| Failure::new(Kind::Io, format!("{}: {e}", path.display())))?;
        Ok(())
    }
}

impl PyCubicalSet {
    /// A set from any numpy array (nonzero = present), copied once; the axes are the
    /// array's, the minimal vertex `min` (numpy axis order; zeros by default).
    pub fn from_array(a: &Bound<'_, PyAny>, min: Option<Vec<i64>>) -> PyResult<Self> {
        let (shape, view, reversed) = array_bits(a)?;
        check_complex_memory(&shape)?;
        let mut min = min.unwrap_or_else(|| vec![0; shape.len()]);
        if min.len() != shape.len() {
            return Err(Failure::input(format!("min has {} coordinates for {} axes", min.len(), shape.len())).into());
        }
        if reversed {
            min.reverse();
        }
        let bits = view.as_slice().map_err(|e| Failure::input(e.to_string()))?.to_vec();
        let set = CubicalSet::new(min, shape, bits).map_err(Failure::from)?;
        Ok(PyCubicalSet { input: Input::Cubical(Sourced::new(set)), reversed })
    }
}

/// Refuses a box whose cubical complex (the general route's) is over the memory budget.
pub fn check_complex_memory(shape: &[usize]) -> Res<()> {
    gmap_core::resources::check_memory(
        "the cubical complex of the array",
        gmap_core::resources::cubical_set_estimate(shape),
    )
    .map_err(Failure::from)
}

/// The bytes of a cubical array: (shape with axis 0 fastest, the array as bytes, whether the
/// numpy axes are reversed). A C- or Fortran-contiguous array of one-byte elements (bool,
/// uint8, int8) is read in place, through a uint8 view; anything else is converted by
/// numpy (`a != 0`) first.
pub fn array_bits<'py>(a: &Bound<'py, PyAny>) -> PyResult<(Vec<usize>, numpy::PyReadonlyArrayDyn<'py, u8>, bool)> {
    let py = a.py();
    let arr = a.downcast::<numpy::PyUntypedArray>().map_err(|_| Failure::input("a cubical set is a numpy array"))?;
    let nd = arr.ndim();
    if !(1..=8).contains(&nd) {
        return Err(Failure::input(format!("a cubical array has 1 to 8 dimensions, not {nd}")).into());
    }
    let np_shape = arr.shape().to_vec();
    if np_shape.contains(&0) {
        return Err(Failure::input(format!("a cubical array of shape {np_shape:?}: every axis needs a cube")).into());
    }
    // the box under the memory policy before numpy or we allocate anything for it
    let volume = np_shape.iter().try_fold(1u64, |v, &s| v.checked_mul(s as u64));
    if volume.is_none_or(|v| v > gmap_ops::import::cubical::MAX_BOX_CUBES) {
        return Err(Failure::new(
            Kind::Limit,
            format!(
                "a cubical array of shape {np_shape:?} has more than {} cubes, the largest box accepted",
                gmap_ops::import::cubical::MAX_BOX_CUBES
            ),
        )
        .into());
    }
    let kind = arr.dtype().kind();
    let one_byte = arr.dtype().itemsize() == 1 && matches!(kind, b'b' | b'u' | b'i');
    let contiguous = arr.is_c_contiguous() || arr.is_fortran_contiguous();
    let bytes: Bound<'py, PyAny> = if one_byte && contiguous {
        a.call_method1("view", ("uint8",))?
    } else {
        if !matches!(kind, b'b' | b'u' | b'i' | b'f') {
            return Err(Failure::input(format!(
                "a cubical array holds numbers or booleans, not dtype {}",
                arr.dtype().str()?
            ))
            .into());
        }
        // the byte per cube numpy makes
        gmap_core::resources::check_memory("the array's cubes as bytes", volume).map_err(Failure::from)?;
        let np = py.import("numpy")?;
        np.call_method1("ascontiguousarray", (np.call_method1("not_equal", (a, 0))?,))?
            .call_method1("view", ("uint8",))?
    };
    let view = bytes.downcast::<numpy::PyArrayDyn<u8>>()?.readonly();
    let c_order = view.is_c_contiguous();
    let (shape, reversed) =
        if c_order && nd > 1 { (np_shape.iter().rev().copied().collect(), true) } else { (np_shape, false) };
    Ok((shape, view, reversed))
}

#[pymethods]
impl PyCubicalSet {
    /// CubicalSet(array, min=None): the cubes where the array (1 to 8 dimensions) is
    /// nonzero; array[i0, i1, …] is the cube with minimal vertex min + (i0, i1, …) (min: zeros
    /// by default).
    #[new]
    #[pyo3(signature = (array, min = None))]
    fn py_new(array: &Bound<'_, PyAny>, min: Option<Vec<i64>>) -> PyResult<Self> {
        PyCubicalSet::from_array(array, min)
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> Reduced<'py, (Bound<'py, PyAny>, Vec<i64>)> {
        let py = slf.py();
        Ok((slf.get_type().into_any(), (slf.get().array(py)?, slf.get().min())))
    }

    /// The dimension d (the array's number of axes).
    #[getter]
    fn dim(&self) -> usize {
        self.set().dim()
    }

    /// The number of cubes in the set.
    fn __len__(&self) -> usize {
        self.set().cube_count()
    }

    fn __repr__(&self) -> String {
        format!("<gmap.CubicalSet dim={} shape={:?} cubes={}>", self.dim(), self.np_shape(), self.__len__())
    }

    /// The box's shape in cubes per axis (numpy axis order).
    #[getter]
    fn shape(&self) -> Vec<usize> {
        self.np_shape()
    }

    /// The box's minimal vertex (numpy axis order).
    #[getter]
    fn min(&self) -> Vec<i64> {
        let mut m = self.set().min().to_vec();
        if self.reversed {
            m.reverse();
        }
        m
    }

    /// The set as a bool array of the box's shape: array[i0, …] is the cube with minimal
    /// vertex min + (i0, …). Refused for a cell complex with lower cells on no cube.
    #[getter]
    fn array<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.set().require_full("an array of cubes").map_err(|e| Failure::input(e.to_string()))?;
        let flat = PyArray1::from_slice(py, self.set().bits());
        let order = if self.reversed { "C" } else { "F" };
        let shaped = flat.call_method("reshape", (self.np_shape(),), Some(&[("order", order)].into_py_dict(py)?))?;
        shaped.call_method1("astype", ("bool",))
    }

    /// The G-map of the set: every cube one d-cell, sewn to its neighbours (periodic: the
    /// box's opposite faces identified). Refused, naming the cell, when the cubes around a
    /// cell share no facet there (two squares at a corner): the map would be another space.
    #[pyo3(signature = (periodic = false))]
    fn to_gmap(&self, py: Python<'_>, periodic: bool) -> PyResult<PyGMap> {
        let set = self.set();
        let m = py.allow_threads(|| set.gmap_of_union(periodic)).map_err(Failure::from)?;
        Ok(PyGMap::from_dense(&m))
    }

    /// Writes the set as a CHomP `.cub` file (one cube a line, numpy axis order).
    fn save(&self, path: std::path::PathBuf) -> PyResult<()> {
        let ext = gmap::input::extension(&path);
        if ext != "cub" {
            return Err(
                Failure::input(format!("{}: a cubical set is written as .cub, not '.{ext}'", path.display())).into()
            );
        }
        let set = self.set();
        set.require_full("a .cub of cubes").map_err(|e| Failure::input(e.to_string()))?;
        let mut s = format!("dimension {}\n", set.dim());
        for mut c in set.cubes() {
            if self.reversed {
                c.reverse();
            }
            let w: Vec<String> = c.iter().map(i64::to_string).collect();
            s.push('(');
            s.push_str(&w.join(","));
            s.push_str(")\n");
        }
        gmap_core::io::write_atomic(&path, s.as_bytes())
            .map_err(|e| Failure::new(Kind::Io, format!("{}: {e}", path.display())))?;
        Ok(())
    }
}

impl PyCubicalSet {
    fn np_shape(&self) -> Vec<usize> {
        let mut s = self.set().shape().to_vec();
        if self.reversed {
            s.reverse();
        }
        s
    }
}

use pyo3::types::IntoPyDict;

#[pymethods]
impl PyArchComplex {
    /// ArchComplex(text): an architectural complex from the text of a `.json` file.
    #[new]
    fn py_new(text: &str) -> PyResult<Self> {
        let x = gmap_homology::json::read_json(text).map_err(Failure::from)?;
        Ok(PyArchComplex { input: Input::Arch(Sourced::new(x)) })
    }

    /// The dimension.
    #[getter]
    fn dim(&self) -> usize {
        self.arch().dim()
    }

    /// The number of regions.
    fn __len__(&self) -> usize {
        self.arch().regions().len()
    }

    fn __repr__(&self) -> String {
        format!("<gmap.ArchComplex dim={} regions={}>", self.arch().dim(), self.arch().regions().len())
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (String,))> {
        Ok((slf.get_type().into_any(), (slf.get().to_json(),)))
    }

    /// The `.json` text of the complex.
    fn to_json(&self) -> String {
        gmap_homology::json::write_json(self.arch())
    }

    /// Writes the complex by extension (`.json`, and what `gmap convert` writes from one).
    fn save(&self, py: Python<'_>, path: std::path::PathBuf) -> PyResult<()> {
        let o = gmap::SaveOptions::default();
        py.allow_threads(|| gmap::save(&self.input, &path, &o)).map_err(|e| Failure::from(e).into())
    }
}
