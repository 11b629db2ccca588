//! [`Mesh::to_gmap`]: the labelled map of a mesh (see the [module documentation](super)),
//! from the fixed kinds' templates ([`volumes`](super::volumes)) or cell by cell.

use gmap_core::{DartId, LabelValue, LabelledGMap, Labels};
use rustc_hash::FxHashMap;
use smallvec::SmallVec;

use super::cells::{check_pinched, CellKind, DataArray, Mesh, MeshCell};
use super::error::MeshError;
use super::matching::{check_conforming, Facet, FacetMatcher, Offer};
use super::volumes;
use crate::build::IncrementalBuilder;
/// The faces of a volume cell as point cycles.
fn volume_faces(c: &MeshCell) -> Vec<SmallVec<[u32; 4]>> {
    if c.kind == CellKind::Polyhedron {
        c.faces.iter().map(|f| f.iter().copied().collect()).collect()
    } else {
        c.kind.faces().iter().map(|f| f.iter().map(|&k| c.nodes[k]).collect()).collect()
    }
}

/// Adds labels to those of the `dim`-cell of `d` (dimensions 0 to 3).
fn set_labels(g: &mut LabelledGMap, dim: usize, d: DartId, l: Labels) {
    let old = match dim {
        0 => g.attribute::<0>(d),
        1 => g.attribute::<1>(d),
        2 => g.attribute::<2>(d),
        _ => g.attribute::<3>(d),
    };
    let mut merged = old.cloned().unwrap_or_default();
    for (n, v) in l.iter() {
        merged.set(n, v.clone());
    }
    let l = merged;
    match dim {
        0 => g.set_attribute::<0>(d, l),
        1 => g.set_attribute::<1>(d, l),
        2 => g.set_attribute::<2>(d, l),
        _ => g.set_attribute::<3>(d, l),
    };
}

impl Mesh {
    /// The number of darts of the map: `2 Σ` face corners per volume, `2k` per polygon,
    /// 2 per line, 1 per vertex, over the top cells. `None` past `u64`.
    fn dart_count(&self, top: usize) -> Option<u64> {
        let mut total = 0u64;
        for c in self.cells.iter().filter(|c| c.kind.dim() == top) {
            let darts = match top {
                3 if c.kind != CellKind::Polyhedron => c.kind.faces().iter().map(|f| 2 * f.len() as u64).sum::<u64>(),
                3 => volume_faces(c).iter().try_fold(0u64, |a, f| a.checked_add(2 * f.len() as u64))?,
                2 => 2 * c.nodes.len() as u64,
                1 => 2,
                _ => 1,
            };
            total = total.checked_add(darts)?;
        }
        Some(total)
    }

    /// Builds the labelled map of the mesh (see the [module documentation](super)), refusing
    /// before any allocation when it would have more than `max_darts` darts. O(N n) expected
    /// for N darts, plus the checks of non-conforming faces (O(Σ over edges of the square of
    /// the faces around the edge)).
    pub fn to_gmap(&self, max_darts: u64) -> Result<LabelledGMap, MeshError> {
        self.check_cells()?;
        let Some(top) = self.top_dim() else {
            return Ok(LabelledGMap::with_attributes(0));
        };
        let darts = self.dart_count(top);
        if darts.is_none_or(|d| d > max_darts) {
            return Err(MeshError::TooManyDarts { cells: self.cells.len(), darts, limit: max_darts });
        }
        let tops: Vec<usize> = (0..self.cells.len()).filter(|&i| self.cells[i].kind.dim() == top).collect();
        let renumber = |e: MeshError| e.renumber(|k| tops.get(k).copied().unwrap_or(k));
        if top == 3 && volumes::applies(self, &tops) {
            // the volumes of fixed kinds written directly (see `volumes`)
            if darts.is_none_or(|d| d >= u32::MAX as u64 - 1) {
                return Err(MeshError::TooManyDarts { cells: self.cells.len(), darts, limit: u32::MAX as u64 - 2 });
            }
            let volumes::Built { mut map, vertex, first, faces } = volumes::build(self, &tops).map_err(renumber)?;
            let mut cell_dart: Vec<Option<DartId>> = vec![None; self.cells.len()];
            for (t, &i) in tops.iter().enumerate() {
                cell_dart[i] = map.dart_at(first[t] as usize);
            }
            let face_of =
                |vs: &[u32]| volumes::face(self, &tops, &first, &faces, vs).map(|(c, d)| (c, FaceDart::Index(d)));
            self.label(&mut map, &vertex, top, &mut cell_dart, &face_of, Some((&tops, &first)))?;
            return Ok(map);
        }
        let mut g = LabelledGMap::with_attributes(top);
        // the map's dart of each top cell, and the point of each dart (by dart index)
        let mut cell_dart: Vec<Option<DartId>> = vec![None; self.cells.len()];
        let mut vertex: Vec<u32> = Vec::new();
        let mut faces_of_top: Option<FacetMatcher<DartId>> = None;
        if top >= 2 {
            let mut b = IncrementalBuilder::new(&mut g).expect("dimension 2 or 3");
            for p in &self.points {
                b.add_vertex(*p);
            }
            if top == 3 {
                for &i in &tops {
                    b.begin_surface().map_err(renumber)?;
                    for f in volume_faces(&self.cells[i]) {
                        let f: Vec<usize> = f.iter().map(|&v| v as usize).collect();
                        b.add_facet(&f).map_err(renumber)?;
                    }
                    cell_dart[i] = b.end_surface().map_err(renumber)?;
                }
            } else {
                b.begin_surface().map_err(renumber)?;
                for &i in &tops {
                    let f: Vec<usize> = self.cells[i].nodes.iter().map(|&v| v as usize).collect();
                    cell_dart[i] = Some(b.add_facet(&f).map_err(renumber)?);
                }
                b.end_surface().map_err(renumber)?;
            }
            if top == 3 {
                check_conforming(b.face_matcher()).map_err(renumber)?;
            }
            vertex = b.take_vertices();
            if top == 3 {
                faces_of_top = Some(b.into_faces());
            }
        } else {
            // lines sewn at shared ends, or isolated vertices
            let mut ends: FacetMatcher<DartId> = FacetMatcher::new(1);
            let mut seen: FxHashMap<u32, usize> = FxHashMap::default();
            for &i in &tops {
                let c = &self.cells[i];
                let made: Vec<DartId> = c.nodes.iter().map(|_| g.create_dart()).collect();
                for (&d, &v) in made.iter().zip(&c.nodes) {
                    let at = g.dart_index(d);
                    if vertex.len() <= at {
                        vertex.resize(at + 1, u32::MAX);
                    }
                    vertex[at] = v;
                    g.set_point(d, Some(self.points[v as usize]));
                }
                cell_dart[i] = Some(made[0]);
                if top == 0 {
                    if let Some(&first) = seen.get(&c.nodes[0]) {
                        return Err(MeshError::RepeatedCell { cells: [first, i], vertices: vec![c.nodes[0] as u64] });
                    }
                    seen.insert(c.nodes[0], i);
                    continue;
                }
                g.link(made[0], made[1], 0);
                for (&d, &v) in made.iter().zip(&c.nodes) {
                    let one: SmallVec<[DartId; 4]> = [d].into_iter().collect();
                    let end = Facet { owner: i, cycle: [v].into_iter().collect(), fwd: one.clone(), back: one };
                    if let Offer::Matched { darts: (a, b), .. } = ends.offer(end)? {
                        g.try_sew(a, b, 1).map_err(|e| MeshError::Map(e.to_string()))?;
                    }
                }
            }
        }
        let (dense, ids) = g.to_dense_with_ids();
        let vert: Vec<u32> = ids.iter().map(|&d| vertex[g.dart_index(d)]).collect();
        drop(ids);
        check_pinched(&dense, &vert, top)?;
        drop(dense);
        let face_of = |vs: &[u32]| -> Option<(SmallVec<[u32; 4]>, FaceDart)> {
            let e = faces_of_top.as_ref()?.get(vs)?;
            Some((e.first.cycle.clone(), FaceDart::Id(e.first.dart)))
        };
        self.label(&mut g, &vertex, top, &mut cell_dart, &face_of, None)?;
        Ok(g)
    }

    /// Finds the lower cells in the map and sets the labels of every cell and point.
    /// `face_of` finds a face of the top cells by its vertices (its cycle and its dart at
    /// corner 0 towards corner 1); `blocks`, the top cells and the index of the first dart
    /// of each when every top cell's darts are consecutive (the labels of the top cells are
    /// then set in one pass).
    fn label(
        &self,
        g: &mut LabelledGMap,
        vertex: &[u32],
        top: usize,
        cell_dart: &mut [Option<DartId>],
        face_of: &FaceLookup<'_>,
        blocks: Option<(&[usize], &[u32])>,
    ) -> Result<(), MeshError> {
        // the map's dart of each point and of each edge, by their points
        let mut point_dart: Vec<Option<DartId>> = vec![None; self.points.len()];
        let mut edge_dart: FxHashMap<(u32, u32), DartId> = FxHashMap::default();
        let need_edges = top >= 2 && self.cells.iter().any(|c| c.kind == CellKind::Line);
        let need_points = !self.point_data.is_empty() || self.cells.iter().any(|c| c.kind.dim() < top);
        if need_points {
            for d in g.darts() {
                let v = vertex[g.dart_index(d)];
                if v == u32::MAX {
                    continue;
                }
                point_dart[v as usize].get_or_insert(d);
                if need_edges {
                    let w = vertex[g.dart_index(g.alpha(d, 0))];
                    edge_dart.entry((v.min(w), v.max(w))).or_insert(d);
                }
            }
        }
        let mut lower_seen: FxHashMap<(usize, SmallVec<[u32; 4]>), usize> = FxHashMap::default();
        for (i, c) in self.cells.iter().enumerate() {
            let dim = c.kind.dim();
            if dim == top {
                continue;
            }
            let loose = || MeshError::LooseCell {
                cell: i,
                kind: c.kind.to_string(),
                vertices: c.nodes.iter().map(|&v| v as u64).collect(),
                top,
            };
            let d = match dim {
                0 => point_dart[c.nodes[0] as usize],
                1 => {
                    let (a, b) = (c.nodes[0], c.nodes[1]);
                    edge_dart.get(&(a.min(b), a.max(b))).copied()
                }
                _ => face_of(&c.nodes).and_then(|(cycle, d)| {
                    let same = cycle.len() == c.nodes.len()
                        && (0..c.nodes.len()).any(|r| {
                            let k = c.nodes.len();
                            (0..k).all(|j| c.nodes[(r + j) % k] == cycle[j])
                                || (0..k).all(|j| c.nodes[(r + k - j) % k] == cycle[j])
                        });
                    if !same {
                        return None;
                    }
                    match d {
                        FaceDart::Id(d) => Some(d),
                        FaceDart::Index(k) => g.dart_at(k),
                    }
                }),
            };
            let d = d.ok_or_else(loose)?;
            let mut key: SmallVec<[u32; 4]> = c.nodes.iter().copied().collect();
            key.sort_unstable();
            if let Some(&first) = lower_seen.get(&(dim, key.clone())) {
                return Err(MeshError::RepeatedCell {
                    cells: [first, i],
                    vertices: c.nodes.iter().map(|&v| v as u64).collect(),
                });
            }
            lower_seen.insert((dim, key), i);
            cell_dart[i] = Some(d);
        }
        // cell data: skip the writer's own `dim` column and the `.id` ranks of text columns
        let skip = |a: &DataArray| -> bool {
            if a.name == "dim" {
                return a.values.iter().zip(&self.cells).all(|(v, c)| *v == Some(LabelValue::Int(c.kind.dim() as i64)));
            }
            a.name.strip_suffix(".id").is_some_and(|base| {
                self.cell_data
                    .iter()
                    .any(|b| b.name == base && b.values.iter().flatten().all(|v| matches!(v, LabelValue::Text(_))))
            })
        };
        let columns: Vec<&DataArray> = self.cell_data.iter().filter(|a| !skip(a)).collect();
        let labels_of = |i: usize| -> Labels {
            columns.iter().filter_map(|a| a.values.get(i).cloned().flatten().map(|v| (a.name.clone(), v))).collect()
        };
        let mut top_done = false;
        if let (Some((tops, first)), 3) = (blocks, top) {
            // the top cells' labels by one id per dart: top cell t holds the darts from
            // first[t] up to first[t + 1]
            let values: Vec<Option<Labels>> =
                tops.iter().map(|&i| Some(labels_of(i)).filter(|l| !l.is_empty())).collect();
            if values.iter().any(Option::is_some) {
                let mut ids = vec![u32::MAX; g.index_bound()];
                for t in 0..tops.len() {
                    let end = first.get(t + 1).map_or(ids.len(), |&e| e as usize);
                    ids[first[t] as usize..end].fill(t as u32);
                }
                g.set_attributes_by_ids::<3>(&ids, values).map_err(|e| MeshError::Map(e.to_string()))?;
            }
            top_done = true;
        }
        for (i, c) in self.cells.iter().enumerate() {
            if top_done && c.kind.dim() == top {
                continue;
            }
            let l = labels_of(i);
            if !l.is_empty() {
                if let Some(d) = cell_dart[i] {
                    set_labels(g, c.kind.dim(), d, l);
                }
            }
        }
        for (p, d) in point_dart.iter().enumerate() {
            let Some(d) = *d else { continue };
            let l: Labels = self
                .point_data
                .iter()
                .filter_map(|a| a.values.get(p).cloned().flatten().map(|v| (a.name.clone(), v)))
                .collect();
            if !l.is_empty() {
                set_labels(g, 0, d, l);
            }
        }
        Ok(())
    }
}

/// Finds a face of the top cells by its vertices: its cycle and its dart.
type FaceLookup<'a> = dyn Fn(&[u32]) -> Option<(SmallVec<[u32; 4]>, FaceDart)> + 'a;

/// The dart of a face found by its vertices: a handle, or a dart index.
pub(crate) enum FaceDart {
    /// a handle
    Id(DartId),
    /// an index ([`gmap_core::GMap::dart_index`])
    Index(usize),
}
