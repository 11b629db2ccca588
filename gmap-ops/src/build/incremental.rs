//! Building a linear cell complex volume by volume, as CGAL's
//! `Linear_cell_complex_incremental_builder_3`, and sewing the free faces of a whole map
//! that have the same points ([`sew3_same_facets`], CGAL's name).
//!
//! [`IncrementalBuilder`] adds to a [`GMap`] of dimension at least 2. The calls follow
//! CGAL's grammar
//!
//! ```text
//! ( add_vertex | begin_surface ( add_vertex | begin_facet add_vertex_to_facet* end_facet | add_facet )* end_surface )*
//! ```
//!
//! A facet is a polygon on vertex indices (the order of [`IncrementalBuilder::add_vertex`]
//! calls); the facets of one surface that share an edge are 2-sewn along it (an edge in
//! three facets of a surface is refused). At `end_surface` every vertex of the surface gets
//! its point and, in a map of dimension 3 or more, every face of the surface is offered to
//! the faces of the earlier surfaces: a face with the same vertices is 3-sewn to it, the
//! darts paired at equal vertices whatever the two faces' orientations; a third face on the
//! same vertices is refused. Faces are matched by a hash map keyed by their sorted vertex
//! ids (`crate::mesh` matching, shared with the mesh readers and [`sew3_same_facets`]).
//!
//! ```
//! use gmap_core::GMap;
//! use gmap_ops::build::IncrementalBuilder;
//! // CGAL's example: a cube, and a pyramid on one of its faces
//! let mut g = GMap::new(3);
//! let mut b = IncrementalBuilder::new(&mut g).unwrap();
//! for p in [[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.],
//!           [0., 1., 1.], [0., 0., 1.], [1., 0., 1.], [1., 1., 1.]] {
//!     b.add_vertex(p);
//! }
//! b.begin_surface().unwrap();
//! for f in [[0, 1, 2, 3], [1, 0, 5, 6], [2, 1, 6, 7], [3, 2, 7, 4], [0, 3, 4, 5], [5, 4, 7, 6]] {
//!     b.add_facet(&f).unwrap();
//! }
//! b.end_surface().unwrap();
//! b.add_vertex([-1., 0.5, 0.5]);
//! b.begin_surface().unwrap();
//! for f in [&[3, 0, 5, 4][..], &[0, 3, 8], &[3, 4, 8], &[4, 5, 8], &[5, 0, 8]] {
//!     b.add_facet(f).unwrap();
//! }
//! b.end_surface().unwrap();
//! let dense = g.to_dense_map();
//! assert_eq!(dense.cell_counts(), vec![9, 16, 10, 2]);
//! assert_eq!(
//!     g.characteristics().to_string(),
//!     "#Darts=80, #0-cells=9, #1-cells=16, #2-cells=10, #3-cells=2, #ccs=1, orientable=true, valid=1"
//! );
//! ```
//!
//! Costs: `end_facet` O(k n) for k vertices plus the expected O(k) edge lookups;
//! `end_surface` O(darts of the surface · n) for the points and one sew per face.

use gmap_core::{Attributes, DartId, GMap, Point};
use rustc_hash::FxHashMap;
use smallvec::SmallVec;

use crate::mesh::error::MeshError;
use crate::mesh::matching::{Facet, FacetMatcher, Offer};

/// The surface being built.
struct Surface {
    /// its edges, matched between its facets
    edges: FacetMatcher<DartId>,
    /// its facets as offered to the faces of the earlier surfaces
    facets: Vec<Facet<DartId>>,
    /// its darts with their vertex
    darts: Vec<(DartId, u32)>,
}

/// Builds volumes from facets on indexed vertices, 2-sewing the facets of a surface and
/// 3-sewing faces of neighbouring surfaces (see the module documentation).
pub struct IncrementalBuilder<'a, A: Attributes = ()> {
    map: &'a mut GMap<A>,
    points: Vec<Point>,
    faces: FacetMatcher<DartId>,
    surface: Option<Surface>,
    facet: Option<SmallVec<[u32; 8]>>,
    /// surfaces ended so far (the index of the current one)
    surfaces: usize,
    /// facets ended so far, over all surfaces
    facets: usize,
    /// the vertex of every dart made, by [`GMap::dart_index`] (`u32::MAX`: not made here)
    vertex: Vec<u32>,
}

impl<'a, A: Attributes> IncrementalBuilder<'a, A> {
    /// A builder adding to `map`, which must have dimension 2 or more.
    pub fn new(map: &'a mut GMap<A>) -> Result<Self, MeshError> {
        if map.dim() < 2 {
            return Err(MeshError::Order(format!("the builder needs a map of dimension 2 or more, not {}", map.dim())));
        }
        let dim = map.dim();
        Ok(IncrementalBuilder {
            map,
            points: Vec::new(),
            faces: FacetMatcher::new(3.min(dim)),
            surface: None,
            facet: None,
            surfaces: 0,
            facets: 0,
            vertex: Vec::new(),
        })
    }

    /// Adds a vertex at `p` and returns its index (0, 1, 2, … in call order). It becomes a
    /// vertex of the map when a facet uses it. O(1).
    pub fn add_vertex(&mut self, p: impl gmap_core::IntoPoint) -> usize {
        self.points.push(p.into_point());
        self.points.len() - 1
    }

    /// The number of vertices added.
    pub fn vertex_count(&self) -> usize {
        self.points.len()
    }

    /// Starts a surface (a volume's boundary). Error: a surface already begun.
    pub fn begin_surface(&mut self) -> Result<(), MeshError> {
        if self.surface.is_some() {
            return Err(MeshError::Order("begin_surface inside a surface".into()));
        }
        self.surface = Some(Surface { edges: FacetMatcher::new(2), facets: Vec::new(), darts: Vec::new() });
        Ok(())
    }

    /// Starts a facet of the current surface. Error: no surface begun, or a facet begun.
    pub fn begin_facet(&mut self) -> Result<(), MeshError> {
        if self.surface.is_none() {
            return Err(MeshError::Order("begin_facet outside a surface".into()));
        }
        if self.facet.is_some() {
            return Err(MeshError::Order("begin_facet inside a facet".into()));
        }
        self.facet = Some(SmallVec::new());
        Ok(())
    }

    /// Adds vertex `i` as the next corner of the current facet. Error: no facet begun, or
    /// `i` not a vertex index.
    pub fn add_vertex_to_facet(&mut self, i: usize) -> Result<(), MeshError> {
        let points = self.points.len();
        let owner = self.facet_owner();
        let f = self.facet.as_mut().ok_or_else(|| MeshError::Order("add_vertex_to_facet outside a facet".into()))?;
        if i >= points {
            return Err(MeshError::NoSuchVertex { cell: owner, vertex: i as u64, points });
        }
        f.push(i as u32);
        Ok(())
    }

    /// The cell a facet's errors name: the surface in dimension 3 and more, the facet in
    /// dimension 2.
    fn facet_owner(&self) -> usize {
        if self.map.dim() >= 3 {
            self.surfaces
        } else {
            self.facets
        }
    }

    /// Ends the current facet: makes its polygon (`2k` darts) and 2-sews it to the facets of
    /// the surface that share an edge with it. Returns the dart at its first vertex on the
    /// edge to its second. Errors: no facet begun; fewer than three vertices or a vertex
    /// twice ([`MeshError::BadCell`]); an edge in a third facet of the surface (in dimension
    /// 2 [`MeshError::FacetInManyCells`], naming facets; in dimension 3, a
    /// [`MeshError::BadCell`] naming the surface). After an error the facet is dropped.
    pub fn end_facet(&mut self) -> Result<DartId, MeshError> {
        let cycle = self.facet.take().ok_or_else(|| MeshError::Order("end_facet outside a facet".into()))?;
        let owner = self.facet_owner();
        let k = cycle.len();
        let bad = |reason: String| MeshError::BadCell { cell: owner, kind: "facet".into(), reason };
        if k < 3 {
            return Err(bad(format!("a facet needs 3 vertices or more, this one has {k}")));
        }
        let mut sorted = cycle.clone();
        sorted.sort_unstable();
        if let Some(w) = sorted.windows(2).find(|w| w[0] == w[1]) {
            return Err(bad(format!("vertex {} appears twice", w[0])));
        }
        let darts: Vec<DartId> = (0..2 * k).map(|_| self.map.create_dart()).collect();
        for j in 0..k {
            self.map.link(darts[2 * j], darts[2 * j + 1], 0);
            self.map.link(darts[2 * j + 1], darts[(2 * j + 2) % (2 * k)], 1);
        }
        for (j, &d) in darts.iter().enumerate() {
            let v = cycle[j.div_ceil(2) % k];
            let at = self.map.dart_index(d);
            if self.vertex.len() <= at {
                self.vertex.resize(at + 1, u32::MAX);
            }
            self.vertex[at] = v;
        }
        let dim = self.map.dim();
        let facet_index = self.facets;
        self.facets += 1;
        let surface = self.surface.as_mut().expect("a facet lies in a surface");
        surface.darts.extend(darts.iter().enumerate().map(|(j, &d)| (d, cycle[j.div_ceil(2) % k])));
        for j in 0..k {
            let (a, b) = (darts[2 * j], darts[2 * j + 1]);
            let edge = Facet {
                owner: facet_index,
                cycle: [cycle[j], cycle[(j + 1) % k]].into_iter().collect(),
                fwd: [a, b].into_iter().collect(),
                back: [a, b].into_iter().collect(),
            };
            match surface.edges.offer(edge) {
                Ok(Offer::Waiting) => {}
                Ok(Offer::Matched { darts: (x, y), .. }) => {
                    self.map.try_sew(x, y, 2).map_err(|e| MeshError::Map(e.to_string()))?;
                }
                Err(e) if dim >= 3 => {
                    return Err(MeshError::BadCell { cell: owner, kind: "surface".into(), reason: e.to_string() })
                }
                Err(e) => return Err(e),
            }
        }
        surface.facets.push(Facet {
            owner,
            cycle: cycle.iter().copied().collect(),
            fwd: (0..k).map(|j| darts[2 * j]).collect(),
            back: (0..k).map(|j| darts[(2 * j + 2 * k - 1) % (2 * k)]).collect(),
        });
        Ok(darts[0])
    }

    /// `begin_facet`, `add_vertex_to_facet` for each index, `end_facet`.
    pub fn add_facet(&mut self, vertices: &[usize]) -> Result<DartId, MeshError> {
        self.begin_facet()?;
        for &v in vertices {
            if let Err(e) = self.add_vertex_to_facet(v) {
                self.facet = None;
                return Err(e);
            }
        }
        self.end_facet()
    }

    /// Ends the current surface: gives its vertices their points and, in dimension 3 and
    /// more, 3-sews each of its faces to the face of an earlier surface on the same
    /// vertices. Returns a dart of the surface (`None` for a surface without facets).
    /// Errors: no surface begun, a facet still open; a face on the vertices of two faces
    /// already ([`MeshError::FacetInManyCells`]), on the same vertices in another order
    /// ([`MeshError::FacetOrder`]), or twice in this surface ([`MeshError::BadCell`]).
    pub fn end_surface(&mut self) -> Result<Option<DartId>, MeshError> {
        if self.facet.is_some() {
            return Err(MeshError::Order("end_surface inside a facet".into()));
        }
        let surface = self.surface.take().ok_or_else(|| MeshError::Order("end_surface outside a surface".into()))?;
        let index = self.surfaces;
        self.surfaces += 1;
        for &(d, v) in &surface.darts {
            if self.map.point(d).is_none() {
                self.map.set_point(d, Some(self.points[v as usize]));
            }
        }
        if self.map.dim() >= 3 {
            for f in surface.facets {
                match self.faces.offer(f)? {
                    Offer::Waiting => {}
                    Offer::Matched { owner, darts: (x, y) } => {
                        if owner == index {
                            return Err(MeshError::BadCell {
                                cell: index,
                                kind: "surface".into(),
                                reason: "two of its faces lie on the same vertices".into(),
                            });
                        }
                        self.map.try_sew(x, y, 3).map_err(|e| MeshError::Map(e.to_string()))?;
                    }
                }
            }
        }
        Ok(surface.darts.first().map(|&(d, _)| d))
    }

    /// The vertex index of a dart this builder made, `None` for another dart. O(1).
    pub fn vertex_of(&self, d: DartId) -> Option<usize> {
        self.vertex.get(self.map.dart_index(d)).filter(|&&v| v != u32::MAX).map(|&v| v as usize)
    }

    /// The faces matched and left free so far, as `(vertex cycle, cells)`: one cell for a
    /// free face, two for a sewn one (surface indices). For checks after the build.
    pub(crate) fn face_matcher(&self) -> &FacetMatcher<DartId> {
        &self.faces
    }

    /// The vertex of every dart made, by [`GMap::dart_index`] (`u32::MAX`: not made by this
    /// builder), leaving the builder without it.
    pub(crate) fn take_vertices(&mut self) -> Vec<u32> {
        std::mem::take(&mut self.vertex)
    }

    /// The faces offered so far, ending the builder.
    pub(crate) fn into_faces(self) -> FacetMatcher<DartId> {
        self.faces
    }

    /// A dart of the face on these vertices (in any order), if a surface has it. Expected
    /// O(k log k).
    pub fn face_dart(&self, vertices: &[usize]) -> Option<DartId> {
        let v: SmallVec<[u32; 8]> = vertices.iter().map(|&x| u32::try_from(x).unwrap_or(u32::MAX)).collect();
        self.faces.get(&v).map(|e| e.first.dart)
    }

    /// The map built on.
    pub fn map(&self) -> &GMap<A> {
        self.map
    }
}

/// 3-sews every pair of 3-free faces whose corners have the same points, CGAL's
/// `sew3_same_facets`: vertices are told apart by their points (equal coordinates, bit for
/// bit, are one vertex), faces are matched by the sorted ids of their points through the
/// same hash map as the builder and the readers, and each pair is sewn at equal points
/// whatever the two faces' orientations. Faces that are open (a free `alpha_0` or
/// `alpha_1`) or pass twice through a point are left alone. Returns the number of faces
/// sewn. Errors: a map of dimension below 3 or a vertex without a point
/// ([`MeshError::Map`]); three free faces on the same points ([`MeshError::FacetInManyCells`],
/// the cells named by the index of a dart of each face, [`GMap::dart_index`]); two faces on
/// the same points in different cycles ([`MeshError::FacetOrder`]). Faces sewn before the
/// error stay sewn. O(N n) expected.
pub fn sew3_same_facets<A: Attributes>(map: &mut GMap<A>) -> Result<usize, MeshError> {
    if map.dim() < 3 {
        return Err(MeshError::Map(format!("sew3_same_facets needs a map of dimension 3 or more, not {}", map.dim())));
    }
    let mut ids: FxHashMap<[u64; 3], u32> = FxHashMap::default();
    let mut seen = vec![false; map.index_bound()];
    let mut matcher: FacetMatcher<DartId> = FacetMatcher::new(3);
    let darts: Vec<DartId> = map.darts().collect();
    let mut sewn = 0;
    let mut vertex_id = |map: &GMap<A>, d: DartId| -> Result<u32, MeshError> {
        let p = map.point(d).ok_or_else(|| {
            MeshError::Map(format!(
                "the vertex of dart {} has no point: sew3_same_facets compares points",
                map.dart_index(d)
            ))
        })?;
        let n = ids.len() as u32;
        Ok(*ids.entry(p.map(f64::to_bits)).or_insert(n))
    };
    for d in darts {
        if seen[map.dart_index(d)] || !map.is_free(d, 3) {
            continue;
        }
        // walk the face: x at corner j towards j + 1, alpha_0 x at corner j + 1
        let mut cycle: SmallVec<[u32; 4]> = SmallVec::new();
        let (mut fwd, mut back): (SmallVec<[DartId; 4]>, SmallVec<[DartId; 4]>) = Default::default();
        let mut x = d;
        let mut closed = true;
        loop {
            let y = map.alpha(x, 0);
            let z = map.alpha(y, 1);
            seen[map.dart_index(x)] = true;
            seen[map.dart_index(y)] = true;
            if y == x || z == y {
                closed = false;
                break;
            }
            cycle.push(vertex_id(map, x)?);
            fwd.push(x);
            back.push(y);
            x = z;
            if x == d {
                break;
            }
        }
        if !closed {
            continue;
        }
        // back[j] is at corner j + 1 towards j: rotate to have the dart at corner j
        back.rotate_right(1);
        let mut sorted = cycle.clone();
        sorted.sort_unstable();
        if sorted.windows(2).any(|w| w[0] == w[1]) {
            continue;
        }
        let owner = map.dart_index(d);
        if let Offer::Matched { darts: (a, b), .. } = matcher.offer(Facet { owner, cycle, fwd, back })? {
            map.try_sew(a, b, 3).map_err(|e| MeshError::Map(e.to_string()))?;
            sewn += 1;
        }
    }
    Ok(sewn)
}
