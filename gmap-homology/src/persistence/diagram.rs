//! The result of a persistence computation: pairs (dimension, birth, death), their cycles
//! named in the input's terms, and the error. A leaf of the module: the filtrations fill a
//! [`Diagram`], the plots read one.

use serde::Serialize;
use thiserror::Error;

/// Why a persistence diagram could not be computed.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum PersistenceError {
    /// The input does not describe a filtration.
    #[error("bad input: {0}")]
    BadInput(String),
    /// An option is out of range.
    #[error("bad option: {0}")]
    BadOption(String),
    /// The complex is past the 32-bit cell indices.
    #[error("too large: {0}")]
    TooLarge(String),
}

/// A cell named in the input's terms.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(untagged)]
#[non_exhaustive]
pub enum CellName {
    /// an image cell by its doubled-grid coordinates (see [`crate::cubical::grid`])
    Grid(Vec<usize>),
    /// a simplex by its sorted vertex labels
    Simplex(Vec<u64>),
    /// a cell of a cell complex by dimension and a number: for a G-map, the cell's
    /// smallest dart
    Cell {
        /// dimension
        dim: usize,
        /// the cell's number (a G-map's: its smallest dart)
        index: usize,
    },
    /// a region of an architectural complex by dimension and id
    Region {
        /// dimension
        dim: usize,
        /// the region's id in its file
        id: u64,
    },
}

/// How messages and the command line name a cell: a grid cell by its coordinates
/// (`[3, 4]`), a simplex by its vertex labels (`[1, 2]`), a map's cell by its
/// smallest dart (`1-cell of dart 8`), a region by its id (`1-region 5`).
impl std::fmt::Display for CellName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CellName::Grid(x) => write!(f, "{x:?}"),
            CellName::Simplex(x) => write!(f, "{x:?}"),
            CellName::Cell { dim, index } => write!(f, "{dim}-cell of dart {index}"),
            CellName::Region { dim, id } => write!(f, "{dim}-region {id}"),
        }
    }
}

/// One point of a persistence diagram.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Pair {
    /// dimension of the class
    pub dim: usize,
    /// value at which it is born
    pub birth: f64,
    /// value at which it dies (`inf` if never; `-inf` for a superlevel filtration)
    pub death: f64,
}

/// A chain with coefficients in `Z/p` (`1..p`) on named cells.
pub type Chain = Vec<(CellName, u32)>;

/// The birth cell and, for a finite pair, the death cell of a pair.
type PairCells = (CellName, Option<CellName>);

/// A persistence diagram over `Z/p`, with a representative cycle per pair if asked for.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Diagram {
    /// the prime `p`
    pub field: u32,
    /// the pairs, sorted by dimension, birth, death
    pub pairs: Vec<Pair>,
    /// `cycles[i]` represents `pairs[i]` (empty unless cycles were asked for)
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub cycles: Vec<Chain>,
    /// `cells[i]`: the cell whose entry gives `pairs[i]` its birth and, for a finite pair,
    /// the cell whose entry kills it (filled alongside `cycles`, empty without them)
    #[serde(skip)]
    pub cells: Vec<(CellName, Option<CellName>)>,
}

/// A pair's representative cycle with the cells that give it its birth and death.
pub(crate) type Named = (Chain, CellName, Option<CellName>);

impl Diagram {
    pub(crate) fn new(field: u32) -> Self {
        Diagram { field, pairs: Vec::new(), cycles: Vec::new(), cells: Vec::new() }
    }

    /// Records a pair from internal (sign-multiplied) values, unless of zero persistence.
    pub(crate) fn push(&mut self, dim: usize, birth: f64, death: f64, sign: f64, cycle: Option<Named>) {
        if birth == death {
            return;
        }
        self.pairs.push(Pair { dim, birth: sign * birth, death: sign * death });
        if let Some((c, born, dies)) = cycle {
            self.cycles.push(c);
            self.cells.push((born, dies));
        }
    }

    /// Sorts the pairs (and their cycles alike).
    pub(crate) fn finish(&mut self) {
        // by dimension, birth, death; values are never NaN, so `total_cmp` is their order
        let order =
            |p: &Pair, q: &Pair| p.dim.cmp(&q.dim).then(p.birth.total_cmp(&q.birth)).then(p.death.total_cmp(&q.death));
        if self.cycles.len() == self.pairs.len() && !self.cycles.is_empty() {
            let mut all: Vec<(Pair, (Chain, PairCells))> =
                self.pairs.drain(..).zip(self.cycles.drain(..).zip(self.cells.drain(..))).collect();
            all.sort_by(|(p, _), (q, _)| order(p, q));
            let (pairs, rest): (Vec<Pair>, Vec<_>) = all.into_iter().unzip();
            self.pairs = pairs;
            (self.cycles, self.cells) = rest.into_iter().unzip();
        } else {
            // pairs equal in the order are equal: an unstable sort gives the same list
            self.pairs.sort_unstable_by(order);
        }
    }

    /// The pairs of dimension `k`.
    pub fn dimension(&self, k: usize) -> impl Iterator<Item = &Pair> + '_ {
        self.pairs.iter().filter(move |p| p.dim == k)
    }

    /// The number of classes alive at `+inf` per dimension (the Betti numbers of the whole
    /// complex over `Z/p`).
    pub fn essential_counts(&self) -> Vec<usize> {
        let top = self.pairs.iter().map(|p| p.dim + 1).max().unwrap_or(0);
        let mut b = vec![0; top];
        for p in self.pairs.iter().filter(|p| p.death.is_infinite()) {
            b[p.dim] += 1;
        }
        b
    }

    /// The diagram as JSON: `{"field": p, "pairs": [[dim, birth, death], …], "cycles": …}`,
    /// infinities written as the strings `"inf"` and `"-inf"`.
    pub fn to_json(&self) -> serde_json::Value {
        let num = |x: f64| {
            if x.is_finite() {
                serde_json::json!(x)
            } else if x > 0.0 {
                serde_json::json!("inf")
            } else {
                serde_json::json!("-inf")
            }
        };
        let pairs: Vec<serde_json::Value> =
            self.pairs.iter().map(|p| serde_json::json!([p.dim, num(p.birth), num(p.death)])).collect();
        let mut v = serde_json::json!({ "field": self.field, "pairs": pairs });
        if !self.cycles.is_empty() {
            v["cycles"] = serde_json::to_value(&self.cycles).expect("cycles serialize");
        }
        v
    }
}
