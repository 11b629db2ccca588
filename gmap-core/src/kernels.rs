//! Tight loops behind the whole-map queries of [`crate::DenseMap`].
//!
//! The involution array is viewed as rows `[u32; W]` with `W = n + 1` fixed at compile
//! time (dimensions 0 to 7 are specialised; larger ones take a generic traversal path), so
//! one row read fetches every `alpha_i` of a dart and the inner loops unroll.
//! - Orbit counts: union-find over one sequential scan of the rows per involution set
//!   (the smaller root wins, paths are halved); the components continue the n-cells'
//!   union-find with the links of `alpha_n`. O(N n α(N)) per set.
//! - Orientability: union-find with parities; big maps are cut in two halves scanned on two
//!   threads, then the links between the halves are merged.
//! - Validity: one fused pass reading each dart's row and its neighbours' rows, checking
//!   ranges, involutions and `alpha_i alpha_j = alpha_j alpha_i` (j >= i + 2); two halves
//!   on two threads.
//!
//! Maps of at least 65,536 darts use two threads when the machine has them.
//!
//! Every kernel expects a map whose links are in range (a validated map); on an invalid map
//! they may panic on an index, never read out of bounds.

use crate::error::{CellDefect, OrientationConflict};
use crate::ids::Dart;
use crate::parallel;
use crate::union_find::{ParitySets, ParityUnionFind, UnionFind};

/// A fixed-size bit set over `0..len`.
pub(crate) struct Bits(Vec<u64>);

impl Bits {
    pub(crate) fn new(len: usize) -> Self {
        Bits(vec![0; len.div_ceil(64)])
    }

    #[inline]
    pub(crate) fn get(&self, i: usize) -> bool {
        (self.0[i >> 6] >> (i & 63)) & 1 != 0
    }

    #[inline]
    pub(crate) fn set(&mut self, i: usize) {
        self.0[i >> 6] |= 1 << (i & 63);
    }

    /// Sets bit `i`; returns its previous value.
    #[inline]
    pub(crate) fn test_and_set(&mut self, i: usize) -> bool {
        let w = &mut self.0[i >> 6];
        let b = 1u64 << (i & 63);
        let old = *w & b != 0;
        *w |= b;
        old
    }

    /// The first clear bit at or after `from`, below `len`.
    #[cfg(test)]
    pub(crate) fn next_clear(&self, from: usize, len: usize) -> Option<usize> {
        let mut k = from >> 6;
        if k >= self.0.len() {
            return None;
        }
        let mut word = !self.0[k] & (!0u64 << (from & 63));
        loop {
            if word != 0 {
                let i = (k << 6) + word.trailing_zeros() as usize;
                return (i < len).then_some(i);
            }
            k += 1;
            if k >= self.0.len() {
                return None;
            }
            word = !self.0[k];
        }
    }
}

/// Calls `$body` with `$rows` bound to the flat array viewed as `[[u32; W]]` for the
/// map's `W`, or with the generic fallback `$generic` for larger widths.
macro_rules! with_width {
    ($a:expr, $w:expr, |$rows:ident| $body:expr, $generic:expr) => {
        with_width!(@arms $a, $w, $rows, $body, $generic; 1 2 3 4 5 6 7 8)
    };
    (@arms $a:expr, $w:expr, $rows:ident, $body:expr, $generic:expr; $($k:literal)*) => {
        match $w {
            $($k => {
                let $rows: &[[u32; $k]] = $a.as_chunks::<$k>().0;
                $body
            })*
            _ => $generic,
        }
    };
}

/// A view of rows of any width, for the generic paths.
#[derive(Clone, Copy)]
struct Dyn<'a> {
    a: &'a [u32],
    w: usize,
}

impl Dyn<'_> {
    #[inline]
    fn row(&self, x: usize) -> &[u32] {
        &self.a[x * self.w..(x + 1) * self.w]
    }
}

/// Number of orbits of the involutions whose bits are set in `mask`, by traversal (the
/// reference the union-find counter is tested against).
#[cfg(test)]
fn count_rows<const W: usize>(rows: &[[u32; W]], mask: u32) -> usize {
    let n = rows.len();
    let mut seen = Bits::new(n);
    let mut stack: Vec<u32> = Vec::with_capacity(1024);
    let mut count = 0;
    let mut d = 0;
    while let Some(s) = seen.next_clear(d, n) {
        d = s + 1;
        count += 1;
        seen.set(s);
        stack.push(s as u32);
        while let Some(x) = stack.pop() {
            let row = &rows[x as usize];
            for (i, &y) in row.iter().enumerate() {
                if mask & (1 << i) != 0 && !seen.test_and_set(y as usize) {
                    stack.push(y);
                }
            }
        }
    }
    count
}

fn count_dyn(m: Dyn<'_>, mask: u32) -> usize {
    let n = m.a.len() / m.w;
    let mut seen = Bits::new(n);
    let mut stack: Vec<u32> = Vec::new();
    let mut count = 0;
    for d in 0..n {
        if seen.get(d) {
            continue;
        }
        count += 1;
        seen.set(d);
        stack.push(d as u32);
        while let Some(x) = stack.pop() {
            for (i, &y) in m.row(x as usize).iter().enumerate() {
                if mask & (1 << i) != 0 && !seen.test_and_set(y as usize) {
                    stack.push(y);
                }
            }
        }
    }
    count
}

/// Number of orbits by union-find over one sequential scan of the rows: each link
/// `d -> alpha_i(d)` with `alpha_i(d) > d` merges two classes, the smaller root becoming the
/// root. Reading rows in order and, for most maps, their partners in runs, it touches
/// memory far more predictably than a traversal.
fn count_rows_uf<const W: usize>(rows: &[[u32; W]], mask: u32) -> usize {
    let mut uf = UnionFind::new(rows.len());
    uf_scan(rows, mask, &mut uf, rows.len())
}

/// The orbit counts of `mask` and of `mask | extra`: the second continues the union-find of
/// the first with the links of `extra` only.
fn count_rows_uf_then<const W: usize>(rows: &[[u32; W]], mask: u32, extra: u32) -> (usize, usize) {
    let mut uf = UnionFind::new(rows.len());
    let first = uf_scan(rows, mask, &mut uf, rows.len());
    let second = uf_scan(rows, extra & !mask, &mut uf, first);
    (first, second)
}

/// One union-find scan over the links of `mask`, starting from `roots` classes.
fn uf_scan<const W: usize>(rows: &[[u32; W]], mask: u32, uf: &mut UnionFind, mut roots: usize) -> usize {
    for (d, row) in rows.iter().enumerate() {
        // the root of d, found at its first link to a later dart and kept up to date
        let mut a = u32::MAX;
        for (i, &e) in row.iter().enumerate() {
            if mask & (1 << i) != 0 && e as usize > d {
                if a == u32::MAX {
                    a = uf.find(d as u32);
                }
                let b = uf.find(e);
                if a != b {
                    a = uf.link_roots(a, b);
                    roots -= 1;
                }
            }
        }
    }
    roots
}

/// The `<mask>`-orbits by one union-find scan of the rows ([`uf_scan`]): each dart's orbit
/// number, orbits numbered in order of smallest dart, and those smallest darts; `None` for
/// the widths without a specialised path (the caller traverses). O(N |mask| α(N)).
pub(crate) fn partition(a: &[u32], w: usize, mask: u32) -> Option<(Vec<u32>, Vec<Dart>)> {
    with_width!(
        a,
        w,
        |rows| {
            let mut uf = UnionFind::new(rows.len());
            uf_scan(rows, mask, &mut uf, rows.len());
            let (of, k) = uf.labels();
            let mut reps = Vec::with_capacity(k);
            for (d, &c) in of.iter().enumerate() {
                if c as usize == reps.len() {
                    reps.push(Dart::new(d as u32));
                }
            }
            Some((of, reps))
        },
        None
    )
}

/// Number of orbits of the involution set `mask` (bits of indices `< w`).
pub(crate) fn count_orbits(a: &[u32], w: usize, mask: u32) -> usize {
    with_width!(a, w, |rows| count_rows_uf(rows, mask), count_dyn(Dyn { a, w }, mask))
}

/// Orbit counts for several involution sets, the sets handed out to the threads of
/// [`parallel::map_tasks`] (one union-find scan per set).
pub(crate) fn count_orbits_many(a: &[u32], w: usize, masks: &[u32]) -> Vec<usize> {
    parallel::map_tasks(masks.len(), a.len() / w.max(1), |k| count_orbits(a, w, masks[k]))
}

/// The numbers of cells of every dimension `0..=n` (`w = n + 1`) and of connected
/// components. The n-cells' union-find is continued with the links of `alpha_n` to give the
/// components, so the rows are scanned n + 1 times plus one light scan; the n + 1 scans
/// are shared among the threads of [`parallel::map_tasks`].
pub(crate) fn counts_and_components(a: &[u32], w: usize) -> (Vec<usize>, usize) {
    let n = w - 1;
    let all = if w >= 32 { u32::MAX } else { (1u32 << w) - 1 };
    let cell = |i: usize| all & !(1u32 << i);
    // task 0: the n-cells, continued into the components; task k > 0: the (k-1)-cells
    let task = |k: usize| -> (usize, usize) {
        if k == 0 {
            with_width!(a, w, |rows| count_rows_uf_then(rows, cell(n), all), {
                (count_dyn(Dyn { a, w }, cell(n)), count_dyn(Dyn { a, w }, all))
            })
        } else {
            (count_orbits(a, w, cell(k - 1)), 0)
        }
    };
    let results = parallel::map_tasks(w, a.len() / w, task);
    let mut counts = vec![0usize; w];
    let mut components = 0;
    for (k, (c, comps)) in results.into_iter().enumerate() {
        if k == 0 {
            counts[n] = c;
            components = comps;
        } else {
            counts[k - 1] = c;
        }
    }
    (counts, components)
}

/// Whether every link is in range, every `alpha_i` an involution, and `alpha_i alpha_j =
/// alpha_j alpha_i` for `j >= i + 2` (equivalent to BO Def. 1 once the `alpha_i` are
/// involutions), on darts `lo..hi`.
// index loops over the small fixed width read more plainly than iterator chains here
#[allow(clippy::needless_range_loop)]
fn valid_rows<const W: usize>(rows: &[[u32; W]], lo: usize, hi: usize) -> bool {
    let n = rows.len();
    for (d, row) in rows[lo..hi].iter().enumerate() {
        let d = d + lo;
        let mut nb = [[0u32; W]; W];
        for i in 0..W {
            let e = row[i] as usize;
            if e >= n {
                return false;
            }
            nb[i] = rows[e];
            if nb[i][i] as usize != d {
                return false;
            }
        }
        for i in 0..W {
            for j in i + 2..W {
                if nb[i][j] != nb[j][i] {
                    return false;
                }
            }
        }
    }
    true
}

fn valid_dyn(m: Dyn<'_>, lo: usize, hi: usize) -> bool {
    let n = m.a.len() / m.w;
    for d in lo..hi {
        let row = m.row(d);
        for (i, &e) in row.iter().enumerate() {
            if e as usize >= n || m.row(e as usize)[i] as usize != d {
                return false;
            }
        }
        for i in 0..m.w {
            for j in i + 2..m.w {
                if m.row(row[i] as usize)[j] != m.row(row[j] as usize)[i] {
                    return false;
                }
            }
        }
    }
    true
}

/// The fast all-or-nothing validity check (BO Def. 1), the darts cut into one range per
/// thread.
pub(crate) fn is_valid(a: &[u32], w: usize) -> bool {
    let n = a.len() / w;
    let check =
        |lo: usize, hi: usize| with_width!(a, w, |rows| valid_rows(rows, lo, hi), valid_dyn(Dyn { a, w }, lo, hi));
    let ranges = parallel::split_ranges(n, parallel::threads_for(n, usize::MAX));
    parallel::map_tasks(ranges.len(), n, |k| check(ranges[k].start, ranges[k].end)).into_iter().all(|ok| ok)
}

/// Orientation colours (BO Def. 7, 8): 1 for the positive class, 2 for the negative, the
/// smallest dart of each component positive; or the first conflict `(dart, alpha, other)`
/// in traversal order.
fn orient_rows<const W: usize>(rows: &[[u32; W]]) -> Result<Vec<u8>, OrientationConflict> {
    let n = rows.len();
    let mut col = vec![0u8; n];
    let mut stack: Vec<u32> = Vec::with_capacity(1024);
    for d in 0..n {
        if col[d] != 0 {
            continue;
        }
        col[d] = 1;
        stack.push(d as u32);
        while let Some(x) = stack.pop() {
            let c = col[x as usize];
            let other = 3 - c;
            for (i, &y) in rows[x as usize].iter().enumerate() {
                if y == x {
                    continue;
                }
                let cy = col[y as usize];
                if cy == 0 {
                    col[y as usize] = other;
                    stack.push(y);
                } else if cy == c {
                    return Err(OrientationConflict { dart: Dart::new(x), alpha: i, other: Dart::new(y) });
                }
            }
        }
    }
    Ok(col)
}

fn orient_dyn(m: Dyn<'_>) -> Result<Vec<u8>, OrientationConflict> {
    let n = m.a.len() / m.w;
    let mut col = vec![0u8; n];
    let mut stack: Vec<u32> = Vec::new();
    for d in 0..n {
        if col[d] != 0 {
            continue;
        }
        col[d] = 1;
        stack.push(d as u32);
        while let Some(x) = stack.pop() {
            let c = col[x as usize];
            for (i, &y) in m.row(x as usize).iter().enumerate() {
                if y == x {
                    continue;
                }
                let cy = col[y as usize];
                if cy == 0 {
                    col[y as usize] = 3 - c;
                    stack.push(y);
                } else if cy == c {
                    return Err(OrientationConflict { dart: Dart::new(x), alpha: i, other: Dart::new(y) });
                }
            }
        }
    }
    Ok(col)
}

/// i-cells oriented as compacted cells (condition C1): `(of, reps, positive words)`, cells
/// numbered by smallest dart, that dart positive; or the first defect in traversal order.
/// One depth-first traversal; `row(x)` gives the links of dart `x` (a fixed-width row on the
/// specialised paths). The colours are written straight into the returned bit words.
#[allow(clippy::type_complexity)]
pub(crate) fn oriented_by<'a>(
    n: usize,
    row: impl Fn(usize) -> &'a [u32],
    i: usize,
) -> Result<(Vec<u32>, Vec<Dart>, Vec<usize>), CellDefect> {
    let bits = usize::BITS as usize;
    let mut pos = vec![0usize; n.div_ceil(bits)];
    let get = |pos: &[usize], x: usize| pos[x / bits] >> (x % bits) & 1 == 1;
    let mut of = vec![u32::MAX; n];
    let mut reps: Vec<Dart> = Vec::new();
    let mut stack: Vec<u32> = Vec::with_capacity(1024);
    for d in 0..n {
        if of[d] != u32::MAX {
            continue;
        }
        let id = reps.len() as u32;
        reps.push(Dart::new(d as u32));
        of[d] = id;
        pos[d / bits] |= 1 << (d % bits);
        stack.push(d as u32);
        while let Some(x) = stack.pop() {
            let cx = get(&pos, x as usize);
            for (k, &y) in row(x as usize).iter().enumerate() {
                if k == i {
                    continue;
                }
                if k < i && y == x {
                    return Err(CellDefect::IncompleteBoundary { dim: i, dart: Dart::new(d as u32), alpha: k });
                }
                let want = if k < i { !cx } else { cx };
                let yu = y as usize;
                if of[yu] == u32::MAX {
                    of[yu] = id;
                    pos[yu / bits] |= usize::from(want) << (yu % bits);
                    stack.push(y);
                } else if get(&pos, yu) != want {
                    return Err(CellDefect::NotOrientable {
                        dim: i,
                        dart: Dart::new(d as u32),
                        alpha: k,
                        at: Dart::new(x),
                    });
                }
            }
        }
    }
    Ok((of, reps, pos))
}

/// The i-cells oriented as compacted cells, as [`oriented_by`] gives them, by a union-find
/// with parities over one sequential scan of the rows: every link `d -> alpha_k(d)`,
/// `k != i`, to a later dart demands opposite colours for `k < i` and equal ones for
/// `k > i`. The smaller root wins a merge, so the root of a class is its smallest dart;
/// a second scan numbers the cells at their roots (in order of smallest dart) and colours
/// each dart by its parity to the root (the root positive). Unlike a traversal, which
/// follows every link of a dart wherever it leads, the scan reads the rows in order and
/// most links (those inside one n-cell, stored together by the builders and importers)
/// stay close by. `None` on a defect (a dart free for some `k < i`, a colouring
/// conflict): the traversal then names it. O(N n α(N)).
fn oriented_scan<const W: usize>(rows: &[[u32; W]], i: usize) -> Option<(Vec<u32>, Vec<Dart>, Vec<usize>)> {
    let n = rows.len();
    let mut uf = ParityUnionFind::new(n);
    let mut sets = uf.view();
    for (d, row) in rows.iter().enumerate() {
        let d32 = d as u32;
        // the root of d and d's parity to it, found at d's first link to a later dart and
        // kept up to date as classes merge
        let mut root: Option<(u32, bool)> = None;
        for (k, &e) in row.iter().enumerate() {
            if k == i {
                continue;
            }
            if e == d32 {
                if k < i {
                    return None;
                }
                continue;
            }
            if e < d32 {
                continue;
            }
            let (a, fa) = *root.get_or_insert_with(|| sets.find(d32));
            let (b, fb) = sets.find(e);
            let flip = k < i;
            if a == b {
                if fa ^ fb != flip {
                    return None;
                }
                continue;
            }
            root = Some(sets.link_roots(a, b, fa ^ fb ^ flip, fa));
        }
    }
    let bits = usize::BITS as usize;
    let mut pos = vec![0usize; n.div_ceil(bits)];
    let mut of = vec![0u32; n];
    let mut reps: Vec<Dart> = Vec::new();
    for d in 0..n {
        let (root, flip) = uf.find(d as u32);
        if root as usize == d {
            of[d] = reps.len() as u32;
            reps.push(Dart::new(root));
        } else {
            of[d] = of[root as usize];
        }
        pos[d / bits] |= usize::from(!flip) << (d % bits);
    }
    Some((of, reps, pos))
}

/// [`oriented_by`] on the rows of the flat involution array, specialised by width: the
/// sequential scan of [`oriented_scan`] first, the traversal when it finds a defect (so the
/// defect reported is the traversal's).
#[allow(clippy::type_complexity)]
pub(crate) fn oriented_cells(a: &[u32], w: usize, i: usize) -> Result<(Vec<u32>, Vec<Dart>, Vec<usize>), CellDefect> {
    let n = a.len() / w.max(1);
    with_width!(a, w, |rows| oriented_scan(rows, i).map_or_else(|| oriented_by(n, |x| &rows[x][..], i), Ok), {
        let m = Dyn { a, w };
        oriented_by(n, |x| m.row(x), i)
    })
}

/// One half of the orientability scan: the links `d -> e`, `e > d`, of darts `lo..hi`,
/// with the union-find range of darts `lo..hi`. Links leaving the range
/// (`e >= hi`) are returned for the merge. `None` on a conflict.
fn orient_range<const W: usize>(
    rows: &[[u32; W]],
    lo: usize,
    hi: usize,
    mut uf: ParitySets<'_>,
) -> Option<Vec<(u32, u32)>> {
    let mut cross = Vec::new();
    for (k, row) in rows[lo..hi].iter().enumerate() {
        let d = (lo + k) as u32;
        for &e in row.iter() {
            if e <= d {
                continue;
            }
            if e as usize >= hi {
                cross.push((d, e));
            } else if !uf.join(d, e, true) {
                return None;
            }
        }
    }
    Some(cross)
}

/// Whether the map is orientable (BO Def. 7): a union-find with parities over sequential
/// scans, each non-fixed link `d -> alpha_i(d)` demanding opposite classes. Big maps are
/// cut into one range of darts per thread, then the links between ranges are merged.
fn orientable_rows<const W: usize>(rows: &[[u32; W]]) -> bool {
    let n = rows.len();
    let mut uf = ParityUnionFind::new(n);
    let ranges = parallel::split_ranges(n, parallel::threads_for(n, usize::MAX));
    let lens: Vec<usize> = ranges.iter().map(|r| r.len()).collect();
    let parts: Vec<_> = ranges.into_iter().zip(uf.split_mut(&lens)).collect();
    let crosses = parallel::map_parts(parts, |(r, sets)| orient_range(rows, r.start, r.end, sets));
    let mut cross = Vec::new();
    for c in crosses {
        match c {
            Some(c) => cross.extend(c),
            None => return false,
        }
    }
    cross.into_iter().all(|(d, e)| uf.join(d, e, true))
}

/// Whether the map is orientable, by [`orientable_rows`] (or a traversal for large widths).
pub(crate) fn is_orientable(a: &[u32], w: usize) -> bool {
    with_width!(a, w, |rows| orientable_rows(rows), orient_dyn(Dyn { a, w }).is_ok())
}

/// See [`orient_rows`].
pub(crate) fn orientation(a: &[u32], w: usize) -> Result<Vec<u8>, OrientationConflict> {
    with_width!(a, w, |rows| orient_rows(rows), orient_dyn(Dyn { a, w }))
}

#[cfg(test)]
mod tests;
