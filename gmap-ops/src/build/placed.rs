//! Builders with coordinates: the objects of [`crate::build`] placed in R³, every dart
//! carrying the point of its vertex, ready for `.off`, `.vtk` or the geometry of
//! [`gmap_core::GMap`] (constructors with coordinates and barycentres are in
//! [`gmap_core::points`]).
//!
//! | builder | object | points |
//! | --- | --- | --- |
//! | [`grid_with_points`] | `k_1 × … × k_d` unit cubes, `d <= 3` | the integer points `(x, y, z)`, `0 <= x <= k_1`, … |
//! | [`cube_with_points`] | the n-cube, `n <= 3` | the corners of `[0, 1]^n` |
//! | [`simplex_with_points`] | the n-simplex, `n <= 3` | the origin and the unit vectors `e_1 … e_n` |
//! | [`torus_with_points`] | the `a × b` periodic grid of squares, `a, b >= 3` | a torus of revolution about `z`, radii `big` and `small` |
//! | [`crate::build::polygon`] | the k-gon | the k-th roots of unity in the plane `z = 0` (already) |
//!
//! Coordinates past the dimension are 0 (a square lies in the plane `z = 0`).
//!
//! ```
//! use gmap_ops::build::placed::grid_with_points;
//! let g = grid_with_points(&[2, 1], &[false, false]).unwrap();
//! assert_eq!(g.cell_counts(), vec![6, 7, 2]);
//! let text = gmap_ops::export::off_string(&g).unwrap();
//! assert!(text.contains("\n2 1 0\n"));
//! ```

use gmap_core::{Dart, DenseMap, Point};

use crate::build::{self, BuildError};
use crate::perm::factorial;

/// The largest dimension with points in R³.
const MAX_PLACED_DIM: usize = 3;

fn too_high(what: &str, d: usize) -> BuildError {
    BuildError::BadArgument(format!("{what} of dimension {d} has no points in R^3 (at most {MAX_PLACED_DIM})"))
}

/// [`build::grid`] with the point of every vertex: the corner `(c_1 + ε_1, …, c_d + ε_d)` of
/// the cube at `(c_1, …, c_d)`, so the grid fills `[0, k_1] × … × [0, k_d]` with unit cubes.
/// On a periodic axis the coordinate is taken modulo its size (the two ends are one vertex,
/// and the points are then not an embedding of the torus, only labels of its vertices).
/// Precondition: that of [`build::grid`], and `d <= 3`. O(N).
pub fn grid_with_points(sizes: &[usize], periodic: &[bool]) -> Result<DenseMap, BuildError> {
    let d = sizes.len();
    if d > MAX_PLACED_DIM {
        return Err(too_high("a grid", d));
    }
    let mut m = build::grid(sizes, periodic)?;
    // the layout of build::grid: dart = cube * (d! 2^d) + ordering * 2^d + corner bits
    let corners = 1usize << d;
    let per = factorial(d).expect("d <= 3") as usize * corners;
    for k in 0..m.dart_count() {
        let (mut cube, eps) = (k / per, k % corners);
        let mut p: Point = [0.0; 3];
        for a in 0..d {
            let c = cube % sizes[a] + (eps >> a & 1);
            cube /= sizes[a];
            p[a] = if periodic[a] { c % sizes[a] } else { c } as f64;
        }
        m.set_point(Dart::new(k as u32), Some(p));
    }
    Ok(m)
}

/// The 2-torus as the periodic `a × b` grid of squares ([`build::grid`] with both axes
/// periodic) placed on a torus of revolution about the z axis: the vertex `(i, j)` at
/// `((big + small cos v) cos u, (big + small cos v) sin u, small sin v)` with
/// `u = 2π i / a`, `v = 2π j / b`. An embedding when `a, b >= 3` and `0 < small < big`
/// (refused otherwise). O(N).
///
/// ```
/// let t = gmap_ops::build::placed::torus_with_points(8, 4, 2.0, 0.7).unwrap();
/// assert_eq!(t.cell_counts(), vec![32, 64, 32]);
/// assert_eq!(t.euler_characteristic(), 0);
/// ```
pub fn torus_with_points(a: usize, b: usize, big: f64, small: f64) -> Result<DenseMap, BuildError> {
    if a < 3 || b < 3 || !(small > 0.0 && small < big && big.is_finite()) {
        return Err(BuildError::BadArgument(format!(
            "a torus of {a} × {b} squares with radii {big} and {small} (needs a, b >= 3 and 0 < small < big)"
        )));
    }
    let mut m = build::grid(&[a, b], &[true, true])?;
    // the layout of build::grid: dart = square * (2! 2^2) + ordering * 2^2 + corner bits
    for k in 0..m.dart_count() {
        let (sq, eps) = (k / 8, k % 4);
        let i = (sq % a + (eps & 1)) % a;
        let j = (sq / a + (eps >> 1 & 1)) % b;
        let (u, v) = (std::f64::consts::TAU * i as f64 / a as f64, std::f64::consts::TAU * j as f64 / b as f64);
        let r = big + small * v.cos();
        m.set_point(Dart::new(k as u32), Some([r * u.cos(), r * u.sin(), small * v.sin()]));
    }
    Ok(m)
}

/// [`build::cube`] with points: the corners of `[0, 1]^n` (for n = 0, one dart at the
/// origin). Precondition: `n <= 3`. O(N).
pub fn cube_with_points(n: usize) -> Result<DenseMap, BuildError> {
    if n == 0 {
        let mut m = build::cube(0)?;
        m.set_point(Dart::new(0), Some([0.0; 3]));
        return Ok(m);
    }
    grid_with_points(&vec![1; n], &vec![false; n])
}

/// [`build::simplex`] with points: one vertex at the origin and the others at the unit
/// vectors `e_1, …, e_n` (every bijection of its vertices is an automorphism of the simplex,
/// so any assignment is an embedding). Precondition: `n <= 3`. O(N).
pub fn simplex_with_points(n: usize) -> Result<DenseMap, BuildError> {
    if n > MAX_PLACED_DIM {
        return Err(too_high("a simplex", n));
    }
    let mut m = build::simplex(n)?;
    let verts = m.cells(0);
    for k in 0..m.dart_count() {
        let v = verts.of[k] as usize;
        let mut p: Point = [0.0; 3];
        if v > 0 {
            p[v - 1] = 1.0;
        }
        m.set_point(Dart::new(k as u32), Some(p));
    }
    Ok(m)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dist2(p: Point, q: Point) -> f64 {
        (0..3).map(|k| (p[k] - q[k]) * (p[k] - q[k])).sum()
    }

    /// Every dart of a vertex has the same point, and the squared length of every edge is
    /// one of `lengths`.
    fn check_points(m: &DenseMap, lengths: &[f64]) {
        let verts = m.cells(0);
        for d in m.darts() {
            let p = m.point(d).expect("every dart has a point");
            assert_eq!(Some(p), m.point(verts.reps[verts.of[d.index()] as usize]), "dart {d}");
            let q = m.point(m.alpha(d, 0)).unwrap();
            assert!(lengths.contains(&dist2(p, q)), "edge at dart {d}: {p:?} {q:?}");
        }
    }

    #[test]
    fn grids_sit_on_the_integer_points() {
        let m = grid_with_points(&[3, 2, 1], &[false; 3]).unwrap();
        check_points(&m, &[1.0]);
        let mut pts: Vec<[i64; 3]> = m.darts().map(|d| m.point(d).unwrap().map(|c| c as i64)).collect();
        pts.sort();
        pts.dedup();
        assert_eq!(pts.len(), 4 * 3 * 2);
        assert_eq!(pts.first(), Some(&[0, 0, 0]));
        assert_eq!(pts.last(), Some(&[3, 2, 1]));
        let square = grid_with_points(&[1, 1], &[false, false]).unwrap();
        check_points(&square, &[1.0]);
        // a periodic axis wraps: 3 distinct x values on a ring of 3 squares
        let ring = grid_with_points(&[3, 1], &[true, false]).unwrap();
        check_points(&ring, &[1.0, 4.0]);
        assert_eq!(ring.cells(0).len(), 6);
        assert!(grid_with_points(&[1; 4], &[false; 4]).is_err());
        assert!(grid_with_points(&[0, 1], &[false; 2]).is_err());
    }

    #[test]
    fn the_torus_is_embedded() {
        let t = torus_with_points(6, 4, 2.0, 0.5).unwrap();
        let verts = t.cells(0);
        assert_eq!(verts.len(), 24);
        let mut pts = Vec::new();
        for d in t.darts() {
            let p = t.point(d).unwrap();
            assert_eq!(Some(p), t.point(verts.reps[verts.of[d.index()] as usize]), "dart {d}");
            // on the torus: (sqrt(x² + y²) - 2)² + z² = 0.25
            let r = (p[0] * p[0] + p[1] * p[1]).sqrt();
            assert!(((r - 2.0).powi(2) + p[2] * p[2] - 0.25).abs() < 1e-12);
            pts.push(p.map(|c| (c * 1e9).round() as i64));
        }
        pts.sort();
        pts.dedup();
        // distinct vertices get distinct points
        assert_eq!(pts.len(), 24);
        assert!(torus_with_points(2, 4, 2.0, 0.5).is_err());
        assert!(torus_with_points(3, 3, 1.0, 1.0).is_err());
    }

    #[test]
    fn cubes_and_simplices_have_standard_corners() {
        for n in 0..=3 {
            let c = cube_with_points(n).unwrap();
            let s = simplex_with_points(n).unwrap();
            if n > 0 {
                // cube edges have length 1; simplex edges length 1 (from the origin) or √2
                check_points(&c, &[1.0]);
                check_points(&s, &[1.0, 2.0]);
            }
            assert_eq!(c.cells(0).len(), 1 << n);
            let mut pts: Vec<Point> = s.cells(0).reps.iter().map(|&d| s.point(d).unwrap()).collect();
            pts.sort_by(|a, b| a.partial_cmp(b).unwrap());
            let mut want: Vec<Point> = (0..=n)
                .map(|v| {
                    let mut p = [0.0; 3];
                    if v > 0 {
                        p[v - 1] = 1.0;
                    }
                    p
                })
                .collect();
            want.sort_by(|a, b| a.partial_cmp(b).unwrap());
            assert_eq!(pts, want);
        }
        assert!(simplex_with_points(4).is_err());
        assert!(cube_with_points(4).is_err());
    }
}
