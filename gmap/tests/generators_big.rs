//! Generators of complexes far above the dense limit: the fill-free reduction leaves as many
//! cells as the Betti numbers, and the cycles found there are lifted back and checked.

use gmap_homology::generators::generators;
use gmap_homology::{cellular_complex, homology_z, simplicial_complex};
use gmap_ops::build;

fn orders(g: &[gmap_homology::generators::Generator], k: usize) -> Vec<u64> {
    g.iter().filter(|x| x.dim == k).map(|x| x.order.to_u64().expect("a small order")).collect()
}

#[test]
fn three_torus_grid() {
    // 12^3 periodic grid: 1,728 vertices, 5,184 edges, 5,184 faces, 1,728 volumes
    let map = build::grid(&[12, 12, 12], &[true; 3]).unwrap();
    let c = cellular_complex(&map).unwrap().chain;
    assert_eq!(c.counts(), &[1728, 5184, 5184, 1728]);
    let g = generators(&c, None).unwrap();
    assert_eq!(orders(&g, 0), vec![0]);
    assert_eq!(orders(&g, 1), vec![0, 0, 0]);
    assert_eq!(orders(&g, 2), vec![0, 0, 0]);
    assert_eq!(orders(&g, 3), vec![0]);
    // the fundamental class is the sum of all volumes, each with coefficient ±1
    let top = g.iter().find(|x| x.dim == 3).unwrap();
    assert_eq!(top.chain.len(), 1728);
    assert!(top.chain.iter().all(|&(_, v)| v.abs() == 1));
    // a loop around the torus crosses at least 12 edges
    for x in g.iter().filter(|x| x.dim == 1) {
        assert!(x.chain.len() >= 12, "{:?}", x.chain.len());
    }
    let g2 = generators(&c, Some(2)).unwrap();
    assert_eq!(g2.len(), 8);
}

#[test]
fn lens_space_torsion_by_both_methods() {
    // L(5,2): H_1 = Z/5
    let map = build::lens_space(5, 2).unwrap();
    let s = simplicial_complex(&map);
    for c in [cellular_complex(&map).unwrap().chain, s] {
        let h = homology_z(&c).unwrap();
        let g = generators(&c, None).unwrap();
        assert_eq!(orders(&g, 1), vec![5]);
        assert_eq!(h.torsion[1], vec![5]);
        assert_eq!(orders(&g, 3), vec![0]);
    }
}

#[test]
fn big_simplicial_counterpart() {
    // the simplicial counterpart of the 6^3 torus grid: 10,368 tetrahedra, one per dart
    let map = build::grid(&[6, 6, 6], &[true; 3]).unwrap();
    let s = simplicial_complex(&map);
    assert_eq!(s.count(3), 10_368);
    let g = generators(&s, None).unwrap();
    assert_eq!(orders(&g, 1), vec![0, 0, 0]);
    assert_eq!(orders(&g, 2), vec![0, 0, 0]);
}
