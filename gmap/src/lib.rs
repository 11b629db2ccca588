//! # gmap: generalized maps, their construction and their homology
//!
//! The front door of the workspace: open any input, run any route, save in any format. The
//! `gmap` command and the Python package are thin layers over these calls; a Rust program
//! gets exactly what they print.
//!
//! ```
//! // examples/open_any.rs: one file of each kind, its characteristics, route and groups
//! fn main() -> Result<(), gmap::Error> {
//!     let files = ["labelled_segment.gmap", "lutz/poincare.facets", "cubical/ring.cub", "arch/tetrahedron.json"];
//!     for file in files {
//!         let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data").join(file);
//!         let input = gmap::open(&path)?;
//!         let info = gmap::info(&input, &gmap::InfoOptions::default())?;
//!         let report = gmap::homology(&input, &gmap::HomologyOptions::default())?;
//!         println!("{file}: {} {}, route {}, {}", input.kind(), info.to_json(), report.route_name(), report.groups);
//!     }
//!     Ok(())
//! }
//! ```
//!
//! The groups as data, and the route the command line would take:
//!
//! ```
//! let input = gmap::open(concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/lutz/poincare.facets"))?;
//! let report = gmap::homology(&input, &gmap::HomologyOptions::default())?;
//! assert_eq!(report.groups.betti, vec![1, 0, 0, 1]);
//! assert_eq!(report.route, Some(gmap::Via::Direct));
//! # Ok::<(), gmap::Error>(())
//! ```
//!
//! ## How an input flows
//!
//! ```text
//! file ──formats (registry: extension → reader → kind)──▶ Input
//!   ──route::plan──▶ Route ──Route::run──▶ chain complex (chains, cubes) ──reduce──▶ Report
//! ```
//!
//! * [`formats`] is the one table of file formats: the reader of each extension, the kind of
//!   [`Input`] it makes, its writer and what the writer keeps; [`open`] reads any file by it
//!   and applies the memory policy, [`save()`] writes by it;
//! * [`plan`] ([`mod@route`]) chooses the [`Route`] of an input as the command line does, and
//!   [`Route::run`] builds the chain complex (`chains` for maps, simplicial and
//!   architectural complexes, [`cubes`] for cubical sets, images and cubes borrowed from
//!   memory), reduces it (fill-free pass, elimination, Smith form) and names the generators
//!   in the input's own terms; [`homology()`] is the two in one call, [`homology_cubes`] the
//!   same for a numpy array read in place; the [`Report`] and its printing are in
//!   [`report`];
//! * [`routes`] ([`mod@bench`]) runs and times every route of an input
//!   ([`route::candidates`]);
//! * [`info()`] ([`mod@info`]) gives the characteristics;
//! * [`view()`] ([`mod@view`]) writes one self-contained HTML page to look at the input (darts,
//!   cells coloured by a label, generators, or the faces of a simplicial complex without a
//!   G-map) in a browser;
//! * [`room_graph`] ([`mod@dual`]) gives the dual graphs of the rooms (through faces,
//!   apertures, to the exterior), as TopologicPy's `Graph.ByTopology`;
//! * [`persistence()`] ([`mod@persistence`]) computes persistence diagrams of images,
//!   valued complexes and labelled maps;
//! * [`simplify_if_safe`] reduces a map by removals and contractions where that keeps the
//!   groups;
//! * [`distributed`] cuts one image across processes (the `gmap-mpi` binary runs it on MPI
//!   ranks): each reduces its slab, process 0 glues them.
//!
//! Errors are one type, [`Error`], with a kind ([`ErrorKind`]: parse, limit, precondition,
//! usage, …), the message the command line prints, the offending [`Item`] and the library's
//! typed error as its `source()`.
//!
//! The three crates below are re-exported for everything else:
//!
//! * [`core`] (`gmap-core`): the kernel — darts, involutions, orbits, cells, marks,
//!   validity, orientation, compacted cells, face operators, the dual, file formats;
//! * [`ops`] (`gmap-ops`): making and changing maps — builders, importers, sewing,
//!   Euler operators, exporters;
//! * [`algebra`] (`gmap-homology`): incidence numbers, the cellular border operator,
//!   homology over Z and Z/p, persistence, architectural complexes, LAR and TM models.

pub use gmap_core as core;
pub use gmap_homology as algebra;
pub use gmap_ops as ops;

mod arch_cells;
pub mod bench;
mod cell_name;
mod chains;
pub mod cubes;
pub mod curves;
pub mod demo;
pub mod distributed;
pub mod dual;
mod error;
pub mod formats;
mod graph;
pub mod homotopy;
pub mod info;
pub mod input;
mod open;
mod options;
pub mod persistence;
mod pinch;
pub mod progress;
mod read;
pub mod report;
pub mod rooms;
pub mod route;
pub mod save;
pub mod tm;
pub mod view;
mod write;

pub use bench::{routes, RouteRun, Times};
pub use chains::{check_simplicial_size, face_complex_within, simplify_if_safe};
pub use cubes::CubesRef;
pub use dual::{room_graph, room_graph_of, Dual, RoomEdge, RoomGraph, RoomNode};
pub use error::{Error, ErrorKind, Item, Result};
pub use formats::{Format, FORMATS};
pub use info::{info, Info, InfoOptions};
pub use input::{Input, Kind, MapInput, OpenOptions, Sourced};
pub use open::{open, open_with};
pub use options::{HomologyOptions, Method, Via};
pub use persistence::{
    lower_star, lower_star_file, persistence, persistence_file, Persistence, PersistenceOptions, VertexValues,
};
pub use progress::Progress;
pub use report::{ArchSpace, CellName, Chain, CubeGrid, NamedGenerator, Report};
pub use rooms::{rooms_file, rooms_of, Rooms};
pub use route::{homology, homology_cubes, homology_file, plan, Route};
pub use save::{save, save_file, SaveOptions};
pub use tm::{tm_check, tm_check_file, tm_views, tm_views_file, TmCheck};
pub use view::{view, ViewOptions};
