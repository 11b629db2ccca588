//! `gmap._gmap`: the compiled half of the `gmap` Python package.
//!
//! Python-facing types and functions only: every computation and decision (routes, checks
//! of options, memory estimates, formats, writers) is a call of the facade, the `gmap`
//! crate, run with the GIL released. Modules:
//! * [`errors`]: the exception classes and the mapping of the facade's errors;
//! * [`objects`]: `SimplicialComplex`, `CubicalSet`, `Image`, `ArchComplex` (each holds a
//!   facade `gmap::Input`), and the bytes of a numpy cubical array;
//! * [`save`]: `obj.save(path, lossy=False)` of every class, through `gmap::save`;
//! * [`gmapobj`]: `GMap`, the editable map, with CGAL's Euler operators;
//! * [`persist`]: `gmap.persistence` (diagrams of paths, numpy grey arrays, objects);
//! * [`page`]: the page of `gmap view` for `obj.view()` and a notebook's `_repr_html_`.

use std::path::PathBuf;
use std::sync::Arc;

use numpy::{PyArrayDescrMethods, ToPyArray};
use pyo3::prelude::*;
use pyo3::sync::GILOnceCell;
use pyo3::types::{PyList, PyString, PyTuple};

mod arch;
mod curves;
mod errors;
mod gmapobj;
mod gudhi;
mod objects;
mod page;
mod persist;
mod save;

use errors::Failure;
use gmap::{CellName, Chain, HomologyOptions, Input, Method, NamedGenerator, Report, Via};
use gmapobj::PyGMap;
use objects::{PyArchComplex, PyCubicalSet, PyImage, PySimplicialComplex};

/// One summand's representative cycle, in the input's own terms. Its arrays are made when
/// first read (a large image has hundreds of thousands of generators: their cells stay in
/// the result, compact, until asked for).
#[pyclass(name = "Generator", module = "gmap", frozen)]
pub struct PyGenerator {
    /// the result the generator belongs to, and its place there
    report: Arc<Report>,
    index: usize,
    /// `order` as a Python int
    order: PyObject,
    /// `(cells, extents, coefficients)`, once read
    arrays: GILOnceCell<(PyObject, PyObject, PyObject)>,
}

impl PyGenerator {
    /// The generator in its report (made from there: a `None` would be a mistake of this
    /// module, reported as an error rather than a panic).
    fn generator(&self) -> PyResult<&NamedGenerator> {
        self.report
            .generators
            .as_deref()
            .and_then(|g| g.get(self.index))
            .ok_or_else(|| Failure::input(format!("generator {} is not in its result", self.index)).into())
    }

    fn arrays(&self, py: Python<'_>) -> PyResult<&(PyObject, PyObject, PyObject)> {
        self.arrays.get_or_try_init(py, || chain_arrays(py, &self.generator()?.chain))
    }
}

#[pymethods]
impl PyGenerator {
    /// the dimension k of the homology group
    #[getter]
    fn dim(&self) -> PyResult<usize> {
        Ok(self.generator()?.dim)
    }

    /// 0 for a free summand (Z, or the field), t for Z/t (an exact int)
    #[getter]
    fn order(&self, py: Python<'_>) -> PyObject {
        self.order.clone_ref(py)
    }

    /// the cells of the chain: tuples of vertex labels (simplicial complexes), a uint32
    /// array of darts (G-maps), an int64 array (m, d) of cubes' minimal vertices (cubical
    /// sets), a uint64 array of region ids (architectural complexes)
    #[getter]
    fn cells(&self, py: Python<'_>) -> PyResult<PyObject> {
        Ok(self.arrays(py)?.0.clone_ref(py))
    }

    /// for cubical sets: a uint8 array (m, d), 1 along the axes a cell spans; else None
    #[getter]
    fn extents(&self, py: Python<'_>) -> PyResult<PyObject> {
        Ok(self.arrays(py)?.1.clone_ref(py))
    }

    /// the coefficient of each cell, an int64 array
    #[getter]
    fn coefficients(&self, py: Python<'_>) -> PyResult<PyObject> {
        Ok(self.arrays(py)?.2.clone_ref(py))
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let g = self.generator()?;
        Ok(format!("<gmap.Generator dim={} order={} cells={}>", g.dim, self.order.bind(py), g.chain.len()))
    }
}

/// The homology groups of an input: H_k = Z^betti[k] + Z/t for t in torsion[k].
#[pyclass(name = "Homology", module = "gmap", frozen)]
pub struct PyHomology {
    report: Arc<Report>,
    generators: Option<Py<PyList>>,
}

fn natural_to_py(py: Python<'_>, n: &gmap::algebra::Natural) -> PyResult<PyObject> {
    Ok(match n.to_u64() {
        Some(v) => v.into_pyobject(py)?.into_any().unbind(),
        None => n.to_biguint().into_pyobject(py)?.into_any().unbind(),
    })
}

/// A generator per summand of the report, each reading its cells from the shared report.
fn generators_to_py(py: Python<'_>, r: &Arc<Report>) -> PyResult<Option<Py<PyList>>> {
    let Some(gens) = &r.generators else { return Ok(None) };
    let mut list = Vec::with_capacity(gens.len());
    for (index, g) in gens.iter().enumerate() {
        let x =
            PyGenerator { report: r.clone(), index, order: natural_to_py(py, &g.order)?, arrays: GILOnceCell::new() };
        list.push(Py::new(py, x)?);
    }
    Ok(Some(PyList::new(py, list)?.unbind()))
}

/// The arrays of a chain: `(cells, extents, coefficients)` as [`PyGenerator`] gives them.
fn chain_arrays(py: Python<'_>, chain: &Chain) -> PyResult<(PyObject, PyObject, PyObject)> {
    // each array copied into numpy's own memory in its shape at once: one Python object per
    // array (handing a Vec over adds a second, its owner; a reshape a third), which is most
    // of the cost when a million generators are read
    let coefficients = chain.coefficients().to_pyarray(py).into_any().unbind();
    let n = chain.len();
    let shaped = |e: numpy::ndarray::ShapeError| Failure::input(e.to_string());
    let cubes = |lo: Vec<i64>, ex: Vec<u8>, d: usize| -> PyResult<(PyObject, PyObject)> {
        Ok((
            numpy::ndarray::ArrayView2::from_shape((n, d), &lo[..]).map_err(shaped)?.to_pyarray(py).into_any().unbind(),
            numpy::ndarray::ArrayView2::from_shape((n, d), &ex[..]).map_err(shaped)?.to_pyarray(py).into_any().unbind(),
        ))
    };
    if let Chain::Grid { cells, grid } = chain {
        let d = grid.dim();
        let (mut lo, mut ex) = (Vec::with_capacity(n * d), Vec::with_capacity(n * d));
        for &(p, _) in cells {
            let (min, extent) = grid.cube(p);
            lo.extend_from_slice(&min);
            ex.extend_from_slice(&extent);
        }
        let (cells, extents) = cubes(lo, ex, d)?;
        return Ok((cells, extents, coefficients));
    }
    let (cells, extents): (PyObject, PyObject) = match chain.first().map(|(c, _)| c) {
        Some(CellName::Cube { min, .. }) => {
            let d = min.len();
            let (mut lo, mut ex) = (Vec::with_capacity(n * d), Vec::with_capacity(n * d));
            for (c, _) in chain.iter() {
                if let CellName::Cube { min, extent } = c {
                    lo.extend_from_slice(&min);
                    ex.extend_from_slice(&extent);
                }
            }
            cubes(lo, ex, d)?
        }
        Some(CellName::Dart { .. }) => {
            let darts: Vec<u32> =
                chain.iter().map(|(c, _)| if let CellName::Dart { dart, .. } = c { dart } else { 0 }).collect();
            (darts.to_pyarray(py).into_any().unbind(), py.None())
        }
        Some(CellName::Region(_)) => {
            let ids: Vec<u64> = chain.iter().map(|(c, _)| if let CellName::Region(r) = c { r } else { 0 }).collect();
            (ids.to_pyarray(py).into_any().unbind(), py.None())
        }
        // regions the file names: their string id (else their name label, else their number)
        Some(CellName::NamedRegion { .. }) => {
            let l = PyList::empty(py);
            for (c, _) in chain.iter() {
                match c {
                    CellName::NamedRegion { key: Some(k), .. } => l.append(k)?,
                    CellName::NamedRegion { name: Some(n), .. } => l.append(n)?,
                    CellName::NamedRegion { id, .. } | CellName::Region(id) => l.append(id.to_string())?,
                    _ => {}
                }
            }
            (l.into_any().unbind(), py.None())
        }
        _ => {
            let l = PyList::empty(py);
            for (c, _) in chain.iter() {
                if let CellName::Simplex(v) = c {
                    l.append(PyTuple::new(py, v)?)?;
                }
            }
            (l.into_any().unbind(), py.None())
        }
    };
    Ok((cells, extents, coefficients))
}

#[pymethods]
impl PyHomology {
    /// The Betti numbers b_0..b_n (ranks over Z, dimensions over Z/p).
    #[getter]
    fn betti(&self) -> Vec<usize> {
        self.report.groups.betti.clone()
    }

    /// The torsion coefficients of each H_k (invariant factors, each dividing the next), as
    /// Python ints, exact at any size; empty lists over a field.
    #[getter]
    fn torsion(&self, py: Python<'_>) -> PyResult<Vec<Vec<PyObject>>> {
        self.report.groups.torsion.iter().map(|t| t.iter().map(|n| natural_to_py(py, n)).collect()).collect()
    }

    /// The dimension of the input.
    #[getter]
    fn dimension(&self) -> usize {
        self.report.dimension
    }

    /// 'cellular' or 'simplicial'.
    #[getter]
    fn method(&self) -> &'static str {
        self.report.method.name()
    }

    /// For a simplicial complex: 'direct' (every face a cell) or 'gmap' (through its
    /// G-map); None for other inputs.
    #[getter]
    fn route(&self) -> Option<&'static str> {
        self.report.route.map(Via::name)
    }

    /// 'Z' or 'Z/p'.
    #[getter]
    fn coefficients(&self) -> String {
        self.report.groups.coefficients.to_string()
    }

    /// The alternating sum of the Betti numbers.
    #[getter]
    fn euler_characteristic(&self) -> i64 {
        self.report.groups.euler_characteristic()
    }

    /// A list of Generator (one per summand: the free ones, then one per torsion
    /// coefficient, dimension by dimension) when asked with generators=True, else None.
    #[getter]
    fn generators(&self, py: Python<'_>) -> Option<Py<PyList>> {
        self.generators.as_ref().map(|g| g.clone_ref(py))
    }

    /// The groups as text: '(Z, 0, Z)'.
    fn __str__(&self) -> String {
        self.report.groups.to_string()
    }

    fn __repr__(&self) -> String {
        format!("<gmap.Homology {} over {}>", self.report.groups, self.report.groups.coefficients)
    }

    /// The text of H_k: 'Z^2 + Z/2'.
    fn group(&self, k: usize) -> String {
        self.report.groups.group_string(k)
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.downcast::<PyHomology>().is_ok_and(|o| o.get().report.groups == self.report.groups)
    }

    /// The object `gmap homology --json` prints, as a dict (torsion and orders as ints).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let text = self.report.to_json().to_string();
        py.import("json")?.call_method1("loads", (text,))
    }

    /// The JSON text of `to_dict()`, as `gmap homology --json` prints it.
    fn to_json(&self) -> String {
        self.report.to_json().to_string()
    }

    /// Homology.from_json(text): the result whose `to_json()` is `text` (how results cross
    /// process boundaries: pickling, Dask).
    #[staticmethod]
    fn from_json(py: Python<'_>, text: &str) -> PyResult<PyHomology> {
        let v: serde_json::Value = serde_json::from_str(text).map_err(|e| Failure::input(format!("not JSON: {e}")))?;
        let report = Report::from_json(&v)
            .ok_or_else(|| Failure::input("not the JSON of a homology result (gmap homology --json)"))?;
        finish(py, report)
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (String,))> {
        let f = slf.get_type().getattr("from_json")?;
        Ok((f, (slf.get().to_json(),)))
    }
}

fn parse_method(method: Option<&str>) -> PyResult<(Method, Option<Via>)> {
    // "cellular" and "simplicial" are `--method`, "direct" and "gmap" are `--via`
    Ok(match method {
        None | Some("cellular") => (Method::Cellular, None),
        Some("simplicial") => (Method::Simplicial, None),
        Some("direct") => (Method::Cellular, Some(Via::Direct)),
        Some("gmap") => (Method::Cellular, Some(Via::Gmap)),
        Some(m) => {
            return Err(Failure::input(format!(
                "method {m:?}: expected 'cellular', 'simplicial' (for G-maps), 'direct' or 'gmap' (the route of a simplicial complex)"
            ))
            .into())
        }
    })
}

/// The `field` argument as the options hold it: None, or an int the facade then checks
/// (`HomologyOptions::field`: it refuses what is not a field, with the rule). Anything that
/// is not an int from 0 to 2^64 - 1 is refused here as an argument, as the command's parser
/// refuses a `--field` that is not a number.
fn field_of(field: Option<&Bound<'_, PyAny>>) -> PyResult<Option<u64>> {
    match field {
        None => Ok(None),
        Some(f) if f.is_none() => Ok(None),
        Some(f) => f.extract::<u64>().map(Some).map_err(|e| {
            Failure::input(format!("field {}: {e}", f.repr().map(|r| r.to_string()).unwrap_or_default())).into()
        }),
    }
}

fn finish(py: Python<'_>, report: Report) -> PyResult<PyHomology> {
    let report = Arc::new(report);
    let generators = generators_to_py(py, &report)?;
    Ok(PyHomology { report, generators })
}

/// The facade's homology of an input, with the GIL released.
fn facade(py: Python<'_>, input: &Input, o: &HomologyOptions) -> PyResult<PyHomology> {
    let r = py.allow_threads(|| gmap::homology(input, o)).map_err(Failure::from)?;
    finish(py, r)
}

/// The homology of facets given from Python (a list, a tuple, a 2-D array).
fn facets_homology(py: Python<'_>, x: &Bound<'_, PyAny>, o: &HomologyOptions) -> PyResult<PyHomology> {
    let facets = objects::facets_from_py(x)?;
    let r = py.allow_threads(|| {
        let sc = objects::complex_of(facets)?;
        gmap::homology(&sc, o).map_err(Failure::from)
    })?;
    finish(py, r)
}

/// homology(x, *, field=None, generators=False, method=None, periodic=False, level=None)
///
/// The homology groups of `x`: a path (str or os.PathLike) to any file `gmap` reads, a
/// GMap, SimplicialComplex, CubicalSet, Image or ArchComplex, a sequence of facets
/// (sequences of non-negative ints), a 2-D integer numpy array of facets (one a row), or a
/// numpy array of bool, uint8 or float dtype (or any dtype with 1 or 3 to 8 axes) as a
/// cubical set (nonzero = the cube is present). `field`: a prime p for Z/p coefficients
/// (None: Z). `generators`: compute a representative cycle per summand ("shortest", with
/// field=2: those of H_1 a shortest basis over Z/2, lengths in edges). `method`:
/// 'cellular' (default) or 'simplicial' for G-maps; 'direct' (default) or 'gmap' for the
/// route of a simplicial complex. `periodic`: for cubical sets, identify the opposite faces
/// of the box. `level`: for an image, the cubes of the values <= level (default: the
/// nonzero values), the command's `--level`.
#[pyfunction]
#[pyo3(signature = (x, *, field = None, generators = None, method = None, periodic = false, level = None))]
fn homology(
    py: Python<'_>,
    x: &Bound<'_, PyAny>,
    field: Option<&Bound<'_, PyAny>>,
    generators: Option<&Bound<'_, PyAny>>,
    method: Option<&str>,
    periodic: bool,
    level: Option<f64>,
) -> PyResult<PyHomology> {
    let (method, via) = parse_method(method)?;
    let mut o = HomologyOptions::default();
    o.field = field_of(field)?;
    curves::generators_option(generators, &mut o)?;
    o.method = method;
    o.via = via;
    o.periodic = periodic;
    o.level = level;
    // facets as a list: the common small case first
    if let Ok(list) = x.downcast::<PyList>() {
        return facets_homology(py, list, &o);
    }
    if x.is_instance_of::<PyString>() || x.hasattr("__fspath__")? {
        let path: PathBuf = x.extract()?;
        let r = py.allow_threads(|| gmap::homology_file(&path, &o)).map_err(Failure::from)?;
        return finish(py, r);
    }
    if let Ok(m) = x.downcast::<PyGMap>() {
        let input = gmapobj::edit(m)?.homology_input()?;
        return facade(py, &input, &o);
    }
    if let Ok(s) = x.downcast::<PySimplicialComplex>() {
        return facade(py, &s.get().input, &o);
    }
    if let Ok(c) = x.downcast::<PyCubicalSet>() {
        return facade(py, &c.get().input, &o);
    }
    if let Ok(img) = x.downcast::<PyImage>() {
        return facade(py, &img.get().input, &o);
    }
    if let Ok(a) = x.downcast::<PyArchComplex>() {
        return facade(py, &a.get().input, &o);
    }
    if let Ok(arr) = x.downcast::<numpy::PyUntypedArray>() {
        use numpy::PyUntypedArrayMethods;
        objects::check_array(x)?;
        let kind = arr.dtype().kind();
        let facets = arr.ndim() == 2 && matches!(kind, b'i' | b'u') && arr.dtype().itemsize() > 1;
        if facets {
            let a = if kind == b'u' && arr.dtype().itemsize() == 8 {
                x.clone()
            } else {
                py.import("numpy")?.call_method1("ascontiguousarray", (x, "int64"))?
            };
            return facets_homology(py, &a, &o);
        }
        // a cubical set borrowed from the array (read in place when it is one-byte and
        // C- or Fortran-contiguous), by the facade's cubical routes
        let bytes = objects::array_bytes(x)?;
        let cubes = bytes.cubes()?;
        let r = py.allow_threads(|| gmap::homology_cubes(&cubes, &o)).map_err(Failure::from)?;
        return finish(py, r);
    }
    // any other sequence of facets (tuples, generators of lists, …)
    facets_homology(py, x, &o)
}

/// open(path): what the file holds, as the facade's format registry reads it, in the class
/// the registry names for its kind: a GMap (.gmap, .moka, .off, .vtk, .vtu, .msh), a
/// SimplicialComplex (.facets, .lex, FILE.lex#name), a CubicalSet (.cub, .cel, .pbm), an
/// Image (.npy, .complex, .pgm, .png) or an ArchComplex (.json).
#[pyfunction]
fn open(py: Python<'_>, path: PathBuf) -> PyResult<PyObject> {
    let input = py.allow_threads(|| gmap::open(&path)).map_err(Failure::from)?;
    let kind = input.input_kind();
    let obj = match input {
        Input::Map(m) => {
            let g = match m.labelled() {
                Some(g) => PyGMap::from_labelled(g.map_err(Failure::from)?.clone()),
                None => PyGMap::from_dense(m.map()),
            };
            Py::new(py, g)?.into_any()
        }
        input @ Input::Simplicial(_) => Py::new(py, PySimplicialComplex { input })?.into_any(),
        input @ Input::Cubical(_) => Py::new(py, PyCubicalSet { input })?.into_any(),
        input @ Input::Image(_) => Py::new(py, PyImage { input })?.into_any(),
        input @ Input::Arch(_) => Py::new(py, PyArchComplex { input })?.into_any(),
        // the facade's Input may grow a kind this build of the package does not know
        other => {
            return Err(Failure::input(format!(
                "{}: the package has no class for a {} (the registry names {})",
                path.display(),
                other.kind(),
                kind.python_class()
            ))
            .into())
        }
    };
    // the class made is the one the registry names for the kind
    let made = obj.bind(py).get_type().name()?.to_string();
    if made != kind.python_class() {
        return Err(Failure::input(format!(
            "{}: a {} opened as a {made}, not the registry's {}",
            path.display(),
            kind.name(),
            kind.python_class()
        ))
        .into());
    }
    Ok(obj)
}

/// The runs of `gmap bench` on files or folders, as its `--json` text: every route of
/// every input with its stage times in ms, groups and agreement.
#[pyfunction]
fn _bench_json(py: Python<'_>, paths: Vec<PathBuf>) -> PyResult<String> {
    let runs =
        py.allow_threads(|| gmap::bench::bench(&paths, None, &gmap::Progress::hidden())).map_err(Failure::from)?;
    Ok(gmap::bench::to_json(&runs).to_string())
}

fn build_result(py: Python<'_>, r: Result<gmap::core::DenseMap, gmap::ops::build::BuildError>) -> PyResult<Py<PyGMap>> {
    let m = r.map_err(Failure::build)?;
    Py::new(py, PyGMap::from_dense(&m))
}

/// build.grid(shape, periodic=False): the cubical grid of shape (s_0, …, s_{d-1}) as a
/// d-map; `periodic` one bool for all axes or one per axis (a torus along those axes).
#[pyfunction]
#[pyo3(signature = (shape, periodic = None))]
fn _build_grid(py: Python<'_>, shape: Vec<usize>, periodic: Option<&Bound<'_, PyAny>>) -> PyResult<Py<PyGMap>> {
    let p: Vec<bool> = match periodic {
        None => vec![false; shape.len()],
        Some(b) if b.is_instance_of::<pyo3::types::PyBool>() => vec![b.extract::<bool>()?; shape.len()],
        Some(v) => v.extract()?,
    };
    // the builder refuses a flag count other than the axes', and a grid past the dart limit
    // or the memory limit before making it
    build_result(py, py.allow_threads(|| gmap::ops::build::grid(&shape, &p)))
}

/// build.simplex(n): the n-simplex as an n-map.
#[pyfunction]
fn _build_simplex(py: Python<'_>, n: usize) -> PyResult<Py<PyGMap>> {
    build_result(py, gmap::ops::build::simplex(n))
}

/// build.cube(n): the n-cube as an n-map.
#[pyfunction]
fn _build_cube(py: Python<'_>, n: usize) -> PyResult<Py<PyGMap>> {
    build_result(py, gmap::ops::build::cube(n))
}

/// build.polygon(k): a k-gon as a 2-map.
#[pyfunction]
fn _build_polygon(py: Python<'_>, k: usize) -> PyResult<Py<PyGMap>> {
    build_result(py, gmap::ops::build::polygon(k))
}

/// build.lens_space(p, q): the lens space L(p, q) as a 3-map.
#[pyfunction]
fn _build_lens_space(py: Python<'_>, p: usize, q: usize) -> PyResult<Py<PyGMap>> {
    build_result(py, gmap::ops::build::lens_space(p, q))
}

/// build.solid_torus(k): a solid torus of k cubes as a 3-map.
#[pyfunction]
fn _build_solid_torus(py: Python<'_>, k: usize) -> PyResult<Py<PyGMap>> {
    build_result(py, gmap::ops::build::solid_torus(k))
}

/// build.surface(word): the surface of a polygon schema word ('a b a^-1 b^-1').
#[pyfunction]
fn _build_surface(py: Python<'_>, word: &str) -> PyResult<Py<PyGMap>> {
    build_result(py, gmap::ops::build::schema(word))
}

/// build.from_facets(facets): the G-map of a pure pseudo-manifold given by its facets; the
/// map keeps the complex (until an edit changes its darts) to name generators by labels.
#[pyfunction]
fn _build_from_facets(py: Python<'_>, facets: &Bound<'_, PyAny>) -> PyResult<Py<PyGMap>> {
    let f = objects::facets_from_py(facets)?;
    let (m, sc) = py.allow_threads(|| {
        let Input::Simplicial(sc) = objects::complex_of(f)? else {
            return Err(Failure::input("facets made no simplicial complex"));
        };
        let m = sc.to_gmap().map_err(Failure::from)?;
        Ok::<_, Failure>((m, std::sync::Arc::new(sc)))
    })?;
    Py::new(py, PyGMap::from_complex(&m, sc))
}

/// set_max_memory(nbytes): the memory limit of the calls that follow (the command's
/// `--max-memory`): work whose estimate passes it is refused with LimitError, and a grey
/// array past it takes the Morse route of `persistence`. None restores the default, half
/// the physical memory.
#[pyfunction]
fn set_max_memory(nbytes: Option<u64>) -> PyResult<()> {
    match nbytes {
        Some(0) => Err(Failure::input("a memory limit of 0 bytes").into()),
        Some(b) => {
            gmap::core::resources::set_max_memory(b);
            Ok(())
        }
        None => {
            gmap::core::resources::clear_max_memory();
            Ok(())
        }
    }
}

/// max_memory(): the memory limit in force, in bytes.
#[pyfunction]
fn max_memory() -> u64 {
    gmap::core::resources::max_memory()
}

/// The compiled module.
#[pymodule]
fn _gmap(m: &Bound<'_, PyModule>) -> PyResult<()> {
    errors::register(m)?;
    m.add_class::<PyGMap>()?;
    m.add_class::<PySimplicialComplex>()?;
    m.add_class::<PyCubicalSet>()?;
    m.add_class::<PyImage>()?;
    m.add_class::<PyArchComplex>()?;
    m.add_class::<PyHomology>()?;
    m.add_class::<PyGenerator>()?;
    m.add_function(wrap_pyfunction!(homology, m)?)?;
    m.add_function(wrap_pyfunction!(curves::shortest_non_contractible_cycle, m)?)?;
    m.add_function(wrap_pyfunction!(curves::edge_width, m)?)?;
    m.add_function(wrap_pyfunction!(curves::face_width, m)?)?;
    m.add_function(wrap_pyfunction!(curves::is_contractible, m)?)?;
    m.add_function(wrap_pyfunction!(curves::are_freely_homotopic, m)?)?;
    m.add_function(wrap_pyfunction!(curves::are_homotopic_with_fixed_endpoints, m)?)?;
    m.add_function(wrap_pyfunction!(curves::is_homotopic_to_simple_cycle, m)?)?;
    m.add_function(wrap_pyfunction!(open, m)?)?;
    m.add_function(wrap_pyfunction!(persist::persistence, m)?)?;
    m.add_function(wrap_pyfunction!(gudhi::_image_pairs, m)?)?;
    m.add_function(wrap_pyfunction!(gudhi::_simplex_pairs, m)?)?;
    m.add_function(wrap_pyfunction!(gudhi::_perseus_cubical, m)?)?;
    m.add_function(wrap_pyfunction!(set_max_memory, m)?)?;
    m.add_function(wrap_pyfunction!(max_memory, m)?)?;
    m.add_function(wrap_pyfunction!(page::_page, m)?)?;
    m.add_function(wrap_pyfunction!(page::_page_frame, m)?)?;
    m.add_function(wrap_pyfunction!(_bench_json, m)?)?;
    m.add_function(wrap_pyfunction!(_build_grid, m)?)?;
    m.add_function(wrap_pyfunction!(_build_simplex, m)?)?;
    m.add_function(wrap_pyfunction!(_build_cube, m)?)?;
    m.add_function(wrap_pyfunction!(_build_polygon, m)?)?;
    m.add_function(wrap_pyfunction!(_build_lens_space, m)?)?;
    m.add_function(wrap_pyfunction!(_build_solid_torus, m)?)?;
    m.add_function(wrap_pyfunction!(_build_surface, m)?)?;
    m.add_function(wrap_pyfunction!(_build_from_facets, m)?)?;
    m.add_function(wrap_pyfunction!(arch::_open_arch, m)?)?;
    m.add_function(wrap_pyfunction!(arch::_arch_homology, m)?)?;
    m.add_function(wrap_pyfunction!(arch::_tm_check, m)?)?;
    m.add_function(wrap_pyfunction!(arch::_tm_views, m)?)?;
    m.add_function(wrap_pyfunction!(arch::_rooms, m)?)?;
    m.add_function(wrap_pyfunction!(arch::_room_graph, m)?)?;
    Ok(())
}

/// mimalloc: the engine makes many small tables; the system allocator was a third of
/// the time of a call on a small complex (perf, a tetrahedron's boundary).
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;
