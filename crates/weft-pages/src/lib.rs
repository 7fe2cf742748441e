//! Transparent huge-page advice and prefetch hints for large buffers.
//!
//! Filling a fresh buffer of hundreds of megabytes faults it in 4 KiB page by
//! page; on Linux with transparent huge pages in `madvise` mode (the common
//! default), advising the buffer first lets the kernel back it with 2 MiB
//! pages instead, which cuts the page faults 512-fold. Subdividing a mesh to
//! a few million faces spends more time in those faults than in arithmetic.
//! A pass whose reads hop across such buffers, at places it learns from
//! other arrays, waits on memory at each one; [`prefetch`] asks for a
//! line a few steps early.
//!
//! The library's only `unsafe` outside its C ABI lives here: one
//! `madvise(MADV_HUGEPAGE)` call, which never reads, writes or frees the
//! memory it is given, so the function is safe to call on any slice; and
//! the prefetch instruction, a hint that changes nothing but the caches.

#![deny(unsafe_op_in_unsafe_fn)]

/// Size of a transparent huge page on x86-64 and most aarch64 kernels.
pub const HUGE_PAGE_BYTES: usize = 2 << 20;

/// Asks the kernel to back the whole 2 MiB pages inside `memory` with huge
/// pages. A hint: it changes no contents, and does nothing for a slice
/// smaller than a huge page, off Linux, or where the kernel refuses.
///
/// Call it on a freshly reserved buffer before filling it, e.g. on
/// [`Vec::spare_capacity_mut`].
pub fn advise_huge_pages<T>(memory: &mut [T]) {
    let start = memory.as_mut_ptr() as usize;
    let bytes = std::mem::size_of_val(memory);
    let Some((aligned, len)) = whole_huge_pages(start, bytes) else {
        return;
    };
    advise(aligned, len);
}

/// The 2 MiB-aligned part of `[start, start + bytes)`, when it is not empty.
fn whole_huge_pages(start: usize, bytes: usize) -> Option<(usize, usize)> {
    let end = start.checked_add(bytes)?;
    let aligned_start = start.checked_next_multiple_of(HUGE_PAGE_BYTES)?;
    let aligned_end = end - end % HUGE_PAGE_BYTES;
    (aligned_end > aligned_start).then(|| (aligned_start, aligned_end - aligned_start))
}

#[cfg(target_os = "linux")]
fn advise(start: usize, len: usize) {
    // SAFETY: the range lies inside a slice the caller holds exclusively;
    // MADV_HUGEPAGE only changes how the kernel backs it, never its contents.
    // A refusal (EINVAL without THP, say) leaves the memory as it was.
    unsafe {
        libc::madvise(start as *mut libc::c_void, len, libc::MADV_HUGEPAGE);
    }
}

#[cfg(not(target_os = "linux"))]
fn advise(_start: usize, _len: usize) {}

/// Asks the processor to bring `value`'s cache line in, ahead of a read
/// it cannot foresee (an index read from another array). A hint: it reads
/// nothing into the program and never faults.
#[inline(always)]
pub fn prefetch<T>(value: &T) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: prefetching has no effect but on the caches, and `value` is
    // a live reference besides.
    unsafe {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        _mm_prefetch::<_MM_HINT_T0>((value as *const T).cast::<i8>());
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = value;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_whole_huge_pages_are_advised() {
        let page = HUGE_PAGE_BYTES;
        assert_eq!(whole_huge_pages(page + 1, page), None);
        assert_eq!(whole_huge_pages(page, page), Some((page, page)));
        assert_eq!(
            whole_huge_pages(page - 8, 2 * page + 16),
            Some((page, 2 * page))
        );
        assert_eq!(whole_huge_pages(usize::MAX - 4, 8), None);
    }

    #[test]
    fn advice_keeps_the_contents() {
        let mut buffer: Vec<u64> = (0..(3 * HUGE_PAGE_BYTES / 8) as u64).collect();
        advise_huge_pages(&mut buffer);
        assert!(buffer.iter().enumerate().all(|(i, &x)| x == i as u64));
        let mut spare: Vec<f64> = Vec::with_capacity(HUGE_PAGE_BYTES);
        advise_huge_pages(spare.spare_capacity_mut());
        spare.extend((0..HUGE_PAGE_BYTES).map(|i| i as f64));
        assert_eq!(spare[HUGE_PAGE_BYTES - 1], (HUGE_PAGE_BYTES - 1) as f64);
    }
}
