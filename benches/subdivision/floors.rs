//! The memory floor of an output: the time one thread takes only to write
//! its bytes (positions and face indices), into fresh memory as the kernel
//! hands it out (4 KiB pages faulted in one by one), into fresh memory
//! advised for transparent huge pages, and into memory already in use.
//! No subdivision can write its output faster than the floor that applies.

use std::hint::black_box;

/// Writes `bytes` into a fresh allocation. Large allocations come straight
/// from the kernel (glibc maps them on demand and unmaps them when freed),
/// so every page is faulted in during the write.
pub fn fresh(bytes: usize, huge_pages: bool) {
    let mut buffer: Vec<u8> = Vec::with_capacity(bytes);
    if huge_pages {
        weft_pages::advise_huge_pages(buffer.spare_capacity_mut());
    }
    buffer.resize(bytes, 1);
    black_box(&buffer);
}

/// A buffer of `bytes` already written once: memory in use, whose pages
/// are faulted in.
pub fn written(bytes: usize) -> Vec<u8> {
    vec![1u8; bytes]
}

/// Writes `buffer` over, every byte, as a re-evaluation into a buffer the
/// caller keeps writes its output.
pub fn warm(buffer: &mut [u8]) {
    buffer.fill(black_box(1));
    black_box(buffer);
}
