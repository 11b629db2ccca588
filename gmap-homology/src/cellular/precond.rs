//! Conditions C1 and C2 under which the cellular border operator gives the true homology
//! (`docs/DESIGN.md`, "When cellular homology is right").
//!
//! * **C1**: every i-cell is orientable as a compacted cell — a colouring of its darts
//!   that `alpha_k` flips for `k < i` and `alpha_j` keeps for `j > i` (so no dart is
//!   k-free for `k < i`, and no cell is folded onto itself).
//! * **C2**: the compacted i-cell, the (i-1)-map on `B_i` with `alpha^i_0..alpha^i_{i-1}`
//!   (BO Def. 3), has the integer homology of the (i-1)-sphere. Under C1 this holds by
//!   itself for `i <= 2` (two ends; a polygon); for `i = 3` the compacted cell is a closed
//!   orientable connected surface, a sphere exactly when its Euler characteristic is 2; for
//!   `i >= 4` the homology of the compacted cell is computed, by its own cells when C1 and
//!   C2 hold on them, else by the simplicial method. Isomorphic compacted cells share one
//!   computation.
//! * **No self-bending** (BO Def. 6, part 2): no cell is folded onto itself. C1 catches the
//!   folds that reverse a cell's orientation; a fold that keeps it (a square face of a
//!   volume sewn to itself by a half-turn) passes C1 and C2 and is refused by
//!   [`check_self_bending`], run once C1 and C2 hold.

use std::sync::atomic::{AtomicUsize, Ordering};

use gmap_core::{parallel, AlphaSet, BoundaryDefect, CellDefect, Dart, DenseMap, Partition};
use rustc_hash::FxHashSet;
use thiserror::Error;

use crate::cellular::border::border_from_oriented;
pub use crate::cellular::oriented::{oriented_cells, OrientedCells};
use crate::cellular::simplicial::simplicial_complex;
use crate::engine::homology::{homology_z, Homology, HomologyError};

/// A cell on which the cellular method does not apply.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum PreconditionError {
    /// Condition C1 fails: the cell is not orientable as a compacted cell, or its boundary
    /// is open (the kernel's message names the cell and the condition).
    #[error(transparent)]
    C1(#[from] CellDefect),
    /// Condition C2 fails: the boundary of the cell is not a homology sphere.
    #[error("the {dim}-cell of dart {dart} is not bounded by a sphere: its boundary has {found} (condition C2: every cell bounded by a homology sphere)")]
    C2 {
        /// dimension of the cell
        dim: usize,
        /// the smallest dart of the cell
        dart: Dart,
        /// what the boundary has instead: `Euler characteristic 0`, `homology (Z, Z^2, Z)`,
        /// or `no computable homology (…)`
        found: String,
    },
    /// A cell is folded onto itself (BO Def. 6, part 2: no self-bending); the defect names
    /// the cell, its dimension and the two darts where its orbits meet.
    #[error(transparent)]
    SelfBending(BoundaryDefect),
}

/// Checks C2 for the i-cells of `map` (C1 assumed, as checked by [`oriented_cells`]).
/// O(N) for a 3-map; in higher dimensions, one walk of `B_i` plus the homology of one
/// compacted cell per isomorphism class (walked breadth-first from its smallest dart).
pub fn check_c2(map: &DenseMap, cells: &OrientedCells) -> Result<(), PreconditionError> {
    let i = cells.dim;
    let n = map.dim();
    if i <= 2 {
        return Ok(());
    }
    if i == 3 && n == 3 {
        // a 3-cell of a 3-map is its own compacted cell: count its dihedral orbits in place
        let chi = chi_of_volumes(map, cells);
        return check_chi(&chi, &cells.cells.reps);
    }
    c2_by_classes(map, cells)
}

/// C2 for `i >= 3` in a map of dimension above 3, one isomorphism class of compacted cells
/// at a time.
///
/// Each compacted i-cell is walked breadth-first over `B_i` from the element holding the
/// cell's smallest dart, numbering elements in the order met; the induced involutions in
/// that numbering are an (i-1)-map, and equal arrays mean isomorphic cells (the array is
/// the cell up to renaming its elements). Its homology is computed once per distinct array:
/// for `i = 3` the Euler characteristic of the surface; above, the cellular homology of the
/// small map when C1 and C2 hold on it (checked by this same function one dimension down),
/// else its simplicial homology. A triangulated manifold has one class per dimension, so the
/// check costs one walk of `B_i`. Cells are taken in order of smallest dart and the first
/// failing one is reported, so the verdict is the one a cell-by-cell check gives.
/// O(|B_i| i) plus the homology of one cell per class.
fn c2_by_classes(map: &DenseMap, cells: &OrientedCells) -> Result<(), PreconditionError> {
    let i = cells.dim;
    let n = map.dim();
    let w = n + 1;
    let a = map.flat();
    // B_i, the <alpha_{i+1..n}>-orbits: for i = n every dart is its own element, for
    // i = n - 1 an alpha_n-pair named by its smaller dart; below, a partition
    let part = (i + 1 < n).then(|| map.partition(AlphaSet::above(i, n)));
    let elem = |d: u32| match &part {
        Some(p) => p.of[d as usize],
        None if i == n => d,
        None => d.min(a[d as usize * w + n]),
    };
    let rep = |e: u32| part.as_ref().map_or(e, |p| p.reps[e as usize].get());
    let size = part.as_ref().map_or(map.dart_count(), Partition::len);
    let mut local = vec![u32::MAX; size];
    let mut order: Vec<u32> = Vec::new();
    let mut code: Vec<u32> = Vec::new();
    let mut spheres: FxHashSet<Vec<u32>> = FxHashSet::default();
    // the last class found a sphere: neighbouring cells are often of the same class
    let mut last: Vec<u32> = Vec::new();
    for r in cells.cells.reps.iter().map(|d| d.get()) {
        let start = elem(r);
        order.clear();
        code.clear();
        local[start as usize] = 0;
        order.push(start);
        let mut k = 0;
        while k < order.len() {
            let x = rep(order[k]) as usize;
            k += 1;
            for &y in &a[x * w..x * w + i] {
                let f = elem(y) as usize;
                if local[f] == u32::MAX {
                    local[f] = order.len() as u32;
                    order.push(f as u32);
                }
                code.push(local[f]);
            }
        }
        for &e in &order {
            local[e as usize] = u32::MAX;
        }
        if code == last {
            continue;
        }
        if spheres.contains(&code) {
            std::mem::swap(&mut last, &mut code);
            continue;
        }
        let fail = |found: String| PreconditionError::C2 { dim: i, dart: Dart::new(r), found };
        let sub = DenseMap::from_flat_unchecked(i - 1, code.clone())
            .map_err(|e| fail(format!("no computable homology ({e})")))?;
        if i == 3 {
            let counts = sub.cell_counts();
            let chi = counts[0] as i64 - counts[1] as i64 + counts[2] as i64;
            if chi != 2 {
                return Err(fail(format!("Euler characteristic {chi}")));
            }
        } else {
            let h = cell_homology(&sub).map_err(|e| fail(format!("no computable homology ({e})")))?;
            if !is_sphere(&h, i - 1) {
                return Err(fail(format!("homology {h}")));
            }
        }
        spheres.insert(code.clone());
        std::mem::swap(&mut last, &mut code);
    }
    Ok(())
}

/// The integer homology of a compacted cell given as a closed map: by its own cells when
/// C1 and C2 hold on them (a handful of cells instead of one simplex per dart), else by the
/// simplicial counterpart.
fn cell_homology(sub: &DenseMap) -> Result<Homology, HomologyError> {
    match check_by_dimension(sub) {
        Ok(oriented) => homology_z(&border_from_oriented(sub, &oriented).chain),
        Err(_) => homology_z(&simplicial_complex(sub)),
    }
}

/// C2 for 3-cells: each compacted cell, a closed orientable surface under C1, must have
/// Euler characteristic 2.
pub(crate) fn check_chi(chi: &[i64], reps: &[Dart]) -> Result<(), PreconditionError> {
    match chi.iter().position(|&x| x != 2) {
        None => Ok(()),
        Some(c) => {
            Err(PreconditionError::C2 { dim: 3, dart: reps[c], found: format!("Euler characteristic {}", chi[c]) })
        }
    }
}

/// Euler characteristic of each volume of a 3-map (C1 holds: `alpha_0..alpha_2` have no fixed
/// point): its corners (`<alpha_1, alpha_2>`-cycles) minus its edge sides (`<alpha_0,
/// alpha_2>`-orbits of four darts, counted at their smallest dart) plus its face sides
/// (`<alpha_0, alpha_1>`-cycles). Every orbit stays inside one volume, so the walks are
/// local in memory. The three counts are tasks of [`parallel::map_tasks`], each with a bit
/// per dart. O(N).
pub(crate) fn chi_of_volumes(map: &DenseMap, cells: &OrientedCells) -> Vec<i64> {
    let a = map.flat();
    let n = map.dart_count();
    let of = &cells.cells.of;
    let count = |task: usize| {
        let mut chi = vec![0i64; cells.cells.len()];
        if task == 0 {
            for (d, row) in a.chunks_exact(4).enumerate() {
                let d32 = d as u32;
                let (a0, a2) = (row[0], row[2]);
                let a02 = a[a2 as usize * 4];
                if d32 <= a0 && d32 <= a2 && d32 <= a02 {
                    chi[of[d] as usize] -= 1;
                }
            }
            return chi;
        }
        let (p, q) = if task == 1 { (1, 2) } else { (0, 1) };
        let mut seen = vec![0u64; n.div_ceil(64)];
        for d in 0..n {
            if seen[d >> 6] & (1 << (d & 63)) != 0 {
                continue;
            }
            chi[of[d] as usize] += 1;
            let mut x = d;
            loop {
                seen[x >> 6] |= 1 << (x & 63);
                let y = a[x * 4 + p] as usize;
                seen[y >> 6] |= 1 << (y & 63);
                x = a[y * 4 + q] as usize;
                if x == d {
                    break;
                }
            }
        }
        chi
    };
    let parts = parallel::map_tasks(3, n, count);
    let mut chi = vec![0i64; cells.cells.len()];
    for part in parts {
        chi.iter_mut().zip(part).for_each(|(c, p)| *c += p);
    }
    chi
}

/// No self-bending in a 3-map whose cells satisfy C1, from its faces: C1 on the edges
/// already keeps `alpha_0(d)` out of the `<alpha_2, alpha_3>`-orbit of `d` (the two have
/// opposite colours in their edge), so the one fold left is a face whose
/// `<alpha_0, alpha_1>`-ring `alpha_3` maps onto itself: one ring walk per face, from its
/// smallest dart, faces shared among threads. Where a face is folded, the error is that of
/// [`check_self_bending`]. O(N), no memory beyond the faces.
pub(crate) fn check_faces_unfolded(map: &DenseMap, faces: &OrientedCells) -> Result<(), PreconditionError> {
    let rows: &[[u32; 4]] = map.flat().as_chunks::<4>().0;
    let folded = |r: u32| {
        let a3 = rows[r as usize][3];
        if a3 == r {
            return false;
        }
        let mut x = r;
        loop {
            let y = rows[x as usize][0];
            if x == a3 || y == a3 {
                return true;
            }
            x = rows[y as usize][1];
            if x == r {
                return false;
            }
        }
    };
    let reps = &faces.cells.reps;
    let parts = parallel::split_ranges(reps.len(), parallel::threads_for(map.dart_count(), usize::MAX));
    let any = parallel::map_parts(parts, |range| reps[range].iter().any(|d| folded(d.get())));
    if any.into_iter().any(|f| f) {
        check_self_bending(map)?;
        debug_assert!(false, "a folded face is a self-bending");
    }
    Ok(())
}

/// Whether `h` is the integer homology of the m-sphere.
fn is_sphere(h: &Homology, m: usize) -> bool {
    h.betti.len() == m + 1
        && h.torsion.iter().all(Vec::is_empty)
        && h.betti.iter().enumerate().all(|(k, &b)| b == usize::from(k == 0 || k == m) + usize::from(m == 0 && k == 0))
}

/// Checks that no cell is folded onto itself (BO Def. 6, part 2), through
/// [`DenseMap::check_no_self_bending`]. O(N n^2).
pub fn check_self_bending(map: &DenseMap) -> Result<(), PreconditionError> {
    map.check_no_self_bending().map_err(PreconditionError::SelfBending)
}

/// Checks C1 and C2 for every dimension, then that no cell is folded onto itself
/// ([`check_self_bending`]), returning the oriented cells of each dimension.
///
/// 3-maps go through [`DenseMap::oriented_cells_3d`] (rings inside volumes glued by
/// `alpha_3`, C2 from the Euler characteristic of each volume); when that finds a cell of
/// another shape, and for other dimensions, [`check_by_dimension`] runs and names the
/// failing cell. The result, cells or error, is the same either way. O(N n) below
/// dimension 4.
pub fn check_preconditions(map: &DenseMap) -> Result<Vec<OrientedCells>, PreconditionError> {
    if let Some(all) = map.oriented_cells_3d() {
        // 3-maps whose cells have the shapes of the ring walks: C1 holds in every dimension,
        // C2 is the Euler characteristic of each volume
        let cells: Vec<OrientedCells> = all
            .cells
            .into_iter()
            .enumerate()
            .map(|(dim, (cells, positive))| OrientedCells { dim, cells, positive })
            .collect();
        check_chi(&all.euler, &cells[3].cells.reps)?;
        check_faces_unfolded(map, &cells[2])?;
        return Ok(cells);
    }
    check_by_dimension(map)
}

/// [`check_preconditions`] by one traversal per dimension ([`oriented_cells`] and
/// [`check_c2`]), then [`check_self_bending`]: the reference for the ring walks of 3-maps.
///
/// The dimensions are checked as separate tasks on the threads `gmap_core::parallel` allows
/// (maps of at least 65,536 darts); the error reported is the same as in order: the lowest
/// failing dimension, C1 before C2.
pub fn check_by_dimension(map: &DenseMap) -> Result<Vec<OrientedCells>, PreconditionError> {
    let n = map.dim();
    let check = |i: usize| -> Result<OrientedCells, PreconditionError> {
        let c = oriented_cells(map, i)?;
        check_c2(map, &c)?;
        Ok(c)
    };
    // one task per dimension; a dimension above one that already failed is skipped, since
    // the lowest failing dimension is the one reported
    let failed = AtomicUsize::new(usize::MAX);
    let results = parallel::map_tasks(n + 1, map.dart_count(), |i| {
        if failed.load(Ordering::Relaxed) < i {
            return None;
        }
        let r = check(i);
        if r.is_err() {
            failed.fetch_min(i, Ordering::Relaxed);
        }
        Some(r)
    });
    let mut out = Vec::with_capacity(n + 1);
    for r in results {
        out.push(r.expect("a dimension is skipped only above a failed one, reported before it")?);
    }
    check_self_bending(map)?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn oriented_cells_match_the_kernel() {
        for m in [gmap_core::examples::cylinder(), gmap_core::examples::klein_bottle(), gmap_core::examples::torus()] {
            for i in 0..=2 {
                let c = oriented_cells(&m, i).unwrap();
                assert_eq!(c.cells, m.cells(i));
                assert_eq!(c.positive, m.cell_orientation(i).unwrap());
            }
        }
    }
}
