//! Revolution: a profile swept about an axis in k steps, the last step closing the loop
//! (Moka's extrusion by revolution). The boundary of a square (a loop of four edges) gives
//! the torus surface; the square face gives the solid torus.
//!
//! The profile is a whole component of dimension p < n: the orbit of `d` under
//! `alpha_0..alpha_p`, its darts free for `alpha_{p+1}..alpha_n` (a loop of edges in a
//! 2-map, a face or a surface in a 3-map). The result is the product `P × S¹` cut in k
//! slabs `P × [j, j + 1]` (the product block the extrusions share, laid out as
//! [`crate::build::extrude`]): the profile's own darts are the bottom of
//! the first slab, the top of each slab is `alpha_{p+1}`-sewn to the bottom of the next, and
//! the top of the last to the profile. The profile's `alpha_p` links move to the sides of
//! the first slab, so the profile becomes one of the k walls between slabs.
//!
//! Euler characteristic: χ(P × S¹) = 0, so the change is `-χ(P)` with `χ(P)` counted in
//! the map before (a lone loop of edges in a 2-map is a disc, χ = 1, and becomes a torus:
//! Δχ = -1; a lone face in a 3-map is a disc in a ball, χ = 0: Δχ = 0). Asserted in the
//! tests, with the homology of the results.
//!
//! Attributes: the profile's darts keep theirs (the reconciliation runs on them first, so
//! a cell of the profile that now spreads over several cells keeps its value on the first
//! and copies on the others, through the split hook); new cells carry none. Every new
//! vertex gets the point of the profile vertex it comes from, turned by `2π j / k` about
//! the axis for the j-th wall.

use gmap_core::{Attributes, DartId, GMap, Point};

use super::extrude::debug_check;
use super::product::{cell_counts, chi, make_slab, place_copy, Profile};
use super::ConstructError;

/// What a revolution made.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Revolved {
    /// For each step j, the dart over the dart given in the bottom of slab j (for j = 0 the
    /// dart given itself).
    pub walls: Vec<DartId>,
    /// The change of the Euler characteristic, `-χ(P)`.
    pub euler_change: i64,
}

/// An axis of revolution: a point on it and its direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Axis {
    /// a point of the axis
    pub origin: Point,
    /// the direction (any length but zero)
    pub direction: [f64; 3],
}

impl Axis {
    /// The axis through `origin` along `direction`.
    pub fn new(origin: Point, direction: [f64; 3]) -> Axis {
        Axis { origin, direction }
    }

    /// The rotation by `angle` radians about the axis (right-handed about `direction`),
    /// by Rodrigues' formula. `None` when the direction is zero or not finite.
    pub fn rotation(&self, angle: f64) -> Option<impl Fn(Point) -> Point> {
        let k = self.direction;
        let len = (k[0] * k[0] + k[1] * k[1] + k[2] * k[2]).sqrt();
        if !(len.is_finite() && len > 0.0) || self.origin.iter().any(|x| !x.is_finite()) {
            return None;
        }
        let k = [k[0] / len, k[1] / len, k[2] / len];
        let (s, c, o) = (angle.sin(), angle.cos(), self.origin);
        Some(move |p: Point| {
            let v = [p[0] - o[0], p[1] - o[1], p[2] - o[2]];
            let kxv = [k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]];
            let kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
            let mut r = [0.0; 3];
            for a in 0..3 {
                r[a] = o[a] + v[a] * c + kxv[a] * s + k[a] * kv * (1.0 - c);
            }
            r
        })
    }
}

/// The smallest number of steps of a revolution.
pub const MIN_STEPS: usize = 3;

/// The checked profile of a revolution.
fn check<A: Attributes>(
    g: &GMap<A>,
    d: DartId,
    p: usize,
    axis: &Axis,
    steps: usize,
) -> Result<Profile, ConstructError> {
    if !g.contains(d) {
        return Err(ConstructError::NoSuchDart(d));
    }
    let n = g.dim();
    if p + 1 > n {
        return Err(ConstructError::BadDimension { what: "a revolution", lo: 0, hi: n.saturating_sub(1), got: p });
    }
    if steps < MIN_STEPS {
        return Err(ConstructError::TooFewSteps { min: MIN_STEPS, got: steps });
    }
    if axis.rotation(0.0).is_none() {
        return Err(ConstructError::BadAxis(axis.direction));
    }
    let prof = Profile::new(g, d, p, p + 1);
    for &x in &prof.darts {
        if let Some(j) = (p + 1..=n).find(|&j| !g.is_free(x, j)) {
            return Err(ConstructError::NotFree { dart: x, alpha: j });
        }
        if g.point(x).is_none() {
            return Err(ConstructError::NoPoint(x));
        }
    }
    Ok(prof)
}

/// Whether [`try_revolve`] would succeed: `d` is live, `p < n`, `steps >= 3`, the axis has
/// a direction, and every dart of the profile (the orbit of `d` under
/// `alpha_0..alpha_p`) is free for `alpha_{p+1}..alpha_n` and has a point. O(s · n).
pub fn can_revolve<A: Attributes>(g: &GMap<A>, d: DartId, p: usize, axis: &Axis, steps: usize) -> bool {
    check(g, d, p, axis, steps).is_ok()
}

/// Revolves the p-dimensional profile of `d` about `axis` in `steps` equal steps, closing
/// the loop (see the [module docs](self)): the profile becomes `P × S¹`, `steps` slabs of
/// dimension p + 1. Precondition: [`can_revolve`]. Δχ = `-χ(P)`. O(steps · s · p²) for a
/// profile of s darts, plus the attribute repair.
pub fn try_revolve<A: Attributes>(
    g: &mut GMap<A>,
    d: DartId,
    p: usize,
    axis: &Axis,
    steps: usize,
) -> Result<Revolved, ConstructError> {
    let prof = check(g, d, p, axis, steps)?;
    let before = chi(&cell_counts(g, &prof.darts));
    let slabs: Vec<Vec<DartId>> = (0..steps).map(|j| make_slab(g, &prof, j == 0)).collect();
    for j in 0..steps {
        let next = (j + 1) % steps;
        for x in 0..prof.darts.len() {
            g.link(slabs[j][prof.at(x, p + 1, 1)], slabs[next][prof.at(x, p + 1, 0)], p + 1);
        }
    }
    if g.needs_reconcile() {
        let touched: Vec<DartId> = prof.darts.iter().chain(slabs.iter().flatten()).copied().collect();
        g.reconcile_attributes(&touched);
    }
    let turn = std::f64::consts::TAU / steps as f64;
    for (j, slab) in slabs.iter().enumerate() {
        for (s, k) in [(0, j), (1, j + 1)] {
            let rot = axis.rotation(turn * k as f64).expect("checked axis");
            place_copy(g, &prof, slab, s, rot);
        }
    }
    let all: Vec<DartId> = slabs.iter().flatten().copied().collect();
    let after = chi(&cell_counts(g, &all));
    debug_assert_eq!(after, 0, "the product with a circle has χ = 0");
    debug_check(g);
    Ok(Revolved { walls: slabs.iter().map(|s| s[prof.at(0, p + 1, 0)]).collect(), euler_change: after - before })
}

/// Like [`try_revolve`], panicking when the precondition fails.
#[track_caller]
pub fn revolve<A: Attributes>(g: &mut GMap<A>, d: DartId, p: usize, axis: &Axis, steps: usize) -> Revolved {
    try_revolve(g, d, p, axis, steps).unwrap_or_else(|e| panic!("revolve: {e}"))
}
