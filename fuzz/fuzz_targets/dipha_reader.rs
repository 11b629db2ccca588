//! Fuzzes the DIPHA `.complex` reader (image data): it must never panic; an image it
//! accepts has 1 to 8 axes, no empty axis, `f64` values in Fortran order, as many as its
//! shape says; written back as DIPHA it reads to the same values.
#![no_main]

use gmap_ops::import::image::{Dtype, Image, Order};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(img) = Image::parse_dipha(data.to_vec()) else { return };
    assert!((1..=8).contains(&img.dim()));
    assert!(img.shape().iter().all(|&s| s > 0), "an empty axis accepted: {:?}", img.shape());
    assert_eq!(img.dtype(), Dtype::F64);
    assert_eq!(img.order(), Order::Fortran);
    let len: usize = img.shape().iter().product();
    assert_eq!(img.len(), len);
    assert_eq!(img.raw().len(), 8 * len);
    if len <= 1 << 12 {
        let dir = std::env::temp_dir().join(format!("gmap-fuzz-dipha-{}", std::process::id()));
        let _ = std::fs::create_dir_all(&dir);
        let path = dir.join("x.complex");
        img.write_dipha(&path).expect("write");
        let back = Image::read_dipha(&path).expect("a written DIPHA image reads back");
        assert_eq!(back.shape(), img.shape());
        for i in 0..len {
            let (a, b) = (img.value(i), back.value(i));
            assert!(a == b || (a.is_nan() && b.is_nan()), "value {i}: {a} then {b}");
        }
    }
});
