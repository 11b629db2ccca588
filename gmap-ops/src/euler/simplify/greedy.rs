//! The greedy stage: scans of the cells in a fixed order of moves, each move followed at
//! once by the cells whose degree it lowered (the work stack), rounds of scans until one
//! changes nothing, and several runs from fresh copies of the input, of which the smallest
//! result is kept.

use gmap_core::DenseMap;

use super::work::Work;
use crate::euler::ops::Move;
use crate::rng::SplitMix64;

/// The smallest result of the greedy runs, and the rounds of scans it took.
pub(super) struct Best {
    pub(super) work: Work,
    pub(super) rounds: usize,
}

/// Runs the greedy stage `tries` times (at least once) from fresh copies of `map`: run 0
/// scans removals first and run 1 contractions first, in dart order; runs 2 and 3 do the
/// same and also re-examine the merged neighbour cell after each move; later runs repeat
/// the four in random orders of the darts drawn from `rng`. Returns the input's cells per
/// dimension and the run that kept the fewest darts (the first of equals).
pub(super) fn best_run(map: &DenseMap, tries: usize, rng: &mut SplitMix64) -> (Vec<usize>, Best) {
    let n = map.dim();
    let nd = map.dart_count();
    let (base, cells_before) = Work::new(map);
    let mut base = Some(base);
    let tries = tries.max(1);
    let removals: Vec<(usize, Move)> = (0..n).rev().map(|i| (i, Move::Remove)).collect();
    let contractions: Vec<(usize, Move)> = (1..=n).map(|i| (i, Move::Contract)).collect();
    let mut best: Option<Best> = None;
    for t in 0..tries {
        let steps: Vec<(usize, Move)> = if t % 2 == 0 {
            removals.iter().chain(&contractions).copied().collect()
        } else {
            contractions.iter().chain(&removals).copied().collect()
        };
        let mut order: Vec<u32> = (0..nd as u32).collect();
        if t >= 4 {
            rng.shuffle(&mut order);
        }
        let mut work =
            if t + 1 == tries { base.take().expect("kept for the last run") } else { base.clone().expect("kept") };
        work.up = (t / 2) % 2 == 1;
        let rounds = work.run(&steps, order);
        if best.as_ref().is_none_or(|b| work.live() < b.work.live()) {
            best = Some(Best { work, rounds });
        }
    }
    (cells_before, best.expect("at least one run"))
}

impl Work {
    /// Runs the work stack dry.
    fn drain(&mut self) {
        while let Some((k, kind, y)) = self.pending.pop() {
            self.try_move(k as usize, kind, y);
        }
    }

    /// One scan of the i-cells, in the order of `order` (live darts); returns the number of
    /// moves made.
    fn scan(&mut self, i: usize, kind: Move, order: &[u32], scan_id: u32) -> u32 {
        let before = self.moves;
        for &d in order {
            if !self.alive[d as usize] {
                continue;
            }
            let r = self.root(i, d) as usize;
            if self.exam[i][r] == scan_id {
                continue;
            }
            self.exam[i][r] = scan_id;
            if self.try_move(i, kind, d) {
                self.drain();
            }
        }
        self.moves - before
    }

    /// Rounds of scans in the given order of moves until one changes nothing; returns the
    /// number of rounds.
    fn run(&mut self, steps: &[(usize, Move)], mut order: Vec<u32>) -> usize {
        let mut rounds = 0;
        let mut scan_id = 0;
        loop {
            rounds += 1;
            let mut changed = 0;
            for &(i, kind) in steps {
                scan_id += 1;
                changed += self.scan(i, kind, &order, scan_id);
            }
            if changed == 0 {
                return rounds;
            }
            order.retain(|&d| self.alive[d as usize]);
        }
    }
}
