//! Values given per facet in the order the facets are given
//! (`gmap::persistence::given_facet_persistence`): each value follows its facet, whatever
//! the dimensions of the facets and however the complex reorders them (its largest facets
//! first).

use gmap::persistence::given_facet_persistence;
use gmap::PersistenceOptions;
use proptest::prelude::*;

fn triples(facets: &[Vec<u64>], values: &[f64]) -> Vec<(usize, f64, f64)> {
    let d = given_facet_persistence(facets.to_vec(), values, &PersistenceOptions::default()).unwrap();
    d.pairs.iter().map(|p| (p.dim, p.birth, p.death)).collect()
}

#[test]
fn an_edge_before_a_triangle_keeps_its_value() {
    // the smallest list of issue 46: two edges at 0 are two components until the triangle
    // [0, 2, 3] joins them at 1 (its edge [0, 2]); vertex 3 is born and dies at 1
    let facets = vec![vec![0, 1], vec![2, 4], vec![0, 2, 3]];
    assert_eq!(triples(&facets, &[0.0, 0.0, 1.0]), vec![(0, 0.0, 1.0), (0, 0.0, f64::INFINITY)]);
    // the same facets, the triangle first: the same diagram
    let moved = vec![vec![0, 2, 3], vec![0, 1], vec![2, 4]];
    assert_eq!(triples(&moved, &[1.0, 0.0, 0.0]), vec![(0, 0.0, 1.0), (0, 0.0, f64::INFINITY)]);
    // vertex 1 comes with its edge [0, 1] at 5 and dies at once; the triangle is one class from 1
    assert_eq!(triples(&[vec![0, 1], vec![0, 2, 3]], &[5.0, 1.0]), vec![(0, 1.0, f64::INFINITY)],);
}

#[test]
fn a_count_of_values_other_than_the_facets_is_refused() {
    let e =
        given_facet_persistence(vec![vec![0, 1], vec![1, 2, 3]], &[1.0], &PersistenceOptions::default()).unwrap_err();
    assert_eq!(e.kind(), gmap::ErrorKind::Usage);
    assert!(e.to_string().contains("1 values for 2 facets"), "{e}");
}

/// Facets of 1 to 4 distinct vertices among 0..7, no facet twice, with a value each.
fn facets_and_values() -> impl Strategy<Value = (Vec<Vec<u64>>, Vec<f64>)> {
    prop::collection::vec((prop::collection::btree_set(0u64..7, 1..=4), 0u8..5), 1..8).prop_map(|raw| {
        let mut seen = std::collections::BTreeSet::new();
        let mut facets = Vec::new();
        let mut values = Vec::new();
        for (f, v) in raw {
            let f: Vec<u64> = f.into_iter().collect();
            if seen.insert(f.clone()) {
                facets.push(f);
                values.push(f64::from(v));
            }
        }
        (facets, values)
    })
}

proptest! {
    #[test]
    fn the_diagram_does_not_depend_on_the_order_of_the_facets(
        (facets, values) in facets_and_values(),
        seed in any::<u64>(),
    ) {
        let want = triples(&facets, &values);
        // the same (facet, value) pairs in another order
        let mut order: Vec<usize> = (0..facets.len()).collect();
        let mut s = seed;
        for i in (1..order.len()).rev() {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            order.swap(i, (s >> 33) as usize % (i + 1));
        }
        let f2: Vec<Vec<u64>> = order.iter().map(|&k| facets[k].clone()).collect();
        let v2: Vec<f64> = order.iter().map(|&k| values[k]).collect();
        prop_assert_eq!(triples(&f2, &v2), want);
    }
}

#[test]
fn an_opened_valued_facets_file_keeps_its_values() {
    // the list above as a file: `gmap::open` reads the values with the complex (the
    // triangle first, each value with its own line), and its diagram is the file's
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("valued.facets");
    std::fs::write(&path, "0 1 : 0\n2 4 : 0\n0 2 3 : 1\n").unwrap();
    let input = gmap::open(&path).unwrap();
    assert_eq!(input.input_kind(), gmap::Kind::Simplicial);
    let gmap::Input::Simplicial(sc) = &input else { panic!("a .facets file is a simplicial complex") };
    assert_eq!(sc.facets().map(<[u64]>::to_vec).collect::<Vec<_>>(), vec![vec![0, 2, 3], vec![0, 1], vec![2, 4]]);
    assert_eq!(sc.facet_values(), Some(&[1.0, 0.0, 0.0][..]));
    let opts = PersistenceOptions::default();
    let d = gmap::persistence(&input, &opts).unwrap();
    let got: Vec<_> = d.pairs.iter().map(|p| (p.dim, p.birth, p.death)).collect();
    assert_eq!(got, vec![(0, 0.0, 1.0), (0, 0.0, f64::INFINITY)]);
    let file = gmap::persistence_file(&path, &opts).unwrap().diagram;
    assert_eq!(file.pairs.iter().map(|p| (p.dim, p.birth, p.death)).collect::<Vec<_>>(), got);
    // a file without values opens with none, and its diagram asks for them
    let plain = dir.path().join("plain.facets");
    std::fs::write(&plain, "0 1\n1 2\n").unwrap();
    let input = gmap::open(&plain).unwrap();
    let gmap::Input::Simplicial(sc) = &input else { panic!("a .facets file is a simplicial complex") };
    assert_eq!(sc.facet_values(), None);
    let e = gmap::persistence(&input, &opts).unwrap_err();
    assert!(e.to_string().contains("needs values"), "{e}");
}
