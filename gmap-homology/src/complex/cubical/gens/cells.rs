//! The box of a cubical set of dimension ≤ 3 on its doubled grid, and what the parts of the
//! generators' route share: the faces and cofaces of a cell there, the sign of an edge in the
//! boundary of a square, cycles as chains of grid points. The loops here run over three
//! axes with strides taken from the doubled grid's ([`crate::cubical::grid`]), the axes past
//! the set's dimension of one point.

#![allow(clippy::needless_range_loop)] // axes index several arrays at once

use gmap_core::fastdiv::Divider;

use crate::complex::cubical::grid::{self, face_sign, Grid, Order, Placement};
use crate::complex::cubical::CubicalError;

/// A representative cycle of one free summand of `H_dim`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CubeCycle {
    /// the dimension k of the group
    pub dim: usize,
    /// `(point, coefficient)`: the cells as points of the doubled grid (`2L + 1` per axis, axis
    /// 0 fastest, a cell odd along the axes it spans), increasing, coefficients ±1 for the
    /// boundaries and the fundamental cycles
    pub chain: Vec<(u64, i64)>,
}

/// A cell of the closure, in the doubled grid's bytes.
pub(super) const PRESENT: u8 = 1;

/// The box: cubes, vertices and the doubled grid, with their strides (axis 0 fastest).
pub(super) struct Box {
    pub(super) d: usize,
    pub(super) n: [usize; 3],
    /// doubled grid points per axis and strides
    pub(super) g: [usize; 3],
    pub(super) gs: [usize; 3],
    /// vertex strides
    pub(super) vs: [usize; 3],
    /// cube strides
    pub(super) cs: [usize; 3],
    /// `g[0]` and `gs[1]`, `gs[2]` as dividers (the grid's points fit in `u32`)
    pub(super) div: [Divider; 3],
}

impl Box {
    pub(super) fn new(shape: &[usize]) -> Result<Self, CubicalError> {
        let d = shape.len();
        let order = Order::FirstFastest;
        let too_large =
            || CubicalError::TooLarge { points: grid::shown(shape, Placement::Cubes), limit: u32::MAX as u64 - 1 };
        // the doubled grid, and the grids of the vertices and of the cubes for their numbers
        let cells = Grid::of_box(shape, Placement::Cubes, order).ok_or_else(too_large)?;
        let vertices = Grid::new(shape.iter().map(|&l| l + 1).collect(), false, order).ok_or_else(too_large)?;
        let cubes = Grid::new(shape.to_vec(), false, order).ok_or_else(too_large)?;
        // an axis past the set's dimension has one point, at the stride of the whole grid
        let axis = |g: &Grid, a: usize| if a < d { (g.points()[a], g.strides()[a]) } else { (1, g.len()) };
        let (mut n, mut g, mut gs, mut vs, mut cs) = ([0usize; 3], [0usize; 3], [0usize; 3], [0usize; 3], [0usize; 3]);
        for a in 0..3 {
            (g[a], gs[a]) = axis(&cells, a);
            vs[a] = axis(&vertices, a).1;
            (n[a], cs[a]) = axis(&cubes, a);
        }
        // the caller checked that the grid's points fit in u32: so do its strides
        let div = [g[0], gs[1], gs[2]]
            .map(|x| Divider::new(x).ok_or(CubicalError::TooLarge { points: x.to_string(), limit: u32::MAX as u64 }));
        let [a, b, c] = div;
        Ok(Box { d, n, g, gs, vs, cs, div: [a?, b?, c?] })
    }

    pub(super) fn grid_len(&self) -> usize {
        self.g.iter().product()
    }

    pub(super) fn vertex_count(&self) -> usize {
        (0..self.d).map(|a| self.n[a] + 1).product()
    }

    pub(super) fn cube_count(&self) -> usize {
        self.n.iter().product()
    }

    /// The number of the cube at cube coordinates `c`.
    #[inline]
    pub(super) fn cube(&self, c: &[usize; 3]) -> usize {
        c[0] * self.cs[0] + c[1] * self.cs[1] + c[2] * self.cs[2]
    }

    /// The cube coordinates of cube number `v`.
    pub(super) fn cube_coords(&self, v: usize) -> [usize; 3] {
        [v % self.n[0], v / self.cs[1] % self.n[1], v / self.cs[2]]
    }

    /// The grid point of the cube at cube coordinates `c` (odd along every axis).
    #[inline]
    pub(super) fn centre(&self, c: &[usize; 3]) -> usize {
        (0..self.d).map(|a| (2 * c[a] + 1) * self.gs[a]).sum()
    }

    /// The grid point at doubled coordinates `c`.
    #[inline]
    pub(super) fn point(&self, c: &[usize; 3]) -> usize {
        c[0] * self.gs[0] + c[1] * self.gs[1] + c[2] * self.gs[2]
    }

    /// The doubled coordinates of grid point `p`.
    #[inline]
    pub(super) fn coords(&self, p: usize) -> [usize; 3] {
        let z = self.div[2].quotient(p);
        let r = p - z * self.gs[2];
        let y = self.div[1].quotient(r);
        [r - y * self.gs[1], y, z]
    }

    /// The vertex number of grid point `p` (even coordinates).
    #[inline]
    pub(super) fn vertex_of(&self, p: usize) -> usize {
        let c = self.coords(p);
        (c[0] / 2) * self.vs[0] + (c[1] / 2) * self.vs[1] + (c[2] / 2) * self.vs[2]
    }
}

/// Visits every point of a product of arithmetic ranges `start[a], start[a] + step[a], … <
/// end[a]`, axis 0 fastest, with the point's coordinates.
pub(super) fn for_each_point(start: [usize; 3], step: [usize; 3], end: [usize; 3], mut f: impl FnMut([usize; 3])) {
    if (0..3).any(|a| start[a] >= end[a]) {
        return;
    }
    let mut c = start;
    loop {
        f(c);
        let mut a = 0;
        loop {
            c[a] += step[a];
            if c[a] < end[a] {
                break;
            }
            c[a] = start[a];
            a += 1;
            if a == 3 {
                return;
            }
        }
    }
}

pub(super) fn try_vec<T: Clone>(len: usize, value: T, what: &'static str) -> Result<Vec<T>, CubicalError> {
    let mut v = Vec::new();
    v.try_reserve_exact(len).map_err(|_| CubicalError::OutOfMemory {
        what,
        bytes: (len as u64).saturating_mul(std::mem::size_of::<T>() as u64),
    })?;
    v.resize(len, value);
    Ok(v)
}

/// The faces of grid point `p` (coordinates `c`): its two neighbours along each odd axis
/// ([`Grid::faces_along`] in a box), `f(q, a, x)` with the face's point, the axis it lies
/// along from `p` and its coordinate there.
#[inline]
pub(super) fn for_faces(bx: &Box, c: &[usize; 3], p: usize, mut f: impl FnMut(usize, usize, usize)) {
    for a in 0..bx.d {
        if c[a] % 2 == 1 {
            f(p - bx.gs[a], a, c[a] - 1);
            f(p + bx.gs[a], a, c[a] + 1);
        }
    }
}

/// The cofaces of grid point `p` within the grid: its neighbours along each even axis
/// ([`Grid::cofaces_along`] in a box), `f(q, a, x)` as for [`for_faces`].
#[inline]
pub(super) fn for_cofaces(bx: &Box, c: &[usize; 3], p: usize, mut f: impl FnMut(usize, usize, usize)) {
    for a in 0..bx.d {
        if c[a].is_multiple_of(2) {
            if c[a] > 0 {
                f(p - bx.gs[a], a, c[a] - 1);
            }
            if c[a] + 1 < bx.g[a] {
                f(p + bx.gs[a], a, c[a] + 1);
            }
        }
    }
}

/// The coordinates `c` with `x` along axis `a`.
#[inline]
pub(super) fn moved(c: &[usize; 3], a: usize, x: usize) -> [usize; 3] {
    let mut n = *c;
    n[a] = x;
    n
}

#[inline]
pub(super) fn dim_of(c: &[usize; 3]) -> usize {
    c.iter().filter(|&&x| x % 2 == 1).count()
}

/// `∂[e, q]`: the coefficient of edge `e` in the boundary of the square at `q` (coordinates
/// `cq`), by [`face_sign`]: `e` lies along the square's first odd axis (`j = 0`) or its
/// second (`j = 1`), above `q` or below.
#[inline]
pub(super) fn square_sign(bx: &Box, cq: &[usize; 3], q: usize, e: usize) -> i64 {
    let first = (0..bx.d).find(|&a| cq[a] % 2 == 1).unwrap_or(0);
    let j = usize::from(e.abs_diff(q) != bx.gs[first]);
    face_sign(j, e > q)
}

/// The chain with its cells sorted, their coefficients summed and the zeros dropped.
pub(super) fn merged(mut chain: Vec<(u64, i64)>) -> Vec<(u64, i64)> {
    chain.sort_unstable_by_key(|x| x.0);
    let mut out: Vec<(u64, i64)> = Vec::with_capacity(chain.len());
    for (p, c) in chain {
        match out.last_mut() {
            Some(last) if last.0 == p => last.1 += c,
            _ => out.push((p, c)),
        }
    }
    out.retain(|x| x.1 != 0);
    out
}
