//! The modelling API of `gmap.GMap` under CGAL's names (`Generalized_map` and
//! `Linear_cell_complex_for_generalized_map`): constructors with points, points per dart,
//! marks, Python values on darts and cells (CGAL's `info`) with merge and split functors,
//! navigation, the construction operations, closing and sewing by points, transforms.
//!
//! Every method is a thin call of the kernel (`gmap::core::GMap`, `gmap::ops::construct`,
//! `gmap::ops::euler::ops`, `gmap::ops::build::sew3_same_facets`) on the map's editable
//! storage; a refusal is a typed error (PreconditionError naming the dart in the map's
//! numbering, InputError for a bad argument, LimitError past the memory policy), never a
//! panic.
//!
//! # Python values on cells
//!
//! The kernel's cells carry [`Labels`]; a cell's Python value is an int key under the
//! reserved label [`INFO_KEY`] into [`Store::values`], shared with the merge and split hooks
//! the map's label slots get once a value is set on a cell of that dimension. The hooks are
//! CGAL's functors: when two cells carrying values become one, `on_merge(kept, other)` gives
//! the value kept (without a functor the first cell's value stays); when one becomes two,
//! `on_split(value)` gives the pair `(kept, new)` (without a functor both cells hold the same
//! object). An exception in a functor is raised when the operation returns (the operation
//! itself is done). Keys of cells that disappeared are dropped at each renumbering; the
//! key never reaches a file, `labels()` or `to_text()` ([`without_info`]). Darts' values are
//! kept by handle and dropped with their darts.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, MutexGuard};

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};

use gmap::core::{AttrId, AttributeAt, Cells, DartId, LabelValue, LabelledGMap, Labels, MakeError, MarkId};
use gmap::ops::construct::{self as cons, ConstructError};
use gmap::ops::euler::ops as eops;

use super::{check_darts_memory, PyGMap};
use crate::errors::{Failure, Kind, Res};

/// The reserved label that holds a cell's key into [`Store::values`]; a label name starting
/// with it is refused by `set_label`, and no reader makes one (a control character).
pub const INFO_KEY: &str = "\u{1}info";

/// The attribute tuple of [`LabelledGMap`].
type L6 = (Cells<Labels>, Cells<Labels>, Cells<Labels>, Cells<Labels>, Cells<Labels>, Cells<Labels>);

/// The largest cell dimension with values (the labels' slots: 0 to 5).
const MAX_INFO_DIM: usize = 5;

/// The Python values of the cells, shared with the hooks of the map's label slots.
#[derive(Default)]
pub struct Store {
    values: HashMap<i64, Py<PyAny>>,
    next: i64,
    on_merge: [Option<Py<PyAny>>; MAX_INFO_DIM + 1],
    on_split: [Option<Py<PyAny>>; MAX_INFO_DIM + 1],
    /// the first exception a functor raised during the operation running now
    error: Option<PyErr>,
}

/// The Python values of a map: of its darts by handle, of its cells through [`Store`].
#[derive(Default)]
pub struct Info {
    darts: HashMap<DartId, Py<PyAny>>,
    store: Arc<Mutex<Store>>,
    /// the dimensions whose label slot has the hooks
    hooked: [bool; MAX_INFO_DIM + 1],
}

fn lock(s: &Mutex<Store>) -> MutexGuard<'_, Store> {
    // a functor that panicked cannot leave the store half-written (each write is one
    // insert): the data stays usable
    s.lock().unwrap_or_else(|e| e.into_inner())
}

fn key(l: &Labels) -> Option<i64> {
    match l.get(INFO_KEY) {
        Some(LabelValue::Int(k)) => Some(*k),
        _ => None,
    }
}

fn merge_hook(s: &Mutex<Store>, i: usize, kept: &mut Labels, other: Labels) {
    let Some(o) = key(&other) else { return };
    let Some(k) = key(kept) else {
        // the cell that stays had no value: it takes the other's
        kept.set(INFO_KEY, LabelValue::Int(o));
        return;
    };
    Python::with_gil(|py| {
        let (f, a, b) = {
            let st = lock(s);
            let get = |k: &i64| st.values.get(k).map(|v| v.clone_ref(py)).unwrap_or_else(|| py.None());
            (st.on_merge[i].as_ref().map(|f| f.clone_ref(py)), get(&k), get(&o))
        };
        let r = f.map(|f| f.call1(py, (a, b)));
        let mut st = lock(s);
        st.values.remove(&o);
        match r {
            Some(Ok(v)) => drop(st.values.insert(k, v)),
            Some(Err(e)) => drop(st.error.get_or_insert(e)),
            None => {}
        }
    })
}

fn split_hook(s: &Mutex<Store>, i: usize, kept: &mut Labels, copy: &mut Labels) {
    let Some(k) = key(kept) else { return };
    Python::with_gil(|py| {
        let (f, v, n) = {
            let mut st = lock(s);
            let n = st.next;
            st.next += 1;
            let v = st.values.get(&k).map(|v| v.clone_ref(py)).unwrap_or_else(|| py.None());
            (st.on_split[i].as_ref().map(|f| f.clone_ref(py)), v, n)
        };
        copy.set(INFO_KEY, LabelValue::Int(n));
        let r = match f {
            None => Ok((v.clone_ref(py), v)),
            Some(f) => f.call1(py, (v,)).and_then(|t| t.extract::<(PyObject, PyObject)>(py)),
        };
        let mut st = lock(s);
        match r {
            Ok((a, b)) => {
                st.values.insert(k, a);
                st.values.insert(n, b);
            }
            Err(e) => {
                let v = st.values.get(&k).map(|v| v.clone_ref(py)).unwrap_or_else(|| py.None());
                st.values.insert(n, v);
                st.error.get_or_insert(e);
            }
        }
    })
}

fn hook_dim<const I: usize>(g: &mut LabelledGMap, store: &Arc<Mutex<Store>>)
where
    L6: AttributeAt<I, Value = Labels>,
{
    let s = store.clone();
    g.set_on_merge::<I>(move |kept, other| merge_hook(&s, I, kept, other));
    let s = store.clone();
    g.set_on_split::<I>(move |kept, copy| split_hook(&s, I, kept, copy));
}

fn keys_dim<const I: usize>(g: &LabelledGMap, out: &mut Vec<i64>)
where
    L6: AttributeAt<I, Value = Labels>,
{
    out.extend(g.attributes::<I>().filter_map(|(_, l)| key(l)));
}

fn strip_dim<const I: usize>(g: &mut LabelledGMap)
where
    L6: AttributeAt<I, Value = Labels>,
{
    let ids: Vec<(AttrId, usize)> =
        g.attributes::<I>().filter(|(_, l)| key(l).is_some()).map(|(id, l)| (id, l.len())).collect();
    for (id, len) in ids {
        if len == 1 {
            if let Some(d) = g.attribute_dart::<I>(id) {
                g.remove_attribute::<I>(d);
            }
        } else if let Some(l) = g.attribute_by_id_mut::<I>(id) {
            l.remove(INFO_KEY);
        }
    }
}

fn cell_key_dim<const I: usize>(g: &LabelledGMap, d: DartId) -> Option<i64>
where
    L6: AttributeAt<I, Value = Labels>,
{
    g.attribute::<I>(d).and_then(key)
}

fn set_key_dim<const I: usize>(g: &mut LabelledGMap, d: DartId, k: Option<i64>)
where
    L6: AttributeAt<I, Value = Labels>,
{
    match (g.attribute_mut::<I>(d), k) {
        (Some(l), Some(k)) => drop(l.set(INFO_KEY, LabelValue::Int(k))),
        (Some(l), None) => {
            l.remove(INFO_KEY);
            if l.is_empty() {
                g.remove_attribute::<I>(d);
            }
        }
        (None, Some(k)) => {
            let mut l = Labels::new();
            l.set(INFO_KEY, LabelValue::Int(k));
            g.set_attribute::<I>(d, l);
        }
        (None, None) => {}
    }
}

/// `$f::<i>($args)` for a runtime `i` in 0..=5 (the callers check the range first).
macro_rules! at_dim {
    ($i:expr, $f:ident($($a:expr),*), $default:expr) => {
        match $i {
            0 => $f::<0>($($a),*),
            1 => $f::<1>($($a),*),
            2 => $f::<2>($($a),*),
            3 => $f::<3>($($a),*),
            4 => $f::<4>($($a),*),
            5 => $f::<5>($($a),*),
            _ => $default,
        }
    };
}

/// A copy of `g` without the keys of the Python values (what a file and `to_text` get).
pub fn without_info(g: &LabelledGMap) -> LabelledGMap {
    let mut c = g.clone();
    for i in 0..=g.dim().min(MAX_INFO_DIM) {
        at_dim!(i, strip_dim(&mut c), ());
    }
    c
}

impl Info {
    /// Drops the values of darts and cells that are gone (after an edit renumbered the map).
    pub fn prune(&mut self, g: &LabelledGMap) {
        self.darts.retain(|&h, _| g.contains(h));
        if !self.hooked.iter().any(|&b| b) {
            return;
        }
        let mut live = Vec::new();
        for i in 0..=g.dim().min(MAX_INFO_DIM) {
            at_dim!(i, keys_dim(g, &mut live), ());
        }
        let live: std::collections::HashSet<i64> = live.into_iter().collect();
        lock(&self.store).values.retain(|k, _| live.contains(k));
    }

    /// Raises the first exception a functor raised during the last operation.
    pub fn raise_hook_error(&self) -> PyResult<()> {
        match lock(&self.store).error.take() {
            Some(e) => Err(e),
            None => Ok(()),
        }
    }

    /// The values of a copy `g` of the map (`old[k]` and `new[k]` the handles of dart `k` in
    /// the map and in the copy), with the functors; `g` gets the hooks.
    pub fn copy_to(&self, g: &mut LabelledGMap, old: &[DartId], new: &[DartId]) -> Info {
        Python::with_gil(|py| {
            let st = lock(&self.store);
            let store = Store {
                values: st.values.iter().map(|(&k, v)| (k, v.clone_ref(py))).collect(),
                next: st.next,
                on_merge: std::array::from_fn(|i| st.on_merge[i].as_ref().map(|f| f.clone_ref(py))),
                on_split: std::array::from_fn(|i| st.on_split[i].as_ref().map(|f| f.clone_ref(py))),
                error: None,
            };
            let mut info = Info { darts: HashMap::new(), store: Arc::new(Mutex::new(store)), hooked: self.hooked };
            for (k, h) in old.iter().enumerate() {
                if let (Some(v), Some(&n)) = (self.darts.get(h), new.get(k)) {
                    info.darts.insert(n, v.clone_ref(py));
                }
            }
            for i in 0..=g.dim().min(MAX_INFO_DIM) {
                if info.hooked[i] {
                    at_dim!(i, hook_dim(g, &info.store), ());
                }
            }
            info
        })
    }

    fn hook(&mut self, g: &mut LabelledGMap, i: usize) {
        if !self.hooked[i] {
            at_dim!(i, hook_dim(g, &self.store), ());
            self.hooked[i] = true;
        }
    }
}

/// A point from Python: a sequence (tuple, list, numpy array) of 2 or 3 finite floats.
fn point_of(p: &Bound<'_, PyAny>) -> Res<[f64; 3]> {
    let v: Vec<f64> = p
        .extract()
        .map_err(|_| Failure::input("a point is a sequence of 2 or 3 floats (a tuple, a list, a numpy array)"))?;
    if !(2..=3).contains(&v.len()) || v.iter().any(|x| !x.is_finite()) {
        return Err(Failure::input(format!("the point {v:?}: a point has 2 or 3 finite coordinates")));
    }
    Ok([v[0], v[1], v.get(2).copied().unwrap_or(0.0)])
}

/// Points from Python: a sequence of points or an array of shape (k, 2) or (k, 3).
fn points_of(p: &Bound<'_, PyAny>) -> Res<Vec<[f64; 3]>> {
    let items: Vec<Bound<'_, PyAny>> = p
        .try_iter()
        .and_then(|it| it.collect::<PyResult<_>>())
        .map_err(|_| Failure::input("points are a sequence of points"))?;
    items.iter().map(point_of).collect()
}

fn vector_of(v: [f64; 3], what: &str) -> Res<[f64; 3]> {
    if v.iter().any(|x| !x.is_finite()) {
        return Err(Failure::input(format!("the {what} {v:?} is not finite")));
    }
    Ok(v)
}

fn make_failure(e: MakeError) -> Failure {
    let kind = if matches!(e, MakeError::TooLarge { .. }) { Kind::Limit } else { Kind::Input };
    Failure::new(kind, e.to_string())
}

fn tuple3(py: Python<'_>, p: [f64; 3]) -> PyResult<PyObject> {
    Ok(PyTuple::new(py, p)?.into_any().unbind())
}

impl PyGMap {
    /// A refused construction (PreconditionError, or InputError for a bad argument), its
    /// dart in the map's numbering.
    fn construct_failure(&self, e: &ConstructError) -> Failure {
        let d = |h: DartId| self.dart_text(h);
        let (kind, message, dart) = match e {
            ConstructError::NoSuchDart(h) => (Kind::Input, format!("{} does not exist", d(*h)), Some(*h)),
            ConstructError::NotFree { dart, alpha } => {
                (Kind::Precondition, format!("{} is not {alpha}-free", d(*dart)), Some(*dart))
            }
            ConstructError::NoPoint(h) => {
                (Kind::Precondition, format!("the vertex of {} has no point", d(*h)), Some(*h))
            }
            ConstructError::TooFewSteps { .. } | ConstructError::BadAxis(_) | ConstructError::BadParameter { .. } => {
                (Kind::Input, e.to_string(), None)
            }
            ConstructError::BadShape { dart, what } => {
                (Kind::Precondition, format!("the cell of {} is not {what}", d(*dart)), Some(*dart))
            }
            ConstructError::NotConvex { volume, face, vertex } => (
                Kind::Precondition,
                format!(
                    "the volume of {} is not convex: the vertex of {} is beyond the plane of the face of {}",
                    d(*volume),
                    d(*vertex),
                    d(*face)
                ),
                Some(*volume),
            ),
            ConstructError::Euler(x) => return self.euler_failure(x),
            other => (Kind::Precondition, other.to_string(), None),
        };
        self.with_dart(Failure::new(kind, message), dart)
    }

    /// Runs a maker of darts after checking the memory for `darts` more; returns its dart.
    fn made(&mut self, darts: u64, f: impl FnOnce(&mut LabelledGMap) -> Result<DartId, MakeError>) -> PyResult<usize> {
        check_darts_memory(self.g.dim(), self.g.dart_count() as u64 + darts)?;
        let h = f(&mut self.g).map_err(make_failure)?;
        Ok(self.index_of(h))
    }

    fn info_dim(&self, i: i64) -> Res<usize> {
        let i = self.dim_index(i, "cell dimension")?;
        if i > MAX_INFO_DIM {
            return Err(Failure::input(format!("cells of dimension {i} hold no values (at most {MAX_INFO_DIM})")));
        }
        Ok(i)
    }

    fn mark_id(&self, m: i64) -> Res<MarkId> {
        usize::try_from(m)
            .ok()
            .and_then(|k| self.marks.get(k).copied().flatten())
            .ok_or_else(|| Failure::input(format!("mark {m} is not reserved (get_new_mark gives marks)")))
    }

    /// Ends a construction: renumbers, then raises a functor's exception.
    fn after_construct<T>(&mut self, r: Result<T, ConstructError>) -> PyResult<T> {
        let r = r.map_err(|e| self.construct_failure(&e));
        self.refresh();
        let v = r?;
        self.info.raise_hook_error()?;
        Ok(v)
    }

    fn handles(&self, path: &[i64]) -> Res<Vec<DartId>> {
        path.iter().map(|&d| self.handle(d)).collect()
    }

    /// The size of the i-cell of `d` (its darts), for the memory estimates.
    fn cell_size(&self, h: DartId, i: usize) -> u64 {
        self.g.cell_darts(h, i).len() as u64
    }
}

#[pymethods]
impl PyGMap {
    // --- constructors (CGAL's Generalized_map and LCC's make_*) ---

    /// CGAL's make_edge(): an isolated edge without points (two darts alpha_0-linked);
    /// returns its first dart.
    fn make_edge(&mut self) -> PyResult<usize> {
        self.made(2, |g| g.try_make_edge())
    }

    /// LCC's make_segment(p0, p1, closed=False): an isolated edge from p0 to p1; closed,
    /// the edge of a 2-map gets its two faces' sides (CGAL's closed segment). Returns the
    /// dart at p0.
    #[pyo3(signature = (p0, p1, closed = false))]
    fn make_segment(&mut self, p0: &Bound<'_, PyAny>, p1: &Bound<'_, PyAny>, closed: bool) -> PyResult<usize> {
        let p = [point_of(p0)?, point_of(p1)?];
        if closed {
            self.made(4, |g| g.try_make_segment_closed(p))
        } else {
            self.made(2, |g| g.try_make_segment(p))
        }
    }

    /// LCC's make_triangle(p0, p1, p2): an isolated triangle; returns the dart at p0.
    fn make_triangle(
        &mut self,
        p0: &Bound<'_, PyAny>,
        p1: &Bound<'_, PyAny>,
        p2: &Bound<'_, PyAny>,
    ) -> PyResult<usize> {
        let p = [point_of(p0)?, point_of(p1)?, point_of(p2)?];
        self.made(6, |g| g.try_make_polygon(&p))
    }

    /// LCC's make_quadrangle(p0, p1, p2, p3): an isolated quadrangle; returns the dart at p0.
    fn make_quadrangle(
        &mut self,
        p0: &Bound<'_, PyAny>,
        p1: &Bound<'_, PyAny>,
        p2: &Bound<'_, PyAny>,
        p3: &Bound<'_, PyAny>,
    ) -> PyResult<usize> {
        let p = [point_of(p0)?, point_of(p1)?, point_of(p2)?, point_of(p3)?];
        self.made(8, |g| g.try_make_polygon(&p))
    }

    /// make_polygon(points): an isolated polygon on the points in order (k >= 1 corners,
    /// 2k darts); returns the dart at `points[0]`.
    fn make_polygon(&mut self, points: &Bound<'_, PyAny>) -> PyResult<usize> {
        let p = points_of(points)?;
        self.made(2 * p.len() as u64, |g| g.try_make_polygon(&p))
    }

    /// CGAL's make_combinatorial_polygon(k): an isolated polygon of k corners without
    /// points; returns a dart of it.
    fn make_combinatorial_polygon(&mut self, k: usize) -> PyResult<usize> {
        self.made(2 * k as u64, |g| g.try_make_combinatorial_polygon(k))
    }

    /// LCC's make_tetrahedron(p0, p1, p2, p3): a tetrahedron (12 darts in a 2-map, 24 in a
    /// 3-map); returns the dart at p0.
    fn make_tetrahedron(
        &mut self,
        p0: &Bound<'_, PyAny>,
        p1: &Bound<'_, PyAny>,
        p2: &Bound<'_, PyAny>,
        p3: &Bound<'_, PyAny>,
    ) -> PyResult<usize> {
        let p = [point_of(p0)?, point_of(p1)?, point_of(p2)?, point_of(p3)?];
        self.made(24, |g| g.try_make_tetrahedron(p))
    }

    /// LCC's make_hexahedron(p0, ..., p7) with CGAL's order of the corners; returns the
    /// dart at p0.
    #[allow(clippy::too_many_arguments)]
    fn make_hexahedron(
        &mut self,
        p0: &Bound<'_, PyAny>,
        p1: &Bound<'_, PyAny>,
        p2: &Bound<'_, PyAny>,
        p3: &Bound<'_, PyAny>,
        p4: &Bound<'_, PyAny>,
        p5: &Bound<'_, PyAny>,
        p6: &Bound<'_, PyAny>,
        p7: &Bound<'_, PyAny>,
    ) -> PyResult<usize> {
        let mut p = [[0.0; 3]; 8];
        for (k, q) in [p0, p1, p2, p3, p4, p5, p6, p7].into_iter().enumerate() {
            p[k] = point_of(q)?;
        }
        self.made(48, |g| g.try_make_hexahedron(p))
    }

    /// make_prism(bottom, top): the prism over a k-gon, `top[j]` above `bottom[j]` (k >= 3;
    /// k = 3 is LCC's make_triangular_prism); returns the dart at `bottom[0]`.
    fn make_prism(&mut self, bottom: &Bound<'_, PyAny>, top: &Bound<'_, PyAny>) -> PyResult<usize> {
        let (b, t) = (points_of(bottom)?, points_of(top)?);
        self.made(12 * b.len() as u64, |g| g.try_make_prism(&b, &t))
    }

    /// CGAL's clear(): removes every dart (marks stay reserved, unmarked).
    fn clear(&mut self) {
        self.g.clear();
        self.refresh();
    }

    // --- points (LCC's point(d), the vertex attributes) ---

    /// LCC's point(d): the point of the vertex of d as a tuple (x, y, z), or None.
    fn point(&self, py: Python<'_>, d: i64) -> PyResult<Option<PyObject>> {
        self.g.point(self.handle(d)?).map(|p| tuple3(py, p)).transpose()
    }

    /// set_point(d, p): sets the point of the vertex of d (2 or 3 coordinates; None
    /// removes it).
    #[pyo3(signature = (d, p))]
    fn set_point(&mut self, d: i64, p: Option<&Bound<'_, PyAny>>) -> PyResult<()> {
        let h = self.handle(d)?;
        let p = p.map(point_of).transpose()?;
        self.g.set_point(h, p);
        self.touched();
        Ok(())
    }

    /// The point of every dart's vertex as a float64 array of shape (darts, 3), a row of
    /// NaN for a vertex without a point (per dart; `points` gives one row per vertex).
    fn dart_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let mut v = Vec::with_capacity(self.ids.len() * 3);
        for &h in &self.ids {
            v.extend_from_slice(&self.g.point(h).unwrap_or([f64::NAN; 3]));
        }
        let n = self.ids.len();
        Ok(PyArray1::from_vec(py, v).reshape([n, 3])?.into_any())
    }

    /// LCC's `barycenter<i>(d)`: the mean of the points of the vertices of the i-cell of d,
    /// or None when one has no point.
    fn barycenter(&self, py: Python<'_>, d: i64, i: i64) -> PyResult<Option<PyObject>> {
        let (h, i) = (self.handle(d)?, self.dim_index(i, "cell dimension")?);
        let b = self.g.try_barycenter(h, i).map_err(|e| self.edit_failure(&e))?;
        b.map(|p| tuple3(py, p)).transpose()
    }

    /// The smallest box holding every point, ((xmin, ymin, zmin), (xmax, ymax, zmax)), or
    /// None when no vertex has a point.
    fn bounding_box(&self, py: Python<'_>) -> PyResult<Option<(PyObject, PyObject)>> {
        match self.g.bounding_box() {
            Some([a, b]) => Ok(Some((tuple3(py, a)?, tuple3(py, b)?))),
            None => Ok(None),
        }
    }

    /// translate(v, d=None, i=None): moves every point by v, or (with d and i) those of the
    /// vertices of the i-cell of d (i = dim + 1: its connected component).
    #[pyo3(signature = (v, d = None, i = None))]
    fn translate(&mut self, v: [f64; 3], d: Option<i64>, i: Option<i64>) -> PyResult<()> {
        let v = vector_of(v, "translation")?;
        self.transform_points(None, Some(v), d, i)
    }

    /// transform(m, d=None, i=None): applies the affine map m to every point (or to those of
    /// the i-cell of d): a (3, 3) linear matrix, a (3, 4) matrix [M | t] or a (4, 4)
    /// homogeneous one (last row 0 0 0 1), or a Python callable taking and returning a point.
    #[pyo3(signature = (m, d = None, i = None))]
    fn transform(&mut self, m: &Bound<'_, PyAny>, d: Option<i64>, i: Option<i64>) -> PyResult<()> {
        if m.is_callable() && !m.hasattr("shape")? {
            return self.transform_by_callable(m, d, i);
        }
        let rows: Vec<Vec<f64>> = m
            .extract()
            .map_err(|_| Failure::input("transform takes a (3, 3), (3, 4) or (4, 4) matrix of floats or a callable"))?;
        let shape = (rows.len(), rows.first().map_or(0, |r| r.len()));
        if rows.iter().any(|r| r.len() != shape.1) || !matches!(shape, (3, 3) | (3, 4) | (4, 4)) {
            return Err(Failure::input(format!(
                "a transform matrix has shape (3, 3), (3, 4) or (4, 4), not {shape:?} (or rows of unequal length)"
            ))
            .into());
        }
        if rows.iter().flatten().any(|x| !x.is_finite()) {
            return Err(Failure::input("a transform matrix has finite entries").into());
        }
        if shape.0 == 4 && rows[3] != [0.0, 0.0, 0.0, 1.0] {
            return Err(Failure::input(format!(
                "the last row of a (4, 4) affine matrix is 0 0 0 1, not {:?}",
                rows[3]
            ))
            .into());
        }
        let mut a = [[0.0; 4]; 3];
        for r in 0..3 {
            for c in 0..shape.1.min(4) {
                a[r][c] = rows[r][c];
            }
        }
        self.transform_points(Some(gmap::core::Affine(a)), None, d, i)
    }

    // --- normals and the dual ---

    /// LCC's compute_normal_of_cell_2(d): the unit normal of the face of d (Newell's, the
    /// orientation of d gives its sign), or None for a degenerate face.
    fn compute_normal_of_cell_2(&self, py: Python<'_>, d: i64) -> PyResult<Option<PyObject>> {
        let h = self.handle(d)?;
        let r = self.g.try_compute_normal_of_cell_2(h).map_err(|e| self.geometry_failure(&e))?;
        r.map(|p| tuple3(py, p)).transpose()
    }

    /// LCC's compute_normal_of_cell_0(d): the unit mean of the normals of the faces around
    /// the vertex of d, or None when they cancel.
    fn compute_normal_of_cell_0(&self, py: Python<'_>, d: i64) -> PyResult<Option<PyObject>> {
        let h = self.handle(d)?;
        let r = self.g.try_compute_normal_of_cell_0(h).map_err(|e| self.geometry_failure(&e))?;
        r.map(|p| tuple3(py, p)).transpose()
    }

    /// CGAL's dual_points_at_barycenter(): the dual map of a map without boundary, each
    /// vertex at the barycentre of its cell (PreconditionError on a free dart or a vertex
    /// without a point).
    fn dual_points_at_barycenter(&self) -> PyResult<PyGMap> {
        check_darts_memory(self.g.dim(), self.g.dart_count() as u64)?;
        let d = self.g.dual_points_at_barycenter().map_err(|e| self.geometry_failure(&e))?;
        let (dense, _) = d.to_dense_with_ids();
        Ok(PyGMap::from_dense(&dense))
    }

    // --- navigation and shape tests (CGAL's names) ---

    /// CGAL's next(d): alpha_1(alpha_0(d)), the next dart of the face's orientation.
    fn next(&self, d: i64) -> PyResult<usize> {
        let h = self.g.try_next(self.handle(d)?).map_err(|e| self.edit_failure(&e))?;
        Ok(self.number(h))
    }

    /// CGAL's previous(d): alpha_0(alpha_1(d)).
    fn previous(&self, d: i64) -> PyResult<usize> {
        let h = self.g.try_previous(self.handle(d)?).map_err(|e| self.edit_failure(&e))?;
        Ok(self.number(h))
    }

    /// CGAL's `opposite<i>(d)`: alpha_0(alpha_i(d)), the dart on the other side of the
    /// i-sew with the same orientation.
    fn opposite(&self, d: i64, i: i64) -> PyResult<usize> {
        let (h, i) = (self.handle(d)?, self.dim_index(i, "alpha")?);
        let h = self.g.try_opposite(h, i).map_err(|e| self.edit_failure(&e))?;
        Ok(self.number(h))
    }

    /// CGAL's other_orientation(d): alpha_0(d).
    fn other_orientation(&self, d: i64) -> PyResult<usize> {
        let h = self.g.try_other_orientation(self.handle(d)?).map_err(|e| self.edit_failure(&e))?;
        Ok(self.number(h))
    }

    /// degree(d, i): the number of (i+1)-cells around the i-cell of d (CGAL's
    /// `Generalized_map::degree`-style count of incident (i+1)-cells).
    fn degree(&self, d: i64, i: i64) -> PyResult<usize> {
        let (h, i) = (self.handle(d)?, self.dim_index(i, "cell dimension")?);
        self.g.try_degree(h, i).map_err(|e| self.edit_failure(&e).into())
    }

    /// codegree(d, i): the number of (i-1)-cells on the boundary of the i-cell of d.
    fn codegree(&self, d: i64, i: i64) -> PyResult<usize> {
        let (h, i) = (self.handle(d)?, self.dim_index(i, "cell dimension")?);
        self.g.try_codegree(h, i).map_err(|e| self.edit_failure(&e).into())
    }

    /// CGAL's is_face_combinatorial_polygon(d, k): whether the face of d is a closed
    /// polygon of k edges.
    fn is_face_combinatorial_polygon(&self, d: i64, k: usize) -> PyResult<bool> {
        Ok(self.g.is_face_combinatorial_polygon(self.handle(d)?, k))
    }

    /// CGAL's is_volume_combinatorial_hexahedron(d).
    fn is_volume_combinatorial_hexahedron(&self, d: i64) -> PyResult<bool> {
        Ok(self.g.is_volume_combinatorial_hexahedron(self.handle(d)?))
    }

    /// CGAL's is_without_boundary(i) (every dim when i is None): whether no dart is i-free.
    #[pyo3(signature = (i = None))]
    fn is_without_boundary(&self, i: Option<i64>) -> PyResult<bool> {
        let dims: Vec<usize> = match i {
            Some(i) => vec![self.dim_index(i, "alpha")?],
            None => (0..=self.g.dim()).collect(),
        };
        Ok(self.g.darts().all(|x| dims.iter().all(|&i| !self.g.is_free(x, i))))
    }

    /// The darts of the i-cell of d (CGAL's `darts_of_cell<i>`), d first, as a uint32 array.
    fn darts_of_cell<'py>(&self, py: Python<'py>, d: i64, i: i64) -> PyResult<Bound<'py, PyArray1<u32>>> {
        let (h, i) = (self.handle(d)?, self.dim_index(i, "cell dimension")?);
        let v: Vec<u32> = self.g.cell_darts(h, i).into_iter().map(|x| self.number(x) as u32).collect();
        Ok(PyArray1::from_vec(py, v))
    }

    // --- marks (CGAL's get_new_mark / free_mark / mark / unmark / is_marked) ---

    /// CGAL's get_new_mark(): reserves a mark (every dart unmarked); returns its number.
    fn get_new_mark(&mut self) -> usize {
        let m = self.g.reserve_mark();
        match self.marks.iter().position(Option::is_none) {
            Some(k) => {
                self.marks[k] = Some(m);
                k
            }
            None => {
                self.marks.push(Some(m));
                self.marks.len() - 1
            }
        }
    }

    /// CGAL's free_mark(m).
    fn free_mark(&mut self, m: i64) -> PyResult<()> {
        let id = self.mark_id(m)?;
        self.g.free_mark(id);
        self.marks[m as usize] = None;
        Ok(())
    }

    /// CGAL's is_reserved(m).
    fn is_reserved(&self, m: i64) -> bool {
        self.mark_id(m).is_ok()
    }

    /// CGAL's mark(d, m): marks dart d.
    fn mark(&mut self, d: i64, m: i64) -> PyResult<()> {
        let (h, id) = (self.handle(d)?, self.mark_id(m)?);
        self.g.mark(id, h);
        Ok(())
    }

    /// CGAL's unmark(d, m).
    fn unmark(&mut self, d: i64, m: i64) -> PyResult<()> {
        let (h, id) = (self.handle(d)?, self.mark_id(m)?);
        self.g.unmark(id, h);
        Ok(())
    }

    /// CGAL's is_marked(d, m).
    fn is_marked(&self, d: i64, m: i64) -> PyResult<bool> {
        Ok(self.g.is_marked(self.mark_id(m)?, self.handle(d)?))
    }

    /// CGAL's `mark_cell<i>(d, m)`: marks every dart of the i-cell of d.
    fn mark_cell(&mut self, d: i64, i: i64, m: i64) -> PyResult<()> {
        let (h, i, id) = (self.handle(d)?, self.dim_index(i, "cell dimension")?, self.mark_id(m)?);
        for x in self.g.cell_darts(h, i) {
            self.g.mark(id, x);
        }
        Ok(())
    }

    /// CGAL's unmark_all(m).
    fn unmark_all(&mut self, m: i64) -> PyResult<()> {
        let id = self.mark_id(m)?;
        self.g.clear_mark(id);
        Ok(())
    }

    /// CGAL's negate_mark(m): every dart's mark flipped.
    fn negate_mark(&mut self, m: i64) -> PyResult<()> {
        let id = self.mark_id(m)?;
        for h in self.ids.clone() {
            if self.g.is_marked(id, h) {
                self.g.unmark(id, h);
            } else {
                self.g.mark(id, h);
            }
        }
        Ok(())
    }

    /// CGAL's number_of_marked_darts(m).
    fn number_of_marked_darts(&self, m: i64) -> PyResult<usize> {
        let id = self.mark_id(m)?;
        Ok(self.ids.iter().filter(|&&h| self.g.is_marked(id, h)).count())
    }

    /// The darts marked with m, as a uint32 array (in dart order).
    fn marked_darts<'py>(&self, py: Python<'py>, m: i64) -> PyResult<Bound<'py, PyArray1<u32>>> {
        let id = self.mark_id(m)?;
        let v: Vec<u32> =
            (0..self.ids.len()).filter(|&k| self.g.is_marked(id, self.ids[k])).map(|k| k as u32).collect();
        Ok(PyArray1::from_vec(py, v))
    }

    /// orient(m, d): marks one orientation class of the component of d with m (unmarking
    /// the other); returns the size of the marked class. PreconditionError when the
    /// component is not orientable.
    fn orient(&mut self, m: i64, d: i64) -> PyResult<usize> {
        let (id, h) = (self.mark_id(m)?, self.handle(d)?);
        self.g.orient(id, h).map_err(|e| self.edit_failure(&e).into())
    }

    /// Whether mark m is an orientation of the component of d.
    fn is_orientation(&self, m: i64, d: i64) -> PyResult<bool> {
        Ok(self.g.is_orientation(self.mark_id(m)?, self.handle(d)?))
    }

    /// CGAL's reverse_orientation of the component of d (an orientation being a mark in a
    /// G-map): every dart's mark m flipped on the component; PreconditionError when m is
    /// not an orientation of it.
    fn reverse_orientation(&mut self, m: i64, d: i64) -> PyResult<()> {
        let (id, h) = (self.mark_id(m)?, self.handle(d)?);
        if !self.g.is_orientation(id, h) {
            return Err(Failure::new(
                Kind::Precondition,
                format!("mark {m} is not an orientation of the component of dart {d} (orient(m, d) makes one)"),
            )
            .with_dart(d as usize)
            .into());
        }
        self.g.reverse_orientation(id, h);
        Ok(())
    }

    // --- Python values on darts and cells (CGAL's info) ---

    /// info(d, i=None): the Python value of the i-cell of d (CGAL's `info<i>(d)`), or of the
    /// dart d when i is None (CGAL's info(d)); None when it has none.
    #[pyo3(signature = (d, i = None))]
    fn info(&self, py: Python<'_>, d: i64, i: Option<i64>) -> PyResult<PyObject> {
        let h = self.handle(d)?;
        let Some(i) = i else {
            return Ok(self.info.darts.get(&h).map(|v| v.clone_ref(py)).unwrap_or_else(|| py.None()));
        };
        let i = self.info_dim(i)?;
        let k = at_dim!(i, cell_key_dim(&self.g, h), None);
        let st = lock(&self.info.store);
        Ok(k.and_then(|k| st.values.get(&k)).map(|v| v.clone_ref(py)).unwrap_or_else(|| py.None()))
    }

    /// set_info(d, value, i=None): sets the Python value of the i-cell of d (of dart d when
    /// i is None); None removes it. The value follows the cell through every operation
    /// (merged and split by the functors of `set_info_functors`).
    #[pyo3(signature = (d, value, i = None))]
    fn set_info(&mut self, d: i64, value: PyObject, i: Option<i64>) -> PyResult<()> {
        let h = self.handle(d)?;
        let none = Python::with_gil(|py| value.is_none(py));
        let Some(i) = i else {
            if none {
                self.info.darts.remove(&h);
            } else {
                self.info.darts.insert(h, value);
            }
            return Ok(());
        };
        let i = self.info_dim(i)?;
        self.info.hook(&mut self.g, i);
        let old = at_dim!(i, cell_key_dim(&self.g, h), None);
        if none {
            if let Some(k) = old {
                lock(&self.info.store).values.remove(&k);
                at_dim!(i, set_key_dim(&mut self.g, h, None), ());
            }
            return Ok(());
        }
        let k = {
            let mut st = lock(&self.info.store);
            let k = old.unwrap_or_else(|| {
                st.next += 1;
                st.next - 1
            });
            st.values.insert(k, value);
            k
        };
        if old.is_none() {
            at_dim!(i, set_key_dim(&mut self.g, h, Some(k)), ());
        }
        Ok(())
    }

    /// The values of the i-cells, one per cell in the order of `cells(i)` (None for a cell
    /// without one).
    fn infos<'py>(&mut self, py: Python<'py>, i: i64) -> PyResult<Bound<'py, PyList>> {
        let i = self.info_dim(i)?;
        let reps = self.dense().cells(i).reps;
        let out = PyList::empty(py);
        let st = lock(&self.info.store);
        for r in reps {
            let h = self.ids[r.index()];
            let k = at_dim!(i, cell_key_dim(&self.g, h), None);
            out.append(k.and_then(|k| st.values.get(&k)).map(|v| v.clone_ref(py)).unwrap_or_else(|| py.None()))?;
        }
        Ok(out)
    }

    /// CGAL's functors of the i-cells' values: `on_merge(kept, other)` returns the value of
    /// the cell two cells become (default: the first's value stays), `on_split(value)`
    /// returns the pair (kept, new) of values of the two cells one becomes (default: both
    /// hold the same object). None leaves the default.
    #[pyo3(signature = (i, on_merge = None, on_split = None))]
    fn set_info_functors(&mut self, i: i64, on_merge: Option<PyObject>, on_split: Option<PyObject>) -> PyResult<()> {
        let i = self.info_dim(i)?;
        Python::with_gil(|py| {
            for f in [&on_merge, &on_split].into_iter().flatten() {
                if !f.bind(py).is_callable() {
                    return Err(PyErr::from(Failure::input("a functor is a callable (or None)")));
                }
            }
            Ok(())
        })?;
        self.info.hook(&mut self.g, i);
        let mut st = lock(&self.info.store);
        st.on_merge[i] = on_merge;
        st.on_split[i] = on_split;
        Ok(())
    }

    /// CGAL's is_attribute_used for the i-cell of d: whether the cell holds a value.
    fn is_attribute_used(&self, d: i64, i: i64) -> PyResult<bool> {
        let (h, i) = (self.handle(d)?, self.info_dim(i)?);
        let k = at_dim!(i, cell_key_dim(&self.g, h), None);
        Ok(k.is_some_and(|k| lock(&self.info.store).values.contains_key(&k)))
    }

    // --- the operations not under an insert_/remove_ name ---

    /// split_cell(seeds, i): cuts the i-cell of the seeds in two by a new (i-1)-cell along
    /// the closed cut the seeds give (insert_cell_0_in_cell_1, _1_in_cell_2, _2_in_cell_3 in
    /// one routine, 1 <= i <= dim); returns the change of the cell counts.
    fn split_cell(&mut self, seeds: Vec<i64>, i: i64) -> PyResult<Vec<i64>> {
        let (hs, i) = (self.handles(&seeds)?, self.dim_index(i, "cell dimension")?);
        let r = eops::try_split_cell(&mut self.g, &hs, i).map_err(|e| self.euler_failure(&e));
        self.refresh();
        let op = r?;
        self.info.raise_hook_error()?;
        Ok(op.vector.dx().to_vec())
    }

    /// Whether split_cell(seeds, i) applies.
    fn can_split_cell(&self, seeds: Vec<i64>, i: i64) -> PyResult<bool> {
        Ok(eops::can_split_cell(&self.g, &self.handles(&seeds)?, self.dim_index(i, "cell dimension")?))
    }

    /// CGAL's `close<i>()`: every i-free dart gets a new partner bounding new i-cells;
    /// returns the number of darts added.
    fn close(&mut self, i: i64) -> PyResult<usize> {
        let i = self.dim_index(i, "alpha")?;
        let free = self.g.darts().filter(|&x| self.g.is_free(x, i)).count() as u64;
        check_darts_memory(self.g.dim(), self.g.dart_count() as u64 + free)?;
        let r = eops::try_close(&mut self.g, i).map_err(|e| self.euler_failure(&e));
        self.refresh();
        let rep = r?;
        self.info.raise_hook_error()?;
        Ok(rep.new_darts)
    }

    /// Whether close(i) applies.
    fn can_close(&self, i: i64) -> PyResult<bool> {
        Ok(eops::can_close(&self.g, self.dim_index(i, "alpha")?))
    }

    /// CGAL's sew3_same_facets(): 3-sews every pair of 3-free faces on the same points;
    /// returns the number of pairs sewn.
    fn sew3_same_facets(&mut self) -> PyResult<usize> {
        let r = gmap::ops::build::sew3_same_facets(&mut self.g)
            .map_err(|e| Failure::new(Kind::Precondition, e.to_string()));
        self.touched();
        let n = r?;
        self.info.raise_hook_error()?;
        Ok(n)
    }

    /// extrude_cell(d, i, v): the i-cell of d (on the boundary) swept along v into an
    /// (i+1)-cell; returns (dart of the new cell at d, dart over d in the moved copy).
    fn extrude_cell(&mut self, d: i64, i: i64, v: [f64; 3]) -> PyResult<(usize, usize)> {
        let (h, i, v) = (self.handle(d)?, self.dim_index(i, "cell dimension")?, vector_of(v, "vector")?);
        check_darts_memory(self.g.dim(), self.g.dart_count() as u64 + self.cell_size(h, i) * 2 * (i as u64 + 2))?;
        let r = cons::try_extrude_cell(&mut self.g, h, i, v);
        let e = self.after_construct(r)?;
        Ok((self.number(e.cell), self.number(e.top)))
    }

    /// Whether extrude_cell(d, i, v) applies.
    fn can_extrude_cell(&self, d: i64, i: i64) -> PyResult<bool> {
        Ok(cons::can_extrude_cell(&self.g, self.handle(d)?, self.dim_index(i, "cell dimension")?))
    }

    /// extrude_cell_along_path(d, i, path): the i-cell of d swept along a path of edges
    /// (one dart per edge); returns the (cell, top) pair of each step.
    fn extrude_cell_along_path(&mut self, d: i64, i: i64, path: Vec<i64>) -> PyResult<Vec<(usize, usize)>> {
        let (h, i, hs) = (self.handle(d)?, self.dim_index(i, "cell dimension")?, self.handles(&path)?);
        let more = self.cell_size(h, i).saturating_mul(2 * (i as u64 + 2)).saturating_mul(hs.len() as u64);
        check_darts_memory(self.g.dim(), (self.g.dart_count() as u64).saturating_add(more))?;
        let r = cons::try_extrude_cell_along_path(&mut self.g, h, i, &hs);
        let v = self.after_construct(r)?;
        Ok(v.iter().map(|e| (self.number(e.cell), self.number(e.top))).collect())
    }

    /// Whether extrude_cell_along_path(d, i, path) applies.
    fn can_extrude_cell_along_path(&self, d: i64, i: i64, path: Vec<i64>) -> PyResult<bool> {
        let (h, i, hs) = (self.handle(d)?, self.dim_index(i, "cell dimension")?, self.handles(&path)?);
        Ok(cons::can_extrude_cell_along_path(&self.g, h, i, &hs))
    }

    /// revolve(d, p, origin, direction, steps): the p-dimensional profile of d (its
    /// component, on the boundary, with points) revolved about the axis in `steps` >= 3
    /// steps; returns a dart of each step's wall.
    fn revolve(&mut self, d: i64, p: i64, origin: [f64; 3], direction: [f64; 3], steps: usize) -> PyResult<Vec<usize>> {
        let (h, p) = (self.handle(d)?, self.dim_index(p, "profile dimension")?);
        let axis = cons::Axis::new(vector_of(origin, "axis origin")?, vector_of(direction, "axis direction")?);
        let prof = self.g.orbit(h, gmap::core::AlphaSet::of(&(0..=p).collect::<Vec<_>>())).len() as u64;
        let more = prof.saturating_mul(2 * (p as u64 + 2)).saturating_mul(steps as u64);
        check_darts_memory(self.g.dim(), (self.g.dart_count() as u64).saturating_add(more))?;
        let r = cons::try_revolve(&mut self.g, h, p, &axis, steps);
        let v = self.after_construct(r)?;
        Ok(v.walls.iter().map(|&w| self.number(w)).collect())
    }

    /// Whether revolve(d, p, origin, direction, steps) applies.
    fn can_revolve(&self, d: i64, p: i64, origin: [f64; 3], direction: [f64; 3], steps: usize) -> PyResult<bool> {
        let (h, p) = (self.handle(d)?, self.dim_index(p, "profile dimension")?);
        Ok(cons::can_revolve(&self.g, h, p, &cons::Axis::new(origin, direction), steps))
    }

    /// triangulate_face_fan(d): the face of d cut into triangles by edges from the vertex
    /// of d; returns the number of edges added.
    fn triangulate_face_fan(&mut self, d: i64) -> PyResult<usize> {
        let h = self.handle(d)?;
        let r = cons::try_triangulate_face_fan(&mut self.g, h);
        self.after_construct(r)
    }

    /// Whether triangulate_face_fan(d) applies.
    fn can_triangulate_face_fan(&self, d: i64) -> PyResult<bool> {
        Ok(cons::can_triangulate_face_fan(&self.g, self.handle(d)?))
    }

    /// triangulate_face_barycentric(d): a vertex at the face's barycentre joined to every
    /// corner; returns a dart of the new vertex.
    fn triangulate_face_barycentric(&mut self, d: i64) -> PyResult<usize> {
        let h = self.handle(d)?;
        let r = cons::try_triangulate_face_barycentric(&mut self.g, h);
        let x = self.after_construct(r)?;
        Ok(self.number(x))
    }

    /// Whether triangulate_face_barycentric(d) applies.
    fn can_triangulate_face_barycentric(&self, d: i64) -> PyResult<bool> {
        Ok(cons::can_triangulate_face_barycentric(&self.g, self.handle(d)?))
    }

    /// tetrahedralize_volume(d): the volume of d cut into tetrahedra from its barycentre;
    /// returns a dart of the new vertex.
    fn tetrahedralize_volume(&mut self, d: i64) -> PyResult<usize> {
        let h = self.handle(d)?;
        check_darts_memory(self.g.dim(), self.g.dart_count() as u64 + 8 * self.cell_size(h, 3.min(self.g.dim())))?;
        let r = cons::try_tetrahedralize_volume(&mut self.g, h);
        let x = self.after_construct(r)?;
        Ok(self.number(x))
    }

    /// Whether tetrahedralize_volume(d) applies.
    fn can_tetrahedralize_volume(&self, d: i64) -> PyResult<bool> {
        Ok(cons::can_tetrahedralize_volume(&self.g, self.handle(d)?))
    }

    /// chamfer_vertex(d, t): the vertex of d cut off at fraction t (0 < t < 1) of its
    /// edges; returns a dart of the new face.
    fn chamfer_vertex(&mut self, d: i64, t: f64) -> PyResult<usize> {
        let h = self.handle(d)?;
        let r = cons::try_chamfer_vertex(&mut self.g, h, t);
        let x = self.after_construct(r)?;
        Ok(self.number(x))
    }

    /// Whether chamfer_vertex(d, t) applies.
    fn can_chamfer_vertex(&self, d: i64, t: f64) -> PyResult<bool> {
        Ok(cons::can_chamfer_vertex(&self.g, self.handle(d)?, t))
    }

    /// chamfer_edge(d, t): the edge of d bevelled at fraction t; returns a dart of the new
    /// face.
    fn chamfer_edge(&mut self, d: i64, t: f64) -> PyResult<usize> {
        let h = self.handle(d)?;
        let r = cons::try_chamfer_edge(&mut self.g, h, t);
        let x = self.after_construct(r)?;
        Ok(self.number(x))
    }

    /// Whether chamfer_edge(d, t) applies.
    fn can_chamfer_edge(&self, d: i64, t: f64) -> PyResult<bool> {
        Ok(cons::can_chamfer_edge(&self.g, self.handle(d)?, t))
    }

    /// merge_volumes(d): the two volumes on the sides of the face of d become one (the
    /// face removed).
    fn merge_volumes(&mut self, d: i64) -> PyResult<()> {
        let h = self.handle(d)?;
        let r = cons::try_merge_volumes(&mut self.g, h);
        self.after_construct(r)
    }

    /// Whether merge_volumes(d) applies.
    fn can_merge_volumes(&self, d: i64) -> PyResult<bool> {
        Ok(cons::can_merge_volumes(&self.g, self.handle(d)?))
    }

    /// split_volume(path): the volume cut along a closed path of edges (one dart per edge)
    /// by a new face; returns a dart of it.
    fn split_volume(&mut self, path: Vec<i64>) -> PyResult<usize> {
        let hs = self.handles(&path)?;
        let r = cons::try_split_volume(&mut self.g, &hs);
        let x = self.after_construct(r)?;
        Ok(self.number(x))
    }

    /// Whether split_volume(path) applies.
    fn can_split_volume(&self, path: Vec<i64>) -> PyResult<bool> {
        Ok(cons::can_split_volume(&self.g, &self.handles(&path)?))
    }
}

impl PyGMap {
    fn geometry_failure(&self, e: &gmap::core::normals::GeometryError) -> Failure {
        use gmap::core::normals::GeometryError as G;
        match e {
            G::Edit(x) => self.edit_failure(x),
            G::Boundary { dart, alpha } => self.with_dart(
                Failure::new(
                    Kind::Precondition,
                    format!("{} is {alpha}-free: the map has a boundary and no dual", self.dart_text(*dart)),
                ),
                Some(*dart),
            ),
            G::NoPoint(h) => self.with_dart(
                Failure::new(Kind::Precondition, format!("the vertex of {} has no point", self.dart_text(*h))),
                Some(*h),
            ),
            other => Failure::new(Kind::Precondition, other.to_string()),
        }
    }

    /// Moves the points of the whole map, or of the i-cell of d: by the affine map or the
    /// vector.
    fn transform_points(
        &mut self,
        a: Option<gmap::core::Affine>,
        v: Option<[f64; 3]>,
        d: Option<i64>,
        i: Option<i64>,
    ) -> PyResult<()> {
        let f = move |p: [f64; 3]| match (a, v) {
            (Some(a), _) => a.apply(p),
            (None, Some(v)) => [p[0] + v[0], p[1] + v[1], p[2] + v[2]],
            (None, None) => p,
        };
        match (d, i) {
            (None, None) => self.g.transform(f),
            (Some(d), Some(i)) => {
                let h = self.handle(d)?;
                let i = usize::try_from(i).ok().filter(|&i| i <= self.g.dim() + 1).ok_or_else(|| {
                    Failure::input(format!(
                        "cell dimension {i}: from 0 to {} (dim + 1: the component)",
                        self.g.dim() + 1
                    ))
                })?;
                self.g.try_transform_cell(h, i, f).map_err(|e| self.edit_failure(&e))?;
            }
            _ => return Err(Failure::input("give both d and i, or neither").into()),
        }
        self.touched();
        Ok(())
    }

    /// [`PyGMap::transform_points`] by a Python callable: every new point computed first, so
    /// that an exception or a bad point changes nothing.
    fn transform_by_callable(&mut self, f: &Bound<'_, PyAny>, d: Option<i64>, i: Option<i64>) -> PyResult<()> {
        let darts: Vec<DartId> = match (d, i) {
            (None, None) => self.g.darts().collect(),
            (Some(d), Some(i)) => {
                let h = self.handle(d)?;
                let i = usize::try_from(i).ok().filter(|&i| i <= self.g.dim() + 1).ok_or_else(|| {
                    Failure::input(format!(
                        "cell dimension {i}: from 0 to {} (dim + 1: the component)",
                        self.g.dim() + 1
                    ))
                })?;
                if i == self.g.dim() + 1 {
                    self.g.orbit(h, gmap::core::AlphaSet::all(self.g.dim()))
                } else {
                    self.g.cell_darts(h, i)
                }
            }
            _ => return Err(Failure::input("give both d and i, or neither").into()),
        };
        // one dart per vertex: the first met of each vertex orbit
        let mut seen = std::collections::HashSet::new();
        let mut moves = Vec::new();
        for x in darts {
            if self.g.point(x).is_none() || !seen.insert(self.vertex_of(x)) {
                continue;
            }
            let p = self.g.point(x).unwrap_or([0.0; 3]);
            let q = f.call1((PyTuple::new(f.py(), p)?,))?;
            moves.push((x, point_of(&q)?));
        }
        for (x, q) in moves {
            self.g.set_point(x, Some(q));
        }
        self.touched();
        Ok(())
    }

    /// The smallest dart number of the vertex of `x` (a vertex's name for the callable
    /// transform).
    fn vertex_of(&self, x: DartId) -> usize {
        let set = gmap::core::AlphaSet::cell(0, self.g.dim());
        self.g.orbit(x, set).into_iter().map(|y| self.g.dart_index(y)).min().unwrap_or(0)
    }
}
