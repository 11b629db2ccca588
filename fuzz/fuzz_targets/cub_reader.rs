//! Fuzzes the `.cub` reader: it must never panic; a set it accepts has a consistent box and
//! bitmap, its cubes written back as `.cub` read to the same set, and on small boxes the
//! cubical complex (collapsed or plain, periodic or not) and the G-map of the union agree
//! where the G-map applies.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "shared/mod.rs"]
mod shared;

fuzz_target!(|data: &[u8]| {
    let Ok(s) = gmap_ops::import::cubical::parse_cub(data) else { return };
    shared::check_set(&s);
    // the box is the bounding box of the cubes: each axis has a cube at both ends
    assert!(s.cube_count() >= 1);
    if s.bits().len() <= 1 << 16 {
        let again =
            gmap_ops::import::cubical::parse_cub(shared::cub_text(&s).as_bytes()).expect("written cubes read back");
        assert_eq!(again, s);
    }
    shared::check_cubical_routes(&s);
});
