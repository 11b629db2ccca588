//! The cubical complex and the G-map of the union agree where the G-map applies (cubes
//! sewn along shared facets): a solid box, an annulus, a shell, a torus of cubes.

use gmap_homology::cubical::{cubical_complex, cubical_complex_with};
use gmap_homology::{cellular_complex, homology_z, Homology};
use gmap_ops::import::cubical::{parse_cub, CubicalSet};

fn by_cubes(s: &CubicalSet, periodic: bool) -> Homology {
    let a = homology_z(&cubical_complex(s.shape(), s.bits(), periodic).unwrap().chain).unwrap();
    let plain = cubical_complex_with(s.shape(), s.bits(), periodic, false).unwrap().chain;
    plain.check_dd().unwrap();
    assert_eq!(homology_z(&plain).unwrap(), a);
    a
}

fn by_gmap(s: &CubicalSet, periodic: bool) -> Homology {
    let m = s.gmap(periodic).unwrap();
    m.validate().unwrap();
    homology_z(&cellular_complex(&m).unwrap().chain).unwrap()
}

fn set(cubes: impl Iterator<Item = Vec<i64>>) -> CubicalSet {
    let text: String =
        cubes.map(|c| format!("({})\n", c.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(","))).collect();
    parse_cub(text.as_bytes()).unwrap()
}

#[test]
fn both_routes_agree() {
    let boxed = set((0..3).flat_map(|x| (0..2).flat_map(move |y| (0..2).map(move |z| vec![x, y, z]))));
    let annulus =
        set((0..4).flat_map(|x| (0..3).map(move |y| vec![x, y])).filter(|c| !(c[1] == 1 && (1..3).contains(&c[0]))));
    let shell = set((0..3)
        .flat_map(|x| (0..3).flat_map(move |y| (0..3).map(move |z| vec![x, y, z])))
        .filter(|c| c != &vec![1, 1, 1]));
    let cases = [
        (&boxed, false, vec![1, 0, 0, 0]),
        (&annulus, false, vec![1, 1, 0]),
        (&shell, false, vec![1, 0, 1, 0]),
        (&boxed, true, vec![1, 3, 3, 1]),
        (&annulus, true, vec![1, 2, 0]),
    ];
    for (s, periodic, betti) in cases {
        let a = by_cubes(s, periodic);
        let b = by_gmap(s, periodic);
        assert_eq!(a, b, "{s:?} periodic {periodic}");
        assert_eq!(a.betti, betti, "{s:?} periodic {periodic}");
    }
}

#[test]
fn a_solid_torus_of_cubes() {
    // a 3 x 3 ring of squares thickened by one layer in z, periodic only where the G-map applies
    let ring = set((0..3).flat_map(|x| (0..3).map(move |y| vec![x, y, 0])).filter(|c| !(c[0] == 1 && c[1] == 1)));
    let a = by_cubes(&ring, false);
    assert_eq!(a.betti, vec![1, 1, 0, 0]);
    assert_eq!(a, by_gmap(&ring, false));
}
