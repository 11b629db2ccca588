//! The search past plateaus of 3-maps: random splits of cells of the greedy result (a face
//! across a volume, an edge across a face), a check that every cell is still a ball, and a
//! greedy reduction of the split map, kept when it is no larger (see the module docs of
//! `simplify` and [`SimplifyOptions::search`]).

use gmap_core::{DartId, DenseMap, GMap};

use super::{simplify_with, SimplifyOptions};
use crate::euler::ops;
use crate::rng::SplitMix64;

/// Whether every cell of a 3-map is a ball as the cellular method demands: C1 in every
/// dimension and a boundary of Euler characteristic 2 for every volume (faces and edges are
/// then balls by themselves). O(N).
fn cells_are_balls(map: &DenseMap) -> bool {
    map.oriented_cells_3d().is_some_and(|c| c.euler.iter().all(|&x| x == 2))
}

/// Splits up to `count` random cells of `g` (faces across volumes with seven chances in
/// ten, else edges across faces), trying at most 400 random placements; the number made.
/// Each placement tried adds the darts of `g` to `work` (the check of a split walks the
/// whole cell, up to the whole map).
fn split_random_cells(g: &mut GMap, count: usize, rng: &mut SplitMix64, work: &mut usize) -> usize {
    let mut made = 0;
    let mut darts: Vec<DartId> = g.darts().collect();
    for _ in 0..400 {
        if made == count {
            break;
        }
        if made > 0 && darts.len() != g.dart_count() {
            darts = g.darts().collect();
        }
        let darts = &darts;
        *work = work.saturating_add(darts.len());
        let pick = |rng: &mut SplitMix64| darts[rng.below(darts.len())];
        if rng.below(10) < 7 {
            // a face across a volume along the closed path of one to three edge sides
            let k = 1 + rng.below(3);
            let seeds: Vec<DartId> = (0..k).map(|_| pick(rng)).collect();
            if ops::split_cell_quietly(g, &seeds, 3) {
                made += 1;
            }
        } else {
            // an edge across the face of d1, to a corner of that face
            let d1 = pick(rng);
            let mut ring = vec![d1];
            let mut x = d1;
            loop {
                let y = g.alpha(x, 0);
                ring.push(y);
                x = g.alpha(y, 1);
                if x == d1 || x == y || ring.len() > darts.len() {
                    break;
                }
                ring.push(x);
            }
            let d2 = ring[rng.below(ring.len())];
            if ops::insert_edge_quietly(g, d1, d2) {
                made += 1;
            }
        }
    }
    made
}

/// Greedy results above this many darts are not searched: every split is checked on the
/// whole map, so a round costs O(N) per attempt, and such results are already far below
/// the input.
const SEARCH_MAX_DARTS: usize = 1 << 10;

/// The search of [`SimplifyOptions::search`] from the greedy result `map`; the smallest map
/// found and the rounds made.
///
/// Chains of rounds start from `map`; a chain keeps a split-and-simplify round when the map
/// has at most as many darts, and ends after `search / 8` rounds without fewer darts. A new
/// chain starts (at most four) while the last one improved on the best map so far: chains
/// that find their way down usually do so within a few hundred rounds, and one that does
/// not sits on a plateau that more random splits rarely leave. Splits grow with the map:
/// up to a third of its darts' count, between 3 and 40. The search also stops when the
/// placements tried have walked `2048 · search` darts (each costs up to the map's size).
/// Returns the map, the rounds made and the work done (darts walked by the placements tried
/// and darts of the split maps simplified).
pub(super) fn search(map: DenseMap, options: &SimplifyOptions, rng: &mut SplitMix64) -> (DenseMap, usize, usize) {
    if map.dim() != 3
        || options.search == 0
        || map.dart_count() == 0
        || map.dart_count() > SEARCH_MAX_DARTS
        || !cells_are_balls(&map)
    {
        return (map, 0, 0);
    }
    let inner = SimplifyOptions { tries: 2, seed: 0, search: 0 };
    let budget = options.search.saturating_mul(256);
    // the placements tried: each walks its cell, up to the whole map, and most fail where
    // the cells meet themselves often; without this bound a round could cost 400 N
    let tries_budget = options.search.saturating_mul(2048);
    let patience = options.search.div_ceil(8);
    let mut best = map.clone();
    let (mut spent, mut rounds, mut tried) = (0usize, 0, 0usize);
    for _chain in 0..4 {
        let mut cur = map.clone();
        let mut since = 0;
        while rounds < options.search && since < patience && spent < budget && tried < tries_budget {
            rounds += 1;
            since += 1;
            let (mut g, _) = GMap::from_dense(&cur);
            let most = (cur.dart_count() / 3).clamp(3, 40);
            let kicks = 1 + rng.below(most);
            if split_random_cells(&mut g, kicks, rng, &mut tried) == 0 {
                continue;
            }
            let split = g.to_dense_map();
            spent += split.dart_count();
            if !cells_are_balls(&split) {
                continue;
            }
            let (small, _) = simplify_with(&split, &SimplifyOptions { seed: rng.next_u64(), ..inner });
            if small.dart_count() <= cur.dart_count() && cells_are_balls(&small) {
                if small.dart_count() < cur.dart_count() {
                    since = 0;
                }
                cur = small;
            }
        }
        if cur.dart_count() >= best.dart_count() {
            break;
        }
        best = cur;
    }
    (best, rounds, spent.saturating_add(tried))
}
