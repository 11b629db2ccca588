//! Fuzzes the whole pipeline: bytes → read → validation → homology by every route that
//! applies, each allowed to refuse with an error, none to panic, and those that answer must
//! agree. The same bytes are tried as
//! - a `.gmap` map: the cellular method (when C1 and C2 hold), the simplicial counterpart
//!   (small maps) and `--simplify` (the simplified map's cellular groups);
//! - a `.facets` complex: the direct route (every face a cell) and the G-map route, which must
//!   agree where the complex is a pseudo-manifold glued through ridges;
//! - a `.cub` cubical set: the cubical complex, collapsed or not, periodic or not, and the
//!   G-map of the union where it applies.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "shared/mod.rs"]
mod shared;

fuzz_target!(|data: &[u8]| {
    let opts = gmap_core::io::ReadOptions { max_darts: Some(4096) };
    if let Ok(m) = gmap_core::io::parse_gmap_with(data, "fuzz.gmap", &opts) {
        shared::check_map_routes(&m);
    }
    if let Ok(text) = std::str::from_utf8(data) {
        if let Ok(sc) = gmap_ops::import::SimplicialComplex::parse_facets(text) {
            shared::check_simplicial_routes(&sc);
        }
    }
    if let Ok(s) = gmap_ops::import::cubical::parse_cub(data) {
        shared::check_cubical_routes(&s);
    }
});
