//! Files formatted on all threads and written in order: the writers of
//! OBJ, OFF, PLY and STL spend most of their time turning numbers into text
//! or bytes.

use std::io::Write;

use rayon::prelude::*;

/// Writes `count` items (vertices, faces) through `format`, which appends
/// the text of a range of them to a buffer: blocks of items are formatted
/// on all threads, a round at a time, and written in order, so the text is
/// the same as one thread's. Each round is formatted while the one before
/// is handed to `w`, into the other of two sets of buffers.
pub(crate) fn write_in_blocks(
    w: &mut dyn Write,
    count: usize,
    format: impl Fn(std::ops::Range<usize>, &mut Vec<u8>) -> std::io::Result<()> + Sync,
) -> std::io::Result<()> {
    const ITEMS: usize = 1 << 14;
    let new_buffers = || vec![Vec::new(); 4 * rayon::current_num_threads().max(1)];
    let (mut ready, mut next) = (new_buffers(), new_buffers());
    let round = ITEMS * ready.len();
    let format_round = |start: usize, buffers: &mut Vec<Vec<u8>>| {
        let end = (start + round).min(count);
        buffers
            .par_iter_mut()
            .enumerate()
            .try_for_each(|(k, buffer)| {
                buffer.clear();
                let first = start + k * ITEMS;
                if first < end {
                    format(first..(first + ITEMS).min(end), buffer)?;
                }
                Ok::<(), std::io::Error>(())
            })
    };
    if count == 0 {
        return Ok(());
    }
    format_round(0, &mut ready)?;
    for start in (round..count).step_by(round) {
        let mut formatted = Ok(());
        // `w` need not be `Send`: it stays on this thread, the formatting
        // goes to the pool.
        let written = rayon::in_place_scope(|scope| {
            scope.spawn(|_| formatted = format_round(start, &mut next));
            ready.iter().try_for_each(|buffer| w.write_all(buffer))
        });
        written?;
        formatted?;
        std::mem::swap(&mut ready, &mut next);
    }
    ready.iter().try_for_each(|buffer| w.write_all(buffer))
}
