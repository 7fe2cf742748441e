//! Files taken a block at a time. Written: formatted on all threads and
//! written in order (the writers of OBJ, OFF, PLY and STL spend most of
//! their time turning numbers into text or bytes). Read: through two
//! buffers, one read on all threads while the other is filled, each cut
//! where the format lets its pieces be read apart (OBJ, OFF, text PLY
//! and text STL).

use std::io::{Read, Write};

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

/// A buffer of a file's bytes: up to `cut`, what can be read without the
/// bytes after it; then the start of what goes on in the next buffer.
pub(crate) struct FileBlock {
    bytes: Vec<u8>,
    cut: usize,
    end: usize,
    /// Whether the file ended in this buffer.
    pub(crate) at_end: bool,
}

impl FileBlock {
    pub(crate) fn new(size: usize) -> FileBlock {
        FileBlock {
            bytes: vec![0; size.max(1)],
            cut: 0,
            end: 0,
            at_end: false,
        }
    }

    /// What can be read now.
    pub(crate) fn ready(&self) -> &[u8] {
        &self.bytes[..self.cut]
    }

    /// What the next buffer goes on with.
    pub(crate) fn carried(&self) -> &[u8] {
        &self.bytes[self.cut..self.end]
    }

    /// Fills the buffer from `source` after `carried` (what the last buffer
    /// carried), and cuts it where `cut` says (all of it at the end of the
    /// file), growing it while `cut` finds no place.
    pub(crate) fn fill(
        &mut self,
        source: &mut impl Read,
        carried: &[u8],
        cut: impl Fn(&[u8]) -> Option<usize>,
    ) -> std::io::Result<()> {
        if self.bytes.len() <= carried.len() {
            self.bytes.resize(2 * carried.len(), 0);
        }
        self.bytes[..carried.len()].copy_from_slice(carried);
        let mut end = carried.len();
        loop {
            while end < self.bytes.len() {
                match source.read(&mut self.bytes[end..]) {
                    Ok(0) => break,
                    Ok(n) => end += n,
                    Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                    Err(e) => return Err(e),
                }
            }
            self.end = end;
            self.at_end = end < self.bytes.len();
            if self.at_end {
                self.cut = end;
                return Ok(());
            }
            match cut(&self.bytes[..end]) {
                Some(at) => {
                    self.cut = at;
                    return Ok(());
                }
                // Nothing to cut at in the buffer: read on into a larger one.
                None => self.bytes.resize(2 * self.bytes.len(), 0),
            }
        }
    }
}

/// Where the whole lines of `bytes` end: where a format whose pieces are
/// lines cuts a block.
pub(crate) fn after_last_line(bytes: &[u8]) -> Option<usize> {
    memchr::memrchr(b'\n', bytes).map(|last| last + 1)
}

/// Reads `source` through two buffers of `block` bytes, each cut where
/// `cut` says: the first buffer's text goes to `header`, which makes the
/// reader and says where the body starts; then `read` is handed the body
/// of each buffer, and whether the file ends with it, while the next is
/// filled. `Ok(None)` when `header` or `read` gives up (a header longer
/// than a buffer among the reasons).
///
/// # Errors
/// Whatever `source` returns.
pub(crate) fn read_blocks<R: Send>(
    mut source: impl Read + Send,
    block: usize,
    cut: impl Fn(&[u8]) -> Option<usize> + Sync,
    header: impl FnOnce(&[u8]) -> Option<(R, usize)>,
    read: impl Fn(&mut R, &[u8], bool) -> Option<()> + Sync,
) -> std::io::Result<Option<R>> {
    let mut front = FileBlock::new(block);
    front.fill(&mut source, &[], &cut)?;
    let Some((mut reader, mut start)) = header(front.ready()) else {
        return Ok(None);
    };
    let mut back = FileBlock::new(block);
    loop {
        let (fine, filled) = rayon::join(
            || read(&mut reader, &front.ready()[start..], front.at_end),
            || match front.at_end {
                true => Ok(false),
                false => back.fill(&mut source, front.carried(), &cut).map(|()| true),
            },
        );
        if fine.is_none() {
            return Ok(None);
        }
        if !filled? {
            return Ok(Some(reader));
        }
        std::mem::swap(&mut front, &mut back);
        start = 0;
    }
}
