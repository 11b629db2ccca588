//! Random images for the cubical tests.

/// `n` cubes, each present with probability `density` percent, from a seeded LCG.
pub fn random_bits(n: usize, density: u64, seed: u64) -> Vec<u8> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((s >> 33) % 100 < density) as u8
        })
        .collect()
}
