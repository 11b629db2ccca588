//! Persistence diagrams equal, as multisets of (dimension, birth, death), to GUDHI's
//! `CubicalComplex`, `PeriodicCubicalComplex` and `SimplexTree`, recorded by
//! `benches/anchors/persistence_fixtures.py` under `tests/data/images` and
//! `tests/data/persistence`.

use std::path::PathBuf;

use gmap_homology::persistence::{
    cubical_persistence, Construction, CubicalOptions, Diagram, FilteredComplex, SimplexValues,
};
use gmap_ops::import::image::{Image, Order};
use gmap_ops::import::raster::read_raster;
use serde_json::Value;

fn data(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tests/data").join(rel)
}

fn num(v: &Value) -> f64 {
    match v {
        Value::String(s) if s == "inf" => f64::INFINITY,
        Value::String(s) if s == "-inf" => f64::NEG_INFINITY,
        _ => v.as_f64().expect("a number"),
    }
}

type Multiset = Vec<(usize, u64, u64)>;

fn expected(pairs: &Value) -> Multiset {
    let mut v: Multiset = pairs
        .as_array()
        .unwrap()
        .iter()
        .map(|p| (p[0].as_u64().unwrap() as usize, num(&p[1]).to_bits(), num(&p[2]).to_bits()))
        .collect();
    v.sort_unstable();
    v
}

fn ours(d: &Diagram) -> Multiset {
    // -0.0 and 0.0 are one value
    let b = |x: f64| (x + 0.0).to_bits();
    let mut v: Multiset = d.pairs.iter().map(|p| (p.dim, b(p.birth), b(p.death))).collect();
    v.sort_unstable();
    v
}

fn options(key: &str) -> CubicalOptions {
    let parts: Vec<&str> = key.split('_').collect();
    CubicalOptions {
        construction: parts[0].parse::<Construction>().unwrap(),
        superlevel: parts[1] == "super",
        periodic: parts[2] == "p",
        field: parts[3].parse().unwrap(),
        cycles: false,
    }
}

fn check_all(what: &str, shape: &[usize], values: &[f64], diagrams: &Value) {
    let mut n = 0;
    for (key, pairs) in diagrams.as_object().unwrap() {
        let mut opts = options(key);
        let want = expected(pairs);
        let got = cubical_persistence(shape, values, &opts).unwrap();
        assert_eq!(ours(&got), want, "{what} {key}");
        // the reduction of every dimension (the path that gives cycles) agrees too
        opts.cycles = true;
        let got = cubical_persistence(shape, values, &opts).unwrap();
        assert_eq!(ours(&got), want, "{what} {key} with cycles");
        n += 1;
    }
    assert_eq!(n, 16, "{what}: every key compared");
}

#[test]
fn sample_images_equal_gudhi() {
    for name in ["camera", "coins", "moon", "page", "text", "clock", "brick", "grass", "gravel", "checkerboard"] {
        let rec: Value =
            serde_json::from_str(&std::fs::read_to_string(data(&format!("images/{name}.json"))).unwrap()).unwrap();
        let img = Image::read(&data(&format!("images/{name}.npy"))).unwrap();
        assert_eq!(img.order(), Order::C);
        let shape: Vec<usize> = rec["shape"].as_array().unwrap().iter().map(|x| x.as_u64().unwrap() as usize).collect();
        assert_eq!(img.shape(), shape.as_slice());
        let values: Vec<f64> = (0..img.len()).map(|i| img.value(i)).collect();
        // the PGM copy holds the same pixels
        let pgm = read_raster(&data(&format!("images/{name}.pgm"))).unwrap();
        assert_eq!(pgm.shape(), img.shape());
        assert!((0..pgm.len()).all(|i| pgm.value(i) == values[i]), "{name}.pgm");
        check_all(name, &shape, &values, &rec["diagrams"]);
    }
}

#[test]
fn random_arrays_equal_gudhi() {
    let cases: Value =
        serde_json::from_str(&std::fs::read_to_string(data("persistence/random.json")).unwrap()).unwrap();
    for (i, case) in cases.as_array().unwrap().iter().enumerate() {
        let shape: Vec<usize> =
            case["shape"].as_array().unwrap().iter().map(|x| x.as_u64().unwrap() as usize).collect();
        let values: Vec<f64> = case["values"].as_array().unwrap().iter().map(num).collect();
        check_all(&format!("case {i} {shape:?}"), &shape, &values, &case["diagrams"]);
    }
}

fn facets(file: &str) -> Vec<Vec<u64>> {
    let text = std::fs::read_to_string(data(&format!("lutz/{file}"))).unwrap();
    text.lines()
        .map(|l| l.split('#').next().unwrap().trim())
        .filter(|l| !l.is_empty())
        .map(|l| l.split_whitespace().map(|x| x.parse().unwrap()).collect())
        .collect()
}

#[test]
fn lutz_random_filtrations_equal_gudhi() {
    let cases: Value = serde_json::from_str(&std::fs::read_to_string(data("persistence/lutz.json")).unwrap()).unwrap();
    for case in cases.as_array().unwrap() {
        let file = case["file"].as_str().unwrap();
        let f = facets(file);
        let fvals: Vec<f64> = case["facet_values"].as_array().unwrap().iter().map(num).collect();
        let vvals: std::collections::HashMap<u64, f64> =
            case["vertex_values"].as_array().unwrap().iter().map(|p| (p[0].as_u64().unwrap(), num(&p[1]))).collect();
        let per_facet = FilteredComplex::from_simplices(&f, SimplexValues::PerSimplex(&fvals)).unwrap();
        let lookup = |v: u64| vvals.get(&v).copied();
        let lower = FilteredComplex::from_simplices(&f, SimplexValues::LowerStar(&lookup)).unwrap();
        for p in [2u32, 3] {
            let key = p.to_string();
            let got = per_facet.diagram(p, false).unwrap();
            assert_eq!(ours(&got), expected(&case["per_facet"][&key]), "{file} per facet over Z/{p}");
            let got = per_facet.diagram(p, true).unwrap();
            assert_eq!(ours(&got), expected(&case["per_facet"][&key]), "{file} per facet over Z/{p}, cycles");
            let got = lower.diagram(p, false).unwrap();
            assert_eq!(ours(&got), expected(&case["lower_star"][&key]), "{file} lower star over Z/{p}");
        }
    }
}
