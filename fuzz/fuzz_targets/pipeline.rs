//! Fuzzes the whole pipeline: bytes → `.gmap` parse → validation → homology, by the cellular
//! method when its preconditions (C1, C2) hold and by the simplicial method when the map is
//! small (fewer than 2,000 darts). When both apply they must give the same groups; each may
//! refuse with an error, none may panic.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let opts = gmap_core::io::ReadOptions { max_darts: Some(4096) };
    let Ok(m) = gmap_core::io::parse_gmap_with(data, "fuzz.gmap", &opts) else { return };
    assert!(m.validate().is_ok());
    let cellular = match gmap_homology::check_preconditions(&m) {
        Ok(_) => {
            let c = gmap_homology::cellular_complex(&m).expect("preconditions hold");
            gmap_homology::homology_z(&c.chain).ok()
        }
        Err(_) => None,
    };
    let simplicial = if m.dart_count() < 2000 {
        gmap_homology::homology_z(&gmap_homology::simplicial_complex(&m)).ok()
    } else {
        None
    };
    if let (Some(a), Some(b)) = (&cellular, &simplicial) {
        assert_eq!(a, b, "cellular and simplicial homology differ");
    }
});
