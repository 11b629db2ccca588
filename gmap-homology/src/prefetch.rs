//! Read-ahead hints for the sweeps that visit cells in an order of their own (values,
//! levels) all over a grid: each step names the entry a few steps later, so that its cache
//! line loads while the current step works; and huge pages for the arrays they read that
//! way ([`filled`]), so that those reads do not also miss the TLB.

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

/// `n` copies of `value`, the kernel asked (Linux, `MADV_HUGEPAGE`) to back the vector
/// with 2 MB pages before it is first written: a sweep in value order reads such arrays
/// all over, and with 4 KB pages nearly every read also misses the TLB. Small vectors and
/// other systems get plain pages.
pub(crate) fn filled<T: Clone>(n: usize, value: T) -> Vec<T> {
    let mut v: Vec<T> = Vec::with_capacity(n);
    #[cfg(target_os = "linux")]
    {
        const PAGE: usize = 4096;
        let bytes = n.saturating_mul(std::mem::size_of::<T>());
        if bytes >= 4 << 20 {
            let start = v.as_ptr() as usize;
            let (lo, hi) = (start.next_multiple_of(PAGE), (start + bytes) / PAGE * PAGE);
            if lo < hi {
                // SAFETY: madvise only advises the kernel on how to back the pages of
                // [lo, hi), a page-aligned range inside the allocation just made, not yet
                // written; it changes no memory the program can see, and a failure (an
                // old kernel, huge pages disabled) is ignored.
                unsafe { libc::madvise(lo as *mut libc::c_void, hi - lo, libc::MADV_HUGEPAGE) };
            }
        }
    }
    v.resize(n, value);
    v
}
