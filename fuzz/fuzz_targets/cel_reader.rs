//! Fuzzes the `.cel` reader (CHomP's cubical cell lists, `[0,1] x [2] x …` or doubled
//! coordinates, read by the `.cub` parser): it must never panic; a complex it accepts has a
//! consistent box, bitmap and lower cells, and on small boxes its cubical routes agree (a
//! set with lower cells goes through the cubical complex only).
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "shared/mod.rs"]
mod shared;

fuzz_target!(|data: &[u8]| {
    let Ok(s) = gmap_ops::import::cubical::parse_cub(data) else { return };
    shared::check_set(&s);
    shared::check_cubical_routes(&s);
});
