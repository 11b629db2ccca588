//! The stratified object of EO: strata with local holes, components with global holes, the
//! two Euler characteristics of EO Theorems 1 and 2, and the invariants every operator
//! keeps.

use thiserror::Error;

/// A stratum: a connected d-manifold, not necessarily a ball, with `holes[k]` k-holes
/// (its k-th Betti number, `1 <= k <= d`; entry 0 is unused and stays 0).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Stratum {
    /// dimension d
    pub dim: usize,
    /// `holes[k]`: number of k-holes, `k = 1..=dim` (length `dim + 1`)
    pub holes: Vec<i64>,
    /// `open_holes[k]`: how many of the k-holes are boundary-incomplete (EO's `f∞h`,
    /// `s∞h`, `s∞c`); never more than `holes[k]`, always 0 on a boundary-complete stratum
    pub open_holes: Vec<i64>,
    /// whether the stratum's boundary is complete (its frontier lies in the object)
    pub complete: bool,
    /// whether the stratum is still part of the object (a detached stratum keeps its number)
    pub alive: bool,
    /// the component it belongs to (EO Theorem 2)
    pub component: usize,
    /// the strata of lower dimension in its frontier that are in the object
    pub frontier: Vec<usize>,
}

impl Stratum {
    /// Whether the stratum is closed: it has a `dim`-hole (a circle edge, a sphere face), so
    /// its frontier is empty and it is boundary-complete on its own.
    pub fn is_closed(&self) -> bool {
        self.dim >= 1 && self.holes[self.dim] > 0
    }

    /// Whether it has no hole at all (homotopic to a point, as a ball is).
    pub fn is_ball(&self) -> bool {
        self.holes.iter().all(|&h| h == 0)
    }
}

/// A connected component of EO Theorem 2: either a component of the boundary-complete
/// part of the object (`C`, with global holes `Ch`, `Cc`, …) or a boundary-incomplete
/// stratum component (`E∞`, `F∞`, `S∞`, with global holes `F∞h`, `S∞h`, `S∞c`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Component {
    /// `holes[k]`: number of global k-holes, `k >= 1` (entry 0 unused)
    pub holes: Vec<i64>,
    /// whether the component is boundary-complete
    pub complete: bool,
    /// whether the component still exists
    pub alive: bool,
}

/// Why an EO operator is refused. On a refusal the object is unchanged.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum StrataError {
    /// No live stratum with this number.
    #[error("no stratum {0}")]
    NoStratum(usize),
    /// No live component with this number.
    #[error("no component {0}")]
    NoComponent(usize),
    /// An argument the operator needs was not given.
    #[error("{op} needs {what}")]
    Missing {
        /// the operator
        op: &'static str,
        /// the argument
        what: &'static str,
    },
    /// The operator's precondition fails, for the reason given.
    #[error("{op}: {why}")]
    Precondition {
        /// the operator
        op: &'static str,
        /// why
        why: String,
    },
    /// EO Theorems 1 and 2 would give different Euler characteristics.
    #[error("EO Theorems 1 and 2 would disagree: {by_strata} by strata, {by_components} by components")]
    TheoremsDisagree {
        /// Theorem 1
        by_strata: i64,
        /// Theorem 2
        by_components: i64,
    },
    /// A vertex would get a hole.
    #[error("vertex {0} would get a hole (a vertex has none)")]
    VertexHole(usize),
    /// A hole dimension out of range for a stratum.
    #[error("stratum {stratum} ({dim}-dimensional, {state}) cannot have a {k}-hole")]
    HoleOutOfRange {
        /// the stratum
        stratum: usize,
        /// its dimension
        dim: usize,
        /// "boundary-complete" or "boundary-incomplete"
        state: &'static str,
        /// the hole dimension
        k: usize,
    },
    /// A hole count would become negative, or a stratum would have two top holes.
    #[error("stratum {stratum} would have {count} {k}-holes")]
    HoleCount {
        /// the stratum
        stratum: usize,
        /// the hole dimension
        k: usize,
        /// the count it would have
        count: i64,
    },
    /// A hole dimension out of range, or a negative count, for a component.
    #[error("component {component} ({dim}-dimensional, {state}) cannot have {count} global {k}-holes")]
    ComponentHoles {
        /// the component
        component: usize,
        /// its dimension
        dim: usize,
        /// "boundary-complete" or "boundary-incomplete"
        state: &'static str,
        /// the hole dimension
        k: usize,
        /// the count it would have
        count: i64,
    },
    /// A boundary-complete stratum would have a boundary-incomplete hole.
    #[error("stratum {0} is boundary-complete but would have a boundary-incomplete hole")]
    OpenHoleOnComplete(usize),
    /// A stratum that is not closed would be marked boundary-complete with nothing in its
    /// frontier (a lone open edge, a lone open face, …).
    #[error("stratum {0} is not closed and nothing of its frontier is in the object: it cannot be boundary-complete")]
    LoneOpenStratum(usize),
    /// A closed stratum (one with a top hole: a circle edge, a sphere face) would have
    /// something in its frontier.
    #[error("stratum {0} is closed and cannot have a frontier")]
    ClosedWithFrontier(usize),
    /// A boundary-incomplete stratum would lie in a boundary-complete component.
    #[error("stratum {stratum} is boundary-incomplete and cannot lie in the boundary-complete component {component}")]
    IncompleteInComplete {
        /// the stratum
        stratum: usize,
        /// the component
        component: usize,
    },
    /// A component would have no stratum.
    #[error("component {0} would have no stratum")]
    EmptyComponent(usize),
    /// A stratum would be bounded by a stratum that is gone or not of lower dimension.
    #[error("stratum {stratum} would be bounded by stratum {by}, which is gone or not of lower dimension")]
    BadFrontier {
        /// the stratum
        stratum: usize,
        /// the stratum in its frontier
        by: usize,
    },
}

/// The counts of EO Theorems 1 and 2, by the paper's own names (objects of dimension at
/// most 3; higher strata are counted in [`EoStep`]'s vectors only).
///
/// Theorem 1 reads `χ = v − (e − eh) + (f − fh + fc) − (s − sh + sc) + χ∞(Σ)` with
/// `χ∞(Σ) = −e∞ + (f∞ − f∞h) − (s∞ − s∞h + s∞c)`; Theorem 2 reads
/// `χ = (C − Ch + Cc) + χ∞(X)` with `χ∞(X) = −E∞ + (F∞ − F∞h) − (S∞ − S∞h + S∞c)`.
/// A hole counts as boundary-complete (`fh`) or not (`f∞h`) by its own state.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EoCounts {
    /// boundary-complete vertices, edges, faces, solids
    pub v: i64,
    /// boundary-complete edges
    pub e: i64,
    /// boundary-complete faces
    pub f: i64,
    /// boundary-complete solids
    pub s: i64,
    /// boundary-complete 1-holes through edges
    pub eh: i64,
    /// boundary-complete 1-holes through faces
    pub fh: i64,
    /// boundary-complete 2-holes of faces
    pub fc: i64,
    /// boundary-complete 1-holes through solids
    pub sh: i64,
    /// boundary-complete 2-holes of solids
    pub sc: i64,
    /// boundary-incomplete edges `e∞`
    pub e_inf: i64,
    /// boundary-incomplete faces `f∞`
    pub f_inf: i64,
    /// boundary-incomplete solids `s∞`
    pub s_inf: i64,
    /// boundary-incomplete 1-holes through faces `f∞h`
    pub f_inf_h: i64,
    /// boundary-incomplete 1-holes through solids `s∞h`
    pub s_inf_h: i64,
    /// boundary-incomplete 2-holes of solids `s∞c`
    pub s_inf_c: i64,
    /// boundary-complete components `C`
    pub big_c: i64,
    /// their global 1-holes `Ch`
    pub big_ch: i64,
    /// their global 2-holes `Cc`
    pub big_cc: i64,
    /// boundary-incomplete edge components `E∞`
    pub big_e_inf: i64,
    /// boundary-incomplete face components `F∞`
    pub big_f_inf: i64,
    /// boundary-incomplete solid components `S∞`
    pub big_s_inf: i64,
    /// global 1-holes of face components `F∞h`
    pub big_f_inf_h: i64,
    /// global 1-holes of solid components `S∞h`
    pub big_s_inf_h: i64,
    /// global 2-holes of solid components `S∞c`
    pub big_s_inf_c: i64,
}

impl EoCounts {
    /// Every count with the paper's name: `v`, `e`, `f`, `s`, `eh`, `fh`, `fc`, `sh`, `sc`,
    /// `e∞`, `f∞`, `s∞`, `f∞h`, `s∞h`, `s∞c`, `C`, `Ch`, `Cc`, `E∞`, `F∞`, `S∞`, `F∞h`,
    /// `S∞h`, `S∞c`.
    pub fn named(&self) -> [(&'static str, i64); 24] {
        [
            ("v", self.v),
            ("e", self.e),
            ("f", self.f),
            ("s", self.s),
            ("eh", self.eh),
            ("fh", self.fh),
            ("fc", self.fc),
            ("sh", self.sh),
            ("sc", self.sc),
            ("e∞", self.e_inf),
            ("f∞", self.f_inf),
            ("s∞", self.s_inf),
            ("f∞h", self.f_inf_h),
            ("s∞h", self.s_inf_h),
            ("s∞c", self.s_inf_c),
            ("C", self.big_c),
            ("Ch", self.big_ch),
            ("Cc", self.big_cc),
            ("E∞", self.big_e_inf),
            ("F∞", self.big_f_inf),
            ("S∞", self.big_s_inf),
            ("F∞h", self.big_f_inf_h),
            ("S∞h", self.big_s_inf_h),
            ("S∞c", self.big_s_inf_c),
        ]
    }

    /// The counts that are not zero, by name (see [`EoCounts::named`]).
    pub fn nonzero(&self) -> Vec<(&'static str, i64)> {
        self.named().into_iter().filter(|&(_, x)| x != 0).collect()
    }

    /// The counts that changed from `before` to `self`, by name, with the change.
    pub fn delta(&self, before: &EoCounts) -> Vec<(&'static str, i64)> {
        self.named()
            .into_iter()
            .zip(before.named())
            .filter(|(a, b)| a.1 != b.1)
            .map(|(a, b)| (a.0, a.1 - b.1))
            .collect()
    }

    /// EO Theorem 1, formula (1), term by term.
    pub fn theorem_1(&self) -> i64 {
        let chi_inf = -self.e_inf + (self.f_inf - self.f_inf_h) - (self.s_inf - self.s_inf_h + self.s_inf_c);
        self.v - (self.e - self.eh) + (self.f - self.fh + self.fc) - (self.s - self.sh + self.sc) + chi_inf
    }

    /// EO Theorem 2, formula (2), term by term.
    pub fn theorem_2(&self) -> i64 {
        let chi_inf = -self.big_e_inf + (self.big_f_inf - self.big_f_inf_h)
            - (self.big_s_inf - self.big_s_inf_h + self.big_s_inf_c);
        (self.big_c - self.big_ch + self.big_cc) + chi_inf
    }
}

/// The result of one EO operator: its name, the strata it made, and the counts after it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EoStep {
    /// the operator's name in EO's notation (e.g. `meehCCh`)
    pub name: String,
    /// the strata the operator made, in the order of its description
    pub new: Vec<usize>,
    /// the components the operator made
    pub new_components: Vec<usize>,
    /// live boundary-complete strata per dimension (`0..=` the highest live dimension)
    pub complete: Vec<i64>,
    /// live boundary-incomplete strata per dimension
    pub incomplete: Vec<i64>,
    /// sum over live strata of their k-holes, per k
    pub local_holes: Vec<i64>,
    /// live components, complete or not
    pub components: i64,
    /// sum over live components of their global k-holes, per k
    pub global_holes: Vec<i64>,
    /// the counts of EO Theorems 1 and 2 by the paper's names
    pub counts: EoCounts,
    /// the Euler characteristic (EO Theorems 1 and 2 agree)
    pub euler: i64,
}

/// A stratified object with incomplete boundaries (EO §3).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct StratifiedObject {
    /// the strata, by number
    pub strata: Vec<Stratum>,
    /// the components, by number
    pub components: Vec<Component>,
}

/// `1 - h_1 + h_2 - …`: the Euler characteristic of a connected homotopy type.
pub(crate) fn alt(holes: &[i64]) -> i64 {
    1 + holes.iter().enumerate().skip(1).map(|(k, &h)| sign(k) * h).sum::<i64>()
}

/// `(-1)^d`
pub(crate) fn sign(d: usize) -> i64 {
    if d.is_multiple_of(2) {
        1
    } else {
        -1
    }
}

fn state(complete: bool) -> &'static str {
    if complete {
        "boundary-complete"
    } else {
        "boundary-incomplete"
    }
}

impl StratifiedObject {
    /// The empty object.
    pub fn new() -> Self {
        Self::default()
    }

    /// The live stratum `s`.
    pub fn stratum(&self, s: usize) -> Result<&Stratum, StrataError> {
        match self.strata.get(s) {
            Some(x) if x.alive => Ok(x),
            _ => Err(StrataError::NoStratum(s)),
        }
    }

    /// The live component `c`.
    pub fn component(&self, c: usize) -> Result<&Component, StrataError> {
        match self.components.get(c) {
            Some(x) if x.alive => Ok(x),
            _ => Err(StrataError::NoComponent(c)),
        }
    }

    /// The live strata, by number.
    pub fn live_strata(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.strata.len()).filter(|&s| self.strata[s].alive)
    }

    /// The live components, by number.
    pub fn live_components(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.components.len()).filter(|&c| self.components[c].alive)
    }

    /// The live strata of component `c`.
    pub fn strata_of(&self, c: usize) -> Vec<usize> {
        self.live_strata().filter(|&s| self.strata[s].component == c).collect()
    }

    /// The dimension of component `c`: the highest of its live strata (0 when empty).
    pub fn component_dim(&self, c: usize) -> usize {
        self.live_strata().filter(|&s| self.strata[s].component == c).map(|s| self.strata[s].dim).max().unwrap_or(0)
    }

    /// The live strata whose frontier holds `s`.
    pub fn bounded_by(&self, s: usize) -> Vec<usize> {
        self.live_strata().filter(|&r| self.strata[r].frontier.contains(&s)).collect()
    }

    /// EO Theorem 1: `χ(Σ) = Σ_strata (-1)^d (1 - h_1 + h_2 - …)` over complete and
    /// incomplete strata alike (the incomplete ones make up `χ∞(Σ)`; EO has no incomplete
    /// vertices). O(strata).
    pub fn euler_by_strata(&self) -> i64 {
        self.strata.iter().filter(|s| s.alive).map(|s| sign(s.dim) * alt(&s.holes)).sum()
    }

    /// EO Theorem 2: `χ(X) = Σ_complete components (1 - H_1 + H_2 - …) + χ∞(X)`, where an
    /// incomplete component of dimension d adds `(-1)^d (1 - H_1 + …)`. O(strata +
    /// components).
    pub fn euler_by_components(&self) -> i64 {
        self.live_components()
            .map(|c| {
                let comp = &self.components[c];
                if comp.complete {
                    alt(&comp.holes)
                } else {
                    sign(self.component_dim(c)) * alt(&comp.holes)
                }
            })
            .sum()
    }

    /// Whether both theorems give the same Euler characteristic.
    pub fn check(&self) -> bool {
        self.euler_by_strata() == self.euler_by_components()
    }

    /// The invariants every operator keeps; an operator whose result breaks one is refused.
    ///
    /// * EO Theorem 1 = EO Theorem 2;
    /// * hole ranges: a vertex has no hole; a boundary-complete n-stratum has k-holes only
    ///   for `1 <= k <= n`, at most one n-hole (it is then closed); a boundary-incomplete
    ///   one only for `k <= n - 1` (a stratum with an n-hole is a closed manifold, hence
    ///   compact); boundary-incomplete holes only on boundary-incomplete strata; a
    ///   component has global k-holes only for `1 <= k <= dim` (`dim - 1` when
    ///   boundary-incomplete); no count is negative;
    /// * a stratum that is not closed is boundary-complete only if some stratum of its
    ///   frontier is in the object: a lone open edge is never complete; a closed stratum
    ///   has an empty frontier;
    /// * a boundary-incomplete stratum never lies in a boundary-complete component, and
    ///   every component has a stratum;
    /// * frontiers hold live strata of lower dimension.
    ///
    /// O(strata · frontier + components · strata).
    pub fn validate(&self) -> Result<(), StrataError> {
        for s in self.live_strata() {
            let st = &self.strata[s];
            let comp = self.component(st.component)?;
            for &b in &st.frontier {
                if !self.strata.get(b).is_some_and(|x| x.alive && x.dim < st.dim) {
                    return Err(StrataError::BadFrontier { stratum: s, by: b });
                }
            }
            let extra = |v: &[i64]| v.iter().enumerate().skip(st.dim + 1).find(|&(_, &h)| h != 0).map(|(k, _)| k);
            if let Some(k) = extra(&st.holes).or(extra(&st.open_holes)).or((st.holes.len() <= st.dim).then_some(st.dim))
            {
                if st.dim == 0 {
                    return Err(StrataError::VertexHole(s));
                }
                return Err(StrataError::HoleOutOfRange { stratum: s, dim: st.dim, state: state(st.complete), k });
            }
            if st.open_holes.len() <= st.dim {
                return Err(StrataError::HoleOutOfRange {
                    stratum: s,
                    dim: st.dim,
                    state: state(st.complete),
                    k: st.dim,
                });
            }
            for k in 1..=st.dim {
                let (h, o) = (st.holes[k], st.open_holes[k]);
                if h < 0 || o < 0 || o > h || (k == st.dim && h > 1) {
                    return Err(StrataError::HoleCount {
                        stratum: s,
                        k,
                        count: if h < 0 || k == st.dim { h } else { o },
                    });
                }
                if h > 0 && k == st.dim && !st.complete {
                    return Err(StrataError::HoleOutOfRange { stratum: s, dim: st.dim, state: state(false), k });
                }
                if o > 0 && st.complete {
                    return Err(StrataError::OpenHoleOnComplete(s));
                }
            }
            if st.is_closed() && !st.frontier.is_empty() {
                return Err(StrataError::ClosedWithFrontier(s));
            }
            if st.complete && st.dim >= 1 && !st.is_closed() && st.frontier.is_empty() {
                return Err(StrataError::LoneOpenStratum(s));
            }
            if !st.complete && comp.complete {
                return Err(StrataError::IncompleteInComplete { stratum: s, component: st.component });
            }
        }
        for c in self.live_components() {
            let comp = &self.components[c];
            if self.strata_of(c).is_empty() {
                return Err(StrataError::EmptyComponent(c));
            }
            let dim = self.component_dim(c);
            let top = if comp.complete { dim } else { dim.saturating_sub(1) };
            for (k, &h) in comp.holes.iter().enumerate().skip(1) {
                if h < 0 || (h > 0 && k > top) {
                    return Err(StrataError::ComponentHoles {
                        component: c,
                        dim,
                        state: state(comp.complete),
                        k,
                        count: h,
                    });
                }
            }
        }
        let (a, b) = (self.euler_by_strata(), self.euler_by_components());
        if a != b {
            return Err(StrataError::TheoremsDisagree { by_strata: a, by_components: b });
        }
        Ok(())
    }

    /// The counts of EO Theorems 1 and 2 by the paper's names.
    pub fn counts(&self) -> EoCounts {
        let mut n = EoCounts::default();
        for s in self.live_strata() {
            let st = &self.strata[s];
            let h = |k: usize| st.holes.get(k).copied().unwrap_or(0) - st.open_holes.get(k).copied().unwrap_or(0);
            let o = |k: usize| st.open_holes.get(k).copied().unwrap_or(0);
            match (st.dim, st.complete) {
                (0, _) => n.v += 1,
                (1, true) => n.e += 1,
                (1, false) => n.e_inf += 1,
                (2, true) => n.f += 1,
                (2, false) => n.f_inf += 1,
                (3, true) => n.s += 1,
                (3, false) => n.s_inf += 1,
                _ => {}
            }
            match st.dim {
                1 => n.eh += h(1),
                2 => {
                    n.fh += h(1);
                    n.fc += h(2);
                    n.f_inf_h += o(1);
                }
                3 => {
                    n.sh += h(1);
                    n.sc += h(2);
                    n.s_inf_h += o(1);
                    n.s_inf_c += o(2);
                }
                _ => {}
            }
        }
        for c in self.live_components() {
            let comp = &self.components[c];
            let h = |k: usize| comp.holes.get(k).copied().unwrap_or(0);
            if comp.complete {
                n.big_c += 1;
                n.big_ch += h(1);
                n.big_cc += h(2);
            } else {
                match self.component_dim(c) {
                    1 => n.big_e_inf += 1,
                    2 => {
                        n.big_f_inf += 1;
                        n.big_f_inf_h += h(1);
                    }
                    3 => {
                        n.big_s_inf += 1;
                        n.big_s_inf_h += h(1);
                        n.big_s_inf_c += h(2);
                    }
                    _ => {}
                }
            }
        }
        n
    }

    /// The counts after a step named `name` that made the strata `new`.
    pub fn step(&self, name: &str) -> EoStep {
        self.step_with(name, Vec::new(), Vec::new())
    }

    pub(crate) fn step_with(&self, name: &str, new: Vec<usize>, new_components: Vec<usize>) -> EoStep {
        let dim = self.live_strata().map(|s| self.strata[s].dim).max().unwrap_or(0);
        let mut complete = vec![0; dim + 1];
        let mut incomplete = vec![0; dim + 1];
        let mut local_holes = vec![0; dim + 2];
        for s in self.live_strata() {
            let st = &self.strata[s];
            if st.complete {
                complete[st.dim] += 1;
            } else {
                incomplete[st.dim] += 1;
            }
            for (k, &h) in st.holes.iter().enumerate().skip(1) {
                local_holes[k] += h;
            }
        }
        let mut global_holes = vec![0; dim + 2];
        let mut components = 0;
        for c in self.live_components() {
            components += 1;
            for (k, &h) in self.components[c].holes.iter().enumerate().skip(1) {
                if global_holes.len() <= k {
                    global_holes.resize(k + 1, 0);
                }
                global_holes[k] += h;
            }
        }
        EoStep {
            name: name.to_string(),
            new,
            new_components,
            complete,
            incomplete,
            local_holes,
            components,
            global_holes,
            counts: self.counts(),
            euler: self.euler_by_strata(),
        }
    }

    // ---------- primitives, used inside a transaction (see `catalogue`) ----------

    pub(crate) fn new_component(&mut self, complete: bool) -> usize {
        self.components.push(Component { holes: vec![0], complete, alive: true });
        self.components.len() - 1
    }

    pub(crate) fn new_stratum(&mut self, dim: usize, complete: bool, component: usize, frontier: &[usize]) -> usize {
        let mut f: Vec<usize> = Vec::new();
        for &b in frontier {
            if !f.contains(&b) {
                f.push(b);
            }
        }
        self.strata.push(Stratum {
            dim,
            holes: vec![0; dim + 1],
            open_holes: vec![0; dim + 1],
            complete,
            alive: true,
            component,
            frontier: f,
        });
        self.strata.len() - 1
    }

    /// Changes the k-holes of stratum `s` by `delta`, boundary-incomplete ones when `open`.
    pub(crate) fn add_hole(&mut self, s: usize, k: usize, delta: i64, open: bool) -> Result<(), StrataError> {
        let st = &mut self.strata[s];
        if st.dim == 0 {
            return Err(StrataError::VertexHole(s));
        }
        if k == 0 || k > st.dim {
            return Err(StrataError::HoleOutOfRange { stratum: s, dim: st.dim, state: state(st.complete), k });
        }
        st.holes[k] += delta;
        if open {
            st.open_holes[k] += delta;
        }
        if st.holes[k] < 0 || st.open_holes[k] < 0 || st.open_holes[k] > st.holes[k] {
            let count = if open { st.open_holes[k] } else { st.holes[k] - st.open_holes[k] };
            return Err(StrataError::HoleCount { stratum: s, k, count });
        }
        Ok(())
    }

    /// Changes the global k-holes of component `c` by `delta`.
    pub(crate) fn add_global_hole(&mut self, c: usize, k: usize, delta: i64) -> Result<(), StrataError> {
        let dim = self.component_dim(c);
        let comp = &mut self.components[c];
        if comp.holes.len() <= k {
            comp.holes.resize(k + 1, 0);
        }
        comp.holes[k] += delta;
        if comp.holes[k] < 0 || k == 0 {
            return Err(StrataError::ComponentHoles {
                component: c,
                dim,
                state: state(comp.complete),
                k,
                count: comp.holes[k],
            });
        }
        Ok(())
    }

    /// Kills stratum `s`, which must bound no live stratum.
    pub(crate) fn kill_stratum(&mut self, op: &'static str, s: usize) -> Result<(), StrataError> {
        if let Some(&r) = self.bounded_by(s).first() {
            return Err(StrataError::Precondition {
                op,
                why: format!("stratum {s} bounds stratum {r}; make {r} boundary-incomplete first"),
            });
        }
        self.strata[s].alive = false;
        Ok(())
    }

    /// Moves every stratum of component `from` into `into` and adds the global holes of
    /// `from` to those of `into`; `from` disappears.
    pub(crate) fn absorb(&mut self, into: usize, from: usize) {
        for s in self.strata_of(from) {
            self.strata[s].component = into;
        }
        let h = std::mem::take(&mut self.components[from].holes);
        let dst = &mut self.components[into].holes;
        if dst.len() < h.len() {
            dst.resize(h.len(), 0);
        }
        for (k, x) in h.into_iter().enumerate() {
            dst[k] += x;
        }
        self.components[from].alive = false;
    }

    /// Replaces `old` by `new` in every frontier (dropping `old` where `new` is already).
    pub(crate) fn replace_in_frontiers(&mut self, old: usize, new: Option<usize>) {
        for st in self.strata.iter_mut().filter(|s| s.alive) {
            if let Some(p) = st.frontier.iter().position(|&b| b == old) {
                st.frontier.remove(p);
                if let Some(n) = new {
                    if !st.frontier.contains(&n) && st.dim > 0 {
                        st.frontier.push(n);
                    }
                }
            }
        }
    }

    /// Adds `new` to the frontier of every live stratum that has `s` in its frontier, and
    /// of those above them.
    pub(crate) fn add_where_bounded(&mut self, s: usize, new: &[usize]) {
        for r in self.bounded_by(s) {
            for &x in new {
                if !self.strata[r].frontier.contains(&x) {
                    self.strata[r].frontier.push(x);
                }
            }
        }
    }
}
