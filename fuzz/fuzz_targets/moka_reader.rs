//! Fuzzes the Moka `.moka` byte parser: it must never panic, and whatever it accepts must
//! be a valid 3-map that survives a write/read round trip (points included).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let opts = gmap_core::io::ReadOptions { max_darts: Some(1 << 16) };
    if let Ok(m) = gmap_core::io::parse_moka_with(data, "fuzz.moka", &opts) {
        assert_eq!(m.dim(), 3);
        assert!(m.validate().is_ok());
        let text = gmap_core::io::format_moka(&m).unwrap();
        assert_eq!(gmap_core::io::parse_moka(&text, "again.moka").unwrap(), m);
        let _ = m.cell_counts_and_components();
        let _ = m.orientation();
        let _ = m.check_complete_boundaries();
    }
});
