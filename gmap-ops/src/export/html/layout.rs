//! Deterministic 3-D layouts of graphs, for maps that have no points.
//!
//! Each connected component is placed by *pivot MDS* (Brandes and Pich, "Eigensolver
//! methods for progressive multidimensional scaling of large data", Graph Drawing 2006):
//! breadth-first distances from [`PIVOTS`] pivots chosen by max–min distance (the first the
//! component's smallest node, ties to the smallest node), double-centred, and projected on
//! the three leading eigenvectors of the small `pivots × pivots` Gram matrix (cyclic
//! Jacobi). Components of at most [`STRESS_NODES`] nodes are then refined by stress
//! majorization (Gansner, Koren and North, Graph Drawing 2004) with all-pairs graph
//! distances and weights `d^-2`, [`STRESS_ROUNDS`] Gauss–Seidel rounds in node order. The
//! layout is scaled so that the mean edge length is 1, and the components are set side by
//! side along x. Nothing is random: the same graph gives the same layout.
//!
//! Cost: O(PIVOTS (V + E)) for pivot MDS, O(m (m + E)) memory-free BFS plus
//! O(STRESS_ROUNDS m²) for the refinement of a component of m nodes.

use std::collections::VecDeque;

/// The number of pivots of pivot MDS.
pub const PIVOTS: usize = 50;

/// The largest component refined by stress majorization.
pub const STRESS_NODES: usize = 1200;

/// The rounds of stress majorization.
pub const STRESS_ROUNDS: usize = 60;

/// The method, in words, for the page.
pub const METHOD: &str = "pivot MDS of graph distances (Brandes & Pich 2006; 50 pivots by max-min \
    distance from the smallest node), refined by stress majorization (Gansner, Koren & North 2004) \
    on components of at most 1,200 nodes; deterministic";

/// Adjacency lists in CSR form.
struct Csr {
    off: Vec<usize>,
    adj: Vec<u32>,
}

impl Csr {
    fn new(n: usize, edges: &[(u32, u32)]) -> Csr {
        let mut off = vec![0usize; n + 1];
        for &(a, b) in edges {
            if a != b {
                off[a as usize + 1] += 1;
                off[b as usize + 1] += 1;
            }
        }
        for k in 0..n {
            off[k + 1] += off[k];
        }
        let mut fill = off.clone();
        let mut adj = vec![0u32; off[n]];
        for &(a, b) in edges {
            if a != b {
                adj[fill[a as usize]] = b;
                fill[a as usize] += 1;
                adj[fill[b as usize]] = a;
                fill[b as usize] += 1;
            }
        }
        Csr { off, adj }
    }

    fn neighbours(&self, v: usize) -> &[u32] {
        &self.adj[self.off[v]..self.off[v + 1]]
    }
}

/// Breadth-first distances from `src` within a component whose nodes have local numbers
/// `local[v]` (`u32::MAX` outside); `dist` is indexed by local number.
fn bfs(g: &Csr, local: &[u32], src: usize, dist: &mut [u32], queue: &mut VecDeque<usize>) {
    dist.fill(u32::MAX);
    dist[local[src] as usize] = 0;
    queue.clear();
    queue.push_back(src);
    while let Some(v) = queue.pop_front() {
        let dv = dist[local[v] as usize];
        for &w in g.neighbours(v) {
            let lw = local[w as usize] as usize;
            if dist[lw] == u32::MAX {
                dist[lw] = dv + 1;
                queue.push_back(w as usize);
            }
        }
    }
}

/// Eigenvalues and eigenvectors (columns of the returned matrix, row-major `k × k`) of a
/// symmetric matrix by cyclic Jacobi rotations. O(k³) per sweep.
fn jacobi(mut a: Vec<f64>, k: usize) -> (Vec<f64>, Vec<f64>) {
    let mut v = vec![0.0; k * k];
    for i in 0..k {
        v[i * k + i] = 1.0;
    }
    for _sweep in 0..60 {
        let off: f64 = (0..k)
            .flat_map(|i| (0..k).filter(move |&j| j != i).map(move |j| (i, j)))
            .map(|(i, j)| a[i * k + j].powi(2))
            .sum();
        let scale: f64 = (0..k).map(|i| a[i * k + i].powi(2)).sum::<f64>().max(1e-300);
        if off <= 1e-22 * scale {
            break;
        }
        for p in 0..k {
            for q in p + 1..k {
                let apq = a[p * k + q];
                if apq.abs() < 1e-300 {
                    continue;
                }
                let theta = (a[q * k + q] - a[p * k + p]) / (2.0 * apq);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let t = if theta == 0.0 { 1.0 } else { t };
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                for r in 0..k {
                    let (arp, arq) = (a[r * k + p], a[r * k + q]);
                    a[r * k + p] = c * arp - s * arq;
                    a[r * k + q] = s * arp + c * arq;
                }
                for r in 0..k {
                    let (apr, aqr) = (a[p * k + r], a[q * k + r]);
                    a[p * k + r] = c * apr - s * aqr;
                    a[q * k + r] = s * apr + c * aqr;
                }
                for r in 0..k {
                    let (vrp, vrq) = (v[r * k + p], v[r * k + q]);
                    v[r * k + p] = c * vrp - s * vrq;
                    v[r * k + q] = s * vrp + c * vrq;
                }
            }
        }
    }
    ((0..k).map(|i| a[i * k + i]).collect(), v)
}

/// Pivot MDS of one component (`nodes`, local numbers in `local`): 3-D coordinates by
/// local number.
fn pivot_mds(g: &Csr, nodes: &[usize], local: &[u32]) -> Vec<[f64; 3]> {
    let m = nodes.len();
    let k = PIVOTS.min(m);
    let mut queue = VecDeque::new();
    let mut mind = vec![u32::MAX; m];
    let mut dist = vec![0u32; m];
    // c[i * k + j]: squared distance from node i to pivot j
    let mut c = vec![0.0f64; m * k];
    let mut pivot = nodes[0];
    for j in 0..k {
        bfs(g, local, pivot, &mut dist, &mut queue);
        for i in 0..m {
            c[i * k + j] = (dist[i] as f64).powi(2);
            mind[i] = mind[i].min(dist[i]);
        }
        // the next pivot: farthest from those chosen, smallest node on ties
        let far = (0..m).max_by_key(|&i| (mind[i], std::cmp::Reverse(i))).unwrap_or(0);
        pivot = nodes[far];
    }
    // double centring
    let mut col = vec![0.0; k];
    let mut row = vec![0.0; m];
    let mut all = 0.0;
    for i in 0..m {
        for j in 0..k {
            let x = c[i * k + j];
            col[j] += x / m as f64;
            row[i] += x / k as f64;
            all += x / (m * k) as f64;
        }
    }
    for i in 0..m {
        for j in 0..k {
            c[i * k + j] = -0.5 * (c[i * k + j] - row[i] - col[j] + all);
        }
    }
    // the Gram matrix C^T C and its leading eigenvectors
    let mut gram = vec![0.0; k * k];
    for i in 0..m {
        let r = &c[i * k..i * k + k];
        for a in 0..k {
            for b in a..k {
                gram[a * k + b] += r[a] * r[b];
            }
        }
    }
    for a in 0..k {
        for b in 0..a {
            gram[a * k + b] = gram[b * k + a];
        }
    }
    let (vals, vecs) = jacobi(gram, k);
    let mut order: Vec<usize> = (0..k).collect();
    order.sort_by(|&a, &b| vals[b].total_cmp(&vals[a]).then(a.cmp(&b)));
    let mut out = vec![[0.0; 3]; m];
    for (axis, &e) in order.iter().take(3).enumerate() {
        // a sign convention so the result does not depend on the eigensolver's
        let mut sign = 1.0;
        if let Some(j) = (0..k).max_by(|&x, &y| vecs[x * k + e].abs().total_cmp(&vecs[y * k + e].abs())) {
            if vecs[j * k + e] < 0.0 {
                sign = -1.0;
            }
        }
        for i in 0..m {
            out[i][axis] = sign * (0..k).map(|j| c[i * k + j] * vecs[j * k + e]).sum::<f64>();
        }
    }
    out
}

/// Stress majorization of one component from the positions `x` (local numbers).
fn stress(g: &Csr, nodes: &[usize], local: &[u32], x: &mut [[f64; 3]]) {
    let m = nodes.len();
    let mut d = vec![0u32; m * m];
    let mut queue = VecDeque::new();
    let mut dist = vec![0u32; m];
    for (i, &v) in nodes.iter().enumerate() {
        bfs(g, local, v, &mut dist, &mut queue);
        d[i * m..i * m + m].copy_from_slice(&dist);
    }
    normalise(x, 1.0, g, nodes, local);
    for _ in 0..STRESS_ROUNDS {
        for i in 0..m {
            let mut num = [0.0; 3];
            let mut den = 0.0;
            for j in 0..m {
                if j == i {
                    continue;
                }
                let dij = d[i * m + j] as f64;
                let w = 1.0 / (dij * dij);
                let diff = [x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]];
                let len = (diff[0] * diff[0] + diff[1] * diff[1] + diff[2] * diff[2]).sqrt();
                // coincident nodes: push apart along a fixed direction chosen by the pair
                let dir = if len > 1e-12 {
                    [diff[0] / len, diff[1] / len, diff[2] / len]
                } else {
                    let t = (i * 31 + j * 17) as f64;
                    let u = [t.sin(), t.cos(), (t * 0.7).sin()];
                    let l = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]).sqrt().max(1e-12);
                    [u[0] / l, u[1] / l, u[2] / l]
                };
                for a in 0..3 {
                    num[a] += w * (x[j][a] + dij * dir[a]);
                }
                den += w;
            }
            if den > 0.0 {
                x[i] = [num[0] / den, num[1] / den, num[2] / den];
            }
        }
    }
}

/// Scales a component so its mean edge length is `target` and centres it.
fn normalise(x: &mut [[f64; 3]], target: f64, g: &Csr, nodes: &[usize], local: &[u32]) {
    let (mut sum, mut count) = (0.0, 0usize);
    for &v in nodes {
        for &w in g.neighbours(v) {
            let (a, b) = (x[local[v] as usize], x[local[w as usize] as usize]);
            sum += ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
            count += 1;
        }
    }
    let mean = if count > 0 { sum / count as f64 } else { 0.0 };
    let s = if mean > 1e-12 { target / mean } else { 1.0 };
    let m = x.len().max(1) as f64;
    let centre = [0, 1, 2].map(|a| x.iter().map(|p| p[a]).sum::<f64>() / m);
    for p in x.iter_mut() {
        for a in 0..3 {
            p[a] = (p[a] - centre[a]) * s;
        }
    }
}

/// Deterministic 3-D positions of the `n` nodes of a graph given by its edges (loops and
/// repeated edges allowed): see the module documentation. O(PIVOTS (n + E)) plus the
/// refinement of the small components.
pub fn graph_layout(n: usize, edges: &[(u32, u32)]) -> Vec<[f64; 3]> {
    let g = Csr::new(n, edges);
    let mut local = vec![u32::MAX; n];
    let mut out = vec![[0.0; 3]; n];
    let mut x_offset = 0.0;
    let mut queue = VecDeque::new();
    for start in 0..n {
        if local[start] != u32::MAX {
            continue;
        }
        // the component of `start`, its nodes in increasing order
        let mut nodes = vec![start];
        local[start] = 0;
        queue.push_back(start);
        while let Some(v) = queue.pop_front() {
            for &w in g.neighbours(v) {
                if local[w as usize] == u32::MAX {
                    local[w as usize] = 0;
                    nodes.push(w as usize);
                    queue.push_back(w as usize);
                }
            }
        }
        nodes.sort_unstable();
        for (i, &v) in nodes.iter().enumerate() {
            local[v] = i as u32;
        }
        let mut x = if nodes.len() == 1 { vec![[0.0; 3]] } else { pivot_mds(&g, &nodes, &local) };
        if nodes.len() > 1 && nodes.len() <= STRESS_NODES {
            stress(&g, &nodes, &local, &mut x);
        }
        normalise(&mut x, 1.0, &g, &nodes, &local);
        let lo = x.iter().map(|p| p[0]).fold(f64::INFINITY, f64::min);
        let hi = x.iter().map(|p| p[0]).fold(f64::NEG_INFINITY, f64::max);
        for (i, &v) in nodes.iter().enumerate() {
            out[v] = [x[i][0] - lo + x_offset, x[i][1], x[i][2]];
        }
        x_offset += hi - lo + 2.0;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn len(a: [f64; 3], b: [f64; 3]) -> f64 {
        ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
    }

    #[test]
    fn a_cycle_is_laid_out_with_even_edges_and_apart_nodes() {
        let n = 12u32;
        let edges: Vec<(u32, u32)> = (0..n).map(|i| (i, (i + 1) % n)).collect();
        let x = graph_layout(n as usize, &edges);
        let lens: Vec<f64> = edges.iter().map(|&(a, b)| len(x[a as usize], x[b as usize])).collect();
        let mean = lens.iter().sum::<f64>() / lens.len() as f64;
        assert!((mean - 1.0).abs() < 1e-9, "{mean}");
        assert!(lens.iter().all(|&l| (l - 1.0).abs() < 0.1), "{lens:?}");
        // opposite nodes are far apart (a circle, not a folded path)
        assert!(len(x[0], x[6]) > 3.0);
        // deterministic
        assert_eq!(x, graph_layout(n as usize, &edges));
    }

    #[test]
    fn components_are_side_by_side_and_isolated_nodes_placed() {
        let x = graph_layout(5, &[(0, 1), (2, 3), (3, 3)]);
        assert!((len(x[0], x[1]) - 1.0).abs() < 1e-9);
        assert!((len(x[2], x[3]) - 1.0).abs() < 1e-9);
        let xs: Vec<f64> = x.iter().map(|p| p[0]).collect();
        assert!(xs[2].min(xs[3]) > xs[0].max(xs[1]), "{xs:?}");
        assert!(xs[4] > xs[2].max(xs[3]));
        assert!(x.iter().all(|p| p.iter().all(|c| c.is_finite())));
    }

    #[test]
    fn jacobi_diagonalises() {
        let (vals, vecs) = jacobi(vec![2.0, 1.0, 1.0, 2.0], 2);
        let mut v = vals.clone();
        v.sort_by(f64::total_cmp);
        assert!((v[0] - 1.0).abs() < 1e-12 && (v[1] - 3.0).abs() < 1e-12, "{vals:?}");
        // columns are unit vectors
        assert!((vecs[0] * vecs[0] + vecs[2] * vecs[2] - 1.0).abs() < 1e-12);
    }
}
