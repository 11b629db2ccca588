//! Column reduction over `Z/p` with clearing, one dimension at a time.
//!
//! The standard persistence algorithm: columns (cells of dimension k, in filtration order)
//! are reduced left to right by adding multiples of earlier reduced columns until their
//! lowest row (the largest face in filtration order) is unclaimed; that row and column are
//! then a persistence pair. Dimensions are reduced from the top down so that the rows
//! claimed as pivots at dimension k + 1 (the k-cells that kill a class) are skipped as
//! columns at dimension k: they would reduce to zero (clearing, or the twist of Chen and
//! Kerber).
//!
//! Columns are asked for through a closure, so the boundary may be explicit (a filtered
//! simplicial complex) or computed from a grid on the fly (an image): only the columns that
//! changed during their reduction are stored, an untouched one is asked for again when it
//! is needed as a pivot column. With `track_v` the reduction also keeps, for each column,
//! the chain of k-cells whose boundary it is (the matrix `V` of `R = ∂V`), which gives the
//! representative of an essential class.
//!
//! Cost: each column costs its length times the number of additions; on images and
//! manifolds nearly all columns are reduced by their boundary alone or one addition
//! (apparent pairs), so the pass is close to linear in the number of cells.

use rustc_hash::FxHashMap;

/// A column entry: row (rank of a face in its dimension) and its coefficient in `1..p`.
pub(crate) type Entry = (u32, u32);

/// No column claims this row.
const FREE: u32 = u32::MAX;

/// Arithmetic of `Z/p`, `p` a prime below `2^31`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Zp {
    p: u64,
}

impl Zp {
    pub(crate) fn new(p: u32) -> Self {
        Zp { p: p as u64 }
    }

    /// The class of a signed integer.
    #[inline]
    pub(crate) fn of(self, x: i64) -> u32 {
        x.rem_euclid(self.p as i64) as u32
    }

    #[inline]
    pub(crate) fn mul(self, a: u32, b: u32) -> u32 {
        if self.p == 2 {
            a & b
        } else {
            ((a as u64 * b as u64) % self.p) as u32
        }
    }

    #[inline]
    pub(crate) fn add(self, a: u32, b: u32) -> u32 {
        if self.p == 2 {
            a ^ b
        } else {
            ((a as u64 + b as u64) % self.p) as u32
        }
    }

    #[inline]
    pub(crate) fn neg(self, a: u32) -> u32 {
        if a == 0 {
            0
        } else {
            (self.p - a as u64) as u32
        }
    }

    /// The inverse of a non-zero class (Fermat: `a^(p-2)`).
    pub(crate) fn inv(self, a: u32) -> u32 {
        if self.p == 2 {
            return a;
        }
        let (mut base, mut e, mut r) = (a as u64 % self.p, self.p - 2, 1u64);
        while e > 0 {
            if e & 1 == 1 {
                r = r * base % self.p;
            }
            base = base * base % self.p;
            e >>= 1;
        }
        r as u32
    }

    /// `out = a + f * b`, entries `(row, coefficient)` sorted by row (any ordered key: a
    /// row number or a filtration key), zeros dropped. O(|a| + |b|).
    pub(crate) fn axpy<K: Copy + Ord>(self, a: &[(K, u32)], f: u32, b: &[(K, u32)], out: &mut Vec<(K, u32)>) {
        out.clear();
        out.reserve(a.len() + b.len());
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            let (ra, rb) = (a[i].0, b[j].0);
            if ra < rb {
                out.push(a[i]);
                i += 1;
            } else if rb < ra {
                out.push((rb, self.mul(f, b[j].1)));
                j += 1;
            } else {
                let c = self.add(a[i].1, self.mul(f, b[j].1));
                if c != 0 {
                    out.push((ra, c));
                }
                i += 1;
                j += 1;
            }
        }
        out.extend_from_slice(&a[i..]);
        out.extend(b[j..].iter().map(|&(r, c)| (r, self.mul(f, c))));
    }
}

/// Sorts a column by row and merges repeated rows (a periodic grid of one cell per axis has
/// both faces of an edge equal), dropping zeros.
pub(crate) fn normalize(field: Zp, col: &mut Vec<Entry>) {
    col.sort_unstable_by_key(|e| e.0);
    let mut w = 0;
    for r in 0..col.len() {
        if w > 0 && col[w - 1].0 == col[r].0 {
            col[w - 1].1 = field.add(col[w - 1].1, col[r].1);
            if col[w - 1].1 == 0 {
                w -= 1;
            }
        } else if !col[r].1.is_multiple_of(field.p as u32) {
            col[w] = (col[r].0, col[r].1 % field.p as u32);
            w += 1;
        }
    }
    col.truncate(w);
}

/// What the reduction of one dimension's columns found.
#[derive(Debug, Default)]
pub(crate) struct DimReduction {
    /// `(row, column)`: the row's cell is born, the column's cell kills it
    pub pairs: Vec<(u32, u32)>,
    /// columns reduced to zero (their cell creates a class), in order
    pub zero: Vec<u32>,
    /// the reduced column of each pair's column (with `keep`), a representative cycle
    pub reduced: FxHashMap<u32, Vec<Entry>>,
    /// `V` of each zero column (with `track_v`): a chain of columns that is a cycle
    pub v: FxHashMap<u32, Vec<Entry>>,
    /// rows claimed as pivots, so that the next dimension down skips them
    pub claimed: Vec<bool>,
}

/// Reduces the columns `cols` (ascending ranks) against `rows` rows. `boundary(j, out)`
/// writes column `j`'s entries (any order, coefficients already in `Z/p`). With `keep`
/// every pair's reduced column is returned; with `track_v` every zero column's `V`.
pub(crate) fn reduce_dim<F>(
    field: Zp,
    rows: usize,
    cols: impl Iterator<Item = u32>,
    mut boundary: F,
    keep: bool,
    track_v: bool,
) -> DimReduction
where
    F: FnMut(u32, &mut Vec<Entry>),
{
    let mut owner = vec![FREE; rows];
    let mut stored: FxHashMap<u32, Vec<Entry>> = FxHashMap::default();
    let mut vs: FxHashMap<u32, Vec<Entry>> = FxHashMap::default();
    let mut out = DimReduction::default();
    let (mut col, mut scratch, mut other) = (Vec::new(), Vec::new(), Vec::new());
    let (mut v, mut vscratch) = (Vec::new(), Vec::new());
    for j in cols {
        col.clear();
        boundary(j, &mut col);
        normalize(field, &mut col);
        let mut changed = false;
        if track_v {
            v.clear();
            v.push((j, 1));
        }
        loop {
            let Some(&(pivot, c)) = col.last() else {
                out.zero.push(j);
                if track_v {
                    vs.insert(j, std::mem::take(&mut v));
                }
                break;
            };
            let o = owner[pivot as usize];
            if o == FREE {
                owner[pivot as usize] = j;
                out.pairs.push((pivot, j));
                if changed || keep {
                    stored.insert(j, col.clone());
                }
                if track_v {
                    vs.insert(j, std::mem::take(&mut v));
                }
                break;
            }
            let pcol: &[Entry] = match stored.get(&o) {
                Some(s) => s,
                None => {
                    other.clear();
                    boundary(o, &mut other);
                    normalize(field, &mut other);
                    &other
                }
            };
            let pc = pcol.last().expect("a pivot column is not zero").1;
            let f = field.neg(field.mul(c, field.inv(pc)));
            field.axpy(&col, f, pcol, &mut scratch);
            std::mem::swap(&mut col, &mut scratch);
            if track_v {
                let vo: &[Entry] = vs.get(&o).map(|x| x.as_slice()).unwrap_or(&[]);
                field.axpy(&v, f, vo, &mut vscratch);
                std::mem::swap(&mut v, &mut vscratch);
            }
            changed = true;
        }
    }
    if keep {
        out.reduced = stored;
    }
    if track_v {
        let zero: rustc_hash::FxHashSet<u32> = out.zero.iter().copied().collect();
        vs.retain(|k, _| zero.contains(k));
        out.v = vs;
    }
    out.claimed = owner.iter().map(|&o| o != FREE).collect();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverses_mod_p() {
        for p in [2u32, 3, 5, 7, 2_147_483_647] {
            let f = Zp::new(p);
            for a in 1..p.min(50) {
                assert_eq!(f.mul(a, f.inv(a)), 1, "p = {p}, a = {a}");
            }
        }
    }

    #[test]
    fn a_triangle_boundary_pairs_over_z3() {
        // vertices 0,1,2; edges 0=(0,1), 1=(1,2), 2=(0,2); the last edge closes a loop
        let f = Zp::new(3);
        let edges = [[0u32, 1], [1, 2], [0, 2]];
        let r = reduce_dim(
            f,
            3,
            0..3u32,
            |j, out| {
                let [a, b] = edges[j as usize];
                out.push((a, f.of(-1)));
                out.push((b, 1));
            },
            true,
            true,
        );
        assert_eq!(r.pairs, vec![(1, 0), (2, 1)]);
        assert_eq!(r.zero, vec![2]);
        // V of edge 2: e2 - e1 - e0 (boundary (v2 - v0) - (v2 - v1) - (v1 - v0) = 0)
        assert_eq!(r.v[&2], vec![(0, 2), (1, 2), (2, 1)]);
    }
}
