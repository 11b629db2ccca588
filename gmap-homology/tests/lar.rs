//! LAR: characteristic matrices, the count rule, and where the vertex-set model loses
//! information (multi-incidence).

use gmap_core::{examples, DenseMap};
use gmap_homology::arch::{cell_incidences, ArchComplex};
use gmap_homology::lar::{characteristic_matrix, Lar, LarOp};
use gmap_homology::{cellular_complex, Incidence};

/// The unsigned incidence numbers (BO Def. 5) of the i-cells on the (i-1)-cells as a dense
/// matrix, rows (i-1)-cells, computed by the homology crate's `Incidence`.
fn unsigned_matrix(m: &DenseMap, i: usize) -> Vec<Vec<i64>> {
    let inc = Incidence::new(m, i);
    let lo = m.cells(i - 1).reps;
    let hi = m.cells(i).reps;
    lo.iter().map(|&f| hi.iter().map(|&c| inc.unsigned(c, f) as i64).collect()).collect()
}

#[test]
fn count_rule_equals_unsigned_incidence_without_multi_incidence() {
    for m in [examples::fig1_curve(), examples::fig1_surface()] {
        let lar = Lar::from_map(&m);
        for p in 1..=m.dim() {
            let u = unsigned_matrix(&m, p);
            assert!(u.iter().flatten().all(|&x| x <= 1), "no multi-incidence");
            assert_eq!(lar.unsigned_boundary(p).unwrap().to_dense(), u, "dimension {p}");
        }
    }
    // the square and the triangle of BO Fig. 1(b): 5 vertices, 6 edges, 2 faces
    let lar = Lar::from_map(&examples::fig1_surface());
    assert_eq!(lar.vertices(), 5);
    let fe = lar.operator(LarOp::FE).unwrap().to_dense();
    // a face shares 2 vertices with each of its own edges
    let b2 = lar.unsigned_boundary(2).unwrap();
    let mut own = 0;
    for (f, row) in fe.iter().enumerate() {
        for (e, &shared) in row.iter().enumerate() {
            if b2.get(e, f) == 1 {
                assert_eq!(shared, 2);
                own += 1;
            }
        }
    }
    assert_eq!(own, 7); // 4 + 3 edges
    assert_eq!(fe.len(), 2);
    // FF: the square has 4 vertices, the triangle 3, sharing 2
    let ff = lar.operator(LarOp::FF).unwrap().to_dense();
    let mut diag = vec![ff[0][0], ff[1][1]];
    diag.sort();
    assert_eq!(diag, vec![3, 4]);
    assert_eq!(ff[0][1], 2);
    assert_eq!(lar.operator(LarOp::VE).unwrap(), lar.operator(LarOp::EV).unwrap().transpose());
    assert_eq!(lar.operator(LarOp::VV).unwrap().rows(), 5);
    for op in LarOp::ALL {
        assert!(lar.operator(op).is_ok());
    }
}

#[test]
fn one_vertex_torus_loses_information() {
    let t = examples::torus();
    assert_eq!(t.cell_counts(), vec![1, 2, 1]);
    let lar = Lar::from_map(&t);
    // both edges and the face have the vertex set {v}
    assert_eq!(lar.characteristic(1).to_dense(), vec![vec![1], vec![1]]);
    assert_eq!(lar.characteristic(2).to_dense(), vec![vec![1]]);
    // the two edges are indistinguishable: EE is all ones
    assert_eq!(lar.operator(LarOp::EE).unwrap().to_dense(), vec![vec![1, 1], vec![1, 1]]);
    // the count rule says 1 everywhere, the G-map says 2 (unsigned) and 0 (signed)
    assert_eq!(lar.unsigned_boundary(1).unwrap().to_dense(), vec![vec![1, 1]]);
    assert_eq!(lar.unsigned_boundary(2).unwrap().to_dense(), vec![vec![1], vec![1]]);
    assert_eq!(unsigned_matrix(&t, 1), vec![vec![2, 2]]);
    assert_eq!(unsigned_matrix(&t, 2), vec![vec![2], vec![2]]);
    let signed: Vec<i64> = cell_incidences(&t, 2).unwrap().iter().map(|c| c.signed()).collect();
    assert_eq!(signed, vec![0, 0]);
    // so does the cylinder's seam (BO Fig. 2: unsigned 1, 2, 1, 2 from the face)
    let cyl = examples::cylinder();
    let c2: Vec<u32> = cell_incidences(&cyl, 2).unwrap().iter().map(|c| c.unsigned()).collect();
    assert_eq!(c2.len(), 3);
    assert_eq!(c2.iter().filter(|&&u| u == 2).count(), 1);
}

#[test]
fn my_incidences_agree_with_the_border_operator() {
    for m in [examples::torus(), examples::klein_bottle(), examples::cylinder(), examples::fig1_surface()] {
        let x = ArchComplex::from_map(&m).unwrap();
        let mine = x.chain_complex();
        let theirs = cellular_complex(&m).map(|c| c.chain);
        if let Ok(theirs) = theirs {
            for k in 1..=m.dim() {
                assert_eq!(mine.boundary(k).to_dense(), theirs.boundary(k).to_dense(), "∂_{k}");
            }
        }
        for i in 1..=m.dim() {
            let inc = Incidence::new(&m, i);
            let (hi, lo) = (m.cells(i).reps, m.cells(i - 1).reps);
            for c in cell_incidences(&m, i).unwrap() {
                let (cd, fd) = (hi[c.upper as usize], lo[c.lower as usize]);
                assert_eq!(c.unsigned() as usize, inc.unsigned(cd, fd));
                assert_eq!(c.signed(), inc.signed(&m, cd, fd).unwrap());
            }
        }
    }
}

#[test]
fn characteristic_matrix_products() {
    let a = characteristic_matrix(3, &[vec![0, 2], vec![1]]).unwrap();
    assert_eq!(a.to_dense(), vec![vec![1, 0, 1], vec![0, 1, 0]]);
    assert_eq!(a.checked_mul(&a.transpose()).unwrap().to_dense(), vec![vec![2, 0], vec![0, 1]]);
    assert!(characteristic_matrix(2, &[vec![2]]).is_err());
    let lar = Lar::from_map(&examples::fig1_surface());
    let json = lar.to_json().unwrap();
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(v["dimension"], 2);
    assert_eq!(v["cells"][0].as_array().unwrap().len(), 6);
    assert_eq!(v["boundary"][1].as_array().unwrap().len(), 2);
}

#[test]
fn characteristic_beyond_the_dimension_is_an_error() {
    let lar = Lar::from_map(&examples::fig1_surface());
    assert_eq!(lar.dim(), 2);
    assert_eq!(lar.try_characteristic(0).unwrap().rows(), lar.vertices());
    assert_eq!(lar.try_characteristic(2).unwrap(), lar.characteristic(2));
    assert_eq!(
        lar.try_characteristic(3).unwrap_err().to_string(),
        gmap_homology::lar::LarError::NoSuchDimension { p: 3, n: 2 }.to_string()
    );
    assert!(lar.try_characteristic(usize::MAX).is_err());
}
