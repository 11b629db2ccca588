use super::*;

#[test]
fn example_2_counts() {
    let steps = example_2();
    let names: Vec<&str> = steps.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["meehCCh", "mfkCh", "mfCc", "mvfh", "meCh"]);
    // Euler characteristic after each step: circle 0, disc 1, sphere 2, 2, sphere ∨ circle 1
    assert_eq!(steps.iter().map(|s| s.euler).collect::<Vec<_>>(), vec![0, 1, 2, 2, 1]);
    let last = &steps[4];
    assert_eq!(last.complete, vec![1, 2, 2]); // v1; e1, e2; f1, f2
    assert_eq!(last.local_holes[1], 2); // e1's hole eh and f1's hole fh
    assert_eq!(last.components, 1);
    assert_eq!(&last.global_holes[1..3], &[1, 1]); // Ch and Cc
    assert_eq!(steps[1].global_holes[1], 0); // mfkCh filled the hole
}

#[test]
fn theorems_agree_and_errors() {
    let mut o = StratifiedObject::new();
    // an open edge (incomplete) as its own component: a lone open edge cannot be compacted
    let s = o.apply_named("me∞E∞", &EoArgs::new()).unwrap();
    let e = s.new[0];
    assert_eq!(s.euler, -1);
    assert!(o.check());
    let before = o.clone();
    assert_eq!(o.apply_named("ke∞me", &EoArgs::new().s(e)), Err(StrataError::LoneOpenStratum(e)));
    assert_eq!(o, before);
    // with a vertex at an end it can
    let v = o.apply_named("mvC", &EoArgs::new()).unwrap().new[0];
    let s = o.apply_named("ke∞me", &EoArgs::new().s(e).on(&[v])).unwrap();
    assert_eq!(s.incomplete, vec![0, 0]);
    assert!(matches!(o.apply_named("ke∞me", &EoArgs::new().s(e)), Err(StrataError::Precondition { .. })));
    assert_eq!(o.apply_named("kvC", &EoArgs::new().s(7)), Err(StrataError::NoStratum(7)));
}

#[test]
fn names_are_unique_and_inverse_pairs() {
    for (i, op) in EoOperator::ALL.iter().enumerate() {
        assert_eq!(EoOperator::from_name(op.name()), Some(*op));
        assert_eq!(EoOperator::ALL.iter().position(|o| o == op), Some(i));
        let inv = op.inverse_op();
        assert!(EoOperator::ALL.contains(&inv), "{} has no inverse", op.name());
        assert_eq!(inv.euler_effect(), -op.euler_effect());
    }
}
