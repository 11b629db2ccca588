//! Compacted cells and face operators (BO Def. 3, 4).
//!
//! For a dimension i, the set `B_i` has one element per `<alpha_{i+1}, …, alpha_n>`-orbit
//! of darts. The involutions `alpha^i_k` (k < i) act on `B_i` by sending the orbit of `d`
//! to the orbit of `alpha_k(d)`; the compacted i-cell of `d` is the `<alpha^i_0, …,
//! alpha^i_{i-1}>`-connected part of `B_i` holding the orbit of `d`. The face operator
//! `∂_i : B_i → B_{i-1}` sends `<alpha_{i+1}..alpha_n>(d)` to `<alpha_i..alpha_n>(d)`.

use crate::alpha::AlphaSet;
use crate::dense::{DenseMap, Partition};
use crate::ids::Dart;

/// The elements of `B_i` with their induced involutions, and the compacted i-cells.
#[derive(Clone, Debug)]
pub struct CompactedCells {
    /// the dimension i
    pub dim: usize,
    /// the `<alpha_{i+1..n}>`-orbits: `orbits.of[d]` is the element of `B_i` holding `d`
    pub orbits: Partition,
    /// `induced[e * i + k]` is `alpha^i_k(e)` for element `e` of `B_i` and `k < i`
    pub induced: Vec<u32>,
    /// the i-cell of each element of `B_i` (numbered as in `DenseMap::cells(i)`)
    pub cell_of: Vec<u32>,
}

impl CompactedCells {
    /// Computes `B_i`, its induced involutions and its compacted cells. O(N n).
    pub fn new(map: &DenseMap, i: usize) -> Self {
        let n = map.dim();
        assert!(i <= n);
        let orbits = map.partition(AlphaSet::above(i, n));
        let mut induced = Vec::with_capacity(orbits.len() * i);
        for &r in &orbits.reps {
            for k in 0..i {
                induced.push(orbits.of[map.alpha(r, k).index()]);
            }
        }
        let cells = map.cells(i);
        let cell_of = orbits.reps.iter().map(|&r| cells.of[r.index()]).collect();
        CompactedCells { dim: i, orbits, induced, cell_of }
    }

    /// Number of elements of `B_i`.
    pub fn len(&self) -> usize {
        self.orbits.len()
    }

    /// Whether `B_i` is empty.
    pub fn is_empty(&self) -> bool {
        self.orbits.is_empty()
    }

    /// `alpha^i_k(e)` for `k < i`.
    pub fn alpha(&self, e: u32, k: usize) -> u32 {
        assert!(k < self.dim);
        self.induced[e as usize * self.dim + k]
    }

    /// The darts of element `e` of `B_i`.
    pub fn darts_of(&self, e: u32) -> Vec<Dart> {
        self.orbits.of.iter().enumerate().filter(|(_, &k)| k == e).map(|(d, _)| Dart::new(d as u32)).collect()
    }
}

/// The face operator `∂_i : B_i → B_{i-1}` (BO Def. 4) and its preimages.
#[derive(Clone, Debug)]
pub struct FaceOperator {
    /// `image[e]` is `∂_i(e)`, an element of `B_{i-1}`
    pub image: Vec<u32>,
    /// CSR offsets of the preimages, indexed by elements of `B_{i-1}`
    pub pre_offsets: Vec<usize>,
    /// preimage elements (of `B_i`), increasing within each element of `B_{i-1}`
    pub pre: Vec<u32>,
}

impl FaceOperator {
    /// Builds `∂_i` from the compacted cells of dimensions i and i-1. O(|B_i| + |B_{i-1}|).
    pub fn new(upper: &CompactedCells, lower: &CompactedCells) -> Self {
        assert_eq!(upper.dim, lower.dim + 1);
        let image: Vec<u32> = upper.orbits.reps.iter().map(|&r| lower.orbits.of[r.index()]).collect();
        let mut pre_offsets = vec![0usize; lower.len() + 1];
        for &t in &image {
            pre_offsets[t as usize + 1] += 1;
        }
        for k in 0..lower.len() {
            pre_offsets[k + 1] += pre_offsets[k];
        }
        let mut fill = pre_offsets.clone();
        let mut pre = vec![0u32; image.len()];
        for (e, &t) in image.iter().enumerate() {
            pre[fill[t as usize]] = e as u32;
            fill[t as usize] += 1;
        }
        FaceOperator { image, pre_offsets, pre }
    }

    /// The preimage `∂_i^{-1}(f)` of an element `f` of `B_{i-1}`.
    pub fn preimage(&self, f: u32) -> &[u32] {
        &self.pre[self.pre_offsets[f as usize]..self.pre_offsets[f as usize + 1]]
    }
}
