//! Mesh files: reading and writing OBJ, PLY, STL and OFF, the format chosen
//! by the path's extension, as the `weft` command does. The readers and
//! writers are those of `crate::io`; this file converts and checks only.

use std::ffi::{c_char, CStr};
use std::path::Path;

use crate::ffi::boundary::{guard, out_param, required, Failure, WeftStatus};
use crate::ffi::mesh::WeftMesh;
use crate::io::{self, IoError};

/// The path behind a C string, which must be UTF-8.
///
/// # Safety
/// `path` is NULL or a NUL-terminated string readable for `'a`.
unsafe fn utf8_path<'a>(path: *const c_char) -> Result<&'a Path, Failure> {
    if path.is_null() {
        return Err(Failure::new(WeftStatus::NullPointer, "path is NULL"));
    }
    // SAFETY: `path` is not NULL and the caller promises a NUL-terminated string.
    let text = unsafe { CStr::from_ptr(path) };
    text.to_str().map(Path::new).map_err(|e| {
        Failure::invalid_argument(format!(
            "path is not UTF-8 (byte {} of \"{}\")",
            e.valid_up_to(),
            text.to_string_lossy()
        ))
    })
}

/// A file error as a status: a file whose faces do not make a valid mesh
/// keeps the status of that mesh error; anything else (a missing or
/// unwritable file, an unknown extension, malformed content) is
/// WEFT_STATUS_INVALID_ARGUMENT. The message names the file and, for bad
/// content, the line or byte offset.
fn file_failure(error: IoError) -> Failure {
    let message = error.to_string();
    match error {
        IoError::InvalidMesh { source, .. } => Failure::new(Failure::from(source).status, message),
        _ => Failure::invalid_argument(message),
    }
}

/// Reads a mesh file, choosing the format by the extension of `path`
/// (`.obj`, `.ply`, `.stl` or `.off`, any case), as `weft` does. STL
/// corners come unwelded, one vertex per triangle corner (`weft_weld` with
/// tolerance 0 joins them); vertex colours, UVs and creases are not read.
///
/// `path` is a NUL-terminated UTF-8 path; it must not be NULL.
/// `out_mesh` receives the mesh on success (free it with `weft_mesh_free`)
/// and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_NULL_POINTER; WEFT_STATUS_INVALID_ARGUMENT for a
/// path that is not UTF-8, an unknown extension, a file that cannot be
/// read, or content that does not follow its format (the message names the
/// file and the line, or the byte offset of a binary file); and with the
/// status of `weft_mesh_new` (WEFT_STATUS_INDEX_OUT_OF_RANGE, …) when the
/// file's faces do not make a valid mesh, the message naming the file, its
/// line or byte offset and the face.
///
/// # Safety
/// `path` is NULL or a NUL-terminated string; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_read_mesh_file(
    path: *const c_char,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    guard(|| {
        let out = out_param(out_mesh, "out_mesh")?;
        // SAFETY: the caller promises `path` is NULL or NUL-terminated.
        let path = unsafe { utf8_path(path) }?;
        let mesh = io::read_mesh(path).map_err(file_failure)?;
        // SAFETY: `out` was checked by `out_param` and the caller promises it is writable.
        unsafe { WeftMesh::write(out, mesh) };
        Ok(())
    })
}

/// Writes a mesh file, choosing the format by the extension of `path`
/// (`.obj`, `.ply`, `.stl` or `.off`, any case), as `weft` does: PLY as
/// binary little endian, STL as binary with polygons written as triangle
/// fans. The file is written beside its destination under a temporary name
/// and renamed into place, so a failed write leaves no partial file and an
/// existing file as it was.
///
/// `mesh` must not be NULL. `path` is a NUL-terminated UTF-8 path; it must
/// not be NULL; its folder must exist.
///
/// Fails with WEFT_STATUS_NULL_POINTER, or WEFT_STATUS_INVALID_ARGUMENT for
/// a path that is not UTF-8, an unknown extension, a missing folder or a
/// file the system refuses to write (the message names the file).
///
/// # Safety
/// `mesh` is NULL or a live handle; `path` is NULL or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn weft_write_mesh_file(
    mesh: *const WeftMesh,
    path: *const c_char,
) -> WeftStatus {
    guard(|| {
        // SAFETY: the caller promises `mesh` is NULL or a live handle.
        let mesh = &unsafe { required(mesh, "mesh") }?.mesh;
        // SAFETY: the caller promises `path` is NULL or NUL-terminated.
        let path = unsafe { utf8_path(path) }?;
        io::write_mesh(path, mesh).map_err(file_failure)
    })
}
