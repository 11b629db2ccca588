//! Incidence numbers between an i-cell and an (i-1)-cell (BO Def. 5 and 9), pair by pair.
//!
//! Both are read off the face operator `∂_i : B_i → B_{i-1}` (BO Def. 4): take the element
//! `f = <alpha_i..alpha_n>(d')` of `B_{i-1}` holding a dart `d'` of the (i-1)-cell, and look
//! at its preimage. The **unsigned** number counts the preimage elements lying in the i-cell
//! (every one of them: a vertex twice on a loop edge counts 2). The **signed** number adds,
//! for each such element `e`, `+1` when `e` and `d'` are in the same orientation class of
//! their compacted cells and `-1` otherwise. Both are independent of the darts chosen
//! (BO Properties 1 and 3).
//!
//! [`Incidence`] answers pair by pair through the kernel's face operator; it is the
//! reference the whole-map computations are tested against. [`incidence_terms`] lists the
//! terms of BO Def. 9 for every pair at once, by one orbit walk per (i-1)-cell: the border
//! operator ([`crate::cellular::border`]) sums them where it has no local formula, and the
//! architectural complex of a map (`crate::complex::arch`) counts them by sign.

use bitvec::vec::BitVec;
use gmap_core::{CellDefect, CompactedCells, Dart, DenseMap, FaceOperator};

use crate::cellular::oriented::{oriented_cells, OrientedCells};

/// The face operator between dimensions i and i-1 of a map, with what is needed to answer
/// incidence questions. Building it is O(N n); each query is O(size of one preimage).
#[derive(Clone, Debug)]
pub struct Incidence {
    dim: usize,
    upper: CompactedCells,
    lower: CompactedCells,
    face: FaceOperator,
}

impl Incidence {
    /// Prepares incidence queries between i-cells and (i-1)-cells (`1 <= i <= n`).
    /// Panics if `i` is out of that range; see [`Incidence::try_new`].
    pub fn new(map: &DenseMap, i: usize) -> Self {
        Self::try_new(map, i).expect("1 <= i <= n")
    }

    /// Like [`Incidence::new`], or `None` when `i` is 0 or above the map's dimension.
    pub fn try_new(map: &DenseMap, i: usize) -> Option<Self> {
        if i == 0 || i > map.dim() {
            return None;
        }
        let upper = CompactedCells::new(map, i);
        let lower = CompactedCells::new(map, i - 1);
        let face = FaceOperator::new(&upper, &lower);
        Some(Incidence { dim: i, upper, lower, face })
    }

    /// The dimension i of the upper cells.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The elements of `B_i` in the preimage of the `B_{i-1}` element of `face_dart` that lie
    /// in the i-cell of `cell_dart`.
    fn inside(&self, cell_dart: Dart, face_dart: Dart) -> impl Iterator<Item = u32> + '_ {
        let cell = self.upper.cell_of[self.upper.orbits.of[cell_dart.index()] as usize];
        let f = self.lower.orbits.of[face_dart.index()];
        self.face.preimage(f).iter().copied().filter(move |&e| self.upper.cell_of[e as usize] == cell)
    }

    /// The unsigned incidence number `(C_i(cell_dart) : C_{i-1}(face_dart))` (BO Def. 5).
    pub fn unsigned(&self, cell_dart: Dart, face_dart: Dart) -> usize {
        self.inside(cell_dart, face_dart).count()
    }

    /// The signed incidence number (BO Def. 9) for given orientations of the i-cells
    /// (`upper`) and (i-1)-cells (`lower`), as produced by [`oriented_cells`].
    pub fn signed_with(&self, upper: &OrientedCells, lower: &OrientedCells, cell_dart: Dart, face_dart: Dart) -> i64 {
        let s = lower.sign(face_dart.get());
        self.inside(cell_dart, face_dart).map(|e| upper.sign(self.upper.orbits.reps[e as usize].get()) * s).sum()
    }

    /// The signed incidence number (BO Def. 9) with the orientation in which the smallest
    /// dart of every cell is positive; fails if a cell of dimension i or i-1 violates C1.
    pub fn signed(&self, map: &DenseMap, cell_dart: Dart, face_dart: Dart) -> Result<i64, CellDefect> {
        let upper = oriented_cells(map, self.dim)?;
        let lower = oriented_cells(map, self.dim - 1)?;
        Ok(self.signed_with(&upper, &lower, cell_dart, face_dart))
    }
}

/// The terms of BO Def. 9 for all i-cells and (i-1)-cells at once (`i = upper.dim`): for
/// each (i-1)-cell, the element of `B_{i-1}` (a `<alpha_i..alpha_n>`-orbit) holding its
/// smallest dart is walked once, and each element `e` of `B_i` met there gives a term
/// `((i-1)-cell, i-cell of e, sign_i(e) · sign_{i-1})`, in order of the (i-1)-cells.
///
/// Summed per pair the terms are the signed incidence numbers, counted the unsigned ones;
/// every adherent pair has a term (an i-cell meeting an (i-1)-cell meets each of its
/// elements of `B_{i-1}`, since `alpha_0..alpha_{i-2}` carry these elements onto one
/// another inside both cells). Both cells oriented as compacted cells (C1). The elements
/// of `B_i` are found inside each walked orbit, so no whole-map partition is needed.
/// O(N n).
pub fn incidence_terms(map: &DenseMap, upper: &OrientedCells, lower: &OrientedCells) -> Vec<(u32, u32, i64)> {
    let i = upper.dim;
    assert_eq!(lower.dim + 1, i, "incidences between consecutive dimensions");
    let n = map.dim();
    let w = n + 1;
    let a = map.flat();
    // `seen`: darts of the orbit being walked; `met`: darts of the elements of B_i already
    // counted in it. Both are cleared after each orbit, so every walk stays local.
    let mut seen: BitVec = BitVec::repeat(false, map.dart_count());
    let mut met: BitVec = BitVec::repeat(false, map.dart_count());
    let mut orbit: Vec<u32> = Vec::new();
    let mut element: Vec<u32> = Vec::new();
    let mut out = Vec::new();
    for (row, d0) in lower.cells.reps.iter().map(|d| d.get()).enumerate() {
        orbit.clear();
        orbit.push(d0);
        seen.set(d0 as usize, true);
        let mut k = 0;
        while k < orbit.len() {
            let x = orbit[k] as usize;
            k += 1;
            for j in i..w {
                let y = a[x * w + j];
                if !seen[y as usize] {
                    seen.set(y as usize, true);
                    orbit.push(y);
                }
            }
        }
        let s = lower.sign(d0);
        for &x in &orbit {
            if met[x as usize] {
                continue;
            }
            // x is the first dart of its element of B_i (a <alpha_{i+1..n}>-orbit, inside
            // the walked one) in walk order: one term, then mark the element
            out.push((row as u32, upper.cells.of[x as usize], upper.sign(x) * s));
            element.clear();
            element.push(x);
            met.set(x as usize, true);
            while let Some(z) = element.pop() {
                for j in i + 1..w {
                    let y = a[z as usize * w + j];
                    if !met[y as usize] {
                        met.set(y as usize, true);
                        element.push(y);
                    }
                }
            }
        }
        for &x in &orbit {
            seen.set(x as usize, false);
            met.set(x as usize, false);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use gmap_core::examples;

    /// Paper dart k is Dart::new(k - 1).
    fn p(k: u32) -> Dart {
        Dart::new(k - 1)
    }

    #[test]
    fn bo_fig1f() {
        let m = examples::fig1_surface();
        let inc = Incidence::new(&m, 2);
        assert_eq!(inc.unsigned(p(1), p(14)), 0);
        assert_eq!(inc.unsigned(p(1), p(9)), 1);
        // Property 1: any dart of either cell gives the same number
        assert_eq!(inc.unsigned(p(2), p(10)), 1);
    }

    #[test]
    fn bo_fig2_cylinder() {
        let m = examples::cylinder();
        let e = Incidence::new(&m, 1);
        let f = Incidence::new(&m, 2);
        assert_eq!(e.unsigned(p(1), p(1)), 1);
        assert_eq!(e.unsigned(p(8), p(1)), 2);
        assert_eq!(f.unsigned(p(1), p(8)), 1);
        assert_eq!(f.unsigned(p(1), p(1)), 2);
        assert_eq!(f.unsigned(p(1), p(2)), 2);
        // signed: the loop edge meets its vertex once each way, the seam is crossed both ways
        assert_eq!(e.signed(&m, p(8), p(1)).unwrap(), 0);
        assert_eq!(e.signed(&m, p(1), p(1)).unwrap().abs(), 1);
        assert_eq!(f.signed(&m, p(1), p(1)).unwrap(), 0);
        assert_eq!(f.signed(&m, p(1), p(8)).unwrap().abs(), 1);
    }
}
