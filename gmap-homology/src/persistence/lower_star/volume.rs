//! 3-D images on the padded grid of their points: the V- and T-constructions' sweeps, which
//! share their phases (dimension 0's negative edges, dimension 2 on the dual, dimension 1 by
//! the reduction of [`super::middle`]), and the templates of the cells around a point.

use bitvec::vec::BitVec;

use super::middle::{square_boundary, Entry, Middle, TooLarge, OTHERS};
use super::sweep::{touch_rows, Forest, Out, AHEAD, BLOCK, CROSS, LOWER, UPPER};
use crate::complex::cubical::grid::{Grid, Order};
use crate::persistence::pairing::Zp;

/// A 3-D image on the grid of its points padded by one on every side: the pixel c at the
/// point c + (1, 1, 1). The border's rank is u32::MAX (never early), so that the
/// neighbours of a pixel are read with no test of the bounds.
pub(super) struct Padded {
    /// the padded grid's shape and strides
    pub(super) g: [usize; 3],
    pub(super) gstride: [usize; 3],
    /// the point of the pixel of each rank
    pub(super) at: Vec<u32>,
}

impl Padded {
    /// The grid, and one union-find node per point, `[point, rank]` (the rank of a
    /// neighbour is read from the cache line its node is on).
    pub(super) fn new(shape: [usize; 3], order: &[u32]) -> (Self, Forest) {
        let g = [shape[0] + 2, shape[1] + 2, shape[2] + 2];
        // C order, the last axis fastest ([`applies`] checked that the points fit a u32)
        let points = Grid::new(g.to_vec(), false, Order::LastFastest).expect("the padded grid fits a u32");
        let gstride = [points.strides()[0], points.strides()[1], points.strides()[2]];
        let inner = gstride[0] + gstride[1] + 1;
        let mut pix = Forest::new(g[0] * gstride[0]);
        for (v, node) in pix.nodes.iter_mut().enumerate() {
            *node = [v as u32, u32::MAX];
        }
        let at = order
            .iter()
            .enumerate()
            .map(|(r, &p)| {
                let p = p as usize;
                let (z, y, x) = (p / (shape[1] * shape[2]), (p / shape[2]) % shape[1], p % shape[2]);
                let v = z * gstride[0] + y * gstride[1] + x + inner;
                pix.nodes[v][1] = r as u32;
                v as u32
            })
            .collect();
        (Padded { g, gstride, at }, pix)
    }
}

/// A vertex or an edge of a voxel (T-construction, on [`Padded`]'s grid): its point's
/// offset from the voxel's point, its axis (an edge's), and the mask of the other voxels
/// around the voxel that contain it (in [`block_offsets`]' bits).
struct VoxelCell {
    at: isize,
    axis: usize,
    voxels: u32,
}

/// The voxel's cell whose point is its lower corner plus `delta` and that spans the axes
/// `spans` (none: a vertex; one: an edge along it).
fn voxel_cell(delta: [isize; 3], spans: Option<usize>, gstride: [usize; 3]) -> VoxelCell {
    let at = (0..3).map(|a| (delta[a] - 1) * gstride[a] as isize).sum();
    // along an axis the cell does not span, the voxels at delta - 1 and delta (relative to
    // the voxel) contain it; along the one it spans, only the voxel's own layer
    let mut voxels = 0;
    for k in 0..8 {
        let d: [isize; 3] = std::array::from_fn(|a| if Some(a) == spans { 0 } else { delta[a] - ((k >> a) & 1) });
        if d != [0, 0, 0] {
            voxels |= block_bit(d);
        }
    }
    VoxelCell { at, axis: spans.unwrap_or(0), voxels }
}

/// The eight vertices of a voxel.
fn corner_templates(gstride: [usize; 3]) -> [VoxelCell; 8] {
    std::array::from_fn(|k| voxel_cell([k >> 2 & 1, k >> 1 & 1, k & 1].map(|x| x as isize), None, gstride))
}

/// The twelve edges of a voxel, in the order of their ids `3 · point + axis`.
fn edge_templates(gstride: [usize; 3]) -> Vec<VoxelCell> {
    let mut edges: Vec<VoxelCell> = (0..3)
        .flat_map(|axis| {
            (0..4).map(move |k| {
                let [b, c] = OTHERS[axis];
                let mut delta = [0isize; 3];
                delta[b] = k & 1;
                delta[c] = k >> 1;
                voxel_cell(delta, Some(axis), gstride)
            })
        })
        .collect();
    edges.sort_unstable_by_key(|e| 3 * e.at + e.axis as isize);
    edges
}

/// The offsets of the 3 × 3 × 3 block around a point of a grid of strides `gstride`, in
/// the order of the block's bits `9(dz+1) + 3(dy+1) + (dx+1)`.
fn block_offsets(gstride: [usize; 3]) -> [isize; 27] {
    std::array::from_fn(|k| {
        let d = [k / 9, (k / 3) % 3, k % 3].map(|x| x as isize - 1);
        (0..3).map(|a| d[a] * gstride[a] as isize).sum()
    })
}

/// The bit of the offset `d` (each coordinate in -1, 0, 1) in a 3 × 3 × 3 block mask.
fn block_bit(d: [isize; 3]) -> u32 {
    1 << (9 * (d[0] + 1) + 3 * (d[1] + 1) + d[2] + 1)
}

/// A cube near a point: its eight corners as block bits, and the offset of its lower corner.
struct Template {
    corners: u32,
    at: isize,
}

/// The cube of lower corner `low` (offsets from a point), as a [`Template`].
fn cube_at(low: [isize; 3], gstride: [usize; 3]) -> Template {
    let corners = (0..8).fold(0, |m, k| m | block_bit([low[0] + (k >> 2), low[1] + ((k >> 1) & 1), low[2] + (k & 1)]));
    Template { corners, at: (0..3).map(|a| low[a] * gstride[a] as isize).sum() }
}

/// The eight cubes that have a point as a corner.
fn cube_templates(gstride: [usize; 3]) -> [Template; 8] {
    std::array::from_fn(|d| cube_at([-((d as isize >> 2) & 1), -((d as isize >> 1) & 1), -(d as isize & 1)], gstride))
}

/// A 2-cell that has a point as a corner: its four corners as block bits, the offset of its
/// id (`3 · lower corner + normal`) from three times the point, and its two cofaces.
struct FaceTemplate {
    corners: u32,
    id: isize,
    /// the offset of its latest edge from three times the point (V: of its two edges
    /// at the point, the one of larger id)
    pivot: isize,
    cofaces: [Template; 2],
}

/// The twelve 2-cells that have a point as a corner, by id.
fn face_templates(gstride: [usize; 3]) -> Vec<FaceTemplate> {
    let mut faces = Vec::with_capacity(12);
    for normal in 0..3 {
        let [a, b] = OTHERS[normal];
        for (da, db) in [(0isize, 0isize), (1, 0), (0, 1), (1, 1)] {
            let mut low = [0isize; 3];
            low[a] = -da;
            low[b] = -db;
            let mut corners = 0;
            for (ea, eb) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let mut c = low;
                c[a] += ea;
                c[b] += eb;
                corners |= block_bit(c);
            }
            let mut below = low;
            below[normal] -= 1;
            let at: isize = (0..3).map(|x| low[x] * gstride[x] as isize).sum();
            // the edges at the point: along a from low + db e_b, along b from low + da e_a
            let pivot = (-3 * da * gstride[a] as isize + a as isize).max(-3 * db * gstride[b] as isize + b as isize);
            faces.push(FaceTemplate {
                corners,
                id: 3 * at + normal as isize,
                pivot,
                cofaces: [cube_at(low, gstride), cube_at(below, gstride)],
            });
        }
    }
    faces.sort_unstable_by_key(|f| f.id);
    faces
}

/// Dimension 0's step across an edge: the edge `edge` (`3 · lower end + axis`) between the
/// nodes `x` and `y`, entering at rank `r`, joins two components (the younger one dies at
/// `r`) or closes a cycle; the edges that join two are marked in `negative_edges`.
#[inline]
fn join_edge(forest: &mut Forest, negative_edges: &mut BitVec, out: &mut Out, (x, y): (u32, u32), edge: usize, r: u32) {
    if let Some(young) = forest.union(x, y, true) {
        out.push(0, young, Some(r));
        negative_edges.set(edge, true);
    }
}

/// The dual of the top dimension: the cubes (numbered by their point) and the outside,
/// joined across the 2-cells, latest first.
struct Dual {
    forest: Forest,
    outside: u32,
}

impl Dual {
    /// Joins `x` and `y` across a 2-cell of rank `r`; if they were two components, the
    /// 2-cell kills the class of the younger one (`(2, r, its latest cube)`) and `true`.
    #[inline]
    fn join(&mut self, x: u32, y: u32, r: u32, out: &mut Out) -> bool {
        match self.forest.union(x, y, false) {
            Some(young) => {
                out.push(2, r, Some(young));
                true
            }
            None => false,
        }
    }
}

/// Dimension 2 on the dual (Alexander duality), pixel after pixel in reverse rank order over
/// a grid of `points` points: `ahead(point, nodes)` reads in what the step [`AHEAD`] ranks
/// later will need, `pixel(dual, out, point, rank)` makes the cubes of its pixel and joins
/// across its 2-cells, returning a bit per 2-cell that joined nothing (negative: left for
/// [`middle_pass`]). Returns those bits, by rank.
fn dual_pass<N: Copy + Default>(
    at: &[u32],
    points: usize,
    out: &mut Out,
    ahead: impl Fn(usize, &[[u32; 2]]),
    mut pixel: impl FnMut(&mut Dual, &mut Out, usize, u32) -> N,
) -> Vec<N> {
    let mut dual = Dual { forest: Forest::new(points + 1), outside: points as u32 };
    dual.forest.make(dual.outside, u32::MAX);
    let mut negative = vec![N::default(); at.len()];
    for r in (0..at.len()).rev() {
        if let Some(&q) = r.checked_sub(AHEAD).and_then(|a| at.get(a)) {
            ahead(q as usize, &dual.forest.nodes);
        }
        negative[r] = pixel(&mut dual, out, at[r] as usize, r as u32);
    }
    negative
}

/// Dimension 1: the columns of the negative 2-cells in rank order, reduced over `field`
/// without the negative edges (Bauer, Kerber and Reininghaus's compression: an edge that
/// joins two components is never the latest edge of a column being reduced, so its row
/// changes no pivot). `negative[r]` holds a bit per 2-cell of the pixel of rank `r` left
/// for this pass, `cell(point, bit)` gives that 2-cell's id and, where it may pair with its
/// latest edge without a column (V), that edge; an edge's key is
/// `(edge_time(lower end, axis) << 32) | id`; `ahead(point, owners)` reads in what the step
/// [`AHEAD`] ranks later will need. Fails as [`Middle::column`] does.
#[allow(clippy::too_many_arguments)] // the phase's inputs, and the three places the constructions differ
fn middle_pass<E: Entry, N: Copy + Into<u32>>(
    at: &[u32],
    negative: &[N],
    negative_edges: &BitVec,
    gstride: [usize; 3],
    field: Zp,
    out: &mut Out,
    edge_time: impl Fn(usize, usize) -> u32,
    ahead: impl Fn(usize, &[u32]),
    cell: impl Fn(usize, u32) -> (u32, Option<u32>),
) -> Result<(), TooLarge> {
    let edge_key = |v: usize, axis: usize| -> Option<u64> {
        let e = 3 * v + axis;
        if negative_edges[e] {
            return None;
        }
        Some(((edge_time(v, axis) as u64) << 32) | e as u64)
    };
    let mut middle = Middle::<E>::new(negative_edges.len(), gstride, field);
    for (r, &neg) in negative.iter().enumerate() {
        if let Some(&q) = at.get(r + AHEAD).filter(|_| negative[r + AHEAD].into() != 0) {
            ahead(q as usize, &middle.owner);
        }
        let (v, r) = (at[r] as usize, r as u32);
        let mut neg: u32 = neg.into();
        while neg != 0 {
            let (id, pivot) = cell(v, neg.trailing_zeros());
            neg &= neg - 1;
            // most 2-cells of V pair with their latest edge at once (its first coface): no
            // column to build, and a pair of one rank to leave out
            if pivot.is_some_and(|e| middle.take(e, id)) {
                continue;
            }
            middle.column(id, r, out, |id, col| square_boundary(id, gstride, field, edge_key, col))?;
        }
    }
    Ok(())
}

/// 3-D V-construction on the padded grid ([`Padded`]). Edges and 2-cells are named
/// `3 · point + axis`: an edge by its lower end and its axis, a 2-cell by its lower corner
/// and the axis it is normal to.
pub(super) fn v3<E: Entry>(grid: Padded, mut pix: Forest, field: Zp, out: &mut Out) -> Result<(), TooLarge> {
    let Padded { g, gstride, at } = grid;
    let points = g[0] * gstride[0];
    let steps = [gstride[0], gstride[1]];
    // dimension 0: the six neighbours, the edges to them in the order of their ids (lower
    // end, axis), as the filtration orders the edges of one rank
    let mut negative_edges: BitVec = BitVec::repeat(false, 3 * points);
    for (r, &v) in at.iter().enumerate() {
        if let Some(&q) = at.get(r + AHEAD) {
            touch_rows(&pix.nodes, q as usize, steps, &CROSS);
        }
        let r = r as u32;
        let v = v as usize;
        for (axis, q, low) in [
            (0, v - gstride[0], v - gstride[0]),
            (1, v - gstride[1], v - gstride[1]),
            (2, v - 1, v - 1),
            (0, v + gstride[0], v),
            (1, v + gstride[1], v),
            (2, v + 1, v),
        ] {
            if pix.nodes[q][1] < r {
                join_edge(&mut pix, &mut negative_edges, out, (v as u32, q as u32), 3 * low + axis, r);
            }
        }
    }
    let rank = pix.times(pix.nodes.len());
    drop(pix);
    let block = block_offsets(gstride);
    let (cubes, faces) = (cube_templates(gstride), face_templates(gstride));
    // the 3 × 3 × 3 block around the point `v` (bit `9(dz+1) + 3(dy+1) + (dx+1)`): the
    // pixels no later than rank `r`, and the pixels
    let masks = |v: usize, r: u32| -> (u32, u32) {
        let (mut early, mut real) = (0u32, 0u32);
        for (k, &o) in block.iter().enumerate() {
            let t = rank[v.wrapping_add_signed(o)];
            early |= u32::from(t <= r) << k;
            real |= u32::from(t != u32::MAX) << k;
        }
        (early, real)
    };

    // dimension 2: the cubes at a pixel by their lower corner; bit k of a pixel's bits is
    // its 2-cell `faces[k]`
    let ahead = |q: usize, nodes: &[[u32; 2]]| {
        touch_rows(&rank, q, steps, &BLOCK);
        touch_rows(nodes, q, steps, &LOWER);
    };
    let negative = dual_pass(&at, points, out, ahead, |dual, out, v, r| {
        let (early, real) = masks(v, r);
        for cube in &cubes {
            if early & cube.corners == cube.corners {
                dual.forest.make(v.wrapping_add_signed(cube.at) as u32, r);
            }
        }
        let outside = dual.outside;
        let node =
            |c: &Template| if real & c.corners == c.corners { v.wrapping_add_signed(c.at) as u32 } else { outside };
        let mut neg = 0u16;
        for (k, face) in faces.iter().enumerate().rev() {
            if early & face.corners == face.corners
                && !dual.join(node(&face.cofaces[0]), node(&face.cofaces[1]), r, out)
            {
                neg |= 1 << k;
            }
        }
        neg
    });

    // dimension 1: an edge's time is its latest end's
    middle_pass::<E, u16>(
        &at,
        &negative,
        &negative_edges,
        gstride,
        field,
        out,
        |v, axis| rank[v].max(rank[v + gstride[axis]]),
        |q, owner| {
            touch_rows(&rank, q, steps, &BLOCK);
            touch_rows(owner, 3 * q, [3 * gstride[0], 3 * gstride[1]], &LOWER);
        },
        |v, k| {
            let face = &faces[k as usize];
            ((3 * v).wrapping_add_signed(face.id) as u32, Some((3 * v).wrapping_add_signed(face.pivot) as u32))
        },
    )
}

/// 3-D T-construction: the voxels are the top cells. Voxels, vertices, edges and 2-cells
/// live on the padded grid ([`Padded`]: the voxel c at the point c + (1, 1, 1), its lower
/// corner at the point c); edges and 2-cells are named `3 · point + axis` (a 2-cell by its
/// lower corner and its normal axis). A cell's time is the rank of its earliest voxel.
pub(super) fn t3<E: Entry>(grid: Padded, pix: Forest, field: Zp, out: &mut Out) -> Result<(), TooLarge> {
    let Padded { g, gstride, at } = grid;
    let block = block_offsets(gstride);
    let rank = pix.times(pix.nodes.len());
    let points = g[0] * gstride[0];
    let inner = gstride[0] + gstride[1] + 1;
    let steps = [gstride[0], gstride[1]];

    // dimension 0 on the vertices and edges themselves (their nodes reuse the voxels'):
    // each voxel brings the vertices and edges none of its neighbours brought before it
    // (a cell's time is its earliest voxel's), the vertices first, then the edges in the
    // order of their ids, as the filtration orders the cells of one rank
    let mut vert = pix;
    let (corners, edges) = (corner_templates(gstride), edge_templates(gstride));
    let mut negative_edges: BitVec = BitVec::repeat(false, 3 * points);
    for (r, &v) in at.iter().enumerate() {
        if let Some(&q) = at.get(r + AHEAD) {
            touch_rows(&rank, q as usize, steps, &BLOCK);
            touch_rows(&vert.nodes, q as usize - inner, steps, &UPPER);
        }
        let (v, r) = (v as usize, r as u32);
        let mut early = 0u32;
        for (k, &o) in block.iter().enumerate() {
            early |= u32::from(rank[v.wrapping_add_signed(o)] < r) << k;
        }
        for c in &corners {
            if early & c.voxels == 0 {
                vert.make(v.wrapping_add_signed(c.at) as u32, r);
            }
        }
        for e in &edges {
            if early & e.voxels == 0 {
                let low = v.wrapping_add_signed(e.at);
                let ends = (low as u32, (low + gstride[e.axis]) as u32);
                join_edge(&mut vert, &mut negative_edges, out, ends, 3 * low + e.axis, r);
            }
        }
    }
    drop(vert);
    // the six faces of a voxel by id, as (offset of the id from 3 · its lower corner,
    // offset of the other voxel): below along z, y, x, then above along x, y, z
    let faces: [(usize, isize); 6] = std::array::from_fn(|k| {
        let a = if k < 3 { k } else { 5 - k };
        let s = gstride[a] as isize;
        if k < 3 {
            (a, -s)
        } else {
            (3 * gstride[a] + a, s)
        }
    });

    // dimension 2: the voxels; a face is its voxel's own when the other voxel is later or
    // absent
    let ahead = |q: usize, nodes: &[[u32; 2]]| {
        touch_rows(&rank, q, steps, &CROSS);
        touch_rows(nodes, q, steps, &CROSS);
    };
    let negative = dual_pass(&at, points, out, ahead, |dual, out, v, r| {
        dual.forest.make(v as u32, r);
        let mut neg = 0u8;
        for (k, &(_, o)) in faces.iter().enumerate().rev() {
            let q = v.wrapping_add_signed(o);
            let t = rank[q];
            if t <= r {
                continue; // the face is the other voxel's
            }
            let other = if t == u32::MAX { dual.outside } else { q as u32 };
            if !dual.join(v as u32, other, r, out) {
                neg |= 1 << k;
            }
        }
        neg
    });

    // dimension 1: an edge's time is its earliest voxel's
    middle_pass::<E, u8>(
        &at,
        &negative,
        &negative_edges,
        gstride,
        field,
        out,
        |v, axis| {
            let [b, c] = OTHERS[axis];
            let at = v + inner;
            rank[at].min(rank[at - gstride[b]]).min(rank[at - gstride[c]]).min(rank[at - gstride[b] - gstride[c]])
        },
        |q, owner| {
            touch_rows(&rank, q, steps, &BLOCK);
            touch_rows(owner, 3 * (q - inner), [3 * gstride[0], 3 * gstride[1]], &UPPER);
        },
        |v, k| ((3 * (v - inner) + faces[k as usize].0) as u32, None),
    )
}
