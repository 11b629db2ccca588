//! Fuzzes the Perseus `.txt` readers (cubical, GUDHI's `perseus_file`, and simplicial,
//! `nmfsimtop`, told apart by `is_simplicial` as `gmap` does): they must never panic; a
//! cubical file accepted has 1 to 8 non-empty axes and as many values (none NaN) as their
//! product, a simplicial one simplices of as many labels as their dimension plus one and a
//! birth each (none NaN); written back as Perseus text either reads to the same contents; a
//! small non-periodic cubical file makes the image `gmap` opens, whose cubical routes agree.
#![no_main]

use gmap_ops::import::image::{Image, Order};
use gmap_ops::import::perseus::{is_simplicial, parse_perseus_cubical, parse_perseus_simplicial, MAX_AXES};
use gmap_ops::import::Level;
use libfuzzer_sys::fuzz_target;

#[path = "shared/mod.rs"]
mod shared;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let _ = is_simplicial(text);
    if let Ok((simplices, births)) = parse_perseus_simplicial(text) {
        assert!(!simplices.is_empty());
        assert_eq!(simplices.len(), births.len());
        assert!(births.iter().all(|b| !b.is_nan()));
        let mut again = String::from("1\n");
        for (s, b) in simplices.iter().zip(&births) {
            assert!(!s.is_empty());
            again.push_str(&format!("{}", s.len() - 1));
            for v in s {
                again.push_str(&format!(" {v}"));
            }
            again.push_str(&format!(" {b:?}\n"));
        }
        assert_eq!(parse_perseus_simplicial(&again).expect("written simplices read back"), (simplices, births));
    }
    if let Ok(p) = parse_perseus_cubical(text) {
        assert!((1..=MAX_AXES).contains(&p.sizes.len()));
        assert_eq!(p.periodic.len(), p.sizes.len());
        assert!(p.sizes.iter().all(|&s| s > 0));
        let n: usize = p.sizes.iter().product();
        assert_eq!(p.values.len(), n);
        assert!(p.values.iter().all(|v| !v.is_nan()));
        let mut again = format!("{}\n", p.sizes.len());
        for (&s, &w) in p.sizes.iter().zip(&p.periodic) {
            again.push_str(&format!("{}{s}\n", if w { "-" } else { "" }));
        }
        for v in &p.values {
            again.push_str(&format!("{v:?}\n"));
        }
        assert_eq!(parse_perseus_cubical(&again).expect("a written cubical file reads back"), p);
        if n <= 1 << 10 && !p.periodic.iter().any(|&w| w) {
            let img = Image::from_values(&p.sizes, Order::Fortran, p.values.clone()).expect("the image gmap opens");
            assert_eq!(img.shape(), &p.sizes[..]);
            if let Ok(set) = img.to_cubical_set(Level::Nonzero) {
                shared::check_set(&set);
                shared::check_cubical_routes(&set);
            }
        }
    }
});
