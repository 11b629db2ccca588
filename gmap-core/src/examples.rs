//! The small G-maps drawn in the border-operator paper (BO), rebuilt from its text.
//!
//! The paper numbers darts from 1; here paper dart `k` is [`Dart`]`(k - 1)`. The figures
//! themselves are not part of the text we have, so each map below is the smallest one
//! consistent with every fact the text states about it (the facts are listed in each
//! function's docs and checked by the tests of this module).
//!
//! | function | figure | dimension | darts | cells | notes |
//! | --- | --- | --- | --- | --- | --- |
//! | [`fig1_curve`] | BO Fig. 1(a) | 1 | 8 | 4 vertices, 4 edges | a closed curve |
//! | [`fig1_surface`] | BO Fig. 1(b) | 2 | 14 | 5, 6, 2 | a square and a triangle sharing an edge |
//! | [`cylinder`] | BO Fig. 2 | 2 | 8 | 2, 3, 1 | multi-incidence, orientable |
//! | [`klein_bottle`] | BO Fig. 4(b) | 2 | 8 | 1, 2, 1 | non-orientable map, orientable cells |
//! | [`torus`] | (contrast) | 2 | 8 | 1, 2, 1 | the orientable twin of the Klein bottle |
//!
//! ```
//! use gmap_core::examples;
//! let k = examples::klein_bottle();
//! assert_eq!(k.cell_counts(), vec![1, 2, 1]);
//! assert!(!k.is_orientable());
//! assert!(k.check_cells_orientable().is_ok());
//! ```
//!
//! [`add_simplex`] adds a free k-simplex to an editable map, the building block of the
//! random maps of the property tests.

use crate::attr::Attributes;
use crate::dense::DenseMap;
use crate::edit::{DartId, GMap};
use crate::ids::Dart;

/// Builds a map from involutions written as pairs of paper darts (numbered from 1);
/// every dart not named in `pairs[i]` is i-free.
fn from_paper_pairs(dim: usize, darts: usize, pairs: &[&[(u32, u32)]]) -> DenseMap {
    debug_assert_eq!(pairs.len(), dim + 1);
    let mut m = DenseMap::new(dim, darts);
    for (i, list) in pairs.iter().enumerate() {
        for &(a, b) in list.iter() {
            m.link(Dart::new(a - 1), Dart::new(b - 1), i);
        }
    }
    debug_assert!(m.validate().is_ok());
    m
}

/// The 8 darts of a polygon with four sides, as paper darts `1..=8`: `alpha_0` pairs the
/// two darts of each side, `alpha_1` the two darts of each corner.
const SQUARE_A0: [(u32, u32); 4] = [(1, 2), (3, 4), (5, 6), (7, 8)];
const SQUARE_A1: [(u32, u32); 4] = [(2, 3), (4, 5), (6, 7), (8, 1)];

/// BO Fig. 1(a): a 1G-map of 8 darts, a closed curve of four edges and four vertices.
///
/// Facts from the text: vertex `{1, 8}` lies on the boundary of edges `{1, 2}` and
/// `{7, 8}`; in the compacted cells (Fig. 1(e)) the face operator `∂_1` sends `{2}` and
/// `{3}` (elements of `B_1`) to `{2, 3} = <alpha_1>(2)` (an element of `B_0`).
/// Here `alpha_0 = (1 2)(3 4)(5 6)(7 8)` and `alpha_1 = (2 3)(4 5)(6 7)(8 1)`.
pub fn fig1_curve() -> DenseMap {
    from_paper_pairs(1, 8, &[&SQUARE_A0, &SQUARE_A1])
}

/// BO Fig. 1(b): a 2G-map of 14 darts, a square face `{1..8}` and a triangle face
/// `{9..14}` sharing the edge `{3, 4, 9, 10}`; a disc.
///
/// Facts from the text: vertex `{2, 3, 9, 14}` lies on edges `{1, 2}`, `{3, 4, 9, 10}` and
/// `{13, 14}`; `<alpha_2>(1) = {1}`, `<alpha_1, alpha_2>(1) = {1, 8}`,
/// `<alpha_2>(3) = {3, 9}`, `<alpha_2>(4) = {4, 10}`, `<alpha_2>(13) = {13}`,
/// `<alpha_2>(14) = {14}`. Here the square is as in [`fig1_curve`],
/// the triangle has `alpha_0 = (9 10)(11 12)(13 14)`, `alpha_1 = (9 14)(10 11)(12 13)`, and
/// `alpha_2 = (3 9)(4 10)`, every other dart 2-free.
pub fn fig1_surface() -> DenseMap {
    let a0 = [SQUARE_A0.as_slice(), &[(9, 10), (11, 12), (13, 14)]].concat();
    let a1 = [SQUARE_A1.as_slice(), &[(9, 14), (10, 11), (12, 13)]].concat();
    from_paper_pairs(2, 14, &[&a0, &a1, &[(3, 9), (4, 10)]])
}

/// BO Fig. 2: a cylinder as a 2G-map of 8 darts with one face, three edges and two
/// vertices (Euler characteristic 0), showing multi-incidence.
///
/// Facts from the text: the face is `{1..8}`; vertex `{1, 6, 7, 8}`; edge `{1, 2, 5, 6}`
/// with `<alpha_2>(1) = {1, 6}` and `<alpha_2>(2) = {2, 5}`; edge `{7, 8}` whose darts are
/// 2-free, twice incident to vertex `{1, 6, 7, 8}`; the edge `{1, 2, 5, 6}` is twice
/// incident to the face. Here the face is the square of [`fig1_curve`] and
/// `alpha_2 = (1 6)(2 5)`; darts 3, 4, 7, 8 are 2-free (the two boundary circles
/// `{3, 4}` and `{7, 8}`), and the other vertex is `{2, 3, 4, 5}`.
pub fn cylinder() -> DenseMap {
    from_paper_pairs(2, 8, &[&SQUARE_A0, &SQUARE_A1, &[(1, 6), (2, 5)]])
}

/// BO Fig. 4(b): a Klein bottle as a 2G-map of 8 darts (one vertex, two edges, one face),
/// not orientable although each of its compacted cells is.
///
/// The square of [`fig1_curve`] with opposite sides glued, one pair keeping and one pair
/// reversing the orientation: `alpha_2 = (1 6)(2 5)(3 7)(4 8)`.
pub fn klein_bottle() -> DenseMap {
    from_paper_pairs(2, 8, &[&SQUARE_A0, &SQUARE_A1, &[(1, 6), (2, 5), (3, 7), (4, 8)]])
}

/// The torus on the same square as [`klein_bottle`], both pairs of sides glued so that the
/// orientation is kept: `alpha_2 = (1 6)(2 5)(3 8)(4 7)`. Not drawn in BO; it is the
/// orientable contrast to Fig. 4(b).
pub fn torus() -> DenseMap {
    from_paper_pairs(2, 8, &[&SQUARE_A0, &SQUARE_A1, &[(1, 6), (2, 5), (3, 8), (4, 7)]])
}

/// All orderings of `0..=k`, in lexicographic order.
fn orderings(k: usize) -> Vec<Vec<usize>> {
    let mut out = vec![vec![]];
    for _ in 0..=k {
        let mut next = Vec::new();
        for p in &out {
            for v in (0..=k).filter(|v| !p.contains(v)) {
                let mut q = p.clone();
                q.push(v);
                next.push(q);
            }
        }
        out = next;
    }
    out
}

/// Adds a free k-simplex to `g` (precondition: `k <= g.dim()`) and returns its darts: one
/// per ordering of its k + 1 vertices, in lexicographic order, `alpha_i` swapping positions
/// i and i + 1 for `i < k`, every other involution free. (k + 1)! darts, built through
/// [`GMap::link`] (no attribute is set).
///
/// ```
/// use gmap_core::{examples::add_simplex, GMap, MapView};
/// let mut g = GMap::new(3);
/// assert_eq!(add_simplex(&mut g, 3).len(), 24);
/// assert_eq!(MapView::cell_counts(&g), vec![4, 6, 4, 1]);
/// ```
pub fn add_simplex<A: Attributes>(g: &mut GMap<A>, k: usize) -> Vec<DartId> {
    let perms = orderings(k);
    let ids: Vec<DartId> = perms.iter().map(|_| g.create_dart()).collect();
    for (a, p) in perms.iter().enumerate() {
        for i in 0..k {
            let mut q = p.clone();
            q.swap(i, i + 1);
            if let Ok(b) = perms.binary_search(&q) {
                if a < b {
                    g.link(ids[a], ids[b], i);
                }
            }
        }
    }
    ids
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{AlphaSet, CompactedCells, FaceOperator, Partition};

    /// Paper darts (from 1) of each part of a partition, each sorted, parts sorted.
    fn paper_sets(p: &Partition) -> Vec<Vec<u32>> {
        let (off, darts) = p.members();
        let mut v: Vec<Vec<u32>> =
            (0..p.len()).map(|k| darts[off[k]..off[k + 1]].iter().map(|&d| d + 1).collect()).collect();
        v.sort();
        v
    }

    fn set_of(m: &DenseMap, paper_dart: u32, set: AlphaSet) -> Vec<u32> {
        let mut v: Vec<u32> = m.orbit(Dart::new(paper_dart - 1), set).iter().map(|d| d.get() + 1).collect();
        v.sort();
        v
    }

    #[test]
    fn fig1_curve_cells_and_face_operator() {
        let m = fig1_curve();
        m.validate().unwrap();
        assert_eq!(paper_sets(&m.cells(0)), vec![vec![1, 8], vec![2, 3], vec![4, 5], vec![6, 7]]);
        assert_eq!(paper_sets(&m.cells(1)), vec![vec![1, 2], vec![3, 4], vec![5, 6], vec![7, 8]]);
        assert_eq!(m.euler_characteristic(), 0);
        let b1 = CompactedCells::new(&m, 1);
        let b0 = CompactedCells::new(&m, 0);
        assert_eq!(b1.len(), 8); // B_1: singletons
        assert_eq!(paper_sets(&b0.orbits), vec![vec![1, 8], vec![2, 3], vec![4, 5], vec![6, 7]]);
        let f = FaceOperator::new(&b1, &b0);
        // ∂_1({2}) = ∂_1({3}) = {2, 3}
        let e2 = f.image[b1.orbits.of[1] as usize];
        let e3 = f.image[b1.orbits.of[2] as usize];
        assert_eq!(e2, e3);
        assert_eq!(b0.darts_of(e2), vec![Dart::new(1), Dart::new(2)]);
        // its preimage is {{2}, {3}}
        let pre: Vec<Vec<Dart>> = f.preimage(e2).iter().map(|&e| b1.darts_of(e)).collect();
        assert_eq!(pre, vec![vec![Dart::new(1)], vec![Dart::new(2)]]);
        assert!(m.is_orientable());
        assert!(m.has_complete_boundaries());
    }

    #[test]
    fn fig1_surface_cells() {
        let m = fig1_surface();
        m.validate().unwrap();
        assert_eq!(
            paper_sets(&m.cells(0)),
            vec![vec![1, 8], vec![2, 3, 9, 14], vec![4, 5, 10, 11], vec![6, 7], vec![12, 13]]
        );
        assert_eq!(
            paper_sets(&m.cells(1)),
            vec![vec![1, 2], vec![3, 4, 9, 10], vec![5, 6], vec![7, 8], vec![11, 12], vec![13, 14]]
        );
        assert_eq!(paper_sets(&m.cells(2)), vec![(1..=8).collect::<Vec<_>>(), (9..=14).collect()]);
        assert_eq!(m.cell_counts(), vec![5, 6, 2]);
        assert_eq!(m.euler_characteristic(), 1);
        assert_eq!(m.component_count(), 1);
        assert_eq!(set_of(&m, 1, AlphaSet::of(&[2])), vec![1]);
        assert_eq!(set_of(&m, 1, AlphaSet::of(&[1, 2])), vec![1, 8]);
        assert_eq!(set_of(&m, 14, AlphaSet::of(&[2])), vec![14]);
        assert_eq!(set_of(&m, 13, AlphaSet::of(&[2])), vec![13]);
        assert!(m.is_orientable());
        // darts 1, 2, … are 2-free and 2 = n: the boundary is complete
        assert!(m.has_complete_boundaries());
        assert!(m.check_cells_orientable().is_ok());
    }

    #[test]
    fn fig1_surface_compacted_cells_and_face_operators() {
        let m = fig1_surface();
        let b2 = CompactedCells::new(&m, 2);
        let b1 = CompactedCells::new(&m, 1);
        let b0 = CompactedCells::new(&m, 0);
        assert_eq!((b2.len(), b1.len(), b0.len()), (14, 12, 5));
        // edge {3, 4, 9, 10} is the alpha^1_0-connected set {{3, 9}, {4, 10}}
        let e39 = b1.orbits.of[2];
        let e410 = b1.orbits.of[3];
        assert_eq!(b1.darts_of(e39), vec![Dart::new(2), Dart::new(8)]);
        assert_eq!(b1.darts_of(e410), vec![Dart::new(3), Dart::new(9)]);
        assert_eq!(b1.alpha(e39, 0), e410);
        assert_eq!(b1.alpha(e410, 0), e39);
        assert_eq!(b1.cell_of[e39 as usize], b1.cell_of[e410 as usize]);
        let in_edge: Vec<u32> =
            (0..b1.len() as u32).filter(|&e| b1.cell_of[e as usize] == b1.cell_of[e39 as usize]).collect();
        assert_eq!(in_edge, vec![e39, e410]);
        // ∂_1(<alpha_2>(1) = {1}) = <alpha_1, alpha_2>(1) = {1, 8}
        let d1 = FaceOperator::new(&b1, &b0);
        let v = d1.image[b1.orbits.of[0] as usize];
        assert_eq!(b0.darts_of(v), vec![Dart::new(0), Dart::new(7)]);
        // ∂_2({2}) = <alpha_2>(2) = {2}; ∂_2({3}) = <alpha_2>(3) = {3, 9}
        let d2 = FaceOperator::new(&b2, &b1);
        assert_eq!(b1.darts_of(d2.image[b2.orbits.of[1] as usize]), vec![Dart::new(1)]);
        assert_eq!(b1.darts_of(d2.image[b2.orbits.of[2] as usize]), vec![Dart::new(2), Dart::new(8)]);
        // the preimage of {3, 9} is {{3}, {9}}; only {3} lies in the face of dart 1
        let pre: Vec<Vec<Dart>> = d2.preimage(e39).iter().map(|&e| b2.darts_of(e)).collect();
        assert_eq!(pre, vec![vec![Dart::new(2)], vec![Dart::new(8)]]);
        let face1 = b2.cell_of[0];
        assert_eq!(d2.preimage(e39).iter().filter(|&&e| b2.cell_of[e as usize] == face1).count(), 1);
        // the preimage of {14} is {{14}}, not in the face of dart 1: incidence 0
        let e14 = b1.orbits.of[13];
        assert_eq!(d2.preimage(e14).iter().filter(|&&e| b2.cell_of[e as usize] == face1).count(), 0);
    }

    #[test]
    fn cylinder_multi_incidence() {
        let m = cylinder();
        m.validate().unwrap();
        assert_eq!(paper_sets(&m.cells(0)), vec![vec![1, 6, 7, 8], vec![2, 3, 4, 5]]);
        assert_eq!(paper_sets(&m.cells(1)), vec![vec![1, 2, 5, 6], vec![3, 4], vec![7, 8]]);
        assert_eq!(paper_sets(&m.cells(2)), vec![(1..=8).collect::<Vec<_>>()]);
        assert_eq!(m.euler_characteristic(), 0);
        assert_eq!(set_of(&m, 1, AlphaSet::of(&[2])), vec![1, 6]);
        assert_eq!(set_of(&m, 2, AlphaSet::of(&[2])), vec![2, 5]);
        assert_eq!(set_of(&m, 7, AlphaSet::of(&[2])), vec![7]);
        assert_eq!(set_of(&m, 8, AlphaSet::of(&[2])), vec![8]);
        let b2 = CompactedCells::new(&m, 2);
        let b1 = CompactedCells::new(&m, 1);
        let b0 = CompactedCells::new(&m, 0);
        let d1 = FaceOperator::new(&b1, &b0);
        let d2 = FaceOperator::new(&b2, &b1);
        // preimage of vertex {1, 6, 7, 8} is {{1, 6}, {7}, {8}}
        let v = b0.orbits.of[0];
        let pre: Vec<Vec<Dart>> = d1.preimage(v).iter().map(|&e| b1.darts_of(e)).collect();
        assert_eq!(pre, vec![vec![Dart::new(0), Dart::new(5)], vec![Dart::new(6)], vec![Dart::new(7)]]);
        // unsigned incidences: edge of 1 with that vertex 1, edge of 8 with it 2
        let cells1 = m.cells(1);
        let count_in = |edge_dart: usize| {
            d1.preimage(v)
                .iter()
                .filter(|&&e| cells1.of[b1.orbits.reps[e as usize].index()] == cells1.of[edge_dart])
                .count()
        };
        assert_eq!(count_in(0), 1);
        assert_eq!(count_in(7), 2);
        // the face: preimage of {8} is {8} (incidence 1), of {1, 6} is {{1}, {6}} (incidence 2)
        assert_eq!(d2.preimage(b1.orbits.of[7]).len(), 1);
        let pre: Vec<Vec<Dart>> = d2.preimage(b1.orbits.of[0]).iter().map(|&e| b2.darts_of(e)).collect();
        assert_eq!(pre, vec![vec![Dart::new(0)], vec![Dart::new(5)]]);
        let pre: Vec<Vec<Dart>> = d2.preimage(b1.orbits.of[1]).iter().map(|&e| b2.darts_of(e)).collect();
        assert_eq!(pre, vec![vec![Dart::new(1)], vec![Dart::new(4)]]);
        assert!(m.is_orientable());
        // 2-free darts only: complete boundaries, and every compacted cell orientable
        assert!(m.has_complete_boundaries());
        assert!(m.check_cells_orientable().is_ok());
    }

    #[test]
    fn klein_bottle_not_orientable_cells_orientable() {
        let m = klein_bottle();
        m.validate().unwrap();
        assert_eq!(paper_sets(&m.cells(0)), vec![(1..=8).collect::<Vec<_>>()]);
        assert_eq!(paper_sets(&m.cells(1)), vec![vec![1, 2, 5, 6], vec![3, 4, 7, 8]]);
        assert_eq!(m.cell_counts(), vec![1, 2, 1]);
        assert_eq!(m.euler_characteristic(), 0);
        assert!(!m.is_orientable());
        assert!(m.has_complete_boundaries());
        for i in 0..=2 {
            assert!(m.cell_orientation(i).is_ok(), "cell dimension {i}");
        }
        let t = torus();
        t.validate().unwrap();
        assert_eq!(t.cell_counts(), vec![1, 2, 1]);
        assert!(t.is_orientable());
        assert!(t.check_cells_orientable().is_ok());
    }
}
