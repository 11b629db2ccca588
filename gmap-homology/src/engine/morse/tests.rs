use super::*;
use crate::engine::homology::homology_z;
use crate::engine::homology::tests::complex;
use crate::engine::ring::{Zi64, Zp};

#[test]
fn a_filled_triangle_reduces_to_one_vertex() {
    // vertices 0 1 2, edges 01 12 02, one face 01 + 12 - 02
    let c = complex(
        vec![3, 3, 1],
        vec![
            vec![(0, 0, -1), (1, 0, 1), (1, 1, -1), (2, 1, 1), (0, 2, -1), (2, 2, 1)],
            vec![(0, 0, 1), (1, 0, 1), (2, 0, -1)],
        ],
    );
    let r = prereduce(&Zi64, &c, true).unwrap();
    assert_eq!(r.chain.counts(), &[1, 0, 0]);
    assert_eq!(r.ids[0], vec![0]);
}

#[test]
fn a_circle_keeps_one_edge() {
    let c = complex(vec![3, 3], vec![vec![(0, 0, -1), (1, 0, 1), (1, 1, -1), (2, 1, 1), (0, 2, 1), (2, 2, -1)]]);
    let r = prereduce(&Zi64, &c, true).unwrap();
    assert_eq!(r.chain.counts(), &[1, 1]);
    assert!(r.chain.boundary(1).is_zero());
}

#[test]
fn one_vertex_per_component_is_set_aside() {
    // two filled triangles, on vertices 0 1 2 and 3 4 5: the smallest vertex of each stays
    let tri = |o: usize, e: usize| {
        vec![(o, e, -1), (o + 1, e, 1), (o + 1, e + 1, -1), (o + 2, e + 1, 1), (o, e + 2, -1), (o + 2, e + 2, 1)]
    };
    let mut d1 = tri(0, 0);
    d1.extend(tri(3, 3));
    let d2 = vec![(0, 0, 1), (1, 0, 1), (2, 0, -1), (3, 1, 1), (4, 1, 1), (5, 1, -1)];
    let r = prereduce(&Zi64, &complex(vec![6, 6, 2], vec![d1, d2]), true).unwrap();
    assert_eq!(r.chain.counts(), &[2, 0, 0]);
    assert_eq!(r.ids[0], vec![0, 3]);
    // the path 0 - 2 - 1: vertex 1 has no smaller neighbour, yet one component
    let c = complex(vec![3, 2], vec![vec![(0, 0, -1), (2, 0, 1), (1, 1, -1), (2, 1, 1)]]);
    let r = prereduce(&Zi64, &c, true).unwrap();
    assert_eq!(r.chain.counts(), &[1, 0]);
    assert_eq!(r.ids[0], vec![0]);
    assert_eq!(r.log.len(), 2);
}

#[test]
fn non_unit_entries_are_not_paired() {
    // the projective plane: one vertex, one edge (a loop), one face with ∂ = 2a
    let c = complex(vec![1, 1, 1], vec![vec![], vec![(0, 0, 2)]]);
    let r = prereduce(&Zi64, &c, true).unwrap();
    assert_eq!(r.chain.counts(), &[1, 1, 1]);
    assert_eq!(homology_z(&r.chain).unwrap().torsion[1], vec![2]);
    // over Z/3 the entry 2 is a unit: the edge and the face go
    let r = prereduce(&Zp { p: 3 }, &c, true).unwrap();
    assert_eq!(r.chain.counts(), &[1, 0, 0]);
    // over Z/2 it is zero: nothing to pair
    let r = prereduce(&Zp { p: 2 }, &c, true).unwrap();
    assert_eq!(r.chain.counts(), &[1, 1, 1]);
    assert!(r.chain.boundary(2).is_zero());
}

proptest::proptest! {
    /// `Ready` pops exactly what an ordered set of (dimension, cell) pairs would: the lowest
    /// dimension first, then the lowest cell, each pushed cell once.
    #[test]
    fn ready_pops_in_order(
        counts in proptest::collection::vec(0usize..9000, 1..4),
        ops in proptest::collection::vec((0usize..4, 0u32..9000, proptest::bool::ANY), 0..600),
    ) {
        let mut ready = Ready::new(&counts);
        let mut model = std::collections::BTreeSet::new();
        let starts: Vec<usize> = counts.iter().scan(0, |s, &m| { let x = *s; *s += m; Some(x) }).collect();
        for (k, j, push) in ops {
            let k = k % counts.len();
            if push && counts[k] > 0 {
                let j = j % counts[k] as u32;
                ready.push(k, j);
                model.insert((k, j));
            } else {
                let want = model.pop_first().map(|(k, j)| (k, j, starts[k] + j as usize));
                proptest::prop_assert_eq!(ready.pop(), want);
            }
        }
        while let Some((k, j)) = model.pop_first() {
            proptest::prop_assert_eq!(ready.pop(), Some((k, j, starts[k] + j as usize)));
        }
        proptest::prop_assert_eq!(ready.pop(), None);
    }
}
