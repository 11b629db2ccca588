//! Cubical sets: CHomP's `.cub` text format (full cubes and cells), its `.cel` cell lists and
//! 2D Netpbm bitmaps (`.pbm`, P1 and P4), read into a [`CubicalSet`], a bitmap over the
//! bounding box with the lower cells that lie on none of its cubes (docs/FORMATS.md).
//!
//! A full set is the union of closed unit cubes `[x_1, x_1 + 1] × … × [x_d, x_d + 1]`, each
//! given by its minimal vertex. A cubical cell complex adds elementary cubes of lower
//! dimension, products of intervals `[a, a + 1]` and points `[a]` (`[0,1]x[2]`): the space is
//! the union of the listed cells and all their faces. [`CubicalSet::gmap`] builds the G-map of the union where that route
//! applies (every cube one d-cell, sewn to its neighbours along shared facets); the cubical
//! chain complex itself is built by `gmap_homology::cubical`.
//!
//! ```
//! use gmap_ops::import::cubical::parse_cub;
//! let s = parse_cub(b"; two squares\n(0,0)\n(1 1)\n").unwrap();
//! assert_eq!((s.dim(), s.shape(), s.cube_count()), (2, &[2usize, 2][..], 2));
//! ```

#![allow(clippy::needless_range_loop)] // axes index several arrays at once

use std::path::Path;

use gmap_core::io::shorten;
use gmap_core::DenseMap;

use super::common::{read_bytes, FileError, ImportError};

/// The largest bounding box accepted, in unit cubes (one byte each in the bitmap), whatever
/// the memory limit: the cells of its closure are numbered with `u32`. Below it, a box is
/// accepted when its estimate fits the memory limit
/// ([`gmap_core::resources::cubical_set_estimate`], checked before the bitmap is allocated).
pub const MAX_BOX_CUBES: u64 = 1 << 30;

/// A cubical set: the cubes of a box `min + [0, shape)` that belong to the set and, for a
/// cubical cell complex, the listed cells of lower dimension that lie on none of them (the
/// space is the union of the cubes, those cells and all their faces).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CubicalSet {
    min: Vec<i64>,
    shape: Vec<usize>,
    /// one byte a cube (0 or 1), axis 0 fastest
    bits: Vec<u8>,
    count: usize,
    /// the lower cells on no cube, `d` absolute doubled coordinates each (`2 x_a + e_a`, `e_a`
    /// 1 where the cell spans axis `a`), sorted, without repeats; empty for a full set
    cells: Vec<i64>,
}

impl CubicalSet {
    /// A set from its box and bitmap (`bits[x_0 + s_0 (x_1 + s_1 (…))]` non-zero for a cube of
    /// the set). Refuses an empty shape, a zero size, a box over [`MAX_BOX_CUBES`] or a
    /// bitmap of the wrong length.
    pub fn new(min: Vec<i64>, shape: Vec<usize>, bits: Vec<u8>) -> Result<Self, ImportError> {
        if shape.is_empty() || min.len() != shape.len() {
            return Err(ImportError::Format("a cubical set needs dimension at least 1".into()));
        }
        let volume = box_volume(&shape)?;
        if bits.len() as u64 != volume {
            return Err(ImportError::Format(format!("a bitmap of {} bytes for a box of {volume} cubes", bits.len())));
        }
        let mut bits = bits;
        let mut count = 0;
        for b in bits.iter_mut() {
            *b = (*b != 0) as u8;
            count += *b as usize;
        }
        Ok(CubicalSet { min, shape, bits, count, cells: Vec::new() })
    }

    /// Whether the set is the union of its full cubes (no lower cell outside them): what
    /// routes and writers that take cubes only (`.gmap` of d-cells, `.vtk` voxels, images,
    /// persistence) need.
    pub fn is_full(&self) -> bool {
        self.cells.is_empty()
    }

    /// Refuses a set that is not full ([`CubicalSet::is_full`]) for `what`, which holds only
    /// d-cubes and would drop the lower cells: the reason names the first of them.
    pub fn require_full(&self, what: &str) -> Result<(), ImportError> {
        match self.lower_cell_names().next() {
            None => Ok(()),
            Some(first) => Err(ImportError::Format(format!(
                "a cubical cell complex with {} cells of dimension below {d} on no {d}-cube (the first: {first}): {what} holds {d}-cubes only and would drop them",
                self.lower_cell_count(),
                d = self.dim()
            ))),
        }
    }

    /// The number of lower cells that lie on no cube of the set (0 for a full set).
    pub fn lower_cell_count(&self) -> usize {
        self.cells.len() / self.dim().max(1)
    }

    /// The lower cells that lie on no cube, as products of intervals and points in the input's
    /// coordinates (`[0,1]x2`), in doubled-coordinate order.
    pub fn lower_cell_names(&self) -> impl Iterator<Item = String> + '_ {
        self.cells.chunks_exact(self.dim().max(1)).map(cell_name)
    }

    /// The lower cells that lie on no cube in doubled coordinates relative to the box,
    /// `2 (x_a - min_a) + e_a` (what `gmap_homology::cubical::cubical_cell_complex_with`
    /// takes), `d` a cell.
    pub fn lower_cells_in_box(&self) -> Vec<usize> {
        let d = self.dim();
        // each cell lies in the box: 0 ≤ offset ≤ 2 shape_a
        self.cells.iter().enumerate().map(|(i, &x)| (x - 2 * self.min[i % d]) as usize).collect()
    }

    /// Adds lower cells (`d` absolute doubled coordinates each) to a set whose box holds them,
    /// keeping those on no cube of the set.
    fn with_lower_cells(mut self, cells: &[i64]) -> Result<Self, ImportError> {
        let d = self.dim();
        let mut kept: Vec<&[i64]> = Vec::new();
        for c in cells.chunks_exact(d) {
            if let Some(a) = (0..d).find(|&a| {
                let (lo, hi) = (c[a].div_euclid(2), (c[a] + 1).div_euclid(2));
                lo < self.min[a] || hi > self.min[a] + self.shape[a] as i64
            }) {
                return Err(ImportError::Format(format!(
                    "the cell {} is outside the box along axis {a}",
                    cell_name(c)
                )));
            }
            if !self.on_a_cube(c) {
                kept.push(c);
            }
        }
        kept.sort_unstable();
        kept.dedup();
        self.cells = kept.concat();
        Ok(self)
    }

    /// Whether the cell of absolute doubled coordinates `c` is a face of a cube of the set:
    /// along each axis it does not span, the cube may sit on either side. O(2^(d - k) d).
    fn on_a_cube(&self, c: &[i64]) -> bool {
        let d = self.dim();
        let free: Vec<usize> = (0..d).filter(|&a| c[a] % 2 == 0).collect();
        (0u64..1 << free.len()).any(|mask| {
            let mut idx = 0usize;
            for a in (0..d).rev() {
                let mut x = c[a].div_euclid(2);
                if let Some(j) = free.iter().position(|&f| f == a) {
                    x -= (mask >> j & 1) as i64;
                }
                let off = x - self.min[a];
                if off < 0 || off >= self.shape[a] as i64 {
                    return false;
                }
                idx = idx * self.shape[a] + off as usize;
            }
            self.bits[idx] != 0
        })
    }

    /// The same cubes in another box: the cubes from `first` to `last` (inclusive) along
    /// every axis, which must hold every cube of the set (`--periodic` then identifies that
    /// box's opposite faces, not those of the cubes' bounding box). O(box).
    pub fn with_box(&self, first: &[i64], last: &[i64]) -> Result<Self, ImportError> {
        let d = self.dim();
        if first.len() != d || last.len() != d {
            return Err(ImportError::Format(format!(
                "a box of dimension {} for a cubical set of dimension {d}",
                first.len().max(last.len())
            )));
        }
        let mut shape = Vec::with_capacity(d);
        for a in 0..d {
            let (lo, hi) = (self.min[a], self.min[a] + self.shape[a] as i64 - 1);
            if first[a] > lo || last[a] < hi {
                return Err(ImportError::Format(format!(
                    "the box from {first:?} to {last:?} does not hold the cubes: along axis {a} they run from {lo} to {hi}"
                )));
            }
            shape
                .push(usize::try_from(last[a] - first[a] + 1).map_err(|_| ImportError::Format("an empty box".into()))?);
        }
        let volume = box_checked(&shape)? as usize;
        let mut bits = vec![0u8; volume];
        for c in self.cubes() {
            let mut idx = 0usize;
            for a in (0..d).rev() {
                idx = idx * shape[a] + (c[a] - first[a]) as usize;
            }
            bits[idx] = 1;
        }
        CubicalSet::new(first.to_vec(), shape, bits)?.with_lower_cells(&self.cells)
    }

    /// The dimension d.
    pub fn dim(&self) -> usize {
        self.shape.len()
    }

    /// The minimal vertex of the box.
    pub fn min(&self) -> &[i64] {
        &self.min
    }

    /// The box's number of cubes along each axis.
    pub fn shape(&self) -> &[usize] {
        &self.shape
    }

    /// One byte a cube of the box, 1 for a cube of the set, axis 0 fastest.
    pub fn bits(&self) -> &[u8] {
        &self.bits
    }

    /// The number of cubes of the set.
    pub fn cube_count(&self) -> usize {
        self.count
    }

    /// The minimal vertices of the cubes of the set in the input's coordinates, axis 0
    /// fastest (the order of [`CubicalSet::bits`]). O(d) per cube, O(box) in all.
    ///
    /// ```
    /// use gmap_ops::import::cubical::parse_cub;
    /// let s = parse_cub(b"(5,-1)\n(4,0)\n").unwrap();
    /// assert_eq!(s.cubes().collect::<Vec<_>>(), vec![vec![5, -1], vec![4, 0]]);
    /// ```
    pub fn cubes(&self) -> impl Iterator<Item = Vec<i64>> + '_ {
        self.bits.iter().enumerate().filter(|(_, &b)| b != 0).map(|(mut i, _)| {
            self.shape
                .iter()
                .zip(&self.min)
                .map(|(&l, &m)| {
                    // within the box: |m| ≤ 2^40 and the offset < 2^30
                    let x = m + (i % l) as i64;
                    i /= l;
                    x
                })
                .collect()
        })
    }

    /// The G-map of the union, refused when it would be another space: [`CubicalSet::gmap`]
    /// after [`CubicalSet::pinched_cell`] found no cell around which the cubes share no
    /// facet (two cubes touching at a corner only), the error naming the first such cell.
    /// What `gmap convert` and the Python package's `to_gmap` write.
    pub fn gmap_of_union(&self, periodic: bool) -> Result<DenseMap, ImportError> {
        self.require_full("a G-map of its cubes")?;
        if let Some((cell, groups)) = self.pinched_cell(periodic) {
            return Err(ImportError::Format(format!(
                "the cubes around the cell {cell} fall into {groups} groups that share no facet there: a G-map sews cubes along facets only, so it would pull them apart (another space); .vtk, .cub and the incidence graphs keep it"
            )));
        }
        self.gmap(periodic)
    }

    /// The G-map of the cubes: the grid of the box ([`crate::build::grid`], axes periodic
    /// with `periodic`) restricted to the cubes of the set, each cube one d-cell sewn to its
    /// neighbours of the set along shared facets, the other facets free. Its cells are those
    /// of the union only where the cubes around every cell meet along paths of facets (a
    /// solid box, a ring, a shell); two cubes touching at a corner only make two components
    /// here ([`CubicalSet::gmap_of_union`] refuses such a set). A set with lower cells on no
    /// cube is refused ([`CubicalSet::require_full`]). Precondition: `2^d d! × cubes < 2^32`.
    pub fn gmap(&self, periodic: bool) -> Result<DenseMap, ImportError> {
        self.require_full("a G-map of its cubes")?;
        let d = self.dim();
        let grid = crate::build::grid(&self.shape, &vec![periodic; d])
            .map_err(|e| ImportError::Format(format!("the grid of the box: {e}")))?;
        let total = grid.dart_count();
        let per = total / self.bits.len();
        let w = d + 1;
        // new index of the first dart of each kept cube
        let mut first = vec![u32::MAX; self.bits.len()];
        let mut next = 0u32;
        for (c, &b) in self.bits.iter().enumerate() {
            if b != 0 {
                first[c] = next;
                next += per as u32;
            }
        }
        let mut alpha = Vec::with_capacity(next as usize * w);
        for (c, &b) in self.bits.iter().enumerate() {
            if b == 0 {
                continue;
            }
            for k in 0..per {
                let old = c * per + k;
                let me = first[c] + k as u32;
                for i in 0..=d {
                    let t = grid.alpha(gmap_core::Dart::new(old as u32), i).index();
                    let (tc, tk) = (t / per, t % per);
                    alpha.push(if first[tc] == u32::MAX { me } else { first[tc] + tk as u32 });
                }
            }
        }
        DenseMap::from_flat_unchecked(d, alpha).map_err(|e| ImportError::Format(e.to_string()))
    }
}

impl CubicalSet {
    /// The first cell (in the order of the cubes, then of their faces) of dimension at most
    /// d − 2 around which the cubes of the set holding it are not joined by a path of cubes
    /// sharing facets that hold it, named as a product of intervals and points, with the
    /// number of groups its cubes fall into; `None` when every cell's cubes are so joined,
    /// that is when sewing the cubes along shared facets gives the union's own cells.
    /// Axes wrap around with `periodic`. O(3^d 2^d) per cube.
    ///
    /// ```
    /// use gmap_ops::import::cubical::parse_cub;
    /// let corner = parse_cub(b"(0,0)\n(1,1)\n").unwrap();
    /// assert_eq!(corner.pinched_cell(false), Some(("1x1".to_string(), 2)));
    /// let ring = parse_cub(b"(0,0)\n(1,0)\n(2,0)\n(0,1)\n(2,1)\n(0,2)\n(1,2)\n(2,2)\n").unwrap();
    /// assert_eq!(ring.pinched_cell(false), None);
    /// ```
    pub fn pinched_cell(&self, periodic: bool) -> Option<(String, usize)> {
        let d = self.dim();
        if d < 2 {
            return None;
        }
        let strides: Vec<usize> =
            self.shape.iter().scan(1usize, |acc, &l| Some(std::mem::replace(acc, *acc * l))).collect();
        // the cube at `x` (box coordinates, possibly one step outside), if it is in the set
        let present = |x: &[i64]| -> bool {
            let mut i = 0usize;
            for a in 0..d {
                let l = self.shape[a] as i64;
                let mut c = x[a];
                if periodic {
                    c = c.rem_euclid(l);
                } else if c < 0 || c >= l {
                    return false;
                }
                i += c as usize * strides[a];
            }
            self.bits[i] != 0
        };
        let faces = 3usize.pow(d as u32);
        let mut x = vec![0i64; d];
        let mut y = vec![0i64; d];
        let mut seen = Vec::new();
        let mut queue = Vec::new();
        // per axis of the face at hand: 0 the point x_a, 1 the interval [x_a, x_a + 1], 2 the
        // point x_a + 1; and the axes it does not span
        let mut t = vec![0usize; d];
        let mut free = Vec::with_capacity(d);
        for (ci, _) in self.bits.iter().enumerate().filter(|(_, &b)| b != 0) {
            let mut r = ci;
            for a in 0..d {
                x[a] = (r % self.shape[a]) as i64;
                r /= self.shape[a];
            }
            for code in 0..faces {
                let mut rest = code;
                for ta in t.iter_mut() {
                    *ta = rest % 3;
                    rest /= 3;
                }
                free.clear();
                free.extend((0..d).filter(|&a| t[a] != 1));
                if free.len() < 2 {
                    continue;
                }
                // the cubes around the cell: one bit per free axis, set for the cube above the point
                let around = |mask: usize, y: &mut [i64]| {
                    y.copy_from_slice(&x);
                    for (j, &a) in free.iter().enumerate() {
                        let p = x[a] + (t[a] / 2) as i64;
                        y[a] = if mask >> j & 1 == 1 { p } else { p - 1 };
                    }
                };
                let n = 1usize << free.len();
                seen.clear();
                seen.resize(n, false);
                let mut groups = 0;
                for m in 0..n {
                    around(m, &mut y);
                    if seen[m] || !present(&y) {
                        continue;
                    }
                    groups += 1;
                    seen[m] = true;
                    queue.push(m);
                    while let Some(u) = queue.pop() {
                        for j in 0..free.len() {
                            let v = u ^ (1 << j);
                            around(v, &mut y);
                            if !seen[v] && present(&y) {
                                seen[v] = true;
                                queue.push(v);
                            }
                        }
                    }
                }
                if groups > 1 {
                    let doubled: Vec<i64> = (0..d).map(|a| 2 * (self.min[a] + x[a]) + t[a] as i64).collect();
                    return Some((cell_name(&doubled), groups));
                }
            }
        }
        None
    }
}

/// A cell of absolute doubled coordinates as a product of intervals and points, `[0,1]x2`.
fn cell_name(c: &[i64]) -> String {
    c.iter()
        .map(
            |&x| {
                if x % 2 != 0 {
                    format!("[{},{}]", x.div_euclid(2), x.div_euclid(2) + 1)
                } else {
                    (x / 2).to_string()
                }
            },
        )
        .collect::<Vec<_>>()
        .join("x")
}

/// Checks the memory a set on a box of `shape` cubes would take (its bitmap and the grid of
/// its chain complex, [`gmap_core::resources::cubical_set_estimate`]) against the memory
/// limit, before anything is allocated; then the box's size ([`box_volume`]).
pub(crate) fn box_checked(shape: &[usize]) -> Result<u64, ImportError> {
    let what = format!(
        "the cubical set on the bounding box {}",
        shape.iter().map(|s| s.to_string()).collect::<Vec<_>>().join(" × ")
    );
    gmap_core::resources::check_memory(&what, gmap_core::resources::cubical_set_estimate(shape))?;
    box_volume(shape)
}

fn box_volume(shape: &[usize]) -> Result<u64, ImportError> {
    let mut v: u64 = 1;
    for &s in shape {
        v = v.checked_mul(s as u64).filter(|&v| v <= MAX_BOX_CUBES).ok_or_else(|| {
            ImportError::Format(format!(
                "the bounding box {} holds more than {MAX_BOX_CUBES} unit cubes",
                shape.iter().map(|s| s.to_string()).collect::<Vec<_>>().join(" × ")
            ))
        })?;
    }
    if v == 0 {
        return Err(ImportError::Format("the box is empty".into()));
    }
    Ok(v)
}

/// Reads a `.cub` file (CHomP's cubical sets: one cube a line, `(x, y, z)`).
pub fn read_cub(path: &Path) -> Result<CubicalSet, FileError> {
    let bytes = read_bytes(path)?;
    parse_cub(&bytes).map_err(|e| FileError::new(path, e))
}

/// Reads a `.pbm` bitmap (P1 or P4): each black pixel a closed unit square.
pub fn read_pbm(path: &Path) -> Result<CubicalSet, FileError> {
    let bytes = read_bytes(path)?;
    parse_pbm(&bytes).map_err(|e| FileError::new(path, e))
}

fn syntax(line: usize, message: String) -> ImportError {
    ImportError::Syntax { line, message }
}

/// Parses the text of a `.cub` or `.cel` file, one element a line:
/// * a cube by its minimal vertex in parentheses, coordinates separated by commas or spaces
///   (`(3,0,-7)`, `(3 0 -7)`);
/// * a cell (an elementary cube of any dimension) as a product of intervals `[a,a+1]` and
///   points `[a]` joined by `x` (`[0,1] x [2] x [3,4]`, `(0,1)x(2)x(3,4)`), or as its two
///   opposite vertices (`[(0,2,3) (1,2,4)]`, CHomP's `cub2cell` output), or in dimension 1
///   as one interval (`[0,1]`, `[5]`);
///
/// `;` starts a comment; lines beginning with `dimension` are skipped; a line
/// `box (0,0) (3,0)` gives the box (its first and last cubes, [`CubicalSet::with_box`])
/// instead of the bounding box of the cells. All elements have the same dimension; one
/// listed twice counts once. The set is the union of the cubes, the cells and their faces.
pub fn parse_cub(text: &[u8]) -> Result<CubicalSet, ImportError> {
    let mut given_box: Option<(Vec<i64>, Vec<i64>)> = None;
    let mut coords: Vec<i64> = Vec::new();
    // the lower cells, absolute doubled coordinates
    let mut cells: Vec<i64> = Vec::new();
    let mut first_lower = 0usize;
    let mut dim = 0usize;
    let mut dim_line = 0usize;
    for (i, raw) in text.split(|&b| b == b'\n').enumerate() {
        let line = i + 1;
        let raw = match raw.iter().position(|&b| b == b';') {
            Some(k) => &raw[..k],
            None => raw,
        };
        let t = raw.trim_ascii();
        if t.is_empty() || t.starts_with(b"dimension") {
            continue;
        }
        if let Some(rest) = t.strip_prefix(b"box") {
            let text = String::from_utf8_lossy(rest);
            given_box = Some(parse_box(&text).map_err(|why| syntax(line, why))?);
            continue;
        }
        let (n, element) = parse_element(t, line)?;
        if dim == 0 {
            dim = n;
            dim_line = line;
        } else if n != dim {
            return Err(syntax(
                line,
                format!("mixed dimensions: this cell has dimension {n}, the one on line {dim_line} dimension {dim}"),
            ));
        }
        match element {
            Element::Cube(x) => coords.extend(x),
            Element::Cell(c) => {
                if first_lower == 0 {
                    first_lower = line;
                }
                cells.extend(c)
            }
        }
    }
    if dim == 0 {
        return Err(ImportError::Format("no cube found".into()));
    }
    if !cells.is_empty() && dim > MAX_CELL_DIM {
        return Err(syntax(
            first_lower,
            format!("cells of lower dimension are read in dimension at most {MAX_CELL_DIM}, not {dim}"),
        ));
    }
    // the box: from the least to the greatest vertex, at least one cube along each axis
    let mut lo = vec![i64::MAX; dim];
    let mut hi = vec![i64::MIN; dim];
    for c in coords.chunks_exact(dim) {
        for a in 0..dim {
            lo[a] = lo[a].min(c[a]);
            hi[a] = hi[a].max(c[a] + 1);
        }
    }
    for c in cells.chunks_exact(dim) {
        for a in 0..dim {
            lo[a] = lo[a].min(c[a].div_euclid(2));
            hi[a] = hi[a].max((c[a] + 1).div_euclid(2));
        }
    }
    let shape: Vec<usize> = (0..dim).map(|a| (hi[a] - lo[a]).max(1) as usize).collect();
    let volume = box_checked(&shape)? as usize;
    let mut bits = Vec::new();
    bits.try_reserve_exact(volume)
        .map_err(|_| ImportError::OutOfMemory { what: "the bitmap".into(), bytes: volume as u64 })?;
    bits.resize(volume, 0u8);
    for c in coords.chunks_exact(dim) {
        let mut idx = 0usize;
        for a in (0..dim).rev() {
            idx = idx * shape[a] + (c[a] - lo[a]) as usize;
        }
        bits[idx] = 1;
    }
    let set = CubicalSet::new(lo, shape, bits)?.with_lower_cells(&cells)?;
    match given_box {
        Some((first, last)) => set.with_box(&first, &last),
        None => Ok(set),
    }
}

/// The largest dimension of a set with cells of lower dimension (finding whether a cell lies
/// on a cube looks at its up to 2^d cofaces' cubes).
pub const MAX_CELL_DIM: usize = 8;

/// One element of a `.cub` or `.cel` line.
enum Element {
    /// a full cube by its minimal vertex
    Cube(Vec<i64>),
    /// a cell of lower dimension, absolute doubled coordinates `2 a + e`
    Cell(Vec<i64>),
}

/// Parses one element (a cube or a cell) and gives its dimension. A cell spanning every axis
/// is a cube.
fn parse_element(t: &[u8], line: usize) -> Result<(usize, Element), ImportError> {
    let bad = || {
        syntax(line, format!("expected a cube like (0,1,2) or a cell like [0,1]x[2]x[3,4], found '{}'", shorten(t, 80)))
    };
    let (lo, hi): (Vec<i64>, Vec<i64>) = if t.iter().any(|&b| b == b'x' || b == b'X') {
        let mut ends = (Vec::new(), Vec::new());
        for part in t.split(|&b| b == b'x' || b == b'X') {
            let (a, b) = interval(part.trim_ascii(), line).ok_or_else(bad)??;
            ends.0.push(a);
            ends.1.push(b);
        }
        ends
    } else if t.starts_with(b"[") && t.ends_with(b"]") {
        let inner = t[1..t.len() - 1].trim_ascii();
        if inner.starts_with(b"(") {
            // two opposite vertices
            let k = inner.iter().position(|&b| b == b')').ok_or_else(bad)?;
            let first = group(&inner[..=k], line).ok_or_else(bad)??;
            let rest = inner[k + 1..].trim_ascii();
            let rest = rest.strip_prefix(b",").unwrap_or(rest).trim_ascii();
            let second = group(rest, line).ok_or_else(bad)??;
            if first.len() != second.len() {
                return Err(syntax(
                    line,
                    format!("the two vertices of the cell '{}' have different dimensions", shorten(t, 80)),
                ));
            }
            if let Some(a) = (0..first.len()).find(|&a| !(0..=1).contains(&(second[a] - first[a]))) {
                return Err(syntax(
                    line,
                    format!(
                        "the vertices of the cell '{}' differ by {} along axis {a}: an elementary cube's differ by 0 or 1",
                        shorten(t, 80),
                        second[a] - first[a]
                    ),
                ));
            }
            (first, second)
        } else {
            let (a, b) = interval(t, line).ok_or_else(bad)??;
            (vec![a], vec![b])
        }
    } else if t.starts_with(b"(") && t.ends_with(b")") {
        let x = group(t, line).ok_or_else(bad)??;
        if x.is_empty() {
            return Err(bad());
        }
        return Ok((x.len(), Element::Cube(x)));
    } else {
        return Err(bad());
    };
    let d = lo.len();
    if lo.iter().zip(&hi).all(|(a, b)| b - a == 1) {
        return Ok((d, Element::Cube(lo)));
    }
    Ok((d, Element::Cell(lo.iter().zip(&hi).map(|(a, b)| 2 * a + (b - a)).collect())))
}

/// An interval `[a,a+1]`, `[a]`, `[a,a]` (or in parentheses): its two ends. `None` when the
/// text is not one.
fn interval(t: &[u8], line: usize) -> Option<Result<(i64, i64), ImportError>> {
    let ends = match group(t, line)? {
        Ok(ends) => ends,
        Err(e) => return Some(Err(e)),
    };
    Some(match ends[..] {
        [a] => Ok((a, a)),
        [a, b] if b == a || b == a + 1 => Ok((a, b)),
        [a, b] => {
            Err(syntax(line, format!("bad interval [{a},{b}]: an elementary interval is [a,a+1] or a point [a]")))
        }
        _ => Err(syntax(line, format!("'{}' is not an interval [a,a+1] or a point [a]", shorten(t, 80)))),
    })
}

/// Integers between matching parentheses or brackets, separated by commas or spaces. `None`
/// when the text is not such a group.
fn group(t: &[u8], line: usize) -> Option<Result<Vec<i64>, ImportError>> {
    let close = match t.first()? {
        b'(' => b')',
        b'[' => b']',
        _ => return None,
    };
    if t.len() < 2 || *t.last()? != close {
        return None;
    }
    let inner = &t[1..t.len() - 1];
    if inner.iter().any(|&b| matches!(b, b'(' | b')' | b'[' | b']')) {
        return None;
    }
    let mut out = Vec::new();
    for tok in inner.split(|&b| b == b',' || b.is_ascii_whitespace()).filter(|s| !s.is_empty()) {
        let v = match std::str::from_utf8(tok).ok().and_then(|s| s.parse::<i64>().ok()) {
            Some(v) => v,
            None => return Some(Err(syntax(line, format!("'{}' is not an integer coordinate", shorten(tok, 80))))),
        };
        if v.unsigned_abs() > 1 << 40 {
            return Some(Err(syntax(line, format!("coordinate {v} out of range (at most 2^40 in absolute value)"))));
        }
        out.push(v);
    }
    if out.is_empty() {
        return None;
    }
    Some(Ok(out))
}

/// Parses a box given as its first and last cubes, `(0,0) (3,0)` (the `box` line of a
/// `.cub` file, `--box`): the two corners, each a cube like the file's.
pub fn parse_box(text: &str) -> Result<(Vec<i64>, Vec<i64>), String> {
    let corners: Vec<Vec<i64>> = text
        .split(')')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| {
            let inner = s
                .strip_prefix('(')
                .ok_or_else(|| format!("expected a box like (0,0) (3,0), found '{}'", text.trim()))?;
            inner
                .split(|c: char| c == ',' || c.is_whitespace())
                .filter(|t| !t.is_empty())
                .map(|t| t.parse::<i64>().map_err(|_| format!("'{t}' is not an integer coordinate")))
                .collect()
        })
        .collect::<Result<_, _>>()?;
    match <[Vec<i64>; 2]>::try_from(corners) {
        Ok([first, last]) if first.len() == last.len() && !first.is_empty() => Ok((first, last)),
        _ => Err(format!("expected a box as its first and last cubes, like (0,0) (3,0), found '{}'", text.trim())),
    }
}

/// Parses a Netpbm bitmap: `P1` (ASCII `0`/`1`, whitespace optional between pixels) or `P4`
/// (packed rows, each padded to a whole byte, most significant bit first), `#` comments in
/// the header. A black pixel (1) in column `x` of row `r` (from the top) is the square with
/// minimal vertex `(x, h - 1 - r)`; the box is the whole image.
pub fn parse_pbm(bytes: &[u8]) -> Result<CubicalSet, ImportError> {
    let fmt = |m: String| ImportError::Format(m);
    let magic = bytes.get(..2).unwrap_or(bytes);
    let binary = match magic {
        b"P1" => false,
        b"P4" => true,
        _ => return Err(fmt(format!("not a PBM bitmap: magic '{}', expected P1 or P4", shorten(magic, 80)))),
    };
    let mut pos = 2;
    let mut header = [0usize; 2];
    for (k, slot) in header.iter_mut().enumerate() {
        let what = ["width", "height"][k];
        // whitespace and comments
        loop {
            match bytes.get(pos) {
                Some(b) if b.is_ascii_whitespace() => pos += 1,
                Some(b'#') => {
                    while bytes.get(pos).is_some_and(|&b| b != b'\n') {
                        pos += 1;
                    }
                }
                _ => break,
            }
        }
        let start = pos;
        while bytes.get(pos).is_some_and(|b| b.is_ascii_digit()) {
            pos += 1;
        }
        let tok = &bytes[start..pos];
        let end = bytes[pos..].iter().position(|b| b.is_ascii_whitespace()).map_or(bytes.len(), |k| pos + k);
        if tok.is_empty() || (pos < bytes.len() && !bytes[pos].is_ascii_whitespace() && bytes[pos] != b'#') {
            return Err(fmt(format!("bad {what} '{}' in the PBM header", shorten(&bytes[start..end], 80))));
        }
        *slot = std::str::from_utf8(tok)
            .ok()
            .and_then(|s| s.parse::<usize>().ok())
            .filter(|&v| v > 0)
            .ok_or_else(|| fmt(format!("bad {what} '{}' in the PBM header", shorten(tok, 80))))?;
    }
    let [w, h] = header;
    let volume = box_checked(&[w, h])? as usize;
    let mut bits = Vec::new();
    bits.try_reserve_exact(volume)
        .map_err(|_| ImportError::OutOfMemory { what: "the bitmap".into(), bytes: volume as u64 })?;
    bits.resize(volume, 0u8);
    if binary {
        // exactly one whitespace byte after the height
        if !bytes.get(pos).is_some_and(|b| b.is_ascii_whitespace()) {
            return Err(fmt("no whitespace after the PBM header".into()));
        }
        pos += 1;
        let row_bytes = w.div_ceil(8);
        let need = row_bytes * h;
        let data = &bytes[pos..];
        if data.len() < need {
            return Err(fmt(format!("P4 data too short: {} bytes for {w} × {h} pixels, expected {need}", data.len())));
        }
        for r in 0..h {
            let row = &data[r * row_bytes..(r + 1) * row_bytes];
            let y = h - 1 - r;
            for x in 0..w {
                bits[y * w + x] = (row[x / 8] >> (7 - x % 8)) & 1;
            }
        }
    } else {
        let mut k = 0usize;
        let mut p = pos;
        while k < volume {
            match bytes.get(p) {
                None => {
                    return Err(fmt(format!("P1 data too short: {k} pixels for {w} × {h}")));
                }
                Some(b) if b.is_ascii_whitespace() => {}
                Some(b'#') => {
                    while bytes.get(p).is_some_and(|&b| b != b'\n') {
                        p += 1;
                    }
                    continue;
                }
                Some(&b @ (b'0' | b'1')) => {
                    let (r, x) = (k / w, k % w);
                    bits[(h - 1 - r) * w + x] = b - b'0';
                    k += 1;
                }
                Some(_) => {
                    let end = (p + 8).min(bytes.len());
                    return Err(fmt(format!("bad P1 pixel '{}', expected 0 or 1", shorten(&bytes[p..end], 80))));
                }
            }
            p += 1;
        }
    }
    CubicalSet::new(vec![0, 0], vec![w, h], bits)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cub_comments_negative_duplicates() {
        let s = parse_cub(b"dimension 2\n; c\n(-1, -2) ; x\n(-1 -2)\n(0,-1)\r\n").unwrap();
        assert_eq!(s.min(), &[-1, -2]);
        assert_eq!(s.shape(), &[2, 2]);
        assert_eq!(s.cube_count(), 2);
        assert_eq!(s.bits(), &[1, 0, 0, 1]);
    }

    #[test]
    fn cub_refusals() {
        assert!(matches!(parse_cub(b"(0,0)\n(1,2,3)\n"), Err(ImportError::Syntax { line: 2, .. })));
        assert!(matches!(parse_cub(b"(0,x)\n"), Err(ImportError::Syntax { line: 1, .. })));
        assert!(matches!(parse_cub(b"0,1\n"), Err(ImportError::Syntax { line: 1, .. })));
        assert!(matches!(parse_cub(b"()\n"), Err(ImportError::Syntax { line: 1, .. })));
        assert!(matches!(parse_cub(b"; nothing\n"), Err(ImportError::Format(_))));
        // a box of 2001^3 cubes: estimated from the box, over any memory limit of this machine
        match parse_cub(b"(0,0,0)\n(2000,2000,2000)\n") {
            Err(ImportError::MemoryLimit(e)) => assert_eq!(e.estimate, Some(2001u64.pow(3) + 9 * 4003u64.pow(3))),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn cell_syntaxes() {
        // the four edges of the unit square, in CHomP's three ways and RedHom's
        let a = parse_cub(b"[0,1]x[0]\n[0,1] x [1]\n(0)x(0,1)\n[(1,0) (1,1)]\n").unwrap();
        let b = parse_cub(b"dimension 2\n[(0,0),(1,0)] ; c\n[0,1]X[1,1]\n[0]x[0,1]\n[1]x[0,1]\n[1]x[0,1]\n").unwrap();
        assert_eq!(a, b);
        assert_eq!((a.min(), a.shape(), a.cube_count(), a.lower_cell_count()), (&[0, 0][..], &[1, 1][..], 0, 4));
        assert_eq!(a.lower_cell_names().collect::<Vec<_>>(), ["0x[0,1]", "[0,1]x0", "[0,1]x1", "1x[0,1]"]);
        assert_eq!(a.lower_cells_in_box(), [0, 1, 1, 0, 1, 2, 2, 1]);
        // a full cell is a cube; its faces and a face of it listed add nothing
        let full = parse_cub(b"[0,1]x[0,1]\n[0]x[0,1]\n[(1,1) (1,1)]\n").unwrap();
        assert_eq!(full, parse_cub(b"(0,0)\n").unwrap());
        assert!(full.is_full());
        // a point and a segment (a cube) in dimension 1, negative coordinates
        let s = parse_cub(b"[-3]\n[5,6]\n").unwrap();
        assert_eq!((s.min(), s.shape(), s.cube_count(), s.lower_cell_count()), (&[-3][..], &[9][..], 1, 1));
        // a box line holds cells too
        let boxed = parse_cub(b"box (0,0) (2,2)\n[1]x[1]\n").unwrap();
        assert_eq!((boxed.min(), boxed.shape(), boxed.lower_cells_in_box()), (&[0, 0][..], &[3, 3][..], vec![2, 2]));
        assert!(parse_cub(b"box (0,0) (0,0)\n[3]x[1]\n").is_err());
    }

    #[test]
    fn cell_refusals() {
        let line_of = |t: &[u8]| match parse_cub(t) {
            Err(ImportError::Syntax { line, message }) => (line, message),
            other => panic!("{other:?}"),
        };
        let (line, m) = line_of(b"[0,1]x[0]\n; c\n[0,2]x[1]\n");
        assert_eq!(line, 3);
        assert!(m.contains("bad interval [0,2]"), "{m}");
        let (line, m) = line_of(b"[0,1]x[0]\n[0,1]x[0]x[1]\n");
        assert!(line == 2 && m.starts_with("mixed dimensions"), "{m}");
        let (line, m) = line_of(b"(0,0)\n[(0,0) (2,1)]\n");
        assert!(line == 2 && m.contains("differ by 2 along axis 0"), "{m}");
        let (line, m) = line_of(b"[0,1]x[99999999999999999999]\n");
        assert!(line == 1 && m.contains("not an integer"), "{m}");
        let (line, m) = line_of(b"[0,1]x[2199023255553]\n");
        assert!(line == 1 && m.contains("out of range"), "{m}");
        assert_eq!(line_of(b"[0,1]x\n").0, 1);
        assert_eq!(line_of(b"[0,1]x[1,0]\n").0, 1);
        assert_eq!(line_of(b"[0,1,2]x[1]\n").0, 1);
        assert_eq!(line_of(b"[(0,0) (1)]\n").0, 1);
        assert_eq!(line_of(b"[0]x[0]x[0]x[0]x[0]x[0]x[0]x[0]x[0]\n").0, 1);
    }

    #[test]
    fn pbm_p1_p4_agree() {
        let p1 = parse_pbm(b"P1\n# c\n3 2\n1 0 1\n011\n").unwrap();
        let p4 = parse_pbm(b"P4 3 2\n\xa0\x60").unwrap();
        assert_eq!(p1, p4);
        assert_eq!(p1.cube_count(), 4);
        assert!(parse_pbm(b"P4 3 2\n\xa0").is_err());
        assert!(parse_pbm(b"P1 3 2 1 0 1").is_err());
        assert!(parse_pbm(b"P2 3 2").is_err());
        assert!(parse_pbm(b"P1 3x 2").is_err());
    }

    #[test]
    fn gmap_of_a_ring() {
        let s = parse_cub(b"(0,0)\n(1,0)\n(2,0)\n(0,1)\n(2,1)\n(0,2)\n(1,2)\n(2,2)\n").unwrap();
        let m = s.gmap(false).unwrap();
        m.validate().unwrap();
        assert_eq!(m.euler_characteristic(), 0);
    }
}
