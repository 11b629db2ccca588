//! Isomorphism of G-maps, for round-trip tests and deduplication.
//!
//! Two n-maps are isomorphic when a bijection of their darts commutes with every `alpha_i`.
//! For a connected map a bijection is fixed by the image of one dart, so the test walks
//! both maps in parallel (breadth first, trying `alpha_0, …, alpha_n` in order) from dart
//! `s` of the first map's first component and from each candidate dart of the second map.
//! Maps with several components are compared component by component through their
//! canonical codes. O(N²) in the worst case: meant for tests and small maps.

use gmap_core::{AlphaSet, DenseMap};

/// The canonical code of the component of dart `start`: the rows of its darts renumbered in
/// breadth-first order from `start` (a dart's number is its rank of first visit).
fn code_from(map: &DenseMap, start: u32, scratch: &mut [u32]) -> Vec<u32> {
    const UNSEEN: u32 = u32::MAX;
    let w = map.dim() + 1;
    let mut order = vec![start];
    scratch[start as usize] = 0;
    let mut k = 0;
    let mut code = Vec::new();
    while k < order.len() {
        let d = order[k] as usize;
        k += 1;
        for i in 0..w {
            let e = map.flat()[d * w + i];
            if scratch[e as usize] == UNSEEN {
                scratch[e as usize] = order.len() as u32;
                order.push(e);
            }
            code.push(scratch[e as usize]);
        }
    }
    for &d in &order {
        scratch[d as usize] = UNSEEN;
    }
    code
}

/// The canonical code of each component (the smallest code over its darts), sorted.
pub fn canonical_form(map: &DenseMap) -> Vec<Vec<u32>> {
    let comps = map.components();
    let (offsets, darts) = comps.members();
    let mut scratch = vec![u32::MAX; map.dart_count()];
    let mut out: Vec<Vec<u32>> = (0..comps.len())
        .map(|c| {
            darts[offsets[c]..offsets[c + 1]].iter().map(|&s| code_from(map, s, &mut scratch)).min().unwrap_or_default()
        })
        .collect();
    out.sort();
    out
}

/// Whether two maps are isomorphic (same dimension, a dart bijection commuting with every
/// `alpha_i`). Points are ignored. O(N²).
pub fn are_isomorphic(a: &DenseMap, b: &DenseMap) -> bool {
    if a.dim() != b.dim() || a.dart_count() != b.dart_count() {
        return false;
    }
    if a.cell_counts() != b.cell_counts()
        || a.count_orbits(AlphaSet::all(a.dim())) != b.count_orbits(AlphaSet::all(b.dim()))
    {
        return false;
    }
    canonical_form(a) == canonical_form(b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::build;

    #[test]
    fn relabelled_maps_are_isomorphic() {
        let m = build::schema("a b a B").unwrap();
        let n = m.dart_count() as u32;
        let perm: Vec<u32> = (0..n).map(|d| (d * 5 + 3) % n).collect();
        assert!(are_isomorphic(&m, &m.permuted(&perm)));
        assert!(!are_isomorphic(&m, &build::schema("a b A B").unwrap()));
        // extruding a square gives the cube
        let c = build::extrude(&build::cube(2).unwrap()).unwrap();
        assert!(are_isomorphic(&c, &build::cube(3).unwrap()));
        assert!(!are_isomorphic(&c, &build::cube(2).unwrap()));
    }
}
