//! Fuzzes the `.off` reader: it must never panic, and a mesh it accepts must become a valid
//! 2-map (or be refused with an error) whose `.off` export, when there is one, reads back.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(mesh) = gmap_ops::import::PolygonMesh::parse_limited(text, 1 << 16) else { return };
    let Ok(m) = mesh.to_gmap() else { return };
    assert!(m.validate().is_ok());
    if let Ok(out) = gmap_ops::export::off_string(&m) {
        let back = gmap_ops::import::PolygonMesh::parse(&out).expect("the writer's .off reads back");
        let back = back.to_gmap().expect("the writer's .off makes a map");
        assert!(gmap_ops::iso::are_isomorphic(&m, &back));
    }
});
