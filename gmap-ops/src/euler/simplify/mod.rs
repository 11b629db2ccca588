//! Homology-preserving simplification by removals and contractions.
//!
//! A G-map whose cells are homology balls (conditions C1, C2 of docs/DESIGN.md) is a
//! CW-structure on its space; its cellular homology is the space's homology. Removing an
//! i-cell of degree 2 that separates two *distinct* (i+1)-cells merges them into one
//! (i+1)-cell — a ball glued to a ball along a ball — and leaves the space untouched;
//! contracting an i-cell of dual degree 2 between two distinct (i-1)-cells is the dual
//! move, a homotopy equivalence. Both therefore keep the homology and keep the cells balls,
//! while the number of darts drops.
//!
//! Two more conditions keep every step a homotopy equivalence that the G-map can represent:
//! the cell's appearances in each k-cell it touches must join distinct *corners* (pieces of
//! the neighbouring cells around that k-cell) without closing a cycle — otherwise the
//! k-cell would fall apart, as a volume does when an edge it meets twice is contracted — and
//! a contraction never merges two cells that carry free darts (two boundary vertices joined
//! by an interior edge would pinch the space), with one exception: in a manifold with
//! boundary (every free dart free for `alpha_n` only), an edge that lies on the boundary
//! itself may be contracted. The links of its two vertices are then (n-1)-disks glued along
//! the edge's link, an (n-2)-disk on both their boundaries, so the merged vertex is one cell
//! and nothing is pinched; contracting an arc is a homotopy equivalence.
//!
//! # Order of the moves
//!
//! [`simplify`] scans the cells dimension by dimension (removals of (n-1)-cells, which merge
//! the n-cells along a spanning tree of the dual graph, then of (n-2)-cells, …, then the
//! contractions of 1-cells, which merge the vertices along a spanning tree, 2-cells, …) and
//! repeats until nothing applies. The order matters: after a removal of an i-cell, the
//! (i-1)-cells on its border have lost a neighbour and are re-examined *at once*, before the
//! scan goes on (a work stack; dually after a contraction for the (i+1)-cells). In a
//! 3-manifold an edge whose degree falls to 2 is thus removed while its two faces still
//! separate two distinct volumes, and the merged face is removed later in the scan: this
//! is the collapse of a free edge of discrete Morse theory. Removing all the faces of the
//! spanning tree first instead leaves such an edge with one face on both sides of the
//! single volume, where no removal or contraction applies any more.
//!
//! A few runs from fresh copies of the input (removals first, contractions first, with and
//! without re-examining the merged neighbour after each move, then seeded random orders of
//! the darts) keep the smallest result; see [`SimplifyOptions`].
//!
//! # Search past plateaus (3-maps)
//!
//! Removals and contractions stop where every remaining cell meets its neighbours more than
//! once: a ball with a knotted boundary may end at one vertex, one volume, and loops and
//! faces that all bound the volume on both sides. The inverse moves get out: splitting the
//! volume by a new face along a closed path of its boundary, or a face by a new edge,
//! subdivides without changing the space, and a face that bounded the volume on both sides
//! may now separate the two halves and be removed. Such a split-then-remove is a handle
//! slide. The search ([`SimplifyOptions::search`]) applies random splits (up to a third of
//! the darts' count, at most 40, at a time) to the smallest map so far, checks that every
//! cell is still a ball (C1 and χ = 2 per volume), simplifies greedily again and keeps the
//! result when it is no larger. Splits come in groups because one to three at a time
//! rarely leave a plateau.
//!
//! The figures — darts and cells before and after for the Lutz library and grids, times,
//! the spread over seeds, and where 4-maps such as K3 stop — are in docs/SIMPLIFY.md.
//!
//! # Cost
//!
//! Every dart carries, per dimension k, the number of its k-cell in the input; cells only
//! merge under the moves (the corner test forbids splits), so a union–find structure per
//! dimension names the current cells, and no partition is recomputed. A move costs
//! O(|c| n²) for the darts of the cell c it removes, plus the corners it has to compare
//! when c meets one k-cell twice; a scan costs O(N α(N)) on top of the moves, and a scan
//! changing nothing ends the reduction. Memory: O(N n) words. The n + 1 partitions of the
//! input (one task each, on the threads of `gmap_core::parallel`) take about a third of the
//! time, the moves the rest. A search round costs O(N) per split tried on the current small
//! map (every split is checked on the whole map), plus a greedy reduction of the split map.
//! On big regular grids the reduction costs more than the direct cellular homology of the
//! grid: its use is the small map itself, and inputs whose direct homology is expensive.
//!
//! The code: `work` holds the working copy of the map, `moves` tests and applies one
//! removal or contraction, `greedy` orders the moves into scans and runs, `search` splits
//! cells of the greedy result and simplifies again.

mod greedy;
mod moves;
mod search;
mod work;

use gmap_core::DenseMap;

use crate::rng::SplitMix64;

/// What [`simplify`] did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SimplifyReport {
    /// darts before
    pub darts_before: usize,
    /// darts after
    pub darts_after: usize,
    /// cells per dimension before
    pub cells_before: Vec<usize>,
    /// cells per dimension after
    pub cells_after: Vec<usize>,
    /// number of i-cells removed, per i
    pub removed: Vec<usize>,
    /// number of i-cells contracted, per i
    pub contracted: Vec<usize>,
    /// rounds of scans run by the greedy stage, the last one changing nothing (`removed`,
    /// `contracted` and `rounds` describe that stage, which ends the reduction when there is
    /// no search)
    pub rounds: usize,
    /// rounds of the search made after the greedy stage (see [`SimplifyOptions::search`])
    pub search_rounds: usize,
    /// darts the search removed beyond the greedy stage's result
    pub search_gain: usize,
    /// the search's work, a measure of its time: darts walked by the splits it tried plus
    /// darts of the split maps it simplified; at most `2304 · search` plus the last round's
    /// (see [`SimplifyOptions::search`])
    pub search_work: usize,
}

impl SimplifyReport {
    /// `darts_after / darts_before` (0 for an empty map).
    pub fn ratio(&self) -> f64 {
        if self.darts_before == 0 {
            0.0
        } else {
            self.darts_after as f64 / self.darts_before as f64
        }
    }
}

/// How [`simplify_with`] searches.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SimplifyOptions {
    /// Number of runs, each from a fresh copy of the input; the smallest result is kept.
    /// Run 0 scans removals first and run 1 contractions first, both in dart order; later
    /// runs alternate the two in a random order of the darts drawn from `seed`.
    pub tries: usize,
    /// Seed of the random orders and splits (a [`SplitMix64`] generator: the result is
    /// deterministic).
    pub seed: u64,
    /// Rounds of search after the greedy runs, for 3-maps whose cells are balls (C1 and
    /// χ = 2 for every volume); 0 for none. A round splits a random number of cells of the
    /// smallest map so far, up to a third of its darts' count and between 3 and 40 at most (a
    /// face across a volume, an edge across a face: subdivisions, which keep the space),
    /// checks that every cell is still a ball, simplifies the result again (two greedy runs)
    /// and keeps it when it has at most as many darts. The splits move cells past each other
    /// where removals and contractions alone are stuck. The search stops after `search`
    /// rounds, when the split maps it has simplified hold `256 · search` darts in all, or
    /// when the placements it tried have walked `2048 · search` darts (a placement is checked
    /// on its whole cell, so on maps whose cells meet themselves everywhere, where most
    /// placements fail, the tries rather than the rounds make the time).
    /// Greedy results of more than 1,024 darts are not searched.
    pub search: usize,
}

impl SimplifyOptions {
    /// The choice of [`simplify`]: eight runs for maps of at most 2^16 darts, two (removals
    /// first, contractions first) up to 2^18, one beyond; 4000 rounds of search for 3-maps
    /// (its cost follows the size of the reduced map, not of the input). The first run does
    /// the work in near-linear time; the others pay off on small, hard inputs (triangulated
    /// manifolds with torsion, 4-manifolds), where they cost a few milliseconds.
    pub fn for_map(map: &DenseMap) -> Self {
        let n = map.dart_count();
        let tries = if n <= 1 << 16 {
            8
        } else if n <= 1 << 18 {
            2
        } else {
            1
        };
        SimplifyOptions { tries, seed: 0x5eed_9a3a, search: if map.dim() == 3 { 4000 } else { 0 } }
    }
}

/// Reduces `map` by removals and contractions of cells (see the module documentation) and
/// returns the reduced map with a report. The reduced map has the same homology as `map`
/// whenever the cells of `map` are homology balls (C1, C2 of docs/DESIGN.md), and its cells are
/// again homology balls, so the cellular method applies to it. Points are dropped.
/// Equivalent to [`simplify_with`] and [`SimplifyOptions::for_map`].
///
/// Precondition: `map` is valid (BO Def. 1). Cells on a boundary (free darts) are left in
/// place. O(T · R · N n² α(N)) time for T tries of R rounds of scans (R is two or three in
/// practice), O(N n) extra memory.
///
/// ```
/// use gmap_core::GMap;
/// use gmap_ops::euler::simplify;
/// // a hexagon as a 1-map: six vertices, six edges, a circle
/// let mut g = GMap::new(1);
/// let d: Vec<_> = (0..12).map(|_| g.create_dart()).collect();
/// for k in 0..6 {
///     g.sew(d[2 * k], d[2 * k + 1], 0);
///     g.sew(d[2 * k + 1], d[(2 * k + 2) % 12], 1);
/// }
/// let (small, report) = simplify(&g.to_dense_map());
/// assert_eq!(small.cell_counts(), vec![1, 1]); // one vertex, one loop
/// assert_eq!((report.darts_before, report.darts_after), (12, 2));
/// ```
pub fn simplify(map: &DenseMap) -> (DenseMap, SimplifyReport) {
    simplify_with(map, &SimplifyOptions::for_map(map))
}

/// [`simplify`] with an explicit number of runs, seed and search (at least one run is made).
pub fn simplify_with(map: &DenseMap, options: &SimplifyOptions) -> (DenseMap, SimplifyReport) {
    let mut rng = SplitMix64::new(options.seed);
    let (cells_before, best) = greedy::best_run(map, options.tries, &mut rng);
    let out = best.work.compact();
    debug_assert!(out.validate().is_ok(), "simplify broke validity");
    let greedy = out.dart_count();
    let (out, search_rounds, search_work) = search::search(out, options, &mut rng);
    let report = SimplifyReport {
        darts_before: map.dart_count(),
        darts_after: out.dart_count(),
        cells_before,
        cells_after: out.cell_counts(),
        removed: best.work.removed,
        contracted: best.work.contracted,
        rounds: best.rounds,
        search_rounds,
        search_gain: greedy - out.dart_count(),
        search_work,
    };
    (out, report)
}
