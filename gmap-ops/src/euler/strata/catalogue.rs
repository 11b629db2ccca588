//! The catalogue of EO's Euler operators: every family of EO §3.2 with the instances the
//! paper names in its figures (dimensions 0 to 3), each with its precondition and its
//! effect on the Euler characteristic, applied by name to a [`StratifiedObject`].

use super::object::{sign, EoStep, StrataError, StratifiedObject};

/// The families of EO §3.2, by the paper's headings.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Family {
    /// global hole shapers (EO Fig. 1–4): attach or detach a boundary-complete stratum and
    /// change the global holes or the number of components
    GlobalHoleShaper,
    /// stratum subdividers and coalescers (EO Fig. 5–7)
    StratumSubdivider,
    /// local hole shapers, filled (EO Fig. 8–9): merge a stratum into a higher one, which
    /// loses or gains a hole
    LocalHoleShaper,
    /// stratum attachers (EO Fig. 10): attach or detach a boundary-incomplete stratum with
    /// its own component
    StratumAttacher,
    /// unfilled hole shapers (EO Fig. 11): a boundary-incomplete hole in a
    /// boundary-incomplete stratum and its component
    UnfilledHoleShaper,
    /// local stratum compacters (EO Fig. 12)
    StratumCompacter,
    /// local hole compacters (EO Fig. 13)
    LocalHoleCompacter,
    /// global stratum compacters (EO Fig. 14–16)
    GlobalCompacter,
}

impl Family {
    /// The eight families, in the paper's order.
    pub const ALL: [Family; 8] = [
        Family::GlobalHoleShaper,
        Family::StratumSubdivider,
        Family::LocalHoleShaper,
        Family::StratumAttacher,
        Family::UnfilledHoleShaper,
        Family::StratumCompacter,
        Family::LocalHoleCompacter,
        Family::GlobalCompacter,
    ];
}

/// The dimension-independent operators of EO §3.2, in the paper's notation (`s^n` an
/// n-stratum, `h^k_n` a k-hole of an n-stratum, `H^k` a global k-hole, `∞` boundary-
/// incomplete). [`EoOperator::inverse`] selects the inverse of the form written here.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Scheme {
    /// `ms^n H^n`: attach a boundary-complete n-ball, making a global n-hole (n = 0: a
    /// vertex that is a new component, `mvC`)
    AttachHole,
    /// `ms^n h^n_n H^0 H^n`: attach a closed n-stratum (with its n-hole) as a new component
    /// with a global n-hole
    AttachClosed,
    /// `ks^n m H^{n-1}`: detach a boundary-complete n-ball, making a global (n-1)-hole
    /// (n = 1: a new component, `kemC`)
    DetachHole,
    /// `ks^n h^{n-1}_n m H^0 H^{n-1}`: detach an n-stratum with an (n-1)-hole, making a new
    /// component and a global (n-1)-hole
    DetachHoled,
    /// `ms^{n-1} s^n`: subdivide an n-stratum in two by a new (n-1)-ball (`open`: the
    /// stratum is boundary-incomplete)
    Subdivide,
    /// `ms^{n-1} h^{n-1}_{n-1} s^n h^{n-1}_n`: subdivide by a closed (n-1)-stratum; the
    /// stratum gets an (n-1)-hole and a new n-ball lies inside
    SubdivideByClosed,
    /// `ms^{n-1} h^{n-1}_{n-1} s^n k h^n_n`: subdivide a closed n-stratum by a closed
    /// (n-1)-stratum; it loses its n-hole
    SubdivideClosedByClosed,
    /// `ks^d h^{n-1-d}_n`: merge a d-ball into an n-stratum, which loses an (n-1-d)-hole
    MergeFill,
    /// `ks^d m h^{n-d}_n`: merge a d-ball into an n-stratum, which gains an (n-d)-hole
    MergeClose,
    /// `ms^n_∞ S^n_∞`: attach a boundary-incomplete n-ball with its own component
    AttachOpen,
    /// `mh^d_∞n H^d_∞n`: a boundary-incomplete d-hole in a boundary-incomplete n-stratum
    /// and its component
    OpenHole,
    /// `ks^n_∞ m s^n`: mark a boundary-incomplete stratum boundary-complete
    CompactStratum,
    /// `kh^d_∞n m h^d_n`: mark a boundary-incomplete d-hole boundary-complete
    CompactHole,
    /// `kC^n_∞ H^{n-1}`: a boundary-incomplete component joins the complete part, deleting
    /// a global (n-1)-hole (n = 1: a component)
    CompactComponent,
    /// `kC^n_∞ m H^n`: a boundary-incomplete component joins the complete part, making a
    /// global n-hole
    CompactComponentHole,
    /// `kH^{n-1}_∞n C`: a global boundary-incomplete (n-1)-hole of an n-component is filled
    /// by the stratum of a component, which merges with it
    FillComponentHole,
}

impl Scheme {
    /// The family of EO §3.2.
    pub fn family(self) -> Family {
        use Scheme::*;
        match self {
            AttachHole | AttachClosed | DetachHole | DetachHoled => Family::GlobalHoleShaper,
            Subdivide | SubdivideByClosed | SubdivideClosedByClosed => Family::StratumSubdivider,
            MergeFill | MergeClose => Family::LocalHoleShaper,
            AttachOpen => Family::StratumAttacher,
            OpenHole => Family::UnfilledHoleShaper,
            CompactStratum => Family::StratumCompacter,
            CompactHole => Family::LocalHoleCompacter,
            CompactComponent | CompactComponentHole | FillComponentHole => Family::GlobalCompacter,
        }
    }

    /// The scheme in EO's generic notation (the paper's form; its inverse swaps `m` and `k`).
    pub fn notation(self) -> &'static str {
        use Scheme::*;
        match self {
            AttachHole => "ms^n H^n",
            AttachClosed => "ms^n h^n_n H^0 H^n",
            DetachHole => "ks^n m H^{n-1}",
            DetachHoled => "ks^n h^{n-1}_n m H^0 H^{n-1}",
            Subdivide => "ms^{n-1} s^n",
            SubdivideByClosed => "ms^{n-1} h^{n-1}_{n-1} s^n h^{n-1}_n",
            SubdivideClosedByClosed => "ms^{n-1} h^{n-1}_{n-1} s^n k h^n_n",
            MergeFill => "ks^d h^{n-1-d}_n",
            MergeClose => "ks^d m h^{n-d}_n",
            AttachOpen => "ms^n_∞ S^n_∞",
            OpenHole => "mh^d_∞n H^d_∞n",
            CompactStratum => "ks^n_∞ m s^n",
            CompactHole => "kh^d_∞n m h^d_n",
            CompactComponent => "kC^n_∞ H^{n-1}",
            CompactComponentHole => "kC^n_∞ m H^n",
            FillComponentHole => "kH^{n-1}_∞n C",
        }
    }
}

/// One Euler operator of EO: a [`Scheme`], its direction, the dimensions `n` (and `d`)
/// and whether it is the paper's boundary-incomplete (`∞`) variant.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct EoOperator {
    /// the dimension-independent form
    pub scheme: Scheme,
    /// the inverse of the form written in [`Scheme::notation`]
    pub inverse: bool,
    /// the dimension n of the main stratum or component
    pub n: usize,
    /// the second dimension d of local hole shapers (merged stratum) and of hole makers and
    /// hole compacters (the hole); 0 elsewhere
    pub d: usize,
    /// the `∞` variant: the strata acted on are boundary-incomplete
    pub open: bool,
}

macro_rules! catalogue {
    ($( $name:literal => $scheme:ident, $inv:literal, $n:literal, $d:literal, $open:literal; )*) => {
        impl EoOperator {
            /// Every operator the paper names (EO Fig. 1–16, dimensions up to 3), each
            /// followed by its inverse.
            pub const ALL: &'static [EoOperator] = &[
                $( EoOperator { scheme: Scheme::$scheme, inverse: $inv, n: $n, d: $d, open: $open } ),*
            ];
            const NAMES: &'static [&'static str] = &[ $( $name ),* ];
        }
    };
}

catalogue! {
    // global hole shapers (Fig. 1–4)
    "mvC" => AttachHole, false, 0, 0, false;
    "kvC" => AttachHole, true, 0, 0, false;
    "meCh" => AttachHole, false, 1, 0, false;
    "keCh" => AttachHole, true, 1, 0, false;
    "mfCc" => AttachHole, false, 2, 0, false;
    "kfCc" => AttachHole, true, 2, 0, false;
    "meehCCh" => AttachClosed, false, 1, 0, false;
    "keehCCh" => AttachClosed, true, 1, 0, false;
    "mffcCCc" => AttachClosed, false, 2, 0, false;
    "kffcCCc" => AttachClosed, true, 2, 0, false;
    "kemC" => DetachHole, false, 1, 0, false;
    "mekC" => DetachHole, true, 1, 0, false;
    "kfmCh" => DetachHole, false, 2, 0, false;
    "mfkCh" => DetachHole, true, 2, 0, false;
    "ksmCc" => DetachHole, false, 3, 0, false;
    "mskCc" => DetachHole, true, 3, 0, false;
    "kffhmCCh" => DetachHoled, false, 2, 0, false;
    "mffhkCCh" => DetachHoled, true, 2, 0, false;
    "ksscmCCc" => DetachHoled, false, 3, 0, false;
    "mssckCCc" => DetachHoled, true, 3, 0, false;
    // stratum subdividers (Fig. 5–7)
    "mve" => Subdivide, false, 1, 0, false;
    "kve" => Subdivide, true, 1, 0, false;
    "mve∞" => Subdivide, false, 1, 0, true;
    "kve∞" => Subdivide, true, 1, 0, true;
    "mef" => Subdivide, false, 2, 0, false;
    "kef" => Subdivide, true, 2, 0, false;
    "mef∞" => Subdivide, false, 2, 0, true;
    "kef∞" => Subdivide, true, 2, 0, true;
    "mfs" => Subdivide, false, 3, 0, false;
    "kfs" => Subdivide, true, 3, 0, false;
    "mfs∞" => Subdivide, false, 3, 0, true;
    "kfs∞" => Subdivide, true, 3, 0, true;
    "meehffh" => SubdivideByClosed, false, 2, 0, false;
    "keehffh" => SubdivideByClosed, true, 2, 0, false;
    "mffcssc" => SubdivideByClosed, false, 3, 0, false;
    "kffcssc" => SubdivideByClosed, true, 3, 0, false;
    "meehfkfc" => SubdivideClosedByClosed, false, 2, 0, false;
    "keehfkfc" => SubdivideClosedByClosed, true, 2, 0, false;
    // local hole shapers (Fig. 8–9)
    "kvfh" => MergeFill, false, 2, 0, false;
    "mvfh" => MergeFill, true, 2, 0, false;
    "kvsc" => MergeFill, false, 3, 0, false;
    "mvsc" => MergeFill, true, 3, 0, false;
    "kesh" => MergeFill, false, 3, 1, false;
    "mesh" => MergeFill, true, 3, 1, false;
    "ke∞s∞h" => MergeFill, false, 3, 1, true;
    "me∞s∞h" => MergeFill, true, 3, 1, true;
    "kvmeh" => MergeClose, false, 1, 0, false;
    "mvkeh" => MergeClose, true, 1, 0, false;
    "kvmfc" => MergeClose, false, 2, 0, false;
    "mvkfc" => MergeClose, true, 2, 0, false;
    "kemfh" => MergeClose, false, 2, 1, false;
    "mekfh" => MergeClose, true, 2, 1, false;
    "ke∞mf∞h" => MergeClose, false, 2, 1, true;
    "me∞kf∞h" => MergeClose, true, 2, 1, true;
    "kemsc" => MergeClose, false, 3, 1, false;
    "meksc" => MergeClose, true, 3, 1, false;
    "ke∞ms∞c" => MergeClose, false, 3, 1, true;
    "me∞ks∞c" => MergeClose, true, 3, 1, true;
    "kfmsh" => MergeClose, false, 3, 2, false;
    "mfksh" => MergeClose, true, 3, 2, false;
    "kf∞ms∞h" => MergeClose, false, 3, 2, true;
    "mf∞ks∞h" => MergeClose, true, 3, 2, true;
    // stratum attachers (Fig. 10)
    "me∞E∞" => AttachOpen, false, 1, 0, true;
    "ke∞E∞" => AttachOpen, true, 1, 0, true;
    "mf∞F∞" => AttachOpen, false, 2, 0, true;
    "kf∞F∞" => AttachOpen, true, 2, 0, true;
    "ms∞S∞" => AttachOpen, false, 3, 0, true;
    "ks∞S∞" => AttachOpen, true, 3, 0, true;
    // unfilled hole shapers (Fig. 11)
    "mf∞hF∞h" => OpenHole, false, 2, 1, true;
    "kf∞hF∞h" => OpenHole, true, 2, 1, true;
    "ms∞hS∞h" => OpenHole, false, 3, 1, true;
    "ks∞hS∞h" => OpenHole, true, 3, 1, true;
    "ms∞cS∞c" => OpenHole, false, 3, 2, true;
    "ks∞cS∞c" => OpenHole, true, 3, 2, true;
    // local stratum compacters (Fig. 12)
    "ke∞me" => CompactStratum, false, 1, 0, true;
    "me∞ke" => CompactStratum, true, 1, 0, true;
    "kf∞mf" => CompactStratum, false, 2, 0, true;
    "mf∞kf" => CompactStratum, true, 2, 0, true;
    "ks∞ms" => CompactStratum, false, 3, 0, true;
    "ms∞ks" => CompactStratum, true, 3, 0, true;
    // local hole compacters (Fig. 13)
    "kf∞hmfh" => CompactHole, false, 2, 1, true;
    "mf∞hkfh" => CompactHole, true, 2, 1, true;
    "ks∞hmsh" => CompactHole, false, 3, 1, true;
    "ms∞hksh" => CompactHole, true, 3, 1, true;
    "ks∞cmsc" => CompactHole, false, 3, 2, true;
    "ms∞cksc" => CompactHole, true, 3, 2, true;
    // global stratum compacters (Fig. 14–16)
    "kE∞C" => CompactComponent, false, 1, 0, true;
    "mE∞C" => CompactComponent, true, 1, 0, true;
    "kF∞Ch" => CompactComponent, false, 2, 0, true;
    "mF∞Ch" => CompactComponent, true, 2, 0, true;
    "kS∞Cc" => CompactComponent, false, 3, 0, true;
    "mS∞Cc" => CompactComponent, true, 3, 0, true;
    "kE∞mCh" => CompactComponentHole, false, 1, 0, true;
    "mE∞kCh" => CompactComponentHole, true, 1, 0, true;
    "kF∞mCc" => CompactComponentHole, false, 2, 0, true;
    "mF∞kCc" => CompactComponentHole, true, 2, 0, true;
    "kF∞hC" => FillComponentHole, false, 2, 0, true;
    "mF∞hC" => FillComponentHole, true, 2, 0, true;
    "kS∞cC" => FillComponentHole, false, 3, 0, true;
    "mS∞cC" => FillComponentHole, true, 3, 0, true;
}

/// Where an operator acts: the strata and components it takes, by number, and the choices
/// the paper leaves to the modeller. Which fields an operator reads is in its
/// [`EoOperator::precondition`]; the others are ignored.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EoArgs {
    /// the stratum acted on (subdivided, merged into, detached, compacted, coalesced into)
    pub s: Option<usize>,
    /// a second stratum: the cut of a coalescence, the stratum merged by a local hole shaper
    pub t: Option<usize>,
    /// a third stratum: the other part of a coalescence
    pub u: Option<usize>,
    /// the component acted on
    pub c: Option<usize>,
    /// a second component (joined, merged away)
    pub c2: Option<usize>,
    /// a third component (the one of a compacting vertex in `kE∞C`)
    pub c3: Option<usize>,
    /// the frontier of the new stratum; the fillers of a compacter; in a subdivision, the
    /// frontier strata that bound both parts (and the cut, where lower than it: the ends of
    /// the edge of `mef`; for `mve` on a loop, its one vertex)
    pub on: Vec<usize>,
    /// strata that go with the new part: the second part of a subdivision takes these of
    /// the frontier (those also in `on` stay with both), a split component takes these
    /// strata, a de-compacted stratum drops these from its frontier
    pub moved: Vec<usize>,
    /// strata that form the second new component of `mE∞C`
    pub moved2: Vec<usize>,
    /// `(k, count)`: holes that go with the new part (of a subdivision, of a split
    /// component)
    pub holes: Vec<(usize, i64)>,
    /// completeness of the two parts of a subdivided boundary-incomplete stratum (default:
    /// for an edge with something in its frontier, the first part complete; otherwise
    /// both incomplete)
    pub parts_complete: Option<(bool, bool)>,
    /// completeness of the new cut of `mef∞`, `mfs∞` (default: complete)
    pub cut_complete: Option<bool>,
}

impl EoArgs {
    /// No argument.
    pub fn new() -> Self {
        Self::default()
    }
    /// With the stratum acted on.
    pub fn s(mut self, s: usize) -> Self {
        self.s = Some(s);
        self
    }
    /// With a second stratum.
    pub fn t(mut self, t: usize) -> Self {
        self.t = Some(t);
        self
    }
    /// With a third stratum.
    pub fn u(mut self, u: usize) -> Self {
        self.u = Some(u);
        self
    }
    /// With the component acted on.
    pub fn c(mut self, c: usize) -> Self {
        self.c = Some(c);
        self
    }
    /// With a second component.
    pub fn c2(mut self, c: usize) -> Self {
        self.c2 = Some(c);
        self
    }
    /// With a third component.
    pub fn c3(mut self, c: usize) -> Self {
        self.c3 = Some(c);
        self
    }
    /// With the frontier of the new stratum, or the fillers.
    pub fn on(mut self, on: &[usize]) -> Self {
        self.on = on.to_vec();
        self
    }
    /// With the strata that go with the new part.
    pub fn moved(mut self, m: &[usize]) -> Self {
        self.moved = m.to_vec();
        self
    }
    /// With the strata of the second new component.
    pub fn moved2(mut self, m: &[usize]) -> Self {
        self.moved2 = m.to_vec();
        self
    }
    /// With holes that go with the new part.
    pub fn holes(mut self, h: &[(usize, i64)]) -> Self {
        self.holes = h.to_vec();
        self
    }
    /// With the completeness of the two parts.
    pub fn parts(mut self, a: bool, b: bool) -> Self {
        self.parts_complete = Some((a, b));
        self
    }
    /// With the completeness of the new cut.
    pub fn cut_complete(mut self, c: bool) -> Self {
        self.cut_complete = Some(c);
        self
    }
}

impl EoOperator {
    /// The name in the paper's notation (`mvC`, `mve∞`, `kffhmCCh`, …); for an instance the
    /// paper does not name (a dimension above 3), the scheme's generic notation.
    pub fn name(&self) -> &'static str {
        match Self::ALL.iter().position(|o| o == self) {
            Some(i) => Self::NAMES[i],
            None => self.scheme.notation(),
        }
    }

    /// The operator with this name, if the paper names one.
    pub fn from_name(name: &str) -> Option<EoOperator> {
        Self::NAMES.iter().position(|&n| n == name).map(|i| Self::ALL[i])
    }

    /// The family of EO §3.2.
    pub fn family(&self) -> Family {
        self.scheme.family()
    }

    /// The inverse operator (`mve` ↔ `kve`, `kemC` ↔ `mekC`, …).
    pub fn inverse_op(&self) -> EoOperator {
        EoOperator { inverse: !self.inverse, ..*self }
    }

    /// The change of the Euler characteristic the operator makes, by both theorems.
    pub fn euler_effect(&self) -> i64 {
        use Scheme::*;
        let n = self.n;
        let fwd = match self.scheme {
            AttachHole | AttachOpen => sign(n),
            AttachClosed => 1 + sign(n),
            DetachHole => -sign(n),
            // the detached stratum counts (-1)^n (1 + (-1)^{n-1})
            DetachHoled => -sign(n) * (1 - sign(n)),
            OpenHole => sign(n + self.d),
            _ => 0,
        };
        if self.inverse {
            -fwd
        } else {
            fwd
        }
    }

    /// The precondition, in words, with the arguments ([`EoArgs`]) the operator reads.
    pub fn precondition(&self) -> &'static str {
        use Scheme::*;
        match (self.scheme, self.inverse, self.n) {
            (AttachHole, false, 0) => "none: the new vertex is a new component",
            (AttachHole, false, _) => {
                "component c is boundary-complete; the new n-ball is attached to the strata `on` of c (its frontier, not empty); c gets a global n-hole"
            }
            (AttachHole, true, 0) => "stratum s is a vertex that is a component alone and bounds nothing",
            (AttachHole, true, _) => {
                "stratum s is a boundary-complete n-ball that bounds nothing; its component has a global n-hole, which goes"
            }
            (AttachClosed, false, _) => "none: the closed n-stratum (with its n-hole) is a new component with a global n-hole",
            (AttachClosed, true, _) => {
                "stratum s is closed (its only hole is its n-hole) and is a component alone whose only hole is a global n-hole"
            }
            (DetachHole, false, 1) => {
                "stratum s is a boundary-complete edge without holes that bounds nothing; the strata `moved` of its component (not empty, not all) form the new component and take the global holes `holes`; no frontier joins them to the others"
            }
            (DetachHole, false, _) => {
                "stratum s is a boundary-complete n-ball that bounds nothing; its component gets a global (n-1)-hole"
            }
            (DetachHole, true, 1) => {
                "components c and c2 are distinct and boundary-complete; the new edge is attached to `on`, which meets both; c2 joins c"
            }
            (DetachHole, true, _) => {
                "component c is boundary-complete with a global (n-1)-hole; the new n-ball is attached to `on` in c; the hole goes"
            }
            (DetachHoled, false, _) => {
                "stratum s is boundary-complete, its only hole an (n-1)-hole, and bounds nothing; the strata `moved` form the new component, which takes the holes `holes` and the new global (n-1)-hole; no frontier joins them to the others"
            }
            (DetachHoled, true, _) => {
                "components c and c2 are distinct and boundary-complete, c2 has a global (n-1)-hole; the new n-stratum with an (n-1)-hole is attached to `on`, which meets both; c2 joins c and loses the hole"
            }
            (Subdivide, false, _) => {
                "stratum s is an n-stratum, boundary-complete (or incomplete for the ∞ form); the new (n-1)-ball is bounded by the strata of `on` below it, which bound both parts; the second part takes the frontier strata `moved` and the complete holes `holes`; parts of a complete stratum are complete, of an incomplete one at least one is incomplete (`parts_complete`; a complete part joins the complete component of its frontier)"
            }
            (Subdivide, true, _) => {
                "s and u are distinct n-strata of one component (or of several, as in a G-map read by `from_map`: the merged stratum stays in s's component, or goes to u's when it is boundary-incomplete and s's is not; a component left empty goes), t an (n-1)-ball in both frontiers that bounds no other stratum beside those above s or u; all complete (at least one incomplete for the ∞ form); u and t join s"
            }
            (SubdivideByClosed, false, _) => {
                "stratum s is an n-stratum; a closed (n-1)-stratum inside it makes an (n-1)-hole in s and bounds a new n-ball"
            }
            (SubdivideByClosed, true, _) => {
                "u is a boundary-complete n-ball bounded by t alone, t a closed (n-1)-stratum bounding only s and u, s has a complete (n-1)-hole; t and u join s, which loses the hole"
            }
            (SubdivideClosedByClosed, false, _) => {
                "stratum s is closed (it has an n-hole); a closed (n-1)-stratum cuts it into s, which loses the n-hole, and a new n-ball"
            }
            (SubdivideClosedByClosed, true, _) => {
                "u is a boundary-complete n-ball bounded by t alone, t a closed (n-1)-stratum bounding only s and u, s bounded by t alone; t and u join s, which becomes closed"
            }
            (MergeFill, false, _) => {
                "t is a d-ball in the frontier of the n-stratum s (same component) bounding nothing else below s; s has an (n-1-d)-hole of t's state (boundary-incomplete for the ∞ form); t joins s, which loses the hole"
            }
            (MergeFill, true, _) => {
                "stratum s is an n-stratum; a new d-ball (boundary-incomplete for the ∞ form, then s is too) attached to `on` in s's frontier makes an (n-1-d)-hole in s"
            }
            (MergeClose, false, _) => {
                "t is a d-ball in the frontier of the n-stratum s (same component) bounding nothing else below s; t joins s, which gets an (n-d)-hole (boundary-incomplete for the ∞ form)"
            }
            (MergeClose, true, _) => {
                "stratum s has an (n-d)-hole (boundary-incomplete for the ∞ form); a new d-ball attached to `on` in s's frontier takes it away"
            }
            (AttachOpen, false, _) => {
                "none: the new boundary-incomplete n-ball, attached to `on`, is a new boundary-incomplete component"
            }
            (AttachOpen, true, _) => {
                "stratum s is a boundary-incomplete n-ball bounding nothing, a component alone and without holes"
            }
            (OpenHole, false, _) => {
                "stratum s is a boundary-incomplete n-stratum in a boundary-incomplete component; both get a boundary-incomplete d-hole, d <= n-1"
            }
            (OpenHole, true, _) => "stratum s has a boundary-incomplete d-hole and its component a global d-hole; both go",
            (CompactStratum, false, _) => {
                "stratum s is boundary-incomplete without boundary-incomplete holes; the fillers `on` join its frontier, which must then hold something unless s is closed"
            }
            (CompactStratum, true, _) => {
                "stratum s is boundary-complete in a boundary-incomplete component; it drops `moved` from its frontier"
            }
            (CompactHole, false, _) => {
                "stratum s has a boundary-incomplete d-hole; the fillers `on` join its frontier; the hole becomes boundary-complete"
            }
            (CompactHole, true, _) => {
                "stratum s is boundary-incomplete with a boundary-complete d-hole, which becomes boundary-incomplete; s drops `moved` from its frontier"
            }
            (CompactComponent, false, 1) => {
                "c is a boundary-incomplete edge component without holes whose strata are all boundary-complete; c2 and c3 are distinct boundary-complete components; c and c3 join c2"
            }
            (CompactComponent, false, _) => {
                "c is a boundary-incomplete n-component without holes whose strata are all boundary-complete; c2 is boundary-complete with a global (n-1)-hole; c joins c2, which loses the hole"
            }
            (CompactComponent, true, 1) => {
                "c is boundary-complete; the strata `moved` form a new boundary-incomplete component, the strata `moved2` a new boundary-complete one"
            }
            (CompactComponent, true, _) => {
                "c is boundary-complete; the strata `moved` form a new boundary-incomplete component; c gets a global (n-1)-hole"
            }
            (CompactComponentHole, false, _) => {
                "c is a boundary-incomplete n-component without holes whose strata are all boundary-complete; c2 is boundary-complete; c joins c2, which gets a global n-hole"
            }
            (CompactComponentHole, true, _) => {
                "c is boundary-complete with a global n-hole; the strata `moved` form a new boundary-incomplete component; the hole goes"
            }
            (FillComponentHole, false, _) => {
                "c is a boundary-incomplete n-component with a global (n-1)-hole; c2 is a boundary-complete component without holes; c2 joins c, which loses the hole"
            }
            (FillComponentHole, true, _) => {
                "c is a boundary-incomplete n-component; the strata `moved` form a new boundary-complete component; c gets a global (n-1)-hole"
            }
        }
    }
}

fn need<T: Copy>(x: Option<T>, op: &'static str, what: &'static str) -> Result<T, StrataError> {
    x.ok_or(StrataError::Missing { op, what })
}

fn pre(op: &'static str, why: impl Into<String>) -> StrataError {
    StrataError::Precondition { op, why: why.into() }
}

impl StratifiedObject {
    /// Applies operator `op` at `args`. On success the object satisfies every invariant of
    /// [`StratifiedObject::validate`] and the step reports the counts; on a refusal (a
    /// failed precondition or a broken invariant, with the reason) the object is unchanged.
    /// O(strata · frontier).
    pub fn apply(&mut self, op: EoOperator, args: &EoArgs) -> Result<EoStep, StrataError> {
        let mut next = self.clone();
        let (new, new_c) = next.apply_raw(op, args)?;
        next.validate()?;
        *self = next;
        Ok(self.step_with(op.name(), new, new_c))
    }

    /// [`StratifiedObject::apply`] by the operator's name.
    pub fn apply_named(&mut self, name: &str, args: &EoArgs) -> Result<EoStep, StrataError> {
        let op = EoOperator::from_name(name)
            .ok_or_else(|| StrataError::Precondition { op: "apply", why: format!("EO names no operator {name:?}") })?;
        self.apply(op, args)
    }

    fn live(&self, s: usize) -> Result<usize, StrataError> {
        self.stratum(s).map(|_| s)
    }

    fn expect_dim(&self, op: &'static str, s: usize, dim: usize) -> Result<(), StrataError> {
        let st = self.stratum(s)?;
        if st.dim != dim {
            return Err(pre(op, format!("stratum {s} is {}-dimensional, not {dim}-dimensional", st.dim)));
        }
        Ok(())
    }

    fn expect_state(&self, op: &'static str, s: usize, complete: bool) -> Result<(), StrataError> {
        let st = self.stratum(s)?;
        if st.complete != complete {
            let want = if complete { "boundary-complete" } else { "boundary-incomplete" };
            return Err(pre(op, format!("stratum {s} is not {want}")));
        }
        Ok(())
    }

    fn expect_ball(&self, op: &'static str, s: usize) -> Result<(), StrataError> {
        if !self.stratum(s)?.is_ball() {
            return Err(pre(op, format!("stratum {s} has holes (it must be a ball)")));
        }
        Ok(())
    }

    fn expect_component_state(&self, op: &'static str, c: usize, complete: bool) -> Result<(), StrataError> {
        if self.component(c)?.complete != complete {
            let want = if complete { "boundary-complete" } else { "boundary-incomplete" };
            return Err(pre(op, format!("component {c} is not {want}")));
        }
        Ok(())
    }

    fn expect_in(&self, op: &'static str, strata: &[usize], comps: &[usize], below: usize) -> Result<(), StrataError> {
        for &b in strata {
            let st = self.stratum(b)?;
            if !comps.contains(&st.component) {
                return Err(pre(op, format!("stratum {b} is not in component {:?}", comps)));
            }
            if st.dim >= below {
                return Err(pre(op, format!("stratum {b} is not of dimension below {below}")));
            }
        }
        Ok(())
    }

    fn expect_frontier_of(&self, op: &'static str, strata: &[usize], s: usize) -> Result<(), StrataError> {
        for &b in strata {
            self.stratum(b)?;
            if !self.strata[s].frontier.contains(&b) {
                return Err(pre(op, format!("stratum {b} is not in the frontier of stratum {s}")));
            }
        }
        Ok(())
    }

    fn expect_fillers(&self, op: &'static str, on: &[usize], below: usize) -> Result<(), StrataError> {
        for &b in on {
            if self.stratum(b)?.dim >= below {
                return Err(pre(op, format!("stratum {b} is not of dimension below {below}")));
            }
        }
        Ok(())
    }

    /// t bounds only `allowed` and strata above them.
    fn expect_bounds_only(&self, op: &'static str, t: usize, allowed: &[usize]) -> Result<(), StrataError> {
        for r in self.bounded_by(t) {
            if allowed.contains(&r) {
                continue;
            }
            if !allowed.iter().any(|a| self.strata[r].frontier.contains(a)) {
                return Err(pre(op, format!("stratum {t} also bounds stratum {r}")));
            }
        }
        Ok(())
    }

    /// Splits component `c`: the strata `moved` go to a new component with the same state,
    /// which takes the global holes `holes` from `c`.
    fn split_component(
        &mut self,
        op: &'static str,
        c: usize,
        moved: &[usize],
        holes: &[(usize, i64)],
        check_frontiers: bool,
    ) -> Result<usize, StrataError> {
        let all = self.strata_of(c);
        if moved.is_empty() || moved.iter().any(|m| !all.contains(m)) {
            return Err(pre(op, format!("the strata that move ({moved:?}) must be some strata of component {c}")));
        }
        if check_frontiers {
            for &s in &all {
                let here = moved.contains(&s);
                for &b in &self.strata[s].frontier {
                    if self.strata[b].component == c && moved.contains(&b) != here {
                        return Err(pre(op, format!("stratum {s} is bounded by stratum {b} across the split")));
                    }
                }
            }
        }
        let nc = self.new_component(self.components[c].complete);
        for &m in moved {
            self.strata[m].component = nc;
        }
        for &(k, h) in holes {
            self.add_global_hole(c, k, -h)?;
            self.add_global_hole(nc, k, h)?;
        }
        Ok(nc)
    }

    fn apply_raw(&mut self, op: EoOperator, a: &EoArgs) -> Result<(Vec<usize>, Vec<usize>), StrataError> {
        use Scheme::*;
        let name = op.name();
        let n = op.n;
        let mut new = Vec::new();
        let mut new_c = Vec::new();
        match (op.scheme, op.inverse) {
            (AttachHole, false) => {
                if n == 0 {
                    let c = self.new_component(true);
                    new_c.push(c);
                    new.push(self.new_stratum(0, true, c, &[]));
                } else {
                    let c = need(a.c, name, "the component c")?;
                    self.expect_component_state(name, c, true)?;
                    self.expect_in(name, &a.on, &[c], n)?;
                    new.push(self.new_stratum(n, true, c, &a.on));
                    self.add_global_hole(c, n, 1)?;
                }
            }
            (AttachHole, true) => {
                let s = self.live(need(a.s, name, "the stratum s")?)?;
                self.expect_dim(name, s, n)?;
                self.expect_state(name, s, true)?;
                self.expect_ball(name, s)?;
                let c = self.strata[s].component;
                self.kill_stratum(name, s)?;
                if n == 0 {
                    if !self.strata_of(c).is_empty() {
                        return Err(pre(name, format!("vertex {s} is not a component alone")));
                    }
                    if self.components[c].holes.iter().any(|&h| h != 0) {
                        return Err(pre(name, format!("component {c} has global holes")));
                    }
                    self.components[c].alive = false;
                } else {
                    self.add_global_hole(c, n, -1)?;
                }
            }
            (AttachClosed, false) => {
                let c = self.new_component(true);
                new_c.push(c);
                let s = self.new_stratum(n, true, c, &[]);
                new.push(s);
                self.add_hole(s, n, 1, false)?;
                self.add_global_hole(c, n, 1)?;
            }
            (AttachClosed, true) => {
                let s = self.live(need(a.s, name, "the stratum s")?)?;
                self.expect_dim(name, s, n)?;
                let st = &self.strata[s];
                if st.holes.iter().enumerate().any(|(k, &h)| h != if k == n { 1 } else { 0 }) {
                    return Err(pre(name, format!("stratum {s} is not closed with its n-hole alone")));
                }
                let c = st.component;
                self.kill_stratum(name, s)?;
                if !self.strata_of(c).is_empty() {
                    return Err(pre(name, format!("stratum {s} is not a component alone")));
                }
                self.add_global_hole(c, n, -1)?;
                if self.components[c].holes.iter().any(|&h| h != 0) {
                    return Err(pre(name, format!("component {c} has other global holes")));
                }
                self.components[c].alive = false;
            }
            (DetachHole, false) | (DetachHoled, false) => {
                let s = self.live(need(a.s, name, "the stratum s")?)?;
                self.expect_dim(name, s, n)?;
                self.expect_state(name, s, true)?;
                let st = &self.strata[s];
                if op.scheme == DetachHole {
                    self.expect_ball(name, s)?;
                } else if st.holes.iter().enumerate().any(|(k, &h)| h != if k + 1 == n { 1 } else { 0 }) {
                    return Err(pre(name, format!("stratum {s} does not have one (n-1)-hole and no other")));
                }
                let c = self.strata[s].component;
                self.expect_component_state(name, c, true)?;
                self.kill_stratum(name, s)?;
                if op.scheme == DetachHole && n >= 2 {
                    self.add_global_hole(c, n - 1, 1)?;
                } else {
                    let nc = self.split_component(name, c, &a.moved, &a.holes, true)?;
                    new_c.push(nc);
                    if op.scheme == DetachHoled {
                        self.add_global_hole(nc, n - 1, 1)?;
                    }
                }
            }
            (DetachHole, true) | (DetachHoled, true) => {
                let c = need(a.c, name, "the component c")?;
                self.expect_component_state(name, c, true)?;
                let joins = op.scheme == DetachHoled || n == 1;
                if joins {
                    let c2 = need(a.c2, name, "the second component c2")?;
                    self.expect_component_state(name, c2, true)?;
                    if c == c2 {
                        return Err(pre(name, "c and c2 are the same component"));
                    }
                    self.expect_in(name, &a.on, &[c, c2], n)?;
                    for x in [c, c2] {
                        if !a.on.iter().any(|&b| self.strata[b].component == x) {
                            return Err(pre(name, format!("the new stratum does not meet component {x}")));
                        }
                    }
                    let s = self.new_stratum(n, true, c, &a.on);
                    new.push(s);
                    if op.scheme == DetachHoled {
                        self.add_hole(s, n - 1, 1, false)?;
                        self.add_global_hole(c2, n - 1, -1)?;
                    }
                    self.absorb(c, c2);
                } else {
                    self.expect_in(name, &a.on, &[c], n)?;
                    new.push(self.new_stratum(n, true, c, &a.on));
                    self.add_global_hole(c, n - 1, -1)?;
                }
            }
            (Subdivide, false) => {
                let s = self.live(need(a.s, name, "the stratum s")?)?;
                self.expect_dim(name, s, n)?;
                self.expect_state(name, s, !op.open)?;
                let st = self.strata[s].clone();
                let (pa, pb) = if st.complete {
                    (true, true)
                } else {
                    a.parts_complete.unwrap_or((n == 1 && !st.frontier.is_empty(), false))
                };
                let cut_complete = if n == 1 { true } else { a.cut_complete.unwrap_or(true) };
                if st.complete && a.parts_complete.is_some_and(|p| p != (true, true)) {
                    return Err(pre(name, "the parts of a boundary-complete stratum are boundary-complete"));
                }
                if st.complete && !cut_complete {
                    return Err(pre(name, "a boundary-complete stratum has no boundary-incomplete cut"));
                }
                if !st.complete && pa && pb {
                    return Err(pre(name, "a boundary-incomplete stratum keeps a boundary-incomplete part"));
                }
                if !cut_complete && (pa || pb) {
                    return Err(pre(name, "the parts along a boundary-incomplete cut are boundary-incomplete"));
                }
                self.expect_frontier_of(name, &a.on, s)?;
                self.expect_frontier_of(name, &a.moved, s)?;
                // the strata of `on` bound both parts, and the cut where they are lower
                let cut_on: Vec<usize> = a.on.iter().copied().filter(|&x| self.strata[x].dim + 1 < n).collect();
                let cut = self.new_stratum(n - 1, cut_complete, st.component, &cut_on);
                let mut fb = vec![cut];
                fb.extend(a.on.iter().copied());
                fb.extend(a.moved.iter().copied());
                let b = self.new_stratum(n, pb, st.component, &fb);
                new.extend([cut, b]);
                let keep: Vec<usize> =
                    st.frontier.iter().copied().filter(|x| !a.moved.contains(x) || a.on.contains(x)).collect();
                self.strata[s].frontier = keep;
                self.strata[s].frontier.push(cut);
                self.strata[s].complete = pa;
                // a boundary-complete part of a boundary-incomplete stratum joins the
                // complete part of the object where its frontier lies (mve∞ on an edge with
                // one end: the part from that end to the new vertex), with the cut
                if pa && !self.components[st.component].complete {
                    let home = self.strata[s]
                        .frontier
                        .iter()
                        .map(|&x| self.strata[x].component)
                        .find(|&c| self.components[c].complete);
                    if let Some(h) = home {
                        self.strata[s].component = h;
                        self.strata[cut].component = h;
                    }
                }
                // the holes that go with the second part are boundary-complete ones; the
                // boundary-incomplete holes stay with the first part
                for &(k, h) in &a.holes {
                    self.add_hole(s, k, -h, false)?;
                    self.add_hole(b, k, h, false)?;
                }
                self.add_where_bounded(s, &[cut, b]);
            }
            (Subdivide, true) => {
                let s = self.live(need(a.s, name, "the part s")?)?;
                let t = self.live(need(a.t, name, "the cut t")?)?;
                let u = self.live(need(a.u, name, "the part u")?)?;
                if s == u {
                    return Err(pre(name, "s and u are the same stratum"));
                }
                self.expect_dim(name, s, n)?;
                self.expect_dim(name, u, n)?;
                self.expect_dim(name, t, n - 1)?;
                self.expect_ball(name, t)?;
                let (cs, ct, cu) = (self.strata[s].component, self.strata[t].component, self.strata[u].component);
                self.expect_frontier_of(name, &[t], s)?;
                self.expect_frontier_of(name, &[t], u)?;
                self.expect_bounds_only(name, t, &[s, u])?;
                let complete = self.strata[s].complete && self.strata[u].complete && self.strata[t].complete;
                // the parts may lie in different components when one of them is a
                // boundary-incomplete stratum component of its own (a G-map read by
                // `from_map`): the merged stratum goes to the boundary-incomplete one, and a
                // component left without strata goes; the theorems check the rest
                let target = if !complete && self.components[cs].complete { cu } else { cs };
                self.strata[s].component = target;
                if complete == op.open {
                    return Err(pre(
                        name,
                        if op.open {
                            "the strata are all boundary-complete (use the form without ∞)"
                        } else {
                            "a stratum is boundary-incomplete (use the ∞ form)"
                        },
                    ));
                }
                let ust = self.strata[u].clone();
                for k in 1..=n {
                    let (h, o) = (ust.holes[k], ust.open_holes[k]);
                    self.add_hole(s, k, h - o, false)?;
                    self.add_hole(s, k, o, true)?;
                }
                let mut f: Vec<usize> = self.strata[s].frontier.clone();
                for x in ust.frontier {
                    if !f.contains(&x) {
                        f.push(x);
                    }
                }
                f.retain(|&x| x != t);
                self.strata[s].frontier = f;
                self.strata[s].complete = complete;
                self.replace_in_frontiers(u, Some(s));
                self.replace_in_frontiers(t, None);
                self.strata[u].alive = false;
                self.strata[t].alive = false;
                for c in [cs, ct, cu] {
                    if self.components[c].alive && self.strata_of(c).is_empty() {
                        if self.components[c].holes.iter().any(|&h| h != 0) {
                            return Err(pre(name, format!("component {c} would vanish with its global holes")));
                        }
                        self.components[c].alive = false;
                    }
                }
            }
            (SubdivideByClosed, false) | (SubdivideClosedByClosed, false) => {
                let s = self.live(need(a.s, name, "the stratum s")?)?;
                self.expect_dim(name, s, n)?;
                let c = self.strata[s].component;
                if op.scheme == SubdivideClosedByClosed && !self.strata[s].is_closed() {
                    return Err(pre(name, format!("stratum {s} is not closed (no {n}-hole)")));
                }
                let cut = self.new_stratum(n - 1, true, c, &[]);
                self.add_hole(cut, n - 1, 1, false)?;
                let b = self.new_stratum(n, true, c, &[cut]);
                new.extend([cut, b]);
                if op.scheme == SubdivideByClosed {
                    self.add_hole(s, n - 1, 1, false)?;
                } else {
                    self.add_hole(s, n, -1, false)?;
                }
                self.strata[s].frontier.push(cut);
                self.add_where_bounded(s, &[cut, b]);
            }
            (SubdivideByClosed, true) | (SubdivideClosedByClosed, true) => {
                let s = self.live(need(a.s, name, "the stratum s")?)?;
                let t = self.live(need(a.t, name, "the closed cut t")?)?;
                let u = self.live(need(a.u, name, "the inner ball u")?)?;
                if s == u {
                    return Err(pre(name, "s and u are the same stratum"));
                }
                self.expect_dim(name, s, n)?;
                self.expect_dim(name, u, n)?;
                self.expect_dim(name, t, n - 1)?;
                let tst = &self.strata[t];
                if tst.holes.iter().enumerate().any(|(k, &h)| h != if k + 1 == n { 1 } else { 0 }) {
                    return Err(pre(name, format!("stratum {t} is not closed with its (n-1)-hole alone")));
                }
                self.expect_ball(name, u)?;
                self.expect_state(name, u, true)?;
                if self.strata[u].frontier != [t] {
                    return Err(pre(name, format!("stratum {u} is not bounded by {t} alone")));
                }
                self.expect_frontier_of(name, &[t], s)?;
                self.expect_bounds_only(name, t, &[s, u])?;
                if op.scheme == SubdivideClosedByClosed && self.strata[s].frontier != [t] {
                    return Err(pre(name, format!("stratum {s} is not bounded by {t} alone")));
                }
                self.replace_in_frontiers(u, Some(s));
                self.replace_in_frontiers(t, None);
                self.strata[u].alive = false;
                self.strata[t].alive = false;
                if op.scheme == SubdivideByClosed {
                    self.add_hole(s, n - 1, -1, false)?;
                } else {
                    self.add_hole(s, n, 1, false)?;
                }
            }
            (MergeFill, false) | (MergeClose, false) => {
                let s = self.live(need(a.s, name, "the stratum s")?)?;
                let t = self.live(need(a.t, name, "the merged stratum t")?)?;
                self.expect_dim(name, s, n)?;
                self.expect_dim(name, t, op.d)?;
                self.expect_ball(name, t)?;
                self.expect_state(name, t, !op.open)?;
                if self.strata[t].component != self.strata[s].component {
                    return Err(pre(name, format!("strata {t} and {s} are not in one component")));
                }
                self.expect_frontier_of(name, &[t], s)?;
                self.expect_bounds_only(name, t, &[s])?;
                let tf = self.strata[t].frontier.clone();
                for x in tf {
                    if !self.strata[s].frontier.contains(&x) {
                        self.strata[s].frontier.push(x);
                    }
                }
                self.replace_in_frontiers(t, None);
                self.strata[t].alive = false;
                if op.scheme == MergeFill {
                    self.add_hole(s, n - 1 - op.d, -1, op.open)?;
                } else {
                    self.add_hole(s, n - op.d, 1, op.open)?;
                }
            }
            (MergeFill, true) | (MergeClose, true) => {
                let s = self.live(need(a.s, name, "the stratum s")?)?;
                self.expect_dim(name, s, n)?;
                if op.open {
                    self.expect_state(name, s, false)?;
                }
                self.expect_frontier_of(name, &a.on, s)?;
                let c = self.strata[s].component;
                let t = self.new_stratum(op.d, !op.open, c, &a.on);
                new.push(t);
                self.strata[s].frontier.push(t);
                self.add_where_bounded(s, &[t]);
                if op.scheme == MergeFill {
                    self.add_hole(s, n - 1 - op.d, 1, op.open)?;
                } else {
                    self.add_hole(s, n - op.d, -1, op.open)?;
                }
            }
            (AttachOpen, false) => {
                self.expect_fillers(name, &a.on, n)?;
                let c = self.new_component(false);
                new_c.push(c);
                new.push(self.new_stratum(n, false, c, &a.on));
            }
            (AttachOpen, true) => {
                let s = self.live(need(a.s, name, "the stratum s")?)?;
                self.expect_dim(name, s, n)?;
                self.expect_state(name, s, false)?;
                self.expect_ball(name, s)?;
                let c = self.strata[s].component;
                self.kill_stratum(name, s)?;
                if !self.strata_of(c).is_empty() || self.components[c].holes.iter().any(|&h| h != 0) {
                    return Err(pre(name, format!("stratum {s} is not a component alone without holes")));
                }
                self.components[c].alive = false;
            }
            (OpenHole, inv) => {
                let s = self.live(need(a.s, name, "the stratum s")?)?;
                self.expect_dim(name, s, n)?;
                self.expect_state(name, s, false)?;
                let c = self.strata[s].component;
                self.expect_component_state(name, c, false)?;
                let delta = if inv { -1 } else { 1 };
                self.add_hole(s, op.d, delta, true)?;
                self.add_global_hole(c, op.d, delta)?;
            }
            (CompactStratum, false) => {
                let s = self.live(need(a.s, name, "the stratum s")?)?;
                self.expect_dim(name, s, n)?;
                self.expect_state(name, s, false)?;
                if self.strata[s].open_holes.iter().any(|&o| o > 0) {
                    return Err(pre(name, format!("stratum {s} has boundary-incomplete holes (compact them first)")));
                }
                self.expect_fillers(name, &a.on, n)?;
                for &b in &a.on {
                    if !self.strata[s].frontier.contains(&b) {
                        self.strata[s].frontier.push(b);
                    }
                }
                self.strata[s].complete = true;
            }
            (CompactStratum, true) => {
                let s = self.live(need(a.s, name, "the stratum s")?)?;
                self.expect_dim(name, s, n)?;
                self.expect_state(name, s, true)?;
                self.expect_frontier_of(name, &a.moved, s)?;
                self.strata[s].frontier.retain(|x| !a.moved.contains(x));
                self.strata[s].complete = false;
            }
            (CompactHole, inv) => {
                let s = self.live(need(a.s, name, "the stratum s")?)?;
                self.expect_dim(name, s, n)?;
                self.expect_state(name, s, false)?;
                let k = op.d;
                if !inv {
                    self.expect_fillers(name, &a.on, n)?;
                    self.add_hole(s, k, -1, true)?;
                    self.add_hole(s, k, 1, false)?;
                    for &b in &a.on {
                        if !self.strata[s].frontier.contains(&b) {
                            self.strata[s].frontier.push(b);
                        }
                    }
                } else {
                    self.expect_frontier_of(name, &a.moved, s)?;
                    self.add_hole(s, k, -1, false)?;
                    self.add_hole(s, k, 1, true)?;
                    self.strata[s].frontier.retain(|x| !a.moved.contains(x));
                }
            }
            (CompactComponent, false) | (CompactComponentHole, false) => {
                let c = need(a.c, name, "the incomplete component c")?;
                let c2 = need(a.c2, name, "the complete component c2")?;
                self.expect_component_state(name, c, false)?;
                self.expect_component_state(name, c2, true)?;
                if self.component_dim(c) != n {
                    return Err(pre(name, format!("component {c} is not {n}-dimensional")));
                }
                if self.components[c].holes.iter().any(|&h| h != 0) {
                    return Err(pre(name, format!("component {c} has global holes")));
                }
                if let Some(s) = self.strata_of(c).into_iter().find(|&s| !self.strata[s].complete) {
                    return Err(pre(name, format!("stratum {s} of component {c} is still boundary-incomplete")));
                }
                self.absorb(c2, c);
                if op.scheme == CompactComponentHole {
                    self.add_global_hole(c2, n, 1)?;
                } else if n == 1 {
                    let c3 = need(a.c3, name, "the component c3 of the compacting vertex")?;
                    self.expect_component_state(name, c3, true)?;
                    if c3 == c2 {
                        return Err(pre(name, "c2 and c3 are the same component (that is kE∞mCh)"));
                    }
                    self.absorb(c2, c3);
                } else {
                    self.add_global_hole(c2, n - 1, -1)?;
                }
            }
            (CompactComponent, true) | (CompactComponentHole, true) => {
                let c = need(a.c, name, "the complete component c")?;
                self.expect_component_state(name, c, true)?;
                if op.scheme == CompactComponentHole {
                    self.add_global_hole(c, n, -1)?;
                } else if n >= 2 {
                    self.add_global_hole(c, n - 1, 1)?;
                }
                let ci = self.split_component(name, c, &a.moved, &[], false)?;
                self.components[ci].complete = false;
                new_c.push(ci);
                if self.component_dim(ci) != n {
                    return Err(pre(name, format!("the new boundary-incomplete component is not {n}-dimensional")));
                }
                if op.scheme == CompactComponent && n == 1 {
                    let c3 = self.split_component(name, c, &a.moved2, &[], false)?;
                    new_c.push(c3);
                }
            }
            (FillComponentHole, false) => {
                let c = need(a.c, name, "the incomplete component c")?;
                let c2 = need(a.c2, name, "the filler's component c2")?;
                self.expect_component_state(name, c, false)?;
                self.expect_component_state(name, c2, true)?;
                if self.component_dim(c) != n {
                    return Err(pre(name, format!("component {c} is not {n}-dimensional")));
                }
                if self.components[c2].holes.iter().any(|&h| h != 0) {
                    return Err(pre(name, format!("component {c2} has global holes")));
                }
                self.add_global_hole(c, n - 1, -1)?;
                self.absorb(c, c2);
            }
            (FillComponentHole, true) => {
                let c = need(a.c, name, "the incomplete component c")?;
                self.expect_component_state(name, c, false)?;
                if self.component_dim(c) != n {
                    return Err(pre(name, format!("component {c} is not {n}-dimensional")));
                }
                self.add_global_hole(c, n - 1, 1)?;
                let nc = self.split_component(name, c, &a.moved, &[], false)?;
                self.components[nc].complete = true;
                new_c.push(nc);
            }
        }
        Ok((new, new_c))
    }
}
