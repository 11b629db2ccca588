//! Torsion of any size is computed and printed exactly: a disjoint union of lens spaces
//! L(p, 1), p running over the first primes, has H_1 = Z/(product of the p), one invariant
//! factor beyond 2^64 (and beyond 2^128), in the text form and as a JSON number.

mod common;
use common::{gmap, stderr, stdout};

use gmap_core::DenseMap;
use gmap_homology::{cellular_complex, homology_z, homology_z_bigint, simplicial_complex, Natural};

/// The primes up to `last`.
fn primes(last: usize) -> Vec<usize> {
    (2..=last).filter(|&p| (2..p).take_while(|d| d * d <= p).all(|d| p % d != 0)).collect()
}

/// The disjoint union of the lens spaces L(p, 1) for the given `p`.
fn lens_union(ps: &[usize]) -> DenseMap {
    let mut flat: Vec<u32> = Vec::new();
    for &p in ps {
        let m = gmap_ops::build::lens_space(p, 1).unwrap();
        let offset = (flat.len() / 4) as u32;
        flat.extend(m.flat().iter().map(|&a| a + offset));
    }
    DenseMap::try_from_flat(3, flat).unwrap()
}

/// The primorial 53# = 2 · 3 · … · 53, the first product of primes above 2^64.
const P53: &str = "32589158477190044730";
/// The primorial 103#, the first product of primes above 2^128.
const P103: &str = "23984823528925228172706521638692258396210";

#[test]
fn library_torsion_beyond_two_to_the_64() {
    let m = lens_union(&primes(53));
    assert_eq!(m.dart_count(), 1524);
    let c = cellular_complex(&m).unwrap();
    let h = homology_z(&c.chain).unwrap();
    let p53: Natural = P53.parse().unwrap();
    assert_eq!(h.betti, vec![16, 0, 0, 16]);
    assert_eq!(h.torsion, vec![vec![], vec![p53.clone()], vec![], vec![]]);
    assert_eq!(h.torsion[1][0].to_u64(), None);
    assert_eq!(h.group_string(1), format!("Z/{P53}"));
    assert_eq!(homology_z_bigint(&c.chain).unwrap(), h);
    // the simplicial counterpart has the same groups
    assert_eq!(homology_z(&simplicial_complex(&m)).unwrap(), h);
}

#[test]
fn cli_prints_the_exact_digits() {
    let dir = tempfile::tempdir().unwrap();
    for (last, digits) in [(53, P53), (103, P103)] {
        let path = dir.path().join(format!("lens{last}.gmap"));
        gmap_core::io::write_gmap(&lens_union(&primes(last)), &path).unwrap();
        let file = path.to_str().unwrap();
        let o = gmap(&["homology", file, "--json"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let out = stdout(&o);
        assert!(out.contains(&format!("\"torsion\":[[],[{digits}],[],[]]")), "{out}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert_eq!(v["torsion"][1][0].to_string(), digits);
        let o = gmap(&["homology", file]);
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(stdout(&o).contains(&format!("H_1 = Z/{digits}\n")), "{}", stdout(&o));
    }
    // small values keep their form
    let path = dir.path().join("rp3.gmap");
    gmap_core::io::write_gmap(&lens_union(&[2]), &path).unwrap();
    let o = gmap(&["homology", path.to_str().unwrap(), "--json"]);
    assert!(stdout(&o).contains("\"torsion\":[[],[2],[],[]]"), "{}", stdout(&o));
}

/// The generator of the torsion summand carries the exact order, in the library, in the text
/// form and as a JSON number.
#[test]
fn generators_of_torsion_beyond_two_to_the_64() {
    let m = lens_union(&primes(53));
    let c = cellular_complex(&m).unwrap();
    let g = gmap_homology::generators::generators(&c.chain, None).unwrap();
    let p53: Natural = P53.parse().unwrap();
    let torsion: Vec<_> = g.iter().filter(|x| x.order != 0).map(|x| (x.dim, x.order.clone())).collect();
    assert_eq!(torsion, vec![(1, p53)]);
    assert_eq!(g.iter().filter(|x| x.order == 0).count(), 32);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("lens53.gmap");
    gmap_core::io::write_gmap(&m, &path).unwrap();
    let file = path.to_str().unwrap();
    let o = gmap(&["homology", file, "--generators"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert_eq!(out.matches(&format!("generator of H_1 (Z/{P53}): ")).count(), 1, "{out}");
    let o = gmap(&["homology", file, "--generators", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains(&format!("\"order\":{P53}")), "{out}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let orders: Vec<String> = v["generators"].as_array().unwrap().iter().map(|x| x["order"].to_string()).collect();
    assert_eq!(orders.iter().filter(|o| *o == P53).count(), 1);
    assert_eq!(orders.iter().filter(|o| *o == "0").count(), 32);
}
