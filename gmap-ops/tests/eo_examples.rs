//! EO §4's two examples, step by step, with the paper's counts asserted whole after every
//! operator: every count of Theorems 1 and 2 that is not zero, and χ by both formulas.

use gmap_ops::euler::strata::{example_1, example_2, EoStep};

/// One step: the operator's name, the counts that are not zero, χ.
type Row = (String, Vec<(&'static str, i64)>, i64);

fn table(steps: &[EoStep]) -> Vec<Row> {
    steps
        .iter()
        .map(|s| {
            assert_eq!(s.counts.theorem_1(), s.euler, "{}: Theorem 1", s.name);
            assert_eq!(s.counts.theorem_2(), s.euler, "{}: Theorem 2", s.name);
            (s.name.clone(), s.counts.nonzero(), s.euler)
        })
        .collect()
}

fn row(name: &str, counts: &[(&'static str, i64)], chi: i64) -> Row {
    (name.to_string(), counts.to_vec(), chi)
}

#[test]
fn example_1_cartan_umbrella() {
    // EO Example 1 (Figure 17): v1 at the origin, the two half-axes e1, e2 and the two
    // sheets f1, f2, every stratum but v1 unbounded, each with its incomplete component
    assert_eq!(
        table(&example_1()),
        vec![
            row("mvC", &[("v", 1), ("C", 1)], 1),
            row("me∞E∞", &[("v", 1), ("e∞", 1), ("C", 1), ("E∞", 1)], 0),
            row("me∞E∞", &[("v", 1), ("e∞", 2), ("C", 1), ("E∞", 2)], -1),
            row("mf∞F∞", &[("v", 1), ("e∞", 2), ("f∞", 1), ("C", 1), ("E∞", 2), ("F∞", 1)], 0),
            row("mf∞F∞", &[("v", 1), ("e∞", 2), ("f∞", 2), ("C", 1), ("E∞", 2), ("F∞", 2)], 1),
        ]
    );
    // with the exception of v1 all strata are unbounded
    let last = example_1().pop().unwrap();
    assert_eq!((last.complete, last.incomplete), (vec![1, 0, 0], vec![0, 2, 2]));
}

#[test]
fn example_2_figure_18() {
    // EO Example 2 (Figure 18): e1 with its hole eh makes a component C with a hole Ch;
    // f1 fills Ch; f2 makes a void Cc; v1 punches a hole fh through f1 without changing
    // the global shape; e2 at v1 makes a global hole Ch again
    assert_eq!(
        table(&example_2()),
        vec![
            row("meehCCh", &[("e", 1), ("eh", 1), ("C", 1), ("Ch", 1)], 0),
            row("mfkCh", &[("e", 1), ("f", 1), ("eh", 1), ("C", 1)], 1),
            row("mfCc", &[("e", 1), ("f", 2), ("eh", 1), ("C", 1), ("Cc", 1)], 2),
            row("mvfh", &[("v", 1), ("e", 1), ("f", 2), ("eh", 1), ("fh", 1), ("C", 1), ("Cc", 1)], 2),
            row("meCh", &[("v", 1), ("e", 2), ("f", 2), ("eh", 1), ("fh", 1), ("C", 1), ("Ch", 1), ("Cc", 1)], 1),
        ]
    );
}
