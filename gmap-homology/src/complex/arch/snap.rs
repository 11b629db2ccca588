//! Snapping a complex with points so that it conforms ([`snap`]): points within a tolerance
//! welded, edges split at the points inside them, faces split along the edges inside them
//! (T-junctions), the rooms given the pieces that close them.
//!
//! 1. Points closer than `eps` are welded (transitively) into the first of them in the
//!    file; an edge whose ends are welded together is removed, two edges with the same ends
//!    become the first.
//! 2. An edge with points inside it (within `eps`) is cut into a chain at them; every face
//!    of the edge takes the whole chain. The first piece keeps the edge's id, the others are
//!    new regions named `<edge>.2`, `<edge>.3`…
//! 3. A face with edges inside it is cut along them: the pieces are the bounded faces of the
//!    plane graph of its edges and the inner ones (traced around each point by angle, holes
//!    given to the piece around them), those inside the face kept; the first keeps the id,
//!    the others are `<face>.2`… Every 3-region of the face takes the fewest pieces that
//!    close its boundary (all of them if none do).
//!
//! Signs must be left out (they are chosen after). O((R + E) · log) plus the metrical
//! checks (near-linear) and, per room cut, 2^pieces subsets for at most 12 pieces.

use std::collections::{BTreeMap, HashMap, HashSet};

use super::metric::{MetricDefect, Shape};
use super::model::{Region, RegionId};
use super::names::RegionNames;

/// An entry whose weight may be left out.
type Loose = (RegionId, RegionId, Option<i64>);

/// The complex after [`snap`].
#[derive(Clone, Debug, Default)]
#[non_exhaustive]
pub struct Snapped {
    /// the entries (signs left out)
    pub entries: Vec<Loose>,
    /// the points of the 0-regions left
    pub points: HashMap<RegionId, [f64; 3]>,
    /// the regions welded into others or collapsed
    pub removed: HashSet<RegionId>,
    /// the new regions: each, the region it was cut from, and its key
    pub added: Vec<(Region, RegionId, String)>,
    /// one line per weld and cut, regions by name
    pub report: Vec<String>,
}

struct State {
    regions: Vec<Region>,
    entries: Vec<Loose>,
    points: HashMap<RegionId, [f64; 3]>,
    names: RegionNames,
    next: u64,
    out: Snapped,
}

/// Snaps the complex (module docs) within `eps`; `next` is the first free region id. Fails
/// for an `eps` that is not finite and positive, or entries with weights given.
pub fn snap(
    eps: f64,
    regions: &[Region],
    entries: &[Loose],
    points: &HashMap<RegionId, [f64; 3]>,
    names: &RegionNames,
    next: u64,
) -> Result<Snapped, String> {
    if !(eps.is_finite() && eps > 0.0) {
        return Err(format!("the tolerance {eps} is not a finite positive real"));
    }
    if entries.iter().any(|e| e.2.is_some()) {
        return Err("the file gives incidence weights; snapping cuts cells and needs them left out".into());
    }
    let mut st = State {
        regions: regions.to_vec(),
        entries: entries.to_vec(),
        points: points.clone(),
        names: names.clone(),
        next,
        out: Snapped::default(),
    };
    st.weld(eps);
    st.split_edges(eps)?;
    st.merge_edges();
    st.split_faces(eps)?;
    let mut out = st.out;
    (out.entries, out.points) = (st.entries, st.points);
    Ok(out)
}

impl State {
    fn name(&self, id: RegionId) -> String {
        self.names.get(id)
    }

    fn shape(&self, eps: f64) -> Shape {
        let s = Shape::new(&self.regions, self.entries.iter().map(|e| (e.0, e.1)), &self.points);
        let t = s.tolerance().max(eps);
        s.with_tolerance(t)
    }

    fn fresh(&mut self, from: RegionId, dim: usize, k: usize) -> Result<RegionId, String> {
        if self.next == u64::MAX {
            return Err("no region id is left for the pieces".into());
        }
        let id = RegionId(self.next);
        self.next += 1;
        let key = format!("{}.{k}", self.name(from));
        self.names.insert(id, key.clone());
        let r = Region { id, dim };
        self.regions.push(r);
        self.out.added.push((r, from, key));
        Ok(id)
    }

    /// Replaces `gone` by `by` in the entries (dropping the repeats) and forgets `gone`.
    fn replace(&mut self, gone: RegionId, by: Option<RegionId>) {
        let mut seen = HashSet::new();
        let old = std::mem::take(&mut self.entries);
        for (f, t, w) in old {
            let (f, t) = match by {
                Some(b) => (if f == gone { b } else { f }, if t == gone { b } else { t }),
                None if f == gone || t == gone => continue,
                None => (f, t),
            };
            if seen.insert((f, t)) {
                self.entries.push((f, t, w));
            }
        }
        self.regions.retain(|r| r.id != gone);
        self.points.remove(&gone);
        self.out.removed.insert(gone);
    }

    fn weld(&mut self, eps: f64) {
        let welds: Vec<(RegionId, RegionId, f64)> = self
            .shape(eps)
            .defects()
            .into_iter()
            .filter_map(|d| match d {
                MetricDefect::NearPoints { a, b, distance } => Some((a, b, distance)),
                _ => None,
            })
            .collect();
        let mut root: HashMap<RegionId, RegionId> = HashMap::new();
        let order: HashMap<RegionId, usize> = self.regions.iter().enumerate().map(|(k, r)| (r.id, k)).collect();
        let find = |root: &HashMap<RegionId, RegionId>, mut x: RegionId| {
            while let Some(&r) = root.get(&x) {
                x = r;
            }
            x
        };
        for &(a, b, _) in &welds {
            let (ra, rb) = (find(&root, a), find(&root, b));
            if ra != rb {
                let (keep, gone) = if order[&ra] < order[&rb] { (ra, rb) } else { (rb, ra) };
                root.insert(gone, keep);
            }
        }
        let mut gone: Vec<RegionId> = root.keys().copied().collect();
        gone.sort_by_key(|g| order[g]);
        for g in gone {
            let keep = find(&root, g);
            let d = welds.iter().find(|w| w.0 == g || w.1 == g).map_or(0.0, |w| w.2);
            self.out.report.push(format!("welded point {} into {} ({d:.2e} apart)", self.name(g), self.name(keep)));
            self.replace(g, Some(keep));
        }
        self.merge_edges();
    }

    /// After welding: edges with one end left are removed, edges with the same ends merged.
    fn merge_edges(&mut self) {
        let dims: HashMap<RegionId, usize> = self.regions.iter().map(|r| (r.id, r.dim)).collect();
        let mut ends: BTreeMap<RegionId, Vec<RegionId>> = BTreeMap::new();
        for &(f, t, _) in &self.entries {
            if dims.get(&f) == Some(&1) && dims.get(&t) == Some(&0) && self.points.contains_key(&t) {
                ends.entry(f).or_default().push(t);
            }
        }
        let order: HashMap<RegionId, usize> = self.regions.iter().enumerate().map(|(k, r)| (r.id, k)).collect();
        let mut edges: Vec<(RegionId, Vec<RegionId>)> = ends.into_iter().collect();
        edges.sort_by_key(|e| order[&e.0]);
        let mut by_ends: HashMap<Vec<RegionId>, RegionId> = HashMap::new();
        for (e, mut v) in edges {
            v.sort();
            if v.len() == 1 {
                self.out.report.push(format!("removed edge {}: its ends were welded together", self.name(e)));
                self.replace(e, None);
            } else if let Some(&first) = by_ends.get(&v) {
                self.out.report.push(format!("merged edge {} into {}: the same ends", self.name(e), self.name(first)));
                self.replace(e, Some(first));
            } else {
                by_ends.insert(v, e);
            }
        }
    }

    fn split_edges(&mut self, eps: f64) -> Result<(), String> {
        let shape = self.shape(eps);
        let mut cuts: BTreeMap<usize, Vec<(f64, usize)>> = BTreeMap::new();
        for d in shape.defects() {
            if let MetricDefect::VertexOnEdge { vertex, edge } = d {
                let (Some(v), Some(e)) = (shape.index(vertex), shape.index(edge)) else { continue };
                if let Some(t) = shape.on_edge(v, e) {
                    cuts.entry(e).or_default().push((t, v));
                }
            }
        }
        for (e, mut at) in cuts {
            at.sort_by(|a, b| a.0.total_cmp(&b.0));
            let Some((a, b)) = shape.ends_of(e) else { continue };
            let mut chain: Vec<RegionId> = vec![shape.id(a)];
            chain.extend(at.iter().map(|&(_, v)| shape.id(v)));
            chain.push(shape.id(b));
            let edge = shape.id(e);
            let faces: Vec<RegionId> = self.entries.iter().filter(|x| x.1 == edge).map(|x| x.0).collect();
            self.entries.retain(|x| x.0 != edge);
            let mut pieces = vec![edge];
            for k in 1..chain.len() - 1 {
                pieces.push(self.fresh(edge, 1, k + 1)?);
            }
            for (k, &p) in pieces.iter().enumerate() {
                self.entries.push((p, chain[k], None));
                self.entries.push((p, chain[k + 1], None));
                if k > 0 {
                    self.entries.extend(faces.iter().map(|&f| (f, p, None)));
                }
            }
            let at: Vec<String> = chain[1..chain.len() - 1].iter().map(|&v| self.name(v)).collect();
            let ps: Vec<String> = pieces.iter().map(|&p| self.name(p)).collect();
            self.out.report.push(format!("split edge {} at {} into {}", self.name(edge), at.join(", "), ps.join(", ")));
        }
        Ok(())
    }
}

mod faces;
