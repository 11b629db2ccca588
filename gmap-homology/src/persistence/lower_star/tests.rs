use super::super::{cubical_persistence, Construction, CubicalOptions, Diagram};

/// Values from a xorshift generator: `levels` distinct values (ties), or all distinct
/// (`levels` 0).
fn values(n: usize, seed: u64, levels: u64) -> Vec<f64> {
    let mut x = seed;
    (0..n)
        .map(|_| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            if levels == 0 {
                (x >> 11) as f64 / (1u64 << 53) as f64
            } else {
                (x % levels) as f64
            }
        })
        .collect()
}

fn pairs(d: &Diagram) -> Vec<(usize, u64, u64)> {
    let mut v: Vec<_> = d.pairs.iter().map(|p| (p.dim, p.birth.to_bits(), p.death.to_bits())).collect();
    v.sort_unstable();
    v
}

/// The pixel route's 3-D diagrams equal the general route's (the one that gives
/// cycles) on arrays large enough for long columns, stored columns and every kind of
/// addition in the middle dimension, and on arrays one or two pixels thick (the padded
/// border on both sides of a pixel).
#[test]
fn pixel_route_equals_general_route_in_3d() {
    for (shape, seed, levels) in [
        ([20, 18, 16], 7, 0),
        ([17, 19, 13], 11, 0),
        ([12, 14, 15], 5, 4),
        ([9, 10, 11], 3, 2),
        ([1, 9, 8], 13, 0),
        ([7, 2, 1], 17, 3),
        ([2, 11, 2], 19, 0),
    ] {
        let vals = values(shape.iter().product(), seed, levels);
        for construction in [Construction::V, Construction::T] {
            for (field, superlevel) in [(2, false), (3, false), (2, true)] {
                let mut opts = CubicalOptions { construction, superlevel, periodic: false, field, cycles: false };
                let fast = cubical_persistence(&shape, &vals, &opts).unwrap();
                opts.cycles = true;
                let general = cubical_persistence(&shape, &vals, &opts).unwrap();
                assert_eq!(pairs(&fast), pairs(&general), "{shape:?} {construction:?} Z/{field} {superlevel}");
            }
        }
    }
}

/// The same on many small random arrays, few of them with distinct values: ties make
/// the order of the cells of one rank matter (which edges join two components, and
/// so which rows the middle pass leaves out).
#[test]
fn pixel_route_equals_general_route_on_small_3d_arrays() {
    for seed in 1..=60u64 {
        let shape = [2 + seed as usize % 5, 2 + (seed as usize / 5) % 4, 3 + (seed as usize / 3) % 5];
        let vals = values(shape.iter().product(), seed * 7919, seed % 4);
        for construction in [Construction::V, Construction::T] {
            for field in [2, 3] {
                let mut opts =
                    CubicalOptions { construction, superlevel: false, periodic: false, field, cycles: false };
                let fast = cubical_persistence(&shape, &vals, &opts).unwrap();
                opts.cycles = true;
                let general = cubical_persistence(&shape, &vals, &opts).unwrap();
                assert_eq!(pairs(&fast), pairs(&general), "{shape:?} seed {seed} {construction:?} Z/{field}");
            }
        }
    }
}
