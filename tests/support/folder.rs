//! A fresh folder for one test's files, removed with them when the test
//! passes and kept for a look when it fails.

use std::ops::Deref;
use std::path::Path;

pub struct Folder(Option<tempfile::TempDir>);

/// An empty folder under the system's temporary folder, its name starting
/// `weft-{name}-`.
pub fn folder(name: &str) -> Folder {
    let dir = tempfile::Builder::new()
        .prefix(&format!("weft-{name}-"))
        .tempdir()
        .expect("a temporary folder");
    Folder(Some(dir))
}

impl Deref for Folder {
    type Target = Path;

    fn deref(&self) -> &Path {
        self.0.as_ref().map(|dir| dir.path()).expect("the folder")
    }
}

impl Drop for Folder {
    fn drop(&mut self) {
        if std::thread::panicking() {
            if let Some(dir) = self.0.take() {
                eprintln!("the test's files are kept in {}", dir.keep().display());
            }
        }
    }
}

impl AsRef<Path> for Folder {
    fn as_ref(&self) -> &Path {
        self
    }
}
