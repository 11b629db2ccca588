//! Euler–Poincaré operators: the tables of AC §7 and exact expansions.

use gmap_homology::ep::{elementary_operators, EpError, EpPolynomial, EpVector, Poly};
use proptest::prelude::*;

fn v(x: &[i64], y: &[i64]) -> EpVector {
    EpVector::try_new(x.to_vec(), y.to_vec()).unwrap()
}

/// (polynomial coefficients, mnemonic, description) of each elementary operator.
fn table(n: usize) -> Vec<(Vec<i64>, String, String)> {
    elementary_operators(n)
        .into_iter()
        .map(|o| (o.vector.to_poly().coeffs().to_vec(), o.mnemonic, o.description))
        .collect()
}

#[test]
fn section_7_1_dimension_1() {
    let t = table(1);
    assert_eq!(
        t,
        vec![
            (vec![0, 1, -1], "mekc".into(), "make edge, kill component".into()), // X - X^2
            (vec![1, 0, 1], "mvmc".into(), "make vertex and component".into()),  // 1 + X^2
            (vec![0, 1, 0, 1], "meml".into(), "make edge and loop".into()),      // X + X^3
        ]
    );
    // A = 1 - X is not an operator for n = 1 (Lemma 6.2 (14))
    assert!(!Poly::new(vec![1, -1]).is_operator(1).unwrap());
    assert!(!v(&[1, -1], &[0, 0]).is_operator());
    // F = a0 + a1 X + a2 X^2 + a3 X^3 = (a1 - a3) A_1 + a0 B_0 + a3 B_1 on the hyperplane
    let f = v(&[5, 2], &[3, 0]); // 5 - 2 = 3 - 0
    let e = f.expand_ab().unwrap();
    assert_eq!((e.gamma.clone(), e.delta.clone()), (vec![2], vec![5, 0]));
    assert_eq!(f.to_poly().expand_ab(1).unwrap(), e);
}

#[test]
fn section_7_2_dimension_2() {
    let t = table(2);
    let polys: Vec<Vec<i64>> = t.iter().map(|r| r.0.clone()).collect();
    assert_eq!(
        polys,
        vec![
            vec![0, 1, 0, -1],      // X - X^3: make edge, kill component
            vec![0, 0, 1, 0, -1],   // X^2 - X^4 = X_2 - Y_1
            vec![1, 0, 0, 1],       // 1 + X^3: make vertex and component
            vec![0, 1, 0, 0, 1],    // X + X^4: make edge and loop
            vec![0, 0, 1, 0, 0, 1], // X^2 + X^5: make area and shell
        ]
    );
    assert_eq!(t[4].2, "make area and shell");
    assert_eq!(t[4].1, "mams");
    assert_eq!(t[1].2, "make area, kill loop");
    // 1 - X^2 = X_0 - X_2 (make vertex, kill area) is an operator: (1 + X)(1 - X)
    let f = Poly::new(vec![1, 0, -1]);
    assert!(f.is_operator(2).unwrap());
    assert_eq!(Poly::new(vec![1, 1]).try_mul(&Poly::new(vec![1, -1])).unwrap(), f);
    assert_eq!(Poly::new(vec![1, 1]).try_mul(&Poly::new(vec![1, -1, 1])).unwrap(), Poly::new(vec![1, 0, 0, 1]));
    // the closed form of §7.2: F(-1) + (a1 - a2 - a4 + a5) A_1 + (a2 - a5) A_2 + (a0 - F(-1)) B_0
    //   + (a2 + a4 - a5) B_1 + a5 B_2
    let e = f.expand_ab(2).unwrap();
    assert_eq!(e.gamma, vec![1, -1]);
    assert_eq!(e.delta, vec![1, -1, 0]);
    // Example 6.6: 1 - X^n = Σ (-1)^{i-1} A_i + Σ_{j<n} (-1)^j B_j
    assert_eq!(EpVector::from_poly(&f, 2).unwrap().expand_ab().unwrap(), e);
    assert_eq!(e.recombine(2).unwrap(), v(&[1, 0, -1], &[0, 0, 0]));
    // K and L of Example 5.3
    assert_eq!(EpVector::l(2, 0), v(&[1, 0, 0], &[1, 0, 0]));
    assert_eq!(EpVector::l(2, 1), v(&[-1, 0, 0], &[0, 1, 0]));
    assert_eq!(EpVector::l(2, 2), v(&[1, 0, 0], &[0, 0, 1]));
    assert_eq!(EpVector::k(2, 1), v(&[1, 1, 0], &[0, 0, 0]));
    assert_eq!(EpVector::k(2, 2), v(&[-1, 0, 1], &[0, 0, 0]));
    // and the polynomial of an even-n non-operator: F(-1) != 0
    assert!(!Poly::new(vec![1, 1, 1]).is_operator(2).unwrap());
}

#[test]
fn section_7_3_dimension_3() {
    let t = table(3);
    let expect: Vec<(Vec<i64>, &str, &str)> = vec![
        (vec![0, 1, 0, 0, -1], "mekc", "make edge, kill component"),
        (vec![0, 0, 1, 0, 0, -1], "makl", "make area, kill loop"),
        (vec![0, 0, 0, 1, 0, 0, -1], "mbks", "make volume, kill shell"),
        (vec![1, 0, 0, 0, 1], "mvmc", "make vertex and component"),
        (vec![0, 1, 0, 0, 0, 1], "meml", "make edge and loop"),
        (vec![0, 0, 1, 0, 0, 0, 1], "mams", "make area and shell"),
        (vec![0, 0, 0, 1, 0, 0, 0, 1], "mbmh3", "make volume and 3-hole"),
    ];
    let got: Vec<(Vec<i64>, &str, &str)> = t.iter().map(|r| (r.0.clone(), r.1.as_str(), r.2.as_str())).collect();
    assert_eq!(got, expect);
    // the §7.3 closed forms on a concrete vector: α = (2, 3, 1, 4; 2, 5, 2, 3)
    let f = v(&[2, 3, 1, 4], &[2, 5, 2, 3]);
    assert!(f.is_operator());
    let a = f.to_poly();
    let c = |k: usize| a.coeff(k);
    let g1 = (c(1) - c(5)) - (c(2) - c(6)) + (c(3) - c(7));
    let g2 = (c(2) - c(6)) - (c(3) - c(7));
    let g3 = c(3) - c(7);
    let d1 = c(5) + (c(2) - c(6)) - (c(3) - c(7));
    let d2 = c(6) + c(3) - c(7);
    let e = a.expand_ab(3).unwrap();
    assert_eq!(e.gamma, vec![g1, g2, g3]);
    assert_eq!(e.delta, vec![c(0), d1, d2, c(7)]);
    assert_eq!(e.gamma, vec![0, -2, 1]);
    assert_eq!(e.delta, vec![2, 3, 3, 3]);
    assert_eq!(f.expand_ab().unwrap(), e);
    assert_eq!(e.recombine(3).unwrap(), f);
    // 1 - X^3 is not an operator for n = 3 (Lemma 6.2: A ∈ 𝔍 iff n even); 1 - X^4 for n = 4 is
    assert!(!Poly::new(vec![1, 0, 0, -1]).is_operator(3).unwrap());
    assert!(Poly::new(vec![1, 0, 0, 0, -1]).is_operator(4).unwrap());
    // Lemma 6.10 / (24): A_0 B_0 = (1 - X^n)(1 + X^{n+1}) is an operator for n odd
    let ab = Poly::new(vec![1, 0, 0, -1]).try_mul(&Poly::new(vec![1, 0, 0, 0, 1])).unwrap();
    assert!(ab.is_operator(3).unwrap());
}

#[test]
fn non_operators_are_refused() {
    let f = v(&[1, 0], &[0, 0]);
    assert_eq!(f.expand_ab(), Err(EpError::NotOnHyperplane { defect: 1 }));
    assert_eq!(f.to_poly().expand_ab(1), Err(EpError::NotOnHyperplane { defect: 1 }));
    assert_eq!(EpVector::from_poly(&Poly::monomial(4), 1), Err(EpError::DegreeTooHigh { degree: 4, n: 1, max: 3 }));
    assert!(v(&[1, 0, 0], &[1, 0, 0]).is_configuration());
    assert!(!v(&[-1, 0, 0], &[-1, 0, 0]).is_configuration());
    // Prop. 4.2: a configuration has non-negative K/L coefficients with inequality (7)
    assert!(v(&[3, 3, 1], &[1, 0, 0]).satisfies_prop_4_2().unwrap());
    assert!(!v(&[0, 1, 0], &[0, 0, 0]).is_operator());
}

fn on_hyperplane(n: usize, raw: Vec<i64>) -> EpVector {
    // adjust X_0 so that the alternating sum vanishes
    let mut x = raw[..=n].to_vec();
    let y = raw[n + 1..].to_vec();
    let s: i64 = x.iter().zip(&y).enumerate().map(|(i, (a, b))| if i.is_multiple_of(2) { a - b } else { b - a }).sum();
    x[0] -= s;
    v(&x, &y)
}

proptest! {
    /// Random operators of dimensions 1..=4: both expansions (recursive and closed form)
    /// agree and recombine exactly; the K/L expansion too; polynomial membership agrees.
    #[test]
    fn random_expansions_recombine(n in 1usize..=4, raw in prop::collection::vec(-50i64..50, 10)) {
        let f = on_hyperplane(n, raw[..2 * n + 2].to_vec());
        prop_assert!(f.is_operator());
        prop_assert!(f.to_poly().is_operator(n).unwrap());
        let e = f.expand_ab().unwrap();
        prop_assert_eq!(&f.to_poly().expand_ab(n).unwrap(), &e);
        prop_assert_eq!(e.recombine(n).unwrap(), f.clone());
        prop_assert_eq!(f.expand_kl().unwrap().recombine(n).unwrap(), f.clone());
        // one step off the hyperplane is refused both ways
        let g = f.try_add(&EpVector::x_unit(n, 0)).unwrap();
        prop_assert!(!g.is_operator());
        prop_assert!(!g.to_poly().is_operator(n).unwrap());
    }
}
