//! How many threads whole-map stages use, and the rayon pool they run on.
//!
//! Every parallel stage of the workspace (orbit counts, orientability, the cells and C1/C2
//! checks, the border operator, simplification) runs on one [rayon] pool that this module
//! keeps, so one setting limits them all:
//!
//! * by default, every core the machine offers ([`std::thread::available_parallelism`]);
//! * the environment variable `GMAP_THREADS` (a positive integer), read once;
//! * [`set_max_threads`] from a program, which wins over both.
//!
//! The pool is built at the first stage that needs more than one thread and kept; a new
//! limit builds a new pool for the stages started afterwards. Rayon's global pool (and
//! `RAYON_NUM_THREADS`) is left to the program. [`install`] runs any closure, rayon
//! iterators included, on the stages' pool.
//!
//! Work is shared in two ways: [`map_tasks`] runs independent tasks (each its own rayon job,
//! so uneven tasks balance), and [`map_parts`] runs work already cut to the thread count,
//! such as the disjoint ranges of [`split_ranges`] for scans that merge their results
//! afterwards. Small inputs stay on the calling thread: waking the pool costs more than it
//! saves below [`PARALLEL_FROM`] items.
//!
//! ```
//! use gmap_core::parallel;
//! let squares = parallel::map_tasks(5, 1 << 20, |k| k * k);
//! assert_eq!(squares, vec![0, 1, 4, 9, 16]);
//! assert_eq!(parallel::split_ranges(10, 3), vec![0..4, 4..7, 7..10]);
//! let sum: u64 = parallel::install(|| {
//!     use rayon::prelude::*;
//!     (0..1000u64).into_par_iter().sum()
//! });
//! assert_eq!(sum, 499_500);
//! ```

use std::ops::Range;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, OnceLock};

use rayon::prelude::*;
use rayon::{ThreadPool, ThreadPoolBuilder};

/// Items (darts, entries) from which a stage is worth more than one thread.
pub const PARALLEL_FROM: usize = 1 << 16;

/// The limit set by [`set_max_threads`]; 0 when none was set.
static LIMIT: AtomicUsize = AtomicUsize::new(0);

/// The stages' pool and its number of threads, built on first use.
static POOL: Mutex<Option<(usize, Arc<ThreadPool>)>> = Mutex::new(None);

/// Limits every parallel stage to at most `n` threads (`n = 0` removes the limit, leaving
/// `GMAP_THREADS` or the machine's cores). Takes effect for stages started afterwards.
pub fn set_max_threads(n: usize) {
    LIMIT.store(n, Ordering::Relaxed);
}

/// The number of threads a stage may use: at least 1.
pub fn max_threads() -> usize {
    let set = LIMIT.load(Ordering::Relaxed);
    if set > 0 {
        return set;
    }
    static DEFAULT: OnceLock<usize> = OnceLock::new();
    *DEFAULT.get_or_init(|| {
        let env = std::env::var("GMAP_THREADS").ok().and_then(|v| v.trim().parse::<usize>().ok()).filter(|&n| n > 0);
        env.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |p| p.get()))
    })
}

/// Threads for a stage over `items` items split into at most `tasks` pieces: 1 below
/// [`PARALLEL_FROM`] items, else `min(max_threads(), tasks)`.
pub fn threads_for(items: usize, tasks: usize) -> usize {
    if items < PARALLEL_FROM || tasks < 2 {
        return 1;
    }
    max_threads().min(tasks).max(1)
}

/// The pool of [`max_threads`] threads, built when missing or when the limit changed;
/// `None` when the system refuses the threads (the stage then runs on the calling thread).
fn pool() -> Option<Arc<ThreadPool>> {
    let n = max_threads();
    let mut slot = POOL.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((k, p)) = slot.as_ref() {
        if *k == n {
            return Some(Arc::clone(p));
        }
    }
    let p = Arc::new(ThreadPoolBuilder::new().num_threads(n).thread_name(|i| format!("gmap-{i}")).build().ok()?);
    *slot = Some((n, Arc::clone(&p)));
    Some(p)
}

/// Runs `op` on the stages' pool of [`max_threads`] threads: rayon iterators and joins
/// inside it use that many threads. Runs it on the calling thread when the pool cannot be
/// built.
pub fn install<R, F>(op: F) -> R
where
    R: Send,
    F: FnOnce() -> R + Send,
{
    match pool() {
        Some(p) => p.install(op),
        None => op(),
    }
}

/// `(a(), b())`, as two rayon jobs on the stages' pool, or one after the other on the
/// calling thread when [`threads_for`]`(items, 2)` is 1.
pub fn join<A, B, RA, RB>(items: usize, a: A, b: B) -> (RA, RB)
where
    A: FnOnce() -> RA + Send,
    B: FnOnce() -> RB + Send,
    RA: Send,
    RB: Send,
{
    if threads_for(items, 2) == 1 {
        return (a(), b());
    }
    install(|| rayon::join(a, b))
}

/// `f(0), …, f(tasks - 1)` in order, each task its own rayon job on the stages' pool (so
/// uneven tasks balance), or on the calling thread when [`threads_for`]`(items, tasks)` is 1.
/// `items` is the size of the whole input, deciding whether threads pay at all.
pub fn map_tasks<T, F>(tasks: usize, items: usize, f: F) -> Vec<T>
where
    T: Send,
    F: Fn(usize) -> T + Sync + Send,
{
    if threads_for(items, tasks) == 1 {
        return (0..tasks).map(f).collect();
    }
    install(|| (0..tasks).into_par_iter().with_max_len(1).map(f).collect())
}

/// `0..len` cut into `parts` contiguous ranges of nearly equal length (the first ones one
/// longer), in order; `parts` is at least 1.
pub fn split_ranges(len: usize, parts: usize) -> Vec<Range<usize>> {
    let parts = parts.max(1);
    let (q, r) = (len / parts, len % parts);
    let mut out = Vec::with_capacity(parts);
    let mut start = 0;
    for k in 0..parts {
        let end = start + q + usize::from(k < r);
        out.push(start..end);
        start = end;
    }
    out
}

/// `f` applied to each of `parts`, each its own rayon job on the stages' pool, results in
/// order; one part runs on the calling thread. For work already cut to the thread count,
/// e.g. the disjoint mutable ranges of [`split_ranges`] over one array.
pub fn map_parts<T, R, F>(parts: Vec<T>, f: F) -> Vec<R>
where
    T: Send,
    R: Send,
    F: Fn(T) -> R + Sync + Send,
{
    if parts.len() <= 1 {
        return parts.into_iter().map(f).collect();
    }
    install(|| parts.into_par_iter().with_max_len(1).map(f).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_cover_in_order() {
        for len in 0..20 {
            for parts in 1..6 {
                let r = split_ranges(len, parts);
                assert_eq!(r.len(), parts);
                assert_eq!(r[0].start, 0);
                assert_eq!(r.last().unwrap().end, len);
                assert!(r.windows(2).all(|w| w[0].end == w[1].start));
                let lens: Vec<usize> = r.iter().map(|x| x.len()).collect();
                assert!(lens.iter().max().unwrap() - lens.iter().min().unwrap() <= 1);
            }
        }
    }

    #[test]
    fn tasks_in_order_on_threads() {
        let v = map_tasks(100, PARALLEL_FROM, |k| k * 3);
        assert_eq!(v, (0..100).map(|k| k * 3).collect::<Vec<_>>());
        let parts = map_parts(split_ranges(10, 3), |r| r.sum::<usize>());
        assert_eq!(parts, vec![6, 15, 24]);
    }

    #[test]
    fn the_pool_has_the_threads_allowed() {
        // a pool of max_threads() threads; the limit itself is not changed here, since
        // other tests of this binary run stages concurrently
        let n = max_threads();
        assert_eq!(install(rayon::current_num_threads), n);
        assert!(install(rayon::current_thread_index).is_some());
    }
}
