//! How many threads whole-map stages use, and the two ways they share work.
//!
//! Every parallel stage of the workspace (orbit counts, orientability, the cells and C1/C2
//! checks, the border operator, simplification) asks this module how many threads it may
//! run, so one setting limits them all:
//!
//! * by default, every core the machine offers ([`std::thread::available_parallelism`]);
//! * the environment variable `GMAP_THREADS` (a positive integer), read once;
//! * [`set_max_threads`] from a program, which wins over both.
//!
//! Work is shared in two ways, both on scoped standard-library threads (no pool is kept
//! between calls; a stage starts its threads once and they run for its whole duration):
//! [`map_tasks`] hands out independent tasks from a shared counter, and [`split_ranges`]
//! cuts `0..len` into one contiguous range per thread for scans that merge their results
//! afterwards. Small inputs stay on the calling thread: starting threads costs more than
//! it saves below [`PARALLEL_FROM`] items.
//!
//! ```
//! use gmap_core::parallel;
//! let squares = parallel::map_tasks(5, 1 << 20, |k| k * k);
//! assert_eq!(squares, vec![0, 1, 4, 9, 16]);
//! assert_eq!(parallel::split_ranges(10, 3), vec![0..4, 4..7, 7..10]);
//! ```

use std::ops::Range;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::OnceLock;

/// Items (darts, entries) from which a stage is worth more than one thread.
pub const PARALLEL_FROM: usize = 1 << 16;

/// The limit set by [`set_max_threads`]; 0 when none was set.
static LIMIT: AtomicUsize = AtomicUsize::new(0);

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

/// `f(0), …, f(tasks - 1)` in order, computed on [`threads_for`]`(items, tasks)` threads
/// taking tasks from a shared counter (so uneven tasks balance). `items` is the size of the
/// whole input, deciding whether threads pay at all.
pub fn map_tasks<T, F>(tasks: usize, items: usize, f: F) -> Vec<T>
where
    T: Send,
    F: Fn(usize) -> T + Sync,
{
    let threads = threads_for(items, tasks);
    if threads == 1 {
        return (0..tasks).map(f).collect();
    }
    let next = AtomicUsize::new(0);
    let mut parts: Vec<Vec<(usize, T)>> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..threads)
            .map(|_| {
                s.spawn(|| {
                    let mut mine = Vec::new();
                    loop {
                        let k = next.fetch_add(1, Ordering::Relaxed);
                        if k >= tasks {
                            break mine;
                        }
                        mine.push((k, f(k)));
                    }
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p))).collect()
    });
    let mut out: Vec<Option<T>> = (0..tasks).map(|_| None).collect();
    for (k, v) in parts.iter_mut().flat_map(std::mem::take) {
        out[k] = Some(v);
    }
    out.into_iter().map(|v| v.expect("every task ran")).collect()
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

/// `f` applied to each of `parts`, one thread per part (the first on the calling thread),
/// results in order. For work already cut to the thread count, e.g. the disjoint mutable
/// ranges of [`split_ranges`] over one array.
pub fn map_parts<T, R, F>(parts: Vec<T>, f: F) -> Vec<R>
where
    T: Send,
    R: Send,
    F: Fn(T) -> R + Sync,
{
    if parts.len() <= 1 {
        return parts.into_iter().map(f).collect();
    }
    let f = &f;
    std::thread::scope(|s| {
        let mut it = parts.into_iter();
        let first = it.next().expect("at least two parts");
        let handles: Vec<_> = it.map(|p| s.spawn(move || f(p))).collect();
        let mut out = vec![f(first)];
        out.extend(handles.into_iter().map(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p))));
        out
    })
}

/// Runs `a` and `b`, on two threads when `parallel` holds, and returns both results.
pub fn join<A, B, RA, RB>(parallel: bool, a: A, b: B) -> (RA, RB)
where
    A: FnOnce() -> RA + Send,
    B: FnOnce() -> RB + Send,
    RA: Send,
    RB: Send,
{
    if !parallel || max_threads() < 2 {
        return (a(), b());
    }
    std::thread::scope(|s| {
        let h = s.spawn(b);
        let ra = a();
        (ra, h.join().unwrap_or_else(|p| std::panic::resume_unwind(p)))
    })
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
        let (a, b) = join(true, || 1, || 2);
        assert_eq!((a, b), (1, 2));
    }
}
