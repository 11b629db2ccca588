//! The one memory policy of the workspace: how many bytes a command may use, and the check
//! made with a cost estimate before any large allocation.
//!
//! The limit in force is [`max_memory`]: the value given to [`set_max_memory`] (the
//! `--max-memory` option of the `gmap` command), or else a default derived from the machine
//! ([`default_max_memory`]): half the physical memory, and no more than three quarters of
//! the process's address-space limit (`ulimit -v`) when one is set. An estimate above it is
//! refused with a [`MemoryLimit`] error naming the estimate and the limit, before anything
//! is allocated. Every reader, the simplicial counterpart, the face poset and the dense
//! stage of the Smith normal form take their limits from here ([`memory_budget`]).
//!
//! Time is bounded the same way where a few bytes of input describe a large map: the
//! default dart limit of the imports that build a map from facets, polygons or a face
//! poset is also at most what [`DEFAULT_MAX_WORK`] dart visits can analyse
//! ([`max_darts_for_work`]); `--max-darts` given explicitly replaces it.
//!
//! The machine's figures are read from `/proc/meminfo` and `/proc/self/limits` (Linux);
//! where they cannot be read, the default is [`FALLBACK_MAX_MEMORY`].

use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};

use thiserror::Error;

/// The default limit where the machine's memory cannot be read: 4 GiB.
pub const FALLBACK_MAX_MEMORY: u64 = 4 << 30;

/// The limit set by [`set_max_memory`]; 0 while unset.
static MAX_MEMORY: AtomicU64 = AtomicU64::new(0);

/// An estimated cost over the memory limit.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[error("{what} would take an estimated {} bytes, over the memory limit of {limit} bytes (--max-memory)",
    estimate.map_or_else(|| "more than 2^64".to_string(), |e| e.to_string()))]
pub struct MemoryLimit {
    /// what the memory is for
    pub what: String,
    /// the estimate in bytes, `None` past `u64`
    pub estimate: Option<u64>,
    /// the limit in force
    pub limit: u64,
}

/// A `--max-memory` value that is not a size.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[error("'{0}' is not a size in bytes: expected digits with an optional K, M, G or T suffix (powers of 1024), at least 1 and at most 2^64 - 1")]
pub struct SizeError(pub String);

/// Parses a size in bytes: digits with an optional suffix `K`, `M`, `G` or `T` (powers of
/// 1024, either case, an optional trailing `B` or `iB`): `4096`, `512M`, `2G`, `1.5G` is
/// refused (whole numbers only). The value must be at least 1.
///
/// ```
/// use gmap_core::resources::parse_size;
/// assert_eq!(parse_size("2G"), Ok(2 << 30));
/// assert_eq!(parse_size("512m"), Ok(512 << 20));
/// assert_eq!(parse_size("100"), Ok(100));
/// assert!(parse_size("0").is_err() && parse_size("2X").is_err() && parse_size("99999999999T").is_err());
/// ```
pub fn parse_size(text: &str) -> Result<u64, SizeError> {
    let err = || SizeError(crate::text::shorten(text.as_bytes(), 80));
    let t = text.trim();
    let t = t.strip_suffix("iB").or_else(|| t.strip_suffix("ib")).unwrap_or(t);
    let digits_end = t.find(|c: char| !c.is_ascii_digit()).unwrap_or(t.len());
    let (digits, suffix) = t.split_at(digits_end);
    let shift = match suffix.trim_end_matches(['B', 'b']) {
        "" => 0,
        "K" | "k" => 10,
        "M" | "m" => 20,
        "G" | "g" => 30,
        "T" | "t" => 40,
        _ => return Err(err()),
    };
    if suffix.len() > 1 && shift == 0 {
        return Err(err());
    }
    let n: u64 = digits.parse().map_err(|_| err())?;
    n.checked_mul(1 << shift).filter(|&v| v > 0).ok_or_else(err)
}

/// Sets the memory limit of this process (what `--max-memory` gives).
pub fn set_max_memory(bytes: u64) {
    MAX_MEMORY.store(bytes.max(1), Ordering::Relaxed);
}

/// Returns to the default limit ([`default_max_memory`]) after [`set_max_memory`].
pub fn clear_max_memory() {
    MAX_MEMORY.store(0, Ordering::Relaxed);
}

/// The memory limit in force: the one set by [`set_max_memory`], else
/// [`default_max_memory`].
pub fn max_memory() -> u64 {
    match MAX_MEMORY.load(Ordering::Relaxed) {
        0 => default_max_memory(),
        set => set,
    }
}

/// The default limit: half the physical memory (`MemTotal`), and at most three quarters of
/// the address-space limit (`ulimit -v`) when there is one (the rest is for the program,
/// its input and the allocator). [`FALLBACK_MAX_MEMORY`] where neither can be read.
///
/// Both figures are fixed for the life of the process, so they are read once (the first
/// call) and remembered: a command checks its estimates many times.
pub fn default_max_memory() -> u64 {
    static DEFAULT: std::sync::OnceLock<u64> = std::sync::OnceLock::new();
    *DEFAULT.get_or_init(machine_max_memory)
}

/// [`default_max_memory`] read from the machine now.
fn machine_max_memory() -> u64 {
    let half = physical_memory().map(|b| b / 2);
    let space = address_space_limit().map(|b| b / 4 * 3);
    match (half, space) {
        (Some(h), Some(s)) => h.min(s),
        (Some(x), None) | (None, Some(x)) => x,
        (None, None) => FALLBACK_MAX_MEMORY,
    }
}

/// The bytes a large allocation may take now: [`max_memory`], and no more than the memory
/// available (`MemAvailable`) when it can be read.
pub fn memory_budget() -> u64 {
    let limit = max_memory();
    available_memory().map_or(limit, |a| a.min(limit))
}

/// Refuses an estimate over [`max_memory`] (`None`: past `u64`), naming `what`.
///
/// ```
/// use gmap_core::resources::{check_memory, max_memory};
/// assert!(check_memory("a small table", Some(1024)).is_ok());
/// let e = check_memory("the orderings", None).unwrap_err();
/// assert_eq!(e.limit, max_memory());
/// assert!(e.to_string().starts_with("the orderings would take an estimated more than 2^64 bytes"));
/// ```
pub fn check_memory(what: &str, estimate: Option<u64>) -> Result<(), MemoryLimit> {
    let limit = max_memory();
    match estimate {
        Some(e) if e <= limit => Ok(()),
        _ => Err(MemoryLimit { what: what.to_string(), estimate, limit }),
    }
}

/// The default work limit of a map built from a short description (the G-map of `.facets`,
/// `.lex` or `.off` input, of a face poset): `2^30` dart visits, about 20 seconds of
/// analysis. A file of a few bytes can describe a map whose memory fits the limit but whose
/// cells, orientation and validity take minutes to compute (one 11-vertex facet: 11! darts in
/// dimension 10); the default dart limit of those imports is therefore also at most
/// [`max_darts_for_work`]. An explicit `--max-darts` replaces both.
pub const DEFAULT_MAX_WORK: u64 = 1 << 30;

/// The work of analysing an n-map of `darts` darts, in dart visits: `darts · (n + 1)²`
/// (n + 1 cell partitions, each visiting every dart once per involution); `None` past `u64`.
///
/// ```
/// use gmap_core::resources::map_work;
/// assert_eq!(map_work(39_916_800, 10), Some(4_829_932_800)); // 11! darts: over 2^30
/// assert_eq!(map_work(3_628_800, 9), Some(362_880_000)); // 10! darts: under
/// ```
pub fn map_work(darts: u64, dim: usize) -> Option<u64> {
    let w = (dim as u64).checked_add(1)?;
    darts.checked_mul(w.checked_mul(w)?)
}

/// The most darts an n-map built from a short description may have by default:
/// [`DEFAULT_MAX_WORK`]` / (n + 1)²` (see [`map_work`]). O(1).
///
/// ```
/// use gmap_core::resources::max_darts_for_work;
/// assert_eq!(max_darts_for_work(10), 8_873_899);
/// assert_eq!(max_darts_for_work(2), 119_304_647);
/// ```
pub fn max_darts_for_work(dim: usize) -> u64 {
    let w = (dim as u64).saturating_add(1);
    DEFAULT_MAX_WORK / w.saturating_mul(w)
}

/// Bytes a point of the doubled grid of a cubical set takes while its chain complex is
/// built (`gmap_homology::cubical`): its state (1 byte), its entry on the collapse stack (4)
/// and its cell number (4). The matrices of the cells left after the collapses are estimated
/// apart, from their exact counts.
pub const CUBICAL_BYTES_PER_POINT: u64 = 9;

/// The points of the doubled grid of a box of `shape` unit cubes, one per cell of the closed
/// box: `Π (2 L_a + 1)`, or `Π 2 L_a` when `periodic`; `None` past `u64`. O(d).
///
/// ```
/// use gmap_core::resources::cubical_grid_points;
/// assert_eq!(cubical_grid_points(&[3, 2], false), Some(35));
/// assert_eq!(cubical_grid_points(&[3, 2], true), Some(24));
/// assert_eq!(cubical_grid_points(&[1 << 40, 1 << 40], false), None);
/// ```
pub fn cubical_grid_points(shape: &[usize], periodic: bool) -> Option<u64> {
    shape.iter().try_fold(1u64, |v, &l| {
        let n = (l as u64).checked_mul(2)?.checked_add(u64::from(!periodic))?;
        v.checked_mul(n)
    })
}

/// The estimated bytes of a cubical set on a box of `shape` cubes and of the grid its
/// chain complex is built on: one byte a box cube (the bitmap) and
/// [`CUBICAL_BYTES_PER_POINT`] per point of the doubled grid (the larger, non-periodic one);
/// `None` past `u64`. The readers of `.cub` and `.pbm` files check it from the bounding box
/// before the bitmap is allocated. O(d).
///
/// ```
/// use gmap_core::resources::cubical_set_estimate;
/// // a 1 × 2^30 box: a 1 GiB bitmap and a grid of 3 × (2^31 + 1) points
/// assert_eq!(cubical_set_estimate(&[1, 1 << 30]), Some((1 << 30) + 9 * 3 * ((1 << 31) + 1)));
/// ```
pub fn cubical_set_estimate(shape: &[usize]) -> Option<u64> {
    let volume = shape.iter().try_fold(1u64, |v, &l| v.checked_mul(l as u64))?;
    cubical_grid_points(shape, false)?.checked_mul(CUBICAL_BYTES_PER_POINT)?.checked_add(volume)
}

/// `MemTotal` of `/proc/meminfo` in bytes, where it can be read.
pub fn physical_memory() -> Option<u64> {
    meminfo("MemTotal:")
}

/// `MemAvailable` of `/proc/meminfo` in bytes, where it can be read.
pub fn available_memory() -> Option<u64> {
    meminfo("MemAvailable:")
}

fn meminfo(key: &str) -> Option<u64> {
    let text = std::fs::read_to_string(Path::new("/proc").join("meminfo")).ok()?;
    let line = text.lines().find(|l| l.starts_with(key))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb.saturating_mul(1024))
}

/// The peak resident memory of this process so far in bytes (`VmHWM` of
/// `/proc/self/status`, what `/usr/bin/time -v` reports as "Maximum resident set size"),
/// where it can be read. Pages of mapped files that were read count too.
pub fn peak_rss() -> Option<u64> {
    status("VmHWM:")
}

/// Resets the high-water mark that [`peak_rss`] reads to the resident memory of now (writes
/// `5` to `/proc/self/clear_refs`, Linux ≥ 4.0), so that a later [`peak_rss`] is the peak of
/// what ran in between. Returns whether the reset was made; where it was not (no `/proc`, a
/// kernel or a sandbox that refuses the write), [`peak_rss`] stays the peak since the start.
///
/// ```
/// use gmap_core::resources::{peak_rss, reset_peak_rss};
/// if reset_peak_rss() {
///     let big = vec![1u8; 64 << 20];
///     assert!(peak_rss().unwrap() >= 64 << 20);
///     drop(big);
///     assert!(reset_peak_rss());
///     assert!(peak_rss().unwrap() < 64 << 20);
/// }
/// ```
pub fn reset_peak_rss() -> bool {
    std::fs::write(Path::new("/proc").join("self").join("clear_refs"), b"5").is_ok()
}

/// The resident memory of this process now in bytes (`VmRSS` of `/proc/self/status`).
pub fn current_rss() -> Option<u64> {
    status("VmRSS:")
}

fn status(key: &str) -> Option<u64> {
    let text = std::fs::read_to_string(Path::new("/proc").join("self").join("status")).ok()?;
    let line = text.lines().find(|l| l.starts_with(key))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb.saturating_mul(1024))
}

/// The soft address-space limit of this process (`ulimit -v`, "Max address space" of
/// `/proc/self/limits`) in bytes; `None` when unlimited or unreadable.
pub fn address_space_limit() -> Option<u64> {
    let text = std::fs::read_to_string(Path::new("/proc").join("self").join("limits")).ok()?;
    let line = text.lines().find(|l| l.starts_with("Max address space"))?;
    line["Max address space".len()..].split_whitespace().next()?.parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes() {
        assert_eq!(parse_size("1K"), Ok(1024));
        assert_eq!(parse_size("3MB"), Ok(3 << 20));
        assert_eq!(parse_size("1GiB"), Ok(1 << 30));
        assert_eq!(parse_size("2T"), Ok(2 << 40));
        for bad in ["", "G", "-1", "1.5G", "1KK", "16777216T", "1 G x"] {
            assert!(parse_size(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn peak_is_at_least_current() {
        // the current size first: the high-water mark read after it cannot be smaller, even
        // while other tests of this process allocate in between
        let now = current_rss();
        let peak = peak_rss();
        if let (Some(peak), Some(now)) = (peak, now) {
            assert!(peak >= now && now > 0);
        }
    }

    #[test]
    fn default_is_positive_and_bounded_by_the_machine() {
        let d = default_max_memory();
        assert!(d > 0);
        if let Some(total) = physical_memory() {
            assert!(d <= total / 2);
        }
    }
}
