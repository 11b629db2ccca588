//! `H_0`: the closure of the set on the doubled grid, and a vertex per component.

#![allow(clippy::needless_range_loop)] // axes index several arrays at once

use gmap_core::union_find::UnionFind;

use super::cells::{for_each_point, Box, PRESENT};

/// Marks the cells of the closure of the set present, and counts them by dimension.
pub(super) fn mark_closure(bx: &Box, bits: &[u8], st: &mut [u8]) -> [i64; 4] {
    let d = bx.d;
    // the 3^d cells of a cube, as offsets from its centre, with their dimensions
    let mut offsets: Vec<(isize, usize)> = vec![(0, d)];
    for a in 0..d {
        let s = bx.gs[a] as isize;
        offsets = offsets.iter().flat_map(|&(o, k)| [(o, k), (o - s, k - 1), (o + s, k - 1)]).collect();
    }
    let mut cells = [0i64; 4];
    for_each_point([0; 3], [1; 3], bx.n, |c| {
        let v = bx.cube(&c);
        if bits[v] == 0 {
            return;
        }
        let centre = bx.centre(&c) as isize;
        for &(o, k) in &offsets {
            let p = (centre + o) as usize;
            if st[p] & PRESENT == 0 {
                st[p] |= PRESENT;
                cells[k] += 1;
            }
        }
    });
    cells
}

/// The union-find of the present vertices over the present edges, and the grid points of
/// its roots, increasing (the smallest vertex of each component).
pub(super) fn components(bx: &Box, st: &[u8]) -> (UnionFind, Vec<usize>) {
    let d = bx.d;
    let mut uf = UnionFind::new(bx.vertex_count());
    for a in 0..d {
        let mut end = [1usize; 3];
        for (e, &n) in end.iter_mut().zip(&bx.n).take(d) {
            *e = n + 1;
        }
        end[a] = bx.n[a];
        for_each_point([0; 3], [1; 3], end, |c| {
            let p = (0..d).map(|b| 2 * c[b] * bx.gs[b]).sum::<usize>() + bx.gs[a];
            if st[p] & PRESENT != 0 {
                let v = (0..d).map(|b| c[b] * bx.vs[b]).sum::<usize>();
                uf.union(v as u32, (v + bx.vs[a]) as u32);
            }
        });
    }
    let mut roots = Vec::new();
    for_each_point([0; 3], [2, 2, 2], bx.g, |c| {
        let p = bx.point(&c);
        if st[p] & PRESENT != 0 {
            let v = (c[0] / 2) * bx.vs[0] + (c[1] / 2) * bx.vs[1] + (c[2] / 2) * bx.vs[2];
            if uf.find(v as u32) == v as u32 {
                roots.push(p);
            }
        }
    });
    (uf, roots)
}
