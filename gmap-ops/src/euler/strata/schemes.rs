//! The catalogue at work: for each direction of each scheme of EO §3.2 (split by dimension
//! where EO states it differently, as `mvC` from `meCh`), one [`Rule`] holding the
//! precondition in words beside the one function that checks it and makes the change.
//!
//! The words are stated once: [`EoOperator::precondition`] returns them, and every refusal of
//! the function reports them ([`StrataError::Precondition`]'s `requires`, built by
//! [`Work::refuse`] from the rule being applied), so the text and the check are one item and
//! cannot part. `tests/eo_preconditions.rs` holds every operator to it.
//!
//! A rule's function runs on a copy of the object ([`StratifiedObject::apply`]): it may
//! refuse after changing the copy, and `apply` then drops the copy.

use super::catalogue::{EoArgs, EoOperator, Scheme};
use super::object::{EoStep, StrataError, StratifiedObject};

/// One direction of one scheme: what it requires, in words, with the arguments
/// ([`EoArgs`]) it reads, and the function that checks it and makes the change.
#[derive(Clone, Copy)]
struct Rule {
    requires: &'static str,
    apply: fn(&mut Work<'_>) -> Result<(), StrataError>,
}

impl EoOperator {
    /// The precondition, in words, with the arguments ([`EoArgs`]) the operator reads. A
    /// refusal of [`StratifiedObject::apply`] for a failed precondition reports this text
    /// ([`StrataError::Precondition`]).
    pub fn precondition(&self) -> &'static str {
        self.rule().requires
    }

    /// The rule of the operator's scheme, direction and dimension.
    fn rule(&self) -> Rule {
        use Scheme::*;
        match (self.scheme, self.inverse, self.n) {
            (AttachHole, false, 0) => MAKE_VERTEX_COMPONENT,
            (AttachHole, false, _) => ATTACH_BALL_MAKING_HOLE,
            (AttachHole, true, 0) => KILL_VERTEX_COMPONENT,
            (AttachHole, true, _) => DETACH_BALL_FILLING_HOLE,
            (AttachClosed, false, _) => ATTACH_CLOSED,
            (AttachClosed, true, _) => DETACH_CLOSED,
            (DetachHole, false, 0 | 1) => DETACH_EDGE_SPLITTING,
            (DetachHole, false, _) => DETACH_BALL_MAKING_HOLE,
            (DetachHole, true, 1) => ATTACH_EDGE_JOINING,
            (DetachHole, true, _) => ATTACH_BALL_FILLING_HOLE,
            (DetachHoled, false, _) => DETACH_HOLED,
            (DetachHoled, true, _) => ATTACH_HOLED,
            (Subdivide, false, _) => SUBDIVIDE,
            (Subdivide, true, _) => COALESCE,
            (SubdivideByClosed, false, _) => SUBDIVIDE_BY_CLOSED,
            (SubdivideByClosed, true, _) => COALESCE_CLOSED_CUT,
            (SubdivideClosedByClosed, false, _) => SUBDIVIDE_CLOSED_BY_CLOSED,
            (SubdivideClosedByClosed, true, _) => COALESCE_INTO_CLOSED,
            (MergeFill, false, _) => MERGE_FILLING,
            (MergeFill, true, _) => UNMERGE_MAKING_HOLE,
            (MergeClose, false, _) => MERGE_MAKING_HOLE,
            (MergeClose, true, _) => UNMERGE_FILLING,
            (AttachOpen, false, _) => ATTACH_OPEN,
            (AttachOpen, true, _) => DETACH_OPEN,
            (OpenHole, false, _) => MAKE_OPEN_HOLE,
            (OpenHole, true, _) => KILL_OPEN_HOLE,
            (CompactStratum, false, _) => COMPACT_STRATUM,
            (CompactStratum, true, _) => DECOMPACT_STRATUM,
            (CompactHole, false, _) => COMPACT_HOLE,
            (CompactHole, true, _) => DECOMPACT_HOLE,
            (CompactComponent, false, 1) => COMPACT_EDGE_COMPONENT,
            (CompactComponent, false, _) => COMPACT_COMPONENT_FILLING,
            (CompactComponent, true, 1) => DECOMPACT_EDGE_COMPONENT,
            (CompactComponent, true, _) => DECOMPACT_COMPONENT_MAKING_HOLE,
            (CompactComponentHole, false, _) => COMPACT_COMPONENT_MAKING_HOLE,
            (CompactComponentHole, true, _) => DECOMPACT_COMPONENT_FILLING,
            (FillComponentHole, false, _) => FILL_COMPONENT_HOLE,
            (FillComponentHole, true, _) => SPLIT_COMPONENT_MAKING_HOLE,
        }
    }
}

impl StratifiedObject {
    /// Applies operator `op` at `args`. On success the object satisfies every invariant of
    /// [`StratifiedObject::validate`] and the step reports the counts; on a refusal (a
    /// failed precondition, reported with the operator's
    /// [`precondition`](EoOperator::precondition), or a broken invariant, with the reason)
    /// the object is unchanged. O(strata · frontier).
    pub fn apply(&mut self, op: EoOperator, args: &EoArgs) -> Result<EoStep, StrataError> {
        let mut next = self.clone();
        let rule = op.rule();
        let mut work = Work {
            o: &mut next,
            op,
            a: args,
            name: op.name(),
            requires: rule.requires,
            new: Vec::new(),
            new_c: Vec::new(),
        };
        (rule.apply)(&mut work)?;
        let (new, new_c) = (work.new, work.new_c);
        next.validate()?;
        *self = next;
        Ok(self.step_with(op.name(), new, new_c))
    }

    /// [`StratifiedObject::apply`] by the operator's name.
    pub fn apply_named(&mut self, name: &str, args: &EoArgs) -> Result<EoStep, StrataError> {
        let op = EoOperator::from_name(name).ok_or_else(|| StrataError::UnknownOperator(name.to_string()))?;
        self.apply(op, args)
    }
}

/// An operator at work on a copy of the object: its arguments, what it has made so far,
/// and the checks shared by several rules, each refusing with the rule's precondition.
struct Work<'a> {
    o: &'a mut StratifiedObject,
    op: EoOperator,
    a: &'a EoArgs,
    name: &'static str,
    requires: &'static str,
    /// the strata made, for the step reported
    new: Vec<usize>,
    /// the components made
    new_c: Vec<usize>,
}

fn state(complete: bool) -> &'static str {
    if complete {
        "boundary-complete"
    } else {
        "boundary-incomplete"
    }
}

// ---------- global hole shapers (EO Fig. 1–4) ----------

/// `mvC`.
const MAKE_VERTEX_COMPONENT: Rule =
    Rule { requires: "none: the new vertex is a new component", apply: make_vertex_component };

fn make_vertex_component(w: &mut Work<'_>) -> Result<(), StrataError> {
    let c = w.o.new_component(true);
    w.new_c.push(c);
    w.new.push(w.o.new_stratum(0, true, c, &[]));
    Ok(())
}

/// `ms^n H^n`, n >= 1 (`meCh`, `mfCc`).
const ATTACH_BALL_MAKING_HOLE: Rule = Rule {
    requires: "component c is boundary-complete; the new n-ball is attached to the strata `on` of c (its frontier, not empty); c gets a global n-hole",
    apply: attach_ball_making_hole,
};

fn attach_ball_making_hole(w: &mut Work<'_>) -> Result<(), StrataError> {
    let n = w.op.n;
    let c = w.need(w.a.c, "the component c")?;
    w.expect_component_state(c, true)?;
    w.expect_in(&w.a.on, &[c], n)?;
    w.new.push(w.o.new_stratum(n, true, c, &w.a.on));
    w.o.add_global_hole(c, n, 1)
}

/// `kvC`.
const KILL_VERTEX_COMPONENT: Rule = Rule {
    requires: "stratum s is a vertex that is a component alone and bounds nothing",
    apply: kill_vertex_component,
};

fn kill_vertex_component(w: &mut Work<'_>) -> Result<(), StrataError> {
    let s = w.stratum(w.a.s, "the stratum s")?;
    w.expect_dim(s, 0)?;
    w.expect_state(s, true)?;
    w.expect_ball(s)?;
    let c = w.o.strata[s].component;
    w.kill(s)?;
    if !w.o.strata_of(c).is_empty() {
        return Err(w.refuse(format!("vertex {s} is not a component alone")));
    }
    w.expect_no_global_holes(c, "has global holes")?;
    w.o.components[c].alive = false;
    Ok(())
}

/// `ks^n k H^n`, n >= 1 (`keCh`, `kfCc`).
const DETACH_BALL_FILLING_HOLE: Rule = Rule {
    requires:
        "stratum s is a boundary-complete n-ball that bounds nothing; its component has a global n-hole, which goes",
    apply: detach_ball_filling_hole,
};

fn detach_ball_filling_hole(w: &mut Work<'_>) -> Result<(), StrataError> {
    let n = w.op.n;
    let s = w.stratum(w.a.s, "the stratum s")?;
    w.expect_dim(s, n)?;
    w.expect_state(s, true)?;
    w.expect_ball(s)?;
    let c = w.o.strata[s].component;
    w.kill(s)?;
    w.o.add_global_hole(c, n, -1)
}

/// `ms^n h^n_n H^0 H^n` (`meehCCh`, `mffcCCc`).
const ATTACH_CLOSED: Rule = Rule {
    requires: "none: the closed n-stratum (with its n-hole) is a new component with a global n-hole",
    apply: attach_closed,
};

fn attach_closed(w: &mut Work<'_>) -> Result<(), StrataError> {
    let n = w.op.n;
    let c = w.o.new_component(true);
    w.new_c.push(c);
    let s = w.o.new_stratum(n, true, c, &[]);
    w.new.push(s);
    w.o.add_hole(s, n, 1, false)?;
    w.o.add_global_hole(c, n, 1)
}

/// The inverse of `ms^n h^n_n H^0 H^n` (`keehCCh`, `kffcCCc`).
const DETACH_CLOSED: Rule = Rule {
    requires:
        "stratum s is closed (its only hole is its n-hole) and is a component alone whose only hole is a global n-hole",
    apply: detach_closed,
};

fn detach_closed(w: &mut Work<'_>) -> Result<(), StrataError> {
    let n = w.op.n;
    let s = w.stratum(w.a.s, "the stratum s")?;
    w.expect_dim(s, n)?;
    w.expect_only_hole(s, n, "is not closed with its n-hole alone")?;
    let c = w.o.strata[s].component;
    w.kill(s)?;
    if !w.o.strata_of(c).is_empty() {
        return Err(w.refuse(format!("stratum {s} is not a component alone")));
    }
    w.o.add_global_hole(c, n, -1)?;
    w.expect_no_global_holes(c, "has other global holes")?;
    w.o.components[c].alive = false;
    Ok(())
}

/// The start of `ks^n m H^{n-1}` and `ks^n h^{n-1}_n m H^0 H^{n-1}`: stratum s, a
/// boundary-complete n-stratum in a boundary-complete component, a ball or (`holed`) with
/// one (n-1)-hole and no other, is removed; returns its component.
fn detach_complete(w: &mut Work<'_>, holed: bool) -> Result<usize, StrataError> {
    let n = w.op.n;
    let s = w.stratum(w.a.s, "the stratum s")?;
    w.expect_dim(s, n)?;
    w.expect_state(s, true)?;
    if holed {
        w.expect_only_hole(s, n.wrapping_sub(1), "does not have one (n-1)-hole and no other")?;
    } else {
        w.expect_ball(s)?;
    }
    let c = w.o.strata[s].component;
    w.expect_component_state(c, true)?;
    w.kill(s)?;
    Ok(c)
}

/// `kemC`: `ks^n m H^{n-1}` for n = 1, whose global 0-hole is a new component.
const DETACH_EDGE_SPLITTING: Rule = Rule {
    requires: "stratum s is a boundary-complete edge without holes that bounds nothing; the strata `moved` of its component (not empty, not all) form the new component and take the global holes `holes`; no frontier joins them to the others",
    apply: detach_edge_splitting,
};

fn detach_edge_splitting(w: &mut Work<'_>) -> Result<(), StrataError> {
    let c = detach_complete(w, false)?;
    let nc = w.split_component(c, &w.a.moved, &w.a.holes, true)?;
    w.new_c.push(nc);
    Ok(())
}

/// `ks^n m H^{n-1}`, n >= 2 (`kfmCh`, `ksmCc`).
const DETACH_BALL_MAKING_HOLE: Rule = Rule {
    requires: "stratum s is a boundary-complete n-ball that bounds nothing; its component gets a global (n-1)-hole",
    apply: detach_ball_making_hole,
};

fn detach_ball_making_hole(w: &mut Work<'_>) -> Result<(), StrataError> {
    let c = detach_complete(w, false)?;
    w.o.add_global_hole(c, w.op.n - 1, 1)
}

/// `ks^n h^{n-1}_n m H^0 H^{n-1}` (`kffhmCCh`, `ksscmCCc`).
const DETACH_HOLED: Rule = Rule {
    requires: "stratum s is boundary-complete, its only hole an (n-1)-hole, and bounds nothing; the strata `moved` form the new component, which takes the holes `holes` and the new global (n-1)-hole; no frontier joins them to the others",
    apply: detach_holed,
};

fn detach_holed(w: &mut Work<'_>) -> Result<(), StrataError> {
    let c = detach_complete(w, true)?;
    let nc = w.split_component(c, &w.a.moved, &w.a.holes, true)?;
    w.new_c.push(nc);
    w.o.add_global_hole(nc, w.op.n - 1, 1)
}

/// The inverses of `kemC` and of `ks^n h^{n-1}_n m H^0 H^{n-1}`: a new n-stratum,
/// boundary-complete, attached to `on` in the distinct boundary-complete components c and c2,
/// joins them; with `holed` it has an (n-1)-hole and c2 loses a global one.
fn attach_joining(w: &mut Work<'_>, holed: bool) -> Result<(), StrataError> {
    let n = w.op.n;
    let c = w.need(w.a.c, "the component c")?;
    w.expect_component_state(c, true)?;
    let c2 = w.need(w.a.c2, "the second component c2")?;
    w.expect_component_state(c2, true)?;
    if c == c2 {
        return Err(w.refuse("c and c2 are the same component"));
    }
    w.expect_in(&w.a.on, &[c, c2], n)?;
    for x in [c, c2] {
        if !w.a.on.iter().any(|&b| w.o.strata[b].component == x) {
            return Err(w.refuse(format!("the new stratum does not meet component {x}")));
        }
    }
    let s = w.o.new_stratum(n, true, c, &w.a.on);
    w.new.push(s);
    if holed {
        w.o.add_hole(s, n - 1, 1, false)?;
        w.o.add_global_hole(c2, n - 1, -1)?;
    }
    w.o.absorb(c, c2);
    Ok(())
}

/// `mekC`.
const ATTACH_EDGE_JOINING: Rule = Rule {
    requires: "components c and c2 are distinct and boundary-complete; the new edge is attached to `on`, which meets both; c2 joins c",
    apply: |w| attach_joining(w, false),
};

/// `ms^n k H^{n-1}`, n >= 2 (`mfkCh`, `mskCc`).
const ATTACH_BALL_FILLING_HOLE: Rule = Rule {
    requires: "component c is boundary-complete with a global (n-1)-hole; the new n-ball is attached to `on` in c; the hole goes",
    apply: attach_ball_filling_hole,
};

fn attach_ball_filling_hole(w: &mut Work<'_>) -> Result<(), StrataError> {
    let n = w.op.n;
    let c = w.need(w.a.c, "the component c")?;
    w.expect_component_state(c, true)?;
    w.expect_in(&w.a.on, &[c], n)?;
    w.new.push(w.o.new_stratum(n, true, c, &w.a.on));
    w.o.add_global_hole(c, n - 1, -1)
}

/// `ms^n h^{n-1}_n k H^0 H^{n-1}` (`mffhkCCh`, `mssckCCc`).
const ATTACH_HOLED: Rule = Rule {
    requires: "components c and c2 are distinct and boundary-complete, c2 has a global (n-1)-hole; the new n-stratum with an (n-1)-hole is attached to `on`, which meets both; c2 joins c and loses the hole",
    apply: |w| attach_joining(w, true),
};

// ---------- stratum subdividers and coalescers (EO Fig. 5–7) ----------

/// `ms^{n-1} s^n` (`mve`, `mef`, `mfs` and their `∞` forms).
const SUBDIVIDE: Rule = Rule {
    requires: "stratum s is an n-stratum, boundary-complete (or incomplete for the ∞ form); the new (n-1)-ball is bounded by the strata of `on` below it, which bound both parts; the second part takes the frontier strata `moved` and the complete holes `holes`; parts of a complete stratum are complete, of an incomplete one at least one is incomplete (`parts_complete`; a complete part joins the complete component of its frontier)",
    apply: subdivide,
};

fn subdivide(w: &mut Work<'_>) -> Result<(), StrataError> {
    let (n, a) = (w.op.n, w.a);
    let s = w.stratum(a.s, "the stratum s")?;
    w.expect_dim(s, n)?;
    w.expect_state(s, !w.op.open)?;
    let st = w.o.strata[s].clone();
    let (pa, pb) =
        if st.complete { (true, true) } else { a.parts_complete.unwrap_or((n == 1 && !st.frontier.is_empty(), false)) };
    let cut_complete = if n == 1 { true } else { a.cut_complete.unwrap_or(true) };
    if st.complete && a.parts_complete.is_some_and(|p| p != (true, true)) {
        return Err(w.refuse("the parts of a boundary-complete stratum are boundary-complete"));
    }
    if st.complete && !cut_complete {
        return Err(w.refuse("a boundary-complete stratum has no boundary-incomplete cut"));
    }
    if !st.complete && pa && pb {
        return Err(w.refuse("a boundary-incomplete stratum keeps a boundary-incomplete part"));
    }
    if !cut_complete && (pa || pb) {
        return Err(w.refuse("the parts along a boundary-incomplete cut are boundary-incomplete"));
    }
    w.expect_frontier_of(&a.on, s)?;
    w.expect_frontier_of(&a.moved, s)?;
    let o = &mut *w.o;
    // the strata of `on` bound both parts, and the cut where they are lower
    let cut_on: Vec<usize> = a.on.iter().copied().filter(|&x| o.strata[x].dim + 1 < n).collect();
    let cut = o.new_stratum(n - 1, cut_complete, st.component, &cut_on);
    let mut fb = vec![cut];
    fb.extend(a.on.iter().copied());
    fb.extend(a.moved.iter().copied());
    let b = o.new_stratum(n, pb, st.component, &fb);
    w.new.extend([cut, b]);
    let keep: Vec<usize> = st.frontier.iter().copied().filter(|x| !a.moved.contains(x) || a.on.contains(x)).collect();
    o.strata[s].frontier = keep;
    o.strata[s].frontier.push(cut);
    o.strata[s].complete = pa;
    // a boundary-complete part of a boundary-incomplete stratum joins the complete part of
    // the object where its frontier lies (mve∞ on an edge with one end: the part from that
    // end to the new vertex), with the cut
    if pa && !o.components[st.component].complete {
        let home = o.strata[s].frontier.iter().map(|&x| o.strata[x].component).find(|&c| o.components[c].complete);
        if let Some(h) = home {
            o.strata[s].component = h;
            o.strata[cut].component = h;
        }
    }
    // the holes that go with the second part are boundary-complete ones; the
    // boundary-incomplete holes stay with the first part
    for &(k, h) in &a.holes {
        o.add_hole(s, k, -h, false)?;
        o.add_hole(b, k, h, false)?;
    }
    o.add_where_bounded(s, &[cut, b]);
    Ok(())
}

/// `ks^{n-1} s^n` (`kve`, `kef`, `kfs` and their `∞` forms).
const COALESCE: Rule = Rule {
    requires: "s and u are distinct n-strata of one component (or of several, as in a G-map read by `from_map`: the merged stratum stays in s's component, or goes to u's when it is boundary-incomplete and s's is not; a component left empty goes), t an (n-1)-ball in both frontiers that bounds no other stratum beside those above s or u; all complete (at least one incomplete for the ∞ form); u and t join s",
    apply: coalesce,
};

fn coalesce(w: &mut Work<'_>) -> Result<(), StrataError> {
    let n = w.op.n;
    let s = w.stratum(w.a.s, "the part s")?;
    let t = w.stratum(w.a.t, "the cut t")?;
    let u = w.stratum(w.a.u, "the part u")?;
    if s == u {
        return Err(w.refuse("s and u are the same stratum"));
    }
    w.expect_dim(s, n)?;
    w.expect_dim(u, n)?;
    w.expect_dim(t, n - 1)?;
    w.expect_ball(t)?;
    let (cs, ct, cu) = (w.o.strata[s].component, w.o.strata[t].component, w.o.strata[u].component);
    w.expect_frontier_of(&[t], s)?;
    w.expect_frontier_of(&[t], u)?;
    w.expect_bounds_only(t, &[s, u])?;
    let complete = w.o.strata[s].complete && w.o.strata[u].complete && w.o.strata[t].complete;
    // the parts may lie in different components when one of them is a boundary-incomplete
    // stratum component of its own (a G-map read by `from_map`): the merged stratum goes to
    // the boundary-incomplete one, and a component left without strata goes; the theorems
    // check the rest
    let target = if !complete && w.o.components[cs].complete { cu } else { cs };
    w.o.strata[s].component = target;
    if complete == w.op.open {
        return Err(w.refuse(if w.op.open {
            "the strata are all boundary-complete (use the form without ∞)"
        } else {
            "a stratum is boundary-incomplete (use the ∞ form)"
        }));
    }
    let o = &mut *w.o;
    let ust = o.strata[u].clone();
    for k in 1..=n {
        let (h, open) = (ust.holes[k], ust.open_holes[k]);
        o.add_hole(s, k, h - open, false)?;
        o.add_hole(s, k, open, true)?;
    }
    let mut f: Vec<usize> = o.strata[s].frontier.clone();
    for x in ust.frontier {
        if !f.contains(&x) {
            f.push(x);
        }
    }
    f.retain(|&x| x != t);
    o.strata[s].frontier = f;
    o.strata[s].complete = complete;
    o.replace_in_frontiers(u, Some(s));
    o.replace_in_frontiers(t, None);
    o.strata[u].alive = false;
    o.strata[t].alive = false;
    for c in [cs, ct, cu] {
        if w.o.components[c].alive && w.o.strata_of(c).is_empty() {
            w.expect_no_global_holes(c, "would vanish with its global holes")?;
            w.o.components[c].alive = false;
        }
    }
    Ok(())
}

/// The n-stratum s is cut by a new closed (n-1)-stratum bounding a new n-ball; returns s.
fn cut_by_closed(w: &mut Work<'_>, s: usize) -> Result<usize, StrataError> {
    let n = w.op.n;
    let c = w.o.strata[s].component;
    let cut = w.o.new_stratum(n - 1, true, c, &[]);
    w.o.add_hole(cut, n - 1, 1, false)?;
    let b = w.o.new_stratum(n, true, c, &[cut]);
    w.new.extend([cut, b]);
    w.o.strata[s].frontier.push(cut);
    w.o.add_where_bounded(s, &[cut, b]);
    Ok(s)
}

/// `ms^{n-1} h^{n-1}_{n-1} s^n h^{n-1}_n` (`meehffh`, `mffcssc`).
const SUBDIVIDE_BY_CLOSED: Rule = Rule {
    requires:
        "stratum s is an n-stratum; a closed (n-1)-stratum inside it makes an (n-1)-hole in s and bounds a new n-ball",
    apply: subdivide_by_closed,
};

fn subdivide_by_closed(w: &mut Work<'_>) -> Result<(), StrataError> {
    let n = w.op.n;
    let s = w.stratum(w.a.s, "the stratum s")?;
    w.expect_dim(s, n)?;
    cut_by_closed(w, s)?;
    w.o.add_hole(s, n - 1, 1, false)
}

/// `ms^{n-1} h^{n-1}_{n-1} s^n k h^n_n` (`meehfkfc`).
const SUBDIVIDE_CLOSED_BY_CLOSED: Rule = Rule {
    requires: "stratum s is closed (it has an n-hole); a closed (n-1)-stratum cuts it into s, which loses the n-hole, and a new n-ball",
    apply: subdivide_closed_by_closed,
};

fn subdivide_closed_by_closed(w: &mut Work<'_>) -> Result<(), StrataError> {
    let n = w.op.n;
    let s = w.stratum(w.a.s, "the stratum s")?;
    w.expect_dim(s, n)?;
    if !w.o.strata[s].is_closed() {
        return Err(w.refuse(format!("stratum {s} is not closed (no {n}-hole)")));
    }
    cut_by_closed(w, s)?;
    w.o.add_hole(s, n, -1, false)
}

/// The checks common to the inverses of the subdividers by a closed stratum: the part s,
/// the closed cut t bounding only s and the boundary-complete n-ball u, which t alone
/// bounds. Returns `(s, t, u)`.
fn closed_cut(w: &Work<'_>) -> Result<(usize, usize, usize), StrataError> {
    let n = w.op.n;
    let s = w.stratum(w.a.s, "the stratum s")?;
    let t = w.stratum(w.a.t, "the closed cut t")?;
    let u = w.stratum(w.a.u, "the inner ball u")?;
    if s == u {
        return Err(w.refuse("s and u are the same stratum"));
    }
    w.expect_dim(s, n)?;
    w.expect_dim(u, n)?;
    w.expect_dim(t, n - 1)?;
    w.expect_only_hole(t, n - 1, "is not closed with its (n-1)-hole alone")?;
    w.expect_ball(u)?;
    w.expect_state(u, true)?;
    if w.o.strata[u].frontier != [t] {
        return Err(w.refuse(format!("stratum {u} is not bounded by {t} alone")));
    }
    w.expect_frontier_of(&[t], s)?;
    w.expect_bounds_only(t, &[s, u])?;
    Ok((s, t, u))
}

/// The cut t and the ball u join s.
fn remove_closed_cut(w: &mut Work<'_>, s: usize, t: usize, u: usize) {
    w.o.replace_in_frontiers(u, Some(s));
    w.o.replace_in_frontiers(t, None);
    w.o.strata[u].alive = false;
    w.o.strata[t].alive = false;
}

/// `ks^{n-1} h^{n-1}_{n-1} s^n h^{n-1}_n` (`keehffh`, `kffcssc`).
const COALESCE_CLOSED_CUT: Rule = Rule {
    requires: "u is a boundary-complete n-ball bounded by t alone, t a closed (n-1)-stratum bounding only s and u, s has a complete (n-1)-hole; t and u join s, which loses the hole",
    apply: coalesce_closed_cut,
};

fn coalesce_closed_cut(w: &mut Work<'_>) -> Result<(), StrataError> {
    let (s, t, u) = closed_cut(w)?;
    remove_closed_cut(w, s, t, u);
    w.o.add_hole(s, w.op.n - 1, -1, false)
}

/// `ks^{n-1} h^{n-1}_{n-1} s^n m h^n_n` (`keehfkfc`).
const COALESCE_INTO_CLOSED: Rule = Rule {
    requires: "u is a boundary-complete n-ball bounded by t alone, t a closed (n-1)-stratum bounding only s and u, s bounded by t alone; t and u join s, which becomes closed",
    apply: coalesce_into_closed,
};

fn coalesce_into_closed(w: &mut Work<'_>) -> Result<(), StrataError> {
    let (s, t, u) = closed_cut(w)?;
    if w.o.strata[s].frontier != [t] {
        return Err(w.refuse(format!("stratum {s} is not bounded by {t} alone")));
    }
    remove_closed_cut(w, s, t, u);
    w.o.add_hole(s, w.op.n, 1, false)
}

// ---------- local hole shapers (EO Fig. 8–9) ----------

/// The d-ball t, in the frontier of the n-stratum s (same component) and bounding nothing
/// else below s, joins s; returns s.
fn merge(w: &mut Work<'_>) -> Result<usize, StrataError> {
    let s = w.stratum(w.a.s, "the stratum s")?;
    let t = w.stratum(w.a.t, "the merged stratum t")?;
    w.expect_dim(s, w.op.n)?;
    w.expect_dim(t, w.op.d)?;
    w.expect_ball(t)?;
    w.expect_state(t, !w.op.open)?;
    if w.o.strata[t].component != w.o.strata[s].component {
        return Err(w.refuse(format!("strata {t} and {s} are not in one component")));
    }
    w.expect_frontier_of(&[t], s)?;
    w.expect_bounds_only(t, &[s])?;
    let tf = w.o.strata[t].frontier.clone();
    w.add_to_frontier(s, &tf);
    w.o.replace_in_frontiers(t, None);
    w.o.strata[t].alive = false;
    Ok(s)
}

/// A new d-ball attached to `on` in the frontier of the n-stratum s (boundary-incomplete,
/// as s, in the `∞` form) is put in s's frontier; returns s.
fn unmerge(w: &mut Work<'_>) -> Result<usize, StrataError> {
    let s = w.stratum(w.a.s, "the stratum s")?;
    w.expect_dim(s, w.op.n)?;
    if w.op.open {
        w.expect_state(s, false)?;
    }
    w.expect_frontier_of(&w.a.on, s)?;
    let c = w.o.strata[s].component;
    let t = w.o.new_stratum(w.op.d, !w.op.open, c, &w.a.on);
    w.new.push(t);
    w.o.strata[s].frontier.push(t);
    w.o.add_where_bounded(s, &[t]);
    Ok(s)
}

/// `ks^d h^{n-1-d}_n` (`kvfh`, `kvsc`, `kesh`, `ke∞s∞h`).
const MERGE_FILLING: Rule = Rule {
    requires: "t is a d-ball in the frontier of the n-stratum s (same component) bounding nothing else below s; s has an (n-1-d)-hole of t's state (boundary-incomplete for the ∞ form); t joins s, which loses the hole",
    apply: merge_filling,
};

fn merge_filling(w: &mut Work<'_>) -> Result<(), StrataError> {
    let s = merge(w)?;
    w.o.add_hole(s, w.op.n - 1 - w.op.d, -1, w.op.open)
}

/// `ms^d k h^{n-1-d}_n` (`mvfh`, `mvsc`, `mesh`, `me∞s∞h`).
const UNMERGE_MAKING_HOLE: Rule = Rule {
    requires: "stratum s is an n-stratum; a new d-ball (boundary-incomplete for the ∞ form, then s is too) attached to `on` in s's frontier makes an (n-1-d)-hole in s",
    apply: unmerge_making_hole,
};

fn unmerge_making_hole(w: &mut Work<'_>) -> Result<(), StrataError> {
    let s = unmerge(w)?;
    w.o.add_hole(s, w.op.n - 1 - w.op.d, 1, w.op.open)
}

/// `ks^d m h^{n-d}_n` (`kvmeh`, `kvmfc`, `kemfh`, `kemsc`, `kfmsh` and `∞` forms).
const MERGE_MAKING_HOLE: Rule = Rule {
    requires: "t is a d-ball in the frontier of the n-stratum s (same component) bounding nothing else below s; t joins s, which gets an (n-d)-hole (boundary-incomplete for the ∞ form)",
    apply: merge_making_hole,
};

fn merge_making_hole(w: &mut Work<'_>) -> Result<(), StrataError> {
    let s = merge(w)?;
    w.o.add_hole(s, w.op.n - w.op.d, 1, w.op.open)
}

/// `ms^d k h^{n-d}_n` (`mvkeh`, `mvkfc`, `mekfh`, `meksc`, `mfksh` and `∞` forms).
const UNMERGE_FILLING: Rule = Rule {
    requires: "stratum s has an (n-d)-hole (boundary-incomplete for the ∞ form); a new d-ball attached to `on` in s's frontier takes it away",
    apply: unmerge_filling,
};

fn unmerge_filling(w: &mut Work<'_>) -> Result<(), StrataError> {
    let s = unmerge(w)?;
    w.o.add_hole(s, w.op.n - w.op.d, -1, w.op.open)
}

// ---------- stratum attachers and unfilled hole shapers (EO Fig. 10–11) ----------

/// `ms^n_∞ S^n_∞` (`me∞E∞`, `mf∞F∞`, `ms∞S∞`).
const ATTACH_OPEN: Rule = Rule {
    requires: "none: the new boundary-incomplete n-ball, attached to `on`, is a new boundary-incomplete component",
    apply: attach_open,
};

fn attach_open(w: &mut Work<'_>) -> Result<(), StrataError> {
    let n = w.op.n;
    w.expect_fillers(&w.a.on, n)?;
    let c = w.o.new_component(false);
    w.new_c.push(c);
    w.new.push(w.o.new_stratum(n, false, c, &w.a.on));
    Ok(())
}

/// `ks^n_∞ S^n_∞` (`ke∞E∞`, `kf∞F∞`, `ks∞S∞`).
const DETACH_OPEN: Rule = Rule {
    requires: "stratum s is a boundary-incomplete n-ball bounding nothing, a component alone and without holes",
    apply: detach_open,
};

fn detach_open(w: &mut Work<'_>) -> Result<(), StrataError> {
    let s = w.stratum(w.a.s, "the stratum s")?;
    w.expect_dim(s, w.op.n)?;
    w.expect_state(s, false)?;
    w.expect_ball(s)?;
    let c = w.o.strata[s].component;
    w.kill(s)?;
    if !w.o.strata_of(c).is_empty() || w.o.components[c].holes.iter().any(|&h| h != 0) {
        return Err(w.refuse(format!("stratum {s} is not a component alone without holes")));
    }
    w.o.components[c].alive = false;
    Ok(())
}

/// A boundary-incomplete d-hole of the boundary-incomplete n-stratum s and its
/// boundary-incomplete component changes by `delta`.
fn open_hole(w: &mut Work<'_>, delta: i64) -> Result<(), StrataError> {
    let s = w.stratum(w.a.s, "the stratum s")?;
    w.expect_dim(s, w.op.n)?;
    w.expect_state(s, false)?;
    let c = w.o.strata[s].component;
    w.expect_component_state(c, false)?;
    w.o.add_hole(s, w.op.d, delta, true)?;
    w.o.add_global_hole(c, w.op.d, delta)
}

/// `mh^d_∞n H^d_∞n` (`mf∞hF∞h`, `ms∞hS∞h`, `ms∞cS∞c`).
const MAKE_OPEN_HOLE: Rule = Rule {
    requires: "stratum s is a boundary-incomplete n-stratum in a boundary-incomplete component; both get a boundary-incomplete d-hole, d <= n-1",
    apply: |w| open_hole(w, 1),
};

/// `kh^d_∞n H^d_∞n` (`kf∞hF∞h`, `ks∞hS∞h`, `ks∞cS∞c`).
const KILL_OPEN_HOLE: Rule = Rule {
    requires: "stratum s has a boundary-incomplete d-hole and its component a global d-hole; both go",
    apply: |w| open_hole(w, -1),
};

// ---------- local stratum and hole compacters (EO Fig. 12–13) ----------

/// `ks^n_∞ m s^n` (`ke∞me`, `kf∞mf`, `ks∞ms`).
const COMPACT_STRATUM: Rule = Rule {
    requires: "stratum s is boundary-incomplete without boundary-incomplete holes; the fillers `on` join its frontier, which must then hold something unless s is closed",
    apply: compact_stratum,
};

fn compact_stratum(w: &mut Work<'_>) -> Result<(), StrataError> {
    let s = w.stratum(w.a.s, "the stratum s")?;
    w.expect_dim(s, w.op.n)?;
    w.expect_state(s, false)?;
    if w.o.strata[s].open_holes.iter().any(|&o| o > 0) {
        return Err(w.refuse(format!("stratum {s} has boundary-incomplete holes (compact them first)")));
    }
    w.expect_fillers(&w.a.on, w.op.n)?;
    w.add_to_frontier(s, &w.a.on);
    w.o.strata[s].complete = true;
    Ok(())
}

/// `ms^n_∞ k s^n` (`me∞ke`, `mf∞kf`, `ms∞ks`).
const DECOMPACT_STRATUM: Rule = Rule {
    requires: "stratum s is boundary-complete in a boundary-incomplete component; it drops `moved` from its frontier",
    apply: decompact_stratum,
};

fn decompact_stratum(w: &mut Work<'_>) -> Result<(), StrataError> {
    let s = w.stratum(w.a.s, "the stratum s")?;
    w.expect_dim(s, w.op.n)?;
    w.expect_state(s, true)?;
    w.expect_frontier_of(&w.a.moved, s)?;
    w.o.strata[s].frontier.retain(|x| !w.a.moved.contains(x));
    w.o.strata[s].complete = false;
    Ok(())
}

/// The boundary-incomplete n-stratum s acted on by a hole compacter.
fn open_stratum(w: &Work<'_>) -> Result<usize, StrataError> {
    let s = w.stratum(w.a.s, "the stratum s")?;
    w.expect_dim(s, w.op.n)?;
    w.expect_state(s, false)?;
    Ok(s)
}

/// `kh^d_∞n m h^d_n` (`kf∞hmfh`, `ks∞hmsh`, `ks∞cmsc`).
const COMPACT_HOLE: Rule = Rule {
    requires: "stratum s has a boundary-incomplete d-hole; the fillers `on` join its frontier; the hole becomes boundary-complete",
    apply: compact_hole,
};

fn compact_hole(w: &mut Work<'_>) -> Result<(), StrataError> {
    let s = open_stratum(w)?;
    w.expect_fillers(&w.a.on, w.op.n)?;
    w.o.add_hole(s, w.op.d, -1, true)?;
    w.o.add_hole(s, w.op.d, 1, false)?;
    w.add_to_frontier(s, &w.a.on);
    Ok(())
}

/// `mh^d_∞n k h^d_n` (`mf∞hkfh`, `ms∞hksh`, `ms∞cksc`).
const DECOMPACT_HOLE: Rule = Rule {
    requires: "stratum s is boundary-incomplete with a boundary-complete d-hole, which becomes boundary-incomplete; s drops `moved` from its frontier",
    apply: decompact_hole,
};

fn decompact_hole(w: &mut Work<'_>) -> Result<(), StrataError> {
    let s = open_stratum(w)?;
    w.expect_frontier_of(&w.a.moved, s)?;
    w.o.add_hole(s, w.op.d, -1, false)?;
    w.o.add_hole(s, w.op.d, 1, true)?;
    w.o.strata[s].frontier.retain(|x| !w.a.moved.contains(x));
    Ok(())
}

// ---------- global stratum compacters (EO Fig. 14–16) ----------

/// The boundary-incomplete n-component c, without holes and with every stratum
/// boundary-complete, joins the boundary-complete component c2; returns c2.
fn compact_component(w: &mut Work<'_>) -> Result<usize, StrataError> {
    let n = w.op.n;
    let c = w.need(w.a.c, "the incomplete component c")?;
    let c2 = w.need(w.a.c2, "the complete component c2")?;
    w.expect_component_state(c, false)?;
    w.expect_component_state(c2, true)?;
    w.expect_component_dim(c, n)?;
    w.expect_no_global_holes(c, "has global holes")?;
    if let Some(s) = w.o.strata_of(c).into_iter().find(|&s| !w.o.strata[s].complete) {
        return Err(w.refuse(format!("stratum {s} of component {c} is still boundary-incomplete")));
    }
    w.o.absorb(c2, c);
    Ok(c2)
}

/// `kE∞C`.
const COMPACT_EDGE_COMPONENT: Rule = Rule {
    requires: "c is a boundary-incomplete edge component without holes whose strata are all boundary-complete; c2 and c3 are distinct boundary-complete components; c and c3 join c2",
    apply: compact_edge_component,
};

fn compact_edge_component(w: &mut Work<'_>) -> Result<(), StrataError> {
    let c2 = compact_component(w)?;
    let c3 = w.need(w.a.c3, "the component c3 of the compacting vertex")?;
    w.expect_component_state(c3, true)?;
    if c3 == c2 {
        return Err(w.refuse("c2 and c3 are the same component (that is kE∞mCh)"));
    }
    w.o.absorb(c2, c3);
    Ok(())
}

/// `kC^n_∞ H^{n-1}`, n >= 2 (`kF∞Ch`, `kS∞Cc`).
const COMPACT_COMPONENT_FILLING: Rule = Rule {
    requires: "c is a boundary-incomplete n-component without holes whose strata are all boundary-complete; c2 is boundary-complete with a global (n-1)-hole; c joins c2, which loses the hole",
    apply: compact_component_filling,
};

fn compact_component_filling(w: &mut Work<'_>) -> Result<(), StrataError> {
    let c2 = compact_component(w)?;
    w.o.add_global_hole(c2, w.op.n - 1, -1)
}

/// `kC^n_∞ m H^n` (`kE∞mCh`, `kF∞mCc`).
const COMPACT_COMPONENT_MAKING_HOLE: Rule = Rule {
    requires: "c is a boundary-incomplete n-component without holes whose strata are all boundary-complete; c2 is boundary-complete; c joins c2, which gets a global n-hole",
    apply: compact_component_making_hole,
};

fn compact_component_making_hole(w: &mut Work<'_>) -> Result<(), StrataError> {
    let c2 = compact_component(w)?;
    w.o.add_global_hole(c2, w.op.n, 1)
}

/// The boundary-complete component c the inverse global compacters split.
fn complete_component(w: &Work<'_>) -> Result<usize, StrataError> {
    let c = w.need(w.a.c, "the complete component c")?;
    w.expect_component_state(c, true)?;
    Ok(c)
}

/// The strata `moved` leave c for a new boundary-incomplete n-component.
fn split_off_incomplete(w: &mut Work<'_>, c: usize) -> Result<(), StrataError> {
    let n = w.op.n;
    let ci = w.split_component(c, &w.a.moved, &[], false)?;
    w.o.components[ci].complete = false;
    w.new_c.push(ci);
    if w.o.component_dim(ci) != n {
        return Err(w.refuse(format!("the new boundary-incomplete component is not {n}-dimensional")));
    }
    Ok(())
}

/// `mE∞C`.
const DECOMPACT_EDGE_COMPONENT: Rule = Rule {
    requires: "c is boundary-complete; the strata `moved` form a new boundary-incomplete component, the strata `moved2` a new boundary-complete one",
    apply: decompact_edge_component,
};

fn decompact_edge_component(w: &mut Work<'_>) -> Result<(), StrataError> {
    let c = complete_component(w)?;
    split_off_incomplete(w, c)?;
    let c3 = w.split_component(c, &w.a.moved2, &[], false)?;
    w.new_c.push(c3);
    Ok(())
}

/// `mC^n_∞ k H^{n-1}`, n >= 2 (`mF∞Ch`, `mS∞Cc`).
const DECOMPACT_COMPONENT_MAKING_HOLE: Rule = Rule {
    requires: "c is boundary-complete; the strata `moved` form a new boundary-incomplete component; c gets a global (n-1)-hole",
    apply: decompact_component_making_hole,
};

fn decompact_component_making_hole(w: &mut Work<'_>) -> Result<(), StrataError> {
    let c = complete_component(w)?;
    // n = 0 has no (n-1)-hole
    if w.op.n >= 2 {
        w.o.add_global_hole(c, w.op.n - 1, 1)?;
    }
    split_off_incomplete(w, c)
}

/// `mC^n_∞ k H^n` (`mE∞kCh`, `mF∞kCc`).
const DECOMPACT_COMPONENT_FILLING: Rule = Rule {
    requires: "c is boundary-complete with a global n-hole; the strata `moved` form a new boundary-incomplete component; the hole goes",
    apply: decompact_component_filling,
};

fn decompact_component_filling(w: &mut Work<'_>) -> Result<(), StrataError> {
    let c = complete_component(w)?;
    w.o.add_global_hole(c, w.op.n, -1)?;
    split_off_incomplete(w, c)
}

/// `kH^{n-1}_∞n C` (`kF∞hC`, `kS∞cC`).
const FILL_COMPONENT_HOLE: Rule = Rule {
    requires: "c is a boundary-incomplete n-component with a global (n-1)-hole; c2 is a boundary-complete component without holes; c2 joins c, which loses the hole",
    apply: fill_component_hole,
};

fn fill_component_hole(w: &mut Work<'_>) -> Result<(), StrataError> {
    let n = w.op.n;
    let c = w.need(w.a.c, "the incomplete component c")?;
    let c2 = w.need(w.a.c2, "the filler's component c2")?;
    w.expect_component_state(c, false)?;
    w.expect_component_state(c2, true)?;
    w.expect_component_dim(c, n)?;
    w.expect_no_global_holes(c2, "has global holes")?;
    w.o.add_global_hole(c, n - 1, -1)?;
    w.o.absorb(c, c2);
    Ok(())
}

/// `mH^{n-1}_∞n C` (`mF∞hC`, `mS∞cC`).
const SPLIT_COMPONENT_MAKING_HOLE: Rule = Rule {
    requires: "c is a boundary-incomplete n-component; the strata `moved` form a new boundary-complete component; c gets a global (n-1)-hole",
    apply: split_component_making_hole,
};

fn split_component_making_hole(w: &mut Work<'_>) -> Result<(), StrataError> {
    let n = w.op.n;
    let c = w.need(w.a.c, "the incomplete component c")?;
    w.expect_component_state(c, false)?;
    w.expect_component_dim(c, n)?;
    w.o.add_global_hole(c, n - 1, 1)?;
    let nc = w.split_component(c, &w.a.moved, &[], false)?;
    w.o.components[nc].complete = true;
    w.new_c.push(nc);
    Ok(())
}

mod work;
