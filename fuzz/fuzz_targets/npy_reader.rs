//! Fuzzes the `.npy` reader: it must never panic; an image it accepts has 1 to 8 axes, no
//! empty axis, a length that is the product of its shape and raw bytes of that many values;
//! its header written back (version 1.0 or 2.0) with the same values reads to the same
//! image; on small images every value reads and the cubical set of its nonzero values has
//! agreeing routes.
#![no_main]

use gmap_ops::import::image::Image;
use gmap_ops::import::Level;
use libfuzzer_sys::fuzz_target;

#[path = "shared/mod.rs"]
mod shared;

fuzz_target!(|data: &[u8]| {
    let Ok(img) = Image::parse_npy(data.to_vec()) else { return };
    check_image(&img);
    // the header written back with the same values: the same image
    let mut again = img.npy_header();
    again.extend_from_slice(img.raw());
    let back = Image::parse_npy(again).expect("a written header reads back");
    assert_eq!(back.shape(), img.shape());
    assert_eq!(back.dtype(), img.dtype());
    assert_eq!(back.order(), img.order());
    assert_eq!(back.raw(), img.raw());
});

/// What every image the readers accept holds.
fn check_image(img: &Image) {
    assert!((1..=8).contains(&img.dim()));
    assert!(img.shape().iter().all(|&s| s > 0), "an empty axis accepted: {:?}", img.shape());
    let len: usize = img.shape().iter().product();
    assert_eq!(img.len(), len);
    assert_eq!(img.raw().len(), len * img.dtype().size());
    if len <= 1 << 12 {
        for i in 0..len {
            let _ = img.value(i);
        }
        if let Ok(set) = img.to_cubical_set(Level::Nonzero) {
            shared::check_set(&set);
            if set.bits().len() <= 1 << 10 {
                shared::check_cubical_routes(&set);
            }
        }
    }
}
