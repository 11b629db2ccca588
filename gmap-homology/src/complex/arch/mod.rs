//! Architectural complexes (AC §3): regions graded by dimension and a *partial* boundary
//! matrix, whose entries are either defined (an integer, zero allowed) or absent.
//!
//! An [`ArchComplex`] is a finite set of regions, each with a user id (`u64`) and a
//! dimension, and a list of defined entries `δ(from, to) = weight` where `from` is a region
//! of higher dimension than `to` (AC Def. 3.1). The entries are the edges of the underlying
//! weighted DAG, the *incidence graph* (AC Lemma 3.2). Construction validates the whole of
//! AC Def. 3.1 and names the offending entry ([`ArchError`]):
//! 1. entries go from a higher to a strictly lower dimension (so the graph is acyclic — a
//!    cycle is reported as such, before the dimension check);
//! 2. an entry across a dimension gap of two or more has weight 0;
//! 3. the partial product `δ²` (rules `a + undefined = a`, `a · undefined = undefined`) has
//!    only zero entries where it is defined.
//!
//! The topology of AC §3.2 is available through stars ([`ArchComplex::star`]: regions with a
//! path *to* a region), closures ([`ArchComplex::closure`]: regions reached *from* a region),
//! open and closed sets and the T0 separation of Axiom 3.6. Homology is that of the
//! *completion by zero* (AC Def. 3.8, 3.9): [`ArchComplex::boundary_entries`] lists its
//! non-zero entries between consecutive dimensions (entries across a gap are zero by
//! Def. 3.1), and [`crate::complex::arch::ArchComplex::euler_characteristic`] is the left side of the
//! Euler–Poincaré formula (AC Cor. 3.11).
//!
//! Algorithm 8.16 (turning a realisable complex into a cw-complex with the same
//! topological Betti numbers) for the constructive cases of AC Example 8.19 is
//! [`ArchComplex::topological`].
//!
//! ```
//! use gmap_homology::arch::{ArchComplex, Region, RegionId};
//! // The left graph of AC Figure 2 / Table 1: a = Q - P, b = R - Q, c a loop at Q.
//! let [p, q, r, a, b, c] = [0, 1, 2, 3, 4, 5].map(RegionId);
//! let regions = [(p, 0), (q, 0), (r, 0), (a, 1), (b, 1), (c, 1)].map(|(id, dim)| Region { id, dim });
//! let entries = vec![(a, p, -1), (a, q, 1), (b, q, -1), (b, r, 1), (c, q, 0)];
//! let x = ArchComplex::try_new(1, regions.to_vec(), entries).unwrap();
//! assert_eq!(x.region_counts(), vec![3, 3]);
//! assert_eq!(x.euler_characteristic(), 0);
//! // the defined zero keeps the loop attached to Q: Q is in the closure of c
//! let ci = x.index_of(c).unwrap();
//! assert_eq!(x.closure(ci), vec![x.index_of(q).unwrap(), ci]);
//! ```
//!
//! Complexities: construction O(R + E + Σ_b outdeg(b)·outdeg of its targets) for the δ²
//! check; stars and closures O(size of the result + its entries).

mod from_map;
mod metric;
mod model;
mod names;
mod orient;
mod snap;
mod topological;
mod topology;

pub use from_map::{all_cell_incidences, cell_incidences, CellIncidence, FromMapError};
pub use metric::{MetricDefect, NamedDefect, Shape};
pub use model::{ArchComplex, ArchError, Entry, Region, RegionId};
pub use names::{Named, RegionNames};
pub use orient::orient_entries;
pub use snap::{snap, Snapped};
pub use topological::{AppliedOperator, Step, Topological, ZeroWeightRule};
