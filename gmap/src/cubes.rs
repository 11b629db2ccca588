//! The cubical routes, over any source of cubes: a cubical set read from a file, a grey
//! image at a level, or cubes borrowed from memory ([`CubesRef`]: a numpy array read in
//! place by the Python package).
//!
//! | route | applies to | what it computes |
//! |---|---|---|
//! | one pass ([`one_pass`]) | dimension ≤ 3, no generators | the groups from union-finds over the layers and Alexander duality (periodic: over the torus), no chain complex |
//! | sweep ([`sweep`]) | dimension ≤ 3, generators, a box that is not periodic | the groups and a cycle per summand from union-finds and a sweep of the grid |
//! | whole complex | any, up to [`WHOLE_GRID_POINTS`] | the cubical complex of the closure after collapses of free faces |
//! | slabs | past [`WHOLE_GRID_POINTS`] | the cubical complex built and reduced slab by slab |
//!
//! [`crate::route`] chooses among them.

use gmap_ops::import::{CubicalSet, Image, Level};

use crate::cell_name::CellName;
use crate::chains::Named;
use crate::error::{err, Error, ErrorKind, Result};
use crate::input::Input;
use crate::options::{check_field, HomologyOptions, Method};
use crate::report::{Chain, CubeGrid, NamedGenerator};

/// Cubes borrowed from memory: one byte per cube of a box, non-zero where the cube is in
/// the set, the box's minimal vertex at the origin. Built from an array's shape and strides
/// (C or Fortran order), so that the bytes are read where they are, never copied whole.
#[derive(Clone, Debug)]
pub struct CubesRef<'a> {
    bytes: &'a [u8],
    /// the box in storage order (axis 0 fastest)
    shape: Vec<usize>,
    /// the caller's axes are those of `shape` in reverse order (a C-ordered array)
    reversed: bool,
}

/// The most axes a box of borrowed cubes has.
pub const MAX_CUBE_AXES: usize = 8;

impl<'a> CubesRef<'a> {
    /// The cubes of an array of `shape` (the caller's axes) whose element `(i_0, i_1, …)`
    /// is `bytes[Σ i_k strides[k]]`: the strides (in elements) must be those of a C-ordered
    /// array (the last axis fastest) or of a Fortran-ordered one (the first fastest), and
    /// the bytes exactly the box's. Refuses, with the reason, no axis or more than
    /// [`MAX_CUBE_AXES`], an empty axis, a box over `gmap_ops::import::cubical::MAX_BOX_CUBES`
    /// cubes and strides of another layout. Cube coordinates come back in the caller's axis
    /// order.
    pub fn new(bytes: &'a [u8], shape: &[usize], strides: &[isize]) -> Result<Self> {
        let d = shape.len();
        let volume = check_box(shape)?;
        if volume != bytes.len() as u64 || strides.len() != d {
            return Err(err!(
                Usage,
                "a cubical array of shape {shape:?} needs {} bytes and {d} strides, not {} and {}",
                volume,
                bytes.len(),
                strides.len()
            ));
        }
        let layout = |order: &[usize]| {
            let mut step = 1isize;
            order.iter().all(|&a| {
                let ok = shape[a] == 1 || strides[a] == step;
                step = step.saturating_mul(shape[a] as isize);
                ok
            })
        };
        let axes: Vec<usize> = (0..d).collect();
        let reversed_axes: Vec<usize> = (0..d).rev().collect();
        let (fortran, c) = (layout(&axes), layout(&reversed_axes));
        match (c, fortran) {
            (true, _) if d > 1 => Ok(CubesRef { bytes, shape: shape.iter().rev().copied().collect(), reversed: true }),
            (_, true) | (true, _) => Ok(CubesRef { bytes, shape: shape.to_vec(), reversed: false }),
            _ => Err(err!(
                Usage,
                "a cubical array with strides {strides:?} for shape {shape:?} is neither C- nor Fortran-contiguous"
            )),
        }
    }

    /// The box in storage order (axis 0 fastest).
    pub fn storage_shape(&self) -> &[usize] {
        &self.shape
    }

    /// The box in the caller's axis order.
    pub fn shape(&self) -> Vec<usize> {
        let mut s = self.shape.clone();
        if self.reversed {
            s.reverse();
        }
        s
    }

    /// The bytes, axis 0 of [`CubesRef::storage_shape`] fastest.
    pub fn bytes(&self) -> &[u8] {
        self.bytes
    }

    /// Whether the caller's axes are the storage's in reverse order.
    pub fn is_reversed(&self) -> bool {
        self.reversed
    }

    /// The refusals of [`CubesRef::new`] that depend on the shape alone (no axis or more
    /// than [`MAX_CUBE_AXES`], an empty axis, a box over `MAX_BOX_CUBES`) and the memory
    /// policy for a byte per cube: for a caller that has to convert its array into bytes
    /// first (numpy's `a != 0` of a float array), made before it allocates them.
    pub fn check_conversion(shape: &[usize]) -> Result<()> {
        let volume = check_box(shape)?;
        gmap_core::resources::check_memory("the array's cubes as bytes", Some(volume))?;
        Ok(())
    }

    /// The cubical set of these cubes, copied, with its axes in the caller's order (a
    /// C-ordered array's bytes transposed) and its minimal vertex `min` (the caller's order;
    /// zeros when empty). Under the memory policy of the readers of `.cub` files: the
    /// bitmap and the grid its chain complex is built on
    /// (`gmap_core::resources::cubical_set_estimate`), checked before the copy.
    pub fn to_input(&self, min: &[i64]) -> Result<Input> {
        let shape = self.shape();
        let d = shape.len();
        if !min.is_empty() && min.len() != d {
            return Err(err!(Usage, "min has {} coordinates for {d} axes", min.len()));
        }
        let what = "the cubical set of the array";
        gmap_core::resources::check_memory(what, gmap_core::resources::cubical_set_estimate(&shape))?;
        let bits = if self.reversed {
            // the caller's axis 0 fastest: an odometer over the caller's index, its offset in
            // the C-ordered bytes (the caller's last axis fastest) kept up to date
            let mut stride = vec![1usize; d];
            for a in (0..d.saturating_sub(1)).rev() {
                stride[a] = stride[a + 1] * shape[a + 1];
            }
            let mut out = Vec::with_capacity(self.bytes.len());
            let (mut index, mut offset) = (vec![0usize; d], 0usize);
            for _ in 0..self.bytes.len() {
                out.push(self.bytes[offset]);
                for a in 0..d {
                    index[a] += 1;
                    offset += stride[a];
                    if index[a] < shape[a] {
                        break;
                    }
                    offset -= stride[a] * shape[a];
                    index[a] = 0;
                }
            }
            out
        } else {
            self.bytes.to_vec()
        };
        let min = if min.is_empty() { vec![0; d] } else { min.to_vec() };
        let set = CubicalSet::new(min, shape, bits).map_err(|e| Error::from_source(ErrorKind::Usage, e))?;
        Ok(Input::Cubical(crate::Sourced::new(set)))
    }
}

/// The number of cubes of a box of borrowed cubes of `shape`, or the refusal: no axis or
/// more than [`MAX_CUBE_AXES`], an empty axis, more than `MAX_BOX_CUBES` cubes.
fn check_box(shape: &[usize]) -> Result<u64> {
    let d = shape.len();
    if !(1..=MAX_CUBE_AXES).contains(&d) {
        return Err(err!(Usage, "a cubical array has 1 to {MAX_CUBE_AXES} dimensions, not {d}"));
    }
    if shape.contains(&0) {
        return Err(err!(Usage, "a cubical array of shape {shape:?}: every axis needs a cube"));
    }
    let volume = shape.iter().try_fold(1u64, |v, &s| v.checked_mul(s as u64));
    let max = gmap_ops::import::cubical::MAX_BOX_CUBES;
    match volume {
        Some(v) if v <= max => Ok(v),
        _ => Err(err!(Limit, "a cubical array of shape {shape:?} has more than {max} cubes, the largest box accepted")),
    }
}

/// Where a cubical route reads its cubes.
#[derive(Clone, Copy)]
pub(crate) enum Cubes<'a> {
    /// a cubical set read or built (its cells too, when it is not full)
    Set(&'a CubicalSet),
    /// an image, its cubes those of the values at a level
    Image(&'a Image, Level),
    /// cubes borrowed from memory
    Borrowed(&'a CubesRef<'a>),
}

impl Cubes<'_> {
    /// The box in storage order (axis 0 fastest).
    pub(crate) fn shape(&self) -> Vec<usize> {
        match self {
            Cubes::Set(s) => s.shape().to_vec(),
            Cubes::Image(img, _) => img.memory_shape(),
            Cubes::Borrowed(b) => b.shape.clone(),
        }
    }

    /// Whether the set holds cubes only (no lower cells of their own).
    pub(crate) fn is_full(&self) -> bool {
        match self {
            Cubes::Set(s) => s.is_full(),
            Cubes::Image(..) | Cubes::Borrowed(_) => true,
        }
    }

    /// The presence bytes of the cubes `start..start + out.len()`, axis 0 fastest.
    pub(crate) fn fill(&self, start: usize, out: &mut [u8]) {
        match self {
            Cubes::Set(s) => out.copy_from_slice(&s.bits()[start..start + out.len()]),
            Cubes::Image(img, level) => img.presence(*level, start, out),
            Cubes::Borrowed(b) => out.copy_from_slice(&b.bytes[start..start + out.len()]),
        }
    }

    /// Whether cube names come back in reverse storage order.
    pub(crate) fn reversed(&self) -> bool {
        matches!(self, Cubes::Borrowed(b) if b.reversed)
    }
}

/// The cubical set of an image at a level (a byte per cube), refused past the memory limit.
pub(crate) fn image_set(img: &Image, level: Level, file: &str) -> Result<CubicalSet> {
    img.to_cubical_set(level).map_err(|e| Error::from_source(ErrorKind::Limit, e).context(file.to_string()))
}

/// The groups of cubes of dimension ≤ 3 in one pass over them (`gmap_homology::cubical::pass`,
/// or `gmap_homology::cubical::torus` for a periodic box): no cubical complex, memory of a
/// layer (the torus: union-finds over the whole box). `None` for a periodic box whose
/// union-finds would not fit in memory (the cubical complex, slab by slab, may still), said
/// in a note. `fill(start, out)` writes the presence bytes of the cubes `start..start +
/// out.len()` (axis 0 fastest); `file` names the input in messages.
pub fn one_pass(
    shape: &[usize],
    fill: impl Fn(usize, &mut [u8]) + Sync,
    o: &HomologyOptions,
    file: &str,
) -> Result<Option<gmap_homology::Homology>> {
    let limit =
        |e: gmap_homology::cubical::CubicalError| Error::from_source(ErrorKind::Limit, e).context(file.to_string());
    let d = shape.len();
    let (betti, torsion): (Vec<u64>, Vec<Vec<u64>>) = if o.periodic {
        if !torus_fits(shape) {
            o.progress.note("the periodic one-pass route does not fit in memory: the cubical complex instead");
            return Ok(None);
        }
        o.progress.stage("one pass over the cubes of the torus: components of the set, of its complement and their windings, Euler characteristic");
        let r = gmap_homology::cubical::torus::betti_one_pass_periodic(shape, fill).map_err(limit)?;
        (r.betti, r.torsion)
    } else {
        o.progress.stage("one pass over the cubes: components of the set and of its complement, Euler characteristic");
        let r = gmap_homology::cubical::pass::betti_one_pass(shape, fill).map_err(limit)?;
        (r.betti, vec![Vec::new(); d + 1])
    };
    Ok(Some(groups_over(o.field, betti, torsion)))
}

/// Whether the periodic one-pass route's union-finds over the whole box fit in memory.
pub(crate) fn torus_fits(shape: &[usize]) -> bool {
    let what = "the periodic one-pass route";
    gmap_core::resources::check_memory(what, gmap_homology::cubical::torus::bytes_needed(shape)).is_ok()
}

/// Integer Betti numbers and torsion as groups over Z, or over Z/p by universal
/// coefficients (a factor divisible by p adds a Z/p to H_k and one to H_{k+1}).
fn groups_over(field: Option<u64>, betti: Vec<u64>, torsion: Vec<Vec<u64>>) -> gmap_homology::Homology {
    use gmap_homology::homology::Coefficients;
    let to_usize = |b: u64| usize::try_from(b).unwrap_or(usize::MAX);
    let d = betti.len() - 1;
    match field {
        None => gmap_homology::Homology {
            coefficients: Coefficients::Integers,
            betti: betti.into_iter().map(to_usize).collect(),
            torsion: torsion.into_iter().map(|t| t.into_iter().map(Into::into).collect()).collect(),
        },
        Some(p) => {
            let hits: Vec<usize> = torsion.iter().map(|t| t.iter().filter(|&&s| s % p == 0).count()).collect();
            let betti = (0..=d).map(|k| to_usize(betti[k]) + hits[k] + if k > 0 { hits[k - 1] } else { 0 }).collect();
            gmap_homology::Homology { coefficients: Coefficients::Field(p), betti, torsion: vec![Vec::new(); d + 1] }
        }
    }
}

/// The groups and a basis of cycles of a full cubical set of dimension ≤ 3 in a box that is
/// not periodic, from union-finds and a sweep over the grid (`gmap_homology::cubical::gens`:
/// a vertex per component, the boundary of each hole or cavity, in 3-D the fundamental
/// cycles of the sweep's forest), in time linear in the cells plus the cycles' length:
/// `bits` a byte per cube of `shape` (axis 0 fastest), the cells named by minimal vertex
/// (offset by `min`, the box's minimal vertex) and extent, their axes reversed with
/// `reversed`. Over Z/p the same cycles, their coefficients taken in `0..p`. `None` where
/// the sweep stops at a vertex (said in a note): the cycles then come from the cubical
/// complex.
pub fn sweep(
    shape: &[usize],
    bits: &[u8],
    min: &[i64],
    reversed: bool,
    o: &HomologyOptions,
    file: &str,
) -> Result<Option<(gmap_homology::Homology, Vec<NamedGenerator>)>> {
    check_field(o.field)?;
    o.progress
        .stage("one pass over the cells: components, the complement's components, the loops of a spanning forest");
    let g = match gmap_homology::cubical::gens::cubical_generators(shape, bits) {
        Ok(g) => g,
        Err(gmap_homology::cubical::CubicalError::NotReduced(why)) => {
            o.progress.note(&format!("{why}: the cubical complex instead"));
            return Ok(None);
        }
        Err(e) => return Err(Error::from_source(ErrorKind::Limit, e).context(file.to_string())),
    };
    let d = shape.len();
    let betti: Vec<u64> = g.betti.clone();
    let groups = groups_over(o.field, betti, vec![Vec::new(); d + 1]);
    let grid = std::sync::Arc::new(CubeGrid::new(&g.grid, min, reversed));
    let generators = g
        .generators
        .into_iter()
        .map(|z| {
            let mut cells = z.chain;
            if let Some(p) = o.field {
                for x in cells.iter_mut() {
                    x.1 = x.1.rem_euclid(p as i64);
                }
            }
            NamedGenerator {
                dim: z.dim,
                order: 0u64.into(),
                chain: Chain::Grid { cells, grid: grid.clone() },
                length: None,
            }
        })
        .collect();
    Ok(Some((groups, generators)))
}

/// The layers of the slowest axis per slab of the slab-by-slab cubical complex: rows of
/// about 32 MiB in all (two per layer), at least one layer and at most 64.
pub(crate) fn slab_layers(shape: &[usize]) -> usize {
    let row: usize = shape[..shape.len().saturating_sub(1)].iter().fold(1usize, |v, &l| v.saturating_mul(2 * l + 1));
    ((32usize << 20) / row.max(1) / 2).clamp(1, 64)
}

/// Refuses the options a cubical set does not take.
pub(crate) fn check_cubical_options(o: &HomologyOptions, file: &str) -> Result<()> {
    if o.method == Method::Simplicial {
        return Err(err!(
            Precondition,
            "{file}: a cubical set has no simplicial counterpart here; use --method cellular"
        ));
    }
    if o.simplify || o.topological {
        return Err(err!(Usage, "{file}: --simplify and --topological do not apply to cubical sets"));
    }
    Ok(())
}

/// The largest doubled grid whose whole cubical complex is built at once (about 1 GiB at
/// [`gmap_core::resources::CUBICAL_BYTES_PER_POINT`]); larger ones go slab by slab.
pub const WHOLE_GRID_POINTS: u64 = 1 << 27;

/// Whether the whole cubical complex of a box of `shape` is built at once (faster: dense
/// collapses over one array) rather than slab by slab (memory of a slab and the survivors).
pub(crate) fn whole_grid_fits(shape: &[usize], periodic: bool) -> bool {
    gmap_core::resources::cubical_grid_points(shape, periodic).is_some_and(|p| p <= WHOLE_GRID_POINTS)
}

/// The chain complex of cubes with their cells named by minimal vertex (`min`, the box's)
/// and extent: the whole complex after collapses of free faces when `whole` (a set with
/// cells of its own is always whole: they are marked on the grid), else built and reduced
/// slab by slab (`gmap_homology::cubical::slabs`; collapses only with generators, so that
/// its cycles are the set's), read in storage order.
pub(crate) fn complex(cubes: Cubes<'_>, whole: bool, o: &HomologyOptions, file: &str) -> Result<Named<'static>> {
    check_cubical_options(o, file)?;
    let shape = cubes.shape();
    let limit =
        |e: gmap_homology::cubical::CubicalError| Error::from_source(ErrorKind::Limit, e).context(file.to_string());
    let c = match (whole || !cubes.is_full(), cubes) {
        (true, Cubes::Image(img, level)) => {
            o.progress.stage("the image's cubical set");
            return complex(Cubes::Set(&image_set(img, level, file)?), true, o, file);
        }
        (true, Cubes::Set(set)) => {
            o.progress.stage("building the cubical complex");
            let cells = set.lower_cells_in_box();
            let c = gmap_homology::cubical::cubical_cell_complex_with(&shape, set.bits(), &cells, o.periodic, true);
            return Ok(named_cubes(c.map_err(limit)?, set.min(), o.generators, None));
        }
        (true, Cubes::Borrowed(b)) => {
            o.progress.stage("building the cubical complex");
            let what = "the cubical complex of the array";
            gmap_core::resources::check_memory(what, gmap_core::resources::cubical_set_estimate(&shape))?;
            let c = gmap_homology::cubical::cubical_complex_with(&shape, b.bytes, o.periodic, true);
            return Ok(named_cubes(c.map_err(limit)?, &[], o.generators, None));
        }
        (false, _) => {
            o.progress.stage(if matches!(cubes, Cubes::Image(..)) {
                "reading the image and reducing its cubical complex slab by slab"
            } else {
                "building and reducing the cubical complex slab by slab"
            });
            let fill = |s: usize, out: &mut [u8]| cubes.fill(s, out);
            gmap_homology::cubical::slabs::cubical_complex_slabs(
                &shape,
                fill,
                o.periodic,
                slab_layers(&shape),
                o.generators,
            )
            .map_err(limit)?
        }
    };
    let min = match cubes {
        Cubes::Set(set) => set.min().to_vec(),
        _ => Vec::new(),
    };
    Ok(named_cubes(c.complex, &min, o.generators, Some(c.relative)))
}

/// Names the cells of a cubical complex by minimal vertex (`min` the box's) and extent, when
/// `generators` asks for names.
fn named_cubes(
    c: gmap_homology::cubical::CubicalComplex,
    min: &[i64],
    generators: bool,
    relative: Option<gmap_homology::cubical::slabs::Relative>,
) -> Named<'static> {
    let names: Vec<Vec<(Vec<i64>, Vec<u8>)>> = if generators {
        let name = |k: usize, i: usize| {
            let coords = c.coordinates(k, i);
            let lo = coords.iter().enumerate().map(|(a, &x)| min.get(a).copied().unwrap_or(0) + (x / 2) as i64);
            (lo.collect(), coords.iter().map(|&x| (x % 2) as u8).collect())
        };
        (0..c.cells.len()).map(|k| (0..c.cells[k].len()).map(|i| name(k, i)).collect()).collect()
    } else {
        vec![Vec::new(); c.cells.len()]
    };
    let name = Box::new(move |k: usize, j: u32| {
        let (min, extent) = &names[k][j as usize];
        CellName::Cube { min: min.as_slice().into(), extent: extent.as_slice().into() }
    });
    Named { chain: c.chain, name, relative }
}
