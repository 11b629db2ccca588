//! The integer homology of a periodic cubical set of dimension ≤ 3 (a set of closed unit
//! cubes of the d-torus) in one pass over its cubes per union-find, without a chain complex:
//! the components of the set, the components of its complement with the lattice of their
//! winding vectors, and the Euler characteristic.
//!
//! # The derivation
//!
//! Let `M = T^d` be the torus of a box of `n_0 × … × n_{d-1}` cubes with opposite faces
//! identified, `X ⊆ M` the union of the closed cubes of the set, `U = M \ X` its open
//! complement. `H_k(M) = Z^{C(d,k)}`. `X = ∅` has no homology and `X = M` has the torus's;
//! below `∅ ≠ X ≠ M`, so `U` is a non-empty open proper subset of `M`.
//!
//! **Duality.** Alexander duality in the sphere does not apply, but its general form does:
//! for a compact, locally contractible `X` in a closed oriented d-manifold `M`,
//! `H^q(X) ≅ H_{d-q}(M, U)`. The groups on the right come from the exact sequence of the
//! pair `(M, U)`:
//!
//! ```text
//! … → H_k(U) --i_k--> H_k(M) → H_k(M, U) → H_{k-1}(U) --i_{k-1}--> H_{k-1}(M) → …
//! ```
//!
//! The pieces it needs are
//!
//! * `c_U`, the components of `U`: `i_0 : Z^{c_U} → Z` is onto with kernel `Z^{c_U - 1}`;
//! * `L_U = i_1(H_1(U)) ⊆ H_1(M) = Z^d`, the **winding lattice** of the complement, spanned
//!   by the winding vectors of its loops: `coker i_1 = Z^d / L_U`.
//!
//! **Combinatorics.** `U` deformation retracts onto the dual complex of the cells of `M`
//! outside `X`: a vertex per absent cube, an edge per facet both of whose cubes are absent,
//! and so on. Its 1-skeleton is the graph of absent cubes joined across shared facets
//! (6-connectivity in 3-D, 4 in 2-D, through the box's sides too), one edge per facet (a
//! period of 1 or 2 gives loops and double edges). `H_1` of a complex is a quotient of
//! `H_1` of its 1-skeleton, so `L_U` is spanned by the graph's cycles, and a cycle's class
//! in `H_1(M)` is its winding vector: how many times it crosses the box's sides along each
//! axis, upwards minus downwards. A union-find that stores with each cube its winding
//! relative to its root (the crossings along the forest's path) finds them: an edge `i → j`
//! that crosses by `δ` between two cubes already in one class closes the cycle
//! `p(i) + δ - p(j)`, and these cycles span `L_U` (every cycle of a graph is a sum of the
//! fundamental cycles of a spanning forest). `X`'s components are its cubes joined across
//! any shared face (26-connectivity in 3-D, 8 in 2-D), and `χ(X)` counts the cells of its
//! closure from the `2^d` cubes around each vertex of the torus.
//!
//! **d = 3.** With the universal coefficients, `H^q(X) ≅ Free(H_q X) ⊕ Tors(H_{q-1} X)`:
//!
//! * `q = 3`: `H_0(M, U) = 0` (`U ≠ ∅`), so `H_3(X) = 0` and `H_2(X)` is free;
//! * `q = 2`: `0 → coker i_1 → H_1(M, U) → ker i_0 → 0` splits (`ker i_0` is free), so
//!   `Free(H_2 X) ⊕ Tors(H_1 X) ≅ Z^3 / L_U ⊕ Z^{c_U - 1}`. With `s_1 | s_2 | …` the invariant
//!   factors of `L_U` (the Smith form of its spanning vectors), of rank `r`:
//!   `b_2 = 3 - r + c_U - 1` and `Tors(H_1 X) = ⊕ Z/s_i` over the factors `s_i > 1`;
//! * `q = 0`: `b_0 = c_X`, the components of `X`;
//! * `b_1 = b_0 + b_2 - χ(X)` (Euler–Poincaré, `b_3 = 0`).
//!
//! Torsion does occur: if `U` is a thin tube whose core winds twice around the first axis,
//! `L_U = 2Z × 0 × 0` and `H_1(X) = Z^3 ⊕ Z/2`.
//!
//! **d = 2.** `H_0(M, U) = 0` gives `H_2(X) = 0` and `Tors(H_1 X) = 0`; `H^1(X) = H_1(M, U) ≅
//! Z^2 / L_U ⊕ Z^{c_U - 1}` is then free, and only its rank is needed, which Euler–Poincaré
//! gives without the complement: `b_0 = c_X`, `b_1 = b_0 - χ(X)`.
//!
//! **d = 1.** A proper subset of the circle is a union of `b_0` disjoint arcs (the runs of
//! the set, counted around the circle), `b_1 = 0`.
//!
//! # Cost
//!
//! The box is read one layer of cubes (across its slowest axis) at a time from the `fill`
//! callback, twice in 3-D (once per union-find); three layers are kept (the first, the
//! previous and the current one). The union-finds span the whole box: 4 bytes per cube for
//! the set's, 16 for the complement's (a parent and a winding in `Z^3`, one after the
//! other), so [`BYTES_PER_CUBE`]. Time O(cubes · α) with path compression; one thread.
//!
//! ```
//! use gmap_homology::cubical::torus::betti_one_pass_periodic;
//! // one full layer of a 3 × 3 × 3 torus: a 2-torus times an interval
//! let bits: Vec<u8> = (0..27).map(|i| (i / 9 == 1) as u8).collect();
//! let r = betti_one_pass_periodic(&[3, 3, 3], |s, out| out.copy_from_slice(&bits[s..s + out.len()])).unwrap();
//! assert_eq!(r.betti, vec![1, 2, 1, 0]);
//! assert_eq!(r.euler_characteristic, 0);
//! ```

use gmap_core::union_find::UnionFind;

use super::CubicalError;

/// What [`betti_one_pass_periodic`] found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TorusPass {
    /// `b_0 … b_d`
    pub betti: Vec<u64>,
    /// the invariant factors (> 1, ascending) of the torsion of each `H_k` (only `H_1` in 3-D)
    pub torsion: Vec<Vec<u64>>,
    /// the cells of the closure, alternating
    pub euler_characteristic: i64,
    /// cubes of the set
    pub cubes: u64,
    /// components of the set
    pub set_components: u64,
    /// components of the complement in the torus (counted in 3-D only; 0 otherwise)
    pub complement_components: u64,
    /// the complement's winding lattice in Hermite form, one row per basis vector (3-D only)
    pub winding: Vec<Vec<i64>>,
}

/// The bytes [`betti_one_pass_periodic`] holds per cube of the box (the complement's
/// union-find with its windings).
pub const BYTES_PER_CUBE: u64 = 16;

/// The most cubes a box may have: windings relative to a root stay within `i32`.
pub const MAX_CUBES: usize = i32::MAX as usize;

/// The bytes [`betti_one_pass_periodic`] needs for a box of `shape` (its union-finds;
/// `None` past `u64`): [`BYTES_PER_CUBE`] per cube in 3-D, 4 in 2-D, none in 1-D.
pub fn bytes_needed(shape: &[usize]) -> Option<u64> {
    let per_cube = match shape.len() {
        3 => BYTES_PER_CUBE,
        2 => 4,
        _ => 0,
    };
    shape.iter().try_fold(per_cube, |v, &s| v.checked_mul(s as u64))
}

/// The groups of the set of a periodic box of `shape` cubes (axis 0 fastest, `1 ≤ d ≤ 3`;
/// opposite faces identified), whose presence bytes (non-zero: in the set) `fill(start,
/// out)` writes for the cubes `start .. start + out.len()`. `fill` is called once or twice
/// per layer of the slowest axis. See the [module docs](self). Refuses a dimension outside
/// 1–3, an empty box, a box over [`MAX_CUBES`] cubes, or one over the memory limit.
pub fn betti_one_pass_periodic(shape: &[usize], fill: impl Fn(usize, &mut [u8])) -> Result<TorusPass, CubicalError> {
    let d = shape.len();
    if !(1..=3).contains(&d) || shape.contains(&0) {
        return Err(CubicalError::BadShape(format!(
            "the periodic one-pass route takes dimensions 1 to 3, not the shape {shape:?}"
        )));
    }
    let volume = shape.iter().try_fold(1usize, |v, &s| v.checked_mul(s)).filter(|&v| v <= MAX_CUBES);
    let Some(volume) = volume else {
        return Err(CubicalError::TooLarge {
            points: shape.iter().map(|s| s.to_string()).collect::<Vec<_>>().join(" × ") + " (cubes)",
            limit: MAX_CUBES as u64,
        });
    };
    if d == 1 {
        let mut row = vec![0u8; shape[0]];
        fill(0, &mut row);
        let n = row.len();
        let cubes = row.iter().filter(|&&b| b != 0).count() as u64;
        // a run starts at a present cube after an absent one, around the circle
        let runs = (0..n).filter(|&i| row[i] != 0 && row[(i + n - 1) % n] == 0).count() as u64;
        let (betti, chi) = match cubes {
            0 => (vec![0, 0], 0),
            c if c == n as u64 => (vec![1, 1], 0),
            _ => (vec![runs, 0], runs as i64),
        };
        return Ok(TorusPass {
            set_components: betti[0],
            betti,
            torsion: vec![Vec::new(); 2],
            euler_characteristic: chi,
            cubes,
            complement_components: 0,
            winding: Vec::new(),
        });
    }
    gmap_core::resources::check_memory(
        "the union-finds of the periodic one-pass cubical homology",
        bytes_needed(shape),
    )?;
    let layout = Layout::new(shape);
    let (cubes, set_components, chi) = set_pass(&layout, &fill);
    let empty = || TorusPass {
        betti: vec![0; d + 1],
        torsion: vec![Vec::new(); d + 1],
        euler_characteristic: 0,
        cubes: 0,
        set_components: 0,
        complement_components: 0,
        winding: Vec::new(),
    };
    if cubes == 0 {
        return Ok(empty());
    }
    if cubes == volume as u64 {
        // the whole torus: H_k = Z^{C(d, k)}
        let betti = if d == 2 { vec![1, 2, 1] } else { vec![1, 3, 3, 1] };
        let winding = if d == 3 { vec![vec![1, 0, 0], vec![0, 1, 0], vec![0, 0, 1]] } else { Vec::new() };
        return Ok(TorusPass { betti, euler_characteristic: 0, cubes, set_components: 1, winding, ..empty() });
    }
    if d == 2 {
        let b1 = set_components as i64 - chi;
        return Ok(TorusPass {
            betti: vec![set_components, b1 as u64, 0],
            euler_characteristic: chi,
            cubes,
            set_components,
            ..empty()
        });
    }
    let (complement_components, lattice) = complement_pass(&layout, &fill);
    let factors = lattice.invariant_factors();
    let rank = factors.len() as u64;
    let b2 = 3 - rank + complement_components - 1;
    let b1 = set_components as i64 + b2 as i64 - chi;
    let torsion1: Vec<u64> = factors.into_iter().filter(|&s| s > 1).map(|s| s as u64).collect();
    Ok(TorusPass {
        betti: vec![set_components, b1 as u64, b2, 0],
        torsion: vec![Vec::new(), torsion1, Vec::new(), Vec::new()],
        euler_characteristic: chi,
        cubes,
        set_components,
        complement_components,
        winding: lattice.rows.iter().map(|r| r.iter().map(|&x| x as i64).collect()).collect(),
    })
}

/// A box of dimension 2 or 3 as layers across its slowest axis; a 2-D box's layers are its
/// rows (one in-layer axis), a 3-D box's its planes (two).
struct Layout {
    n0: usize,
    /// rows of a layer (1 in 2-D)
    n1: usize,
    layers: usize,
    three: bool,
}

impl Layout {
    fn new(shape: &[usize]) -> Layout {
        let three = shape.len() == 3;
        Layout { n0: shape[0], n1: if three { shape[1] } else { 1 }, layers: shape[shape.len() - 1], three }
    }

    fn layer(&self) -> usize {
        self.n0 * self.n1
    }

    /// Reads layer `z` into `out` as 0/1 bytes.
    fn read(&self, z: usize, out: &mut [u8], fill: &impl Fn(usize, &mut [u8])) {
        fill(z * out.len(), out);
        for b in out.iter_mut() {
            *b = (*b != 0) as u8;
        }
    }

    /// The in-layer offsets `(dx, dy)` of the cubes sharing any face with a cube: all of
    /// them (`all`), or one of each opposite pair (`!all`, the cube itself excluded).
    fn neighbours(&self, all: bool) -> Vec<(isize, isize)> {
        let ys: &[isize] = if self.three { &[-1, 0, 1] } else { &[0] };
        let mut v = Vec::new();
        for &dy in ys {
            for dx in -1isize..=1 {
                if all || (dy, dx) > (0, 0) {
                    v.push((dx, dy));
                }
            }
        }
        v
    }

    /// The cube of layer-index `i` moved by `(dx, dy)` in the layer, around the torus.
    fn shift(&self, i: usize, dx: isize, dy: isize) -> usize {
        let (x, y) = (i % self.n0, i / self.n0);
        let x = (x as isize + dx).rem_euclid(self.n0 as isize) as usize;
        let y = (y as isize + dy).rem_euclid(self.n1 as isize) as usize;
        y * self.n0 + x
    }
}

/// The first, the previous and the current layer of a pass over the layers.
struct Window {
    first: Vec<u8>,
    prev: Vec<u8>,
    cur: Vec<u8>,
}

impl Window {
    fn new(m: usize) -> Window {
        Window { first: vec![0; m], prev: vec![0; m], cur: vec![0; m] }
    }

    /// Reads layer `z` as the current one; the current one becomes the previous one.
    fn advance(&mut self, l: &Layout, z: usize, fill: &impl Fn(usize, &mut [u8])) {
        std::mem::swap(&mut self.prev, &mut self.cur);
        l.read(z, &mut self.cur, fill);
        if z == 0 {
            self.first.copy_from_slice(&self.cur);
        }
    }
}

/// The set's cubes, its components (cubes joined across any shared face, around the torus)
/// and χ of its closure.
fn set_pass(l: &Layout, fill: &impl Fn(usize, &mut [u8])) -> (u64, u64, i64) {
    let m = l.layer();
    let mut uf = UnionFind::new(m * l.layers);
    let mut sets = uf.view();
    let mut w = Window::new(m);
    let (inside, across) = (l.neighbours(false), l.neighbours(true));
    let table = euler_table(if l.three { 3 } else { 2 });
    let (mut cubes, mut unions, mut chi) = (0u64, 0u64, 0i64);
    let mut join = |a: usize, b: usize| unions += sets.union(a as u32, b as u32) as u64;
    for z in 0..l.layers {
        w.advance(l, z, fill);
        let (prev, cur) = (&w.prev, &w.cur);
        let base = z * m;
        for i in 0..m {
            if cur[i] == 0 {
                continue;
            }
            cubes += 1;
            for &(dx, dy) in &inside {
                let j = l.shift(i, dx, dy);
                if cur[j] != 0 {
                    join(base + i, base + j);
                }
            }
            if z > 0 {
                for &(dx, dy) in &across {
                    let j = l.shift(i, dx, dy);
                    if prev[j] != 0 {
                        join(base + i, base - m + j);
                    }
                }
            }
        }
        if z > 0 {
            chi += vertex_layer(l, prev, cur, &table);
        }
    }
    let (first, cur) = (&w.first, &w.cur);
    // the last layer meets the first around the torus (the same layer when there is one)
    let last = (l.layers - 1) * m;
    for (i, _) in cur.iter().enumerate().filter(|(_, &b)| b != 0) {
        for &(dx, dy) in &across {
            let j = l.shift(i, dx, dy);
            if first[j] != 0 {
                join(last + i, j);
            }
        }
    }
    chi += vertex_layer(l, cur, first, &table);
    (cubes, cubes - unions, chi)
}

/// χ of the cells whose minimal vertex lies between the cube layers `below` and `above`.
fn vertex_layer(l: &Layout, below: &[u8], above: &[u8], table: &[i8]) -> i64 {
    let mut sum = 0i64;
    for vy in 0..l.n1 {
        for vx in 0..l.n0 {
            let v = vy * l.n0 + vx;
            let mut code = 0usize;
            // the cube on the lower (0) or upper (1) side of the vertex along each axis
            for (bit, &(dx, dy, dz)) in corners(l.three).iter().enumerate() {
                let j = l.shift(v, dx - 1, dy - 1);
                let layer = if dz == 1 { above } else { below };
                code |= (layer[j] as usize) << bit;
            }
            sum += table[code] as i64;
        }
    }
    sum
}

/// The cubes around a vertex as offsets in {0, 1} along (x, y, layer axis): pattern bit `k`
/// is corner `k`, the axes of a cell spanned in the same order.
fn corners(three: bool) -> &'static [(isize, isize, isize)] {
    if three {
        &[(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), (0, 0, 1), (1, 0, 1), (0, 1, 1), (1, 1, 1)]
    } else {
        // 2-D: no y axis (dy = 1: no shift along it), x and the layer axis
        &[(0, 1, 0), (1, 1, 0), (0, 1, 1), (1, 1, 1)]
    }
}

/// The contribution to χ of the cells whose minimal vertex is a vertex with the pattern
/// `code` of its `2^d` cubes: the cell spanning the axes `S` (bit `a` of `S`: axis `a` of
/// the pattern) is present iff a cube on the upper side along each axis of `S` is.
fn euler_table(d: usize) -> Vec<i8> {
    let corners = 1usize << d;
    (0..1usize << corners)
        .map(|code| {
            let mut chi = 0i8;
            for span in 0..corners {
                let present = (0..corners).any(|c| code >> c & 1 == 1 && c & span == span);
                if present {
                    chi += if span.count_ones() % 2 == 0 { 1 } else { -1 };
                }
            }
            chi
        })
        .collect()
}

/// The complement's components (absent cubes joined across shared facets, around the torus)
/// and its winding lattice, in 3-D.
fn complement_pass(l: &Layout, fill: &impl Fn(usize, &mut [u8])) -> (u64, Lattice) {
    let m = l.layer();
    let mut uf = WindingForest::new(m * l.layers);
    let mut lattice = Lattice::default();
    let mut w = Window::new(m);
    let (mut absent, mut unions) = (0u64, 0u64);
    let mut edge =
        |uf: &mut WindingForest, a: usize, b: usize, cross: [i32; 3]| match uf.join(a as u32, b as u32, cross) {
            Joined::Merged => unions += 1,
            Joined::Cycle(w) => lattice.insert(w),
            Joined::Same => {}
        };
    for z in 0..l.layers {
        w.advance(l, z, fill);
        let (prev, cur) = (&w.prev, &w.cur);
        let base = z * m;
        for i in 0..m {
            if cur[i] != 0 {
                continue;
            }
            absent += 1;
            let (x, y) = (i % l.n0, i / l.n0);
            // the facets on the upper side along x and y; crossing the box's side counts
            let j = l.shift(i, 1, 0);
            if cur[j] == 0 {
                edge(&mut uf, base + i, base + j, [(x + 1 == l.n0) as i32, 0, 0]);
            }
            let j = l.shift(i, 0, 1);
            if cur[j] == 0 {
                edge(&mut uf, base + i, base + j, [0, (y + 1 == l.n1) as i32, 0]);
            }
            if z > 0 && prev[i] == 0 {
                edge(&mut uf, base - m + i, base + i, [0, 0, 0]);
            }
        }
    }
    let last = (l.layers - 1) * m;
    for i in 0..m {
        if w.cur[i] == 0 && w.first[i] == 0 {
            edge(&mut uf, last + i, i, [0, 0, 1]);
        }
    }
    (absent - unions, lattice)
}

/// What [`WindingForest::join`] did.
enum Joined {
    /// two classes became one
    Merged,
    /// the edge closed a cycle of this (non-zero) winding vector
    Cycle([i64; 3]),
    /// the edge closed a cycle that winds nowhere
    Same,
}

/// Disjoint sets over `0..len` in which each item knows its winding relative to its root
/// (the crossings of the box's sides along the path of the forest from the root to it).
/// Path compression keeps the windings relative to the new parent. O(α) amortised per call.
struct WindingForest {
    parent: Vec<u32>,
    winding: Vec<[i32; 3]>,
    path: Vec<u32>,
}

impl WindingForest {
    fn new(len: usize) -> WindingForest {
        WindingForest { parent: (0..len as u32).collect(), winding: vec![[0; 3]; len], path: Vec::new() }
    }

    /// The root of `x` and the winding of `x` relative to it.
    fn find(&mut self, x: u32) -> (u32, [i32; 3]) {
        self.path.clear();
        let mut r = x;
        while self.parent[r as usize] != r {
            self.path.push(r);
            r = self.parent[r as usize];
        }
        // from the node nearest the root down: each winding becomes relative to the root
        let mut acc = [0i32; 3];
        for &y in self.path.iter().rev() {
            let w = &mut self.winding[y as usize];
            // |winding| < the cubes of the box ≤ i32::MAX (the forest's paths are simple)
            for (s, &x) in acc.iter_mut().zip(w.iter()) {
                *s += x;
            }
            *w = acc;
            self.parent[y as usize] = r;
        }
        (r, self.winding[x as usize])
    }

    /// The edge `a → b` that crosses the box's sides by `cross`.
    fn join(&mut self, a: u32, b: u32, cross: [i32; 3]) -> Joined {
        let (ra, wa) = self.find(a);
        let (rb, wb) = self.find(b);
        // the winding of b's root seen from a's: w(a) + cross - w(b)
        let w: [i64; 3] = std::array::from_fn(|k| wa[k] as i64 + cross[k] as i64 - wb[k] as i64);
        if ra == rb {
            return if w == [0; 3] { Joined::Same } else { Joined::Cycle(w) };
        }
        // the smaller root stays the root
        let (root, child, w) = if ra < rb { (ra, rb, w) } else { (rb, ra, w.map(|x| -x)) };
        self.parent[child as usize] = root;
        self.winding[child as usize] = w.map(|x| x as i32);
        Joined::Merged
    }
}

/// A sublattice of `Z^3` in Hermite form: `rows[k]`'s first non-zero entry is its pivot,
/// positive, in a column after the pivots of the rows before it.
#[derive(Clone, Debug, Default)]
struct Lattice {
    rows: Vec<[i128; 3]>,
}

impl Lattice {
    /// Adds `v` to the spanning vectors. O(1) (at most 3 rows).
    fn insert(&mut self, v: [i64; 3]) {
        let mut v = v.map(|x| x as i128);
        let mut rows: Vec<[i128; 3]> = Vec::with_capacity(3);
        let mut old = std::mem::take(&mut self.rows).into_iter().peekable();
        for col in 0..3 {
            let pivot_row = old.next_if(|r| r[..col].iter().all(|&x| x == 0) && r[col] != 0);
            match (pivot_row, v[col] != 0) {
                (Some(r), false) => rows.push(r),
                (None, false) => {}
                (None, true) => {
                    // v takes this column; nothing is left to reduce
                    rows.push(if v[col] < 0 { v.map(|x| -x) } else { v });
                    v = [0; 3];
                }
                (Some(r), true) => {
                    // the gcd of the two pivots becomes the pivot, the other combination
                    // has a zero in this column
                    let (g, s, t) = ext_gcd(r[col], v[col]);
                    let (p, q) = (r[col] / g, v[col] / g);
                    let new: [i128; 3] = std::array::from_fn(|k| s * r[k] + t * v[k]);
                    v = std::array::from_fn(|k| p * v[k] - q * r[k]);
                    rows.push(if new[col] < 0 { new.map(|x| -x) } else { new });
                }
            }
        }
        // keep the entries small: reduce each row above a pivot modulo it
        for j in 0..rows.len() {
            let col = rows[j].iter().position(|&x| x != 0).unwrap_or(0);
            for i in 0..j {
                let f = rows[i][col].div_euclid(rows[j][col]);
                if f != 0 {
                    let rj = rows[j];
                    for k in 0..3 {
                        rows[i][k] -= f * rj[k];
                    }
                }
            }
        }
        self.rows = rows;
    }

    /// The invariant factors `s_1 | s_2 | …` (one per rank), from the gcds `D_k` of the
    /// `k × k` minors: `s_k = D_k / D_{k-1}`.
    fn invariant_factors(&self) -> Vec<i128> {
        let r = &self.rows;
        let minors: Vec<Vec<i128>> = match r.len() {
            0 => Vec::new(),
            1 => vec![r[0].to_vec()],
            2 => vec![r.iter().flatten().copied().collect(), minors2(r[0], r[1])],
            _ => {
                let mut two = Vec::new();
                for (i, j) in [(0, 1), (0, 2), (1, 2)] {
                    two.extend(minors2(r[i], r[j]));
                }
                let det = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1])
                    - r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0])
                    + r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
                vec![r.iter().flatten().copied().collect(), two, vec![det]]
            }
        };
        let mut prev = 1i128;
        minors
            .iter()
            .map(|m| {
                let dk = m.iter().fold(0i128, |g, &x| gcd(g, x));
                let s = dk / prev;
                prev = dk;
                s
            })
            .collect()
    }
}

/// The 2 × 2 minors of two rows.
fn minors2(a: [i128; 3], b: [i128; 3]) -> Vec<i128> {
    vec![a[0] * b[1] - a[1] * b[0], a[0] * b[2] - a[2] * b[0], a[1] * b[2] - a[2] * b[1]]
}

fn gcd(a: i128, b: i128) -> i128 {
    let (mut a, mut b) = (a.abs(), b.abs());
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// `(g, s, t)` with `g = gcd(a, b) > 0` and `s a + t b = g` (`a`, `b` not both zero).
fn ext_gcd(a: i128, b: i128) -> (i128, i128, i128) {
    let (mut r0, mut r1, mut s0, mut s1, mut t0, mut t1) = (a, b, 1i128, 0i128, 0i128, 1i128);
    while r1 != 0 {
        let q = r0.div_euclid(r1);
        (r0, r1) = (r1, r0 - q * r1);
        (s0, s1) = (s1, s0 - q * s1);
        (t0, t1) = (t1, t0 - q * t1);
    }
    if r0 < 0 {
        (-r0, -s0, -t0)
    } else {
        (r0, s0, t0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lattices_and_their_factors() {
        let mut l = Lattice::default();
        assert!(l.invariant_factors().is_empty());
        l.insert([2, 0, 0]);
        assert_eq!(l.invariant_factors(), vec![2]);
        l.insert([0, 1, 0]);
        l.insert([0, 0, 1]);
        l.insert([2, 1, 0]);
        assert_eq!(l.invariant_factors(), vec![1, 1, 2]);
        l.insert([3, 0, 0]);
        assert_eq!(l.invariant_factors(), vec![1, 1, 1]);
        let mut l = Lattice::default();
        for v in [[4, 6, 0], [6, 9, 0], [0, 0, 0], [2, 3, 0]] {
            l.insert(v);
        }
        assert_eq!(l.invariant_factors(), vec![1]);
        let mut l = Lattice::default();
        l.insert([0, 2, 4]);
        l.insert([0, 4, 2]);
        assert_eq!(l.invariant_factors(), vec![2, 6]);
    }

    #[test]
    fn euler_tables() {
        // the cube below the vertex along every axis: of its cells only the vertex has it as
        // minimal vertex; the cube above: all 2^d of them do
        assert_eq!(euler_table(2)[0b0001], 1);
        assert_eq!(euler_table(3)[0b0000_0001], 1);
        assert_eq!(euler_table(2)[0b1000], 0);
        assert_eq!(euler_table(3)[0b1000_0000], 1 - 3 + 3 - 1);
        // the two cubes before the vertex along the layer axis in 2-D: the vertex and the edge along x
        assert_eq!(euler_table(2)[0b0011], 1 - 1);
        assert_eq!(euler_table(3)[255], 0);
    }
}
