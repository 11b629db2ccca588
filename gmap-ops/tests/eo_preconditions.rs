//! Each operator's precondition is stated once, beside its check: every refusal of a failed
//! precondition reports the operator's own `precondition()`, every operator that can fail one
//! does on some object, and every argument an operator asks for is named in its precondition.

use std::collections::BTreeSet;

use gmap_ops::euler::strata::{EoArgs, EoOperator, StrataError, StratifiedObject};

fn run(o: &mut StratifiedObject, name: &str, a: EoArgs) -> usize {
    o.apply_named(name, &a).unwrap_or_else(|e| panic!("{name}: {e}")).new.first().copied().unwrap_or(usize::MAX)
}

/// One object holding strata of every dimension and state: a triangle filled by a face, a
/// circle edge, a sphere face, a solid ball, an open edge, an open face with an open hole,
/// an open solid with an open 2-hole, an isolated vertex.
fn zoo() -> StratifiedObject {
    let mut o = StratifiedObject::new();
    let v: Vec<usize> = (0..3).map(|_| run(&mut o, "mvC", EoArgs::new())).collect();
    let comp = |o: &StratifiedObject, s: usize| o.strata[s].component;
    let c = comp(&o, v[0]);
    let (c1, c2) = (comp(&o, v[1]), comp(&o, v[2]));
    let e0 = run(&mut o, "mekC", EoArgs::new().c(c).c2(c1).on(&[v[0], v[1]]));
    let e1 = run(&mut o, "mekC", EoArgs::new().c(c).c2(c2).on(&[v[1], v[2]]));
    let e2 = run(&mut o, "meCh", EoArgs::new().c(c).on(&[v[2], v[0]]));
    run(&mut o, "mfkCh", EoArgs::new().c(c).on(&[e0, e1, e2, v[0], v[1], v[2]]));
    run(&mut o, "meehCCh", EoArgs::new());
    let sphere = run(&mut o, "mffcCCc", EoArgs::new());
    let cs = comp(&o, sphere);
    run(&mut o, "mskCc", EoArgs::new().c(cs).on(&[sphere]));
    run(&mut o, "me∞E∞", EoArgs::new());
    let f = run(&mut o, "mf∞F∞", EoArgs::new());
    run(&mut o, "mf∞hF∞h", EoArgs::new().s(f));
    let s = run(&mut o, "ms∞S∞", EoArgs::new());
    run(&mut o, "ms∞cS∞c", EoArgs::new().s(s));
    run(&mut o, "mvC", EoArgs::new());
    o
}

/// A small deterministic generator (xorshift), so the arguments tried are the same each run.
struct Gen(u64);

impl Gen {
    fn below(&mut self, n: usize) -> usize {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 % n as u64) as usize
    }
    fn some(&mut self, n: usize, max_len: usize) -> Vec<usize> {
        let len = self.below(max_len + 1);
        (0..len).map(|_| self.below(n)).collect()
    }
}

#[test]
fn every_refusal_reports_the_operators_own_precondition() {
    let o = zoo();
    let (ns, nc) = (o.strata.len(), o.components.len());
    let mut g = Gen(0x9e37_79b9_7f4a_7c15);
    let mut refused: BTreeSet<&str> = BTreeSet::new();
    for op in EoOperator::ALL {
        for _ in 0..1500 {
            let a = EoArgs::new()
                .s(g.below(ns))
                .t(g.below(ns))
                .u(g.below(ns))
                .c(g.below(nc))
                .c2(g.below(nc))
                .c3(g.below(nc))
                .on(&g.some(ns, 3))
                .moved(&g.some(ns, 3))
                .moved2(&g.some(ns, 2));
            let mut x = o.clone();
            if let Err(StrataError::Precondition { op: name, requires, why }) = x.apply(*op, &a) {
                assert_eq!(name, op.name());
                assert_eq!(requires, op.precondition(), "{name} refused ({why}) citing another precondition");
                assert_eq!(x, o, "{name} refused but changed the object");
                refused.insert(op.name());
            }
        }
    }
    // only an operator that requires nothing is never refused for its precondition
    for op in EoOperator::ALL {
        assert!(
            refused.contains(op.name()) || op.precondition().starts_with("none:"),
            "{}: no refusal found for its precondition {:?}",
            op.name(),
            op.precondition()
        );
    }
    assert!(refused.len() >= 90, "{} operators refused", refused.len());
}

#[test]
fn every_argument_asked_for_is_named_in_the_precondition() {
    let o = zoo();
    let args = ["s", "t", "u", "c", "c2", "c3"];
    for op in EoOperator::ALL {
        let mut a = EoArgs::new();
        for _ in 0..args.len() {
            let Err(StrataError::Missing { op: name, what }) = o.clone().apply(*op, &a) else { break };
            assert_eq!(name, op.name());
            let arg = what.split(|ch: char| !ch.is_alphanumeric()).rfind(|w| args.contains(w));
            let arg = arg.unwrap_or_else(|| panic!("{name}: {what:?} names no argument"));
            let words: Vec<&str> = op.precondition().split(|ch: char| !ch.is_alphanumeric()).collect();
            assert!(words.contains(&arg), "{name} asks for {what} but its precondition does not name {arg}");
            a = match arg {
                "s" => a.s(0),
                "t" => a.t(0),
                "u" => a.u(0),
                "c" => a.c(0),
                "c2" => a.c2(0),
                _ => a.c3(0),
            };
        }
    }
}

#[test]
fn unknown_names_are_refused_by_name() {
    assert_eq!(
        StratifiedObject::new().apply_named("mxyz", &EoArgs::new()),
        Err(StrataError::UnknownOperator("mxyz".to_string()))
    );
}
