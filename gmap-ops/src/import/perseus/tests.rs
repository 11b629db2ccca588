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
