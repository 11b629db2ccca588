//! Stratified objects with incomplete boundaries and their Euler operators (EO).
//!
//! EO models a geometric object as a set of *strata* — connected open manifolds of
//! dimension d, not necessarily balls: a stratum may have k-holes (its k-th Betti number,
//! `k >= 1`), and may be *boundary-incomplete* (its closure adds points that are not in the
//! object, as an edge missing an end). Its Euler operators attach and detach strata,
//! subdivide and coalesce them, make and fill holes, and compact strata, without the
//! "boundary first" order of classical B-reps.
//!
//! * [`StratifiedObject`] keeps the two levels of EO's bookkeeping: the strata with their
//!   local holes (EO Theorem 1) and the components of the object with their global holes
//!   (EO Theorem 2), with [`EoCounts`] naming every term of both formulas.
//! * [`EoOperator`] is the catalogue: every operator the paper names, with its [`Family`],
//!   [`Scheme`] (the dimension-independent form), precondition and Euler-characteristic
//!   effect. [`StratifiedObject::apply`] applies one at [`EoArgs`]; it refuses, with the
//!   reason and leaving the object unchanged, an operator whose precondition fails or whose
//!   result would break an invariant ([`StratifiedObject::validate`]: both theorems agree,
//!   hole ranges, no lone open stratum marked complete, …).
//! * [`example_1`] and [`example_2`] are EO §4's examples step by step.
//! * In a G-map a boundary-incomplete stratum is a cell with darts free for some `alpha_k`,
//!   `k` below the cell's dimension ([`incomplete_cells`]); [`apply_on_gmap`] applies the
//!   G-map counterpart of an operator, [`StratifiedObject::from_map`] reads the stratified
//!   object a G-map carries.
//!
//! docs/EO.md maps each item of the paper to its code and its test.
//!
//! ```
//! use gmap_ops::euler::strata::{example_2, EoArgs, EoOperator, StratifiedObject};
//! let steps = example_2();
//! assert_eq!(steps.len(), 5);
//! assert_eq!(steps.last().unwrap().euler, 1); // a sphere with a loop attached
//!
//! // a lone open edge is never marked boundary-complete
//! let mut o = StratifiedObject::new();
//! let e = o.apply_named("me∞E∞", &EoArgs::new()).unwrap().new[0];
//! let before = o.clone();
//! assert!(o.apply_named("ke∞me", &EoArgs::new().s(e)).is_err());
//! assert_eq!(o, before);
//! assert_eq!(EoOperator::from_name("kffhmCCh").unwrap().euler_effect(), 0);
//! ```

mod catalogue;
mod examples;
mod gmap;
mod object;
mod schemes;

pub use catalogue::{EoArgs, EoOperator, Family, Scheme};
pub use examples::{example_1, example_2};
pub use gmap::{apply_on_gmap, incomplete_cells, map_counts};
pub use object::{Component, EoCounts, EoStep, StrataError, StratifiedObject, Stratum};

#[cfg(test)]
mod tests;
