//! Builders of classic objects, all returned as valid [`DenseMap`]s.
//!
//! | builder | object | darts |
//! | --- | --- | --- |
//! | [`simplex`] | the n-simplex (a ball) | `(n + 1)!` |
//! | [`cube`] | the n-cube (a ball) | `2^n n!` |
//! | [`polygon`] | a k-gon (a disc) with points on the unit circle | `2k` |
//! | [`extrude`] | the product of an n-map with an edge | `2 (n + 1) N` |
//! | [`grid`] | `k_1 × … × k_d` cubes, any axes periodic (the d-torus) | `2^d d! Π k_i` |
//! | [`schema`] | a surface from a polygonal schema word (`a b A B`) | `2 ×` letters |
//! | [`solid_torus`] | a ring of cubes | `48 k` |
//! | [`lens_space`] | L(p, q): a ball whose two hemispheres are glued with a twist | `4p` |
//!
//! The classic ones have complete boundaries (BO Def. 6) where they have no boundary,
//! cells orientable as compacted cells (C1) and cells that are homology balls (C2), so the
//! cellular homology applies to them. Each builder states its precondition and returns a
//! [`BuildError`] when it fails; none panics. [`placed`] builds the grid, the cube, the
//! simplex and the torus with the points of their vertices.
//!
//! ```
//! use gmap_ops::build;
//! let torus = build::schema("a b A B").unwrap();
//! assert_eq!(torus.cell_counts(), vec![1, 2, 1]);
//! assert_eq!(torus.euler_characteristic(), 0);
//! let t3 = build::grid(&[2, 2, 2], &[true, true, true]).unwrap();
//! assert_eq!(t3.euler_characteristic(), 0);
//! assert_eq!(t3.dart_count(), 8 * 48);
//! ```

use gmap_core::{Dart, DenseMap};

use crate::import::SimplicialComplex;
use crate::perm::{factorial, PermTable};

mod error;
mod incremental;
pub mod placed;
mod schema;

use error::checked_darts;
pub use error::BuildError;
pub use incremental::{sew3_same_facets, IncrementalBuilder};

pub use schema::{nonorientable_surface_word, orientable_surface_word, schema};

/// The n-simplex: one facet of the simplicial importer, `(n + 1)!` darts, `C(n+1, i+1)`
/// i-cells, χ = 1. Its darts are n-free (the boundary). Precondition: `(n + 1)! < 2^32`,
/// that is `n <= 11`.
pub fn simplex(n: usize) -> Result<DenseMap, BuildError> {
    let what = || format!("the {n}-simplex");
    let f = n.checked_add(1).and_then(factorial).ok_or_else(|| BuildError::TooManyDarts { what: what() })?;
    checked_darts(what, n, &[f])?;
    let sc = SimplicialComplex::from_facets(vec![(0..=n as u64).collect()]).expect("one facet of distinct vertices");
    sc.to_gmap(u64::MAX).map_err(|_| BuildError::TooManyDarts { what: what() })
}

/// The n-cube `[0,1]^n`: `2^n n!` darts, `C(n, i) 2^(n-i)` i-cells, χ = 1 (a 1×…×1 [`grid`];
/// for n = 0 a single dart). Precondition: `2^n n! < 2^32`, that is `n <= 10`.
pub fn cube(n: usize) -> Result<DenseMap, BuildError> {
    if n == 0 {
        return Ok(DenseMap::new(0, 1));
    }
    // the dimension first: the grid's side list is not made for a dimension past the maximum
    if n > gmap_core::MAX_DIM {
        return Err(BuildError::BadArgument(format!(
            "the {n}-cube: a map has a dimension from 0 to {}",
            gmap_core::MAX_DIM
        )));
    }
    grid(&vec![1; n], &vec![false; n])
}

/// A k-gon as a 2-map: one face, `2k` darts, the boundary 2-free; dart `2j` lies at corner
/// `j` on edge `j`, dart `2j + 1` at corner `j + 1`. Corner `j` carries the point
/// `(cos 2πj/k, sin 2πj/k, 0)`. Precondition: `k >= 1` (k = 1, 2 give a monogon, a digon).
pub fn polygon(k: usize) -> Result<DenseMap, BuildError> {
    if k == 0 {
        return Err(BuildError::BadArgument("a polygon needs at least one side".into()));
    }
    let darts = checked_darts(|| format!("a {k}-gon"), 2, &[2, k as u64])?;
    let mut m = DenseMap::new(2, darts);
    let corner = |j: usize| {
        let t = std::f64::consts::TAU * (j % k) as f64 / k as f64;
        Some([t.cos(), t.sin(), 0.0])
    };
    for j in 0..k {
        let (a, b) = (Dart::new(2 * j as u32), Dart::new(2 * j as u32 + 1));
        m.link(a, b, 0);
        m.link(b, Dart::new(((2 * j + 2) % darts) as u32), 1);
        m.set_point(a, corner(j));
        m.set_point(b, corner(j + 1));
    }
    Ok(m)
}

/// The product `M × [0, 1]` of an n-map with an edge: an (n + 1)-map with `2 (n + 1)` darts
/// per dart of `M`. An i-cell `c` of `M` gives the i-cells `c × {0}`, `c × {1}` and the
/// (i + 1)-cell `c × [0, 1]`, so χ(M × I) = χ(M) and the cell counts follow. The darts over
/// `c × {s}` are (n + 1)-free (the two copies of `M` bound the product). Points, if any, are
/// copied to height `z + s`. Precondition: `M` valid, `n + 1 <= MAX_DIM`. O(N n).
///
/// Dart `(d, k, s)` (index `d · 2(n+1) + 2(k-1) + s`, `1 <= k <= n + 1`) is the flag
/// `c_0 × s < … < c_{k-1} × s < c_{k-1} × I < c_k × I < … < c_n × I` built on the flag
/// `c_0 < … < c_n` of dart `d`.
pub fn extrude(map: &DenseMap) -> Result<DenseMap, BuildError> {
    let n = map.dim();
    if n + 1 > gmap_core::MAX_DIM {
        return Err(BuildError::BadArgument(format!("dimension {} is over the maximum", n + 1)));
    }
    let per = 2 * (n + 1);
    let darts = checked_darts(|| "the extrusion".into(), n + 1, &[map.dart_count() as u64, per as u64])?;
    let w = n + 2;
    let mut alpha = vec![0u32; darts * w];
    let idx = |d: usize, k: usize, s: usize| (d * per + 2 * (k - 1) + s) as u32;
    for d in 0..map.dart_count() {
        let row = map.row(Dart::new(d as u32));
        for k in 1..=n + 1 {
            for s in 0..2 {
                let me = idx(d, k, s) as usize;
                for j in 0..w {
                    let img = if j + 1 < k {
                        idx(row[j] as usize, k, s)
                    } else if j + 1 == k {
                        if k >= 2 {
                            idx(d, k - 1, s)
                        } else {
                            idx(d, 1, 1 - s)
                        }
                    } else if j == k {
                        if k <= n {
                            idx(d, k + 1, s)
                        } else {
                            me as u32
                        }
                    } else {
                        idx(row[j - 1] as usize, k, s)
                    };
                    alpha[me * w + j] = img;
                }
            }
        }
    }
    let mut out = DenseMap::from_flat_unchecked(n + 1, alpha)
        .map_err(|_| BuildError::TooManyDarts { what: "the extrusion".into() })?;
    if map.has_points() {
        for d in map.darts() {
            if let Some(p) = map.point(d) {
                for k in 1..=n + 1 {
                    for s in 0..2 {
                        out.set_point(Dart::new(idx(d.index(), k, s)), Some([p[0], p[1], p[2] + s as f64]));
                    }
                }
            }
        }
    }
    Ok(out)
}

/// A grid of `sizes[0] × … × sizes[d-1]` unit d-cubes; axis `a` is periodic (its two ends
/// glued) when `periodic[a]`. All axes periodic gives the d-torus (χ = 0). Built directly
/// as flat arrays in one pass: the 40³ grid (3,072,000 darts) takes a few tens of ms.
///
/// Darts of a cube are pairs (corner `ε ∈ {0,1}^d`, ordering `π` of the axes): the flag
/// whose vertex is the corner, whose edge leaves it along `π_0`, whose 2-face spans `π_0, π_1`,
/// and so on. `alpha_0` flips `ε[π_0]`, `alpha_i` (0 < i < d) swaps `π_{i-1}, π_i`, and
/// `alpha_d` crosses the facet normal to `π_{d-1}` into the neighbouring cube (free on the
/// boundary of a non-periodic axis). Precondition: `1 <= d`, every size `>= 1`, the dart
/// count `2^d d! Π sizes < 2^32`.
pub fn grid(sizes: &[usize], periodic: &[bool]) -> Result<DenseMap, BuildError> {
    let d = sizes.len();
    if d == 0 || periodic.len() != d {
        return Err(BuildError::BadArgument(format!(
            "a grid needs one size and one periodicity flag per axis (got {} and {})",
            d,
            periodic.len()
        )));
    }
    if sizes.contains(&0) {
        return Err(BuildError::BadArgument("grid sizes must be at least 1".into()));
    }
    let what = || format!("the grid {sizes:?}");
    let fact = factorial(d).ok_or_else(|| BuildError::TooManyDarts { what: what() })?;
    let corners = 1u64
        .checked_shl(d as u32)
        .filter(|&c| c != 0 && d < 32)
        .ok_or_else(|| BuildError::TooManyDarts { what: what() })?;
    let mut factors: Vec<u64> = sizes.iter().map(|&k| k as u64).collect();
    factors.push(fact);
    factors.push(corners);
    let darts = checked_darts(what, d, &factors)?;
    let table = PermTable::new(d);
    let nc = corners as usize;
    let per = table.len() * nc;
    let cubes = darts / per;
    let w = d + 1;
    let mut stride = vec![1usize; d];
    for a in 1..d {
        stride[a] = stride[a - 1] * sizes[a - 1];
    }
    let mut alpha = vec![0u32; darts * w];
    let mut coord = vec![0usize; d];
    for cube in 0..cubes {
        let base = cube * per;
        for p in 0..table.len() {
            let perm = table.perm(p);
            let first = perm[0] as usize;
            let ax = perm[d - 1] as usize;
            // the neighbour across the facet normal to `ax`, on each side
            let lo = if coord[ax] > 0 {
                Some(cube - stride[ax])
            } else if periodic[ax] {
                Some(cube + (sizes[ax] - 1) * stride[ax])
            } else {
                None
            };
            let hi = if coord[ax] + 1 < sizes[ax] {
                Some(cube + stride[ax])
            } else if periodic[ax] {
                Some(cube - (sizes[ax] - 1) * stride[ax])
            } else {
                None
            };
            for eps in 0..nc {
                let me = base + p * nc + eps;
                let row = &mut alpha[me * w..(me + 1) * w];
                row[0] = (base + p * nc + (eps ^ (1 << first))) as u32;
                for (i, slot) in row.iter_mut().enumerate().take(d).skip(1) {
                    *slot = (base + table.swap(p, i - 1) as usize * nc + eps) as u32;
                }
                let side = if eps & (1 << ax) != 0 { hi } else { lo };
                row[d] = match side {
                    Some(c) => (c * per + p * nc + (eps ^ (1 << ax))) as u32,
                    None => me as u32,
                };
            }
        }
        for a in 0..d {
            coord[a] += 1;
            if coord[a] < sizes[a] {
                break;
            }
            coord[a] = 0;
        }
    }
    DenseMap::from_flat_unchecked(d, alpha)
        .map_err(|_| BuildError::TooManyDarts { what: format!("the grid {sizes:?}") })
}

/// The solid torus: a ring of `k` cubes, each glued to the next (axis 2 periodic):
/// `48 k` darts, cells `(4k, 8k, 5k, k)`, χ = 0, boundary a torus (3-free darts).
/// Precondition: `k >= 1`.
pub fn solid_torus(k: usize) -> Result<DenseMap, BuildError> {
    grid(&[1, 1, k], &[false, false, true])
}

/// The lens space L(p, q) as a 3-map of `4p` darts: one 3-ball whose boundary is two p-gons
/// (the upper and lower hemispheres, sharing the equator of p vertices and p edges), the
/// upper one glued to the lower one by the reflection through the equator followed by a
/// rotation of `q / p` of a turn. With `gcd(p, q) = 1` the cells are `(1, 1, 1, 1)`, χ = 0,
/// the map is orientable and closed, and H_1 = Z/p (L(1, q) is the 3-sphere, L(2, 1) the
/// projective space RP³). Precondition: `p >= 1`; `q` is taken modulo `p`.
///
/// Darts: `u(j, s) = 2j + s` on the upper face and `l(j, s) = 2p + 2j + s` on the lower one,
/// for edge `j` of the equator and its end `s` (vertex `j + s`); `alpha_2` pairs `u(j, s)`
/// with `l(j, s)` inside the ball and `alpha_3` pairs `u(j, s)` with `l(j + q, s)`.
pub fn lens_space(p: usize, q: usize) -> Result<DenseMap, BuildError> {
    if p == 0 {
        return Err(BuildError::BadArgument("a lens space L(p, q) needs p >= 1".into()));
    }
    let darts = checked_darts(|| format!("L({p}, {q})"), 3, &[4, p as u64])?;
    let q = q % p;
    let mut m = DenseMap::new(3, darts);
    let at = |base: usize, j: usize, s: usize| Dart::new((base + 2 * (j % p) + s) as u32);
    let u = |j: usize, s: usize| at(0, j, s);
    let l = |j: usize, s: usize| at(2 * p, j, s);
    for j in 0..p {
        for base in [0, 2 * p] {
            m.link(at(base, j, 0), at(base, j, 1), 0);
            m.link(at(base, j, 1), at(base, j + 1, 0), 1);
        }
        for s in 0..2 {
            m.link(u(j, s), l(j, s), 2);
            m.link(u(j, s), l(j + q, s), 3);
        }
    }
    Ok(m)
}

/// The objects of `gmap demo`, by name: sphere, torus, Klein bottle, projective plane,
/// cylinder, Möbius band, genus-2 surface, triangle, solid cube, tetrahedron, solid torus,
/// 3-torus, lens spaces L(5, 2) and L(2, 1), 4-cube and 4-torus. Each is small (at most a
/// few thousand darts).
pub fn demo_objects() -> Vec<(String, DenseMap)> {
    let items: Vec<(&str, Result<DenseMap, BuildError>)> = vec![
        ("sphere (a A)", schema("a A")),
        ("torus (a b A B)", schema("a b A B")),
        ("Klein bottle (a b a B)", schema("a b a B")),
        ("projective plane (a a)", schema("a a")),
        ("cylinder (a b A c)", schema("a b A c")),
        ("Moebius band (a b a c)", schema("a b a c")),
        ("genus-2 surface", schema(&orientable_surface_word(2))),
        ("triangle", polygon(3)),
        ("solid cube", cube(3)),
        ("tetrahedron", simplex(3)),
        ("solid torus (3 cubes)", solid_torus(3)),
        ("3-torus (2x2x2 cubes)", grid(&[2, 2, 2], &[true; 3])),
        ("lens space L(5,2)", lens_space(5, 2)),
        ("RP3 = L(2,1)", lens_space(2, 1)),
        ("4-cube", cube(4)),
        ("4-torus (1x1x1x1)", grid(&[1; 4], &[true; 4])),
    ];
    items.into_iter().map(|(n, m)| (n.to_string(), m.expect("built-in arguments are valid"))).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(m: &DenseMap, cells: &[usize], chi: i64, orientable: bool) {
        m.validate().unwrap();
        assert_eq!(m.cell_counts(), cells);
        assert_eq!(m.euler_characteristic(), chi);
        assert_eq!(m.is_orientable(), orientable);
        m.check_cells_orientable().unwrap();
    }

    #[test]
    fn simplices_and_cubes() {
        check(&simplex(0).unwrap(), &[1], 1, true);
        check(&simplex(1).unwrap(), &[2, 1], 1, true);
        check(&simplex(2).unwrap(), &[3, 3, 1], 1, true);
        check(&simplex(3).unwrap(), &[4, 6, 4, 1], 1, true);
        check(&simplex(4).unwrap(), &[5, 10, 10, 5, 1], 1, true);
        assert_eq!(simplex(4).unwrap().dart_count(), 120);
        check(&cube(1).unwrap(), &[2, 1], 1, true);
        check(&cube(2).unwrap(), &[4, 4, 1], 1, true);
        check(&cube(3).unwrap(), &[8, 12, 6, 1], 1, true);
        check(&cube(4).unwrap(), &[16, 32, 24, 8, 1], 1, true);
        assert_eq!(cube(4).unwrap().dart_count(), 384);
        assert!(matches!(simplex(12), Err(BuildError::TooManyDarts { .. })));
    }

    #[test]
    fn polygons_and_extrusions() {
        check(&polygon(5).unwrap(), &[5, 5, 1], 1, true);
        check(&polygon(1).unwrap(), &[1, 1, 1], 1, true);
        assert!(polygon(0).is_err());
        let prism = extrude(&polygon(5).unwrap()).unwrap();
        check(&prism, &[10, 15, 7, 1], 1, true);
        assert_eq!(prism.dart_count(), 60);
        assert_eq!(prism.vertex_point(Dart::new(1)).map(|p| p[2]), Some(1.0));
        let sq = extrude(&cube(1).unwrap()).unwrap();
        check(&sq, &[4, 4, 1], 1, true);
        let c4 = extrude(&cube(3).unwrap()).unwrap();
        check(&c4, &[16, 32, 24, 8, 1], 1, true);
        // the product of the torus with an edge: a thickened torus
        let tt = extrude(&schema("a b A B").unwrap()).unwrap();
        check(&tt, &[2, 5, 4, 1], 0, true);
        let kb = extrude(&schema("a b a B").unwrap()).unwrap();
        check(&kb, &[2, 5, 4, 1], 0, false);
    }

    #[test]
    fn grids_and_tori() {
        check(&grid(&[3], &[false]).unwrap(), &[4, 3], 1, true);
        check(&grid(&[3], &[true]).unwrap(), &[3, 3], 0, true);
        check(&grid(&[2, 3], &[false, false]).unwrap(), &[12, 17, 6], 1, true);
        check(&grid(&[2, 3], &[true, true]).unwrap(), &[6, 12, 6], 0, true);
        check(&grid(&[2, 3], &[true, false]).unwrap(), &[8, 14, 6], 0, true);
        check(&grid(&[2, 2, 2], &[false; 3]).unwrap(), &[27, 54, 36, 8], 1, true);
        check(&grid(&[2, 2, 3], &[true; 3]).unwrap(), &[12, 36, 36, 12], 0, true);
        check(&grid(&[1, 1, 1], &[true; 3]).unwrap(), &[1, 3, 3, 1], 0, true);
        check(&grid(&[2, 2, 2, 2], &[true; 4]).unwrap(), &[16, 64, 96, 64, 16], 0, true);
        check(&grid(&[1, 1, 1, 2], &[false, false, false, true]).unwrap(), &[16, 40, 36, 14, 2], 0, true);
        let g = grid(&[40, 40, 40], &[false; 3]).unwrap();
        assert_eq!(g.dart_count(), 3_072_000);
        assert!(grid(&[0, 2], &[false, false]).is_err());
        assert!(grid(&[2, 2], &[false]).is_err());
        assert!(matches!(grid(&[1000, 1000, 1000], &[false; 3]), Err(BuildError::TooManyDarts { .. })));
    }

    #[test]
    fn solid_torus_and_lens_spaces() {
        let st = solid_torus(3).unwrap();
        check(&st, &[12, 24, 15, 3], 0, true);
        assert!(st.has_complete_boundaries());
        assert_eq!(st.darts().filter(|&d| st.is_free(d, 3)).count(), 4 * 3 * 8);
        for (p, q) in [(1, 0), (2, 1), (3, 1), (5, 2), (7, 3)] {
            let l = lens_space(p, q).unwrap();
            assert_eq!(l.dart_count(), 4 * p);
            check(&l, &[1, 1, 1, 1], 0, true);
            assert!(l.has_complete_boundaries(), "L({p},{q})");
        }
        // q not prime to p: vertices and edges fall in gcd(p, q) classes
        let l = lens_space(6, 2).unwrap();
        l.validate().unwrap();
        assert_eq!(l.cell_counts(), vec![2, 2, 1, 1]);
        assert!(lens_space(0, 1).is_err());
    }

    #[test]
    fn demo_objects_are_valid() {
        let objs = demo_objects();
        assert_eq!(objs.len(), 16);
        for (name, m) in &objs {
            assert!(m.is_valid(), "{name}");
            assert!(m.check_cells_orientable().is_ok(), "{name}");
        }
    }
}
