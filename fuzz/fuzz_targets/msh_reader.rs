//! Fuzzes the `.msh` reader: it must never panic; a mesh it accepts makes a valid labelled
//! map or is refused with an error, and the map's `.vtk` reads back to the same cells and
//! labels (`shared::check_mesh`).
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "shared/mod.rs"]
mod shared;

fuzz_target!(|data: &[u8]| {
    let Ok(file) = gmap_ops::import::parse_msh(data) else { return };
    shared::check_mesh(&file.mesh);
});
