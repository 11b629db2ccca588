//! A shortest basis of `H_1` over `Z/2` of any chain complex whose 1-cells are edges (a
//! boundary of two vertices, or none: a loop): the cellular complex of a map of any
//! dimension, a simplicial, cubical or architectural complex.
//!
//! Three steps:
//!
//! 1. **Annotations** (Busaryev, Cabello, Chen, Dey, Wang 2012): a vector of `β₁` bits per
//!    edge such that a cycle's class in `H_1(Z/2)` is the sum of its edges' vectors. Edges
//!    of a spanning forest get zero. The 2-cells' boundaries, restricted to the other edges,
//!    are eliminated modulo 2, each 2-cell pivoting on one of its edges: first those found
//!    in no other 2-cell left (a peel: no fill), else the sparsest (Markowitz). A 2-cell
//!    that is a free face of a 3-cell is dropped first (its boundary is the sum of the
//!    other faces'). The edges never pivoted are the basis of `H_1`; a pivoted edge's
//!    vector is the sum of the others of its 2-cell at its turn, taken in reverse order.
//! 2. **Candidates** (Horton 1987; Erickson–Whittlesey 2005 on surfaces, Dey–Sun–Wang 2010
//!    on complexes): from every vertex `v`, its shortest-path tree `T_v`; for every edge
//!    `e = ab` outside it whose two tree paths part at `v`, the cycle `T_v(a) e T_v(b)`
//!    when its class is not zero; each loop is a candidate by itself. A shortest basis is
//!    among them.
//! 3. **Greedy**: the candidates by length, each kept when its class is independent of the
//!    classes kept (Gaussian elimination of `β₁`-bit vectors), until `β₁` are kept: the
//!    greedy basis of a matroid, so the k-th shortest kept cycle is as short as the k-th
//!    of any basis.
//!
//! Costs: step 1 O(E + F) times the fill (none on surfaces, whose 2-cells peel); step 2
//! V shortest-path trees, O(V E log V), and `β₁/64` words per candidate; step 3 O(C β₁²/64)
//! for C candidates. Candidates are kept only up to the longest cycle of the greedy basis
//! of the first root's candidates (a basis, so no cycle of a shortest basis is longer).

use crate::curves::error::CurveError;
use crate::curves::tree::{Graph, Tree, NONE};
use crate::engine::chain::ChainComplex;

/// Past this many steps (vertices times edges) the candidates are refused.
pub const BASIS_WORK_LIMIT: u128 = 20_000_000_000;

/// Past this many 64-bit words of candidates' classes the search is refused (1 GiB).
pub const BASIS_MEMORY_LIMIT: u128 = 1 << 27;

/// A cycle of a shortest basis: its length, a vertex where its two shortest paths start
/// (`NONE` for a loop), and its edges in order along it.
#[derive(Clone, Debug, PartialEq)]
pub struct BasisCycle {
    /// the sum of its edges' weights
    pub length: f64,
    /// the root of its two shortest paths (`NONE` for a loop edge)
    pub root: u32,
    /// the edges in order
    pub edges: Vec<u32>,
}

/// The edges' classes in `H_1(Z/2)`: `words` 64-bit words per edge.
#[derive(Clone, Debug)]
pub struct Annotations {
    /// `β₁` over `Z/2`: the number of bits
    pub rank: usize,
    /// words per edge
    pub words: usize,
    /// `bits[e * words..(e + 1) * words]` is edge `e`'s vector
    pub bits: Vec<u64>,
}

impl Annotations {
    /// The vector of edge `e`.
    pub fn of(&self, e: u32) -> &[u64] {
        &self.bits[e as usize * self.words..(e as usize + 1) * self.words]
    }

    /// The class of a chain (its edges, each counted modulo 2).
    pub fn class(&self, edges: &[u32]) -> Vec<u64> {
        let mut out = vec![0u64; self.words];
        for &e in edges {
            xor(&mut out, self.of(e));
        }
        out
    }
}

/// The graph of the 1-cells of `c` with `weights` (one per 1-cell): refuses a 1-cell whose
/// boundary modulo 2 is not two vertices or none. Loops (no end) have `(NONE, NONE)`.
pub fn edge_ends(c: &ChainComplex) -> Result<Vec<(u32, u32)>, CurveError> {
    let n1 = c.counts().get(1).copied().unwrap_or(0);
    let mut ends = Vec::with_capacity(n1);
    for j in 0..n1 {
        let (rows, vals) = c.boundary(1).col(j);
        let odd: Vec<u32> = rows.iter().zip(vals).filter(|(_, v)| *v % 2 != 0).map(|(&r, _)| r).collect();
        match odd[..] {
            [] => ends.push((NONE, NONE)),
            [a, b] => ends.push((a, b)),
            _ => return Err(CurveError::NotAGraph { edge: j as u32, ends: odd.len() }),
        }
    }
    Ok(ends)
}

/// The annotations of the edges of `c` over `Z/2` (step 1).
pub fn annotations(c: &ChainComplex) -> Result<Annotations, CurveError> {
    let ends = edge_ends(c)?;
    let vertices = c.counts()[0];
    let tree = spanning_forest(vertices, &ends);
    let mut rows = two_cell_rows(c, &tree);
    if c.counts().len() > 3 {
        drop_free_faces(c, &mut rows);
    }
    let (order, stored) = eliminate(&mut rows, ends.len());
    let pivoted: Vec<bool> = {
        let mut p = vec![false; ends.len()];
        order.iter().for_each(|&e| p[e as usize] = true);
        p
    };
    let free: Vec<u32> = (0..ends.len() as u32).filter(|&e| !tree[e as usize] && !pivoted[e as usize]).collect();
    let rank = free.len();
    let words = rank.div_ceil(64).max(1);
    let mut bits = vec![0u64; ends.len() * words];
    for (k, &e) in free.iter().enumerate() {
        bits[e as usize * words + k / 64] |= 1 << (k % 64);
    }
    for &e in order.iter().rev() {
        let mut v = vec![0u64; words];
        for &x in &stored[e as usize] {
            xor(&mut v, &bits[x as usize * words..(x as usize + 1) * words]);
        }
        bits[e as usize * words..(e as usize + 1) * words].copy_from_slice(&v);
    }
    Ok(Annotations { rank, words, bits })
}

/// A spanning forest of the edges (breadth first from each vertex in turn): whether each
/// edge is in it.
fn spanning_forest(vertices: usize, ends: &[(u32, u32)]) -> Vec<bool> {
    let mut parent: Vec<u32> = (0..vertices as u32).collect();
    fn find(p: &mut [u32], mut x: u32) -> u32 {
        while p[x as usize] != x {
            p[x as usize] = p[p[x as usize] as usize];
            x = p[x as usize];
        }
        x
    }
    ends.iter()
        .map(|&(a, b)| {
            if a == NONE {
                return false;
            }
            let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
            if ra != rb {
                parent[ra as usize] = rb;
            }
            ra != rb
        })
        .collect()
}

/// Each 2-cell's boundary modulo 2 outside the tree, sorted.
fn two_cell_rows(c: &ChainComplex, tree: &[bool]) -> Vec<Vec<u32>> {
    let n2 = c.counts().get(2).copied().unwrap_or(0);
    (0..n2)
        .map(|j| {
            let (rows, vals) = c.boundary(2).col(j);
            rows.iter().zip(vals).filter(|(r, v)| *v % 2 != 0 && !tree[**r as usize]).map(|(&r, _)| r).collect()
        })
        .collect()
}

/// Empties the 2-cells that are free faces (odd coefficient) of a single remaining 3-cell,
/// removing that 3-cell, until none is left: their boundaries are in the span of the
/// others'.
fn drop_free_faces(c: &ChainComplex, rows: &mut [Vec<u32>]) {
    let d3 = c.boundary(3);
    let n3 = d3.cols();
    let mut faces_of: Vec<Vec<u32>> = Vec::with_capacity(n3);
    let mut cells_of: Vec<Vec<u32>> = vec![Vec::new(); rows.len()];
    for j in 0..n3 {
        let (r, v) = d3.col(j);
        let odd: Vec<u32> = r.iter().zip(v).filter(|(_, v)| *v % 2 != 0).map(|(&r, _)| r).collect();
        odd.iter().for_each(|&f| cells_of[f as usize].push(j as u32));
        faces_of.push(odd);
    }
    let mut alive3 = vec![true; n3];
    let mut count: Vec<u32> = cells_of.iter().map(|c| c.len() as u32).collect();
    let mut queue: Vec<u32> = (0..rows.len() as u32).filter(|&f| count[f as usize] == 1).collect();
    while let Some(f) = queue.pop() {
        if count[f as usize] != 1 {
            continue;
        }
        let Some(&t) = cells_of[f as usize].iter().find(|&&t| alive3[t as usize]) else { continue };
        alive3[t as usize] = false;
        rows[f as usize].clear();
        for &g in &faces_of[t as usize] {
            count[g as usize] -= 1;
            if count[g as usize] == 1 {
                queue.push(g);
            }
        }
    }
}

/// Eliminates the rows modulo 2: the pivot edges in order, and for each the other edges of
/// its row at its turn.
fn eliminate(rows: &mut [Vec<u32>], edges: usize) -> (Vec<u32>, Vec<Vec<u32>>) {
    let mut rows_of: Vec<Vec<u32>> = vec![Vec::new(); edges];
    let mut count = vec![0u32; edges];
    for (r, row) in rows.iter().enumerate() {
        for &e in row {
            rows_of[e as usize].push(r as u32);
            count[e as usize] += 1;
        }
    }
    let mut alive: Vec<bool> = rows.iter().map(|r| !r.is_empty()).collect();
    let mut peel: Vec<u32> = (0..edges as u32).filter(|&e| count[e as usize] == 1).collect();
    let mut by_size: std::collections::BinaryHeap<std::cmp::Reverse<(usize, u32)>> = rows
        .iter()
        .enumerate()
        .filter(|(_, r)| !r.is_empty())
        .map(|(i, r)| std::cmp::Reverse((r.len(), i as u32)))
        .collect();
    let (mut order, mut stored) = (Vec::new(), vec![Vec::new(); edges]);
    loop {
        let pivot = next_pivot(rows, &mut alive, &count, &rows_of, &mut peel, &mut by_size);
        let Some((e, r)) = pivot else { break };
        let row = std::mem::take(&mut rows[r as usize]);
        alive[r as usize] = false;
        for &x in &row {
            count[x as usize] -= 1;
        }
        let others: Vec<u32> = rows_of[e as usize].clone();
        for o in others {
            if !alive[o as usize] || rows[o as usize].binary_search(&e).is_err() {
                continue;
            }
            let merged = sym_diff(&rows[o as usize], &row);
            for &x in &rows[o as usize] {
                count[x as usize] -= 1;
            }
            for &x in &merged {
                count[x as usize] += 1;
                rows_of[x as usize].push(o);
            }
            rows[o as usize] = merged;
            if rows[o as usize].is_empty() {
                alive[o as usize] = false;
            } else {
                by_size.push(std::cmp::Reverse((rows[o as usize].len(), o)));
            }
            peel.extend(rows[o as usize].iter().filter(|&&x| count[x as usize] == 1));
        }
        peel.extend(row.iter().filter(|&&x| count[x as usize] == 1));
        order.push(e);
        stored[e as usize] = row.into_iter().filter(|&x| x != e).collect();
    }
    (order, stored)
}

/// The next pivot: an edge in one live row (a peel), else the rarest edge of the sparsest
/// live row.
fn next_pivot(
    rows: &[Vec<u32>],
    alive: &mut [bool],
    count: &[u32],
    rows_of: &[Vec<u32>],
    peel: &mut Vec<u32>,
    by_size: &mut std::collections::BinaryHeap<std::cmp::Reverse<(usize, u32)>>,
) -> Option<(u32, u32)> {
    while let Some(e) = peel.pop() {
        if count[e as usize] != 1 {
            continue;
        }
        let live =
            rows_of[e as usize].iter().find(|&&r| alive[r as usize] && rows[r as usize].binary_search(&e).is_ok());
        if let Some(&r) = live {
            return Some((e, r));
        }
    }
    while let Some(std::cmp::Reverse((len, r))) = by_size.pop() {
        if !alive[r as usize] || rows[r as usize].len() != len {
            continue;
        }
        let e = *rows[r as usize].iter().min_by_key(|&&x| (count[x as usize], x))?;
        return Some((e, r));
    }
    None
}

/// The symmetric difference of two sorted lists.
fn sym_diff(a: &[u32], b: &[u32]) -> Vec<u32> {
    let (mut i, mut j, mut out) = (0, 0, Vec::with_capacity(a.len() + b.len()));
    while i < a.len() || j < b.len() {
        match (a.get(i), b.get(j)) {
            (Some(x), Some(y)) if x == y => (i, j) = (i + 1, j + 1),
            (Some(x), Some(y)) if x < y => (out.push(*x), i += 1).1,
            (Some(_), Some(y)) => (out.push(*y), j += 1).1,
            (Some(x), None) => (out.push(*x), i += 1).1,
            (None, Some(y)) => (out.push(*y), j += 1).1,
            (None, None) => unreachable!("the loop ends first"),
        }
    }
    out
}

/// `a ^= b`.
fn xor(a: &mut [u64], b: &[u64]) {
    a.iter_mut().zip(b).for_each(|(x, y)| *x ^= y);
}

/// A set of independent classes, kept in reduced echelon form by leading bit.
struct Echelon {
    rows: Vec<(usize, Vec<u64>)>,
}

impl Echelon {
    /// Adds `v` when it is independent of the rows; whether it was.
    fn insert(&mut self, mut v: Vec<u64>) -> bool {
        for (lead, r) in &self.rows {
            if v[lead / 64] >> (lead % 64) & 1 == 1 {
                xor(&mut v, r);
            }
        }
        let Some(w) = v.iter().position(|&x| x != 0) else { return false };
        let lead = w * 64 + v[w].trailing_zeros() as usize;
        for (_, r) in &mut self.rows {
            if r[lead / 64] >> (lead % 64) & 1 == 1 {
                xor(r, &v);
            }
        }
        self.rows.push((lead, v));
        true
    }
}

/// A candidate: its length, root, edge.
type Candidate = (f64, u32, u32);

/// A shortest basis of `H_1(c; Z/2)` with `weights` (one per 1-cell, finite, `≥ 0`): `β₁`
/// cycles, shortest first (steps 1–3 above).
///
/// ```
/// use gmap_homology::{cellular_complex, curves::shortest_basis};
/// let c = cellular_complex(&gmap_core::examples::torus()).unwrap();
/// let b = shortest_basis(&c.chain, &[1.0, 1.0]).unwrap();
/// assert_eq!(b.iter().map(|x| x.length).collect::<Vec<_>>(), vec![1.0, 1.0]);
/// ```
pub fn shortest_basis(c: &ChainComplex, weights: &[f64]) -> Result<Vec<BasisCycle>, CurveError> {
    let ends = edge_ends(c)?;
    let vertices = c.counts()[0];
    let graph_ends: Vec<(u32, u32)> = ends.iter().map(|&(a, b)| if a == NONE { (0, 0) } else { (a, b) }).collect();
    let g = Graph::try_new(vertices.max(1), graph_ends, weights.to_vec())?;
    let work = vertices as u128 * ends.len() as u128;
    if work > BASIS_WORK_LIMIT {
        return Err(CurveError::TooLarge { what: "the shortest basis's candidates", work, limit: BASIS_WORK_LIMIT });
    }
    let ann = annotations(c)?;
    if ann.rank == 0 {
        return Ok(Vec::new());
    }
    let loops: Vec<u32> = (0..ends.len() as u32).filter(|&e| ends[e as usize].0 == NONE).collect();
    // a first basis from the loops and one root per component bounds every length kept
    let mut roots = component_roots(&g, vertices);
    let mut first: Vec<(Candidate, Vec<u64>)> = loop_candidates(&ann, &g, &loops, f64::INFINITY);
    for &r in &roots {
        first.extend(root_candidates(&g, &ann, &g.shortest_path_tree(r), &ends, f64::INFINITY, false));
    }
    // every fundamental cycle of these trees: they span the cycles, so their greedy basis
    // is a basis whose longest (nominal) length bounds a shortest basis's
    let first = greedy(first, ann.rank);
    let bound = if first.len() == ann.rank { first.last().map_or(f64::INFINITY, |c| c.0) } else { f64::INFINITY };
    roots = (0..vertices as u32).collect();
    let mut all = loop_candidates(&ann, &g, &loops, bound);
    for &r in &roots {
        all.extend(root_candidates(&g, &ann, &g.shortest_path_tree(r), &ends, bound, true));
        let bytes = all.len() as u128 * (ann.words as u128 + 2);
        if bytes > BASIS_MEMORY_LIMIT {
            return Err(CurveError::TooLarge {
                what: "the shortest basis's candidates (words)",
                work: bytes,
                limit: BASIS_MEMORY_LIMIT,
            });
        }
    }
    let chosen = greedy(all, ann.rank);
    Ok(chosen.into_iter().map(|(len, root, e)| basis_cycle(&g, len, root, e)).collect())
}

/// One vertex of each component.
fn component_roots(g: &Graph, vertices: usize) -> Vec<u32> {
    let mut seen = vec![false; vertices];
    let mut roots = Vec::new();
    for v in 0..vertices as u32 {
        if !seen[v as usize] {
            roots.push(v);
            let mut stack = vec![v];
            seen[v as usize] = true;
            while let Some(x) = stack.pop() {
                for &(_, y) in g.incident(x) {
                    if !seen[y as usize] {
                        seen[y as usize] = true;
                        stack.push(y);
                    }
                }
            }
        }
    }
    roots
}

/// The loops of non-zero class, as candidates of root `NONE`.
fn loop_candidates(ann: &Annotations, g: &Graph, loops: &[u32], bound: f64) -> Vec<(Candidate, Vec<u64>)> {
    loops
        .iter()
        .filter(|&&e| g.weight(e) <= bound && ann.of(e).iter().any(|&x| x != 0))
        .map(|&e| ((g.weight(e), NONE, e), ann.of(e).to_vec()))
        .collect()
}

/// The candidates of one root: the edges outside its tree (whose paths part at the root
/// when `tight`), of non-zero class and length at most `bound`.
fn root_candidates(
    g: &Graph,
    ann: &Annotations,
    t: &Tree,
    ends: &[(u32, u32)],
    bound: f64,
    tight: bool,
) -> Vec<(Candidate, Vec<u64>)> {
    let w = ann.words;
    let n = g.vertex_count();
    // the class of each tree path, and the first vertex after the root on it
    let mut path = vec![0u64; n * w];
    let mut branch = vec![NONE; n];
    for &v in &t.order {
        let e = t.parent[v as usize];
        if e == NONE {
            continue;
        }
        let (a, b) = g.ends(e);
        let p = if a == v { b } else { a };
        path.copy_within(p as usize * w..(p as usize + 1) * w, v as usize * w);
        xor(&mut path[v as usize * w..(v as usize + 1) * w], ann.of(e));
        branch[v as usize] = if p == t.root { v } else { branch[p as usize] };
    }
    let mut out = Vec::new();
    for (e, &(a, b)) in ends.iter().enumerate() {
        let e = e as u32;
        if a == NONE || a == b || t.has_edge(g, e) || !t.dist[a as usize].is_finite() {
            continue;
        }
        let parts = a == t.root || b == t.root || branch[a as usize] != branch[b as usize];
        let len = t.dist[a as usize] + g.weight(e) + t.dist[b as usize];
        if (tight && !parts) || len > bound {
            continue;
        }
        let mut class = ann.of(e).to_vec();
        xor(&mut class, &path[a as usize * w..(a as usize + 1) * w]);
        xor(&mut class, &path[b as usize * w..(b as usize + 1) * w]);
        if class.iter().any(|&x| x != 0) {
            out.push(((len, t.root, e), class));
        }
    }
    out
}

/// The greedy basis: candidates by length (then root, then edge), each kept when
/// independent, until `rank` are kept.
fn greedy(mut cands: Vec<(Candidate, Vec<u64>)>, rank: usize) -> Vec<Candidate> {
    cands.sort_by(|x, y| x.0 .0.total_cmp(&y.0 .0).then(x.0 .1.cmp(&y.0 .1)).then(x.0 .2.cmp(&y.0 .2)));
    let mut ech = Echelon { rows: Vec::with_capacity(rank) };
    let mut kept = Vec::with_capacity(rank);
    for (c, class) in cands {
        if kept.len() == rank {
            break;
        }
        if ech.insert(class) {
            kept.push(c);
        }
    }
    kept
}

/// The cycle of a kept candidate, its edges in order from its root.
fn basis_cycle(g: &Graph, length: f64, root: u32, e: u32) -> BasisCycle {
    if root == NONE {
        return BasisCycle { length, root, edges: vec![e] };
    }
    let (_, edges) = g.shortest_path_tree(root).loop_through(g, e);
    BasisCycle { length, root, edges }
}

#[cfg(test)]
mod tests;
