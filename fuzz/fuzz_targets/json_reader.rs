//! Fuzzes the `.json` reader of architectural complexes (gmap-homology, read only): never a
//! panic; an accepted complex writes back to JSON that reads to the same complex.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let Ok(x) = gmap_homology::json::read_json(text) else { return };
    let again = gmap_homology::json::read_json(&gmap_homology::json::write_json(&x)).expect("written JSON reads back");
    assert_eq!(again.region_counts(), x.region_counts());
    assert_eq!(again.entries().len(), x.entries().len());
    if x.regions().len() < 200 {
        let _ = x.homology_z();
    }
});
