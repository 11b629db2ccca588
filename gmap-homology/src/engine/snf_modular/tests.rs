use super::*;
use crate::engine::ring::ZBig;
use crate::engine::snf::smith_diagonal;

fn big(a: &[&[i64]]) -> Vec<Vec<BigInt>> {
    a.iter().map(|r| r.iter().map(|&v| BigInt::from(v)).collect()).collect()
}

fn reference(a: &[Vec<BigInt>], cols: usize) -> Vec<BigInt> {
    let mut d: Vec<BigInt> = smith_diagonal(&ZBig, a.to_vec(), cols).unwrap().into_iter().map(|x| x.abs()).collect();
    d.sort();
    d
}

#[test]
fn known_matrices() {
    let a = big(&[&[2, 4, 4], &[-6, 6, 12], &[10, -4, -16]]);
    assert_eq!(smith_diagonal_modular(&a, 3).unwrap(), big(&[&[2, 6, 12]])[0]);
    // rank 1, and a zero row and column
    let a = big(&[&[0, 0, 0], &[0, 4, 6], &[0, 0, 0]]);
    assert_eq!(smith_diagonal_modular(&a, 3).unwrap(), big(&[&[2]])[0]);
    // the largest factor equals the determinant: diag(1, 6)
    let a = big(&[&[2, 0], &[0, 3]]);
    assert_eq!(smith_diagonal_modular(&a, 2).unwrap(), big(&[&[1, 6]])[0]);
    assert_eq!(smith_diagonal_modular(&big(&[&[0, 0]]), 2).unwrap(), Vec::<BigInt>::new());
    assert!(is_prime_u64((1 << 61) - 1) && !is_prime_u64((1 << 62) - 1));
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(200))]
    /// The same factors as elimination over `Z`, on small matrices of small entries
    /// (rank-deficient ones included).
    #[test]
    fn agrees_with_elimination_over_z(
        rows in 1usize..6, cols in 1usize..6,
        entries in proptest::collection::vec(-4i64..=4, 36),
        scale in 1i64..4,
    ) {
        let a: Vec<Vec<BigInt>> = (0..rows)
            .map(|i| (0..cols).map(|j| BigInt::from(entries[i * 6 + j] * if i == 0 { scale } else { 1 })).collect())
            .collect();
        proptest::prop_assert_eq!(smith_diagonal_modular(&a, cols).unwrap(), reference(&a, cols));
    }
}
