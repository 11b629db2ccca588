use super::*;
use crate::cellular::checked::cellular_complex;
use crate::cellular::incidence::Incidence;
use crate::cellular::precond::check_preconditions;
use crate::engine::homology::homology_z;
use gmap_core::examples;

#[test]
fn matrix_agrees_with_pairwise_incidence() {
    for m in [examples::cylinder(), examples::torus(), examples::klein_bottle()] {
        let c = cellular_complex(&m).unwrap();
        c.chain.check_dd().unwrap();
        let oriented: Vec<_> = (0..=2).map(|i| crate::cellular::precond::oriented_cells(&m, i).unwrap()).collect();
        for i in 1..=2 {
            let inc = Incidence::new(&m, i);
            for (col, &cd) in c.reps[i].iter().enumerate() {
                for (row, &fd) in c.reps[i - 1].iter().enumerate() {
                    let want = inc.signed_with(&oriented[i], &oriented[i - 1], cd, fd);
                    assert_eq!(c.chain.boundary(i).get(row, col), want);
                }
            }
        }
    }
}

/// The local formulas agree with the orbit walks of BO Def. 9 in every dimension.
#[test]
fn local_formulas_agree_with_walks() {
    let mut maps = vec![examples::cylinder(), examples::torus(), examples::klein_bottle(), examples::fig1_surface()];
    maps.push(gmap_core::examples::torus().embedded(3).unwrap());
    for m in maps {
        let Ok(oriented) = check_preconditions(&m) else { continue };
        assert_eq!(border_from_oriented(&m, &oriented).chain, border_by_walks(&m, &oriented).chain);
    }
}

#[test]
fn cylinder_homology() {
    let c = cellular_complex(&examples::cylinder()).unwrap();
    assert_eq!(c.chain.counts(), &[2, 3, 1]);
    let h = homology_z(&c.chain).unwrap();
    assert_eq!(h.betti, vec![1, 1, 0]);
}
