//! The integer homology of a cubical set cut into slabs, each reduced apart: the route of
//! one image over several processes or machines, in any dimension.
//!
//! The box's cubes are cut along its slowest axis (the last one, axis 0 fastest) into
//! slabs of consecutive layers. Slab `i` builds the cubical complex of the closure of its
//! own cubes (on its doubled grid, [`super::grid`]); its cells on a cut between two slabs —
//! the hyperplanes of the doubled grid at the cut — are **shared**, every other cell is
//! **interior**. An interior cell's cofaces in the whole set are those it has in its slab
//! (a cube of another slab reaches no further than the cut), so:
//!
//! 1. the slab collapses its free faces that are not shared, then pairs its interior cells
//!    by coreductions and collapses with the shared cells critical from the start
//!    ([`crate::homology::reduce_keeping`]): every pair eliminated is a pair of the whole
//!    complex, the fill lands in the rows of the shared cells and of the interior cells left;
//! 2. what is left, a [`BlockComplex`], names its shared cells by their point of the whole
//!    doubled grid and its interior cells by their number in the slab;
//! 3. [`glue`] puts the slabs' survivors side by side, each shared cell once (its boundary,
//!    within the cut, is the same from both sides), and the whole reduced complex goes to
//!    [`crate::homology_z`]: exact over `Z`, torsion included, the same groups as the
//!    complex of the whole set.
//!
//! A slab of `m` layers holds its doubled grid (`(2m + 1) ∏ (2 L_a + 1)` points of about
//! 9 bytes, [`gmap_core::resources::CUBICAL_BYTES_PER_POINT`], checked against the memory
//! limit) while it reduces; what it sends is its survivors: the shared cells of its one or
//! two cuts (`≤ 3^(d-1) ∏ L_a` cells each) plus the interior cells that got stuck (on the
//! images measured, about as many as the slab's own Betti numbers). Time: the cubical
//! complex's, per slab.
//!
//! Dimension ≤ 3 images, whose one-pass route ([`super::pass`]) needs no complex,
//! are cut by [`super::pass::block_pass`] instead; this route serves every
//! dimension and is checked against it.
//!
//! ```
//! use gmap_homology::cubical::blocks::{block_complex, glue};
//! use gmap_homology::homology_z;
//! // a 3 × 3 ring of squares, two layers thick, cut between its layers: a solid torus
//! let ring = [1u8, 1, 1, 1, 0, 1, 1, 1, 1];
//! let bits: Vec<u8> = ring.iter().chain(&ring).copied().collect();
//! let fill = |s: usize, out: &mut [u8]| out.copy_from_slice(&bits[s..s + out.len()]);
//! let shape = [3, 3, 2];
//! let blocks = vec![block_complex(&shape, 0..1, &fill).unwrap(), block_complex(&shape, 1..2, &fill).unwrap()];
//! let whole = glue(&shape, &blocks).unwrap();
//! assert_eq!(homology_z(&whole).unwrap().betti, vec![1, 1, 0, 0]);
//! ```

use std::ops::Range;

use rustc_hash::FxHashMap;

use super::grid::{Grid, Order};
use super::{slab_complex, CubicalError};
use crate::complex::wire::{Reader, Writer};
use crate::homology::reduce_keeping;
use crate::{ChainComplex, SparseMatrix};

/// The key of an interior cell: this bit and the cell's number among its slab's survivors
/// of its dimension (a shared cell's key is its point of the whole doubled grid, below it).
pub const INTERIOR: u64 = 1 << 63;

/// What a slab keeps after its reduction: its survivors and the boundary between them.
#[derive(Clone, Debug)]
pub struct BlockComplex {
    /// the slab's layers of cubes
    pub layers: Range<usize>,
    /// `keys[k][j]`: survivor j of dimension k, a shared cell's point of the whole doubled
    /// grid, or [`INTERIOR`] `| j`
    pub keys: Vec<Vec<u64>>,
    /// the boundary between the survivors
    pub chain: ChainComplex,
}

impl BlockComplex {
    /// The number of survivors.
    pub fn cell_count(&self) -> usize {
        self.keys.iter().map(Vec::len).sum()
    }

    /// The message a process sends of it. O(cells + entries).
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut w = Writer::default();
        w.u64(self.layers.start as u64);
        w.u64(self.layers.end as u64);
        w.u64(self.keys.len() as u64);
        for keys in &self.keys {
            w.u64(keys.len() as u64);
            for &key in keys {
                w.u64(key);
            }
        }
        for k in 1..self.keys.len() {
            let m = self.chain.boundary(k);
            for j in 0..m.cols() {
                let (rows, vals) = m.col(j);
                w.u64(rows.len() as u64);
                for (&r, &v) in rows.iter().zip(vals) {
                    w.u64(r as u64);
                    w.i64(v);
                }
            }
        }
        w.bytes
    }

    /// Reads back what [`BlockComplex::to_bytes`] wrote; a malformed message is an error
    /// ([`CubicalError::BadMessage`]), never a panic.
    pub fn from_bytes(bytes: &[u8]) -> Result<BlockComplex, CubicalError> {
        let mut r = Reader::new(bytes, "a block complex");
        let start = r.usize(usize::MAX)?;
        let end = r.usize(usize::MAX)?;
        let dims = r.usize(64)?;
        if dims == 0 {
            return Err(r.error("no dimension"));
        }
        let mut keys = Vec::with_capacity(dims);
        for _ in 0..dims {
            let n = r.usize(bytes.len())?;
            let mut v = Vec::with_capacity(n);
            for _ in 0..n {
                v.push(r.u64()?);
            }
            keys.push(v);
        }
        let counts: Vec<usize> = keys.iter().map(Vec::len).collect();
        let mut mats = Vec::with_capacity(dims - 1);
        for k in 1..dims {
            let mut cols = Vec::with_capacity(counts[k]);
            for _ in 0..counts[k] {
                let n = r.usize(bytes.len())?;
                let mut col = Vec::with_capacity(n);
                for _ in 0..n {
                    col.push((r.u32()?, r.i64()?));
                }
                cols.push(col);
            }
            mats.push(SparseMatrix::try_from_columns(counts[k - 1], &cols).map_err(|e| r.error(&e.to_string()))?);
        }
        r.finish()?;
        let chain = ChainComplex::try_new(counts, mats).map_err(|e| r.error(&e.to_string()))?;
        Ok(BlockComplex { layers: start..end, keys, chain })
    }
}

/// Slab `layers` of the box of `shape` cubes (axis 0 fastest, the last axis cut), whose
/// presence bytes `fill(start, out)` writes for the cubes `start .. start + out.len()`
/// (called once, for the slab's cubes only), reduced with its cells on the cuts kept: see
/// the [module docs](self). Refuses an empty box or range, and a slab over the memory limit.
pub fn block_complex(
    shape: &[usize],
    layers: Range<usize>,
    fill: &impl Fn(usize, &mut [u8]),
) -> Result<BlockComplex, CubicalError> {
    let d = shape.len();
    if d == 0 || shape.contains(&0) {
        return Err(CubicalError::BadShape(format!("shape {shape:?}")));
    }
    let n = shape[d - 1];
    if layers.start >= layers.end || layers.end > n {
        return Err(CubicalError::BadShape(format!("layers {layers:?} of a box of {n}")));
    }
    let layer: usize = shape[..d - 1].iter().product();
    let volume = layer.checked_mul(layers.len()).ok_or_else(|| CubicalError::TooLarge {
        points: format!("{layer} × {} (a slab)", layers.len()),
        limit: usize::MAX as u64,
    })?;
    gmap_core::resources::check_memory("the slab's cubes", Some(volume as u64))?;
    let mut bits = vec![0u8; volume];
    fill(layers.start * layer, &mut bits);
    let mut local = shape.to_vec();
    local[d - 1] = layers.len();
    let (first, last) = (layers.start > 0, layers.end < n);
    let c = slab_complex(&local, &bits, first, last)?;
    drop(bits);
    // the slab's doubled grid: a hyperplane of its last axis has the same points as one of
    // the whole, whose doubled layer 2 · layers.start is the slab's first
    let g = Grid::new(c.grid.clone(), false, Order::FirstFastest)
        .ok_or_else(|| CubicalError::Internal(format!("the slab's grid {:?}", c.grid)))?;
    let (plane, top) = (g.strides()[d - 1], g.points()[d - 1] - 1);
    let shared = |p: u64| {
        let z = g.coord(p as usize, d - 1);
        (first && z == 0) || (last && z == top)
    };
    let r = reduce_keeping(&c.chain, |k, j| shared(c.cells[k][j]));
    let offset = (2 * layers.start * plane) as u64;
    let keys = r
        .ids
        .iter()
        .enumerate()
        .map(|(k, ids)| {
            ids.iter()
                .enumerate()
                .map(|(i, &j)| {
                    let p = c.cells[k][j as usize];
                    if shared(p) {
                        p + offset
                    } else {
                        INTERIOR | i as u64
                    }
                })
                .collect()
        })
        .collect();
    Ok(BlockComplex { layers, keys, chain: r.chain })
}

/// The complex of the whole box from its slabs' [`BlockComplex`]es, in any order: every
/// survivor once, a shared cell once whichever slabs have it. Refuses slabs of different
/// dimensions and a shared cell whose boundary differs between two slabs (they would not be
/// slabs of one box). O(survivors + entries).
pub fn glue(shape: &[usize], blocks: &[BlockComplex]) -> Result<ChainComplex, CubicalError> {
    let dims = shape.len() + 1;
    if let Some(b) = blocks.iter().find(|b| b.keys.len() != dims) {
        return Err(CubicalError::BadMessage(format!(
            "the block of layers {:?} has cells of {} dimensions, the box {dims}",
            b.layers,
            b.keys.len()
        )));
    }
    // per dimension: the whole complex's number of each survivor, per block
    let mut number: Vec<Vec<Vec<u32>>> = vec![Vec::with_capacity(blocks.len()); dims];
    let mut owner: Vec<Vec<(usize, usize)>> = vec![Vec::new(); dims];
    for k in 0..dims {
        let mut shared: FxHashMap<u64, u32> = FxHashMap::default();
        for (b, block) in blocks.iter().enumerate() {
            let mut ids = Vec::with_capacity(block.keys[k].len());
            for (j, &key) in block.keys[k].iter().enumerate() {
                let fresh = owner[k].len() as u32;
                let id = if key & INTERIOR != 0 { fresh } else { *shared.entry(key).or_insert(fresh) };
                if id == fresh {
                    owner[k].push((b, j));
                }
                ids.push(id);
            }
            number[k].push(ids);
        }
    }
    let counts: Vec<usize> = owner.iter().map(Vec::len).collect();
    let column = |k: usize, b: usize, j: usize| -> Vec<(u32, i64)> {
        let (rows, vals) = blocks[b].chain.boundary(k).col(j);
        let mut col: Vec<(u32, i64)> =
            rows.iter().zip(vals).map(|(&r, &v)| (number[k - 1][b][r as usize], v)).collect();
        col.sort_unstable_by_key(|e| e.0);
        col
    };
    let mut mats = Vec::with_capacity(dims - 1);
    for k in 1..dims {
        let cols: Vec<Vec<(u32, i64)>> = owner[k].iter().map(|&(b, j)| column(k, b, j)).collect();
        // a shared cell seen again: the same boundary
        for (b, ids) in number[k].iter().enumerate() {
            for (j, &id) in ids.iter().enumerate() {
                if owner[k][id as usize] != (b, j) && column(k, b, j) != cols[id as usize] {
                    return Err(CubicalError::BadMessage(format!(
                        "the shared {k}-cell {} has another boundary in the block of layers {:?}",
                        blocks[b].keys[k][j], blocks[b].layers
                    )));
                }
            }
        }
        mats.push(
            SparseMatrix::try_from_columns(counts[k - 1], &cols)
                .map_err(|e| CubicalError::BadMessage(format!("internal: {e}")))?,
        );
    }
    ChainComplex::try_new(counts, mats).map_err(|e| CubicalError::BadMessage(format!("the glued complex: {e}")))
}
