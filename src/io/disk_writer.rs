//! A file writer that hands the file to the disk block by block on a
//! helper thread, past the page cache where the file system allows it
//! (`O_DIRECT` on Linux), while the caller goes on formatting the next
//! blocks.
//!
//! Buffered, every byte of a large file is copied into fresh page-cache
//! memory first (for the 465 MB of ten million welded triangles, the
//! largest single cost of `weft weld`), and the sync before the rename
//! waits for all of it to reach the disk. Written directly, the disk reads
//! the writer's own few blocks, reused from one to the next, and the
//! helper thread sleeps in the kernel while it does. Where direct writes
//! are refused (tmpfs, some network file systems), the helper writes
//! through the page cache and syncs every [`SYNC_EVERY`] bytes, so the
//! final sync waits for the last few megabytes only. Files smaller than a
//! block are written through the page cache in one go, without a thread.

use std::fs::File;
use std::io::{self, Write};
use std::path::Path;
use std::sync::mpsc::{sync_channel, Receiver, SyncSender};
use std::thread::{Scope, ScopedJoinHandle};

/// Bytes a block holds: large enough that the disk streams, small enough
/// that the caller's formatting and the disk overlap from the start.
const BLOCK_BYTES: usize = 8 << 20;

/// Blocks in use at once: one being filled, the others queued or on disk.
const BLOCKS: usize = 3;

/// Alignment of a direct write's memory, length and file offset: the
/// largest logical block size of common disks.
const ALIGN: usize = 4096;

/// Bytes written through the page cache between two syncs, when direct
/// writes are refused.
const SYNC_EVERY: u64 = 32 << 20;

/// Bytes in memory aligned for direct writes.
struct Block {
    memory: Vec<u8>,
    start: usize,
    len: usize,
}

impl Block {
    fn new(capacity: usize) -> Block {
        let memory = vec![0u8; capacity + ALIGN];
        let start = memory.as_ptr().align_offset(ALIGN);
        Block {
            memory,
            start,
            len: 0,
        }
    }

    fn capacity(&self) -> usize {
        self.memory.len() - ALIGN
    }

    fn bytes(&self) -> &[u8] {
        &self.memory[self.start..self.start + self.len]
    }

    /// Appends as much of `bytes` as fits; returns how much did.
    fn append(&mut self, bytes: &[u8]) -> usize {
        let n = bytes.len().min(self.capacity() - self.len);
        let at = self.start + self.len;
        self.memory[at..at + n].copy_from_slice(&bytes[..n]);
        self.len += n;
        n
    }
}

/// A block for the helper, and where in the file it goes.
type Job = (Block, u64);

enum Helper<'scope> {
    NotYet,
    Running {
        jobs: SyncSender<Job>,
        done: Receiver<Block>,
        thread: ScopedJoinHandle<'scope, io::Result<()>>,
    },
    /// No second handle to the file, or no thread: the writer writes each
    /// block itself, through the page cache, and the final sync does it all.
    Unavailable,
}

/// Writes a new file at `path` (created, empty) through its handle `file`.
pub(super) struct DiskWriter<'scope, 'env> {
    scope: &'scope Scope<'scope, 'env>,
    path: &'env Path,
    file: File,
    block: Block,
    /// Blocks made so far (at most [`BLOCKS`]).
    blocks: usize,
    /// Where `block` goes in the file: the bytes handed to the helper.
    offset: u64,
    helper: Helper<'scope>,
    /// Direct writes are tried (false in tests of the fallback).
    try_direct: bool,
}

impl<'scope, 'env> DiskWriter<'scope, 'env> {
    /// A writer to the new, empty file `file` at `path`, whose helper
    /// thread, once it needs one, lives in `scope`.
    pub(super) fn new(scope: &'scope Scope<'scope, 'env>, path: &'env Path, file: File) -> Self {
        Self::with_blocks(scope, path, file, BLOCK_BYTES, true)
    }

    fn with_blocks(
        scope: &'scope Scope<'scope, 'env>,
        path: &'env Path,
        file: File,
        block_bytes: usize,
        try_direct: bool,
    ) -> Self {
        DiskWriter {
            scope,
            path,
            file,
            block: Block::new(block_bytes.next_multiple_of(ALIGN)),
            blocks: 1,
            offset: 0,
            helper: Helper::NotYet,
            try_direct,
        }
    }

    /// Hands the full block to the helper (started at the first) and takes
    /// an empty one, waiting for the disk when all are in use.
    fn hand_off(&mut self) -> io::Result<()> {
        if let Helper::NotYet = self.helper {
            self.helper = self.start_helper().unwrap_or(Helper::Unavailable);
        }
        let Helper::Running { jobs, done, .. } = &self.helper else {
            write_all_at(&self.file, self.block.bytes(), self.offset)?;
            self.offset += self.block.len as u64;
            self.block.len = 0;
            return Ok(());
        };
        let empty = match done.try_recv() {
            Ok(block) => block,
            Err(_) if self.blocks < BLOCKS => {
                self.blocks += 1;
                Block::new(self.block.capacity())
            }
            Err(_) => match done.recv() {
                Ok(block) => block,
                Err(_) => return Err(self.stop_helper()),
            },
        };
        let full = std::mem::replace(&mut self.block, empty);
        let len = full.len as u64;
        if jobs.send((full, self.offset)).is_err() {
            return Err(self.stop_helper());
        }
        self.offset += len;
        self.block.len = 0;
        Ok(())
    }

    fn start_helper(&self) -> io::Result<Helper<'scope>> {
        let direct = match self.try_direct {
            true => open_direct(self.path).ok(),
            false => None,
        };
        let buffered = self.file.try_clone()?;
        let (jobs, received) = sync_channel::<Job>(BLOCKS - 1);
        let (finished, done) = sync_channel::<Block>(BLOCKS);
        let thread = std::thread::Builder::new()
            .name("weft-write".into())
            .spawn_scoped(self.scope, move || {
                write_blocks(direct, buffered, received, finished)
            })?;
        Ok(Helper::Running { jobs, done, thread })
    }

    /// The helper's error, once it has stopped on one.
    fn stop_helper(&mut self) -> io::Error {
        let stopped = std::mem::replace(&mut self.helper, Helper::Unavailable);
        match stopped {
            Helper::Running { thread, .. } => match thread.join() {
                Ok(Err(e)) => e,
                _ => io::Error::other("the file's writing thread stopped"),
            },
            _ => io::Error::other("the file's writing thread stopped"),
        }
    }

    /// Writes what is left, waits for the helper, and returns the file
    /// (not yet synced: the caller syncs it before renaming it into place).
    pub(super) fn finish(mut self) -> io::Result<File> {
        let helper = std::mem::replace(&mut self.helper, Helper::Unavailable);
        if let Helper::Running { jobs, thread, .. } = helper {
            drop(jobs);
            match thread.join() {
                Ok(result) => result?,
                Err(_) => return Err(io::Error::other("the file's writing thread panicked")),
            }
        }
        // The last, partial block goes through the page cache: a direct
        // write's length must be a whole number of disk blocks.
        write_all_at(&self.file, self.block.bytes(), self.offset)?;
        Ok(self.file)
    }
}

impl Write for DiskWriter<'_, '_> {
    fn write(&mut self, bytes: &[u8]) -> io::Result<usize> {
        let mut rest = bytes;
        while !rest.is_empty() {
            let n = self.block.append(rest);
            rest = &rest[n..];
            if self.block.len == self.block.capacity() {
                self.hand_off()?;
            }
        }
        Ok(bytes.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

/// The helper: writes each block where it goes, directly while the file
/// system takes direct writes, and hands the block back.
fn write_blocks(
    mut direct: Option<File>,
    buffered: File,
    jobs: Receiver<Job>,
    done: SyncSender<Block>,
) -> io::Result<()> {
    let mut unsynced = 0;
    for (block, offset) in jobs {
        if let Some(file) = &direct {
            match write_all_at(file, block.bytes(), offset) {
                Ok(()) => {}
                // Refused for this file system: from here on, buffered.
                Err(e) if e.kind() == io::ErrorKind::InvalidInput => direct = None,
                Err(e) => return Err(e),
            }
        }
        if direct.is_none() {
            write_all_at(&buffered, block.bytes(), offset)?;
            unsynced += block.len as u64;
            if unsynced >= SYNC_EVERY {
                buffered.sync_data()?;
                unsynced = 0;
            }
        }
        // The writer may have stopped on an error of its own.
        let _ = done.send(block);
    }
    Ok(())
}

/// A second handle to `path` whose writes skip the page cache.
#[cfg(target_os = "linux")]
fn open_direct(path: &Path) -> io::Result<File> {
    use std::os::unix::fs::OpenOptionsExt;
    std::fs::OpenOptions::new()
        .write(true)
        .custom_flags(libc::O_DIRECT)
        .open(path)
}

#[cfg(not(target_os = "linux"))]
fn open_direct(_path: &Path) -> io::Result<File> {
    Err(io::ErrorKind::Unsupported.into())
}

#[cfg(unix)]
fn write_all_at(file: &File, bytes: &[u8], offset: u64) -> io::Result<()> {
    std::os::unix::fs::FileExt::write_all_at(file, bytes, offset)
}

#[cfg(not(unix))]
fn write_all_at(mut file: &File, bytes: &[u8], offset: u64) -> io::Result<()> {
    use std::io::{Seek, SeekFrom};
    file.seek(SeekFrom::Start(offset))?;
    file.write_all(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Writes `bytes` in pieces of `piece` through a writer of blocks of
    /// `block` bytes, and reads the file back.
    fn round_trip(bytes: &[u8], piece: usize, block: usize, try_direct: bool) -> Vec<u8> {
        let folder = std::env::current_dir().unwrap().join("target");
        std::fs::create_dir_all(&folder).unwrap();
        let path = folder.join(format!(
            "weft-disk-writer-{}-{piece}-{block}-{try_direct}.bin",
            std::process::id()
        ));
        std::thread::scope(|scope| {
            let file = File::create(&path).unwrap();
            let mut writer = DiskWriter::with_blocks(scope, &path, file, block, try_direct);
            for chunk in bytes.chunks(piece) {
                writer.write_all(chunk).unwrap();
            }
            let started = matches!(writer.helper, Helper::Running { .. });
            assert_eq!(started, bytes.len() >= writer.block.capacity());
            writer.finish().unwrap().sync_all().unwrap();
        });
        let read = std::fs::read(&path).unwrap();
        std::fs::remove_file(&path).unwrap();
        read
    }

    #[test]
    fn every_byte_arrives_in_order_across_blocks() {
        let bytes: Vec<u8> = (0..300_000u32)
            .flat_map(|i| (i * 7).to_le_bytes())
            .collect();
        for try_direct in [true, false] {
            // Pieces smaller and larger than a block, blocks of one and
            // several disk blocks, a file of many blocks and a partial last.
            for (piece, block) in [(1000, ALIGN), (5000, 3 * ALIGN), (70_000, 2 * ALIGN)] {
                let read = round_trip(&bytes, piece, block, try_direct);
                assert!(
                    read == bytes,
                    "pieces {piece}, blocks {block}, {try_direct}"
                );
            }
        }
    }

    #[test]
    fn without_a_helper_the_writer_writes_each_block_itself() {
        let bytes: Vec<u8> = (0..50_000u32).flat_map(|i| i.to_le_bytes()).collect();
        let path = std::env::current_dir()
            .unwrap()
            .join("target")
            .join(format!("weft-disk-writer-alone-{}.bin", std::process::id()));
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::thread::scope(|scope| {
            let file = File::create(&path).unwrap();
            let mut writer = DiskWriter::with_blocks(scope, &path, file, ALIGN, true);
            // As when no second handle or thread could be had.
            writer.helper = Helper::Unavailable;
            for chunk in bytes.chunks(3000) {
                writer.write_all(chunk).unwrap();
            }
            assert!(matches!(writer.helper, Helper::Unavailable));
            writer.finish().unwrap().sync_all().unwrap();
        });
        let read = std::fs::read(&path).unwrap();
        std::fs::remove_file(&path).unwrap();
        assert!(read == bytes);
    }

    #[test]
    fn a_file_smaller_than_a_block_starts_no_helper() {
        assert_eq!(round_trip(b"v 0 0 0\n", 3, ALIGN, true), b"v 0 0 0\n");
        assert_eq!(round_trip(b"", 3, ALIGN, true), b"");
    }

    #[test]
    fn a_file_of_whole_blocks_ends_with_no_partial_block() {
        let bytes = vec![7u8; 4 * ALIGN];
        assert!(round_trip(&bytes, 999, ALIGN, true) == bytes);
    }
}
