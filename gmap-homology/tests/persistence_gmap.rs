//! Persistence of G-maps: a labelled map read from `.gmap` text, and the G-maps of Lutz
//! complexes with lower-star values, which must give the simplicial complex's diagram.

use gmap_homology::cellular_complex;
use gmap_homology::persistence::{CellName, FilteredComplex, Pair, SimplexValues};
use gmap_ops::import::SimplicialComplex;

#[test]
fn a_labelled_circle_of_two_edges() {
    // darts 0,1 form edge A, darts 2,3 edge B; vertices {1,2} and {3,0}
    let text = "gmap 1 4\n1 3\n0 2\n3 1\n2 0\nlabels 0 2\n0 t=0\n1 t=1.0\nlabels 1 2\n0 t=2\n2 t=3\n";
    let g = gmap_core::io::parse_labelled_gmap(text.as_bytes(), "circle.gmap").unwrap();
    let f = FilteredComplex::from_labelled_gmap(&g, "t").unwrap();
    let d = f.diagram(2, true).unwrap();
    let inf = f64::INFINITY;
    assert_eq!(
        d.pairs,
        vec![
            Pair { dim: 0, birth: 0.0, death: inf },
            Pair { dim: 0, birth: 1.0, death: 2.0 },
            Pair { dim: 1, birth: 3.0, death: inf }
        ]
    );
    // the loop: both edges, named by their smallest darts
    let mut names: Vec<&CellName> = d.cycles[2].iter().map(|(n, _)| n).collect();
    names.sort();
    assert_eq!(names, vec![&CellName::Cell { dim: 1, index: 0 }, &CellName::Cell { dim: 1, index: 2 }]);
    // a missing label takes the faces' maximum; a text label is refused
    let text2 = text.replace("2 t=3\n", "2 u=3\n");
    let g = gmap_core::io::parse_labelled_gmap(text2.as_bytes(), "c.gmap").unwrap();
    let d = FilteredComplex::from_labelled_gmap(&g, "t").unwrap().diagram(2, false).unwrap();
    // edge B comes in at 1 and joins the vertices; edge A at 2 closes the loop
    assert_eq!(d.pairs, vec![Pair { dim: 0, birth: 0.0, death: inf }, Pair { dim: 1, birth: 2.0, death: inf }]);
    let text3 = text.replace("0 t=0\n", "0 t=\"zero\"\n");
    let g = gmap_core::io::parse_labelled_gmap(text3.as_bytes(), "c.gmap").unwrap();
    let e = FilteredComplex::from_labelled_gmap(&g, "t").unwrap_err().to_string();
    assert!(e.contains("not a number"), "{e}");
}

fn facets(file: &str) -> Vec<Vec<u64>> {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tests/data/lutz").join(file);
    let text = std::fs::read_to_string(path).unwrap();
    text.lines()
        .map(|l| l.split('#').next().unwrap().trim())
        .filter(|l| !l.is_empty())
        .map(|l| l.split_whitespace().map(|x| x.parse().unwrap()).collect())
        .collect()
}

#[test]
fn lutz_gmaps_with_lower_star_values_equal_their_simplicial_complexes() {
    for file in ["Barnette_sphere.facets", "CP2.facets", "poincare.facets", "RP4.facets"] {
        let f = facets(file);
        // a value per vertex from its label
        let vertex_value = |v: u64| Some(((v * 7919) % 13) as f64);
        let simplicial = FilteredComplex::from_simplices(&f, SimplexValues::LowerStar(&vertex_value)).unwrap();
        let sc = SimplicialComplex::from_facets(f.clone()).unwrap();
        let map = sc.to_gmap(u64::MAX).unwrap();
        let cc = cellular_complex(&map).unwrap();
        let reps = &cc.reps;
        let cellular = FilteredComplex::from_chain(
            &cc.chain,
            |k, i| {
                let face = sc.dart_face(reps[k][i].index() as u64, k).unwrap();
                Ok(Some(face.iter().map(|&v| vertex_value(v).unwrap()).fold(f64::NEG_INFINITY, f64::max)))
            },
            |k, i| CellName::Cell { dim: k, index: reps[k][i].index() },
        )
        .unwrap();
        for p in [2, 3] {
            let a = simplicial.diagram(p, false).unwrap();
            let b = cellular.diagram(p, false).unwrap();
            assert_eq!(a.pairs, b.pairs, "{file} over Z/{p}");
            assert!(!a.pairs.is_empty());
        }
    }
}
