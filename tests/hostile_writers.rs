//! The writers never write another space or a file their readers refuse (the hostile-input
//! audit): `.facets` of every `gmap demo` object reads back with the same homology, `.off` of
//! every 2-map with points reads back as the same map, or the writer refuses.

use gmap_core::{Dart, DenseMap};
use gmap_homology::{cellular_complex, homology_z, simplicial_complex, Homology};
use gmap_ops::export::{barycentric_facets_string, off_string, ExportError};
use gmap_ops::import::{PolygonMesh, SimplicialComplex};
use gmap_ops::{build, iso};

/// The homology of a map as `gmap homology` gives it: cellular where C1 and C2 hold, else
/// the simplicial counterpart (BO §6: the homology of its barycentric subdivision).
fn homology(m: &DenseMap) -> Homology {
    match cellular_complex(m) {
        Ok(c) => homology_z(&c.chain).unwrap(),
        Err(_) => homology_z(&simplicial_complex(m)).unwrap(),
    }
}

fn facets_round_trip(name: &str, m: &DenseMap) -> Result<(bool, Homology, Homology), ExportError> {
    let text = barycentric_facets_string(m)?;
    let second = text.starts_with("# second");
    let sc = SimplicialComplex::parse_facets(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
    let back = sc.to_gmap(u32::MAX as u64 - 1).unwrap_or_else(|e| panic!("{name}: {e}"));
    Ok((second, homology(m), homology(&back)))
}

#[test]
fn monogon_disk_facets_read_back_as_a_disk() {
    // gmap 2 2 / 1 1 0 / 0 0 1: a monogon, whose first subdivision is the same triangle twice
    let m = gmap_core::io::parse_gmap(b"gmap 2 2\n1 1 0\n0 0 1\n", "monogon.gmap").unwrap();
    let text = barycentric_facets_string(&m).unwrap();
    assert!(text.starts_with("# second barycentric subdivision"), "{text}");
    let (second, a, b) = facets_round_trip("monogon", &m).unwrap();
    assert!(second);
    assert_eq!(a, b);
    assert_eq!(b.betti, vec![1, 0, 0], "a disk, not a sphere");
}

#[test]
fn every_demo_object_converts_to_facets_with_its_homology_or_is_refused() {
    let mut seconds = Vec::new();
    for (name, m) in build::demo_objects() {
        // the second subdivision of the largest objects makes millions of darts to read back
        if m.dart_count() * (1..=m.dim() + 1).product::<usize>() > 400_000 {
            let text = barycentric_facets_string(&m).unwrap();
            if text.starts_with("# second") {
                eprintln!("{name}: second subdivision, {} facets (not read back here)", text.lines().count() - 1);
                continue;
            }
        }
        match facets_round_trip(&name, &m) {
            Ok((second, a, b)) => {
                assert_eq!(a, b, "{name}");
                if second {
                    seconds.push(name);
                }
            }
            Err(e) => eprintln!("{name}: refused: {e}"),
        }
    }
    // the maps whose cells are not embedded need the second subdivision
    for needs in ["torus (a b A B)", "projective plane (a a)", "RP3 = L(2,1)"] {
        assert!(seconds.iter().any(|s| s == needs), "{needs} in {seconds:?}");
    }
}

#[test]
fn regular_maps_keep_the_first_subdivision() {
    for m in [build::cube(3).unwrap(), build::simplex(2).unwrap(), build::grid(&[2, 2, 2], &[true; 3]).unwrap()] {
        let text = barycentric_facets_string(&m).unwrap();
        assert!(text.starts_with("# barycentric subdivision"));
        assert_eq!(text.lines().count() - 1, m.dart_count());
    }
}

/// Every dart gets the point of its vertex, numbered along the x axis.
fn with_points(mut m: DenseMap) -> DenseMap {
    let v = m.cells(0);
    for d in 0..m.dart_count() as u32 {
        m.set_point(Dart::new(d), Some([v.of[d as usize] as f64, 0.5, -1.0]));
    }
    m
}

#[test]
fn off_export_reads_back_as_the_same_map_or_is_refused() {
    let mut maps: Vec<(String, DenseMap)> = (1..=6).map(|k| (format!("{k}-gon"), build::polygon(k).unwrap())).collect();
    maps.push(("square".into(), build::cube(2).unwrap()));
    maps.push(("prism side".into(), build::extrude(&build::cube(1).unwrap()).unwrap()));
    for (sizes, periodic) in
        [([2, 3], [false, false]), ([3, 3], [true, false]), ([3, 3], [true, true]), ([1, 1], [true, true])]
    {
        maps.push((format!("grid {sizes:?} {periodic:?}"), with_points(build::grid(&sizes, &periodic).unwrap())));
    }
    for (name, m) in build::demo_objects() {
        if m.dim() == 2 {
            maps.push((name, with_points(m)));
        }
    }
    let (mut written, mut refused) = (0, 0);
    for (name, m) in &maps {
        match off_string(m) {
            Ok(text) => {
                let back =
                    PolygonMesh::parse(&text).and_then(|x| x.to_gmap()).unwrap_or_else(|e| panic!("{name}: {e}"));
                assert!(iso::are_isomorphic(m, &back), "{name}");
                written += 1;
            }
            Err(e) => {
                eprintln!("{name}: refused: {e}");
                refused += 1;
            }
        }
    }
    assert!(written >= 6 && refused >= 3, "{written} written, {refused} refused");
    // a monogon and a digon cannot be written; a triangle can
    assert!(matches!(off_string(&build::polygon(1).unwrap()), Err(ExportError::NotAMesh { .. })));
    assert!(matches!(off_string(&build::polygon(2).unwrap()), Err(ExportError::NotAMesh { .. })));
    assert!(off_string(&build::polygon(3).unwrap()).is_ok());
    let mut nan = build::polygon(3).unwrap();
    nan.set_point(Dart::new(0), Some([f64::NAN, 0.0, 0.0]));
    assert!(matches!(off_string(&nan), Err(ExportError::NonFinitePoint { .. })));
}
