//! Triangulations: a face cut into triangles, by a fan of edges from one corner or around a
//! new vertex at its barycentre (Moka's face triangulations), and a convex volume cut into
//! tetrahedra. All are subdivisions made of the Euler operators of [`crate::euler::ops`], so
//! the space and its homology do not change (Δχ = 0, asserted in the tests), and the
//! attributes follow those operators' rules (the part holding the dart given keeps the
//! cell's attribute, the other parts get copies through the split hook).

use gmap_core::{Attributes, DartId, GMap, Point};

use super::ConstructError;
use crate::euler::ops::{try_insert_edge, try_star_cell, EulerError};

/// The corners of the face of `d` in order: `d`, then `alpha_1 alpha_0` repeatedly, one dart
/// per corner on the side of `d`, until the walk comes back. Refused when the boundary has a
/// free dart or the face has fewer than three corners.
fn corners<A: Attributes>(g: &GMap<A>, d: DartId) -> Result<Vec<DartId>, ConstructError> {
    if !g.contains(d) {
        return Err(ConstructError::NoSuchDart(d));
    }
    if g.dim() < 2 {
        return Err(ConstructError::BadDimension { what: "a face triangulation", lo: 2, hi: g.dim(), got: 2 });
    }
    let mut out = vec![d];
    let mut x = d;
    loop {
        let y = g.alpha(x, 0);
        if y == x {
            return Err(ConstructError::Euler(EulerError::Free { dart: x, alpha: 0 }));
        }
        let z = g.alpha(y, 1);
        if z == y {
            return Err(ConstructError::Euler(EulerError::Free { dart: y, alpha: 1 }));
        }
        if z == d {
            break;
        }
        if out.len() > g.dart_count() {
            return Err(ConstructError::BadShape { dart: d, what: "a closed polygon" });
        }
        out.push(z);
        x = z;
    }
    if out.len() < 3 {
        return Err(ConstructError::BadShape { dart: d, what: "a polygon of three sides or more" });
    }
    Ok(out)
}

/// Whether [`try_triangulate_face_fan`] would succeed: `d` is live, `n >= 2`, and the face
/// of `d` is a closed polygon of three sides or more (no free dart on its boundary). A
/// polygon with a repeated vertex may still be refused by the edge insertions. O(face size).
pub fn can_triangulate_face_fan<A: Attributes>(g: &GMap<A>, d: DartId) -> bool {
    corners(g, d).is_ok()
}

/// Cuts the face of `d`, a k-gon, into `k - 2` triangles by `k - 3` edges from the corner of
/// `d`'s vertex (Moka's fan triangulation of a face; on both sides when the face is shared
/// by two volumes). Returns the number of edges inserted. Each edge is a `mef` (Δχ = 0).
/// The triangle holding `alpha_0(d)` keeps the face's attribute. O(k² · n).
pub fn try_triangulate_face_fan<A: Attributes>(g: &mut GMap<A>, d: DartId) -> Result<usize, ConstructError> {
    let c = corners(g, d)?;
    // the apex corner is seen from the last side (between alpha_1(d) and d): that dart stays
    // in the part that keeps the corners not yet reached
    let apex = g.alpha(d, 1);
    for &corner in &c[2..c.len() - 1] {
        try_insert_edge(g, apex, corner)?;
    }
    Ok(c.len() - 3)
}

/// Like [`try_triangulate_face_fan`], panicking when the precondition fails.
#[track_caller]
pub fn triangulate_face_fan<A: Attributes>(g: &mut GMap<A>, d: DartId) -> usize {
    try_triangulate_face_fan(g, d).unwrap_or_else(|e| panic!("triangulate_face_fan: {e}"))
}

/// Whether [`try_triangulate_face_barycentric`] would succeed: as
/// [`can_triangulate_face_fan`]. O(face size).
pub fn can_triangulate_face_barycentric<A: Attributes>(g: &GMap<A>, d: DartId) -> bool {
    corners(g, d).is_ok()
}

/// Cuts the face of `d`, a k-gon, into k triangles around a new vertex at its barycentre
/// (CGAL's `insert_barycenter_in_cell<2>`, Moka's barycentric triangulation; the vertex
/// has no point when a corner has none). Returns a dart of the new vertex. Δχ = 0
/// (+1 vertex, +k edges, +(k - 1) faces). O(k · n).
pub fn try_triangulate_face_barycentric<A: Attributes>(g: &mut GMap<A>, d: DartId) -> Result<DartId, ConstructError> {
    corners(g, d)?;
    let at = g.barycenter(d, 2);
    Ok(try_star_cell(g, d, 2, at)?.vertex)
}

/// Like [`try_triangulate_face_barycentric`], panicking when the precondition fails.
#[track_caller]
pub fn triangulate_face_barycentric<A: Attributes>(g: &mut GMap<A>, d: DartId) -> DartId {
    try_triangulate_face_barycentric(g, d).unwrap_or_else(|e| panic!("triangulate_face_barycentric: {e}"))
}

/// One dart per face of the volume of `d`, on the volume's side: the orbits of
/// `alpha_0, alpha_1` inside the volume's orbit of `alpha_0, alpha_1, alpha_2`.
fn volume_faces<A: Attributes>(g: &GMap<A>, d: DartId) -> Vec<DartId> {
    let volume = g.orbit(d, gmap_core::AlphaSet::range(0, 2));
    let mut seen: rustc_hash::FxHashSet<DartId> = rustc_hash::FxHashSet::default();
    let mut faces = Vec::new();
    for x in volume {
        if seen.insert(x) {
            faces.push(x);
            seen.extend(g.orbit(x, gmap_core::AlphaSet::range(0, 1)));
        }
    }
    faces
}

/// The barycentre of the volume of `d` and the checked faces, or why not.
fn check_volume<A: Attributes>(g: &GMap<A>, d: DartId) -> Result<(Point, Vec<DartId>), ConstructError> {
    if !g.contains(d) {
        return Err(ConstructError::NoSuchDart(d));
    }
    if g.dim() < 3 {
        return Err(ConstructError::BadDimension { what: "a tetrahedralization", lo: 3, hi: g.dim(), got: 3 });
    }
    let faces = volume_faces(g, d);
    for &f in &faces {
        corners(g, f)?;
        if let Some(x) = g.orbit(f, gmap_core::AlphaSet::range(0, 1)).into_iter().find(|&x| g.is_free(x, 2)) {
            return Err(ConstructError::Euler(EulerError::Free { dart: x, alpha: 2 }));
        }
    }
    let c = g.barycenter(d, 3).ok_or(ConstructError::NoPoint(d))?;
    let volume = g.orbit(d, gmap_core::AlphaSet::range(0, 2));
    if let Some(&x) = volume.iter().find(|&&x| g.point(x).is_none()) {
        return Err(ConstructError::NoPoint(x));
    }
    check_convex(g, d, c, &faces, &volume)?;
    Ok((c, faces))
}

/// The normal of the polygon `p` by Newell's formula (twice its vector area): the plane's
/// normal for a planar polygon, whatever its convexity. O(|p|).
fn newell(p: &[Point]) -> Point {
    let mut n = [0.0; 3];
    for (j, a) in p.iter().enumerate() {
        let b = p[(j + 1) % p.len()];
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    n
}

fn dot(a: Point, b: Point) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn sub(a: Point, b: Point) -> Point {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// Checks that the volume of `d` (darts `volume`, faces `faces`, barycentre `c`) is convex:
/// for every face, the barycentre is strictly on one side of the face's plane and every
/// vertex of the volume on that side or on the plane, up to a tolerance of 1e-9 of the
/// volume's extent. This also refuses faces that are not planar (a vertex of the face off
/// its plane) and flat volumes. [`ConstructError::NotConvex`] names the volume by `d`.
/// O(faces · volume size).
fn check_convex<A: Attributes>(
    g: &GMap<A>,
    d: DartId,
    c: Point,
    faces: &[DartId],
    volume: &[DartId],
) -> Result<(), ConstructError> {
    let point = |x: DartId| g.point(x).expect("checked");
    let extent = volume.iter().map(|&x| sub(point(x), c)).map(|v| dot(v, v).sqrt()).fold(0.0, f64::max);
    let tol = 1e-9 * extent.max(f64::MIN_POSITIVE);
    for &f in faces {
        let ring: Vec<Point> = corners(g, f)?.into_iter().map(point).collect();
        let n = newell(&ring);
        let len = dot(n, n).sqrt();
        let not_convex = |vertex| ConstructError::NotConvex { volume: d, face: f, vertex };
        if len.is_nan() || len <= 0.0 {
            return Err(not_convex(f));
        }
        let n = n.map(|x| x / len);
        let p0 = ring[0];
        // the side of the barycentre: the inside
        let inside = dot(n, sub(c, p0));
        if inside.abs() <= tol {
            return Err(not_convex(f));
        }
        let s = inside.signum();
        if let Some(&x) = volume.iter().find(|&&x| s * dot(n, sub(point(x), p0)) < -tol) {
            return Err(not_convex(x));
        }
    }
    Ok(())
}

/// Whether [`try_tetrahedralize_volume`] would succeed: `n >= 3`, the volume of `d` is
/// closed (no 2-free dart), every face of it a closed polygon, every vertex with a point,
/// and the volume convex (every vertex on the inner side of every face's plane, the
/// barycentre strictly inside; see [`ConstructError::NotConvex`]). O(faces · volume size).
pub fn can_tetrahedralize_volume<A: Attributes>(g: &GMap<A>, d: DartId) -> bool {
    check_volume(g, d).is_ok()
}

/// Cuts the convex volume of `d` into tetrahedra (a volume that is not convex is refused
/// with [`ConstructError::NotConvex`], nothing changed): every face of more than three sides fanned
/// ([`try_triangulate_face_fan`], also on the neighbouring volume's side), then a vertex at
/// the volume's barycentre joined to every triangle (CGAL's
/// `insert_barycenter_in_cell<3>`). A volume with f triangles after the fans becomes f
/// tetrahedra. Returns a dart of the new vertex. Δχ = 0. O(volume size² · n).
pub fn try_tetrahedralize_volume<A: Attributes>(g: &mut GMap<A>, d: DartId) -> Result<DartId, ConstructError> {
    let (c, faces) = check_volume(g, d)?;
    for f in faces {
        try_triangulate_face_fan(g, f)?;
    }
    Ok(try_star_cell(g, d, 3, Some(c))?.vertex)
}

/// Like [`try_tetrahedralize_volume`], panicking when the precondition fails.
#[track_caller]
pub fn tetrahedralize_volume<A: Attributes>(g: &mut GMap<A>, d: DartId) -> DartId {
    try_tetrahedralize_volume(g, d).unwrap_or_else(|e| panic!("tetrahedralize_volume: {e}"))
}
