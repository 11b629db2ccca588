//! Algorithm 8.16 of AC for the constructive cases of Example 8.19: turning a realisable
//! complex into a cw-complex with the same topological Betti numbers.

use std::fmt;

use gmap_core::union_find::UnionFind;

use super::{ArchComplex, ArchError, Region, RegionId};
use crate::complex::ep::EpVector;

/// How Algorithm 8.16 treats a region of dimension i > 0 with an empty boundary whose only
/// cobounding entries have weight 0 (AC Example 8.19, case α = 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ZeroWeightRule {
    /// Treat it as a closed region (a loop, a sphere — AC Remark 8.2) like the case α ≠ 0:
    /// attach a base vertex with a zero entry (`X_0 + Y_0`). No Betti number decreases
    /// (Remark 8.18 asks this of the cellulation steps); the ring of AC Example 8.21 gets
    /// the stated `b_0 = b_1 = 1`.
    #[default]
    Closed,
    /// The paper's literal case α = 0: the region is an open ball whose boundary was not
    /// recorded; complete it with a new (i-1)-region of weight 1 and a base vertex
    /// (`(X_0 + Y_0) + (X_{i-1} - Y_i)`), or for i = 1 with two end vertices
    /// (`(X_0 + Y_0) + (X_0 - Y_1)`). Reproduces the operator `3X_0 + 2Y_0 - Y_1` printed
    /// in AC Example 8.21.
    Seam,
}

/// Which step of Algorithm 8.16 applied an operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// a region with empty boundary, hit with non-zero weight or not at all: base vertex
    BaseVertex,
    /// a region with empty boundary hit only with weight 0, [`ZeroWeightRule::Seam`]
    CompleteSeam,
    /// a region whose boundary `Γ_b` had several components: a connecting edge
    ConnectBoundary,
    /// a 2-region of genus g ≥ 1 (its Betti numbers given): one of its 2g loops at a
    /// vertex of its boundary, entries of weight 0 (`X_1 + Y_1`)
    HandleLoop,
}

/// How Algorithm 8.16 cellulates one region of the input, from its dimension, its Betti
/// numbers ([`ArchComplex::region_betti`]) and the components of its recorded boundary.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Plan {
    /// no Betti numbers given: the region of the cw case (the steps of Example 8.19)
    Default,
    /// a sphere (a loop in dimension 1): a base vertex where nothing is recorded
    Sphere,
    /// a ball whose boundary is not recorded: the completion of Example 8.19, α = 0
    Ball,
    /// a 2-region of genus g: connected boundary as in the default, then 2g loops
    Surface { genus: usize },
}

/// One Euler–Poincaré operator applied by Algorithm 8.16.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AppliedOperator {
    /// the step
    pub step: Step,
    /// the region it was applied to (id)
    pub region: RegionId,
    /// the regions it created (ids)
    pub created: Vec<RegionId>,
    /// the operator `(ΔX; ΔY)`
    pub vector: EpVector,
}

impl fmt::Display for AppliedOperator {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?} on region {}: {}", self.step, self.region, self.vector)
    }
}

/// The output of Algorithm 8.16: the cw-complex and the operators applied, in order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Topological {
    /// the resulting complex `cw(C)`
    pub complex: ArchComplex,
    /// every operator applied
    pub operators: Vec<AppliedOperator>,
}

impl Topological {
    /// The sum of all operators applied, or `None` on overflow.
    pub fn total(&self) -> Option<EpVector> {
        let mut t = EpVector::zero(self.complex.dim());
        for o in &self.operators {
            t = t.try_add(&o.vector).ok()?;
        }
        Some(t)
    }
}

struct Growing {
    dim: usize,
    regions: Vec<Region>,
    entries: Vec<(RegionId, RegionId, i64)>,
    /// the next fresh id; `None` once `u64::MAX` is taken
    next_id: Option<u64>,
}

impl Growing {
    /// The `2 genus` loops of a 2-region of genus `genus` at vertex `v`: each a new 1-region
    /// with an entry of weight 0 to `v`, in the region's boundary with weight 0 (the word
    /// `a b a⁻¹ b⁻¹` of each handle has coefficient 0 on every letter).
    fn handle_loops(&mut self, region: RegionId, v: RegionId, genus: usize) -> Result<Vec<AppliedOperator>, ArchError> {
        let mut ops = Vec::with_capacity(2 * genus);
        for _ in 0..2 * genus {
            let e = self.fresh(1)?;
            self.entries.push((e, v, 0));
            self.entries.push((region, e, 0));
            ops.push(AppliedOperator {
                step: Step::HandleLoop,
                region,
                created: vec![e],
                vector: EpVector::b(self.dim, 1),
            });
        }
        Ok(ops)
    }

    /// A new region with an id above every existing one; refused when the ids run out.
    fn fresh(&mut self, dim: usize) -> Result<RegionId, ArchError> {
        let id = self.next_id.ok_or(ArchError::IdsExhausted)?;
        self.next_id = id.checked_add(1);
        self.regions.push(Region { id: RegionId(id), dim });
        Ok(RegionId(id))
    }
}

impl ArchComplex {
    /// The plan for region `r` (dimension ≥ 1), or the refusal naming it.
    fn plan(&self, r: usize) -> Result<Plan, ArchError> {
        if !self.has_region_betti(r) {
            return Ok(Plan::Default);
        }
        let i = self.regions[r].dim;
        let betti = self.region_betti(r);
        let boundary = self.boundary_component_count(r);
        let refuse = |reason: &'static str| ArchError::RegionTopologyUnknown {
            id: self.regions[r].id,
            dim: i,
            betti: betti.clone(),
            boundary,
            reason,
        };
        let sphere_with_holes = |holes: usize| {
            let mut b = vec![0usize; i + 1];
            b[0] = 1;
            if holes == 0 {
                b[i] += 1;
            } else {
                b[i - 1] += holes - 1;
            }
            b
        };
        let closed = betti[i] == 1;
        if i == 1 || (boundary >= 1 && betti == sphere_with_holes(boundary)) {
            // a loop or a segment, or the default reading confirmed
            return Ok(match (boundary, closed) {
                (0, true) => Plan::Sphere,
                (0, false) => Plan::Ball,
                _ => Plan::Default,
            });
        }
        if closed {
            if self.down(r).iter().any(|e| e.weight != 0) {
                return Err(refuse("a closed region has no boundary to glue with a non-zero weight"));
            }
            if boundary > 1 {
                return Err(refuse("a closed region touches the complex in one connected place"));
            }
            if betti == sphere_with_holes(0) {
                return Ok(Plan::Sphere);
            }
            if i == 2 {
                return Ok(Plan::Surface { genus: betti[1] / 2 });
            }
            return Err(refuse(
                "a closed region of dimension 3 or more other than a sphere is not determined by its Betti numbers",
            ));
        }
        if boundary == 0 {
            if betti == sphere_with_holes(1) {
                return Ok(Plan::Ball);
            }
            return Err(refuse("its boundary is not recorded, and only a ball's can be completed"));
        }
        if i == 2 && betti[1] + 1 >= boundary && (betti[1] + 1 - boundary).is_multiple_of(2) {
            // genus g with r boundary circles: b_1 = 2g + r - 1
            return Ok(Plan::Surface { genus: (betti[1] + 1 - boundary) / 2 });
        }
        if i == 2 {
            return Err(refuse(
                "a surface of genus g with r boundary circles has b_1 = 2g + r - 1, so b_1 + 1 - r must be even and not negative",
            ));
        }
        Err(refuse(
            "a region of dimension 3 or more is cellulated only as a sphere with r holes, (1, 0, …, 0, r - 1, 0)",
        ))
    }

    /// Algorithm 8.16 for the constructive cases of AC Example 8.19, on a realisable complex:
    ///
    /// 1. *Empty boundary.* Every region of dimension i > 0 without entries gets a base
    ///    vertex with a zero entry (`X_0 + Y_0`, `mvmc`); with [`ZeroWeightRule::Seam`], a
    ///    region hit only by zero weights is completed as in the paper's case α = 0.
    /// 2. *Disconnected boundary.* For i = 2..n, every i-region `b` whose `Γ_b` (closure
    ///    minus `b`) has several components gets, for each component but the first, a new
    ///    edge from a vertex of the first to a vertex of that component (weights -1, +1),
    ///    recorded in `b`'s boundary with weight 0 (a seam). The operator is `X_1 - Y_0`
    ///    (`mekc`) when the two vertices were in different components of the whole complex's
    ///    1-skeleton, and `X_1 + Y_1` (`meml`) when they were already connected elsewhere
    ///    (the new edge then closes a loop: an extension of the paper, which assumes the
    ///    first case).
    ///
    /// *Regions with their own topology* (AC Def. 8.1: a region is a manifold, not
    /// necessarily a cell). A region without Betti numbers is the cw case's: a cell glued
    /// along its recorded boundary, a sphere with r holes when `Γ_b` has r components
    /// (Example 8.22 counts the boundary components this way), a closed region read by
    /// `rule` when nothing is recorded. A region given Betti numbers
    /// ([`ArchComplex::with_region_betti`]) is cellulated as they say where they determine
    /// it: a sphere gets a base vertex, a ball without recorded boundary the completion of
    /// the case α = 0 (whatever `rule` says), a 2-region of genus g with r boundary
    /// components (`b_1 = 2g + r - 1`, `b_2` 1 if closed) the steps above and then 2g loops
    /// with entries of weight 0 at a vertex of its boundary (`X_1 + Y_1` each,
    /// [`Step::HandleLoop`]): a torus region becomes a vertex, two loops and a face, with
    /// Betti numbers (1, 2, 1). Where they do not determine it (a region of dimension 3 or
    /// more other than a sphere with r holes; numbers that contradict the recorded boundary),
    /// the algorithm refuses with [`ArchError::RegionTopologyUnknown`] naming the region,
    /// rather than answer with numbers Theorem 8.11 does not support. The output's regions
    /// are cells: it carries no Betti numbers of regions.
    ///
    /// New regions get ids above the largest existing id. Every intermediate complex
    /// satisfies Def. 3.1 (checked). O((R + E) · R) in the worst case (one closure per region).
    pub fn topological(&self, rule: ZeroWeightRule) -> Result<Topological, ArchError> {
        let n = self.dim;
        let mut g = Growing {
            dim: n,
            regions: self.regions.clone(),
            entries: self.entry_ids(),
            next_id: self.regions.iter().map(|r| r.id.0).max().map_or(Some(0), |m| m.checked_add(1)),
        };
        let mut ops = Vec::new();
        let mut plans = Vec::with_capacity(self.regions.len());
        for (r, reg) in self.regions.iter().enumerate() {
            plans.push(if reg.dim == 0 { Plan::Default } else { self.plan(r)? });
        }
        // step 1: regions with empty boundary
        for (r, reg) in self.regions.iter().enumerate() {
            if reg.dim == 0 || !self.down(r).is_empty() {
                continue;
            }
            let i = reg.dim;
            let seam = match plans[r] {
                Plan::Default => {
                    let mut hit = self.up_of(r).filter(|e| self.regions[e.from].dim == i + 1).peekable();
                    let all_zero = hit.peek().is_some() && hit.all(|e| e.weight == 0);
                    rule == ZeroWeightRule::Seam && all_zero
                }
                Plan::Ball => true,
                Plan::Sphere | Plan::Surface { .. } => false,
            };
            if seam {
                let v = g.fresh(0)?;
                let created = if i > 1 {
                    let s = g.fresh(i - 1)?;
                    g.entries.push((reg.id, s, 1));
                    g.entries.push((s, v, 0));
                    vec![s, v]
                } else {
                    let w = g.fresh(0)?;
                    g.entries.push((reg.id, v, -1));
                    g.entries.push((reg.id, w, 1));
                    vec![v, w]
                };
                // (X_0 + Y_0) + (X_{i-1} - Y_i)
                let vector = EpVector::b(n, 0)
                    .try_add(&EpVector::x_unit(n, i - 1))
                    .and_then(|x| x.try_add_scaled(-1, &EpVector::y_unit(n, i)))
                    .expect("small");
                ops.push(AppliedOperator { step: Step::CompleteSeam, region: reg.id, created, vector });
            } else {
                let v = g.fresh(0)?;
                g.entries.push((reg.id, v, 0));
                let vec = EpVector::b(n, 0);
                ops.push(AppliedOperator { step: Step::BaseVertex, region: reg.id, created: vec![v], vector: vec });
                if let Plan::Surface { genus } = plans[r] {
                    ops.extend(g.handle_loops(reg.id, v, genus)?);
                }
            }
        }
        let mut cur = ArchComplex::try_new(g.dim, g.regions.clone(), g.entries.clone())?;
        // step 2: disconnected boundaries, dimension by dimension; then the loops of the
        // genus of 2-regions whose boundary was recorded
        for i in 2..=n {
            let targets: Vec<RegionId> = cur.per_dim[i].iter().map(|&r| cur.regions[r as usize].id).collect();
            for bid in targets {
                let b = cur.index_of(bid).expect("region kept");
                let genus = match self.index_of(bid).map(|r| (r, plans[r])) {
                    Some((r, Plan::Surface { genus })) if !self.down(r).is_empty() => genus,
                    _ => 0,
                };
                let comps = cur.components_of(&cur.boundary_regions(b));
                if comps.len() < 2 && genus == 0 {
                    continue;
                }
                let vertex_of = |c: &Vec<usize>| c.iter().copied().find(|&r| cur.regions[r].dim == 0);
                let Some(v0) = comps.first().and_then(vertex_of) else {
                    if genus > 0 {
                        let r = self.index_of(bid).expect("an input region");
                        return Err(ArchError::RegionTopologyUnknown {
                            id: bid,
                            dim: i,
                            betti: self.region_betti(r),
                            boundary: self.boundary_component_count(r),
                            reason: "its boundary has no vertex to attach the loops of its genus at",
                        });
                    }
                    continue;
                };
                let mut uf = cur.vertex_connectivity();
                let mut added = Vec::new();
                for comp in &comps[1..] {
                    let Some(v1) = vertex_of(comp) else { continue };
                    let e = g.fresh(1)?;
                    let (a, c) = (cur.regions[v0].id, cur.regions[v1].id);
                    g.entries.push((e, a, -1));
                    g.entries.push((e, c, 1));
                    g.entries.push((bid, e, 0));
                    let joined = uf.union(v0 as u32, v1 as u32);
                    let vector = if joined { EpVector::a(n, 1) } else { EpVector::b(n, 1) };
                    added.push(AppliedOperator { step: Step::ConnectBoundary, region: bid, created: vec![e], vector });
                }
                added.extend(g.handle_loops(bid, cur.regions[v0].id, genus)?);
                if !added.is_empty() {
                    ops.extend(added);
                    cur = ArchComplex::try_new(g.dim, g.regions.clone(), g.entries.clone())?;
                }
            }
        }
        Ok(Topological { complex: cur, operators: ops })
    }

    /// Union–find over the 0-regions, joined by 1-regions with non-zero weights to both.
    fn vertex_connectivity(&self) -> UnionFind {
        let mut uf = UnionFind::new(self.regions.len());
        for &e in &self.per_dim.get(1).cloned().unwrap_or_default() {
            let ends: Vec<usize> = self
                .down(e as usize)
                .iter()
                .filter(|x| x.weight != 0 && self.regions[x.to].dim == 0)
                .map(|x| x.to)
                .collect();
            for w in ends.windows(2) {
                uf.union(w[0] as u32, w[1] as u32);
            }
        }
        uf
    }
}
