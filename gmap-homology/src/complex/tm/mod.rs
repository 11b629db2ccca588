//! The boundary/coboundary model of TM ("topological models for architectural and
//! engineering projects"), in any dimension (the paper's 2D and 3D manifolds included).
//!
//! Cells are joined by incidences; each incidence of a (k-1)-cell on a k-cell occurs a
//! number of times with each orientation (on a G-map: the elements of the face-operator
//! preimage, counted by sign; the cylinder's seam occurs once with each sign). The model
//! works on [`SignedSet`]s: sets of cells where positive and negative occurrences are
//! kept apart, each with a multiplicity (TM §IV).
//!
//! [`TmModel`] is the paper's structure (6:1) `(C^k, Z^k, Y^k, B, G)`, stored as its file
//! layout (TM §XI, Figs. 3 and 4): every cell is an entry under the key of its dimension
//! `C^k` ([`TmModel::regions_of_dim`]) and holds its bounding circuit `B(c)`, a member of
//! `Z_B^{k-1}` ([`TmModel::bounding`], [`TmModel::bounding_circuits`]), and its cobounding
//! cocircuit `G(c)`, a member of `Y_G^{k+1}` ([`TmModel::cobounding`],
//! [`TmModel::cobounding_cocircuits`]); [`TmModel::file_layout`] names the set each key
//! holds in the paper's figures. On this structure:
//! * the boundary `B` and the coboundary `G` of a set ([`TmModel::boundary`],
//!   [`TmModel::coboundary`]), amalgamated with signs and multiplicities;
//! * the *view* `(1 - B)^{-1} c = c + Bc + B²c + …` (a cell with its complete boundary) and
//!   the *section* `(1 - G)^{-1} c` (a cell with everything above it), TM (7:1), (7:2),
//!   annotated with the near and far n-cells `G c^{n-1}` (7:3) and the from and to 0-cells
//!   `B c^1` (7:4) ([`TmModel::try_annotated_view`], [`TmModel::try_annotated_section`]);
//! * circuits (every bounding cell occurs as often with each orientation; for 0-cells the
//!   coefficients sum to zero, TM §VI) and, dually, cocircuits;
//! * the topological edit check (TM §XI, (7:5), (7:6)): the boundary of every cell is a
//!   circuit and the coboundary of every cell a cocircuit; the offending cell and the
//!   condition are named ([`TmDefect`]). An open model (one with a boundary) fails (7:6) on
//!   its free (n-1)-cells; [`TmModel::try_close_with_exterior`] adds the exterior n-cell
//!   that closes it.
//!
//! Poincaré duality: [`TmModel::dual`] swaps dimensions k and n - k and swaps `B` with
//! `G` (the incidence graph transposed); on a G-map it is the model of the dual map
//! (`DenseMap::dual`), as the tests check.
//!
//! ```
//! use gmap_core::{Dart, DenseMap};
//! use gmap_homology::tm::{SignedSet, TmModel};
//! // a square: 4 vertices, 4 edges, 1 face
//! let mut m = DenseMap::new(2, 8);
//! for k in 0..4u32 {
//!     m.link(Dart::new(2 * k), Dart::new(2 * k + 1), 0);
//!     m.link(Dart::new(2 * k + 1), Dart::new((2 * k + 2) % 8), 1);
//! }
//! let t = TmModel::from_map(&m).unwrap();
//! let face = t.regions_of_dim(2)[0];
//! let view = t.view(&SignedSet::cell(face));
//! assert_eq!(view.len(), 9); // the face, its 4 edges, its 4 vertices
//! // the boundary of the face is a circuit; the disc's free edges are not cocircuits
//! assert!(t.is_circuit(t.bounding(face), 1));
//! assert!(t.edit_check().is_err());
//! // closed by an exterior face, the disc becomes a sphere and passes
//! let (closed, _exterior) = t.try_close_with_exterior(100).unwrap();
//! assert_eq!(closed.edit_check(), Ok(()));
//! ```

mod annotate;
mod check;
mod signed;

pub use annotate::{Ends, Section, Sides, View};
pub use check::TmDefect;
pub use signed::SignedSet;

mod model;
pub use model::{TmError, TmModel, TmSet};
