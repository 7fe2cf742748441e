//! A file writer that has what it wrote so far put on disk while it goes
//! on writing, so that the sync before a file is renamed into place waits
//! for the last few megabytes only, not for the whole file.

use std::fs::File;
use std::io::Write;
use std::sync::mpsc::{sync_channel, SyncSender, TrySendError};
use std::thread::{Scope, ScopedJoinHandle};

/// Bytes written between two requests to put the file on disk.
const FLUSH_EVERY: u64 = 32 << 20;

/// Writes to `file` and, every [`FLUSH_EVERY`] bytes, asks a helper
/// thread (started at the first request) to sync the file's data. A
/// request made while a sync is under way is dropped: that sync, or the
/// next, covers its bytes.
pub(super) struct FlushingWriter<'scope, 'env> {
    scope: &'scope Scope<'scope, 'env>,
    file: File,
    /// Bytes between two requests: [`FLUSH_EVERY`] but in tests.
    every: u64,
    unflushed: u64,
    helper: Helper<'scope>,
}

enum Helper<'scope> {
    NotYet,
    Running(SyncSender<()>, ScopedJoinHandle<'scope, ()>),
    /// No second handle to the file, or no thread: the final sync does it all.
    Unavailable,
}

impl<'scope, 'env> FlushingWriter<'scope, 'env> {
    /// A writer to `file` whose helper thread, if it needs one, lives in
    /// `scope`.
    pub(super) fn new(scope: &'scope Scope<'scope, 'env>, file: File) -> Self {
        Self::flushing_every(scope, file, FLUSH_EVERY)
    }

    fn flushing_every(scope: &'scope Scope<'scope, 'env>, file: File, every: u64) -> Self {
        FlushingWriter {
            scope,
            file,
            every: every.max(1),
            unflushed: 0,
            helper: Helper::NotYet,
        }
    }

    fn start_helper(&self) -> Helper<'scope> {
        let Ok(handle) = self.file.try_clone() else {
            return Helper::Unavailable;
        };
        let (requests, received) = sync_channel::<()>(1);
        let helper = std::thread::Builder::new()
            .name("weft-flush".into())
            .spawn_scoped(self.scope, move || {
                // Errors surface in the final sync, which the caller checks.
                while received.recv().is_ok() {
                    let _ = handle.sync_data();
                }
            });
        match helper {
            Ok(helper) => Helper::Running(requests, helper),
            Err(_) => Helper::Unavailable,
        }
    }

    /// Stops the helper (after the sync under way) and returns the file.
    pub(super) fn into_file(self) -> File {
        if let Helper::Running(requests, helper) = self.helper {
            drop(requests);
            let _ = helper.join();
        }
        self.file
    }
}

impl Write for FlushingWriter<'_, '_> {
    fn write(&mut self, bytes: &[u8]) -> std::io::Result<usize> {
        let written = self.file.write(bytes)?;
        self.unflushed += written as u64;
        if self.unflushed >= self.every {
            self.unflushed = 0;
            if let Helper::NotYet = self.helper {
                self.helper = self.start_helper();
            }
            if let Helper::Running(requests, _) = &self.helper {
                if let Err(TrySendError::Disconnected(())) = requests.try_send(()) {
                    self.helper = Helper::Unavailable;
                }
            }
        }
        Ok(written)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.file.flush()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_byte_arrives_while_the_helper_syncs() {
        let path = std::env::temp_dir().join(format!("weft-flushing-{}.bin", std::process::id()));
        let expected: Vec<u8> = (0..200_000u32)
            .flat_map(|i| (i * 7).to_le_bytes())
            .collect();
        let started = std::thread::scope(|scope| {
            let file = File::create(&path).unwrap();
            let mut writer = FlushingWriter::flushing_every(scope, file, 4096);
            for chunk in expected.chunks(1000) {
                writer.write_all(chunk).unwrap();
            }
            let started = matches!(writer.helper, Helper::Running(..));
            writer.into_file().sync_all().unwrap();
            started
        });
        assert!(started, "a helper thread syncs a file past the interval");
        assert_eq!(std::fs::read(&path).unwrap(), expected);
        std::fs::remove_file(&path).unwrap();
    }

    #[test]
    fn a_small_file_starts_no_helper() {
        let path =
            std::env::temp_dir().join(format!("weft-flushing-small-{}.txt", std::process::id()));
        std::thread::scope(|scope| {
            let mut writer = FlushingWriter::new(scope, File::create(&path).unwrap());
            writer.write_all(b"v 0 0 0\n").unwrap();
            assert!(matches!(writer.helper, Helper::NotYet));
            writer.into_file().sync_all().unwrap();
        });
        assert_eq!(std::fs::read(&path).unwrap(), b"v 0 0 0\n");
        std::fs::remove_file(&path).unwrap();
    }
}
