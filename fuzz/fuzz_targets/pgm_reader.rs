//! Fuzzes the `.pgm` reader (`P2` text, `P5` binary, 8 or 16 bits): it must never panic; an
//! image it accepts is 2-D, rows × columns with none empty, `u8` or `u16` values in C order;
//! written back as `P2` and as `P5` (the largest value of its type as maxval) it reads to the
//! same values; on small images the cubical set of the non-zero pixels has agreeing routes.
#![no_main]

use gmap_ops::import::image::{Image, Order};
use gmap_ops::import::raster::parse_pgm;
use libfuzzer_sys::fuzz_target;

#[path = "shared/mod.rs"]
mod shared;

fuzz_target!(|data: &[u8]| {
    let Ok(img) = parse_pgm(data) else { return };
    let (h, w, sixteen) = shared::check_grey_raster(&img, "PGM");
    let maxval = if sixteen { 65535 } else { 255 };
    let values: Vec<u16> = (0..img.len()).map(|i| img.value(i) as u16).collect();
    // P2: decimal tokens; P5: one byte or two big-endian bytes a pixel
    let mut p2 = format!("P2\n{w} {h}\n{maxval}\n").into_bytes();
    let mut p5 = format!("P5\n{w} {h}\n{maxval}\n").into_bytes();
    for &v in &values {
        p2.extend_from_slice(format!("{v}\n").as_bytes());
        if sixteen {
            p5.extend_from_slice(&v.to_be_bytes());
        } else {
            p5.push(v as u8);
        }
    }
    for again in [p2, p5] {
        let back = parse_pgm(&again).expect("a written PGM reads back");
        assert_eq!(back.shape(), img.shape());
        assert_eq!(back.dtype(), img.dtype());
        assert_eq!(back.raw(), img.raw());
    }
    shared::check_small_raster_routes(&img);
    let _ = Image::from_values(&[h, w], Order::C, values);
});
