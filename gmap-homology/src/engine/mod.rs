//! The homology engine: groups and generators of any chain complex over `Z` or `Z/p`, knowing nothing of where its cells came from.

pub mod chain;
pub mod field;
pub mod generators;
pub mod homology;
pub(crate) mod morse;
pub mod natural;
pub(crate) mod reduce;
pub(crate) mod ring;
pub(crate) mod snf;
pub(crate) mod snf_modular;
pub mod sparse;
