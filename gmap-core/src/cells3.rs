//! The oriented cells of every dimension of a 3-map at once, from rings inside volumes.
//!
//! The generic traversal ([`crate::kernels`]) finds an i-cell by following all three of its
//! involutions from every dart. In a big map most of those links lead into other volumes,
//! far away in memory, and each step of a traversal waits for the previous one: the walk
//! is a chain of cache misses. Below dimension 3 a cell of a 3-map has a rigid shape that
//! avoids this (`alpha_i` and `alpha_j` commute when `|i - j| >= 2`):
//!
//! * inside one volume, the darts of an i-cell, `i < 3`, form rings of the two involutions
//!   other than `alpha_i` and `alpha_3`: *corners* (`<alpha_1, alpha_2>`), *edge sides*
//!   (`<alpha_0, alpha_2>`, four darts) and *face sides* (`<alpha_0, alpha_1>`);
//! * `alpha_3` glues the rings of neighbouring volumes into cells, and it commutes with the
//!   first involution of each ring, so one link per pair of darts of the ring (one link per
//!   face side) is enough.
//!
//! So each dimension takes one sequential scan: the rings are walked where the scan finds
//! them (memory next to the scan), each gets a provisional number and a colouring by the
//! rule of condition C1 (`alpha_k` flips the colour for `k < i`, `alpha_j` keeps it for
//! `j > i`), and the `alpha_3` links to rings met earlier are merged by a union-find with
//! parities over ring numbers. These lookups are independent of each other, so the
//! processor overlaps their misses. A last sequential pass renumbers the cells by smallest
//! dart and fixes the colours. The rings also give, per volume, its corners, edge sides and
//! face sides: the Euler characteristic of the volume's boundary surface (condition C2).
//!
//! Anything outside these shapes (a dart free for `alpha_0`, `alpha_1` or `alpha_2`, a
//! colouring conflict, that is a folded or non-orientable cell, links that are not
//! involutions) gives `None`, and the caller runs the generic traversal, which names the
//! offending cell.

use crate::ids::Dart;
use crate::kernels::oriented_by;
use crate::parallel;
use crate::union_find::ParityUnionFind;

const NONE: u32 = u32::MAX;
const BITS: usize = usize::BITS as usize;

/// The partition, representatives and colour words of one dimension.
pub(crate) type Cells = (Vec<u32>, Vec<Dart>, Vec<usize>);

/// The oriented cells of dimensions 0 to 3 of a 3-map, and the Euler characteristic of the
/// boundary of each volume; `None` when a cell is not of the shapes of the module docs.
/// The four dimensions are tasks of [`parallel::map_tasks`]. O(N α(N)).
pub(crate) fn oriented_cells_3(rows: &[[u32; 4]]) -> Option<([Cells; 4], Vec<i64>)> {
    let mut parts = parallel::map_tasks(4, rows.len(), |k| cells_of(rows, k)).into_iter();
    let mut next = || parts.next().flatten();
    let ((v, corners), (e, sides), (f, rings), (c, _)) = (next()?, next()?, next()?, next()?);
    let vol = &c.0;
    let mut chi = vec![0i64; c.1.len()];
    for &x in corners.iter().chain(&rings) {
        chi[vol[x as usize] as usize] += 1;
    }
    for &x in &sides {
        chi[vol[x as usize] as usize] -= 1;
    }
    Some(([v, e, f, c], chi))
}

/// The oriented i-cells of a 3-map for each `i` of `dims`, in that order, each a task of
/// [`parallel::map_tasks`]; `None` when a cell of one of these dimensions is not of the
/// shapes of the module docs. O(N α(N)) per dimension.
pub(crate) fn oriented_cells_3_of(rows: &[[u32; 4]], dims: &[usize]) -> Option<Vec<Cells>> {
    parallel::map_tasks(dims.len(), rows.len(), |t| cells_of(rows, dims[t]).map(|(c, _)| c)).into_iter().collect()
}

/// The oriented `i`-cells (`i <= 3`) and, below 3, the first dart of every ring.
fn cells_of(rows: &[[u32; 4]], i: usize) -> Option<(Cells, Vec<u32>)> {
    // (first involution of the ring, second, does each flip the colour, link every pair)
    match i {
        0 => glued(rows, 1, 2, false, false, true),
        1 => glued(rows, 0, 2, true, false, true),
        2 => glued(rows, 0, 1, true, true, false),
        _ => oriented_by(rows.len(), |x| &rows[x][..], 3).ok().map(|c| (c, Vec::new())),
    }
}

/// The i-cells whose darts, inside a volume, form rings of `alpha_a` and `alpha_b`, glued
/// by `alpha_3`; `fa`, `fb`: whether each flips the colour; `every_pair`: whether each pair
/// `{x, alpha_a(x)}` of a ring has its own `alpha_3` link to check (else only the ring's
/// first dart, when `alpha_3` commutes with both). Also the first dart of every ring.
fn glued(rows: &[[u32; 4]], a: usize, b: usize, fa: bool, fb: bool, every_pair: bool) -> Option<(Cells, Vec<u32>)> {
    let n = rows.len();
    // pass 1: ring numbers in `of`, colours in `col`, α3 links to earlier rings merged
    let mut of = vec![NONE; n];
    let mut col = vec![0usize; n.div_ceil(BITS)];
    let mut first: Vec<u32> = Vec::with_capacity(n / 4);
    let mut uf = ParityUnionFind::with_capacity(n / 4);
    let mut links: Vec<u32> = Vec::with_capacity(64);
    let colour = |col: &[usize], x: usize| col[x / BITS] >> (x % BITS) & 1 == 1;
    for d in 0..n {
        if of[d] != NONE {
            continue;
        }
        let r = first.len() as u32;
        first.push(d as u32);
        uf.push();
        links.clear();
        let mut x = d;
        let mut c = true;
        loop {
            if of[x] != NONE {
                return None;
            }
            of[x] = r;
            col[x / BITS] |= usize::from(c) << (x % BITS);
            if every_pair || x == d {
                links.push(x as u32);
            }
            let y = rows[x][a] as usize;
            if y == x || of[y] != NONE {
                return None;
            }
            c ^= fa;
            of[y] = r;
            col[y / BITS] |= usize::from(c) << (y % BITS);
            let z = rows[y][b] as usize;
            if z == y {
                return None;
            }
            c ^= fb;
            if z == d {
                if !c {
                    return None;
                }
                break;
            }
            x = z;
        }
        for &x in &links {
            let y = rows[x as usize][3] as usize;
            if y == x as usize || of[y] == NONE {
                continue;
            }
            // alpha_3 keeps the colour: the rings' flips differ as the local colours do
            if !uf.join(r, of[y], colour(&col, x as usize) ^ colour(&col, y)) {
                return None;
            }
        }
    }
    // pass 2: cells numbered by smallest dart (the first dart of their first ring)
    let rings = first.len();
    let mut reps = Vec::new();
    let mut fin: Vec<(u32, bool)> = Vec::with_capacity(rings);
    for r in 0..rings as u32 {
        let (root, f) = uf.find(r);
        if root == r {
            fin.push((reps.len() as u32, false));
            reps.push(Dart::new(first[r as usize]));
        } else {
            fin.push((fin[root as usize].0, f));
        }
    }
    // pass 3: darts take their cell and their colour in it
    let mut pos = vec![0usize; n.div_ceil(BITS)];
    for (k, word) in pos.iter_mut().enumerate() {
        let lo = k * BITS;
        let hi = (lo + BITS).min(n);
        let mut w = col[k];
        for (bit, x) in (lo..hi).enumerate() {
            let (cell, f) = fin[of[x] as usize];
            of[x] = cell;
            w ^= usize::from(f) << bit;
        }
        *word = w;
    }
    Some(((of, reps, pos), first))
}
