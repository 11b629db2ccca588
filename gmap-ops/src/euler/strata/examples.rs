//! The two worked examples of EO §4, step by step.

use super::catalogue::{EoArgs, EoOperator};
use super::object::{EoStep, StratifiedObject};

fn run(o: &mut StratifiedObject, name: &str, args: EoArgs) -> EoStep {
    let op = EoOperator::from_name(name).expect("an operator of the catalogue");
    o.apply(op, &args).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// EO Example 1 (Figure 17), the stratified Cartan umbrella, step by step: the vertex
/// `v1` at the origin as a component (`mvC`), the two unbounded half-axes `e1`, `e2`
/// attached to it with their edge components (`me∞E∞` twice), and the two unbounded sheets
/// `f1`, `f2` attached to `e1` and `e2` with their face components (`mf∞F∞` twice). Every
/// stratum but `v1` is boundary-incomplete; at the end `C = 1`, `E∞ = 2`, `F∞ = 2` and
/// χ = 1 − 2 + 2 = 1 by both theorems.
pub fn example_1() -> Vec<EoStep> {
    let mut o = StratifiedObject::new();
    let s = run(&mut o, "mvC", EoArgs::new());
    let v1 = s.new[0];
    let mut steps = vec![s];
    let s = run(&mut o, "me∞E∞", EoArgs::new().on(&[v1]));
    let e1 = s.new[0];
    steps.push(s);
    let s = run(&mut o, "me∞E∞", EoArgs::new().on(&[v1]));
    let e2 = s.new[0];
    steps.push(s);
    steps.push(run(&mut o, "mf∞F∞", EoArgs::new().on(&[e1, v1])));
    steps.push(run(&mut o, "mf∞F∞", EoArgs::new().on(&[e2, v1])));
    steps
}

/// EO Example 2 (Figure 18), step by step: a circle edge `e1` with its hole (`meehCCh`),
/// a face `f1` filling it (`mfkCh`), a second face `f2` closing a void (`mfCc`), a vertex
/// `v1` put in `f1` (`mvfh`), and a loop edge `e2` at `v1` (`meCh`). The final object is a
/// sphere with a loop attached: one component, one global 1-hole, one 2-hole, χ = 1.
pub fn example_2() -> Vec<EoStep> {
    let mut o = StratifiedObject::new();
    let s = run(&mut o, "meehCCh", EoArgs::new());
    let (e1, c) = (s.new[0], s.new_components[0]);
    let mut steps = vec![s];
    let s = run(&mut o, "mfkCh", EoArgs::new().c(c).on(&[e1]));
    let f1 = s.new[0];
    steps.push(s);
    steps.push(run(&mut o, "mfCc", EoArgs::new().c(c).on(&[e1])));
    let s = run(&mut o, "mvfh", EoArgs::new().s(f1));
    let v1 = s.new[0];
    steps.push(s);
    steps.push(run(&mut o, "meCh", EoArgs::new().c(c).on(&[v1])));
    steps
}
