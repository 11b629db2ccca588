use super::*;

#[test]
fn gudhis_one_sphere_and_the_refusals() {
    // GUDHI's test_cubical_complex.py CubicalOneSphere.txt: a 3×3 box, 100 in its middle
    let p = parse_perseus_cubical("2\n3\n3\n0\n0\n0\n0\n100\n0\n0\n0\n0\n").unwrap();
    assert_eq!(p.sizes, vec![3, 3]);
    assert_eq!(p.periodic, vec![false, false]);
    assert_eq!(p.values, vec![0.0, 0.0, 0.0, 0.0, 100.0, 0.0, 0.0, 0.0, 0.0]);
    // comments, blank lines and a periodic axis
    let p = parse_perseus_cubical("# a torus\n2\n-2\n\n1\n# values\n1.5\n-1\n").unwrap();
    assert_eq!((p.sizes, p.periodic, p.values), (vec![2, 1], vec![true, false], vec![1.5, -1.0]));
    let e = |t: &str| parse_perseus_cubical(t).unwrap_err().to_string();
    assert!(matches!(parse_perseus_cubical("# nothing\n\n"), Err(ImportError::Empty)));
    assert_eq!(e("0\n"), "line 1: the dimension \"0\" is not an integer from 1 to 8");
    assert_eq!(e("2\n3\n"), "line 2: the file ends after 1 of 2 sizes");
    assert_eq!(e("1\n0\n"), "line 2: the size \"0\" is not a non-zero integer");
    assert_eq!(e("1\n3\n1\n2\n"), "line 4: the file ends after 2 of 3 values of a [3] complex");
    assert_eq!(e("1\n2\n1\nx\n"), "line 4: the value \"x\" is not a number");
    assert_eq!(e("1\n1\n1\n2\n"), "line 4: more lines after the 1 values: \"2\"");
}

#[test]
fn a_simplicial_file_and_its_refusals() {
    // Perseus's nmfsimtop: a hollow triangle's edges born at 1, 2, 3, its vertices at 0
    let text = "1\n# vertices\n0 1 0\n0 2 0\n0 3 0\n1 1 2 1\n1 2 3 2\n1 1 3 3.5\n";
    assert!(is_simplicial(text));
    assert!(!is_simplicial("2\n3\n3\n0\n"));
    let (s, v) = parse_perseus_simplicial(text).unwrap();
    assert_eq!(s, vec![vec![1], vec![2], vec![3], vec![1, 2], vec![2, 3], vec![1, 3]]);
    assert_eq!(v, vec![0.0, 0.0, 0.0, 1.0, 2.0, 3.5]);
    let e = |t: &str| parse_perseus_simplicial(t).unwrap_err().to_string();
    assert_eq!(e("2\n0 1 0\n"), "line 1: a Perseus simplicial file begins with the line 1, not \"2\"");
    assert_eq!(e("1\n1 1 0\n"), "line 2: a 1-simplex is its dimension, 2 labels and a birth: 4 numbers, not 3");
    assert_eq!(e("1\n0 -1 0\n"), "line 2: the vertex label \"-1\" is not a non-negative integer");
    assert_eq!(e("1\n0 1 x\n"), "line 2: the birth \"x\" is not a number");
    assert!(matches!(parse_perseus_simplicial("1\n"), Err(ImportError::Empty)));
    // the fuzzer's input (perseus_reader): a dimension of usize::MAX overflowed k + 3
    assert_eq!(
        e("1\n18446744073709551615 1.0\n"),
        "line 2: a 18446744073709551615-simplex is its dimension, 18446744073709551616 labels and a birth: 18446744073709551618 numbers, not 2"
    );
    let fuzzed = "\x0b\x0b1\n0000000000000018446744073709551615\x0b\x0b#1.00\n \n11111";
    assert!(parse_perseus_simplicial(fuzzed).is_err());
}
