//! Filtered complexes given cell by cell: simplicial complexes with values, and any cell
//! complex with a value per cell.
//!
//! Values are made monotone as they come in: a cell's value is raised to the maximum of
//! its faces' values (a filtration needs every face present no later than its cofaces).
//! Simplices can be given with a value each, faces not listed taking the minimum over the
//! listed simplices containing them (GUDHI's `SimplexTree.insert`, then
//! `make_filtration_non_decreasing`); per facet (the same with the facets); or by vertex
//! values (the lower-star filtration: a simplex takes its largest vertex value).
//!
//! The diagram comes from the column reduction (`pairing`, private) over every dimension
//! from the top down with clearing. Cost: building the faces of a facet of dimension `n` is
//! `2^(n+1)` subsets; the reduction is near linear on manifolds.

use rustc_hash::FxHashMap;

use gmap_core::labels::{to_dense_labels, LabelValue, LabelledGMap, Labels};

use super::image::{check_field, key};
use super::pairing::{reduce_dim, Entry};
use super::{CellName, Chain, Diagram, PersistenceError};
use crate::arch::ArchComplex;
use crate::{cellular_complex, ChainComplex};

/// The cells of one dimension, in flat arrays: cell `i` has the value `values[i]`, the
/// signed faces `entries[start[i]..start[i + 1]]` (indices of cells one dimension down)
/// and the name `names.get(i)`.
#[derive(Clone, Debug)]
struct Cells {
    values: Vec<f64>,
    start: Vec<usize>,
    entries: Vec<(u32, i64)>,
    names: Names,
}

impl Default for Cells {
    fn default() -> Self {
        Cells { values: Vec::new(), start: vec![0], entries: Vec::new(), names: Names::Simplices(0, Vec::new()) }
    }
}

impl Cells {
    fn len(&self) -> usize {
        self.values.len()
    }

    fn boundary(&self, i: usize) -> &[(u32, i64)] {
        &self.entries[self.start[i]..self.start[i + 1]]
    }
}

/// The names of one dimension's cells: simplices of `width` vertices kept as one buffer of
/// labels (no allocation per cell) as long as every name is one, else a list.
#[derive(Clone, Debug)]
enum Names {
    Simplices(usize, Vec<u64>),
    Listed(Vec<CellName>),
}

impl Names {
    fn push(&mut self, name: NameRef<'_>) {
        if let (Names::Simplices(width, labels), NameRef::Simplex(s)) = (&mut *self, &name) {
            if labels.is_empty() {
                *width = s.len();
            }
            if *width == s.len() {
                labels.extend_from_slice(s);
                return;
            }
        }
        if let Names::Simplices(width, labels) = self {
            let listed = labels.chunks_exact((*width).max(1)).map(|s| CellName::Simplex(s.to_vec())).collect();
            *self = Names::Listed(listed);
        }
        if let Names::Listed(v) = self {
            v.push(match name {
                NameRef::Simplex(s) => CellName::Simplex(s.to_vec()),
                NameRef::Owned(n) => n,
            });
        }
    }

    fn get(&self, i: usize) -> CellName {
        match self {
            Names::Simplices(width, labels) => CellName::Simplex(labels[i * width..(i + 1) * width].to_vec()),
            Names::Listed(v) => v[i].clone(),
        }
    }
}

/// A name given to [`FilteredComplex::push`]: a simplex's labels in place, or any name.
enum NameRef<'a> {
    Simplex(&'a [u64]),
    Owned(CellName),
}

impl std::fmt::Display for NameRef<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            NameRef::Simplex(s) => write!(f, "{s:?}"),
            NameRef::Owned(n) => write!(f, "{n}"),
        }
    }
}

/// A cell complex whose cells carry values, stored per dimension in the order given.
///
/// A superlevel filtration (cells from the largest value down, a cell lowered to its
/// faces' minimum) is kept as the sublevel filtration of the values negated, with `sign`
/// −1 to report the diagram in the values given (the `_superlevel` constructors).
#[derive(Clone, Debug)]
pub struct FilteredComplex {
    cells: Vec<Cells>,
    sign: f64,
}

impl Default for FilteredComplex {
    fn default() -> Self {
        FilteredComplex { cells: Vec::new(), sign: 1.0 }
    }
}

/// How the simplices of a complex get their values.
#[derive(Clone, Copy)]
#[non_exhaustive]
pub enum SimplexValues<'a> {
    /// one value per listed simplex, a face taking the minimum of its listed cofaces
    PerSimplex(&'a [f64]),
    /// the lower star of vertex values: `value(label)` (a missing label is an error)
    LowerStar(&'a dyn Fn(u64) -> Option<f64>),
}

/// The value of the numeric label `label` among `labels`: `None` when there is no such
/// label; refused, naming the cell as `cell()` does, when it is not a number.
fn label_number(labels: &Labels, label: &str, cell: impl FnOnce() -> String) -> Result<Option<f64>, PersistenceError> {
    match labels.get(label) {
        None => Ok(None),
        Some(LabelValue::Int(x)) => Ok(Some(*x as f64)),
        Some(LabelValue::Real(x)) => Ok(Some(*x)),
        Some(other) => {
            Err(PersistenceError::BadInput(format!("{}: label {label} = {other:?} is not a number", cell())))
        }
    }
}

impl FilteredComplex {
    /// An empty complex.
    pub fn new() -> Self {
        Self::default()
    }

    /// Number of cells of dimension `k`.
    pub fn count(&self, k: usize) -> usize {
        self.cells.get(k).map_or(0, Cells::len)
    }

    /// Adds a `dim`-cell with `value` and the signed faces `boundary` (indices among the
    /// `(dim-1)`-cells); its value is raised to its faces' maximum. Returns its index.
    /// Refuses a face that does not exist, a NaN and a boundary on a vertex.
    pub fn try_push(
        &mut self,
        dim: usize,
        value: f64,
        boundary: Vec<(u32, i64)>,
        name: CellName,
    ) -> Result<u32, PersistenceError> {
        self.push(dim, value, &boundary, NameRef::Owned(name))
    }

    /// [`FilteredComplex::try_push`] with the boundary borrowed and a simplex's name in
    /// place (nothing allocated per cell).
    fn push(
        &mut self,
        dim: usize,
        value: f64,
        boundary: &[(u32, i64)],
        name: NameRef<'_>,
    ) -> Result<u32, PersistenceError> {
        if value.is_nan() {
            return Err(PersistenceError::BadInput(format!("{name} has a NaN value")));
        }
        if dim == 0 && !boundary.is_empty() {
            return Err(PersistenceError::BadInput(format!("the vertex {name} has faces")));
        }
        let mut v = value;
        for &(f, _) in boundary {
            let face = dim.checked_sub(1).and_then(|k| self.cells.get(k)).and_then(|c| c.values.get(f as usize));
            let face = face
                .ok_or_else(|| PersistenceError::BadInput(format!("{name}: no face {f} of dimension {}", dim - 1)))?;
            v = v.max(*face);
        }
        while self.cells.len() <= dim {
            self.cells.push(Cells::default());
        }
        let cells = &mut self.cells[dim];
        let i = cells.len();
        if i >= u32::MAX as usize {
            return Err(PersistenceError::TooLarge(format!("{i} cells of dimension {dim}")));
        }
        cells.values.push(v);
        cells.entries.extend_from_slice(boundary);
        cells.start.push(cells.entries.len());
        cells.names.push(name);
        Ok(i as u32)
    }

    /// The simplicial complex of `simplices` (vertex labels, any order, each listed simplex
    /// with all its faces) with values as `values` says. The cells of each dimension are
    /// its faces in lexicographic order of their sorted labels.
    ///
    /// Dimension by dimension, every face of every simplex is written into one flat buffer,
    /// sorted and merged (no map keyed by faces, no allocation per face), and a face's
    /// faces are found by binary search among the dimension below: `O(F log F)` for `F`
    /// faces of the listed simplices, counted with repeats.
    pub fn from_simplices(simplices: &[Vec<u64>], values: SimplexValues<'_>) -> Result<Self, PersistenceError> {
        Self::simplices(simplices, values, 1.0)
    }

    /// [`FilteredComplex::from_simplices`] for superlevel sets: from the largest value down,
    /// a face taking the maximum of its listed cofaces' values (per simplex) or a simplex
    /// the smallest of its vertices' (the upper star); essential classes die at `-inf`.
    pub fn from_simplices_superlevel(
        simplices: &[Vec<u64>],
        values: SimplexValues<'_>,
    ) -> Result<Self, PersistenceError> {
        Self::simplices(simplices, values, -1.0)
    }

    fn simplices(simplices: &[Vec<u64>], values: SimplexValues<'_>, sign: f64) -> Result<Self, PersistenceError> {
        let mut sorted: Vec<Vec<u64>> = Vec::with_capacity(simplices.len());
        for (s, simplex) in simplices.iter().enumerate() {
            let mut v = simplex.clone();
            v.sort_unstable();
            if v.is_empty() || v.windows(2).any(|w| w[0] == w[1]) {
                return Err(PersistenceError::BadInput(format!(
                    "simplex {s} {simplex:?} is empty or repeats a vertex"
                )));
            }
            if v.len() > 20 {
                return Err(PersistenceError::TooLarge(format!("simplex {s} has {} vertices", v.len())));
            }
            sorted.push(v);
        }
        if let SimplexValues::PerSimplex(vals) = values {
            if vals.len() != simplices.len() {
                return Err(PersistenceError::BadInput(format!(
                    "{} values for {} simplices",
                    vals.len(),
                    simplices.len()
                )));
            }
        }
        let top = sorted.iter().map(Vec::len).max().unwrap_or(0);
        let mut out = FilteredComplex { cells: Vec::new(), sign };
        // the faces of the dimension below, `k` labels each, in order
        let mut below: Vec<u64> = Vec::new();
        let mut labels: Vec<u64> = Vec::new();
        let mut vals: Vec<f64> = Vec::new();
        let mut vertex_value: FxHashMap<u64, f64> = FxHashMap::default();
        for w in 1..=top {
            let k = w - 1;
            // every face of w vertices of every simplex, with the simplex's value
            labels.clear();
            vals.clear();
            for (s, v) in sorted.iter().enumerate().filter(|(_, v)| v.len() >= w) {
                let x = match values {
                    SimplexValues::PerSimplex(xs) => sign * xs[s],
                    SimplexValues::LowerStar(_) => f64::NEG_INFINITY,
                };
                // the masks of w bits below 2^len, in increasing order (Gosper's hack)
                let mut mask: u32 = (1 << w) - 1;
                while mask < 1 << v.len() {
                    let mut bits = mask;
                    while bits != 0 {
                        labels.push(v[bits.trailing_zeros() as usize]);
                        bits &= bits - 1;
                    }
                    vals.push(x);
                    let c = mask & mask.wrapping_neg();
                    let r = mask + c;
                    mask = (((r ^ mask) >> 2) / c) | r;
                }
            }
            let face = |i: u32| &labels[i as usize * w..(i as usize + 1) * w];
            let mut ids: Vec<u32> = (0..vals.len() as u32).collect();
            ids.sort_unstable_by(|&a, &b| face(a).cmp(face(b)));
            // merged: each face once, with the least value of the simplices that have it
            let mut faces: Vec<u64> = Vec::with_capacity(labels.len());
            let mut face_vals: Vec<f64> = Vec::new();
            for &i in &ids {
                let f = face(i);
                let n = face_vals.len();
                if n > 0 && &faces[(n - 1) * w..] == f {
                    face_vals[n - 1] = face_vals[n - 1].min(vals[i as usize]);
                } else {
                    faces.extend_from_slice(f);
                    face_vals.push(vals[i as usize]);
                }
            }
            let count_below = below.len().checked_div(k).unwrap_or(0);
            let find_below = |f: &[u64]| -> u32 {
                let (mut lo, mut hi) = (0, count_below);
                while lo < hi {
                    let mid = (lo + hi) / 2;
                    if below[mid * k..(mid + 1) * k] < *f {
                        lo = mid + 1;
                    } else {
                        hi = mid;
                    }
                }
                lo as u32
            };
            let mut dropped: Vec<u64> = Vec::with_capacity(k);
            let mut boundary: Vec<(u32, i64)> = Vec::with_capacity(w);
            for (j, &x) in face_vals.iter().enumerate() {
                let f = &faces[j * w..(j + 1) * w];
                let x = match values {
                    // each vertex's value asked for once, then kept
                    SimplexValues::LowerStar(value) if k == 0 => {
                        let x = sign
                            * value(f[0])
                                .ok_or_else(|| PersistenceError::BadInput(format!("vertex {} has no value", f[0])))?;
                        vertex_value.insert(f[0], x);
                        x
                    }
                    SimplexValues::LowerStar(_) => f.iter().map(|u| vertex_value[u]).fold(f64::NEG_INFINITY, f64::max),
                    SimplexValues::PerSimplex(_) => x,
                };
                boundary.clear();
                for i in (0..w).filter(|_| k > 0) {
                    dropped.clear();
                    dropped.extend_from_slice(&f[..i]);
                    dropped.extend_from_slice(&f[i + 1..]);
                    boundary.push((find_below(&dropped), if i % 2 == 0 { 1 } else { -1 }));
                }
                out.push(k, x, &boundary, NameRef::Simplex(f))?;
            }
            below = faces;
        }
        Ok(out)
    }

    /// The filtration of a chain complex whose cells get values from `value(k, i)`: `None`
    /// gives a cell the maximum of its faces' values (a vertex needs a value); a value below
    /// a face's is raised to it. `name(k, i)` names the cells in cycles.
    pub fn from_chain<V, N>(chain: &ChainComplex, value: V, name: N) -> Result<Self, PersistenceError>
    where
        V: FnMut(usize, usize) -> Result<Option<f64>, PersistenceError>,
        N: FnMut(usize, usize) -> CellName,
    {
        Self::chain(chain, value, name, 1.0)
    }

    fn chain<V, N>(chain: &ChainComplex, mut value: V, mut name: N, sign: f64) -> Result<Self, PersistenceError>
    where
        V: FnMut(usize, usize) -> Result<Option<f64>, PersistenceError>,
        N: FnMut(usize, usize) -> CellName,
    {
        let mut out = FilteredComplex { cells: Vec::new(), sign };
        for k in 0..chain.counts().len() {
            let d = (k > 0).then(|| chain.boundary(k));
            for i in 0..chain.count(k) {
                let boundary: Vec<(u32, i64)> = match d {
                    Some(d) => {
                        let (rows, vals) = d.col(i);
                        rows.iter().zip(vals).map(|(&r, &x)| (r, x)).collect()
                    }
                    None => Vec::new(),
                };
                let v = match value(k, i)? {
                    Some(v) => sign * v,
                    None if k == 0 => return Err(PersistenceError::BadInput(format!("{} has no value", name(0, i)))),
                    None => f64::NEG_INFINITY,
                };
                out.try_push(k, v, boundary, name(k, i))?;
            }
        }
        Ok(out)
    }

    /// The filtration of a labelled G-map by the numeric label `label` of its cells
    /// (integers and reals; a text is refused, naming the cell): through its cellular
    /// complex (conditions C1 and C2, refused otherwise), cells named by dimension and
    /// smallest dart. Cells without the label take the maximum of their faces' values.
    pub fn from_labelled_gmap(g: &LabelledGMap, label: &str) -> Result<Self, PersistenceError> {
        Self::labelled_gmap(g, label, 1.0)
    }

    /// [`FilteredComplex::from_labelled_gmap`] for superlevel sets: a cell's value lowered
    /// to the minimum of its faces', a cell without the label taking that minimum.
    pub fn from_labelled_gmap_superlevel(g: &LabelledGMap, label: &str) -> Result<Self, PersistenceError> {
        Self::labelled_gmap(g, label, -1.0)
    }

    fn labelled_gmap(g: &LabelledGMap, label: &str, sign: f64) -> Result<Self, PersistenceError> {
        let (dense, labels, _) = to_dense_labels(g);
        let cc = cellular_complex(&dense)
            .map_err(|e| PersistenceError::BadInput(format!("the map's cellular complex: {e}")))?;
        let parts: Vec<Vec<u32>> = (0..=dense.dim()).map(|k| dense.cells(k).of).collect();
        let reps = &cc.reps;
        Self::chain(
            &cc.chain,
            |k, i| {
                let c = parts[k][reps[k][i].index()] as usize;
                label_number(labels.get(k, c), label, || format!("the {k}-cell of dart {}", reps[k][i].index()))
            },
            |k, i| CellName::Cell { dim: k, index: reps[k][i].index() },
            sign,
        )
    }

    /// The filtration of an architectural complex by the numeric label `label` of its
    /// regions: the chain complex `gmap homology` computes for it (the completion by zero of
    /// its partial boundary operator, AC Def. 3.9), each region's value raised to the
    /// maximum of its faces', a region without the label taking that maximum (a 0-region
    /// needs one). Cells are named by region id. O(R + E) plus the sort.
    pub fn from_arch(x: &ArchComplex, label: &str) -> Result<Self, PersistenceError> {
        Self::arch(x, label, 1.0)
    }

    /// [`FilteredComplex::from_arch`] for superlevel sets: a region's value lowered to the
    /// minimum of its faces'.
    pub fn from_arch_superlevel(x: &ArchComplex, label: &str) -> Result<Self, PersistenceError> {
        Self::arch(x, label, -1.0)
    }

    fn arch(x: &ArchComplex, label: &str, sign: f64) -> Result<Self, PersistenceError> {
        let regions: Vec<&[u32]> = (0..=x.dim()).map(|k| x.regions_of_dim(k)).collect();
        let id = |k: usize, i: usize| x.region(regions[k][i] as usize).id.0;
        Self::chain(
            &x.chain_complex(),
            |k, i| label_number(x.region_labels(regions[k][i] as usize), label, || format!("region {}", id(k, i))),
            |k, i| CellName::Region { dim: k, id: id(k, i) },
            sign,
        )
    }

    /// The persistence diagram over `Z/field`, with a cycle per pair if `cycles`.
    pub fn diagram(&self, field: u32, cycles: bool) -> Result<Diagram, PersistenceError> {
        let zp = check_field(field)?;
        let mut diagram = Diagram::new(field);
        let top = self.cells.len();
        if top == 0 {
            return Ok(diagram);
        }
        // per dimension: cells in filtration order and each cell's rank
        let mut order: Vec<Vec<u32>> = Vec::with_capacity(top);
        let mut rank: Vec<Vec<u32>> = Vec::with_capacity(top);
        for cells in &self.cells {
            let mut o: Vec<u32> = (0..cells.len() as u32).collect();
            o.sort_unstable_by_key(|&i| (key(cells.values[i as usize]), i));
            let mut r = vec![0u32; o.len()];
            for (p, &i) in o.iter().enumerate() {
                r[i as usize] = p as u32;
            }
            order.push(o);
            rank.push(r);
        }
        let name = |k: usize, r: u32| self.cells[k].names.get(order[k][r as usize] as usize);
        let val = |k: usize, r: u32| self.cells[k].values[order[k][r as usize] as usize];
        let chain = |k: usize, e: &[Entry]| -> Chain { e.iter().map(|&(r, c)| (name(k, r), c)).collect() };
        let mut claimed: Vec<bool> = Vec::new();
        for k in (1..top).rev() {
            let cols = (0..order[k].len() as u32).filter(|&j| !claimed.get(j as usize).copied().unwrap_or(false));
            let r = reduce_dim(
                zp,
                order[k - 1].len(),
                cols,
                |j, out: &mut Vec<Entry>| {
                    let boundary = self.cells[k].boundary(order[k][j as usize] as usize);
                    out.extend(boundary.iter().map(|&(f, s)| (rank[k - 1][f as usize], zp.of(s))));
                },
                cycles,
                cycles,
            );
            for &(row, col) in &r.pairs {
                let c = cycles.then(|| (chain(k - 1, &r.reduced[&col]), name(k - 1, row), Some(name(k, col))));
                diagram.push(k - 1, val(k - 1, row), val(k, col), self.sign, c);
            }
            for &col in &r.zero {
                let c = cycles.then(|| (chain(k, &r.v[&col]), name(k, col), None));
                diagram.push(k, val(k, col), f64::INFINITY, self.sign, c);
            }
            claimed = r.claimed;
        }
        for j in 0..order[0].len() as u32 {
            if !claimed.get(j as usize).copied().unwrap_or(false) {
                let c = cycles.then(|| (vec![(name(0, j), 1)], name(0, j), None));
                diagram.push(0, val(0, j), f64::INFINITY, self.sign, c);
            }
        }
        diagram.finish();
        Ok(diagram)
    }
}
