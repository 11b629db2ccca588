//! Step 3 of snapping: faces cut along the edges inside them (module docs of `snap`).

use std::collections::{BTreeMap, HashMap};

use super::super::metric::{MetricDefect, Shape};
use super::super::model::RegionId;
use super::State;

type Q = [f64; 2];

/// A cycle of the plane graph: its half-edges and twice its signed area.
struct Cycle {
    halves: Vec<usize>,
    area2: f64,
}

/// The plane graph of a face's edges and the edges inside it, projected on a coordinate plane.
struct Plane {
    /// ends of each edge (indices into `pts`)
    edges: Vec<(usize, usize)>,
    pts: Vec<Q>,
}

impl Plane {
    fn tail(&self, h: usize) -> usize {
        let (a, b) = self.edges[h / 2];
        if h.is_multiple_of(2) {
            a
        } else {
            b
        }
    }

    fn vec(&self, h: usize) -> Q {
        let (a, b) = (self.pts[self.tail(h)], self.pts[self.tail(h ^ 1)]);
        [b[0] - a[0], b[1] - a[1]]
    }

    /// Every cycle of half-edges, each with the face on its left (bounded faces turn
    /// anticlockwise, positive area).
    fn cycles(&self) -> Vec<Cycle> {
        let mut out_of: Vec<Vec<usize>> = vec![Vec::new(); self.pts.len()];
        for h in 0..2 * self.edges.len() {
            out_of[self.tail(h)].push(h);
        }
        let angle = |h: usize| {
            let v = self.vec(h);
            v[1].atan2(v[0])
        };
        for list in &mut out_of {
            list.sort_by(|&a, &b| angle(a).total_cmp(&angle(b)));
        }
        let mut pos = vec![0usize; 2 * self.edges.len()];
        for list in &out_of {
            for (k, &h) in list.iter().enumerate() {
                pos[h] = k;
            }
        }
        let next = |h: usize| {
            let t = h ^ 1;
            let list = &out_of[self.tail(t)];
            list[(pos[t] + list.len() - 1) % list.len()]
        };
        let mut seen = vec![false; 2 * self.edges.len()];
        let mut cycles = Vec::new();
        for start in 0..2 * self.edges.len() {
            if seen[start] {
                continue;
            }
            let (mut halves, mut area2, mut h) = (Vec::new(), 0.0, start);
            while !seen[h] {
                seen[h] = true;
                halves.push(h);
                let (a, b) = (self.pts[self.tail(h)], self.pts[self.tail(h ^ 1)]);
                area2 += a[0] * b[1] - a[1] * b[0];
                h = next(h);
            }
            cycles.push(Cycle { halves, area2 });
        }
        cycles
    }

    /// A point just left of the middle of the first half-edge of `c`.
    fn left_of(&self, c: &Cycle) -> Q {
        let h = c.halves[0];
        let (a, v) = (self.pts[self.tail(h)], self.vec(h));
        let len = (v[0] * v[0] + v[1] * v[1]).sqrt().max(f64::MIN_POSITIVE);
        let d = 1e-6;
        [a[0] + v[0] / 2.0 - v[1] / len * d * len, a[1] + v[1] / 2.0 + v[0] / len * d * len]
    }

    /// Whether `p` is inside the region bounded by the edges `edges` (ray parity).
    fn inside(&self, edges: impl Iterator<Item = usize>, p: Q) -> bool {
        let mut odd = false;
        for e in edges {
            let (a, b) = (self.pts[self.edges[e].0], self.pts[self.edges[e].1]);
            if (a[1] > p[1]) != (b[1] > p[1]) && a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) > p[0] {
                odd = !odd;
            }
        }
        odd
    }
}

impl State {
    pub(super) fn split_faces(&mut self, eps: f64) -> Result<(), String> {
        let shape = self.shape(eps);
        let mut inner: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
        for d in shape.defects() {
            if let MetricDefect::EdgeInFace { edge, face } = d {
                if let (Some(e), Some(f)) = (shape.index(edge), shape.index(face)) {
                    inner.entry(f).or_default().push(e);
                }
            }
        }
        let mut cuts: HashMap<RegionId, Vec<RegionId>> = HashMap::new();
        for (f, inside) in inner {
            let Some(pieces) = pieces(&shape, f, &inside) else { continue };
            let ids = self.cut(&shape, f, &inside, pieces)?;
            cuts.insert(shape.id(f), ids);
        }
        let mut rooms: Vec<RegionId> = self.entries.iter().filter(|x| cuts.contains_key(&x.1)).map(|x| x.0).collect();
        rooms.sort();
        rooms.dedup();
        for room in rooms {
            self.give_pieces(room, &cuts);
        }
        Ok(())
    }

    /// Replaces face `f` by `pieces` (edge indices of `shape`); the first keeps its id.
    /// Returns the ids of the pieces.
    fn cut(
        &mut self,
        shape: &Shape,
        f: usize,
        inside: &[usize],
        pieces: Vec<Vec<usize>>,
    ) -> Result<Vec<RegionId>, String> {
        let face = shape.id(f);
        let mut ids = vec![face];
        for k in 1..pieces.len() {
            ids.push(self.fresh(face, 2, k + 1)?);
        }
        self.entries.retain(|x| x.0 != face);
        for (id, piece) in ids.iter().zip(&pieces) {
            self.entries.extend(piece.iter().map(|&e| (*id, shape.id(e), None)));
        }
        let along: Vec<String> = inside.iter().map(|&e| self.name(shape.id(e))).collect();
        let names: Vec<String> = ids.iter().map(|&i| self.name(i)).collect();
        self.out.report.push(format!(
            "split face {} along {} into {}",
            self.name(face),
            along.join(", "),
            names.join(", ")
        ));
        Ok(ids)
    }

    /// Gives `room` the fewest pieces of its cut faces that, with its other faces, leave
    /// every edge on an even number of them (all the pieces when no subset does, or there
    /// are more than 12).
    fn give_pieces(&mut self, room: RegionId, cuts: &HashMap<RegionId, Vec<RegionId>>) {
        let faces: Vec<RegionId> = self.entries.iter().filter(|x| x.0 == room).map(|x| x.1).collect();
        let pieces: Vec<RegionId> = faces.iter().filter_map(|f| cuts.get(f)).flatten().copied().collect();
        let mut odd: HashMap<RegionId, bool> = HashMap::new();
        let flip = |g: RegionId, odd: &mut HashMap<RegionId, bool>| {
            for x in self.entries.iter().filter(|x| x.0 == g) {
                *odd.entry(x.1).or_default() ^= true;
            }
        };
        for &g in faces.iter().filter(|f| !cuts.contains_key(f)) {
            flip(g, &mut odd);
        }
        let mut best: Option<Vec<RegionId>> = None;
        if pieces.len() <= 12 {
            for mask in 1u32..(1 << pieces.len()) {
                if best.as_ref().is_some_and(|b| b.len() <= mask.count_ones() as usize) {
                    continue;
                }
                let set: Vec<RegionId> = (0..pieces.len()).filter(|k| mask >> k & 1 == 1).map(|k| pieces[k]).collect();
                let mut o = odd.clone();
                set.iter().for_each(|&p| flip(p, &mut o));
                if o.values().all(|v| !v) {
                    best = Some(set);
                }
            }
        }
        let chosen = best.unwrap_or_else(|| pieces.clone());
        self.entries.retain(|x| !(x.0 == room && cuts.contains_key(&x.1)));
        self.entries.extend(chosen.iter().map(|&p| (room, p, None)));
        let c: Vec<String> = chosen.iter().map(|&p| self.name(p)).collect();
        self.out.report.push(format!("{} takes {}", self.name(room), c.join(", ")));
    }
}

/// The pieces of face `f` cut along the edges `inside` (edge indices), `None` when they do
/// not cut it in two or more.
fn pieces(shape: &Shape, f: usize, inside: &[usize]) -> Option<Vec<Vec<usize>>> {
    let (edges, drop) = shape.face_of(f)?;
    let (i, j) = match drop {
        0 => (1, 2),
        1 => (2, 0),
        _ => (0, 1),
    };
    let all: Vec<usize> = edges.iter().chain(inside).copied().collect();
    let mut index: HashMap<usize, usize> = HashMap::new();
    let mut plane = Plane { edges: Vec::new(), pts: Vec::new() };
    for &e in &all {
        let (a, b) = shape.ends_of(e)?;
        let mut at = |v: usize| {
            *index.entry(v).or_insert_with(|| {
                let p = shape.point(v);
                plane.pts.push([p[i], p[j]]);
                plane.pts.len() - 1
            })
        };
        let (a, b) = (at(a), at(b));
        plane.edges.push((a, b));
    }
    let cycles = plane.cycles();
    let own = 0..edges.len();
    let kept: Vec<&Cycle> =
        cycles.iter().filter(|c| c.area2 > 0.0 && plane.inside(own.clone(), plane.left_of(c))).collect();
    if kept.len() < 2 {
        return None;
    }
    let mut pieces: Vec<Vec<usize>> = kept.iter().map(|c| c.halves.clone()).collect();
    for c in cycles.iter().filter(|c| c.area2 <= 0.0) {
        let p = plane.left_of(c);
        let around = (0..kept.len())
            .filter(|&k| plane.inside(kept[k].halves.iter().map(|h| h / 2), p))
            .min_by(|&a, &b| kept[a].area2.total_cmp(&kept[b].area2));
        if let Some(k) = around {
            pieces[k].extend(&c.halves);
        }
    }
    Some(
        pieces
            .into_iter()
            .map(|halves| {
                let mut count: BTreeMap<usize, usize> = BTreeMap::new();
                for h in halves {
                    *count.entry(all[h / 2]).or_default() += 1;
                }
                count.into_iter().filter(|x| x.1 % 2 == 1).map(|x| x.0).collect()
            })
            .collect(),
    )
}
