//! Fuzzes the reader of CGAL's XML generalized maps (`.cgal.xml`): it must never panic, and
//! whatever it accepts must be a valid map whose written form reads back with the same darts
//! and links, and writes again to the same text.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    if let Ok(m) = gmap_ops::import::parse_cgal_xml(text, Some(1 << 16)) {
        assert!(m.validate().is_ok());
        let written = gmap_ops::import::format_cgal_xml(&m);
        let back = gmap_ops::import::parse_cgal_xml(&written, None).unwrap();
        assert_eq!(back.dim(), m.dim());
        assert_eq!(back.dart_count(), m.dart_count());
        for d in m.darts() {
            assert_eq!(back.row(d), m.row(d));
        }
        assert_eq!(gmap_ops::import::format_cgal_xml(&back), written);
        let _ = m.cell_counts_and_components();
    }
});
