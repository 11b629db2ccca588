//! An architectural complex cut into the cells of a regular cell complex of the same space,
//! for the writers that go through a G-map (`.gmap`, `.moka`, `.facets`, `.lar.json`, …).
//!
//! The flag construction ([`FacePoset::to_gmap`]) reads a face poset as a *regular* complex:
//! every cell a ball whose boundary is a sphere. A region of an architectural complex need
//! not be one (AC Def. 8.1): a wall with a window is a 2-region whose boundary is two
//! circles, a floor around a court an annulus. Read as a cell, such a region would come out
//! as one disk per boundary circle, another space. Here every region is checked and, where
//! the space is known, cut:
//!
//! - a 1-region with two vertices is a cell; a loop (one vertex) or a closed 1-region (none)
//!   is cut in two edges at a new vertex;
//! - a 2-region whose boundary is `k` disjoint circles is, as Algorithm 8.16 reads it
//!   ([`ArchComplex::region_betti`]), a sphere with `k` holes: `k = 1` is a cell; for
//!   `k >= 2` each circle is split in two arcs at two of its vertices and `k` new edges join
//!   the circles in a ring (the end of one circle's upper arc to the start of the next's),
//!   which cuts the region in two disks, one over the upper arcs, one over the lower arcs
//!   (Euler characteristic `2 - k`, as the sphere with `k` holes); `k = 0` (a closed
//!   region, a sphere) becomes two disks on a new circle of two edges;
//! - a region of dimension 3 or more takes the pieces of its faces; its boundary must then
//!   be a sphere (a closed connected 2-map of Euler characteristic 2 in dimension 3, the
//!   homology of a sphere above).
//!
//! Every other case is refused, naming the region by its id and `name` label and saying
//! why: an entry across a dimension gap or of a weight other than ±1 (a regular complex
//! meets each face of a cell once), a boundary that is not a union of circles, Betti
//! numbers given to the region that are not those of a sphere with holes (a surface of
//! genus g ≥ 1), a region of dimension 3 or more with a cavity or whose boundary is not a
//! sphere. The space written is then that of `gmap homology --topological`.
//!
//! O(R + E) for regions of dimension ≤ 2; a region of dimension d ≥ 3 costs the G-map of
//! its boundary (O(flags of the boundary · d)).

use std::collections::HashMap;

use gmap_homology::arch::ArchComplex;
use gmap_ops::import::{FacePoset, PosetError};

use crate::error::{err, Error, Result};

/// The cells of a regular complex of the space of an architectural complex: the face
/// poset, and for each of its cells the index of the region it is (a part of).
#[derive(Clone, Debug)]
pub(crate) struct Cells {
    /// the face poset (covering pairs between consecutive dimensions)
    pub poset: FacePoset,
    /// the region index of each cell of `poset`; the first `regions().len()` cells are the
    /// regions themselves (or the first of their pieces)
    pub origin: Vec<usize>,
    /// the faces of each cell (the covers, from above)
    down: Vec<Vec<usize>>,
    /// the regions of dimension ≥ 3, whose boundaries [`check_solids`] checks
    solids: Vec<usize>,
}

/// The name of region `r` in messages: `region 7 (kitchen)`, `region door`: the file's id
/// (string or number) and its `name` label ([`ArchComplex::region_name`]).
pub(crate) fn region_name(x: &ArchComplex, r: usize) -> String {
    format!("region {}", x.region_name(r))
}

fn refuse(x: &ArchComplex, r: usize, why: impl std::fmt::Display) -> Error {
    err!(Precondition, "{}: {why}", region_name(x, r))
}

struct Builder {
    poset: FacePoset,
    origin: Vec<usize>,
    down: Vec<Vec<usize>>,
}

impl Builder {
    fn cell(&mut self, dim: usize, origin: usize) -> usize {
        self.origin.push(origin);
        self.down.push(Vec::new());
        self.poset.add_cell(dim)
    }

    fn cover(&mut self, higher: usize, lower: usize) {
        self.down[higher].push(lower);
        self.poset.add_cover(higher, lower);
    }
}

/// The cells of `x` (module docs), or the refusal naming the region that cannot be cut.
pub(crate) fn cells(x: &ArchComplex) -> Result<Cells> {
    let nr = x.regions().len();
    let mut b = Builder { poset: FacePoset::new(), origin: Vec::with_capacity(nr), down: Vec::with_capacity(nr) };
    for (r, reg) in x.regions().iter().enumerate() {
        b.cell(reg.dim, r);
    }
    for e in x.entries() {
        let (f, t) = (x.region(e.from), x.region(e.to));
        if f.dim != t.dim + 1 {
            return Err(refuse(
                x,
                e.from,
                format_args!(
                    "its entry to {} (dimension {}) crosses a dimension gap: where that region lies inside this {}-region is not recorded, so it cannot be cut into cells",
                    region_name(x, e.to),
                    t.dim,
                    f.dim
                ),
            ));
        }
        if e.weight.abs() != 1 {
            return Err(refuse(
                x,
                e.from,
                format_args!(
                    "its entry to {} has weight {}: a cell of a regular complex meets each face of its boundary once (weight 1 or -1), so the cells written would be another space",
                    region_name(x, e.to),
                    e.weight
                ),
            ));
        }
    }
    // the cells each region became, dimension by dimension
    let mut pieces: Vec<Vec<usize>> = (0..nr).map(|r| vec![r]).collect();
    for d in 1..=x.dim() {
        for &r in x.regions_of_dim(d) {
            let r = r as usize;
            let faces: Vec<usize> = x.down(r).iter().flat_map(|e| pieces[e.to].iter().copied()).collect();
            pieces[r] = match d {
                1 => edge(x, &mut b, r, &faces)?,
                2 => face(x, &mut b, r, &faces)?,
                _ => solid(x, &mut b, r, &faces)?,
            };
        }
    }
    let solids = (3..=x.dim()).flat_map(|d| x.regions_of_dim(d).iter().map(|&r| r as usize)).collect();
    Ok(Cells { poset: b.poset, origin: b.origin, down: b.down, solids })
}

/// Checks that the boundary of every region of dimension d ≥ 3 is a (d-1)-sphere (module
/// docs). Made after the whole complex's G-map passed its size and memory checks, since
/// each boundary is a G-map of its own. O(Σ flags of the boundaries · d).
pub(crate) fn check_solids(x: &ArchComplex, c: &Cells, max_darts: u64) -> Result<()> {
    for &r in &c.solids {
        solid_boundary(x, c, r, max_darts)?;
    }
    Ok(())
}

/// A 1-region over its vertices: a cell with two; cut at a new vertex with one or none.
fn edge(x: &ArchComplex, b: &mut Builder, r: usize, vertices: &[usize]) -> Result<Vec<usize>> {
    match *vertices {
        [v, w] => {
            b.cover(r, v);
            b.cover(r, w);
            Ok(vec![r])
        }
        [v] => {
            let w = b.cell(0, r);
            let second = b.cell(1, r);
            for e in [r, second] {
                b.cover(e, v);
                b.cover(e, w);
            }
            Ok(vec![r, second])
        }
        [] => {
            let (v, w) = (b.cell(0, r), b.cell(0, r));
            let second = b.cell(1, r);
            for e in [r, second] {
                b.cover(e, v);
                b.cover(e, w);
            }
            Ok(vec![r, second])
        }
        _ => Err(refuse(x, r, format_args!("an edge with {} vertices is not a cell (2 expected)", vertices.len()))),
    }
}

/// A 2-region over the edges of its boundary: a cell when they make one circle; a sphere
/// with k holes cut in two disks by a ring of k new edges (module docs).
fn face(x: &ArchComplex, b: &mut Builder, r: usize, edges: &[usize]) -> Result<Vec<usize>> {
    let circles = boundary_circles(x, b, r, edges)?;
    let k = circles.len();
    if x.has_region_betti(r) {
        let betti = x.region_betti(r);
        let planar = if k == 0 { vec![1, 0, 1] } else { vec![1, k - 1, 0] };
        if betti != planar {
            return Err(refuse(
                x,
                r,
                format_args!(
                    "a 2-region with Betti numbers ({}) and {k} boundary circle(s) is a surface of higher genus, which is not cut into cells here; give it as cells (gmap homology --topological computes its space)",
                    betti.iter().map(usize::to_string).collect::<Vec<_>>().join(", ")
                ),
            ));
        }
    }
    Ok(match k {
        0 => sphere_cells(b, r),
        1 => {
            for &e in edges {
                b.cover(r, e);
            }
            vec![r]
        }
        _ => holed_disk_cells(b, r, &circles),
    })
}

/// The circles of a 2-region's boundary edges, each as its (vertex, edge to the next
/// vertex) in order; refused where a vertex is not on exactly two of the edges.
fn boundary_circles(x: &ArchComplex, b: &Builder, r: usize, edges: &[usize]) -> Result<Vec<Vec<(usize, usize)>>> {
    let mut at: HashMap<usize, Vec<usize>> = HashMap::new();
    for &e in edges {
        for &v in &b.down[e] {
            at.entry(v).or_default().push(e);
        }
    }
    let mut vertices: Vec<usize> = at.keys().copied().collect();
    vertices.sort_unstable();
    if let Some(&v) = vertices.iter().find(|v| at[v].len() != 2) {
        return Err(refuse(
            x,
            r,
            format_args!(
                "its boundary is not a union of circles: {} lies on {} of its boundary edges (2 expected), so the region is not a surface with holes that can be cut into cells",
                cell_name(x, &b.origin, v),
                at[&v].len()
            ),
        ));
    }
    let mut seen_edge: HashMap<usize, ()> = HashMap::new();
    let mut circles: Vec<Vec<(usize, usize)>> = Vec::new();
    let mut on_circle: HashMap<usize, ()> = HashMap::new();
    for &start in &vertices {
        if on_circle.contains_key(&start) {
            continue;
        }
        let mut circle = Vec::new();
        let mut v = start;
        loop {
            on_circle.insert(v, ());
            let Some(&e) = at[&v].iter().find(|e| !seen_edge.contains_key(e)) else { break };
            seen_edge.insert(e, ());
            circle.push((v, e));
            let ends = &b.down[e];
            v = if ends[0] == v { ends[1] } else { ends[0] };
            if v == start {
                break;
            }
        }
        circles.push(circle);
    }
    Ok(circles)
}

/// A 2-region without boundary (a sphere): two disks on a circle of two new edges.
fn sphere_cells(b: &mut Builder, r: usize) -> Vec<usize> {
    let (v, w) = (b.cell(0, r), b.cell(0, r));
    let (e1, e2) = (b.cell(1, r), b.cell(1, r));
    let other = b.cell(2, r);
    for e in [e1, e2] {
        b.cover(e, v);
        b.cover(e, w);
        b.cover(r, e);
        b.cover(other, e);
    }
    vec![r, other]
}

/// A sphere with k ≥ 2 holes cut in two disks: circle i split at its vertex 0 (l_i) and its
/// vertex m_i / 2 (r_i); the ring of new edges joins r_i to l_{i+1}.
fn holed_disk_cells(b: &mut Builder, r: usize, circles: &[Vec<(usize, usize)>]) -> Vec<usize> {
    let lower = b.cell(2, r);
    for (i, c) in circles.iter().enumerate() {
        let half = c.len() / 2;
        for (k, &(_, e)) in c.iter().enumerate() {
            b.cover(if k < half { r } else { lower }, e);
        }
        let next = &circles[(i + 1) % circles.len()];
        let ring = b.cell(1, r);
        b.cover(ring, c[half].0);
        b.cover(ring, next[0].0);
        b.cover(r, ring);
        b.cover(lower, ring);
    }
    vec![r, lower]
}

/// A region of dimension d ≥ 3 over the pieces of its faces: a cell when they make a sphere.
fn solid(x: &ArchComplex, b: &mut Builder, r: usize, faces: &[usize]) -> Result<Vec<usize>> {
    let d = x.region(r).dim;
    let betti = x.region_betti(r);
    let mut ball = vec![0; d + 1];
    ball[0] = 1;
    if faces.is_empty() {
        return Err(refuse(
            x,
            r,
            format_args!("a closed {d}-region (no boundary recorded) is not cut into cells here; give its boundary"),
        ));
    }
    if betti != ball {
        let list = betti.iter().map(usize::to_string).collect::<Vec<_>>().join(", ");
        return Err(refuse(
            x,
            r,
            format_args!(
                "a {d}-region with Betti numbers ({list}) is not a ball and is not cut into cells here (gmap homology --topological computes its space)"
            ),
        ));
    }
    for &f in faces {
        b.cover(r, f);
    }
    Ok(vec![r])
}

/// The boundary of region `r` (dimension d ≥ 3) is a (d-1)-sphere, or the refusal.
fn solid_boundary(x: &ArchComplex, b: &Cells, r: usize, max_darts: u64) -> Result<()> {
    let d = x.region(r).dim;
    let (sub, members) = boundary_poset(b, r);
    let m = sub.to_gmap(max_darts).map_err(|e| {
        let named = poset_error(x, &b.origin, &e, |k| members.get(k).copied());
        err!(Precondition, "{}: its boundary is not a closed surface of cells: {named}", region_name(x, r))
    })?;
    let not_sphere = |what: String| {
        refuse(
            x,
            r,
            format_args!(
                "its boundary is not a sphere ({what}), so the {d}-region is not a ball and is not cut into cells here"
            ),
        )
    };
    if let Some(dart) = m.darts().find(|&dart| m.is_free(dart, d - 1)) {
        return Err(not_sphere(format!("it has an open edge at flag {}", dart.index())));
    }
    let (counts, components) = m.cell_counts_and_components();
    if components != 1 {
        return Err(not_sphere(format!("{components} components: a {d}-region with a cavity")));
    }
    if d == 3 {
        let chi = counts[0] as i64 - counts[1] as i64 + counts[2] as i64;
        if chi != 2 {
            return Err(not_sphere(format!("Euler characteristic {chi}, 2 expected")));
        }
    } else {
        let h = gmap_homology::cellular_complex(&m)
            .map_err(|e| Error::from_source(crate::ErrorKind::Compute, e))
            .and_then(|c| {
                gmap_homology::homology::homology_z(&c.chain)
                    .map_err(|e| Error::from_source(crate::ErrorKind::Compute, e))
            })?;
        let mut sphere = vec![0; d];
        (sphere[0], sphere[d - 1]) = (1, 1);
        if h.betti != sphere || h.torsion.iter().any(|t| !t.is_empty()) {
            return Err(not_sphere(format!(
                "homology ({})",
                (0..d).map(|k| h.group_string(k)).collect::<Vec<_>>().join(", ")
            )));
        }
    }
    Ok(())
}

/// The cells below region `r` as a face poset of their own, with the cell each of its
/// cells is.
fn boundary_poset(b: &Cells, r: usize) -> (FacePoset, Vec<usize>) {
    let mut index: HashMap<usize, usize> = HashMap::new();
    let mut stack: Vec<usize> = b.down[r].clone();
    let mut sub = FacePoset::new();
    let mut members = Vec::new();
    while let Some(c) = stack.pop() {
        if index.contains_key(&c) {
            continue;
        }
        index.insert(c, sub.add_cell(b.poset.dims[c]));
        members.push(c);
        stack.extend(b.down[c].iter().copied());
    }
    for &c in &members {
        for &f in &b.down[c] {
            sub.add_cover(index[&c], index[&f]);
        }
    }
    (sub, members)
}

/// The name of cell `c` of the poset being built: its region, or a piece of one.
fn cell_name(x: &ArchComplex, origin: &[usize], c: usize) -> String {
    if c < x.regions().len() {
        region_name(x, c)
    } else {
        format!("a new cell cutting {}", region_name(x, origin[c]))
    }
}

/// A poset refusal with the cells named by the file's regions (`cell` maps the poset's
/// numbers to the builder's).
fn poset_error(x: &ArchComplex, origin: &[usize], e: &PosetError, cell: impl Fn(usize) -> Option<usize>) -> String {
    let name = |k: usize| cell(k).map_or_else(|| format!("cell {k}"), |c| cell_name(x, origin, c));
    match *e {
        PosetError::Diamond { lower, upper, dim, count } => {
            format!("{count} cells of dimension {dim} lie between {} and {} (2 expected)", name(lower), name(upper))
        }
        PosetError::TooManyCofaces { cell, dim, count } => {
            format!("{} of dimension {dim} lies in {count} cells of dimension {} (at most 2)", name(cell), dim + 1)
        }
        PosetError::NotPure { cell, dim, top } => {
            format!("{} of dimension {dim} is not part of any {top}-region: the complex is not pure", name(cell))
        }
        PosetError::EdgeVertices { edge, vertices } => format!("{} has {vertices} vertices, not 2", name(edge)),
        ref other => other.to_string(),
    }
}

/// [`poset_error`] over the whole complex's cells.
pub(crate) fn name_poset_error(x: &ArchComplex, c: &Cells, e: &PosetError) -> String {
    poset_error(x, &c.origin, e, Some)
}
