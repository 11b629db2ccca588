//! Stratified objects with incomplete boundaries and their Euler operators (EO).
//!
//! EO models a geometric object as a set of *strata* — connected open manifolds of
//! dimension d, not necessarily balls: a stratum may have k-holes (its k-th Betti number,
//! `k >= 1`), and may be *boundary-incomplete* (its closure adds points that are not in the
//! object, as an edge missing an end). Its Euler operators attach and detach strata,
//! subdivide and coalesce them, make and fill holes, and compact strata, without the
//! "boundary first" order of classical B-reps.
//!
//! [`StratifiedObject`] keeps the two levels of EO's bookkeeping: the strata with their
//! local holes (EO Theorem 1) and the connected components of the object with their global
//! holes (EO Theorem 2). Each operator states its effect on both and returns an
//! [`EoStep`]; both theorems must give the same Euler characteristic after every step,
//! which [`StratifiedObject::check`] verifies.
//!
//! In a G-map a boundary-incomplete stratum is a cell with darts free for some `alpha_k`,
//! `k` below the cell's dimension (see [`incomplete_cells`]).
//!
//! ```
//! use gmap_ops::euler::strata::example_2;
//! let steps = example_2();
//! assert_eq!(steps.len(), 5);
//! assert_eq!(steps.last().unwrap().euler, 1); // a sphere with a loop attached
//! ```

use gmap_core::DenseMap;
use thiserror::Error;

/// A stratum: a connected d-manifold with `holes[k]` k-holes (`k = 1..=d`; entry 0 unused).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Stratum {
    /// dimension d
    pub dim: usize,
    /// `holes[k]`: number of k-holes (Betti number b_k of the stratum), `k >= 1`
    pub holes: Vec<i64>,
    /// whether the stratum's boundary is complete
    pub complete: bool,
    /// whether the stratum is still part of the object (detached strata keep their slot)
    pub alive: bool,
}

/// A connected component of the object with its global holes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Component {
    /// dimension of the component (the highest of its strata)
    pub dim: usize,
    /// `holes[k]`: number of global k-holes (`k >= 1`; entry 0 unused)
    pub holes: Vec<i64>,
    /// whether the component is boundary-complete
    pub complete: bool,
    /// whether the component still exists
    pub alive: bool,
}

/// Why an EO operator cannot be applied.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum StrataError {
    /// No live stratum with this number.
    #[error("no stratum {0}")]
    NoStratum(usize),
    /// No live component with this number.
    #[error("no component {0}")]
    NoComponent(usize),
    /// A hole count would become negative.
    #[error("{what} {id} has no {k}-hole to remove")]
    NoHole {
        /// "stratum" or "component"
        what: &'static str,
        /// its number
        id: usize,
        /// the hole dimension
        k: usize,
    },
    /// A hole dimension out of range for the stratum or component.
    #[error("a {dim}-dimensional {what} cannot have a {k}-hole")]
    BadHole {
        /// "stratum" or "component"
        what: &'static str,
        /// its dimension
        dim: usize,
        /// the hole dimension asked for
        k: usize,
    },
    /// The stratum is already boundary-complete.
    #[error("stratum {0} is already boundary-complete")]
    AlreadyComplete(usize),
}

/// The result of one EO operator: its name and the counts after it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EoStep {
    /// the operator's name in EO's notation (e.g. `meehCCh`)
    pub name: String,
    /// live boundary-complete strata per dimension
    pub complete: Vec<i64>,
    /// live boundary-incomplete strata per dimension
    pub incomplete: Vec<i64>,
    /// sum over live strata of their k-holes, per k
    pub local_holes: Vec<i64>,
    /// live components
    pub components: i64,
    /// sum over live components of their global k-holes, per k
    pub global_holes: Vec<i64>,
    /// the Euler characteristic (EO Theorems 1 and 2 agree)
    pub euler: i64,
}

/// What accompanies a change of local holes in [`StratifiedObject::try_shape_holes`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Filler {
    /// nothing is added or merged (an unfilled hole, EO's `mh^d_∞n H^d_∞n`)
    Nothing,
    /// this stratum merges into the other one and disappears (the vertex that fills a
    /// face's hole in `kvfh`)
    Merge(usize),
    /// a new stratum without holes is put inside (the vertex of `mvfh`)
    Add {
        /// its dimension
        dim: usize,
        /// whether it is boundary-complete
        complete: bool,
    },
}

/// A hole vector change: `(k, delta)` pairs.
pub type HoleDelta<'a> = &'a [(usize, i64)];

/// A stratified object of dimension at most `dim` (EO §3).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct StratifiedObject {
    /// the strata, by number
    pub strata: Vec<Stratum>,
    /// the components, by number
    pub components: Vec<Component>,
}

fn alt(holes: &[i64]) -> i64 {
    // 1 - b_1 + b_2 - … : the Euler characteristic of a connected homotopy type
    1 + holes.iter().enumerate().skip(1).map(|(k, &h)| if k.is_multiple_of(2) { h } else { -h }).sum::<i64>()
}

fn sign(d: usize) -> i64 {
    if d.is_multiple_of(2) {
        1
    } else {
        -1
    }
}

fn apply(holes: &mut Vec<i64>, delta: HoleDelta, what: &'static str, id: usize, dim: usize) -> Result<(), StrataError> {
    let mut h = holes.clone();
    for &(k, dk) in delta {
        if k == 0 || k > dim.max(1) + 1 {
            return Err(StrataError::BadHole { what, dim, k });
        }
        if h.len() <= k {
            h.resize(k + 1, 0);
        }
        h[k] += dk;
        if h[k] < 0 {
            return Err(StrataError::NoHole { what, id, k });
        }
    }
    *holes = h;
    Ok(())
}

impl StratifiedObject {
    /// The empty object.
    pub fn new() -> Self {
        Self::default()
    }

    fn stratum_mut(&mut self, s: usize) -> Result<&mut Stratum, StrataError> {
        match self.strata.get_mut(s) {
            Some(x) if x.alive => Ok(x),
            _ => Err(StrataError::NoStratum(s)),
        }
    }

    fn component_mut(&mut self, c: usize) -> Result<&mut Component, StrataError> {
        match self.components.get_mut(c) {
            Some(x) if x.alive => Ok(x),
            _ => Err(StrataError::NoComponent(c)),
        }
    }

    /// EO Theorem 1: `χ(Σ) = Σ_strata (-1)^d (1 - h_1 + h_2 - …)` over complete and
    /// incomplete strata alike (the incomplete ones make up `χ∞(Σ)`; EO has no incomplete
    /// vertices). O(strata).
    pub fn euler_by_strata(&self) -> i64 {
        self.strata.iter().filter(|s| s.alive).map(|s| sign(s.dim) * alt(&s.holes)).sum()
    }

    /// EO Theorem 2: `χ(X) = Σ_complete components (1 - H_1 + H_2 - …) + χ∞(X)`, where an
    /// incomplete component of dimension d adds `(-1)^d (1 - H_1 + …)`. O(components).
    pub fn euler_by_components(&self) -> i64 {
        self.components
            .iter()
            .filter(|c| c.alive)
            .map(|c| if c.complete { alt(&c.holes) } else { sign(c.dim) * alt(&c.holes) })
            .sum()
    }

    /// Whether both theorems give the same Euler characteristic.
    pub fn check(&self) -> bool {
        self.euler_by_strata() == self.euler_by_components()
    }

    /// The counts after a step named `name`.
    pub fn step(&self, name: &str) -> EoStep {
        let dim = self.strata.iter().map(|s| s.dim).max().unwrap_or(0);
        let mut complete = vec![0; dim + 1];
        let mut incomplete = vec![0; dim + 1];
        let mut local_holes = vec![0; dim + 2];
        for s in self.strata.iter().filter(|s| s.alive) {
            if s.complete {
                complete[s.dim] += 1;
            } else {
                incomplete[s.dim] += 1;
            }
            for (k, &h) in s.holes.iter().enumerate().skip(1) {
                if local_holes.len() <= k {
                    local_holes.resize(k + 1, 0);
                }
                local_holes[k] += h;
            }
        }
        let mut global_holes = vec![0; dim + 2];
        let mut components = 0;
        for c in self.components.iter().filter(|c| c.alive) {
            components += 1;
            for (k, &h) in c.holes.iter().enumerate().skip(1) {
                if global_holes.len() <= k {
                    global_holes.resize(k + 1, 0);
                }
                global_holes[k] += h;
            }
        }
        EoStep {
            name: name.to_string(),
            complete,
            incomplete,
            local_holes,
            components,
            global_holes,
            euler: self.euler_by_strata(),
        }
    }

    /// Attaches a new stratum of dimension `dim` with `holes` (EO's `ms^n…` family:
    /// `msnHn`, `msnhnH0Hn`, `msnkHn-1`, `msn∞Sn∞`). It either starts a new component
    /// (`component = None`, with global holes `new_component_holes`) or joins component `c`,
    /// whose global holes change by `global`. Returns the stratum's number.
    ///
    /// Precondition: `c` is a live component; hole changes keep counts non-negative.
    pub fn try_attach(
        &mut self,
        name: &str,
        dim: usize,
        holes: HoleDelta,
        complete: bool,
        component: Option<usize>,
        global: HoleDelta,
    ) -> Result<(usize, EoStep), StrataError> {
        let mut h = vec![0i64];
        apply(&mut h, holes, "stratum", self.strata.len(), dim)?;
        match component {
            None => {
                let mut ch = vec![0i64];
                apply(&mut ch, global, "component", self.components.len(), dim)?;
                self.components.push(Component { dim, holes: ch, complete, alive: true });
            }
            Some(c) => {
                let comp = self.component_mut(c)?;
                let cdim = comp.dim.max(dim);
                let mut ch = comp.holes.clone();
                apply(&mut ch, global, "component", c, cdim + 1)?;
                comp.holes = ch;
                comp.dim = cdim;
            }
        }
        self.strata.push(Stratum { dim, holes: h, complete, alive: true });
        Ok((self.strata.len() - 1, self.step(name)))
    }

    /// Detaches stratum `s` (EO's `ks^n…` family), changing the global holes of component
    /// `c` by `global`; `remove_component` also drops the component (the stratum was all of
    /// it). Inverse of [`StratifiedObject::try_attach`].
    pub fn try_detach(
        &mut self,
        name: &str,
        s: usize,
        c: usize,
        global: HoleDelta,
        remove_component: bool,
    ) -> Result<EoStep, StrataError> {
        self.stratum_mut(s)?;
        let comp = self.component_mut(c)?;
        let mut ch = comp.holes.clone();
        let d = comp.dim;
        apply(&mut ch, global, "component", c, d + 1)?;
        comp.holes = ch;
        if remove_component {
            comp.alive = false;
        }
        self.strata[s].alive = false;
        Ok(self.step(name))
    }

    /// Changes the local holes of stratum `s` (EO's local hole shapers `ks^d h^{n-1-d}_n`,
    /// `ks^d m h^{n-d}_n`, unfilled hole shapers `mh^d_∞n H^d_∞n`) and the global holes of
    /// component `c`; `filler` says what makes or fills the hole.
    pub fn try_shape_holes(
        &mut self,
        name: &str,
        s: usize,
        local: HoleDelta,
        c: usize,
        global: HoleDelta,
        filler: Filler,
    ) -> Result<EoStep, StrataError> {
        let (sdim, mut sh) = {
            let st = self.stratum_mut(s)?;
            (st.dim, st.holes.clone())
        };
        apply(&mut sh, local, "stratum", s, sdim)?;
        let comp = self.component_mut(c)?;
        let cd = comp.dim;
        let mut ch = comp.holes.clone();
        apply(&mut ch, global, "component", c, cd + 1)?;
        if let Filler::Merge(t) = filler {
            self.stratum_mut(t)?;
            self.strata[t].alive = false;
        }
        self.components[c].holes = ch;
        self.strata[s].holes = sh;
        if let Filler::Add { dim, complete } = filler {
            self.strata.push(Stratum { dim, holes: vec![0], complete, alive: true });
        }
        Ok(self.step(name))
    }

    /// Subdivides stratum `s` by a new stratum of dimension `dim(s) - 1` with `cut_holes`
    /// (EO's `ms^{n-1}s^n` family); the two parts get `holes_a` and `holes_b`. With
    /// `split = false` the stratum is not cut in two (the cut is an edge with a hole on a
    /// sphere-like face: `meehfkfc`). Global shape unchanged.
    pub fn try_subdivide(
        &mut self,
        name: &str,
        s: usize,
        cut_holes: HoleDelta,
        holes_a: HoleDelta,
        holes_b: Option<HoleDelta>,
    ) -> Result<EoStep, StrataError> {
        let st = self.stratum_mut(s)?.clone();
        let d = st.dim;
        let mut cut = vec![0i64];
        apply(&mut cut, cut_holes, "stratum", self.strata.len(), d.saturating_sub(1))?;
        let mut a = vec![0i64];
        apply(&mut a, holes_a, "stratum", s, d)?;
        let b = match holes_b {
            Some(hb) => {
                let mut b = vec![0i64];
                apply(&mut b, hb, "stratum", s, d)?;
                Some(b)
            }
            None => None,
        };
        self.strata[s].holes = a;
        self.strata.push(Stratum { dim: d.saturating_sub(1), holes: cut, complete: st.complete, alive: true });
        if let Some(b) = b {
            self.strata.push(Stratum { dim: d, holes: b, complete: st.complete, alive: true });
        }
        Ok(self.step(name))
    }

    /// Coalesces: strata `cut` and `other` disappear into `s`, which gets `holes`
    /// (inverse of [`StratifiedObject::try_subdivide`]).
    pub fn try_coalesce(
        &mut self,
        name: &str,
        s: usize,
        cut: usize,
        other: Option<usize>,
        holes: HoleDelta,
    ) -> Result<EoStep, StrataError> {
        let d = self.stratum_mut(s)?.dim;
        self.stratum_mut(cut)?;
        if let Some(o) = other {
            self.stratum_mut(o)?;
        }
        let mut h = vec![0i64];
        apply(&mut h, holes, "stratum", s, d)?;
        self.strata[cut].alive = false;
        if let Some(o) = other {
            self.strata[o].alive = false;
        }
        self.strata[s].holes = h;
        Ok(self.step(name))
    }

    /// Compacts stratum `s` (EO's `ks^n_∞ m s^n`): marks it boundary-complete, and its
    /// component too when `component_complete`. The strata that complete its boundary must
    /// have been attached before.
    pub fn try_compact(
        &mut self,
        name: &str,
        s: usize,
        c: usize,
        component_complete: bool,
    ) -> Result<EoStep, StrataError> {
        let st = self.stratum_mut(s)?;
        if st.complete {
            return Err(StrataError::AlreadyComplete(s));
        }
        self.component_mut(c)?;
        self.strata[s].complete = true;
        if component_complete {
            self.components[c].complete = true;
        }
        Ok(self.step(name))
    }
}

/// EO Example 2 (Figure 18), step by step: a circle edge `e1` with its hole (`meehCCh`),
/// a face `f1` filling it (`mfkCh`), a second face `f2` closing a void (`mfCc`), a vertex
/// `v1` put in `f1` (`mvfh`), and a loop edge `e2` at `v1` (`meCh`). The final object is a
/// sphere with a loop attached: one component, one global 1-hole, one 2-hole, χ = 1.
pub fn example_2() -> Vec<EoStep> {
    let mut o = StratifiedObject::new();
    let mut steps = Vec::new();
    let (_e1, s) = o.try_attach("meehCCh", 1, &[(1, 1)], true, None, &[(1, 1)]).expect("new component");
    steps.push(s);
    let (f1, s) = o.try_attach("mfkCh", 2, &[], true, Some(0), &[(1, -1)]).expect("component 0");
    steps.push(s);
    let (_f2, s) = o.try_attach("mfCc", 2, &[], true, Some(0), &[(2, 1)]).expect("component 0");
    steps.push(s);
    let s =
        o.try_shape_holes("mvfh", f1, &[(1, 1)], 0, &[], Filler::Add { dim: 0, complete: true }).expect("f1 exists");
    steps.push(s);
    let (_e2, s) = o.try_attach("meCh", 1, &[], true, Some(0), &[(1, 1)]).expect("component 0");
    steps.push(s);
    debug_assert!(o.check());
    steps
}

/// EO's split of the cells of a G-map into boundary-complete and boundary-incomplete
/// ones: an i-cell is incomplete when one of its darts is free for some `alpha_k`, `k < i`.
/// Returns `(complete, incomplete)` counts per dimension. O(N n).
pub fn incomplete_cells(map: &DenseMap) -> (Vec<usize>, Vec<usize>) {
    let n = map.dim();
    let mut complete = vec![0usize; n + 1];
    let mut incomplete = vec![0usize; n + 1];
    for i in 0..=n {
        let p = map.cells(i);
        let mut bad = vec![false; p.len()];
        for d in map.darts() {
            if (0..i).any(|k| map.is_free(d, k)) {
                bad[p.of[d.index()] as usize] = true;
            }
        }
        for b in bad {
            if b {
                incomplete[i] += 1;
            } else {
                complete[i] += 1;
            }
        }
    }
    (complete, incomplete)
}

#[cfg(test)]
mod tests {
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
        // an open edge (incomplete) as its own component, then compacted
        let (e, s) = o.try_attach("me∞E∞", 1, &[], false, None, &[]).unwrap();
        assert_eq!(s.euler, -1);
        assert!(o.check());
        assert_eq!(o.try_compact("ke∞me", e, 0, false).unwrap().incomplete, vec![0, 0]);
        assert_eq!(o.try_compact("ke∞me", e, 0, false), Err(StrataError::AlreadyComplete(e)));
        assert_eq!(o.try_detach("k", 7, 0, &[], true), Err(StrataError::NoStratum(7)));
        assert!(matches!(
            o.try_shape_holes("x", e, &[(1, -1)], 0, &[], Filler::Nothing),
            Err(StrataError::NoHole { .. })
        ));
    }
}
