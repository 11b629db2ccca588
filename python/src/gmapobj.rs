//! `gmap.GMap`: an editable generalized map with points and labels, darts numbered `0..N`.
//!
//! Storage is the kernel's editable map ([`LabelledGMap`]: stable handles, cell labels of
//! dimensions 0–5, a point per vertex). Python sees darts as integers `0..N` in storage
//! order: `ids[k]` is the handle of dart `k`. Queries run on the frozen [`DenseMap`],
//! made once after each edit (O(N n)) and kept until the next; sewing keeps the numbering,
//! an Euler operator that makes or removes darts renumbers them (in storage order).

use std::sync::Arc;

use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray2, ToPyArray};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use gmap::core::edit::EditError;
use gmap::core::{AlphaSet, DartId, DenseMap, LabelValue, LabelledGMap, Labels, MAX_DIM};
use gmap::ops::euler::ops as eops;
use gmap::ops::euler::EulerError;
use gmap::ops::import::SimplicialComplex;
use gmap::{Input, MapInput, Sourced};

use crate::errors::{Failure, Kind, Res};

mod modelling;

/// An editable generalized map of dimension `dim` (CGAL's `Generalized_map`): darts
/// `0..len(m)`, involutions `alpha_0..alpha_dim`, a point per vertex, labels per cell.
#[pyclass(name = "GMap", module = "gmap")]
pub struct PyGMap {
    g: LabelledGMap,
    ids: Vec<DartId>,
    /// the dart number of each storage slot (`u32::MAX` for an empty slot)
    slot_index: Vec<u32>,
    dense: Option<Arc<DenseMap>>,
    /// the simplicial complex the map was built from (`build.from_facets`), while no edit
    /// changed its darts: generators are then named by the complex's vertex labels
    source: Option<Arc<Sourced<SimplicialComplex>>>,
    /// the marks reserved from Python (`get_new_mark`), by number; `None` once freed
    marks: Vec<Option<gmap::core::MarkId>>,
    /// the Python values of darts and cells (CGAL's `info`), see [`modelling`]
    info: modelling::Info,
}

impl PyGMap {
    /// Wraps a dense map (no labels).
    pub fn from_dense(m: &DenseMap) -> Self {
        let (g, ids) = LabelledGMap::from_dense_with_attributes(m);
        let mut m = PyGMap {
            g,
            ids,
            slot_index: Vec::new(),
            dense: None,
            source: None,
            marks: Vec::new(),
            info: Default::default(),
        };
        m.index_slots();
        m
    }

    /// Wraps a labelled map.
    pub fn from_labelled(g: LabelledGMap) -> Self {
        let mut m = PyGMap {
            g,
            ids: Vec::new(),
            slot_index: Vec::new(),
            dense: None,
            source: None,
            marks: Vec::new(),
            info: Default::default(),
        };
        m.refresh();
        m
    }

    /// The map of a simplicial complex's facets (`m`, its G-map), which keeps the complex to
    /// name its cells.
    pub fn from_complex(m: &DenseMap, complex: Arc<Sourced<SimplicialComplex>>) -> Self {
        let mut g = PyGMap::from_dense(m);
        g.source = Some(complex);
        g
    }

    /// The map with its points and labels as a facade input (a copy, without the Python
    /// values of [`modelling`], which no file holds).
    pub fn input(&self) -> Input {
        Input::Map(MapInput::from_labelled(modelling::without_info(&self.g)))
    }

    /// The map as the facade's homology takes it (a copy of its darts): the G-map of the
    /// complex it was built from while no edit changed its darts (its cells then named by
    /// the complex's vertex labels), else the map itself.
    pub fn homology_input(&mut self) -> Res<Input> {
        match &self.source {
            Some(sc) => Ok(Input::Map(MapInput::of_complex(sc.clone())?)),
            None => Ok(Input::Map(MapInput::new((*self.dense()).clone()))),
        }
    }

    /// Renumbers the darts after darts were made or removed.
    fn refresh(&mut self) {
        self.source = None;
        self.freeze();
        self.info.prune(&self.g);
    }

    /// Makes the frozen map and numbers the darts in storage order.
    fn freeze(&mut self) {
        let (d, ids) = self.g.to_dense_with_ids();
        self.ids = ids;
        self.dense = Some(Arc::new(d));
        self.index_slots();
    }

    /// Numbers the storage slots after the darts changed.
    fn index_slots(&mut self) {
        self.slot_index.clear();
        self.slot_index.resize(self.g.index_bound(), u32::MAX);
        for (k, &h) in self.ids.iter().enumerate() {
            self.slot_index[self.g.dart_index(h)] = k as u32;
        }
    }

    /// The dart number of a live handle.
    fn number(&self, h: DartId) -> usize {
        self.slot_index[self.g.dart_index(h)] as usize
    }

    /// The dart number of a handle, when it names a dart numbered now (not one an edit made
    /// or removed since the numbering).
    fn number_of(&self, h: DartId) -> Option<usize> {
        if !self.g.contains(h) {
            return None;
        }
        let k = *self.slot_index.get(self.g.dart_index(h))?;
        (k != u32::MAX && self.ids.get(k as usize) == Some(&h)).then_some(k as usize)
    }

    /// A dart in a message: `dart N` in the map's numbering.
    fn dart_text(&self, h: DartId) -> String {
        match self.number_of(h) {
            Some(k) => format!("dart {k}"),
            None => "a dart the edit made or removed".to_string(),
        }
    }

    /// A refused sew or unsew (PreconditionError), its darts in the map's numbering and the
    /// offending one as the error's `item`.
    fn edit_failure(&self, e: &EditError) -> Failure {
        let d = |h: DartId| self.dart_text(h);
        let (message, dart) = match e {
            EditError::NoSuchDart(h) => (format!("{} does not exist (removed or from another map)", d(*h)), Some(*h)),
            EditError::NotFree { dart, alpha } => (format!("{} is not {alpha}-free", d(*dart)), Some(*dart)),
            EditError::NotIsomorphic { first, second, alpha, at } => (
                format!(
                    "the orbits of {} and {} cannot be paired one-to-one by alpha_{alpha}-sewing (conflict at {})",
                    d(*first),
                    d(*second),
                    d(*at)
                ),
                Some(*at),
            ),
            EditError::NotOrientable { dart, alpha, other } => (
                format!(
                    "the component is not orientable: alpha_{alpha} links {} and {} of the same class",
                    d(*dart),
                    d(*other)
                ),
                Some(*dart),
            ),
            // the variants without a dart (an index, a dimension) say it as they are
            other => (other.to_string(), None),
        };
        self.with_dart(Failure::new(Kind::Precondition, message), dart)
    }

    /// A refused Euler operator (PreconditionError), as [`PyGMap::edit_failure`]; made
    /// before the map is renumbered.
    fn euler_failure(&self, e: &EulerError) -> Failure {
        let d = |h: DartId| self.dart_text(h);
        let (message, dart) = match e {
            EulerError::NoSuchDart(h) => (format!("{} does not exist", d(*h)), Some(*h)),
            EulerError::Free { dart, alpha } => (format!("{} is {alpha}-free", d(*dart)), Some(*dart)),
            EulerError::Misplaced { dart, what } => {
                (format!("{} is not where the {what} needs it", d(*dart)), Some(*dart))
            }
            EulerError::OpenCut(h) => (format!("the cut is not closed at {}", d(*h)), Some(*h)),
            EulerError::NotSeparating(h) => (format!("the cut through {} does not separate its cell", d(*h)), Some(*h)),
            EulerError::DegreeAboveTwo { dim, dart } => {
                (format!("the {dim}-cell of {} has degree above 2", d(*dart)), Some(*dart))
            }
            EulerError::WouldChangeTopology { dim, dart, why } => {
                (format!("the {dim}-cell of {} {why}", d(*dart)), Some(*dart))
            }
            EulerError::NoPoint { dim, dart } => {
                (format!("the {dim}-cell of {} has a vertex without a point", d(*dart)), Some(*dart))
            }
            // the variants without a dart (a cell dimension out of range) say it as they are
            other => (other.to_string(), None),
        };
        self.with_dart(Failure::new(Kind::Precondition, message), dart)
    }

    /// `f` with the dart's number as its item, when it has one now.
    fn with_dart(&self, f: Failure, dart: Option<DartId>) -> Failure {
        match dart.and_then(|h| self.number_of(h)) {
            Some(k) => f.with_dart(k),
            None => f,
        }
    }

    /// Drops the frozen map after an edit that keeps the darts.
    fn touched(&mut self) {
        self.dense = None;
        self.source = None;
    }

    /// The frozen map (made now if an edit dropped it).
    pub fn dense(&mut self) -> Arc<DenseMap> {
        if self.dense.is_none() {
            self.freeze();
        }
        self.dense.clone().expect("just made")
    }

    fn handle(&self, d: i64) -> Res<DartId> {
        usize::try_from(d).ok().and_then(|k| self.ids.get(k).copied()).ok_or_else(|| {
            Failure::input(format!(
                "dart {d} does not exist: the map has {} darts (0..{})",
                self.ids.len(),
                self.ids.len()
            ))
        })
    }

    fn dim_index(&self, i: i64, what: &str) -> Res<usize> {
        usize::try_from(i)
            .ok()
            .filter(|&i| i <= self.g.dim())
            .ok_or_else(|| Failure::input(format!("{what} {i} does not exist in a map of dimension {}", self.g.dim())))
    }

    /// The dart number of a handle after a refresh.
    fn index_of(&mut self, h: DartId) -> usize {
        self.refresh();
        self.number(h)
    }

    fn after_insert(&mut self, r: Result<DartId, EulerError>) -> PyResult<usize> {
        match r {
            Ok(h) => {
                let k = self.index_of(h);
                self.info.raise_hook_error()?;
                Ok(k)
            }
            Err(e) => {
                // the darts named in the numbering the caller used, then renumbered
                let f = self.euler_failure(&e);
                self.refresh();
                Err(f.into())
            }
        }
    }
}

/// An incidence pair of `GMap.incidences`: ((i, a), (i + 1, b)).
type Incidence = ((usize, u32), (usize, u32));

/// The GMap behind a Python object for an edit or a snapshot, borrowed under the GIL for as
/// long as the caller holds it (never across a release of the GIL: computations run on
/// [`snapshot`]s). A GMap another borrow holds is refused with InputError, not a panic.
pub fn edit<'py>(slf: &Bound<'py, PyGMap>) -> PyResult<PyRefMut<'py, PyGMap>> {
    slf.try_borrow_mut().map_err(|_| busy())
}

/// The GMap behind a Python object, read-only ([`edit`]'s rule).
pub fn read<'py>(slf: &Bound<'py, PyGMap>) -> PyResult<PyRef<'py, PyGMap>> {
    slf.try_borrow().map_err(|_| busy())
}

/// Refuses (LimitError) an editable map of `darts` darts past the memory policy, before
/// they are made.
fn check_darts_memory(dim: usize, darts: u64) -> PyResult<()> {
    let what = format!("a map of dimension {dim} with {darts} darts");
    gmap::core::resources::check_memory(&what, LabelledGMap::memory_estimate(dim, darts))
        .map_err(|e| Failure::new(Kind::Limit, e.to_string()).into())
}

fn busy() -> PyErr {
    Failure::input("the GMap is held by another call in progress (in another thread); retry when it returns").into()
}

/// The frozen map of a GMap, taken under a short borrow and released before the caller
/// releases the GIL: many threads may compute on one map at once, and an edit meanwhile
/// changes the map, not their snapshots.
pub fn snapshot(slf: &Bound<'_, PyGMap>) -> PyResult<Arc<DenseMap>> {
    Ok(edit(slf)?.dense())
}

fn label_to_py(py: Python<'_>, v: &LabelValue) -> PyObject {
    match v {
        LabelValue::Int(i) => i.into_pyobject(py).expect("int").into_any().unbind(),
        LabelValue::Real(x) => x.into_pyobject(py).expect("float").into_any().unbind(),
        LabelValue::Text(t) => t.into_pyobject(py).expect("str").into_any().unbind(),
    }
}

fn label_from_py(v: &Bound<'_, PyAny>) -> PyResult<LabelValue> {
    if v.is_instance_of::<pyo3::types::PyBool>() {
        return Err(Failure::input("a label is an int, a finite float or a str (not a bool)").into());
    }
    if let Ok(i) = v.extract::<i64>() {
        return Ok(LabelValue::Int(i));
    }
    // an int past 64 bits (Python's, numpy's uint64) is refused, not stored as a float
    if v.is_instance_of::<pyo3::types::PyInt>() || v.hasattr("__index__")? {
        let text = v.str().map(|t| t.to_string()).unwrap_or_default();
        return Err(Failure::input(format!(
            "the label value {text}: an int label holds 64 bits (from -2^63 to 2^63 - 1); give it as a str"
        ))
        .into());
    }
    if let Ok(x) = v.extract::<f64>() {
        if !x.is_finite() {
            return Err(Failure::input(format!("a label's real value must be finite, not {x}")).into());
        }
        return Ok(LabelValue::Real(x));
    }
    if let Ok(t) = v.extract::<String>() {
        return Ok(LabelValue::Text(t));
    }
    Err(Failure::input("a label is an int (64-bit), a finite float or a str").into())
}

macro_rules! with_labels_mut {
    ($g:expr, $i:expr, $d:expr, |$l:ident| $body:expr) => {{
        match $i {
            0 => {
                let x = $g.attribute_mut::<0>($d);
                match x {
                    Some($l) => {
                        $body;
                        true
                    }
                    None => false,
                }
            }
            1 => {
                let x = $g.attribute_mut::<1>($d);
                match x {
                    Some($l) => {
                        $body;
                        true
                    }
                    None => false,
                }
            }
            2 => {
                let x = $g.attribute_mut::<2>($d);
                match x {
                    Some($l) => {
                        $body;
                        true
                    }
                    None => false,
                }
            }
            3 => {
                let x = $g.attribute_mut::<3>($d);
                match x {
                    Some($l) => {
                        $body;
                        true
                    }
                    None => false,
                }
            }
            4 => {
                let x = $g.attribute_mut::<4>($d);
                match x {
                    Some($l) => {
                        $body;
                        true
                    }
                    None => false,
                }
            }
            5 => {
                let x = $g.attribute_mut::<5>($d);
                match x {
                    Some($l) => {
                        $body;
                        true
                    }
                    None => false,
                }
            }
            _ => false,
        }
    }};
}

fn set_labels(g: &mut LabelledGMap, i: usize, d: DartId, l: Labels) {
    match i {
        0 => drop(g.set_attribute::<0>(d, l)),
        1 => drop(g.set_attribute::<1>(d, l)),
        2 => drop(g.set_attribute::<2>(d, l)),
        3 => drop(g.set_attribute::<3>(d, l)),
        4 => drop(g.set_attribute::<4>(d, l)),
        5 => drop(g.set_attribute::<5>(d, l)),
        _ => {}
    }
}

#[pymethods]
impl PyGMap {
    /// GMap(dim, darts=0): a map of dimension `dim` with `darts` free darts (every dart its
    /// own image under every involution).
    #[new]
    #[pyo3(signature = (dim, darts = 0))]
    fn py_new(dim: i64, darts: i64) -> PyResult<Self> {
        let dim = usize::try_from(dim)
            .ok()
            .filter(|&d| d <= MAX_DIM)
            .ok_or_else(|| Failure::input(format!("dimension {dim}: a map has a dimension from 0 to {MAX_DIM}")))?;
        let darts = usize::try_from(darts)
            .ok()
            .filter(|&n| n < u32::MAX as usize)
            .ok_or_else(|| Failure::input(format!("{darts} darts: the count must be from 0 to 2^32 - 2")))?;
        // the dart limit of the readers of map files (what the memory budget and the work
        // limit hold for this dimension)
        let most = gmap::ops::import::default_max_darts(dim);
        if darts as u64 > most {
            return Err(Failure::new(
                Kind::Limit,
                format!("{darts} darts: a map of dimension {dim} holds at most {most} here (the memory budget)"),
            )
            .into());
        }
        check_darts_memory(dim, darts as u64)?;
        let mut g = LabelledGMap::with_attributes(dim);
        for _ in 0..darts {
            g.create_dart();
        }
        Ok(PyGMap::from_labelled(g))
    }

    /// GMap.from_alphas(a): the map whose involutions are the rows of `a`, an integer array
    /// of shape (dim + 1, darts); a free dart is its own image. Refuses (ValidityError) an
    /// array that is not a G-map (not involutions, alpha_i alpha_j not involutive for
    /// i + 2 <= j).
    #[staticmethod]
    fn from_alphas(py: Python<'_>, a: PyReadonlyArray2<'_, i64>) -> PyResult<Self> {
        let v = a.as_array();
        let (rows, n) = v.dim();
        if rows == 0 || rows > MAX_DIM + 1 {
            return Err(Failure::input(format!(
                "an alphas array has dim + 1 rows, from 1 to {}; this one has {rows}",
                MAX_DIM + 1
            ))
            .into());
        }
        if n >= u32::MAX as usize {
            return Err(Failure::new(Kind::Limit, format!("{n} darts: at most 2^32 - 2")).into());
        }
        let mut flat = Vec::new();
        flat.try_reserve_exact(rows * n).map_err(|_| Failure::new(Kind::Limit, "cannot allocate the map"))?;
        for d in 0..n {
            for i in 0..rows {
                let x = v[(i, d)];
                if x < 0 || x as u64 >= n as u64 {
                    return Err(Failure::input(format!(
                        "alpha_{i}({d}) = {x}: an image must be a dart from 0 to {}",
                        n.saturating_sub(1)
                    ))
                    .into());
                }
                flat.push(x as u32);
            }
        }
        let m = py.allow_threads(|| DenseMap::try_from_flat(rows - 1, flat)).map_err(Failure::validity)?;
        Ok(PyGMap::from_dense(&m))
    }

    /// The dimension n.
    #[getter]
    fn dim(&self) -> usize {
        self.g.dim()
    }

    /// The number of darts.
    fn __len__(&self) -> usize {
        self.ids.len()
    }

    fn __repr__(&mut self) -> String {
        let d = self.dense();
        format!("<gmap.GMap dim={} darts={} cells={:?}>", d.dim(), d.dart_count(), d.cell_counts())
    }

    /// The involutions as a uint32 array of shape (dim + 1, darts): `alphas[i, d]` is
    /// alpha_i(d). A copy: editing it does not change the map.
    #[getter]
    fn alphas<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let d = self.dense();
        let w = d.dim() + 1;
        let n = d.dart_count();
        let a = PyArray1::from_slice(py, d.flat()).reshape([n, w])?;
        a.getattr("T")?.call_method0("copy")
    }

    /// alpha_i(d).
    fn alpha(&self, d: i64, i: i64) -> PyResult<usize> {
        let h = self.handle(d)?;
        let i = self.dim_index(i, "alpha")?;
        let e = self.g.alpha(h, i);
        Ok(self.number(e))
    }

    /// Whether d is i-free (its own image under alpha_i).
    fn is_free(&self, d: i64, i: i64) -> PyResult<bool> {
        Ok(self.g.is_free(self.handle(d)?, self.dim_index(i, "alpha")?))
    }

    /// Adds `k` free darts; returns the number of the first.
    #[pyo3(signature = (k = 1))]
    fn add_darts(&mut self, k: usize) -> PyResult<usize> {
        let first = self.ids.len();
        if first.checked_add(k).is_none_or(|n| n >= u32::MAX as usize) {
            return Err(Failure::new(Kind::Limit, "at most 2^32 - 2 darts").into());
        }
        check_darts_memory(self.g.dim(), (first + k) as u64)?;
        for _ in 0..k {
            let h = self.g.create_dart();
            self.ids.push(h);
        }
        self.index_slots();
        self.touched();
        Ok(first)
    }

    /// Whether `sew(d, e, i)` would succeed.
    fn is_sewable(&self, d: i64, e: i64, i: i64) -> PyResult<bool> {
        Ok(self.g.is_sewable(self.handle(d)?, self.handle(e)?, self.dim_index(i, "alpha")?))
    }

    /// i-sews d and e and the orbits that must follow to keep a G-map (CGAL's `sew<i>`);
    /// PreconditionError when they cannot be sewn.
    fn sew(&mut self, d: i64, e: i64, i: i64) -> PyResult<()> {
        let (d, e, i) = (self.handle(d)?, self.handle(e)?, self.dim_index(i, "alpha")?);
        self.g.try_sew(d, e, i).map_err(|e| self.edit_failure(&e))?;
        self.touched();
        self.info.raise_hook_error()
    }

    /// i-unsews d (and its orbit), CGAL's `unsew<i>`.
    fn unsew(&mut self, d: i64, i: i64) -> PyResult<()> {
        let (d, i) = (self.handle(d)?, self.dim_index(i, "alpha")?);
        self.g.try_unsew(d, i).map_err(|e| self.edit_failure(&e))?;
        self.touched();
        self.info.raise_hook_error()
    }

    /// The number of i-cells for i = 0..dim.
    fn cell_counts(&mut self) -> Vec<usize> {
        self.dense().cell_counts()
    }

    /// One dart per i-cell (the smallest), as a uint32 array, in the order cells are
    /// numbered everywhere (labels, points, generators).
    fn cells<'py>(slf: &Bound<'py, Self>, i: i64) -> PyResult<Bound<'py, PyArray1<u32>>> {
        let py = slf.py();
        let (d, i) = {
            let mut m = edit(slf)?;
            let i = m.dim_index(i, "cell dimension")?;
            (m.dense(), i)
        };
        let p = py.allow_threads(|| d.cells(i));
        Ok(p.reps.iter().map(|r| r.index() as u32).collect::<Vec<_>>().to_pyarray(py))
    }

    /// One dart per connected component (the smallest), as a uint32 array.
    fn components<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyArray1<u32>>> {
        let py = slf.py();
        let d = snapshot(slf)?;
        let p = py.allow_threads(|| d.components());
        Ok(p.reps.iter().map(|r| r.index() as u32).collect::<Vec<_>>().to_pyarray(py))
    }

    /// The orbit of d under the involutions listed in `dims`, as a uint32 array (d first).
    fn orbit<'py>(&mut self, py: Python<'py>, d: i64, dims: Vec<i64>) -> PyResult<Bound<'py, PyArray1<u32>>> {
        let h = self.handle(d)?;
        let mut set = Vec::with_capacity(dims.len());
        for i in dims {
            set.push(self.dim_index(i, "alpha")?);
        }
        let o = self.g.orbit(h, AlphaSet::of(&set));
        Ok(o.iter().map(|&x| self.number(x) as u32).collect::<Vec<_>>().to_pyarray(py))
    }

    /// Whether the map is orientable.
    fn is_orientable(slf: &Bound<'_, Self>) -> PyResult<bool> {
        let d = snapshot(slf)?;
        Ok(slf.py().allow_threads(|| d.is_orientable()))
    }

    /// The Euler characteristic: the alternating sum of the cell counts.
    fn euler_characteristic(&mut self) -> i64 {
        self.dense().euler_characteristic()
    }

    /// Raises ValidityError naming the fault when the map is not a G-map (alpha_i not an
    /// involution, alpha_i alpha_j not involutive for i + 2 <= j); returns None otherwise.
    fn check(&mut self) -> PyResult<()> {
        let d = self.dense();
        d.validate().map_err(Failure::validity)?;
        Ok(())
    }

    /// Whether `check()` passes.
    fn is_valid(&mut self) -> bool {
        self.dense().is_valid()
    }

    /// The vertex points as a float64 array of shape (number of 0-cells, 3), in the order
    /// of `cells(0)`; a row of NaN for a vertex without a point.
    #[getter]
    fn get_points<'py>(&mut self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let d = self.dense();
        let reps = d.cells(0).reps;
        let mut v = Vec::with_capacity(reps.len() * 3);
        for r in reps {
            v.extend_from_slice(&d.vertex_point(r).unwrap_or([f64::NAN; 3]));
        }
        let n = v.len() / 3;
        PyArray1::from_vec(py, v).reshape([n, 3]).expect("a whole number of rows")
    }

    /// Sets the vertex points from an array of shape (number of 0-cells, 3) or (…, 2) in
    /// the order of `cells(0)`; a row with a NaN leaves its vertex without a point.
    #[setter]
    fn set_points(&mut self, p: PyReadonlyArray2<'_, f64>) -> PyResult<()> {
        let v = p.as_array();
        let d = self.dense();
        let reps = d.cells(0).reps;
        let (rows, cols) = v.dim();
        if rows != reps.len() || !(2..=3).contains(&cols) {
            return Err(Failure::input(format!(
                "points of shape ({rows}, {cols}): the map has {} vertices, points have 2 or 3 coordinates",
                reps.len()
            ))
            .into());
        }
        for (k, r) in reps.iter().enumerate() {
            let mut q = [0.0; 3];
            for c in 0..cols {
                q[c] = v[(k, c)];
            }
            let p = if q.iter().any(|x| x.is_nan()) { None } else { Some(q) };
            if p.is_some_and(|q| q.iter().any(|x| !x.is_finite())) {
                return Err(Failure::input(format!("vertex {k}: a point's coordinates must be finite")).into());
            }
            let h = self.ids[r.index()];
            self.g.set_point(h, p);
        }
        self.dense = None;
        Ok(())
    }

    /// The labels of the i-cells, one dict per cell in the order of `cells(i)` (empty for a
    /// cell without labels). Labels exist for dimensions 0 to 5.
    fn labels<'py>(&mut self, py: Python<'py>, i: i64) -> PyResult<Bound<'py, PyList>> {
        let i = self.dim_index(i, "cell dimension")?;
        let (_, labels, _) = gmap::core::to_dense_labels(&self.g);
        let n = self.dense().cell_count(i);
        let out = PyList::empty(py);
        for c in 0..n {
            let d = PyDict::new(py);
            for (k, v) in labels.get(i, c).iter().filter(|(k, _)| *k != modelling::INFO_KEY) {
                d.set_item(k, label_to_py(py, v))?;
            }
            out.append(d)?;
        }
        Ok(out)
    }

    /// Sets the label `name` of the i-cell of dart d to `value` (int, float or str).
    fn set_label(&mut self, i: i64, d: i64, name: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        let i = self.dim_index(i, "cell dimension")?;
        if i > gmap::core::labels::MAX_LABELLED_DIM {
            return Err(Failure::input(format!("cells of dimension {i} have no labels (at most 5)")).into());
        }
        let h = self.handle(d)?;
        if name.starts_with(modelling::INFO_KEY) {
            return Err(Failure::input(format!("the label name {name:?} is reserved (it starts with \\u0001)")).into());
        }
        let v = label_from_py(value)?;
        let done = with_labels_mut!(self.g, i, h, |l| {
            l.set(name, v.clone());
        });
        if !done {
            let mut l = Labels::new();
            l.set(name, v);
            set_labels(&mut self.g, i, h, l);
        }
        Ok(())
    }

    /// A copy of the map, with its points, labels and Python values (`info`, the same
    /// objects: a shallow copy) and their functors; marks are not copied.
    fn copy(&mut self) -> Self {
        let (d, labels, old) = gmap::core::to_dense_labels(&self.g);
        let mut m = PyGMap::from_dense(&d);
        for (i, per) in labels.of.iter().enumerate() {
            let reps = d.cells(i).reps;
            for (c, l) in per.iter().enumerate() {
                if !l.is_empty() {
                    let h = m.ids[reps[c].index()];
                    set_labels(&mut m.g, i, h, l.clone());
                }
            }
        }
        let info = self.info.copy_to(&mut m.g, &old, &m.ids);
        m.info = info;
        m
    }

    /// The text of the map in the `.gmap` format (points and labels kept).
    fn to_text(&self) -> PyResult<String> {
        Ok(gmap::formats::to_text(&self.input(), "gmap").map_err(Failure::from)?)
    }

    /// GMap.from_text(text): the map of a `.gmap` text (ParseError naming the line).
    #[staticmethod]
    fn from_text(text: &str) -> PyResult<Self> {
        match gmap::formats::parse_text("gmap", text).map_err(Failure::from)? {
            Input::Map(m) => match m.labelled() {
                Some(g) => Ok(PyGMap::from_labelled(g.map_err(Failure::from)?.clone())),
                None => Ok(PyGMap::from_dense(m.map())),
            },
            other => Err(Failure::input(format!("a .gmap text read as a {}", other.kind())).into()),
        }
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (String,))> {
        let f = slf.get_type().getattr("from_text")?;
        let t = read(slf)?.to_text()?;
        Ok((f, (t,)))
    }

    /// save(path, lossy=False): writes the map by extension, as `gmap convert` does:
    /// `.gmap` (points and labels kept), `.moka`, `.off`, `.vtk` (labels as cell data),
    /// `.facets` (the barycentric subdivision), the incidence graph (`.json`, `.dot`,
    /// `.graphml`), `.lar.json`. Without `lossy`, a format that would drop the map's
    /// labels or points is refused (InputError), as `gmap convert` refuses it without
    /// `--lossy`.
    #[pyo3(signature = (path, lossy = false))]
    fn save(slf: &Bound<'_, Self>, path: std::path::PathBuf, lossy: bool) -> PyResult<()> {
        let input = read(slf)?.input();
        crate::save::save_input(slf.py(), &input, &path, lossy)
    }

    /// The incidence pairs of the map's cells: a list of ((i, a), (i + 1, b)) for each
    /// i-cell a on the boundary of the (i+1)-cell b (cells numbered as in `cells(i)`).
    fn incidences(slf: &Bound<'_, Self>) -> PyResult<Vec<Incidence>> {
        let d = snapshot(slf)?;
        Ok(slf.py().allow_threads(|| {
            let parts: Vec<_> = (0..=d.dim()).map(|i| d.cells(i)).collect();
            let mut out = Vec::new();
            for i in 0..d.dim() {
                let mut seen = std::collections::BTreeSet::new();
                for x in d.darts() {
                    seen.insert((parts[i].cell_of(x).index() as u32, parts[i + 1].cell_of(x).index() as u32));
                }
                out.extend(seen.into_iter().map(|(a, b)| ((i, a), (i + 1, b))));
            }
            out
        }))
    }

    // --- Euler operators under CGAL's names (gmap::ops::euler::ops::cgal) ---

    /// CGAL's insert_cell_0_in_cell_1(d): a vertex in the middle of the edge of d; returns a
    /// dart of the new vertex.
    fn insert_cell_0_in_cell_1(&mut self, d: i64) -> PyResult<usize> {
        let h = self.handle(d)?;
        let r = eops::insert_cell_0_in_cell_1(&mut self.g, h);
        self.after_insert(r)
    }

    /// Whether insert_cell_0_in_cell_1(d) applies.
    fn is_insertable_cell_0_in_cell_1(&self, d: i64) -> PyResult<bool> {
        Ok(eops::is_insertable_cell_0_in_cell_1(&self.g, self.handle(d)?))
    }

    /// CGAL's insert_cell_0_in_cell_2(d, point=None): a vertex joined to every corner of the
    /// face of d; returns a dart of the new vertex.
    #[pyo3(signature = (d, point = None))]
    fn insert_cell_0_in_cell_2(&mut self, d: i64, point: Option<[f64; 3]>) -> PyResult<usize> {
        let h = self.handle(d)?;
        let r = eops::insert_cell_0_in_cell_2(&mut self.g, h, point);
        self.after_insert(r)
    }

    /// Whether insert_cell_0_in_cell_2(d) applies.
    fn is_insertable_cell_0_in_cell_2(&self, d: i64) -> PyResult<bool> {
        Ok(eops::is_insertable_cell_0_in_cell_2(&self.g, self.handle(d)?))
    }

    /// CGAL's insert_cell_1_in_cell_2(d1, d2): an edge splitting the face of d1 between the
    /// corners of d1 and d2; returns a dart of the new edge.
    fn insert_cell_1_in_cell_2(&mut self, d1: i64, d2: i64) -> PyResult<usize> {
        let (a, b) = (self.handle(d1)?, self.handle(d2)?);
        let r = eops::insert_cell_1_in_cell_2(&mut self.g, a, b);
        self.after_insert(r)
    }

    /// Whether insert_cell_1_in_cell_2(d1, d2) applies.
    fn is_insertable_cell_1_in_cell_2(&self, d1: i64, d2: i64) -> PyResult<bool> {
        Ok(eops::is_insertable_cell_1_in_cell_2(&self.g, self.handle(d1)?, self.handle(d2)?))
    }

    /// CGAL's insert_dangling_cell_1_in_cell_2(d, point=None): an edge hanging from the
    /// vertex of d into its face; returns the dart of the new edge at the new vertex.
    #[pyo3(signature = (d, point = None))]
    fn insert_dangling_cell_1_in_cell_2(&mut self, d: i64, point: Option<[f64; 3]>) -> PyResult<usize> {
        let h = self.handle(d)?;
        let r = eops::insert_dangling_cell_1_in_cell_2(&mut self.g, h, point);
        self.after_insert(r)
    }

    /// Whether insert_dangling_cell_1_in_cell_2(d) applies.
    fn is_insertable_dangling_cell_1_in_cell_2(&self, d: i64) -> PyResult<bool> {
        Ok(eops::is_insertable_dangling_cell_1_in_cell_2(&self.g, self.handle(d)?))
    }

    /// CGAL's insert_cell_1_between_two_cells_2(d1, d2): an edge joining two faces; returns
    /// a dart of the new edge.
    fn insert_cell_1_between_two_cells_2(&mut self, d1: i64, d2: i64) -> PyResult<usize> {
        let (a, b) = (self.handle(d1)?, self.handle(d2)?);
        let r = eops::insert_cell_1_between_two_cells_2(&mut self.g, a, b);
        self.after_insert(r)
    }

    /// Whether insert_cell_1_between_two_cells_2(d1, d2) applies.
    fn is_insertable_cell_1_between_two_cells_2(&self, d1: i64, d2: i64) -> PyResult<bool> {
        Ok(eops::is_insertable_cell_1_between_two_cells_2(&self.g, self.handle(d1)?, self.handle(d2)?))
    }

    /// CGAL's insert_cell_2_in_cell_3(path): a face splitting a volume along a closed path
    /// of edges (one dart per edge); returns a dart of the new face.
    fn insert_cell_2_in_cell_3(&mut self, path: Vec<i64>) -> PyResult<usize> {
        let hs = path.iter().map(|&d| self.handle(d)).collect::<Res<Vec<_>>>()?;
        let r = eops::insert_cell_2_in_cell_3(&mut self.g, &hs);
        self.after_insert(r)
    }

    /// Whether insert_cell_2_in_cell_3(path) applies.
    fn is_insertable_cell_2_in_cell_3(&self, path: Vec<i64>) -> PyResult<bool> {
        let hs = path.iter().map(|&d| self.handle(d)).collect::<Res<Vec<_>>>()?;
        Ok(eops::is_insertable_cell_2_in_cell_3(&self.g, &hs))
    }

    /// LCC's insert_barycenter_in_cell(d, i): a vertex at the barycentre of the i-cell of d
    /// joined to its boundary; returns a dart of the new vertex.
    fn insert_barycenter_in_cell(&mut self, d: i64, i: i64) -> PyResult<usize> {
        let (h, i) = (self.handle(d)?, self.dim_index(i, "cell dimension")?);
        let r = eops::insert_barycenter_in_cell(&mut self.g, h, i);
        self.after_insert(r)
    }

    /// Whether insert_barycenter_in_cell(d, i) applies.
    fn is_insertable_barycenter_in_cell(&self, d: i64, i: i64) -> PyResult<bool> {
        Ok(eops::is_insertable_barycenter_in_cell(&self.g, self.handle(d)?, self.dim_index(i, "cell dimension")?))
    }

    /// LCC's insert_point_in_cell(d, point, i): a vertex at `point` in the i-cell of d
    /// joined to its boundary; returns a dart of the new vertex.
    fn insert_point_in_cell(&mut self, d: i64, point: [f64; 3], i: i64) -> PyResult<usize> {
        let (h, i) = (self.handle(d)?, self.dim_index(i, "cell dimension")?);
        let r = eops::insert_point_in_cell(&mut self.g, h, i, point);
        self.after_insert(r)
    }

    /// CGAL's `remove_cell<i>(d)`: removes the i-cell of d, 0 <= i <= dim, on the boundary or
    /// not (the (i+1)-cells around it merge; a face of a 2-map, a volume of a 3-map goes
    /// with its darts); may change the space (`remove_cell_keeping_homology` never does).
    /// Returns the number of darts removed, as CGAL.
    fn remove_cell(&mut self, d: i64, i: i64) -> PyResult<usize> {
        let (h, i) = (self.handle(d)?, self.dim_index(i, "cell dimension")?);
        let r = eops::try_remove_cell(&mut self.g, h, i).map_err(|e| self.euler_failure(&e));
        self.refresh();
        let n = r?;
        self.info.raise_hook_error()?;
        Ok(n)
    }

    /// CGAL's `is_removable<i>(d)`: i <= dim and, for i <= dim - 2, the cell has degree 2.
    fn is_removable(&self, d: i64, i: i64) -> PyResult<bool> {
        Ok(eops::is_removable(&self.g, self.handle(d)?, self.dim_index(i, "cell dimension")?))
    }

    /// CGAL's `contract_cell<i>(d)`: contracts the i-cell of d, 1 <= i <= dim (the
    /// (i-1)-cells at its ends merge; a loop or a lone dart vanishes); may change the space
    /// (`contract_cell_keeping_homology` never does). Returns the number of darts removed.
    fn contract_cell(&mut self, d: i64, i: i64) -> PyResult<usize> {
        let (h, i) = (self.handle(d)?, self.dim_index(i, "cell dimension")?);
        let r = eops::try_contract_cell(&mut self.g, h, i).map_err(|e| self.euler_failure(&e));
        self.refresh();
        let n = r?;
        self.info.raise_hook_error()?;
        Ok(n)
    }

    /// CGAL's `is_contractible<i>(d)`: 1 <= i <= dim and, for i >= 2, dual degree 2.
    fn is_contractible(&self, d: i64, i: i64) -> PyResult<bool> {
        Ok(eops::is_contractible(&self.g, self.handle(d)?, self.dim_index(i, "cell dimension")?))
    }

    /// remove_cell_keeping_homology(d, i): removes the i-cell of d only when the space
    /// stays the same (degree 2, two distinct interior (i+1)-cells merge, nothing falls
    /// apart; or a dangling edge); PreconditionError naming why otherwise. Returns the
    /// number of darts removed.
    fn remove_cell_keeping_homology(&mut self, d: i64, i: i64) -> PyResult<usize> {
        let (h, i) = (self.handle(d)?, self.dim_index(i, "cell dimension")?);
        let before = self.g.dart_count();
        let r = eops::try_remove_cell_keeping_homology(&mut self.g, h, i).map_err(|e| self.euler_failure(&e));
        self.refresh();
        r?;
        self.info.raise_hook_error()?;
        Ok(before - self.g.dart_count())
    }

    /// Whether remove_cell_keeping_homology(d, i) applies.
    fn is_removable_keeping_homology(&self, d: i64, i: i64) -> PyResult<bool> {
        Ok(eops::is_removable_keeping_homology(&self.g, self.handle(d)?, self.dim_index(i, "cell dimension")?))
    }

    /// contract_cell_keeping_homology(d, i): contracts the i-cell of d only when the space
    /// stays the same (two distinct interior (i-1)-cells at its ends, nothing falls apart);
    /// returns the number of darts removed.
    fn contract_cell_keeping_homology(&mut self, d: i64, i: i64) -> PyResult<usize> {
        let (h, i) = (self.handle(d)?, self.dim_index(i, "cell dimension")?);
        let before = self.g.dart_count();
        let r = eops::try_contract_cell_keeping_homology(&mut self.g, h, i).map_err(|e| self.euler_failure(&e));
        self.refresh();
        r?;
        self.info.raise_hook_error()?;
        Ok(before - self.g.dart_count())
    }

    /// Whether contract_cell_keeping_homology(d, i) applies.
    fn is_contractible_keeping_homology(&self, d: i64, i: i64) -> PyResult<bool> {
        Ok(eops::is_contractible_keeping_homology(&self.g, self.handle(d)?, self.dim_index(i, "cell dimension")?))
    }

    /// CGAL's make_combinatorial_tetrahedron(): adds a tetrahedron (a 3-map); returns a dart.
    fn make_combinatorial_tetrahedron(&mut self) -> PyResult<usize> {
        if self.g.dim() < 2 {
            return Err(Failure::input("a tetrahedron needs a map of dimension at least 2").into());
        }
        let h = self.g.make_combinatorial_tetrahedron();
        Ok(self.index_of(h))
    }

    /// CGAL's make_combinatorial_hexahedron(): adds a hexahedron; returns a dart.
    fn make_combinatorial_hexahedron(&mut self) -> PyResult<usize> {
        if self.g.dim() < 2 {
            return Err(Failure::input("a hexahedron needs a map of dimension at least 2").into());
        }
        let h = self.g.make_combinatorial_hexahedron();
        Ok(self.index_of(h))
    }
}
