//! Images through the facade: a `.npy` or DIPHA file opens as an image, its groups by the
//! one-pass route equal those of the cubical complex (`--generators` takes that route), and
//! `--level` picks the sublevel set.

use gmap::ops::import::image::{Image, Order};
use gmap::{homology, open, HomologyOptions, Input};

fn groups(input: &Input, level: Option<f64>, generators: bool) -> Vec<usize> {
    let mut o = HomologyOptions::default();
    o.level = level;
    o.generators = generators;
    homology(input, &o).unwrap().groups.betti
}

#[test]
fn images_open_and_both_routes_agree() {
    let dir = tempfile::tempdir().unwrap();
    // a 5 × 5 × 3 image: a ring of 1s around a 0 in the middle layer, values 2 elsewhere
    let mut v = vec![2u16; 75];
    for (x, y) in [(1, 1), (2, 1), (3, 1), (1, 2), (3, 2), (1, 3), (2, 3), (3, 3)] {
        v[25 + 5 * y + x] = 1; // C order: a[z][y][x]
    }
    let img = Image::from_values(&[3, 5, 5], Order::C, v).unwrap();
    let (npy, dipha) = (dir.path().join("ring.npy"), dir.path().join("ring.complex"));
    img.write_npy(&npy).unwrap();
    img.write_dipha(&dipha).unwrap();
    for path in [&npy, &dipha] {
        let input = open(path).unwrap();
        assert!(matches!(input, Input::Image(_)));
        assert_eq!(input.kind(), "cubical set");
        // the ring: a circle; everything: a ball
        assert_eq!(groups(&input, Some(1.0), false), vec![1, 1, 0, 0]);
        assert_eq!(groups(&input, Some(1.0), true), vec![1, 1, 0, 0]);
        assert_eq!(groups(&input, None, false), vec![1, 0, 0, 0]);
        assert_eq!(groups(&input, Some(0.5), false), vec![0, 0, 0, 0]);
    }
    // --level on something else is refused
    let cub = dir.path().join("c.cub");
    std::fs::write(&cub, "(0,0)\n").unwrap();
    let mut o = HomologyOptions::default();
    o.level = Some(1.0);
    let e = homology(&open(&cub).unwrap(), &o).unwrap_err().to_string();
    assert!(e.contains("--level applies to images"), "{e}");
}

#[test]
fn a_bad_image_names_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("bad.npy");
    std::fs::write(&p, b"\x93NUMPY\x01\x00\x10\x00{'descr': '|O'}").unwrap();
    let e = open(&p).unwrap_err().to_string();
    assert!(e.contains("bad.npy"), "{e}");
}

/// A periodic image of dimension ≤ 3 takes the one-pass route (`cubical::torus`), torsion
/// included, and its groups equal the cubical complex's (`--generators` takes that route);
/// over Z/2 the torsion Z/2 of H_1 adds a Z/2 to H_1 and to H_2.
#[test]
fn periodic_images_take_the_one_pass_route() {
    // a 5 × 5 × 8 torus whose complement is a tube winding twice around the x axis
    let (nx, n) = (8usize, 5usize);
    let ring = [(1, 1), (1, 2), (1, 3), (2, 3), (3, 3), (3, 2), (3, 1), (2, 1)];
    let mut v = vec![1u8; nx * n * n];
    for t in 0..2 * nx {
        for k in [t / 2 % 8, t.div_ceil(2) % 8] {
            let (y, z) = ring[k];
            v[t % nx + nx * (y + n * z)] = 0; // C order: a[z][y][x]
        }
    }
    let img = Image::from_values(&[n, n, nx], Order::C, v.clone()).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("helix.npy");
    img.write_npy(&path).unwrap();
    let input = open(&path).unwrap();
    let mut o = HomologyOptions::default();
    o.periodic = true;
    let shape = [nx, n, n];
    let fill = |s: usize, out: &mut [u8]| out.copy_from_slice(&v[s..s + out.len()]);
    let direct = gmap::cubes::one_pass(&shape, fill, &o, "helix").unwrap().expect("the one-pass route");
    let one_pass = homology(&input, &o).unwrap().groups;
    assert_eq!(one_pass, direct);
    assert_eq!(one_pass.betti, vec![1, 3, 2, 0]);
    assert_eq!(one_pass.group_string(1), "Z^3 + Z/2");
    o.generators = true;
    assert_eq!(homology(&input, &o).unwrap().groups, one_pass);
    o.generators = false;
    o.field = Some(2);
    assert_eq!(homology(&input, &o).unwrap().groups.betti, vec![1, 4, 3, 0]);
    o.field = Some(3);
    assert_eq!(homology(&input, &o).unwrap().groups.betti, vec![1, 3, 2, 0]);
}

/// A 2-D image or cubical set with `--generators` takes the one-pass cycles
/// (`cubical::gens`): the groups equal the cubical complex's, a vertex per component and the
/// outline of each hole, named in the input's axes (C order: the file's `(row, column)`), over
/// Z/p with coefficients in `0..p`; the JSON written straight equals the JSON values'.
#[test]
fn two_dimensional_generators_are_outlines() {
    // C order, 4 rows × 6 columns: a ring of 8 pixels around (row 1, column 1), a lone pixel
    // at (row 3, column 5)
    let mut v = vec![0u8; 24];
    for (r, c) in [(0, 0), (0, 1), (0, 2), (1, 0), (1, 2), (2, 0), (2, 1), (2, 2), (3, 5)] {
        v[6 * r + c] = 1;
    }
    let img = Image::from_values(&[4, 6], Order::C, v).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("ring.npy");
    img.write_npy(&path).unwrap();
    let input = open(&path).unwrap();
    let mut o = HomologyOptions::default();
    o.generators = true;
    let r = homology(&input, &o).unwrap();
    assert_eq!(r.groups.betti, vec![2, 1, 0]);
    let g = r.generators.as_ref().unwrap();
    let text: Vec<String> = g
        .iter()
        .map(|x| x.chain.iter().map(|(c, k)| format!("{k:+} {}", c.to_text())).collect::<Vec<_>>().join(" "))
        .collect();
    // the hole's outline: the four edges of pixel (1, 1), in the file's (row, column) axes
    assert_eq!(text, vec!["+1 0x0", "+1 3x5", "+1 [1,2]x1 -1 1x[1,2] +1 2x[1,2] -1 [1,2]x2"]);
    assert_eq!(r.to_json_string(), r.to_json().to_string());
    o.field = Some(3);
    let r3 = homology(&input, &o).unwrap();
    assert_eq!(r3.groups.betti, vec![2, 1, 0]);
    let coefficients: Vec<i64> = r3.generators.unwrap()[2].chain.iter().map(|x| x.1).collect();
    assert_eq!(coefficients, vec![1, 2, 1, 2]);
    // the same through a .cub: the cubical complex's groups
    o.field = None;
    let cub = dir.path().join("ring.cub");
    std::fs::write(&cub, "(0,0)\n(0,1)\n(0,2)\n(1,0)\n(1,2)\n(2,0)\n(2,1)\n(2,2)\n(3,5)\n").unwrap();
    let rc = homology(&open(&cub).unwrap(), &o).unwrap();
    assert_eq!(rc.groups.betti, vec![2, 1, 0]);
    assert_eq!(rc.generators.as_ref().unwrap().len(), 3);
    assert_eq!(rc.to_json_string(), rc.to_json().to_string());
}
