//! What every builder shares: the error and the checked dart count.

use thiserror::Error;

/// Why a builder refused its arguments.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum BuildError {
    /// An argument out of range (a 0-gon, a grid with a zero side, a lens space with p = 0…).
    #[error("bad argument: {0}")]
    BadArgument(String),
    /// The object would have 2^32 - 1 darts or more.
    #[error("{what} would have more than 2^32 - 2 darts")]
    TooManyDarts {
        /// the object asked for
        what: String,
    },
    /// A token of a polygonal schema that is not a letter name.
    #[error("schema token '{token}' is not a letter name (use a, A, a', a^-1, a1 …)")]
    BadToken {
        /// the token
        token: String,
    },
    /// A schema letter used more than twice.
    #[error("schema letter '{letter}' is used {count} times (at most 2: twice glues, once is boundary)")]
    LetterUsedTooOften {
        /// the letter
        letter: String,
        /// how many times it occurs
        count: usize,
    },
    /// The map would pass the memory limit.
    #[error(transparent)]
    MemoryLimit(#[from] gmap_core::resources::MemoryLimit),
}

/// The darts of a map of dimension `dim` whose count is the product of `factors`: refused
/// from 2^32 - 1 on (the largest dart index), and when the map's involutions (a `u32` per
/// dart and dimension) would pass the memory limit (`gmap_core::resources`), before they
/// are allocated.
pub(super) fn checked_darts(what: impl Fn() -> String, dim: usize, factors: &[u64]) -> Result<usize, BuildError> {
    let darts = factors
        .iter()
        .try_fold(1u64, |a, &b| a.checked_mul(b))
        .filter(|&d| d < u32::MAX as u64)
        .ok_or_else(|| BuildError::TooManyDarts { what: what() })?;
    let bytes = darts.checked_mul(4 * (dim as u64 + 1));
    gmap_core::resources::check_memory(&what(), bytes)?;
    Ok(darts as usize)
}
