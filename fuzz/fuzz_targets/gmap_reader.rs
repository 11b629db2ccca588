//! Fuzzes the native `.gmap` byte parser: it must never panic, and whatever it accepts
//! must be a valid map that survives a write/read round trip and the whole-map queries.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let opts = gmap_core::io::ReadOptions { max_darts: Some(1 << 16) };
    if let Ok(m) = gmap_core::io::parse_gmap_with(data, "fuzz.gmap", &opts) {
        assert!(m.validate().is_ok());
        let text = gmap_core::io::format_gmap(&m);
        assert_eq!(gmap_core::io::parse_gmap(&text, "again.gmap").unwrap(), m);
        let (counts, _components) = m.cell_counts_and_components();
        assert_eq!(counts.len(), m.dim() + 1);
        let _ = m.orientation();
        let _ = m.check_complete_boundaries();
        let _ = m.check_cells_orientable();
    }
});
