//! The catalogue of EO's Euler operators: every family of EO §3.2 with the instances the
//! paper names in its figures (dimensions 0 to 3), their names, families and effect on the
//! Euler characteristic, and the arguments an operator takes. What each one requires and
//! does to a [`StratifiedObject`](super::StratifiedObject) is in `schemes.rs`, one rule per
//! scheme and direction.

use super::object::sign;

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
}
