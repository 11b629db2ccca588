//! Fuzzes the `.pbm` reader (P1 and P4): it must never panic; a bitmap it accepts is a 2D
//! set on the whole image, written back as P1 and as P4 it reads to the same set, and on
//! small images the cubical complex and the G-map of the union agree where the G-map applies.
#![no_main]

use libfuzzer_sys::fuzz_target;

#[path = "shared/mod.rs"]
mod shared;

/// The set as P1 text and as P4 bytes.
fn written(s: &gmap_ops::import::CubicalSet) -> (Vec<u8>, Vec<u8>) {
    let (w, h) = (s.shape()[0], s.shape()[1]);
    let pixel = |x: usize, r: usize| s.bits()[(h - 1 - r) * w + x];
    let mut p1 = format!("P1\n{w} {h}\n").into_bytes();
    let mut p4 = format!("P4\n{w} {h}\n").into_bytes();
    for r in 0..h {
        let mut row = vec![0u8; w.div_ceil(8)];
        for x in 0..w {
            p1.push(b'0' + pixel(x, r));
            row[x / 8] |= pixel(x, r) << (7 - x % 8);
        }
        p1.push(b'\n');
        p4.extend_from_slice(&row);
    }
    (p1, p4)
}

fuzz_target!(|data: &[u8]| {
    let Ok(s) = gmap_ops::import::cubical::parse_pbm(data) else { return };
    shared::check_set(&s);
    assert_eq!(s.dim(), 2);
    assert_eq!(s.min(), &[0, 0]);
    if s.bits().len() <= 1 << 16 {
        let (p1, p4) = written(&s);
        assert_eq!(gmap_ops::import::cubical::parse_pbm(&p1).expect("written P1 reads back"), s);
        assert_eq!(gmap_ops::import::cubical::parse_pbm(&p4).expect("written P4 reads back"), s);
    }
    shared::check_cubical_routes(&s);
});
