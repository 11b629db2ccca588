//! Fuzzes the `.png` reader (grey, 1 to 16 bits, through the `png` crate): it must never
//! panic; an image it accepts is 2-D, rows × columns with none empty, `u8` or `u16` values in
//! C order; encoded again as a grey PNG of its depth it reads to the same values; on small
//! images the cubical set of the non-zero pixels has agreeing routes.
#![no_main]

use gmap_ops::import::raster::parse_png;
use libfuzzer_sys::fuzz_target;

#[path = "shared/mod.rs"]
mod shared;

fuzz_target!(|data: &[u8]| {
    let Ok(img) = parse_png(data) else { return };
    let (h, w, sixteen) = shared::check_grey_raster(&img, "PNG");
    let mut pixels = Vec::with_capacity(img.len() * if sixteen { 2 } else { 1 });
    for i in 0..img.len() {
        let v = img.value(i) as u16;
        if sixteen {
            pixels.extend_from_slice(&v.to_be_bytes());
        } else {
            pixels.push(v as u8);
        }
    }
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, w as u32, h as u32);
        enc.set_color(png::ColorType::Grayscale);
        enc.set_depth(if sixteen { png::BitDepth::Sixteen } else { png::BitDepth::Eight });
        let mut writer = enc.write_header().expect("a PNG header");
        writer.write_image_data(&pixels).expect("the pixels");
    }
    let back = parse_png(&out).expect("a written PNG reads back");
    assert_eq!(back.shape(), img.shape());
    assert_eq!(back.dtype(), img.dtype());
    assert_eq!(back.raw(), img.raw());
    shared::check_small_raster_routes(&img);
});
