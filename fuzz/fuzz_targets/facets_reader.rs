//! Fuzzes the `.facets` and `.lex` parsers and the simplicial importer: never a panic, and
//! whatever is accepted is a valid map within the dart limit.
#![no_main]

use gmap_ops::import::SimplicialComplex;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    for sc in [SimplicialComplex::parse_facets(text), SimplicialComplex::parse_lex(text, None)].into_iter().flatten() {
        if let Ok(m) = sc.to_gmap(1 << 14) {
            assert!(m.dart_count() <= 1 << 14);
            assert!(m.validate().is_ok());
            let _ = m.cell_counts_and_components();
        }
    }
});
