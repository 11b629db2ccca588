//! The objects a file can hold besides a G-map — `SimplicialComplex`, `CubicalSet`,
//! `Image`, `ArchComplex` — each holding a facade [`Input`], and the bytes of a numpy
//! cubical array ([`ArrayBytes`], read in place by the facade's cubical routes).

use numpy::{PyArray1, PyArrayDescrMethods, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::IntoPyDict;

use gmap::algebra::arch::ArchComplex;
use gmap::ops::import::{CubicalSet, Image, SimplicialComplex};
use gmap::{CubesRef, Input, Sourced};

use crate::errors::{Failure, Res};
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
    /// always [`Input::Cubical`], its axes those of numpy (the array's, the file's)
    pub input: Input,
}

/// A grey-value image (`.npy`, DIPHA's `.complex`, `.pgm`, `.png`): a cubical set at a
/// level for homology, a filtration for persistence.
#[pyclass(name = "Image", module = "gmap", frozen)]
pub struct PyImage {
    /// always [`Input::Image`]
    pub input: Input,
}

/// An architectural complex (an incidence graph of regions with weights, `.json`).
#[pyclass(name = "ArchComplex", module = "gmap", frozen)]
pub struct PyArchComplex {
    /// always [`Input::Arch`]
    pub input: Input,
}

/// A held input that is not of its class's kind: a mistake of this module, reported as an
/// error rather than a panic.
fn not_held(class: &str) -> PyErr {
    Failure::input(format!("a {class} that holds no {class}")).into()
}

impl PySimplicialComplex {
    pub fn sc(&self) -> PyResult<&Sourced<SimplicialComplex>> {
        match &self.input {
            Input::Simplicial(s) => Ok(s),
            _ => Err(not_held("SimplicialComplex")),
        }
    }
}

impl PyCubicalSet {
    pub fn set(&self) -> PyResult<&CubicalSet> {
        match &self.input {
            Input::Cubical(s) => Ok(s.get()),
            _ => Err(not_held("CubicalSet")),
        }
    }
}

impl PyImage {
    pub fn image(&self) -> PyResult<&Image> {
        match &self.input {
            Input::Image(s) => Ok(s.get()),
            _ => Err(not_held("Image")),
        }
    }
}

impl PyArchComplex {
    pub fn arch(&self) -> PyResult<&ArchComplex> {
        match &self.input {
            Input::Arch(s) => Ok(s.get()),
            _ => Err(not_held("ArchComplex")),
        }
    }
}

/// What `__reduce__` gives pickle: a constructor and its arguments.
type Reduced<'py, A> = PyResult<(Bound<'py, PyAny>, A)>;

/// `SimplicialComplex`'s constructor arguments: the facets and their values, if any.
type ComplexArgs = (Vec<Vec<u64>>, Option<Vec<f64>>);

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
                    .with_facet(f)
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
        let items = facet
            .try_iter()
            .map_err(|_| Failure::input(format!("facet {f} is not a sequence of vertex labels")).with_facet(f))?;
        for l in items {
            let l = l?;
            if l.extract::<u64>().is_err() {
                return Err(Failure::input(format!(
                    "facet {f}: vertex label {} is not an int from 0 to 2^64 - 1",
                    l.repr().map(|r| r.to_string()).unwrap_or_default()
                ))
                .with_facet(f)
                .into());
            }
        }
    }
    Err(Failure::input("facets must be a sequence of sequences of non-negative ints").into())
}

/// A simplicial complex from facets, as a facade input (refused with the reader's reason:
/// a repeated vertex, no facet).
pub fn complex_of(facets: Vec<Vec<u64>>) -> Res<Input> {
    let sc = SimplicialComplex::from_facets(facets).map_err(Failure::in_memory)?;
    Ok(Input::Simplicial(Sourced::new(sc)))
}

/// A simplicial complex from facets with a value per facet (the order given), as a facade
/// input: the reader's refusals, and a count of values other than the facets'.
pub fn valued_complex_of(facets: Vec<Vec<u64>>, values: Vec<f64>) -> Res<Input> {
    if let Some(f) = values.iter().position(|v| v.is_nan()) {
        return Err(Failure::input(format!("facet_values[{f}] is NaN: a filtration value is a number")).with_facet(f));
    }
    if values.len() != facets.len() {
        return Err(Failure::input(format!(
            "{} facet_values for {} facets: give one value per facet",
            values.len(),
            facets.len()
        )));
    }
    let sc = SimplicialComplex::from_facets(facets).map_err(Failure::in_memory)?;
    // the complex lists its top-dimensional facets first: each value goes with its facet,
    // found by its place in the input (facet k is line k + 1)
    let values = sc.facet_lines().map(|line| values[line - 1]).collect();
    Ok(Input::Simplicial(Sourced::with_facet_values(sc, values).map_err(Failure::from)?))
}

#[pymethods]
impl PySimplicialComplex {
    /// SimplicialComplex(facets, facet_values=None): facets as a sequence of sequences of
    /// non-negative ints or a 2-D integer array (one facet a row); `facet_values`, one
    /// number per facet in the order given, is the complex's filtration (what a `.facets`
    /// file's `: VALUE` gives), which `gmap.persistence` reads.
    #[new]
    #[pyo3(signature = (facets, facet_values = None))]
    fn py_new(py: Python<'_>, facets: &Bound<'_, PyAny>, facet_values: Option<Vec<f64>>) -> PyResult<Self> {
        let f = facets_from_py(facets)?;
        let input = match facet_values {
            None => py.allow_threads(|| complex_of(f))?,
            Some(values) => py.allow_threads(|| valued_complex_of(f, values))?,
        };
        Ok(PySimplicialComplex { input })
    }

    /// The values given to the facets (in the order of `facets`), or None: a `.facets`
    /// file's `: VALUE`, or the constructor's `facet_values`.
    #[getter]
    fn facet_values(&self) -> PyResult<Option<Vec<f64>>> {
        Ok(self.sc()?.facet_values().map(<[f64]>::to_vec))
    }

    /// The dimension of the largest facets.
    #[getter]
    fn dim(&self) -> PyResult<usize> {
        Ok(self.sc()?.dim())
    }

    /// The facets, each a list of vertex labels as given.
    #[getter]
    fn facets(&self) -> PyResult<Vec<Vec<u64>>> {
        Ok(self.sc()?.facets().map(<[u64]>::to_vec).collect())
    }

    /// The number of facets.
    fn __len__(&self) -> PyResult<usize> {
        Ok(self.sc()?.total_facet_count())
    }

    fn __repr__(&self) -> PyResult<String> {
        let sc = self.sc()?;
        Ok(format!("<gmap.SimplicialComplex dim={} facets={}>", sc.dim(), sc.total_facet_count()))
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> Reduced<'py, ComplexArgs> {
        Ok((slf.get_type().into_any(), (slf.get().facets()?, slf.get().facet_values()?)))
    }

    /// Whether every facet has the top dimension.
    fn is_pure(&self) -> PyResult<bool> {
        Ok(self.sc()?.is_pure())
    }

    /// The G-map of the facets (a pure pseudo-manifold: every ridge in at most two facets),
    /// one dart per flag; PreconditionError otherwise.
    fn to_gmap(&self, py: Python<'_>) -> PyResult<PyGMap> {
        let sc = self.sc()?;
        let m = py.allow_threads(|| sc.to_gmap()).map_err(Failure::from)?;
        Ok(PyGMap::from_dense(&m))
    }

    /// save(path, lossy=False): writes the complex by extension, as `gmap convert` does:
    /// `.facets` (its facets, one a line), the map formats through its G-map (`.gmap`,
    /// `.moka`, `.off`, `.vtk`), its face poset as `.json`, `.dot`, `.graphml`.
    #[pyo3(signature = (path, lossy = false))]
    fn save(&self, py: Python<'_>, path: std::path::PathBuf, lossy: bool) -> PyResult<()> {
        crate::save::save_input(py, &self.input, &path, lossy)
    }
}

/// The bytes of a numpy cubical array, one per cube (non-zero: the cube is present), with
/// the array's shape and strides in elements: the array itself, read in place, when it is
/// C- or Fortran-contiguous with one-byte elements (bool, uint8, int8); else numpy's
/// `a != 0` of it (any other dtype of numbers, a strided view), made once.
pub struct ArrayBytes<'py> {
    view: numpy::PyReadonlyArrayDyn<'py, u8>,
    shape: Vec<usize>,
    strides: Vec<isize>,
}

impl ArrayBytes<'_> {
    /// The cubes, as the facade borrows them (its refusals: the axes, an empty axis, the
    /// largest box, a layout neither C nor Fortran).
    pub fn cubes(&self) -> PyResult<CubesRef<'_>> {
        let bytes = self.view.as_slice().map_err(|e| Failure::input(e.to_string()))?;
        Ok(CubesRef::new(bytes, &self.shape, &self.strides).map_err(Failure::from)?)
    }
}

/// Refuses what a numpy array given as an input cannot be: a masked array (its mask would
/// be ignored: refused, the caller chooses `a.filled(0)` or `a.data`), a dtype the `.npy`
/// reader does not read (float16, complex, strings, objects: the reader's own rule and
/// message).
pub fn check_array(a: &Bound<'_, PyAny>) -> PyResult<()> {
    let masked = a.py().import("numpy.ma")?.getattr("MaskedArray")?;
    if a.is_instance(&masked)? {
        return Err(Failure::input(
            "a numpy masked array is refused (its mask would be ignored): give a.filled(0) to leave the masked cubes out, or a.data to take every value",
        )
        .into());
    }
    if let Ok(arr) = a.downcast::<numpy::PyUntypedArray>() {
        // numpy's `dtype.str`, the `.npy` header's descr ('<f2'), not its name
        let descr: String = arr.dtype().getattr("str")?.extract()?;
        gmap::ops::import::image::check_dtype(&descr).map_err(Failure::in_memory)?;
    }
    Ok(())
}

/// The bytes of the cubical array `a` ([`ArrayBytes`]); anything but a numpy array of
/// numbers or booleans is refused.
pub fn array_bytes<'py>(a: &Bound<'py, PyAny>) -> PyResult<ArrayBytes<'py>> {
    let py = a.py();
    let arr = a.downcast::<numpy::PyUntypedArray>().map_err(|_| Failure::input("a cubical set is a numpy array"))?;
    check_array(a)?;
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
        // the box refused, or its byte per cube under the memory policy, before numpy
        // allocates it
        CubesRef::check_conversion(arr.shape()).map_err(Failure::from)?;
        let np = py.import("numpy")?;
        np.call_method1("ascontiguousarray", (np.call_method1("not_equal", (a, 0))?,))?
            .call_method1("view", ("uint8",))?
    };
    let view = bytes.downcast::<numpy::PyArrayDyn<u8>>()?.readonly();
    let shape = view.shape().to_vec();
    // one-byte elements: the strides in bytes are the strides in elements
    let strides = view.strides().to_vec();
    Ok(ArrayBytes { view, shape, strides })
}

#[pymethods]
impl PyCubicalSet {
    /// CubicalSet(array, min=None): the cubes where the array (1 to 8 dimensions) is
    /// nonzero; array[i0, i1, …] is the cube with minimal vertex min + (i0, i1, …) (min: zeros
    /// by default). The set is a copy, its axes those of the array.
    #[new]
    #[pyo3(signature = (array, min = None))]
    fn py_new(py: Python<'_>, array: &Bound<'_, PyAny>, min: Option<Vec<i64>>) -> PyResult<Self> {
        let bytes = array_bytes(array)?;
        let cubes = bytes.cubes()?;
        let min = min.unwrap_or_default();
        let input = py.allow_threads(|| cubes.to_input(&min)).map_err(Failure::from)?;
        Ok(PyCubicalSet { input })
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> Reduced<'py, (Bound<'py, PyAny>, Vec<i64>)> {
        let py = slf.py();
        Ok((slf.get_type().into_any(), (slf.get().array(py)?, slf.get().min()?)))
    }

    /// The dimension d (the array's number of axes).
    #[getter]
    fn dim(&self) -> PyResult<usize> {
        Ok(self.set()?.dim())
    }

    /// The number of cubes in the set.
    fn __len__(&self) -> PyResult<usize> {
        Ok(self.set()?.cube_count())
    }

    fn __repr__(&self) -> PyResult<String> {
        let s = self.set()?;
        Ok(format!("<gmap.CubicalSet dim={} shape={:?} cubes={}>", s.dim(), s.shape(), s.cube_count()))
    }

    /// The box's shape in cubes per axis.
    #[getter]
    fn shape(&self) -> PyResult<Vec<usize>> {
        Ok(self.set()?.shape().to_vec())
    }

    /// The box's minimal vertex.
    #[getter]
    fn min(&self) -> PyResult<Vec<i64>> {
        Ok(self.set()?.min().to_vec())
    }

    /// The set as a bool array of the box's shape: array[i0, …] is the cube with minimal
    /// vertex min + (i0, …). Refused for a cell complex with lower cells on no cube.
    #[getter]
    fn array<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let set = self.set()?;
        set.require_full("an array of cubes").map_err(Failure::in_memory)?;
        // the set's bytes have axis 0 fastest: Fortran order
        let flat = PyArray1::from_slice(py, set.bits());
        let order = [("order", "F")].into_py_dict(py)?;
        let shaped = flat.call_method("reshape", (set.shape().to_vec(),), Some(&order))?;
        shaped.call_method1("astype", ("bool",))
    }

    /// The G-map of the set: every cube one d-cell, sewn to its neighbours (periodic: the
    /// box's opposite faces identified). Refused, naming the cell, when the cubes around a
    /// cell share no facet there (two squares at a corner): the map would be another space.
    #[pyo3(signature = (periodic = false))]
    fn to_gmap(&self, py: Python<'_>, periodic: bool) -> PyResult<PyGMap> {
        let set = self.set()?;
        let m = py.allow_threads(|| set.gmap_of_union(periodic)).map_err(Failure::in_memory)?;
        Ok(PyGMap::from_dense(&m))
    }

    /// save(path, lossy=False): writes the set by extension, as `gmap convert` does: a
    /// CHomP `.cub` (one cube a line), `.vtk` voxels, the G-map of its cubes (`.gmap`,
    /// `.moka`, …), its incidence graph (`.json`, `.dot`, `.graphml`).
    #[pyo3(signature = (path, lossy = false))]
    fn save(&self, py: Python<'_>, path: std::path::PathBuf, lossy: bool) -> PyResult<()> {
        crate::save::save_input(py, &self.input, &path, lossy)
    }
}

#[pymethods]
impl PyImage {
    /// The number of axes.
    #[getter]
    fn dim(&self) -> PyResult<usize> {
        Ok(self.image()?.dim())
    }

    /// The sizes along the axes, axis 0 first (numpy's `shape`).
    #[getter]
    fn shape(&self) -> PyResult<Vec<usize>> {
        Ok(self.image()?.shape().to_vec())
    }

    /// The number of values.
    fn __len__(&self) -> PyResult<usize> {
        Ok(self.image()?.len())
    }

    fn __repr__(&self) -> PyResult<String> {
        let img = self.image()?;
        Ok(format!("<gmap.Image dim={} shape={:?}>", img.dim(), img.shape()))
    }

    /// save(path, lossy=False): writes the image as it is, `.npy` or DIPHA's `.complex`
    /// (as `gmap convert` does).
    #[pyo3(signature = (path, lossy = false))]
    fn save(&self, py: Python<'_>, path: std::path::PathBuf, lossy: bool) -> PyResult<()> {
        crate::save::save_input(py, &self.input, &path, lossy)
    }
}

#[pymethods]
impl PyArchComplex {
    /// ArchComplex(text): an architectural complex from the text of a `.json` file.
    #[new]
    fn py_new(text: &str) -> PyResult<Self> {
        let input = gmap::formats::parse_text("json", text).map_err(Failure::from)?;
        Ok(PyArchComplex { input })
    }

    /// The dimension.
    #[getter]
    fn dim(&self) -> PyResult<usize> {
        Ok(self.arch()?.dim())
    }

    /// The number of regions.
    fn __len__(&self) -> PyResult<usize> {
        Ok(self.arch()?.regions().len())
    }

    fn __repr__(&self) -> PyResult<String> {
        let x = self.arch()?;
        Ok(format!("<gmap.ArchComplex dim={} regions={}>", x.dim(), x.regions().len()))
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (String,))> {
        Ok((slf.get_type().into_any(), (slf.get().to_json()?,)))
    }

    /// The `.json` text of the complex.
    fn to_json(&self) -> PyResult<String> {
        Ok(gmap::formats::to_text(&self.input, "json").map_err(Failure::from)?)
    }

    /// save(path, lossy=False): writes the complex by extension (`.json`, and what
    /// `gmap convert` writes from one).
    #[pyo3(signature = (path, lossy = false))]
    fn save(&self, py: Python<'_>, path: std::path::PathBuf, lossy: bool) -> PyResult<()> {
        crate::save::save_input(py, &self.input, &path, lossy)
    }
}
