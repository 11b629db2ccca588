//! Read-ahead hints for the sweeps that visit cells in an order of their own (values,
//! levels) all over a grid: each step names the entry a few steps later, so that its cache
//! line loads while the current step works.

/// Asks the processor to bring the cache line of `data[i]` in (nothing if `i` is out of
/// bounds): the load does not wait for it, unlike reading the entry.
#[inline(always)]
pub(crate) fn prefetch<T>(data: &[T], i: usize) {
    #[cfg(target_arch = "x86_64")]
    if i < data.len() {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        // SAFETY: a prefetch is a hint that never faults nor reads into the program's
        // state; the address is inside `data`, and SSE is part of x86_64.
        unsafe { _mm_prefetch::<_MM_HINT_T0>(data.as_ptr().add(i) as *const i8) };
    }
    #[cfg(not(target_arch = "x86_64"))]
    std::hint::black_box(data.get(i).map(|x| x as *const T));
}
