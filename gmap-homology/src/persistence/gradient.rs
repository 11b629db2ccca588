//! Persistence of an image too large to hold: the Morse complex of its lower stars.
//!
//! The other routes of [`super::image`] keep a value (and more) per cell of the doubled
//! grid, about 2^d cells per pixel. This one keeps nothing per pixel: it reads the image
//! through a function (an `.npy` through its memory map), slab after slab of pixels, and
//! holds only the **critical cells** of a discrete gradient and their boundaries.
//!
//! ## The gradient
//!
//! Every cell of the filtration has an **owner**, the pixel whose value it takes: in the
//! V-construction the largest of its vertices, in the T-construction the smallest of the
//! top cells around it (ties broken by the pixel's index, a total order refining the
//! values). The cells a pixel owns, its **lower star**, all enter the filtration at its
//! value and lie in the 3^d cells around it, so they can be paired from the pixel's 3^d
//! neighbours alone. They are paired by `ProcessLowerStars` (Robins, Wood and Sheppard,
//! docs/REFERENCES.md), which pairs each cell with a face or coface of the same lower star
//! into an acyclic matching; the cells it leaves unpaired are critical. The algorithm is
//! written for a vertex's lower star in a complex of cubes whose vertices are the pixels:
//! that is the V-construction's grid, and the T-construction's after duality (its pixels
//! are the top cells; a cell's pixels are the top cells around it, the padding outside the
//! box lowest of all), a lattice face being a face of the grid's cell in V and a coface in
//! T.
//!
//! ## The Morse complex
//!
//! The critical cells with the boundary `∂_M` (the sum over gradient paths from a cell's
//! faces down to critical cells, signed over `Z/p`) form a filtered complex with the same
//! persistence diagram as the image, since every pair of the matching enters at one value
//! (Mischaikow and Nanda, docs/REFERENCES.md). `∂_M` of a cell of dimension 1 to d-1 is
//! found by flowing its boundary down the gradient (the cells reached, in topological
//! order); `∂_M` of the top cells from the other side, following from each critical
//! (d-1)-cell its at most two cofaces up the gradient, a path that never branches (a
//! (d-1)-cell has two cofaces at most). A pixel's pairing is computed again whenever a path
//! meets one of its cells (a small cache per thread keeps the last ones).
//!
//! The diagram of the critical complex comes from the column reduction the other routes
//! use, from the top dimension down with clearing: a cell whose column is cleared needs no
//! boundary, so the gradient paths are followed only from the others.
//!
//! Cost: the first pass is `O(3^d · 2^d)` per pixel, on every thread; the boundaries cost
//! the cells their gradient paths meet, small on images whose values vary smoothly (few
//! critical cells, whatever the size) and large on noise, where a good part of the cells
//! stay critical. Plateaus (equal neighbours, as in 8-bit images) are ordered by index,
//! which leaves critical cells of zero persistence where plateaus meet. Memory: about
//! [`BYTES_PER_CRITICAL`] per critical cell, checked against the limit given while the
//! first pass runs, and a cache of pairings per thread (a few MB). Images of 1 to 4 axes
//! (the order G of a lower star is kept as a 128-bit mask of the 3^d − 1 neighbours). Not
//! built: periodic images (a torus) and representative cycles (a cycle of the critical
//! complex is not one of the image until mapped back).

#![allow(clippy::needless_range_loop)] // axes index several arrays at once

use std::sync::atomic::{AtomicU64, Ordering};

use rustc_hash::FxHashMap;

use super::options::{check_field, key, Construction, CubicalOptions};
use super::pairing::{reduce_dim, Entry, Zp};
use super::{Diagram, PersistenceError};
use crate::complex::cubical::grid::{Grid, Order, Placement};

/// Bytes held per critical cell, for the limit: its place in the list (16), its name and
/// boundary in the critical complex (about 64), and the diagram's reduction (16).
pub const BYTES_PER_CRITICAL: u64 = 96;

/// A local cell outside the lower star.
const OUT: u16 = u16::MAX;
/// A critical local cell.
const CRIT: u16 = u16::MAX - 1;
/// A local cell of the lower star not classified yet.
const OPEN: u16 = u16::MAX - 2;

/// The 3^d cells of the lattice around a pixel, numbered in base 3 (digit `δ_a + 1` per
/// axis, axis 0 most significant); the same numbers name the 3^d pixels around it.
struct Star {
    d: usize,
    /// `delta[q * d + a]` in `{-1, 0, 1}`
    delta: Vec<i8>,
    /// the lattice dimension (number of nonzero `δ_a`)
    support: Vec<u8>,
    /// the faces containing the centre (one nonzero `δ_a` set to 0)
    faces: Vec<Vec<u16>>,
    /// the cofaces (one zero `δ_a` set to ±1)
    cofaces: Vec<Vec<u16>>,
    /// local cells by lattice dimension, ascending
    by_support: Vec<u16>,
    centre: u16,
}

impl Star {
    fn new(d: usize) -> Self {
        let k = 3usize.pow(d as u32);
        let mut delta = vec![0i8; k * d];
        for q in 0..k {
            let mut r = q;
            for a in (0..d).rev() {
                delta[q * d + a] = (r % 3) as i8 - 1;
                r /= 3;
            }
        }
        let pow: Vec<usize> = (0..d).map(|a| 3usize.pow((d - 1 - a) as u32)).collect();
        let support: Vec<u8> =
            (0..k).map(|q| delta[q * d..(q + 1) * d].iter().filter(|&&x| x != 0).count() as u8).collect();
        let mut faces = vec![Vec::new(); k];
        let mut cofaces = vec![Vec::new(); k];
        for q in 0..k {
            let dq = &delta[q * d..(q + 1) * d];
            for a in 0..d {
                if dq[a] != 0 {
                    // zeroing axis a: digit 0 or 2 becomes 1
                    let f = (q as i64 - dq[a] as i64 * pow[a] as i64) as usize;
                    faces[q].push(f as u16);
                    cofaces[f].push(q as u16);
                }
            }
        }
        let mut by_support: Vec<u16> = (0..k as u16).collect();
        by_support.sort_by_key(|&q| support[q as usize]);
        Star { d, delta, support, faces, cofaces, by_support, centre: ((k - 1) / 2) as u16 }
    }

    fn len(&self) -> usize {
        self.support.len()
    }
}

/// The image and its grid: pixels per axis, the doubled grid, the owner's order.
struct Lattice<'a> {
    /// pixels per axis (C order: the last fastest)
    n: Vec<usize>,
    pstride: Vec<usize>,
    /// the doubled grid ([`crate::cubical::grid`]), not periodic: `2n - 1` points per axis
    /// (V) or `2n + 1` (T)
    grid: Grid,
    t: bool,
    sign: f64,
    value: &'a (dyn Fn(usize) -> f64 + Sync),
    /// the index offset of each local pixel of a star
    offsets: Vec<i64>,
}

/// A pixel's rank in the owners' order (the owner of a cell is its largest-ranked pixel);
/// 0 is below every pixel (the T-construction's padding).
type Rank = u128;

impl Lattice<'_> {
    fn d(&self) -> usize {
        self.n.len()
    }

    /// The value (times the sign) of pixel `i`, refusing a NaN.
    fn pixel(&self, i: usize) -> Result<f64, PersistenceError> {
        let v = (self.value)(i);
        if v.is_nan() {
            return Err(PersistenceError::BadInput(format!("value {i} is NaN")));
        }
        Ok(self.sign * v)
    }

    fn rank(&self, i: usize) -> Result<Rank, PersistenceError> {
        let r = ((key(self.pixel(i)?) as u128) << 64) | i as u128;
        // T: the smallest value owns (ties: the smallest index)
        Ok(if self.t { !r } else { r })
    }

    /// The primal cell of local cube `q` of pixel `x`: `2x + δ` (V), `2x + 1 + δ` (T).
    fn cell(&self, star: &Star, x: &[usize], q: u16) -> usize {
        let dq = &star.delta[q as usize * star.d..(q as usize + 1) * star.d];
        let off = i64::from(self.t);
        let stride = self.grid.strides();
        (0..self.d()).map(|a| (2 * x[a] as i64 + off + dq[a] as i64) as usize * stride[a]).sum()
    }

    /// The owner of grid cell `g` (its pixel coordinates in `x`) and the local cube it is
    /// in that pixel's star.
    fn owner(&self, g: usize, x: &mut [usize]) -> Result<u16, PersistenceError> {
        let d = self.d();
        let mut best: Option<(Rank, usize)> = None;
        // candidate pixels per axis: one or two
        let mut lo = [0usize; 8];
        let mut two = [false; 8];
        let mut count = 0;
        let mut c = [0usize; 8];
        for a in 0..d {
            let ca = self.grid.coord(g, a);
            c[a] = ca;
            if !self.t {
                lo[a] = ca / 2;
                two[a] = ca & 1 == 1;
            } else if ca & 1 == 1 {
                lo[a] = (ca - 1) / 2;
            } else if ca == 0 {
                lo[a] = 0;
            } else if ca / 2 == self.n[a] {
                lo[a] = ca / 2 - 1;
            } else {
                lo[a] = ca / 2 - 1;
                two[a] = true;
            }
            count += usize::from(two[a]);
        }
        let mut axes = [0usize; 8];
        for (j, a) in (0..d).filter(|&a| two[a]).enumerate() {
            axes[j] = a;
        }
        let axes = &axes[..count];
        for mask in 0..1usize << count {
            let mut idx = 0;
            for a in 0..d {
                idx += lo[a] * self.pstride[a];
            }
            for (b, &a) in axes.iter().enumerate() {
                if mask >> b & 1 == 1 {
                    idx += self.pstride[a];
                }
            }
            let r = self.rank(idx)?;
            if best.is_none_or(|(br, _)| r > br) {
                best = Some((r, mask));
            }
        }
        let mask = best.map_or(0, |b| b.1);
        let mut q = 0usize;
        for a in 0..d {
            x[a] = lo[a];
            if let Some(b) = axes.iter().position(|&y| y == a) {
                x[a] += mask >> b & 1;
            }
            let off = i64::from(self.t);
            let delta = c[a] as i64 - 2 * x[a] as i64 - off;
            q = q * 3 + (delta + 1) as usize;
        }
        Ok(q as u16)
    }

    /// `ProcessLowerStars` on pixel `x`: `class[q]` is [`OUT`], [`CRIT`] or the local cube
    /// paired with `q`.
    fn process(&self, star: &Star, x: &[usize], s: &mut Scratch) -> Result<(), PersistenceError> {
        let (d, k) = (star.d, star.len());
        s.class.clear();
        s.class.resize(k, OUT);
        s.rank.clear();
        // ranks of the pixels around x; None outside the box in V
        let centre: usize = x.iter().zip(&self.pstride).map(|(x, s)| x * s).sum();
        if (0..d).all(|a| x[a] > 0 && x[a] + 1 < self.n[a]) {
            for &off in &self.offsets {
                s.rank.push(Some(self.rank((centre as i64 + off) as usize)?));
            }
        } else {
            for q in 0..k {
                let dq = &star.delta[q * d..(q + 1) * d];
                let inside = (0..d).all(|a| {
                    let y = x[a] as i64 + dq[a] as i64;
                    y >= 0 && y < self.n[a] as i64
                });
                s.rank.push(if inside {
                    Some(self.rank((centre as i64 + self.offsets[q]) as usize)?)
                } else if self.t {
                    Some(0)
                } else {
                    None
                });
            }
        }
        let r0 = s.rank[star.centre as usize].expect("the centre is inside");
        // the order G of the algorithm compares cubes by their pixels' ranks, largest first,
        // lexicographically: that is the order of the sets of their pixels as bit masks, a
        // pixel's bit being its place among the pixels below the centre
        s.pos.clear();
        s.pos.extend((0..k as u16).filter(|&q| s.rank[q as usize].is_some_and(|r| r < r0)));
        s.pos.sort_unstable_by_key(|&q| s.rank[q as usize]);
        s.mask.clear();
        s.mask.resize(k, 0);
        for (i, &q) in s.pos.iter().enumerate() {
            s.mask[q as usize] = 1u128 << i;
        }
        s.mask[star.centre as usize] = 1u128 << 127;
        // a cube is in the lower star when its other pixels are all below the centre; its
        // mask is its far corner's bit and its faces' masks
        for &q in &star.by_support {
            let q = q as usize;
            let below = q == star.centre as usize || s.rank[q].is_some_and(|r| r < r0);
            if below && star.faces[q].iter().all(|&f| s.class[f as usize] != OUT) {
                s.class[q] = OPEN;
                for &f in &star.faces[q] {
                    s.mask[q] |= s.mask[f as usize];
                }
            }
        }
        let c = star.centre;
        s.zero.clear();
        s.one.clear();
        s.zero.extend(star.cofaces[c as usize].iter().copied().filter(|&e| s.class[e as usize] != OUT));
        let Some(i) = pop_min(s, false) else {
            s.class[c as usize] = CRIT;
            return Ok(());
        };
        let first = s.zero.swap_remove(i);
        s.class[c as usize] = first;
        s.class[first as usize] = c;
        push_ready(star, s, first);
        loop {
            while let Some(i) = pop_min(s, true) {
                let a = s.one.swap_remove(i);
                if s.class[a as usize] != OPEN {
                    continue;
                }
                let mut open = star.faces[a as usize].iter().copied().filter(|&f| s.class[f as usize] == OPEN);
                match (open.next(), open.next()) {
                    (None, _) => s.zero.push(a),
                    (Some(f), None) => {
                        s.class[a as usize] = f;
                        s.class[f as usize] = a;
                        push_ready(star, s, a);
                        push_ready(star, s, f);
                    }
                    _ => {}
                }
            }
            match pop_min(s, false) {
                Some(i) => {
                    let a = s.zero.swap_remove(i);
                    if s.class[a as usize] == OPEN {
                        s.class[a as usize] = CRIT;
                        push_ready(star, s, a);
                    }
                }
                None => break,
            }
        }
        Ok(())
    }
}

/// Pushes onto the queue of one the open cofaces of `q` with exactly one open face.
fn push_ready(star: &Star, s: &mut Scratch, q: u16) {
    for &b in &star.cofaces[q as usize] {
        if s.class[b as usize] == OPEN
            && star.faces[b as usize].iter().filter(|&&f| s.class[f as usize] == OPEN).count() == 1
        {
            s.one.push(b);
        }
    }
}

/// The position of the least cube (in the order G) of the queue of one or of zero.
fn pop_min(s: &Scratch, one: bool) -> Option<usize> {
    let q = if one { &s.one } else { &s.zero };
    (0..q.len()).min_by_key(|&i| s.mask[q[i] as usize])
}

/// Buffers of one pixel's `ProcessLowerStars`.
#[derive(Default)]
struct Scratch {
    class: Vec<u16>,
    rank: Vec<Option<Rank>>,
    /// the local pixels below the centre, by rank
    pos: Vec<u16>,
    /// each cube's pixels as a bit mask (bit i: the i-th of `pos`; bit 127: the centre)
    mask: Vec<u128>,
    one: Vec<u16>,
    zero: Vec<u16>,
}

/// How the gradient treats a grid cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Class {
    Critical,
    /// paired with this coface
    Up(usize),
    /// paired with this face
    Down(usize),
}

/// The pairings of the pixels last asked for (direct-mapped by pixel index), and buffers.
struct Gradient<'a> {
    lat: &'a Lattice<'a>,
    star: &'a Star,
    tags: Vec<u64>,
    classes: Vec<u16>,
    scratch: Scratch,
    x: Vec<usize>,
}

const CACHE_SLOTS: usize = 1 << 16;

impl<'a> Gradient<'a> {
    fn new(lat: &'a Lattice<'a>, star: &'a Star) -> Self {
        Gradient {
            lat,
            star,
            tags: vec![u64::MAX; CACHE_SLOTS],
            classes: vec![OUT; CACHE_SLOTS * star.len()],
            scratch: Scratch::default(),
            x: vec![0; lat.d()],
        }
    }

    fn class(&mut self, id: usize) -> Result<Class, PersistenceError> {
        let (lat, star) = (self.lat, self.star);
        let q = lat.owner(id, &mut self.x)?;
        let pixel = self.x.iter().zip(&lat.pstride).map(|(x, s)| x * s).sum::<usize>() as u64;
        let slot = (pixel as usize).wrapping_mul(0x9E37_79B9) % CACHE_SLOTS;
        let k = star.len();
        if self.tags[slot] != pixel {
            lat.process(star, &self.x, &mut self.scratch)?;
            self.classes[slot * k..(slot + 1) * k].copy_from_slice(&self.scratch.class);
            self.tags[slot] = pixel;
        }
        let p = self.classes[slot * k + q as usize];
        if p == OUT || p == OPEN {
            return Err(PersistenceError::BadInput(format!(
                "internal: grid cell {id} is not in its owner's lower star"
            )));
        }
        if p == CRIT {
            return Ok(Class::Critical);
        }
        let other = lat.cell(star, &self.x, p);
        // a lattice coface is a coface of the grid in V and a face in T
        let lattice_up = star.support[p as usize] > star.support[q as usize];
        Ok(if lattice_up != lat.t { Class::Up(other) } else { Class::Down(other) })
    }
}

/// `∂_M` of a critical cell of dimension 1 to d-1: its boundary flowed down the gradient,
/// the cells reached visited in topological order. Entries are (critical face, coefficient).
fn flow_down(grad: &mut Gradient<'_>, zp: Zp, id: usize, out: &mut Vec<(usize, u32)>) -> Result<(), PersistenceError> {
    let lat = grad.lat;
    out.clear();
    let mut faces = Vec::new();
    lat.grid.faces(id, &mut faces);
    // the faces reached: each one's class, its successors `succ[start..end]` (the faces of
    // the coface it is paired with), its DFS state (0 new, 1 on the stack, 2 done)
    let mut index: FxHashMap<usize, u32> = FxHashMap::default();
    let mut nodes: Vec<(usize, Class, usize, usize)> = Vec::new();
    let mut state: Vec<u8> = Vec::new();
    let mut succ: Vec<(usize, i64)> = Vec::new();
    let mut post: Vec<u32> = Vec::new();
    let mut stack: Vec<(u32, usize)> = Vec::new();
    let mut gf = Vec::new();
    let mut visit = |f: usize,
                     grad: &mut Gradient<'_>,
                     nodes: &mut Vec<(usize, Class, usize, usize)>,
                     state: &mut Vec<u8>,
                     succ: &mut Vec<(usize, i64)>|
     -> Result<u32, PersistenceError> {
        if let Some(&i) = index.get(&f) {
            return Ok(i);
        }
        let class = grad.class(f)?;
        let start = succ.len();
        if let Class::Up(g) = class {
            lat.grid.faces(g, &mut gf);
            succ.extend_from_slice(&gf);
        }
        let i = nodes.len() as u32;
        nodes.push((f, class, start, succ.len()));
        state.push(0);
        index.insert(f, i);
        Ok(i)
    };
    let mut roots = Vec::with_capacity(faces.len());
    for &(f, _) in &faces {
        let root = visit(f, grad, &mut nodes, &mut state, &mut succ)?;
        roots.push(root);
        if state[root as usize] != 0 {
            continue;
        }
        state[root as usize] = 1;
        stack.push((root, nodes[root as usize].2));
        while let Some(top) = stack.last_mut() {
            let (n, next) = (top.0, top.1);
            let (nid, _, _, end) = nodes[n as usize];
            if next < end {
                top.1 += 1;
                let (child, _) = succ[next];
                if child == nid {
                    continue;
                }
                let ch = visit(child, grad, &mut nodes, &mut state, &mut succ)?;
                match state[ch as usize] {
                    0 => {
                        state[ch as usize] = 1;
                        stack.push((ch, nodes[ch as usize].2));
                    }
                    1 => {
                        return Err(PersistenceError::BadInput(format!(
                            "internal: the gradient has a closed path through grid cell {child}"
                        )))
                    }
                    _ => {}
                }
            } else {
                state[n as usize] = 2;
                post.push(n);
                stack.pop();
            }
        }
    }
    // coefficients, in topological order (reverse postorder)
    let mut acc = vec![0u32; nodes.len()];
    for (&(_, s), &r) in faces.iter().zip(&roots) {
        acc[r as usize] = zp.add(acc[r as usize], zp.of(s));
    }
    for &n in post.iter().rev() {
        let (fid, class, start, end) = nodes[n as usize];
        let a = acc[n as usize];
        if a == 0 {
            continue;
        }
        match class {
            Class::Critical => out.push((fid, a)),
            Class::Down(_) => {}
            Class::Up(_) => {
                let w = succ[start..end].iter().find(|e| e.0 == fid).map_or(1, |e| zp.of(e.1));
                let factor = zp.neg(zp.mul(a, zp.inv(w)));
                for &(f2, s2) in &succ[start..end] {
                    if f2 != fid {
                        let j = index[&f2] as usize;
                        acc[j] = zp.add(acc[j], zp.mul(factor, zp.of(s2)));
                    }
                }
            }
        }
    }
    out.sort_unstable();
    Ok(())
}

/// The coefficient of face `f` in the boundary of `g`, and `g`'s faces into `buf`.
fn incidence(lat: &Lattice<'_>, g: usize, f: usize, buf: &mut Vec<(usize, i64)>) -> i64 {
    lat.grid.faces(g, buf);
    buf.iter().find(|e| e.0 == f).map_or(0, |e| e.1)
}

/// The cofaces of a (d-1)-cell: along its one even axis, below and above when inside.
fn top_cofaces(lat: &Lattice<'_>, f: usize) -> [Option<usize>; 2] {
    let a = (0..lat.d()).find(|&a| lat.grid.coord(f, a) & 1 == 0).expect("a (d-1)-cell has an even axis");
    lat.grid.cofaces_along(f, a, lat.grid.coord(f, a))
}

/// The entries of `∂_M` on a critical (d-1)-cell `c`: (critical top cell, coefficient),
/// by following each coface of `c` up the gradient.
fn flow_up(
    grad: &mut Gradient<'_>,
    zp: Zp,
    c: usize,
    out: &mut Vec<(usize, usize, u32)>,
) -> Result<(), PersistenceError> {
    let lat = grad.lat;
    let mut buf = Vec::new();
    let limit = lat.grid.len();
    for start in top_cofaces(lat, c).into_iter().flatten() {
        let (mut face, mut cur, mut coef) = (c, start, 1u32);
        let mut steps = 0usize;
        loop {
            let w = zp.of(incidence(lat, cur, face, &mut buf));
            match grad.class(cur)? {
                Class::Critical => {
                    out.push((cur, c, zp.mul(coef, w)));
                    break;
                }
                Class::Up(_) => break,
                Class::Down(f) => {
                    let wf = zp.of(incidence(lat, cur, f, &mut buf));
                    coef = zp.neg(zp.mul(coef, zp.mul(w, zp.inv(wf))));
                    let next = top_cofaces(lat, f).into_iter().flatten().find(|&g| g != cur);
                    match next {
                        Some(g) => {
                            face = f;
                            cur = g;
                        }
                        None => break,
                    }
                }
            }
            steps += 1;
            if steps > limit {
                return Err(PersistenceError::BadInput(format!(
                    "internal: the gradient has a closed path through grid cell {cur}"
                )));
            }
        }
    }
    Ok(())
}

/// The persistence diagram of the image of shape `shape` (C order) whose pixel `i` is
/// `value(i)`, through the Morse complex of its lower stars (module docs). Refuses, as
/// [`PersistenceError::TooLarge`], a critical complex past `max_bytes` (with
/// [`super::image::PROCESS_BYTES`]), as soon as the first pass finds it so; a NaN, naming
/// its index; and the options it does not build: periodic images and cycles.
pub fn morse_persistence(
    shape: &[usize],
    value: &(dyn Fn(usize) -> f64 + Sync),
    opts: &CubicalOptions,
    max_bytes: u64,
) -> Result<Diagram, PersistenceError> {
    let zp = check_field(opts.field)?;
    if opts.periodic {
        return Err(PersistenceError::BadOption(
            "a periodic image is not computed from its lower stars (the Morse route)".into(),
        ));
    }
    if opts.cycles {
        return Err(PersistenceError::BadOption(
            "cycles are not computed from an image's lower stars (the Morse route): its critical cells are not a cycle of the image".into(),
        ));
    }
    let d = shape.len();
    if d == 0 || shape.contains(&0) {
        return Err(PersistenceError::BadInput(format!("shape {shape:?} has no cells")));
    }
    if d > 4 {
        return Err(PersistenceError::BadOption(format!(
            "a {d}-dimensional image is not computed from its lower stars (the Morse route takes 1 to 4 axes)"
        )));
    }
    let t = opts.construction == Construction::T;
    let too_large = || PersistenceError::TooLarge(format!("a grid of shape {shape:?}"));
    // the pixels' own grid, for their strides, and the doubled grid of their cells
    let pixels = Grid::new(shape.to_vec(), false, Order::LastFastest).ok_or_else(too_large)?;
    let (pstride, plen) = (pixels.strides().to_vec(), pixels.len());
    let placement = if t { Placement::Cubes } else { Placement::Vertices };
    let grid = Grid::of_box(shape, placement, Order::LastFastest).ok_or_else(too_large)?;
    let sign = if opts.superlevel { -1.0 } else { 1.0 };
    let star = Star::new(d);
    let offsets =
        (0..star.len()).map(|q| (0..d).map(|a| star.delta[q * d + a] as i64 * pstride[a] as i64).sum()).collect();
    let lat = Lattice { n: shape.to_vec(), pstride, grid, t, sign, value, offsets };

    // pass 1: each pixel's lower star, slab after slab; the critical cells per dimension
    let budget = max_bytes.saturating_sub(super::image::PROCESS_BYTES) / BYTES_PER_CRITICAL;
    let found = AtomicU64::new(0);
    let tasks = plen.div_ceil(1 << 16).max(1);
    let parts = gmap_core::parallel::map_tasks(
        tasks,
        plen,
        |task| -> Result<Vec<Vec<(usize, f64)>>, PersistenceError> {
            let (lo, hi) = (task << 16, ((task + 1) << 16).min(plen));
            let mut crit = vec![Vec::new(); d + 1];
            let mut s = Scratch::default();
            let mut x = vec![0usize; d];
            for i in lo..hi {
                for a in 0..d {
                    x[a] = (i / lat.pstride[a]) % lat.n[a];
                }
                lat.process(&star, &x, &mut s)?;
                let v = lat.pixel(i)?;
                let mut here = 0;
                for q in 0..star.len() {
                    if s.class[q] == CRIT {
                        let id = lat.cell(&star, &x, q as u16);
                        crit[lat.grid.dim(id)].push((id, v));
                        here += 1;
                    }
                }
                if here > 0 && found.fetch_add(here, Ordering::Relaxed) + here > budget {
                    return Err(PersistenceError::TooLarge(format!(
                    "the image of shape {shape:?} has more than {budget} critical cells, over the memory limit of {max_bytes} bytes at {BYTES_PER_CRITICAL} bytes each"
                )));
                }
            }
            Ok(crit)
        },
    );
    let mut crit: Vec<Vec<(usize, f64)>> = vec![Vec::new(); d + 1];
    for part in parts {
        for (k, v) in part?.into_iter().enumerate() {
            crit[k].extend(v);
        }
    }
    for list in &mut crit {
        list.sort_unstable_by_key(|e| e.0);
    }

    // pass 2, from the top dimension down: the boundaries of the critical cells that are
    // columns (not cleared by the dimension above), then their reduction
    let position = |k: usize, id: usize| -> usize {
        crit[k].binary_search_by_key(&id, |e| e.0).expect("the gradient ends on critical cells")
    };
    // per dimension, the rank of each critical cell in the order (value, grid index)
    let rank: Vec<Vec<u32>> = crit
        .iter()
        .map(|list| {
            let mut o: Vec<u32> = (0..list.len() as u32).collect();
            o.sort_unstable_by_key(|&i| (key(list[i as usize].1), list[i as usize].0));
            let mut r = vec![0u32; o.len()];
            for (p, &i) in o.iter().enumerate() {
                r[i as usize] = p as u32;
            }
            r
        })
        .collect();
    let by_rank: Vec<Vec<f64>> = crit
        .iter()
        .zip(&rank)
        .map(|(list, r)| {
            let mut v = vec![0.0; list.len()];
            for (i, e) in list.iter().enumerate() {
                v[r[i] as usize] = e.1;
            }
            v
        })
        .collect();
    let chunk = 4096usize;
    let mut diagram = Diagram::new(opts.field);
    let mut claimed: Vec<bool> = Vec::new();
    for k in (1..=d).rev() {
        // columns[rank]: the boundary of the k-cell of that rank, as ranks of (k-1)-cells
        let mut columns: Vec<Vec<Entry>> = vec![Vec::new(); crit[k].len()];
        if k == d {
            // the top cells, from every critical (d-1)-cell up
            let list = &crit[d - 1];
            let parts = gmap_core::parallel::map_tasks(list.len().div_ceil(chunk), list.len() * 64, |task| {
                let mut grad = Gradient::new(&lat, &star);
                let mut out = Vec::new();
                for &(id, _) in &list[task * chunk..((task + 1) * chunk).min(list.len())] {
                    flow_up(&mut grad, zp, id, &mut out)?;
                }
                Ok::<_, PersistenceError>(out)
            });
            for part in parts {
                for (g, f, coef) in part? {
                    columns[rank[d][position(d, g)] as usize].push((rank[d - 1][position(d - 1, f)], coef));
                }
            }
        } else {
            let list: Vec<(usize, usize)> = crit[k]
                .iter()
                .enumerate()
                .filter(|&(i, _)| !claimed.get(rank[k][i] as usize).copied().unwrap_or(false))
                .map(|(i, e)| (i, e.0))
                .collect();
            let parts = gmap_core::parallel::map_tasks(list.len().div_ceil(chunk), list.len() * 64, |task| {
                let mut grad = Gradient::new(&lat, &star);
                let mut out = Vec::new();
                let mut b = Vec::new();
                for &(i, id) in &list[task * chunk..((task + 1) * chunk).min(list.len())] {
                    flow_down(&mut grad, zp, id, &mut out)?;
                    let col: Vec<Entry> = out.iter().map(|&(f, c)| (rank[k - 1][position(k - 1, f)], c)).collect();
                    b.push((rank[k][i], col));
                }
                Ok::<_, PersistenceError>(b)
            });
            for part in parts {
                for (r, col) in part? {
                    columns[r as usize] = col;
                }
            }
        }
        let cols = (0..crit[k].len() as u32).filter(|&j| !claimed.get(j as usize).copied().unwrap_or(false));
        let r =
            reduce_dim(zp, crit[k - 1].len(), cols, |j, out| out.extend_from_slice(&columns[j as usize]), false, false);
        for &(row, col) in &r.pairs {
            diagram.push(k - 1, by_rank[k - 1][row as usize], by_rank[k][col as usize], sign, None);
        }
        for &col in &r.zero {
            diagram.push(k, by_rank[k][col as usize], f64::INFINITY, sign, None);
        }
        claimed = r.claimed;
    }
    for (j, &v) in by_rank[0].iter().enumerate() {
        if !claimed.get(j).copied().unwrap_or(false) {
            diagram.push(0, v, f64::INFINITY, sign, None);
        }
    }
    diagram.finish();
    Ok(diagram)
}
