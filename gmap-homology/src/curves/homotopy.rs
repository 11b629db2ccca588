//! Homotopy tests of paths on a surface: [`Homotopy`] (the preprocessing of a 2-map) and
//! [`SurfacePath`] (a checked sequence of darts).
//!
//! The surface is reduced once to a presentation of its fundamental group: a spanning tree
//! `T` of the vertices, a spanning tree `C` of the faces across the other edges (rooted at
//! the outside when there is boundary), and the edges left are the generators. Each edge
//! gets its word (empty on `T`, itself for a generator, and for an edge of `C` the rest of
//! its face, found from the leaves of `C` up). A path's word is the product of its edges'
//! words. Then:
//!
//! * with boundary (orientable or not), the group is free: a path is contractible when its
//!   word reduces to nothing, two closed paths are freely homotopic when their cyclic
//!   reductions are rotations of each other;
//! * a closed orientable surface is one polygon of `4g` sides: the sphere (`g = 0`, every
//!   path contractible), the torus (`Z²`: the words' exponent sums), or `g ≥ 2`, where
//!   Dehn's algorithm ([`crate::curves::words::Dehn`]) decides contractibility;
//! * a closed non-orientable surface is read on its orientation double cover (built as a
//!   G-map of twice the darts): a path lifts to a closed path exactly when it keeps the
//!   orientation, and is contractible exactly when it keeps it and its lift is.
//!
//! Free homotopy on closed surfaces of genus ≥ 2 (orientable, or non-orientable of genus
//! ≥ 3) is decided when the cyclically Dehn-reduced words are rotations of each other
//! (homotopic) or when the classes in `H_1` differ or exactly one is contractible (not
//! homotopic); otherwise the test is refused ([`CurveError::Undecided`]), never guessed.
//! `is_homotopic_to_simple_cycle` is answered on the sphere, the torus and for contractible
//! paths; otherwise refused.
//!
//! Costs: the preprocessing O(N) darts plus the words of the edges of `C` (each at most the
//! sum of its subtree's generator sides); a path of L steps costs O(L w) letters for edge
//! words of at most w letters, then O(L) on free groups and the torus, O(L m²) for Dehn's
//! algorithm on a relator of m = 4g letters, O(L² m) for the cyclic reduction.

use std::collections::VecDeque;

use gmap_core::{Dart, DenseMap, Partition};

use crate::curves::error::CurveError;
use crate::curves::surface::check_surface;
use crate::curves::words::{self, Dehn, Letter};

/// A path on a 2-map: for each step, a dart of its edge at the vertex it leaves (CGAL's
/// paths of darts); step `k` ends at the vertex of `alpha_0` of its dart, where step
/// `k + 1` starts.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SurfacePath {
    /// the darts of the steps
    pub darts: Vec<Dart>,
    /// the vertex it starts at (`None` for the empty path)
    pub start: Option<u32>,
    /// the vertex it ends at
    pub end: Option<u32>,
}

/// What the fundamental group of the (working) surface is.
#[derive(Clone, Debug)]
enum Group {
    /// trivial: the sphere, the disc, the projective plane's cover
    Trivial,
    /// free on this many generators (with boundary)
    Free,
    /// `Z²` (the torus)
    Torus,
    /// a closed surface of genus ≥ 2 with its relator
    Hyperbolic(Dehn),
}

/// The kind of surface, for reports.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct SurfaceKind {
    /// whether the surface is orientable
    pub orientable: bool,
    /// whether it has boundary
    pub boundary: bool,
    /// its Euler characteristic
    pub euler: i64,
    /// the number of generators of its fundamental group as computed (of the orientation
    /// double cover for closed non-orientable surfaces)
    pub generators: usize,
}

/// The preprocessing of a connected 2-map for homotopy tests.
#[derive(Clone, Debug)]
pub struct Homotopy {
    /// the map's vertices
    vertices: Partition,
    /// `alpha_0` of the map, dart by dart
    alpha0: Vec<u32>,
    /// the darts of the map
    n: usize,
    /// the working surface's vertex of each of its darts (the map, or its double cover:
    /// darts `d` and `d + n`)
    wvertex: Vec<u32>,
    /// `alpha_0` of the working surface
    walpha0: Vec<u32>,
    /// whether the working surface is the double cover
    cover: bool,
    /// each working dart's word, for the step leaving its vertex along its edge
    dart_word: Vec<Vec<Letter>>,
    group: Group,
    kind: SurfaceKind,
}

impl Homotopy {
    /// The preprocessing of `map`: a connected 2-map without `alpha_0`- or `alpha_1`-free
    /// darts (refused otherwise, naming the dart or the number of components).
    pub fn new(map: &DenseMap) -> Result<Self, CurveError> {
        check_surface(map)?;
        if map.dart_count() == 0 {
            return Err(CurveError::Disconnected { components: 0 });
        }
        let components = map.component_count();
        if components != 1 {
            return Err(CurveError::Disconnected { components });
        }
        let boundary = map.darts().any(|d| map.is_free(d, 2));
        let orientable = map.is_orientable();
        let euler = map.euler_characteristic();
        let cover = !boundary && !orientable;
        let work = if cover { double_cover(map)? } else { map.clone() };
        let pres = Presentation::of(&work, boundary)?;
        let n = map.dart_count();
        let gens = pres.generators;
        let group = if gens == 0 {
            Group::Trivial
        } else if boundary {
            Group::Free
        } else if gens == 2 {
            Group::Torus
        } else {
            Group::Hyperbolic(Dehn::new(pres.relator.clone()).map_err(|reason| CurveError::Presentation { reason })?)
        };
        let expected = if boundary {
            1 - euler
        } else if cover {
            2 - 2 * euler
        } else {
            2 - euler
        };
        if gens as i64 != expected {
            return Err(CurveError::Presentation {
                reason: format!("{gens} generators where the Euler characteristic {euler} gives {expected}"),
            });
        }
        Ok(Homotopy {
            vertices: map.cells(0),
            alpha0: (0..n).map(|d| map.alpha(Dart::new(d as u32), 0).get()).collect(),
            n,
            wvertex: pres.vertex,
            walpha0: pres.alpha0,
            cover,
            dart_word: pres.dart_word,
            group,
            kind: SurfaceKind { orientable, boundary, euler, generators: gens },
        })
    }

    /// What the surface is.
    pub fn kind(&self) -> SurfaceKind {
        self.kind
    }

    /// Checks that `darts` is a path: every dart exists and each step starts where the
    /// one before ends. Refuses naming the first step that breaks.
    pub fn path(&self, darts: &[Dart]) -> Result<SurfacePath, CurveError> {
        for (k, d) in darts.iter().enumerate() {
            if d.index() >= self.n {
                return Err(CurveError::NotAPath { step: k, dart: d.get(), reason: "is not a dart of the map" });
            }
            if k > 0 {
                let prev = self.alpha0[darts[k - 1].index()] as usize;
                if self.vertices.of[prev] != self.vertices.of[d.index()] {
                    return Err(CurveError::NotAPath {
                        step: k,
                        dart: d.get(),
                        reason: "does not start at the vertex where the step before ends",
                    });
                }
            }
        }
        let start = darts.first().map(|d| self.vertices.of[d.index()]);
        let end = darts.last().map(|d| self.vertices.of[self.alpha0[d.index()] as usize]);
        Ok(SurfacePath { darts: darts.to_vec(), start, end })
    }

    /// The path through the vertices `vertices` (numbered as the map's vertex partition
    /// numbers them), each step along the only edge joining two vertices that follow each
    /// other; refused (naming the step) when no edge or several edges join them.
    pub fn path_through_vertices(&self, map: &DenseMap, vertices: &[u32]) -> Result<SurfacePath, CurveError> {
        let nv = self.vertices.len();
        let mut darts = Vec::with_capacity(vertices.len().saturating_sub(1));
        for (k, w) in vertices.windows(2).enumerate() {
            for &v in w {
                if v as usize >= nv {
                    return Err(CurveError::NoSuchVertex { vertex: v, vertices: nv });
                }
            }
            let rep = self.vertices.reps[w[0] as usize];
            let mut found: Vec<(u32, Dart)> = Vec::new();
            for x in map.cell_darts(rep, 0) {
                if self.vertices.of[self.alpha0[x.index()] as usize] == w[1] {
                    let edge = map.cell_darts(x, 1).into_iter().min().unwrap_or(x).get();
                    if !found.iter().any(|&(e, _)| e == edge) {
                        found.push((edge, x));
                    }
                }
            }
            match found.as_slice() {
                [(_, x)] => darts.push(*x),
                _ => return Err(CurveError::NoEdge { step: k, from: w[0], to: w[1], edges: found.len() }),
            }
        }
        self.path(&darts)
    }

    /// The lift of `p` to the working surface from sheet `sheet`: its working darts and
    /// whether it ends on the vertex over its end in the same sheet as it starts (always on
    /// a map read directly).
    fn lift(&self, p: &SurfacePath, sheet: usize) -> Result<(Vec<u32>, bool), CurveError> {
        if !self.cover {
            return Ok((p.darts.iter().map(|d| d.get()).collect(), true));
        }
        let n = self.n as u32;
        let mut out = Vec::with_capacity(p.darts.len());
        let mut at: Option<u32> = None;
        for (k, d) in p.darts.iter().enumerate() {
            let c = match at {
                None => d.get() + if sheet == 0 { 0 } else { n },
                Some(v) => {
                    if self.wvertex[d.index()] == v {
                        d.get()
                    } else if self.wvertex[d.index() + self.n] == v {
                        d.get() + n
                    } else {
                        return Err(CurveError::Presentation { reason: format!("step {k} does not lift") });
                    }
                }
            };
            at = Some(self.wvertex[self.walpha0[c as usize] as usize]);
            out.push(c);
        }
        let same = match (out.first(), at) {
            (Some(&c0), Some(v)) => v == self.wvertex[c0 as usize],
            _ => true,
        };
        Ok((out, same))
    }

    /// The freely reduced word of working darts.
    fn word(&self, darts: &[u32]) -> Vec<Letter> {
        let mut w = Vec::with_capacity(darts.len());
        for &c in darts {
            words::push_reduced(&mut w, self.dart_word[c as usize].iter().copied());
        }
        w
    }

    /// Whether the freely reduced word `w` is 1 in the group.
    fn trivial(&self, w: &[Letter]) -> bool {
        match &self.group {
            Group::Trivial => true,
            Group::Free => w.is_empty(),
            Group::Torus => words::exponent_sums(w, 2).iter().all(|&s| s == 0),
            Group::Hyperbolic(d) => d.reduce(w).is_empty(),
        }
    }

    fn closed(&self, p: &SurfacePath) -> Result<(), CurveError> {
        match (p.start, p.end) {
            (Some(s), Some(e)) if s != e => Err(CurveError::NotClosed {
                start: self.vertices.reps[s as usize].get(),
                end: self.vertices.reps[e as usize].get(),
            }),
            _ => Ok(()),
        }
    }

    /// Whether the closed path `p` is contractible. Refuses a path that is not closed.
    pub fn is_contractible(&self, p: &SurfacePath) -> Result<bool, CurveError> {
        self.closed(p)?;
        let (lift, same) = self.lift(p, 0)?;
        Ok(same && self.trivial(&self.word(&lift)))
    }

    /// Whether `p` and `q`, with the same start and the same end, are homotopic with their
    /// ends fixed. Refuses paths whose ends differ.
    pub fn are_homotopic_with_fixed_endpoints(&self, p: &SurfacePath, q: &SurfacePath) -> Result<bool, CurveError> {
        let ends = |x: &SurfacePath| (x.start, x.end);
        if ends(p) != ends(q) && !(p.darts.is_empty() || q.darts.is_empty()) {
            return Err(self.ends_differ(p, q));
        }
        if p.darts.is_empty() || q.darts.is_empty() {
            // an empty path against a closed one: whether the closed one is contractible
            let other = if p.darts.is_empty() { q } else { p };
            return self.is_contractible(other);
        }
        let (lp, _) = self.lift(p, 0)?;
        let (lq, _) = self.lift(q, 0)?;
        let end = |l: &[u32]| self.wvertex[self.walpha0[*l.last().unwrap_or(&0) as usize] as usize];
        if self.cover && end(&lp) != end(&lq) {
            return Ok(false);
        }
        let mut w = self.word(&lp);
        words::push_reduced(&mut w, words::inverse(&self.word(&lq)));
        Ok(self.trivial(&w))
    }

    fn ends_differ(&self, p: &SurfacePath, q: &SurfacePath) -> CurveError {
        let r = |v: Option<u32>| v.map_or(u32::MAX, |v| self.vertices.reps[v as usize].get());
        CurveError::EndsDiffer { p: [r(p.start), r(p.end)], q: [r(q.start), r(q.end)] }
    }

    /// Whether the closed paths `p` and `q` are freely homotopic. Refuses paths that are
    /// not closed, and answers that cannot be proved (see the module's notes).
    pub fn are_freely_homotopic(&self, p: &SurfacePath, q: &SurfacePath) -> Result<bool, CurveError> {
        self.closed(p)?;
        self.closed(q)?;
        let (lp, sp) = self.lift(p, 0)?;
        let (lq, sq) = self.lift(q, 0)?;
        if sp != sq {
            return Ok(false); // one keeps the orientation, the other reverses it
        }
        if !self.cover {
            return self.conjugate(&self.word(&lp), &self.word(&lq));
        }
        if sp {
            // on the cover, q lifts from either sheet
            let (lq2, _) = self.lift(q, 1)?;
            let wp = self.word(&lp);
            let a = self.conjugate(&wp, &self.word(&lq));
            if a == Ok(true) {
                return a;
            }
            let b = self.conjugate(&wp, &self.word(&lq2));
            return match (a, b) {
                (Ok(true), _) | (_, Ok(true)) => Ok(true),
                (Ok(false), Ok(false)) => Ok(false),
                (Err(e), _) | (_, Err(e)) => Err(e),
            };
        }
        // both reverse the orientation: on a surface of negative Euler characteristic
        // (torsion-free, square roots unique) p ~ q exactly when p² ~ q²; on the projective
        // plane both are its one non-trivial class
        if self.kind.euler == 1 {
            return Ok(true);
        }
        if self.kind.euler == 0 {
            return Err(CurveError::Undecided {
                what: "free homotopy",
                reason: "two orientation-reversing closed paths on the Klein bottle".into(),
            });
        }
        let sq_path = |x: &SurfacePath| {
            let mut d = x.darts.clone();
            d.extend_from_slice(&x.darts);
            SurfacePath { darts: d, start: x.start, end: x.end }
        };
        self.are_freely_homotopic(&sq_path(p), &sq_path(q))
    }

    /// Whether freely reduced words are conjugate in the group.
    fn conjugate(&self, a: &[Letter], b: &[Letter]) -> Result<bool, CurveError> {
        match &self.group {
            Group::Trivial => Ok(true),
            Group::Free => Ok(words::is_rotation(words::cyclically_reduced(a), words::cyclically_reduced(b))),
            Group::Torus => Ok(words::exponent_sums(a, 2) == words::exponent_sums(b, 2)),
            Group::Hyperbolic(d) => {
                let n = self.kind.generators;
                if words::exponent_sums(a, n) != words::exponent_sums(b, n) {
                    return Ok(false);
                }
                let (ra, rb) = (d.cyclic_reduce(a), d.cyclic_reduce(b));
                if words::is_rotation(&ra, &rb) {
                    return Ok(true);
                }
                if ra.is_empty() != rb.is_empty() {
                    return Ok(false);
                }
                Err(CurveError::Undecided {
                    what: "free homotopy",
                    reason: format!(
                        "the cyclically reduced words ({} and {} letters) are not rotations of each other, \
                         and equal classes in H_1 do not show they are not homotopic",
                        ra.len(),
                        rb.len()
                    ),
                })
            }
        }
    }

    /// Whether the closed path `p` is homotopic to a simple closed curve: answered on the
    /// sphere and the projective plane (their curves), the torus (class `(a, b)` with
    /// `gcd(a, b) = 1`, or contractible) and for contractible paths; refused otherwise.
    pub fn is_homotopic_to_simple_cycle(&self, p: &SurfacePath) -> Result<bool, CurveError> {
        if self.is_contractible(p)? {
            return Ok(true);
        }
        match (&self.group, self.cover, self.kind.boundary) {
            (Group::Trivial, _, false) => Ok(true), // sphere, or the projective plane's one class
            (Group::Torus, false, false) => {
                let (l, _) = self.lift(p, 0)?;
                let s = words::exponent_sums(&self.word(&l), 2);
                Ok(gcd(s[0].unsigned_abs(), s[1].unsigned_abs()) == 1)
            }
            _ => Err(CurveError::Undecided {
                what: "homotopy to a simple cycle",
                reason: "decided here on the sphere, the projective plane, the torus and for contractible paths".into(),
            }),
        }
    }
}

fn gcd(a: u64, b: u64) -> u64 {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

/// The orientation double cover of a closed map: darts `d` and `d + n`; `alpha_i` goes to
/// the other sheet (a fixed point stays fixed). Connected when the map is not orientable.
fn double_cover(map: &DenseMap) -> Result<DenseMap, CurveError> {
    let n = map.dart_count() as u32;
    let dim = map.dim();
    let mut flat = vec![0u32; 2 * n as usize * (dim + 1)];
    for s in 0..2u32 {
        for d in map.darts() {
            let c = (d.get() + s * n) as usize;
            for i in 0..=dim {
                let a = map.alpha(d, i).get();
                flat[c * (dim + 1) + i] = if a == d.get() { c as u32 } else { a + (1 - s) * n };
            }
        }
    }
    DenseMap::try_from_flat(dim, flat).map_err(|e| CurveError::Invalid { reason: e.to_string() })
}

/// The tree–cotree presentation of a connected surface map.
struct Presentation {
    /// the vertex of each dart
    vertex: Vec<u32>,
    /// `alpha_0`
    alpha0: Vec<u32>,
    /// the number of generators
    generators: usize,
    /// each dart's word (the step leaving its vertex along its edge)
    dart_word: Vec<Vec<Letter>>,
    /// the boundary of the one polygon left (closed surfaces)
    relator: Vec<Letter>,
}

impl Presentation {
    fn of(map: &DenseMap, boundary: bool) -> Result<Self, CurveError> {
        const NONE: u32 = u32::MAX;
        let v = map.cells(0);
        let e = map.cells(1);
        let f = map.cells(2);
        let (nv, ne, nf) = (v.len(), e.len(), f.len());
        let a = |d: u32, i: usize| map.alpha(Dart::new(d), i).get();
        // an edge goes forward from the vertex of its smallest dart r: darts r and α2 r
        let forward = |d: u32| {
            let r = e.reps[e.of[d as usize] as usize].get();
            d == r || d == a(r, 2)
        };
        // 1. T: a BFS tree of the vertices
        let mut adj: Vec<Vec<(u32, u32)>> = vec![Vec::new(); nv];
        for (k, r) in e.reps.iter().enumerate() {
            let (x, y) = (v.of[r.index()], v.of[map.alpha(*r, 0).index()]);
            adj[x as usize].push((y, k as u32));
            adj[y as usize].push((x, k as u32));
        }
        let mut in_t = vec![false; ne];
        let mut seen = vec![false; nv];
        let mut queue = VecDeque::from([0u32]);
        seen[0] = true;
        while let Some(x) = queue.pop_front() {
            for &(y, k) in &adj[x as usize] {
                if !seen[y as usize] {
                    seen[y as usize] = true;
                    in_t[k as usize] = true;
                    queue.push_back(y);
                }
            }
        }
        // 2. C: a BFS tree of the faces (and the outside, node nf) across edges not in T
        let out = nf as u32;
        let mut dual: Vec<Vec<(u32, u32)>> = vec![Vec::new(); nf + 1];
        for (k, r) in e.reps.iter().enumerate() {
            if in_t[k] {
                continue;
            }
            let f1 = f.of[r.index()];
            let f2 = if map.is_free(*r, 2) { out } else { f.of[map.alpha(*r, 2).index()] };
            if f1 != f2 {
                dual[f1 as usize].push((f2, k as u32));
                dual[f2 as usize].push((f1, k as u32));
            }
        }
        let root = if boundary { out } else { 0 };
        let mut parent_edge = vec![NONE; nf + 1];
        let mut fseen = vec![false; nf + 1];
        let mut order = Vec::with_capacity(nf + 1);
        fseen[root as usize] = true;
        let mut queue = VecDeque::from([root]);
        while let Some(x) = queue.pop_front() {
            order.push(x);
            for &(y, k) in &dual[x as usize] {
                if !fseen[y as usize] {
                    fseen[y as usize] = true;
                    parent_edge[y as usize] = k;
                    queue.push_back(y);
                }
            }
        }
        let in_c: Vec<bool> = {
            let mut c = vec![false; ne];
            for &k in &parent_edge {
                if k != NONE {
                    c[k as usize] = true;
                }
            }
            c
        };
        // 3. generators
        let mut edge_word: Vec<Option<Vec<Letter>>> = vec![None; ne];
        let mut generators = 0usize;
        for k in 0..ne {
            if in_t[k] {
                edge_word[k] = Some(Vec::new());
            } else if !in_c[k] {
                generators += 1;
                edge_word[k] = Some(vec![generators as Letter]);
            }
        }
        // the sides of a face in cyclic order: darts x, α1 α0 x, … (one per side)
        let sides = |face: u32| {
            let x0 = f.reps[face as usize].get();
            let mut s = vec![x0];
            let mut x = a(a(x0, 0), 1);
            while x != x0 {
                s.push(x);
                x = a(a(x, 0), 1);
            }
            s
        };
        // 4. the words of C's edges, from the leaves up
        for &face in order.iter().rev() {
            if face == out || parent_edge[face as usize] == NONE {
                continue;
            }
            let p = parent_edge[face as usize];
            let s = sides(face);
            let Some(at) = s.iter().position(|&x| e.of[x as usize] == p) else {
                return Err(CurveError::Presentation { reason: format!("face {face} misses its edge {p}") });
            };
            let mut rest: Vec<Letter> = Vec::new();
            for t in 1..s.len() {
                let x = s[(at + t) % s.len()];
                let k = e.of[x as usize] as usize;
                let Some(w) = &edge_word[k] else {
                    return Err(CurveError::Presentation { reason: format!("edge {k} has no word yet") });
                };
                if forward(x) {
                    words::push_reduced(&mut rest, w.iter().copied());
                } else {
                    words::push_reduced(&mut rest, words::inverse(w));
                }
            }
            // around the face: (p as the face runs it) · rest = 1
            edge_word[p as usize] = Some(if forward(s[at]) { words::inverse(&rest) } else { rest });
        }
        let word_of = |x: u32| -> Vec<Letter> {
            let w = edge_word[e.of[x as usize] as usize].clone().unwrap_or_default();
            if forward(x) {
                w
            } else {
                words::inverse(&w)
            }
        };
        let mut relator = Vec::new();
        if !boundary {
            for x in sides(root) {
                words::push_reduced(&mut relator, word_of(x));
            }
        }
        let n = map.dart_count();
        let dart_word = (0..n as u32).map(word_of).collect();
        Ok(Presentation {
            vertex: v.of.clone(),
            alpha0: (0..n as u32).map(|d| a(d, 0)).collect(),
            generators,
            dart_word,
            relator,
        })
    }
}
