//! Small map builders shared by the Euler-operator tests (independent of the builders
//! module, so these tests exercise only the kernel and the Euler operators).
#![allow(dead_code)]

use std::collections::HashMap;

use gmap_core::{Dart, DartId, DenseMap, GMap};
use gmap_ops::euler::ops::can_split_cell;

/// All permutations of `0..k` in lexicographic order.
pub fn permutations(k: usize) -> Vec<Vec<usize>> {
    let mut out = vec![];
    let mut p: Vec<usize> = (0..k).collect();
    loop {
        out.push(p.clone());
        let Some(i) = (1..k).rev().find(|&i| p[i - 1] < p[i]) else { break };
        let j = (i..k).rev().find(|&j| p[j] > p[i - 1]).unwrap();
        p.swap(i - 1, j);
        p[i..].reverse();
    }
    out
}

/// A `k^d` grid of d-cubes (a d-torus when `periodic`): dart (cube, corner, order of axes).
pub fn cube_grid(d: usize, k: usize, periodic: bool) -> DenseMap {
    let perms = permutations(d);
    let pidx: HashMap<Vec<usize>, usize> = perms.iter().cloned().enumerate().map(|(i, p)| (p, i)).collect();
    let corners = 1usize << d;
    let per_cube = perms.len() * corners;
    let cubes = k.pow(d as u32);
    let dart = |c: usize, eps: usize, p: usize| (c * per_cube + p * corners + eps) as u32;
    let coord = |c: usize| -> Vec<usize> { (0..d).map(|a| (c / k.pow(a as u32)) % k).collect() };
    let index = |x: &[usize]| -> usize { x.iter().enumerate().map(|(a, &v)| v * k.pow(a as u32)).sum() };
    let mut flat = vec![0u32; cubes * per_cube * (d + 1)];
    for c in 0..cubes {
        let x = coord(c);
        for (pi, p) in perms.iter().enumerate() {
            for eps in 0..corners {
                let me = dart(c, eps, pi) as usize;
                let row = &mut flat[me * (d + 1)..(me + 1) * (d + 1)];
                row[0] = dart(c, eps ^ (1 << p[0]), pi);
                for (i, slot) in row.iter_mut().enumerate().take(d).skip(1) {
                    let mut q = p.clone();
                    q.swap(i - 1, i);
                    *slot = dart(c, eps, pidx[&q]);
                }
                let ax = p[d - 1];
                let up = eps >> ax & 1 == 1;
                let mut y = x.clone();
                let inside = if up { y[ax] + 1 < k } else { y[ax] > 0 };
                if inside || periodic {
                    y[ax] = if up { (y[ax] + 1) % k } else { (y[ax] + k - 1) % k };
                    row[d] = dart(index(&y), eps ^ (1 << ax), pi);
                } else {
                    row[d] = me as u32;
                }
            }
        }
    }
    DenseMap::try_from_flat(d, flat).expect("valid grid")
}

/// The G-map of a pure simplicial complex: one dart per (facet, vertex order); alpha_i
/// (i < n) swaps positions i and i+1, alpha_n crosses the ridge of the first n vertices.
pub fn simplicial(facets: &[Vec<u32>]) -> DenseMap {
    let n = facets[0].len() - 1;
    let perms = permutations(n + 1);
    let pidx: HashMap<Vec<usize>, usize> = perms.iter().cloned().enumerate().map(|(i, p)| (p, i)).collect();
    let facets: Vec<Vec<u32>> = facets
        .iter()
        .map(|f| {
            let mut f = f.clone();
            f.sort_unstable();
            f
        })
        .collect();
    let mut ridges: HashMap<Vec<u32>, Vec<usize>> = HashMap::new();
    for (fi, f) in facets.iter().enumerate() {
        for j in 0..=n {
            let mut r = f.clone();
            r.remove(j);
            ridges.entry(r).or_default().push(fi);
        }
    }
    let np = perms.len();
    let mut flat = vec![0u32; facets.len() * np * (n + 1)];
    for (fi, f) in facets.iter().enumerate() {
        for (pi, p) in perms.iter().enumerate() {
            let me = fi * np + pi;
            for i in 0..n {
                let mut q = p.clone();
                q.swap(i, i + 1);
                flat[me * (n + 1) + i] = (fi * np + pidx[&q]) as u32;
            }
            let seq: Vec<u32> = p.iter().map(|&j| f[j]).collect();
            let mut ridge = seq[..n].to_vec();
            ridge.sort_unstable();
            let other = ridges[&ridge].iter().copied().find(|&g| g != fi);
            flat[me * (n + 1) + n] = match other {
                None => me as u32,
                Some(g) => {
                    let gf = &facets[g];
                    let extra = *gf.iter().find(|v| !ridge.contains(v)).unwrap();
                    let mut want = seq[..n].to_vec();
                    want.push(extra);
                    let q: Vec<usize> = want.iter().map(|v| gf.iter().position(|x| x == v).unwrap()).collect();
                    (g * np + pidx[&q]) as u32
                }
            };
        }
    }
    DenseMap::try_from_flat(n, flat).expect("valid simplicial map")
}

/// The boundary of the (n+1)-simplex: an n-sphere with n+2 facets.
pub fn sphere_simplicial(n: usize) -> DenseMap {
    let all: Vec<u32> = (0..n as u32 + 2).collect();
    let facets: Vec<Vec<u32>> = (0..n + 2)
        .map(|j| {
            let mut f = all.clone();
            f.remove(j);
            f
        })
        .collect();
    simplicial(&facets)
}

/// A cycle of k edges in a map of dimension `dim`: darts 2j, 2j+1 are edge j.
fn ring(dim: usize, k: usize) -> GMap {
    let mut g = GMap::new(dim);
    let d: Vec<_> = (0..2 * k).map(|_| g.create_dart()).collect();
    for j in 0..k {
        g.sew(d[2 * j], d[2 * j + 1], 0);
        g.sew(d[2 * j + 1], d[(2 * j + 2) % (2 * k)], 1);
    }
    g
}

/// A k-gon as a 2-map (one face, complete lower boundaries, 2-free).
pub fn polygon(k: usize) -> GMap {
    ring(2, k)
}

/// A cycle of k edges as a 1-map.
pub fn cycle(k: usize) -> GMap {
    ring(1, k)
}

/// Thaws a dense map; returns the map and the handle of each dense dart.
pub fn thaw(m: &DenseMap) -> (GMap, Vec<gmap_core::DartId>) {
    GMap::from_dense(m)
}

/// Cell counts of an editable map.
pub fn counts(g: &GMap) -> Vec<usize> {
    g.to_dense().0.cell_counts()
}

/// The dense dart of index k.
pub fn dart(k: u32) -> Dart {
    Dart::new(k)
}

/// Four darts of a closed path of edges on the boundary of a volume, one per edge: from each,
/// go to the other end of its edge and turn into the next face of the same side. The first
/// such path along which the volume can be split.
pub fn find_cut(g: &GMap) -> Vec<DartId> {
    for s in g.darts() {
        let mut seeds = vec![s];
        let mut x = s;
        for _ in 0..3 {
            let y = g.alpha(x, 0);
            let z = g.alpha(g.alpha(y, 1), 2);
            x = g.alpha(z, 1);
            seeds.push(x);
        }
        if can_split_cell(g, &seeds, 3) {
            return seeds;
        }
    }
    panic!("no closed cut found");
}
