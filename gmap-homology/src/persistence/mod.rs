//! # Persistent homology of filtered cell complexes
//!
//! A filtration gives each cell a value no smaller than its faces' values; the persistence
//! diagram records, for each dimension, when a homology class is born and when it dies
//! (`+inf` if it never does), over `Z/p`. This module computes it for
//!
//! * grey images in any dimension ([`image`]): T- and V-constructions, sublevel and
//!   superlevel, periodic; and images too large to hold, read pixel by pixel, through the
//!   Morse complex of the discrete gradient of their lower stars ([`gradient`], 1 to 4 axes,
//!   not periodic);
//! * complexes given cell by cell with their boundaries ([`filtered`]): simplicial complexes
//!   with a value per simplex, per facet (a face takes the minimum of its cofacets, GUDHI's
//!   `SimplexTree` convention) or per vertex (lower star), and any cell complex with a value
//!   per cell (a cell's value is raised to the maximum of its faces').
//!
//! Cells are ordered by (value, dimension, index). The reduction (`pairing`, private) works
//! one dimension at a time from the top down with clearing; images take dimension 0, and
//! dimension d-1 when not periodic, from union-find instead. On request every pair comes
//! with a representative cycle in the input's terms ([`CellName`]): for a finite pair the
//! reduced column of its death cell (a cycle made of cells no later than the birth cell,
//! whose class is not a boundary before the death value and is one at it), for an
//! essential class the chain of cells whose boundary reduced to zero.
//!
//! Pairs of zero persistence (birth equal to death) are left out, as GUDHI does.
//!
//! [`plot`] draws diagrams, barcodes and a 2-D image with a cycle over it as SVG.

mod diagram;
pub mod filtered;
pub mod gradient;
pub mod image;
mod lower_star;
mod options;
pub(crate) mod pairing;
pub mod plot;

pub use diagram::{CellName, Chain, Diagram, Pair, PersistenceError};
pub use filtered::{FilteredComplex, SimplexValues};
pub use gradient::morse_persistence;
pub use image::{cubical_persistence, memory_estimate, Construction, CubicalFiltration, CubicalOptions};
