//! Binary images: numpy's own `.npy` files in every dtype, order, byte order and format
//! version equal the `.cub` of the same cubes; DIPHA's files; round trips of the writers;
//! hostile headers refused with a message naming the file and the fault.

use std::path::{Path, PathBuf};

use gmap_ops::import::image::{Dtype, Image, Level, Order};
use gmap_ops::import::read_cub;
use proptest::prelude::*;

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/image").join(name)
}

fn cubes(set: &gmap_ops::import::CubicalSet) -> Vec<Vec<i64>> {
    let mut c: Vec<Vec<i64>> = set.cubes().collect();
    c.sort();
    c
}

/// `a[i, j, k] = (7 (6 i + 2 j + k)) mod 6`, the array of make.py.
fn a(i: usize, j: usize, k: usize) -> f64 {
    ((7 * (6 * i + 2 * j + k)) % 6) as f64
}

#[test]
fn numpy_files_in_every_dtype_and_order_equal_the_cub() {
    let want = cubes(&read_cub(&data("a.cub")).unwrap());
    assert_eq!(want.len(), 20);
    let mut names: Vec<String> = std::fs::read_dir(data(""))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with("a_") || n == "a.complex")
        .collect();
    names.sort();
    assert_eq!(names.len(), 35, "{names:?}");
    for name in &names {
        let img = Image::read(&data(name)).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(img.shape(), &[4, 3, 2], "{name}");
        let expect_order =
            if name.ends_with("_f.npy") || name.ends_with(".complex") { Order::Fortran } else { Order::C };
        assert_eq!(img.order(), expect_order, "{name}");
        assert_eq!(img.is_big_endian(), name.contains("_be"), "{name}");
        for i in 0..4 {
            for j in 0..3 {
                for k in 0..2 {
                    let v = if name.contains("bool") { (a(i, j, k) != 0.0) as u8 as f64 } else { a(i, j, k) };
                    assert_eq!(img.get(&[i, j, k]), v, "{name} at {i} {j} {k}");
                }
            }
        }
        let set = img.to_cubical_set(Level::Nonzero).unwrap();
        assert_eq!(cubes(&set), want, "{name}");
        // the sublevel set at 2.5: values 0, 1, 2
        let low = img.to_cubical_set(Level::AtMost(2.5)).unwrap();
        let mut n = 0;
        for (i, j, k) in (0..24).map(|m| (m / 6, (m / 2) % 3, m % 2)) {
            let v = img.get(&[i, j, k]);
            assert_eq!(low.bits()[i + 4 * (j + 3 * k)] == 1, v <= 2.5, "{name}");
            n += (v <= 2.5) as usize;
        }
        assert_eq!(low.cube_count(), n);
    }
    let dtypes: Vec<Dtype> =
        names.iter().filter(|n| n.ends_with(".npy")).map(|n| Image::read(&data(n)).unwrap().dtype()).collect();
    for d in [Dtype::Bool, Dtype::I8, Dtype::U8, Dtype::I16, Dtype::U16, Dtype::I32, Dtype::U32, Dtype::I64, Dtype::U64]
    {
        assert!(dtypes.contains(&d), "{d:?}");
    }
    assert!(dtypes.contains(&Dtype::F32) && dtypes.contains(&Dtype::F64));
}

#[test]
fn a_one_dimensional_image() {
    let img = Image::read_npy(&data("line.npy")).unwrap();
    assert_eq!(img.shape(), &[4]);
    assert_eq!(cubes(&img.to_cubical_set(Level::Nonzero).unwrap()), vec![vec![0], vec![2], vec![3]]);
}

#[test]
fn the_writers_round_trip() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["a_lei2_c.npy", "a_bef8_f.npy", "a_bool_c.npy", "a.complex"] {
        let img = Image::read(&data(name)).unwrap();
        let (n, d) = (dir.path().join("x.npy"), dir.path().join("x.complex"));
        img.write_npy(&n).unwrap();
        img.write_dipha(&d).unwrap();
        let (back, dipha) = (Image::read(&n).unwrap(), Image::read_dipha(&d).unwrap());
        assert_eq!((back.dtype(), back.order(), back.shape()), (img.dtype(), img.order(), img.shape()));
        assert_eq!(back.raw(), img.raw(), "{name}");
        assert_eq!((dipha.dtype(), dipha.order(), dipha.shape()), (Dtype::F64, Order::Fortran, img.shape()));
        for m in 0..24 {
            let idx = [m / 6, (m / 2) % 3, m % 2];
            assert_eq!(dipha.get(&idx), img.get(&idx), "{name}");
        }
        // numpy's header is padded so that the values start on 64 bytes
        assert_eq!(img.npy_header().len() % 64, 0);
    }
    // a DIPHA file written here has the bytes of DIPHA's own writer
    let a = Image::read(&data("a_lef8_c.npy")).unwrap();
    let p = dir.path().join("a.complex");
    a.write_dipha(&p).unwrap();
    assert_eq!(std::fs::read(&p).unwrap(), std::fs::read(data("a.complex")).unwrap());
}

fn refused(bytes: &[u8], needle: &str) {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("hostile.npy");
    std::fs::write(&p, bytes).unwrap();
    let e = Image::read(&p).unwrap_err().to_string();
    assert!(e.contains("hostile.npy") && e.contains(needle), "{e:?} lacks {needle:?}");
}

fn npy(dict: &str, data: &[u8]) -> Vec<u8> {
    let mut v = b"\x93NUMPY\x01\x00".to_vec();
    v.extend_from_slice(&(dict.len() as u16).to_le_bytes());
    v.extend_from_slice(dict.as_bytes());
    v.extend_from_slice(data);
    v
}

#[test]
fn hostile_headers_are_refused_with_the_reason() {
    refused(b"\x93NUMPX\x01\x00\x00\x00", "neither numpy's magic");
    refused(b"", "not an image");
    refused(b"\x93NUMPY\x01", "truncated in its preamble");
    refused(b"\x93NUMPY\x04\x00\x10\x00", "version 4.0");
    refused(b"\x93NUMPY\x01\x00\xff\x00{'descr'", "truncated in its header");
    let ok = "{'descr': '|u1', 'fortran_order': False, 'shape': (2, 2), }\n";
    assert!(Image::parse_npy(npy(ok, &[1, 0, 0, 1])).is_ok());
    refused(&npy(ok, &[1, 0, 0]), "truncated data");
    refused(&npy("{'descr': '|O', 'fortran_order': False, 'shape': (2,), }", &[0; 16]), "dtype '|O' is not read");
    refused(&npy("{'descr': '<c16', 'fortran_order': False, 'shape': (2,), }", &[0; 32]), "dtype '<c16'");
    refused(&npy("{'descr': [('a', '<i4')], 'fortran_order': False, 'shape': (2,), }", &[0; 8]), "structured");
    refused(
        &npy("{'descr': '<i8', 'fortran_order': False, 'shape': (4294967296, 4294967296, 4294967296), }", &[]),
        "overflows",
    );
    refused(&npy("{'descr': '|u1', 'fortran_order': False, 'shape': (99999999999999999999999,), }", &[]), "shape");
    refused(&npy("{'descr': '|u1', 'fortran_order': Maybe, 'shape': (2,), }", &[0; 2]), "neither True nor False");
    refused(&npy("{'descr': '|u1', 'shape': (2,), }", &[0; 2]), "no 'fortran_order'");
    refused(&npy("{'descr': '|u1', 'fortran_order': False, 'shape': (2,), 'x': 1}", &[0; 2]), "unknown key 'x'");
    refused(&npy("['descr', '|u1']", &[0; 2]), "expected a dict");
    refused(&npy("{'descr': '|u1', 'fortran_order': False, 'shape': (), }", &[0]), "dimension 0");
    refused(&npy("{'descr': '|u1', 'fortran_order': False, 'shape': (1,1,1,1,1,1,1,1,1), }", &[0]), "dimension 9");
    refused(&npy("{'descr': '|u1', 'fortran_order': False, 'shape': (2,) } junk", &[0; 2]), "text after the dict");
    // DIPHA
    let word = |v: i64| v.to_le_bytes().to_vec();
    let dipha = |words: &[i64], extra: usize| {
        let mut v: Vec<u8> = words.iter().flat_map(|&w| word(w)).collect();
        v.extend(std::iter::repeat_n(0u8, extra));
        v
    };
    refused(&dipha(&[8067171840, 0, 1, 1, 1], 8), "DIPHA file type 0");
    refused(&dipha(&[8067171840, 1, 4, 2, 2, 2], 24), "truncated data");
    refused(&dipha(&[8067171840, 1, 5, 2, 2, 2], 40), "counts 5 values");
    refused(&dipha(&[8067171840, 1, 1, 9], 0), "dimension 9");
    refused(&dipha(&[8067171840, 1, 1, 2, -1, 1], 8), "size -1");
    refused(&dipha(&[8067171840, 1, 1], 0), "truncated in its header");
}

#[test]
fn an_empty_image_has_no_cubical_set() {
    // refused when read, with the one message every command gives, axes in the file's order
    let e = Image::parse_npy(npy("{'descr': '|u1', 'fortran_order': False, 'shape': (0, 3), }", &[])).unwrap_err();
    assert_eq!(e.to_string(), "an empty image: the shape 0 × 3 has no pixels (size 0 along axis 0)");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Random images of dimension 1 to 4 in both orders: written, read back, the set at a
    /// level equals the one computed from the values directly.
    #[test]
    fn random_images_round_trip(shape in prop::collection::vec(1usize..5, 1..5), fortran: bool,
                                seed in any::<u64>(), t in -1.0f64..6.0) {
        let n: usize = shape.iter().product();
        let mut s = seed;
        let vals: Vec<i16> = (0..n).map(|_| {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((s >> 33) % 7) as i16 - 1
        }).collect();
        let order = if fortran { Order::Fortran } else { Order::C };
        let img = Image::from_values(&shape, order, vals.clone()).unwrap();
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("r.npy");
        img.write_npy(&p).unwrap();
        let back = Image::read(&p).unwrap();
        prop_assert_eq!(back.raw(), img.raw());
        let set = back.to_cubical_set(Level::AtMost(t)).unwrap();
        let d = shape.len();
        for (m, &v) in vals.iter().enumerate() {
            // the index of the m-th value in layout order
            let mut idx = vec![0usize; d];
            let mut r = m;
            let axes: Vec<usize> = if fortran { (0..d).collect() } else { (0..d).rev().collect() };
            for &a in &axes {
                idx[a] = r % shape[a];
                r /= shape[a];
            }
            let mut bit = 0usize;
            for a in (0..d).rev() {
                bit = bit * shape[a] + idx[a];
            }
            prop_assert_eq!(set.bits()[bit] == 1, (v as f64) <= t);
            prop_assert_eq!(back.get(&idx), v as f64);
        }
    }
}
