//! The topology of AC §3.2 on the regions: stars, closures, open and closed sets, the T0
//! separation of Axiom 3.6 and connected components.

use super::ArchComplex;

impl ArchComplex {
    /// A topological order of the DAG: every region before the regions of its boundary
    /// (decreasing dimension, then index). O(R log R).
    pub fn topological_order(&self) -> Vec<usize> {
        let mut v: Vec<usize> = (0..self.regions.len()).collect();
        v.sort_by_key(|&r| (std::cmp::Reverse(self.regions[r].dim), r));
        v
    }

    fn reach(&self, seeds: &[usize], downward: bool) -> Vec<usize> {
        let mut seen = vec![false; self.regions.len()];
        let mut stack: Vec<usize> = Vec::new();
        for &s in seeds {
            if !seen[s] {
                seen[s] = true;
                stack.push(s);
            }
        }
        let mut out = Vec::new();
        while let Some(r) = stack.pop() {
            out.push(r);
            if downward {
                for e in self.down(r) {
                    if !seen[e.to] {
                        seen[e.to] = true;
                        stack.push(e.to);
                    }
                }
            } else {
                for e in self.up_of(r) {
                    if !seen[e.from] {
                        seen[e.from] = true;
                        stack.push(e.from);
                    }
                }
            }
        }
        out.sort_unstable();
        out
    }

    /// `Star(b)`: the regions with a path to `b` in the DAG, `b` included (AC §3.2); the
    /// smallest open set holding `b`. Sorted indices.
    pub fn star(&self, b: usize) -> Vec<usize> {
        self.reach(&[b], false)
    }

    /// The closure of `{b}` in the underlying topology: the regions reached from `b`, `b`
    /// included (those whose star holds `b`). Sorted indices.
    pub fn closure(&self, b: usize) -> Vec<usize> {
        self.reach(&[b], true)
    }

    /// The smallest open set holding a set of regions: the union of their stars.
    pub fn open_hull(&self, set: &[usize]) -> Vec<usize> {
        self.reach(set, false)
    }

    /// The closure of a set of regions: the union of their closures.
    pub fn closure_of(&self, set: &[usize]) -> Vec<usize> {
        self.reach(set, true)
    }

    /// Whether a set is open in the underlying topology (AC Def. 3.5): a union of stars,
    /// i.e. closed under going up the DAG. O(size + entries).
    pub fn is_open(&self, set: &[usize]) -> bool {
        let mut inside = vec![false; self.regions.len()];
        for &r in set {
            inside[r] = true;
        }
        set.iter().all(|&r| self.up_of(r).all(|e| inside[e.from]))
    }

    /// Whether a set is closed: its complement is open, i.e. it is closed under going down.
    pub fn is_closed(&self, set: &[usize]) -> bool {
        let mut inside = vec![false; self.regions.len()];
        for &r in set {
            inside[r] = true;
        }
        set.iter().all(|&r| self.down(r).iter().all(|e| inside[e.to]))
    }

    /// An open set holding exactly one of two distinct regions (the T0 axiom, AC Axiom 3.6):
    /// `Star(y)` if it misses `x`, else `Star(x)` (which then misses `y`, the DAG being
    /// acyclic). Panics if `x == y`.
    pub fn separating_open_set(&self, x: usize, y: usize) -> Vec<usize> {
        assert_ne!(x, y, "T0 separation needs two distinct regions");
        let sy = self.star(y);
        if sy.binary_search(&x).is_err() {
            sy
        } else {
            self.star(x)
        }
    }

    /// The connected components of a set of regions, linked by the entries between them
    /// (directions ignored). Each component sorted, components ordered by smallest index.
    pub fn components_of(&self, set: &[usize]) -> Vec<Vec<usize>> {
        let mut inside = vec![false; self.regions.len()];
        for &r in set {
            inside[r] = true;
        }
        let mut seen = vec![false; self.regions.len()];
        let mut sorted = set.to_vec();
        sorted.sort_unstable();
        let mut comps = Vec::new();
        for &s in &sorted {
            if seen[s] {
                continue;
            }
            seen[s] = true;
            let mut stack = vec![s];
            let mut comp = Vec::new();
            while let Some(r) = stack.pop() {
                comp.push(r);
                let nbrs = self.down(r).iter().map(|e| e.to).chain(self.up_of(r).map(|e| e.from)).collect::<Vec<_>>();
                for t in nbrs {
                    if inside[t] && !seen[t] {
                        seen[t] = true;
                        stack.push(t);
                    }
                }
            }
            comp.sort_unstable();
            comps.push(comp);
        }
        comps
    }

    /// Number of connected components of the incidence graph (directions ignored).
    /// O(R + E).
    pub fn component_count(&self) -> usize {
        let all: Vec<usize> = (0..self.regions.len()).collect();
        self.components_of(&all).len()
    }

    /// `Γ_b` of AC Example 8.19: the closure of `b` without `b` (its topological boundary
    /// as regions).
    pub fn boundary_regions(&self, b: usize) -> Vec<usize> {
        let mut c = self.closure(b);
        c.retain(|&r| r != b);
        c
    }
}
