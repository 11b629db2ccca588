//! Facets matched by their vertices: the one routine behind the mesh readers, the
//! incremental builder and [`crate::build::sew3_same_facets`].
//!
//! A *facet* is a cycle of vertex ids (a face of a volume; a 2-cycle for an edge of a
//! polygon; a 1-cycle for the end of a line) together with, at each corner `j`, the dart at
//! corner `j` on the side towards corner `j + 1` and the dart at corner `j` on the side
//! towards corner `j - 1`. Facets are keyed in a hash map by their sorted vertex ids. The
//! first facet with a key waits; the second is matched to it — the two cycles must be the
//! same up to rotation and reversal — and the matcher returns the pair of darts at the same
//! vertex on the same edge, from which a sew walks the rest; a third is refused, naming the
//! three cells. Orientation is chosen by the vertices alone: two volumes whose shared face
//! is listed in the same cyclic order (one of them inverted) are sewn like two listing it
//! in opposite orders.
//!
//! Cost: O(k log k) per facet of k vertices for the key, expected O(k) for the lookup and
//! the match; memory: the key, the cycle, the cell and one dart for every key (kept after a
//! match to catch a third facet and for [`FacetMatcher::facets`]).

use rustc_hash::FxHashMap;
use smallvec::SmallVec;

use super::error::MeshError;

/// The sorted vertex ids of a facet: its key.
pub(crate) type Key = SmallVec<[u32; 4]>;

/// One facet as offered: its cell, its vertex cycle and its darts.
#[derive(Clone, Debug)]
pub(crate) struct Facet<D> {
    /// the cell it belongs to (a cell index of the caller's numbering)
    pub owner: usize,
    /// the vertex ids around it
    pub cycle: SmallVec<[u32; 4]>,
    /// at corner `j`: the dart towards corner `j + 1`
    pub fwd: SmallVec<[D; 4]>,
    /// at corner `j`: the dart towards corner `j - 1`
    pub back: SmallVec<[D; 4]>,
}

/// What is kept of the first facet offered with a key.
#[derive(Clone, Debug)]
pub(crate) struct Kept<D> {
    /// its cell
    pub owner: usize,
    /// its vertex cycle
    pub cycle: SmallVec<[u32; 4]>,
    /// its dart at corner 0 towards corner 1
    pub dart: D,
}

/// The state of one key.
#[derive(Clone, Debug)]
pub(crate) struct Entry<D> {
    /// the first facet offered
    pub first: Kept<D>,
    /// the cell of the second, once matched
    pub second: Option<usize>,
}

/// What [`FacetMatcher::offer`] did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Offer<D> {
    /// the facet is the first with its vertices: it waits for a partner
    Waiting,
    /// the facet met its partner: sew `(earlier facet's dart, this facet's dart)`, which
    /// lie at the same vertex on the same edge; `owner` is the earlier facet's cell
    Matched { owner: usize, darts: (D, D) },
}

/// Facets keyed by their sorted vertex ids (see the module documentation).
#[derive(Clone, Debug)]
pub(crate) struct FacetMatcher<D> {
    entries: FxHashMap<Key, Entry<D>>,
    /// the dimension of the cells the facets bound (for the error messages)
    dim: usize,
}

fn key_of(cycle: &[u32]) -> Key {
    let mut k: Key = cycle.iter().copied().collect();
    k.sort_unstable();
    k
}

/// Where `b` is `a` up to rotation and reversal: `Some((r, reversed))` with
/// `b[(r ± j) mod k] = a[j]`. Both cycles have distinct entries. O(k).
pub(crate) fn align(a: &[u32], b: &[u32]) -> Option<(usize, bool)> {
    let k = a.len();
    if b.len() != k || k == 0 {
        return None;
    }
    let r = b.iter().position(|&x| x == a[0])?;
    if (0..k).all(|j| b[(r + j) % k] == a[j]) {
        return Some((r, false));
    }
    if (0..k).all(|j| b[(r + k - j) % k] == a[j]) {
        return Some((r, true));
    }
    None
}

impl<D: Copy> FacetMatcher<D> {
    /// An empty matcher for the facets of `dim`-dimensional cells.
    pub fn new(dim: usize) -> Self {
        FacetMatcher { entries: FxHashMap::default(), dim }
    }

    /// Offers a facet. Precondition: its cycle has distinct vertices and `fwd`, `back` one
    /// dart per corner. Errors: a third facet on the same vertices
    /// ([`MeshError::FacetInManyCells`]); the same vertices in another cycle
    /// ([`MeshError::FacetOrder`]). Expected O(k log k).
    pub fn offer(&mut self, facet: Facet<D>) -> Result<Offer<D>, MeshError> {
        let key = key_of(&facet.cycle);
        match self.entries.get_mut(&key) {
            None => {
                let first = Kept { owner: facet.owner, dart: facet.fwd[0], cycle: facet.cycle };
                self.entries.insert(key, Entry { first, second: None });
                Ok(Offer::Waiting)
            }
            Some(e) => {
                if let Some(second) = &e.second {
                    return Err(MeshError::FacetInManyCells {
                        dim: self.dim,
                        vertices: key.iter().map(|&v| v as u64).collect(),
                        cells: vec![e.first.owner, *second, facet.owner],
                    });
                }
                let Some((r, reversed)) = align(&e.first.cycle, &facet.cycle) else {
                    return Err(MeshError::FacetOrder {
                        cells: [e.first.owner, facet.owner],
                        first: e.first.cycle.iter().map(|&v| v as u64).collect(),
                        second: facet.cycle.iter().map(|&v| v as u64).collect(),
                    });
                };
                // corner 0 of the first facet towards its corner 1 is, in this one, corner
                // r towards r + 1 (same direction) or towards r - 1 (reversed)
                let theirs = if reversed { facet.back[r] } else { facet.fwd[r] };
                let darts = (e.first.dart, theirs);
                let owner = e.first.owner;
                e.second = Some(facet.owner);
                Ok(Offer::Matched { owner, darts })
            }
        }
    }

    /// Every key's entry, in no particular order.
    pub fn facets(&self) -> impl Iterator<Item = &Entry<D>> {
        self.entries.values()
    }

    /// The entry of the facet on these vertices (in any order), if one was offered.
    pub fn get(&self, vertices: &[u32]) -> Option<&Entry<D>> {
        self.entries.get(&key_of(vertices))
    }
}

/// One face of a mesh for [`check_conforming_faces`]: its cycle and the one or two cells
/// it bounds.
#[derive(Clone, Debug)]
pub(crate) struct FaceRecord {
    /// the vertex cycle (of the first cell that has it)
    pub cycle: SmallVec<[u32; 4]>,
    /// the first cell that has it
    pub owner: usize,
    /// the second, when two share it
    pub second: Option<usize>,
}

/// Refuses non-conforming faces: two faces of different cells, not the same face, that share
/// two edges or more (a triangle on half of a quadrangle, a quadrangle split in two on the
/// other side). Faces are the matcher's entries. Hanging vertices in the middle of an edge
/// share a single edge and are not seen (that needs the geometry). Expected O(Σ over edges
/// of the square of the number of faces around the edge).
pub(crate) fn check_conforming<D: Copy>(m: &FacetMatcher<D>) -> Result<(), MeshError> {
    if m.dim < 3 {
        return Ok(());
    }
    let faces: Vec<FaceRecord> = m
        .facets()
        .map(|e| FaceRecord { cycle: e.first.cycle.clone(), owner: e.first.owner, second: e.second })
        .collect();
    check_conforming_faces(&faces)
}

/// [`check_conforming`] on a list of faces, each face once (in any order).
pub(crate) fn check_conforming_faces(entries: &[FaceRecord]) -> Result<(), MeshError> {
    // Two faces sharing two edges or more without being one face: two triangles sharing two
    // edges have the same three vertices, hence one key and one entry, so one of the two has
    // four corners or more, and the edges shared are edges of it. Only the edges of such
    // faces are looked at (none in a tetrahedral mesh).
    let edge = |c: &SmallVec<[u32; 4]>, j: usize| {
        let (a, b) = (c[j], c[(j + 1) % c.len()]);
        (a.min(b), a.max(b))
    };
    let mut polygon_edges: rustc_hash::FxHashSet<(u32, u32)> = rustc_hash::FxHashSet::default();
    for e in entries.iter().filter(|e| e.cycle.len() > 3) {
        polygon_edges.extend((0..e.cycle.len()).map(|j| edge(&e.cycle, j)));
    }
    if polygon_edges.is_empty() {
        return Ok(());
    }
    let mut around: FxHashMap<(u32, u32), SmallVec<[u32; 4]>> = FxHashMap::default();
    for (k, e) in entries.iter().enumerate() {
        let c = &e.cycle;
        for j in 0..c.len() {
            let key = edge(c, j);
            if polygon_edges.contains(&key) {
                around.entry(key).or_default().push(k as u32);
            }
        }
    }
    let owners = |e: &FaceRecord| -> SmallVec<[usize; 2]> {
        let mut o: SmallVec<[usize; 2]> = SmallVec::new();
        o.push(e.owner);
        if let Some(s) = &e.second {
            o.push(*s);
        }
        o
    };
    // the number of edges each pair of faces around a common edge shares
    let mut shared: FxHashMap<(u32, u32), u32> = FxHashMap::default();
    for faces in around.values() {
        for x in 0..faces.len() {
            for y in x + 1..faces.len() {
                let (f, g) = (faces[x].min(faces[y]), faces[x].max(faces[y]));
                *shared.entry((f, g)).or_default() += 1;
            }
        }
    }
    // faces of one cell meet along edges: only faces of disjoint cells are compared
    let worst = shared
        .iter()
        .filter(|&(&(f, g), &n)| {
            let (of, og) = (owners(&entries[f as usize]), owners(&entries[g as usize]));
            n >= 2 && !of.iter().any(|c| og.contains(c))
        })
        .map(|(&fg, _)| {
            let cells = |k: u32| owners(&entries[k as usize]).into_iter().min().unwrap_or(0);
            // the pair of cells first, then the cycles: the same pair whatever the order of
            // the entries
            let (x, y) = (&entries[fg.0 as usize].cycle, &entries[fg.1 as usize].cycle);
            let cyc = if x <= y { (x.clone(), y.clone()) } else { (y.clone(), x.clone()) };
            ((cells(fg.0).min(cells(fg.1)), cells(fg.0).max(cells(fg.1))), cyc, fg)
        })
        .min();
    if let Some((_, _, (f, g))) = worst {
        let (mut ef, mut eg) = (&entries[f as usize], &entries[g as usize]);
        if owners(ef).into_iter().min() > owners(eg).into_iter().min() {
            std::mem::swap(&mut ef, &mut eg);
        }
        let edges_of = |e: &FaceRecord| -> Vec<[u64; 2]> {
            let c = &e.cycle;
            (0..c.len())
                .map(|j| {
                    let (a, b) = (c[j] as u64, c[(j + 1) % c.len()] as u64);
                    [a.min(b), a.max(b)]
                })
                .collect()
        };
        let eg_edges = edges_of(eg);
        let mut es: Vec<[u64; 2]> = edges_of(ef).into_iter().filter(|e| eg_edges.contains(e)).collect();
        es.sort_unstable();
        return Err(MeshError::NonConforming {
            cells: [owners(ef)[0], owners(eg)[0]],
            first: cyc(ef),
            second: cyc(eg),
            shared: es,
        });
    }
    Ok(())
}

fn cyc(e: &FaceRecord) -> Vec<u64> {
    e.cycle.iter().map(|&v| v as u64).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn facet(owner: usize, cycle: &[u32]) -> Facet<(usize, usize, bool)> {
        let k = cycle.len();
        Facet {
            owner,
            cycle: cycle.iter().copied().collect(),
            fwd: (0..k).map(|j| (owner, j, true)).collect(),
            back: (0..k).map(|j| (owner, j, false)).collect(),
        }
    }

    #[test]
    fn facets_pair_at_the_same_vertex_whatever_the_orientation() {
        let mut m = FacetMatcher::new(3);
        assert_eq!(m.offer(facet(0, &[1, 2, 3, 4])).unwrap(), Offer::Waiting);
        // reversed, starting at 4: corner 0 of the first (vertex 1, towards 2) is corner 3
        // of the second (vertex 1) towards its corner 2 (vertex 2): the back dart
        assert_eq!(
            m.offer(facet(1, &[4, 3, 2, 1])).unwrap(),
            Offer::Matched { owner: 0, darts: ((0, 0, true), (1, 3, false)) }
        );
        let e = m.offer(facet(2, &[2, 3, 4, 1])).unwrap_err();
        assert_eq!(
            e.to_string(),
            "the face with vertices [1, 2, 3, 4] lies in 3 cells ([0, 1, 2]): at most two cells may share it"
        );
        // same direction
        assert_eq!(m.offer(facet(3, &[7, 8, 9])).unwrap(), Offer::Waiting);
        assert_eq!(
            m.offer(facet(4, &[9, 7, 8])).unwrap(),
            Offer::Matched { owner: 3, darts: ((3, 0, true), (4, 1, true)) }
        );
        // a bow tie on the same vertices
        m.offer(facet(5, &[10, 11, 12, 13])).unwrap();
        assert_eq!(
            m.offer(facet(6, &[10, 12, 11, 13])).unwrap_err().to_string(),
            "cells 5 and 6 have faces on the same vertices [10, 11, 12, 13] joined in different orders ([10, 11, 12, 13] and [10, 12, 11, 13])"
        );
        assert_eq!(align(&[1], &[1]), Some((0, false)));
        assert_eq!(align(&[1, 2], &[2, 1]), Some((1, false)));
    }

    #[test]
    fn a_triangle_on_half_a_quadrangle_is_not_conforming() {
        let mut m = FacetMatcher::new(3);
        m.offer(facet(0, &[0, 1, 2, 3])).unwrap();
        m.offer(facet(0, &[0, 1, 5])).unwrap();
        m.offer(facet(1, &[0, 1, 2])).unwrap();
        assert_eq!(
            check_conforming(&m).unwrap_err().to_string(),
            "non-conforming faces: face [0, 1, 2, 3] of cell 0 and face [0, 1, 2] of cell 1 share the edges 0-1, 1-2 without being one face"
        );
        let mut ok = FacetMatcher::new(3);
        ok.offer(facet(0, &[0, 1, 2, 3])).unwrap();
        ok.offer(facet(0, &[0, 1, 4, 5])).unwrap();
        ok.offer(facet(1, &[3, 2, 1, 0])).unwrap();
        check_conforming(&ok).unwrap();
    }
}
