//! Incidence signs left out of a file, chosen so that every region's boundary is a cycle
//! (`.json` entries without `"weight"`).
//!
//! Regions are oriented one dimension after the other. An edge goes from its first end to
//! its second (with points, from the lexicographically lower point to the higher one, TM
//! §III); an edge with one end is a loop (weight 0). A k-region, k ≥ 2, takes each of its
//! (k-1)-faces with the sign that makes the faces cancel on every (k-2)-region they share,
//! found by propagation from its first face; a region whose faces cannot cancel is refused
//! with its name ([`ArchError::CannotOrient`]). A boundary in several components (a wall
//! around a window, a floor around a court) needs points: the component of the largest
//! vector area (2-regions) or volume (3-regions) turns one way, the others the other way;
//! without points it is refused. The regions of the top dimension are then turned so that
//! their orientations agree: with points, every 3-region has a positive volume (the normals
//! of its faces point out of it) and a plane 2-region runs anticlockwise seen from +z;
//! without points, neighbours take their common face with opposite signs; a complex where no
//! choice does (a Möbius band of regions) is refused, naming the region where the
//! propagation meets itself with the wrong sign and the face. Entries across a dimension gap
//! get 0 (AC Def. 3.1).
//!
//! O(E · log E) over the entries, plus the propagation, linear in the entries of each region.

use std::collections::{BTreeMap, HashMap, VecDeque};

use super::model::{ArchError, Region, RegionId};

/// An entry whose weight may be left out.
pub type LooseEntry = (RegionId, RegionId, Option<i64>);

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

struct State<'a> {
    regions: &'a [Region],
    points: Vec<Option<[f64; 3]>>,
    /// the entries to the dimension just below, by region index: (to, weight)
    down: Vec<Vec<(usize, i64)>>,
}

impl State<'_> {
    fn fail(&self, c: usize, reason: impl Into<String>) -> ArchError {
        ArchError::CannotOrient { id: self.regions[c].id, dim: self.regions[c].dim, reason: reason.into(), at: None }
    }

    /// The ends (from, to) of an oriented edge, `None` for a loop.
    fn ends(&self, e: usize) -> Option<(usize, usize)> {
        let from = self.down[e].iter().find(|x| x.1 < 0)?.0;
        let to = self.down[e].iter().find(|x| x.1 > 0)?.0;
        Some((from, to))
    }

    /// Twice the vector area of a chain of 2-regions (signed), `None` without points.
    fn area2(&self, faces: &[(usize, i64)]) -> Option<[f64; 3]> {
        let mut a = [0.0; 3];
        for &(f, s) in faces {
            for &(e, w) in &self.down[f] {
                if let Some((u, v)) = self.ends(e) {
                    let c = cross(self.points[u]?, self.points[v]?);
                    let k = (s * w) as f64;
                    a = [a[0] + k * c[0], a[1] + k * c[1], a[2] + k * c[2]];
                }
            }
        }
        Some(a)
    }

    /// Six times the volume enclosed by a chain of 2-regions, `None` without points.
    fn volume6(&self, faces: &[(usize, i64)]) -> Option<f64> {
        let mut vol = 0.0;
        for &(f, s) in faces {
            let mut ends = Vec::new();
            for &(e, w) in &self.down[f] {
                if let Some((u, v)) = self.ends(e) {
                    ends.push((self.points[u]?, self.points[v]?, (s * w) as f64));
                }
            }
            if ends.is_empty() {
                continue;
            }
            let n = ends.len() as f64;
            let c = ends.iter().fold([0.0; 3], |c, (a, _, _)| [c[0] + a[0] / n, c[1] + a[1] / n, c[2] + a[2] / n]);
            for (a, b, k) in ends {
                vol += k * dot(c, cross(a, b));
            }
        }
        Some(vol)
    }

    /// The signs of the faces of `c` that make its boundary a cycle, one sign per
    /// component of the boundary (the first face of each component taken positively).
    fn face_signs(&self, c: usize) -> Result<Vec<Vec<(usize, i64)>>, ArchError> {
        let faces: Vec<usize> = self.down[c].iter().map(|x| x.0).collect();
        let mut on: BTreeMap<usize, Vec<(usize, i64)>> = BTreeMap::new();
        for (j, &f) in faces.iter().enumerate() {
            for &(r, w) in &self.down[f] {
                if w != 0 {
                    on.entry(r).or_default().push((j, w));
                }
            }
        }
        let mut sign = vec![0i64; faces.len()];
        let mut components = Vec::new();
        for start in 0..faces.len() {
            if sign[start] != 0 {
                continue;
            }
            sign[start] = 1;
            let mut comp = vec![start];
            let mut queue = VecDeque::from([start]);
            while let Some(j) = queue.pop_front() {
                for &(r, _) in &self.down[faces[j]] {
                    let Some(list) = on.get(&r) else { continue };
                    if list.len() != 2 {
                        continue;
                    }
                    let ((a, wa), (b, wb)) = (list[0], list[1]);
                    let (k, wk, wj) = if a == j { (b, wb, wa) } else { (a, wa, wb) };
                    if k == j || wk.abs() != wj.abs() {
                        continue;
                    }
                    let s = -sign[j] * wj.signum() * wk.signum();
                    if sign[k] == 0 {
                        sign[k] = s;
                        comp.push(k);
                        queue.push_back(k);
                    } else if sign[k] != s {
                        return Err(self.fail(c, "its faces cannot be signed so that their boundaries cancel"));
                    }
                }
            }
            components.push(comp.into_iter().map(|j| (faces[j], sign[j])).collect::<Vec<_>>());
        }
        for (&r, list) in &on {
            let sum: i64 = list.iter().map(|&(j, w)| sign[j] * w).sum();
            if sum != 0 {
                return Err(ArchError::CannotOrient {
                    id: self.regions[c].id,
                    dim: self.regions[c].dim,
                    reason: "its faces do not cancel".into(),
                    at: Some(self.regions[r].id),
                });
            }
        }
        Ok(components)
    }

    /// The measure of a boundary component: a vector area (2-regions) or a volume (3-regions)
    /// as three numbers (a volume in the first); `None` without points or in other dimensions.
    fn measure(&self, k: usize, comp: &[(usize, i64)]) -> Option<[f64; 3]> {
        match k {
            2 => {
                // a component of a 2-region's boundary is a cycle of edges
                let mut a = [0.0; 3];
                for &(e, s) in comp {
                    let (u, v) = self.ends(e)?;
                    let c = cross(self.points[u]?, self.points[v]?);
                    a = [a[0] + s as f64 * c[0], a[1] + s as f64 * c[1], a[2] + s as f64 * c[2]];
                }
                Some(a)
            }
            3 => Some([self.volume6(comp)?, 0.0, 0.0]),
            _ => None,
        }
    }
}

/// The entries with every weight left out chosen (module docs); given weights are kept.
/// `points` are the points of 0-regions. Unknown ids are left to
/// [`super::ArchComplex::try_new`] to report. Fails with [`ArchError::CannotOrient`] naming
/// the region.
pub fn orient_entries(
    dim: usize,
    regions: &[Region],
    entries: &[LooseEntry],
    points: &HashMap<RegionId, [f64; 3]>,
) -> Result<Vec<(RegionId, RegionId, i64)>, ArchError> {
    let by_id: HashMap<RegionId, usize> = regions.iter().enumerate().map(|(k, r)| (r.id, k)).collect();
    let mut out: Vec<(RegionId, RegionId, i64)> = Vec::with_capacity(entries.len());
    let mut st = State {
        regions,
        points: regions.iter().map(|r| points.get(&r.id).copied()).collect(),
        down: vec![Vec::new(); regions.len()],
    };
    // entries whose weight is to be found, by region; the others are final
    let mut loose: Vec<Vec<usize>> = vec![Vec::new(); regions.len()];
    let mut given: Vec<bool> = vec![false; regions.len()];
    for &(f, t, w) in entries {
        let (Some(&a), Some(&b)) = (by_id.get(&f), by_id.get(&t)) else {
            out.push((f, t, w.unwrap_or(0)));
            continue;
        };
        let consecutive = regions[a].dim == regions[b].dim + 1;
        match w {
            Some(w) => {
                out.push((f, t, w));
                if consecutive {
                    st.down[a].push((b, w));
                    given[a] = true;
                }
            }
            None if consecutive => loose[a].push(b),
            None => out.push((f, t, 0)),
        }
    }
    let mut inferred_top = Vec::new();
    for k in 1..=dim {
        let todo: Vec<usize> = (0..regions.len()).filter(|&c| regions[c].dim == k && !loose[c].is_empty()).collect();
        if k >= 2 {
            check_closed(&st, &todo, &loose, &given)?;
        }
        for c in todo {
            if given[c] {
                return Err(st.fail(c, "some of its incidence weights are given and some left out"));
            }
            let faces = std::mem::take(&mut loose[c]);
            if k == 1 {
                let w = match faces.as_slice() {
                    [_] => vec![0],
                    [a, b] => {
                        let first_low = match (st.points[*a], st.points[*b]) {
                            (Some(p), Some(q)) => p <= q,
                            _ => true,
                        };
                        if first_low {
                            vec![-1, 1]
                        } else {
                            vec![1, -1]
                        }
                    }
                    _ => return Err(st.fail(c, format!("an edge has one or two ends, not {}", faces.len()))),
                };
                st.down[c] = faces.iter().copied().zip(w).collect();
                continue;
            }
            st.down[c] = faces.iter().map(|&f| (f, 1)).collect();
            let comps = st.face_signs(c)?;
            let mut signed: Vec<(usize, i64)> = Vec::with_capacity(faces.len());
            if comps.len() == 1 {
                signed.extend(&comps[0]);
            } else {
                let measures: Option<Vec<[f64; 3]>> = comps.iter().map(|cmp| st.measure(k, cmp)).collect();
                let Some(m) = measures else {
                    return Err(st.fail(
                        c,
                        format!("its boundary has {} components and no points tell how they turn", comps.len()),
                    ));
                };
                let size = |v: &[f64; 3]| dot(*v, *v);
                let outer = (0..m.len()).max_by(|&a, &b| size(&m[a]).total_cmp(&size(&m[b]))).unwrap_or(0);
                for (j, cmp) in comps.iter().enumerate() {
                    let turn = if j == outer || dot(m[j], m[outer]) < 0.0 { 1 } else { -1 };
                    signed.extend(cmp.iter().map(|&(f, s)| (f, s * turn)));
                }
            }
            st.down[c] = signed;
            if k == dim {
                inferred_top.push(c);
            }
        }
    }
    orient_top(&mut st, dim, &inferred_top)?;
    for (c, list) in st.down.iter().enumerate() {
        if given[c] {
            continue;
        }
        out.extend(list.iter().map(|&(t, w)| (regions[c].id, regions[t].id, w)));
    }
    Ok(out)
}

/// The (k-2)-regions on an odd number of the faces `faces` (counted with their weights):
/// where a boundary made of them is open, whatever the signs.
fn open_at(st: &State<'_>, faces: &[usize]) -> Vec<usize> {
    let mut count: BTreeMap<usize, i64> = BTreeMap::new();
    for &f in faces {
        for &(r, w) in &st.down[f] {
            *count.entry(r).or_default() += w.abs();
        }
    }
    count.into_iter().filter(|x| x.1 % 2 == 1).map(|x| x.0).collect()
}

/// Refuses the first of the k-regions `todo` (k ≥ 2, signs left out) whose faces leave a
/// (k-2)-region on an odd number of them ([`ArchError::BoundaryOpen`]), naming another one
/// open at one of the same places (the two miss the face between them). O(entries of the
/// regions and of their faces).
fn check_closed(st: &State<'_>, todo: &[usize], loose: &[Vec<usize>], given: &[bool]) -> Result<(), ArchError> {
    let open: Vec<(usize, Vec<usize>)> =
        todo.iter().filter(|&&c| !given[c]).map(|&c| (c, open_at(st, &loose[c]))).filter(|x| !x.1.is_empty()).collect();
    let Some((c, at)) = open.first() else { return Ok(()) };
    let with = open[1..].iter().find(|(_, o)| o.iter().any(|r| at.binary_search(r).is_ok())).map(|x| x.0);
    Err(ArchError::BoundaryOpen {
        id: st.regions[*c].id,
        dim: st.regions[*c].dim,
        at: at.iter().map(|&r| st.regions[r].id).collect(),
        with: with.map(|d| st.regions[d].id),
    })
}

/// Turns the top regions whose signs were chosen so that their orientations agree (module
/// docs); refuses a complex whose regions cannot agree.
fn orient_top(st: &mut State<'_>, dim: usize, top: &[usize]) -> Result<(), ArchError> {
    let flip = |st: &mut State<'_>, c: usize| st.down[c].iter_mut().for_each(|x| x.1 = -x.1);
    if dim == 3 {
        let volumes: Option<Vec<f64>> = top.iter().map(|&c| st.volume6(&st.down[c])).collect();
        if let Some(v) = volumes {
            for (&c, v) in top.iter().zip(v) {
                if v < 0.0 {
                    flip(st, c);
                }
            }
            return Ok(());
        }
    }
    // neighbours across a common face take it with opposite signs
    let mut on: HashMap<usize, Vec<usize>> = HashMap::new();
    for &c in top {
        for &(f, _) in &st.down[c] {
            on.entry(f).or_default().push(c);
        }
    }
    let weight = |st: &State<'_>, c: usize, f: usize| st.down[c].iter().find(|x| x.0 == f).map_or(0, |x| x.1);
    let mut seen = vec![false; st.regions.len()];
    for &start in top {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        let mut component = vec![start];
        let mut queue = VecDeque::from([start]);
        while let Some(c) = queue.pop_front() {
            let faces: Vec<usize> = st.down[c].iter().map(|x| x.0).collect();
            for f in faces {
                let Some(list) = on.get(&f) else { continue };
                if list.len() != 2 {
                    continue;
                }
                let d = if list[0] == c { list[1] } else { list[0] };
                if seen[d] {
                    // both already turned: a loop of neighbours that comes back reversed
                    if weight(st, c, f) * weight(st, d, f) > 0 {
                        return Err(ArchError::CannotOrient {
                            id: st.regions[d].id,
                            dim,
                            reason: "the complex is not orientable (a Möbius band, say): turned to agree with its \
                                     neighbours one way round, it disagrees with the neighbour across the face"
                                .into(),
                            at: Some(st.regions[f].id),
                        });
                    }
                    continue;
                }
                seen[d] = true;
                if weight(st, c, f) * weight(st, d, f) > 0 {
                    flip(st, d);
                }
                component.push(d);
                queue.push_back(d);
            }
        }
        // a plane complex (all points at one z) runs anticlockwise seen from +z
        if dim == 2 {
            if let Some(a) = st.area2(&[(start, 1)]) {
                if a[0] == 0.0 && a[1] == 0.0 && a[2] < 0.0 {
                    component.iter().for_each(|&c| flip(st, c));
                }
            }
        }
    }
    Ok(())
}
