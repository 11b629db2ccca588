//! Random sequences of Euler operators, for tests and benches.
//!
//! A property test of the Euler operators, of homology or of simplification wants maps that
//! differ from the classic objects in many small ways: split an edge here, remove a face
//! there. This module tries the operators of [`ops`] at chosen or random places and
//! reports, for every attempt, whether the operator's predicate allowed it and what its
//! `try_` form did, so that a test can also check that the two agree.
//!
//! * [`attempt`] tries one [`Operator`] at given darts and dimension;
//! * [`attempt_at`] takes the darts and the dimension from plain numbers, as proptest
//!   strategies draw them;
//! * [`random_steps`] draws operators and places from a [`SplitMix64`] generator.
//!
//! ```
//! use gmap_core::GMap;
//! use gmap_ops::build::cube;
//! use gmap_ops::euler::random::{random_steps, Operator};
//! use gmap_ops::rng::SplitMix64;
//! let (mut g, _) = GMap::from_dense(&cube(3).unwrap());
//! let mut rng = SplitMix64::new(1);
//! let applied = random_steps(&mut g, 20, &[Operator::InsertVertex, Operator::InsertEdge], &mut rng);
//! assert!(!applied.is_empty());
//! let (m, _) = g.to_dense_with_ids();
//! assert!(m.validate().is_ok());
//! assert_eq!(m.euler_characteristic(), 1); // still a ball
//! ```

use gmap_core::{AlphaSet, Attributes, DartId, GMap};

use super::ops::{self, EulerError};
use super::vector::EulerOp;
use crate::rng::SplitMix64;

/// An Euler operator of [`ops`] that a random step can try, with the darts `d`, `e` and the
/// dimension `i` of [`attempt`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Operator {
    /// [`ops::try_insert_vertex`] in the edge of `d`
    InsertVertex,
    /// [`ops::try_insert_edge`] from the corner of `d` to the corner of `e`
    InsertEdge,
    /// [`ops::try_insert_dangling_edge`] at the corner of `d`
    InsertDanglingEdge,
    /// [`ops::try_remove_cell_keeping_homology`] of the i-cell of `d`
    RemoveCell,
    /// [`ops::try_contract_cell_keeping_homology`] of the i-cell of `d`
    ContractCell,
    /// [`ops::try_split_cell`] of the i-cell of `d` along the cut given by `d` and `e`
    SplitCell,
}

impl Operator {
    /// Every operator, in the order of the declaration.
    pub const ALL: [Operator; 6] = [
        Operator::InsertVertex,
        Operator::InsertEdge,
        Operator::InsertDanglingEdge,
        Operator::RemoveCell,
        Operator::ContractCell,
        Operator::SplitCell,
    ];
}

/// One operator tried at one place.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Attempt {
    /// what the operator's predicate (`can_…` / `is_…`) said
    pub allowed: bool,
    /// what its `try_…` form returned; on an error the map is unchanged
    pub result: Result<EulerOp, EulerError>,
}

impl Attempt {
    /// Whether the predicate and the `try_` form agree (the operator was applied exactly
    /// when the predicate allowed it).
    pub fn consistent(&self) -> bool {
        self.allowed == self.result.is_ok()
    }
}

/// Tries `op` on `g` at the darts `d`, `e` and the cell dimension `i` (each operator reads
/// what it needs, see [`Operator`]): asks its predicate, then calls its `try_` form.
/// O(size of the cells touched · n).
pub fn attempt<A: Attributes>(g: &mut GMap<A>, op: Operator, d: DartId, e: DartId, i: usize) -> Attempt {
    let (allowed, result) = match op {
        Operator::InsertVertex => (ops::can_insert_vertex(g, d), ops::try_insert_vertex(g, d)),
        Operator::InsertEdge => (ops::can_insert_edge(g, d, e), ops::try_insert_edge(g, d, e)),
        Operator::InsertDanglingEdge => (ops::can_insert_dangling_edge(g, d), ops::try_insert_dangling_edge(g, d)),
        Operator::RemoveCell => {
            (ops::is_removable_keeping_homology(g, d, i), ops::try_remove_cell_keeping_homology(g, d, i))
        }
        Operator::ContractCell => {
            (ops::is_contractible_keeping_homology(g, d, i), ops::try_contract_cell_keeping_homology(g, d, i))
        }
        Operator::SplitCell => (ops::can_split_cell(g, &[d, e], i), ops::try_split_cell(g, &[d, e], i)),
    };
    Attempt { allowed, result }
}

/// [`attempt`] at a place given by plain numbers: `d` and `e` are the darts of ranks
/// `pick % N` and `pick2 % N` in the order of [`GMap::darts`] (N darts), and
/// `i = dim % (n + 1)`. `None` for a map without darts. O(N) on top of [`attempt`].
pub fn attempt_at<A: Attributes>(
    g: &mut GMap<A>,
    op: Operator,
    pick: usize,
    pick2: usize,
    dim: usize,
) -> Option<Attempt> {
    let darts: Vec<DartId> = g.darts().collect();
    if darts.is_empty() {
        return None;
    }
    let (d, e) = (darts[pick % darts.len()], darts[pick2 % darts.len()]);
    let i = dim % (g.dim() + 1);
    Some(attempt(g, op, d, e, i))
}

/// `steps` random attempts on `g`: each draws a dart `d` of `g`, an operator of `choices`
/// (repeat an operator to draw it more often), and what that operator needs — for
/// [`Operator::InsertEdge`] and [`Operator::SplitCell`] a dart `e` of the face of `d`, for
/// [`Operator::RemoveCell`] a dimension `i < n`, for [`Operator::ContractCell`] and
/// [`Operator::SplitCell`] a dimension `1 <= i <= n`. Returns the classical names of the
/// operators applied, in order. O(steps · N) on top of the attempts.
///
/// # Panics
/// If `choices` is empty, `g` has no dart, or a removal is drawn in a 0-map; and when an operator's predicate disagrees
/// with its `try_` form (a bug of [`ops`]).
pub fn random_steps<A: Attributes>(
    g: &mut GMap<A>,
    steps: usize,
    choices: &[Operator],
    rng: &mut SplitMix64,
) -> Vec<String> {
    let n = g.dim();
    let mut applied = Vec::new();
    for _ in 0..steps {
        let darts: Vec<DartId> = g.darts().collect();
        let d = darts[rng.below(darts.len())];
        let op = choices[rng.below(choices.len())];
        let in_face = |g: &GMap<A>, rng: &mut SplitMix64| {
            let face = g.orbit(d, AlphaSet::of(&[0, 1]));
            face[rng.below(face.len())]
        };
        let (e, i) = match op {
            Operator::InsertEdge => (in_face(g, rng), 0),
            Operator::RemoveCell => (d, rng.below(n)),
            Operator::ContractCell => (d, 1 + rng.below(n)),
            Operator::SplitCell => (in_face(g, rng), 1 + rng.below(n)),
            Operator::InsertVertex | Operator::InsertDanglingEdge => (d, 0),
        };
        let tried = attempt(g, op, d, e, i);
        assert!(
            tried.consistent(),
            "{op:?} at {d:?}: the predicate said {}, the operator {:?}",
            tried.allowed,
            tried.result
        );
        if let Ok(done) = tried.result {
            applied.push(done.name);
        }
    }
    applied
}
