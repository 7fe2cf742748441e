//! Buffers that report rather than abort when memory runs out, and the
//! helpers that fill them in parallel: every large array of the library is
//! reserved through [`try_vec`], and the subdivision's arrays are written
//! slot by slot on rayon's threads.

use rayon::prelude::*;

use crate::error::{Error, Result};

/// Items per rayon task: small enough to balance, large enough to amortise.
pub(crate) const CHUNK: usize = 4096;

/// Buffers from this size up are advised for transparent huge pages.
const HUGE_PAGE_ADVICE_BYTES: usize = 2 << 20;

/// Advises `memory` for huge pages when it is large; says whether it was.
fn advise_when_large<T>(memory: &mut [T]) -> bool {
    let large = std::mem::size_of_val(memory) >= HUGE_PAGE_ADVICE_BYTES;
    if large {
        weft_pages::advise_huge_pages(memory);
    }
    large
}

/// Reserve `capacity` elements or report, rather than abort, that memory ran out.
pub(crate) fn try_vec<T>(capacity: usize, what: &str) -> Result<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(capacity).map_err(|_| {
        Error::OutOfMemory(format!(
            "could not reserve {capacity} elements of {} bytes for {what}",
            std::mem::size_of::<T>()
        ))
    })?;
    // Large results are written once into fresh memory: with 4 KiB pages,
    // faulting it in costs more than the arithmetic that fills it.
    advise_when_large(v.spare_capacity_mut());
    Ok(v)
}

/// `n` zeros from the allocator's zeroed memory, advised for huge pages
/// when large: a large block comes straight from the kernel, already zero
/// and not yet touched, so it is faulted in only as it is written, once,
/// in any order (where `zeroed` writes every value twice).
pub(crate) fn fresh_zeroed<T: bytemuck::Zeroable>(n: usize, what: &str) -> Result<Vec<T>> {
    let mut values = bytemuck::allocation::try_zeroed_vec(n).map_err(|_| {
        Error::OutOfMemory(format!(
            "could not reserve {n} elements of {} bytes for {what}",
            std::mem::size_of::<T>()
        ))
    })?;
    advise_when_large(values.as_mut_slice());
    Ok(values)
}

/// A copy of `values` in memory advised for huge pages when large (a host's
/// buffers handed in: the copy is all page faults and memory traffic).
/// Aborts, as `to_vec` does, when memory runs out.
pub(crate) fn advised_copy<T: Copy + Send + Sync>(values: &[T]) -> Vec<T> {
    let mut copy = Vec::with_capacity(values.len());
    if advise_when_large(&mut copy.spare_capacity_mut()[..values.len()]) {
        // Fresh pages fault in on the thread that first writes them: copy
        // on all threads.
        copy.par_extend(values.par_iter().copied().with_min_len(16 * CHUNK));
    } else {
        copy.extend_from_slice(values);
    }
    copy
}

/// `f(0), …, f(n - 1)` written on all threads into memory advised for huge
/// pages when large. Aborts, as `collect` does, when memory runs out.
pub(crate) fn advised_map<T: Send>(n: usize, f: impl Fn(usize) -> T + Sync + Send) -> Vec<T> {
    let mut values = Vec::with_capacity(n);
    advise_when_large(values.spare_capacity_mut());
    values.par_extend((0..n).into_par_iter().with_min_len(CHUNK).map(f));
    values
}

/// A copy of `values`, reserved fallibly.
pub(crate) fn try_copy<T: Clone>(values: &[T], what: &str) -> Result<Vec<T>> {
    let mut copy = try_vec(values.len(), what)?;
    copy.extend_from_slice(values);
    Ok(copy)
}

/// A vector of `n` zeros, reserved fallibly and filled in parallel (filling
/// is what faults the fresh pages in, and the kernel zeroes each page on the
/// thread that touches it first).
pub(crate) fn zeroed<T: Default + Clone + Send + Sync>(n: usize, what: &str) -> Result<Vec<T>> {
    let mut v = try_vec(n, what)?;
    v.par_extend(rayon::iter::repeat_n(T::default(), n).with_min_len(4 * CHUNK));
    Ok(v)
}

/// The indices of fixed-size groups (a quad's, a triangle's children's) as
/// one list, in place: the buffer is reinterpreted, not copied.
pub(crate) fn flatten<const N: usize>(groups: Vec<[u32; N]>) -> Vec<u32> {
    // `[u32; N]` and `u32` share their alignment and N divides the bytes:
    // the cast cannot fail.
    bytemuck::cast_vec(groups)
}

/// The groups `group(0), …, group(n - 1)` of N indices each as one flat
/// list, written in parallel: into a new buffer, returned, or into the
/// first `n * N` values of `into` (a caller's), and then an empty list is
/// returned. `into` must have room.
pub(crate) fn par_groups<const N: usize>(
    n: usize,
    into: Option<&mut [u32]>,
    what: &str,
    group: impl Fn(usize) -> [u32; N] + Sync + Send,
) -> Result<Vec<u32>> {
    match into {
        None => Ok(flatten(par_map(n, what, group)?)),
        Some(out) => {
            out[..n * N]
                .par_chunks_exact_mut(N)
                .with_min_len(CHUNK.div_ceil(N))
                .enumerate()
                .for_each(|(i, slot)| slot.copy_from_slice(&group(i)));
            Ok(Vec::new())
        }
    }
}

/// `f(0), …, f(n - 1)`, reserved fallibly and written in parallel, each
/// element once.
pub(crate) fn par_map<T: Send>(
    n: usize,
    what: &str,
    f: impl Fn(usize) -> T + Sync + Send,
) -> Result<Vec<T>> {
    let mut values = try_vec(n, what)?;
    values.par_extend((0..n).into_par_iter().with_min_len(CHUNK).map(f));
    Ok(values)
}

/// The offsets of `n` items of `count(i)` values each (one longer than `n`),
/// counted and summed in parallel.
pub(crate) fn par_offsets(
    n: usize,
    what: &str,
    count: impl Fn(usize) -> u32 + Sync + Send,
) -> Result<Vec<u32>> {
    let mut offsets = try_vec(n + 1, what)?;
    offsets.push(0);
    offsets.par_extend((0..n).into_par_iter().with_min_len(CHUNK).map(count));
    // Each block's total, then each block summed from the totals before it.
    let block = (4 * CHUNK).max(n.div_ceil(4 * rayon::current_num_threads().max(1)));
    let totals: Vec<u32> = offsets[1..]
        .par_chunks(block)
        .map(|b| b.iter().sum())
        .collect();
    let mut bases = Vec::with_capacity(totals.len());
    let mut sum = 0u32;
    for total in totals {
        bases.push(sum);
        sum += total;
    }
    offsets[1..]
        .par_chunks_mut(block)
        .zip(bases)
        .for_each(|(b, mut sum)| {
            for x in b {
                sum += *x;
                *x = sum;
            }
        });
    Ok(offsets)
}

/// A vector of `offsets[n]` values, item i's `offsets[i]..offsets[i + 1]`
/// written by `fill(i, part)`, blocks of items in parallel.
pub(crate) fn fill_by_offsets<T: Default + Clone + Send + Sync>(
    offsets: &[u32],
    what: &str,
    fill: impl Fn(usize, &mut [T]) + Sync + Send,
) -> Result<Vec<T>> {
    let mut values = zeroed(offsets.last().map_or(0, |&n| n as usize), what)?;
    split_by_offsets(&mut values, offsets, CHUNK)
        .into_par_iter()
        .with_max_len(1)
        .for_each(|(items, block)| {
            let base = offsets[items.start] as usize;
            for i in items {
                fill(
                    i,
                    &mut block[offsets[i] as usize - base..offsets[i + 1] as usize - base],
                );
            }
        });
    Ok(values)
}

/// For each item i, blocks of `block` items in parallel: `each(i, start,
/// part)` fills item i's part of `values`, `values[offsets[i]..offsets[i +
/// 1]]` counted from `offsets[0]` (`start` is `offsets[i]`), and returns
/// `singles[i]`.
pub(crate) fn fill_groups<T: Send, S: Send>(
    values: &mut [T],
    offsets: &[u32],
    singles: &mut [S],
    block: usize,
    each: impl Fn(usize, usize, &mut [T]) -> S + Sync,
) {
    // One task per block: a block's work follows its groups' sizes, which
    // can run lopsided across the level (Loop's inside edges mostly go to
    // the lower-numbered parent edges), so idle threads must be able to
    // take any block still waiting.
    split_by_offsets(values, offsets, block)
        .into_par_iter()
        .zip(singles.par_chunks_mut(block))
        .with_max_len(1)
        .for_each(|((items, part), singles)| fill_items(part, offsets, items, singles, &each));
}

/// [`fill_groups`] on one thread for the items `items`, whose values
/// `part` starts at `offsets[items.start]` and whose singles are `singles`.
#[inline]
pub(crate) fn fill_items<T, S>(
    part: &mut [T],
    offsets: &[u32],
    items: std::ops::Range<usize>,
    singles: &mut [S],
    each: &impl Fn(usize, usize, &mut [T]) -> S,
) {
    let base = offsets[items.start] as usize;
    for (i, single) in items.zip(singles) {
        let start = offsets[i] as usize;
        let end = offsets[i + 1] as usize;
        *single = each(i, start, &mut part[start - base..end - base]);
    }
}

/// Splits `values` into the parts owned by each block of `block` items,
/// item i owning `values[offsets[i]..offsets[i + 1]]`; each part comes with
/// its items.
pub(crate) fn split_by_offsets<'a, T>(
    mut values: &'a mut [T],
    offsets: &[u32],
    block: usize,
) -> Vec<(std::ops::Range<usize>, &'a mut [T])> {
    let items = offsets.len().saturating_sub(1);
    let mut parts = Vec::with_capacity(items.div_ceil(block));
    for first in (0..items).step_by(block) {
        let last = (first + block).min(items);
        let len = (offsets[last] - offsets[first]) as usize;
        let (part, rest) = std::mem::take(&mut values).split_at_mut(len);
        parts.push((first..last, part));
        values = rest;
    }
    parts
}

/// Turns counts into running totals, in place.
pub(crate) fn prefix_sum(counts: &mut [u32]) {
    for i in 1..counts.len() {
        counts[i] += counts[i - 1];
    }
}
