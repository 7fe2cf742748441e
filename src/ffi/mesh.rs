//! The mesh handle: construction from borrowed buffers, accessors, copies,
//! topology info, version and errors.

use std::ffi::c_char;

use crate::ffi::boundary::{
    check_room, guard, input_slice, last_error_ptr, make_mesh, out_param, output_slice, required,
    Failure, WeftStatus,
};
use crate::mesh::topology::MeshInfo;
use crate::mesh::{check_element_counts, Mesh, MeshOptions};

/// Major version of the library this header belongs to.
pub const WEFT_VERSION_MAJOR: u32 = 0;
/// Minor version of the library this header belongs to.
pub const WEFT_VERSION_MINOR: u32 = 1;
/// Patch version of the library this header belongs to.
pub const WEFT_VERSION_PATCH: u32 = 0;

/// An immutable polygon mesh owned by Weft. Create it with `weft_mesh_new`
/// or receive it from an operation; free it with `weft_mesh_free`.
pub struct WeftMesh {
    pub(crate) mesh: Mesh,
}

impl WeftMesh {
    /// Moves a mesh to the heap for the caller, who frees it with `weft_mesh_free`.
    pub(crate) fn into_raw(mesh: Mesh) -> *mut WeftMesh {
        Box::into_raw(Box::new(WeftMesh { mesh }))
    }

    /// Writes a new mesh to an out-parameter already checked by `out_param`.
    ///
    /// # Safety
    /// `out` is a valid, writable pointer.
    pub(crate) unsafe fn write(out: *mut *mut WeftMesh, mesh: Mesh) {
        // SAFETY: `out` is valid and writable, as the caller promises.
        unsafe { *out = WeftMesh::into_raw(mesh) };
    }
}

/// Passes on a result whose coordinates are all finite, or fails with
/// WEFT_STATUS_DEGENERATE_INPUT naming the first vertex that is not: the
/// arithmetic of `what` overflowed `f64` on coordinates near `f64::MAX`.
/// A last check at the boundary for operations that do not check their own
/// output, so a host never receives an invalid mesh.
pub(crate) fn finite_result(mesh: Mesh, what: &str) -> Result<Mesh, Failure> {
    match mesh.first_non_finite_vertex() {
        None => Ok(mesh),
        Some(v) => Err(degenerate_result(&mesh.positions()[v], v, what)),
    }
}

/// The failure of a result whose vertex `v` left the f64 range at `p`.
pub(crate) fn degenerate_result(p: &glam::DVec3, v: usize, what: &str) -> Failure {
    Failure::new(
        WeftStatus::DegenerateInput,
        format!(
            "degenerate input: {what} moves vertex {v} to ({}, {}, {}); the coordinates are too large for f64 arithmetic",
            p.x, p.y, p.z
        ),
    )
}

/// Borrows the mesh behind a handle that may be NULL.
///
/// # Safety
/// `mesh` is NULL or a live handle from this library.
pub(crate) unsafe fn mesh_ref<'a>(mesh: *const WeftMesh, name: &str) -> Result<&'a Mesh, Failure> {
    // SAFETY: `mesh` is as this function's `# Safety` section
    // requires, which its callers promise.
    unsafe { Ok(&required(mesh, name)?.mesh) }
}

/// Counts and flags of a mesh's topology, filled by `weft_mesh_info`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct WeftMeshInfo {
    /// Number of vertices.
    pub vertex_count: usize,
    /// Number of unique edges.
    pub edge_count: usize,
    /// Number of faces.
    pub face_count: usize,
    /// Edges with exactly one face.
    pub naked_edge_count: usize,
    /// Edges with three or more faces.
    pub non_manifold_edge_count: usize,
    /// Vertices whose faces do not form one fan, or on a non-manifold edge.
    pub non_manifold_vertex_count: usize,
    /// Pieces of faces connected through shared edges.
    pub component_count: usize,
    /// No naked and no non-manifold edges (false for a mesh without faces).
    pub is_closed: bool,
    /// Every component can be given one consistent winding.
    pub is_orientable: bool,
    /// Every manifold edge already runs in opposite directions in its two faces.
    pub is_oriented: bool,
}

/// Returns the library's version as a string such as "0.1.0".
///
/// The string is static: do not free it.
#[no_mangle]
pub extern "C" fn weft_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

/// Returns the UTF-8 sentence that explains the last failure on the calling
/// thread, or an empty string when no call on this thread has failed.
///
/// The pointer stays valid until the next failing Weft call on the same
/// thread; copy the text to keep it. Do not free it.
#[no_mangle]
pub extern "C" fn weft_last_error_message() -> *const c_char {
    last_error_ptr()
}

/// Creates a mesh by copying caller buffers; the buffers may be freed after
/// the call.
///
/// `positions` holds `3 * vertex_count` doubles (x, y, z per vertex); it may
/// be NULL only when `vertex_count` is 0.
/// `face_sizes` holds `face_count` corner counts, each at least 3; it may be
/// NULL only when `face_count` is 0.
/// `face_indices` holds `index_count` vertex indices, the faces one after
/// another; their total must equal the sum of `face_sizes`; it may be NULL
/// only when `index_count` is 0.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INDEX_OUT_OF_RANGE, WEFT_STATUS_FACE_TOO_SMALL,
/// WEFT_STATUS_REPEATED_INDEX, WEFT_STATUS_NON_FINITE_COORDINATE,
/// WEFT_STATUS_COUNT_MISMATCH or WEFT_STATUS_INPUT_TOO_LARGE, with a message
/// that names the face, corner or vertex. A vertex, face or index count past
/// 2^31 - 1 fails with WEFT_STATUS_INPUT_TOO_LARGE before any buffer is read.
/// A face that names a vertex twice is refused; `weft_mesh_new_ex` with
/// WEFT_MESH_ALLOW_REPEATED_VERTICES accepts it.
///
/// # Safety
/// Each non-NULL buffer must hold the number of elements stated.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_new(
    positions: *const f64,
    vertex_count: usize,
    face_sizes: *const u32,
    face_count: usize,
    face_indices: *const u32,
    index_count: usize,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: as `weft_mesh_new_ex`, whose requirements are this function's.
    unsafe {
        weft_mesh_new_ex(
            positions,
            vertex_count,
            face_sizes,
            face_count,
            face_indices,
            index_count,
            0,
            out_mesh,
        )
    }
}

/// `weft_mesh_new_ex` flag: accept faces that name a vertex more than once
/// (`0 1 1 2`, `0 1 2 1 3`). Subdivision treats them as OpenSubdiv does, as
/// non-manifold topology: a degenerate edge `[v, v]`, and each further
/// time a face meets a vertex pair, get an edge of their own, infinitely
/// sharp. Other operations take such faces as they are.
pub const WEFT_MESH_ALLOW_REPEATED_VERTICES: u32 = 1;

/// As `weft_mesh_new`, with `flags` (0, or WEFT_MESH_ALLOW_REPEATED_VERTICES)
/// saying what else to accept. An unknown flag fails with
/// WEFT_STATUS_INVALID_ARGUMENT.
///
/// # Safety
/// As `weft_mesh_new`.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn weft_mesh_new_ex(
    positions: *const f64,
    vertex_count: usize,
    face_sizes: *const u32,
    face_count: usize,
    face_indices: *const u32,
    index_count: usize,
    flags: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `positions`, `face_sizes`, `face_indices` and `out_mesh` are as the `# Safety`
    // section above requires; each is checked for NULL before it is used.
    unsafe {
        make_checked_mesh(
            out_mesh,
            flags,
            (positions, vertex_count),
            (face_sizes, face_count),
            (face_indices, index_count),
            |options, (coordinates, face_sizes, face_indices)| {
                Mesh::from_flat_with(coordinates, face_sizes, face_indices, options)
            },
        )
    }
}

/// As `weft_mesh_new_ex`, but the mesh reads `positions` and `face_indices`
/// where they are instead of copying them: a million vertices and faces
/// cross in the time it takes to check them. The arrays are checked as
/// `weft_mesh_new_ex` checks them, with the same errors. `face_sizes` may be
/// freed after the call (Weft keeps a copy only when the faces differ in
/// size).
///
/// The caller lends the two arrays: they must stay valid, and must not
/// change, until `weft_mesh_free(*out_mesh)`. Weft never writes to them.
/// Every mesh an operation returns, including a copy, has buffers of its
/// own, so only this one mesh holds the caller's arrays. `positions` must
/// be aligned for doubles and `face_indices` for uint32_t (any array of
/// those types is).
///
/// # Safety
/// As `weft_mesh_new`, and `positions` and `face_indices` stay valid and
/// unchanged until the mesh is freed.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn weft_mesh_new_borrowed(
    positions: *const f64,
    vertex_count: usize,
    face_sizes: *const u32,
    face_count: usize,
    face_indices: *const u32,
    index_count: usize,
    flags: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: as `weft_mesh_new_ex`; the lent arrays outlive the mesh, as
    // the caller promises, which is what their `'static` stands for.
    unsafe {
        make_checked_mesh(
            out_mesh,
            flags,
            (positions, vertex_count),
            (face_sizes, face_count),
            (face_indices, index_count),
            |options, (coordinates, face_sizes, face_indices)| {
                // Three doubles are a DVec3 (same alignment, no padding): no copy.
                let positions = bytemuck::cast_slice(coordinates);
                Mesh::borrowing(positions, face_sizes, face_indices, options)
            },
        )
    }
}

/// A mesh's coordinates (x, y, z per vertex), face sizes and face indices,
/// as a caller passed them.
type MeshBuffers<'a> = (&'a [f64], &'a [u32], &'a [u32]);

/// Writes to `out_mesh` the mesh `make` builds from the options of `flags`
/// and the three buffers, each count checked before its buffer is viewed
/// (a slice longer than the caller's buffer is undefined behaviour even if
/// never read).
///
/// # Safety
/// Each non-NULL buffer holds the stated number of elements for `'a`;
/// `out_mesh` is NULL or writable.
unsafe fn make_checked_mesh<'a>(
    out_mesh: *mut *mut WeftMesh,
    flags: u32,
    positions: (*const f64, usize),
    face_sizes: (*const u32, usize),
    face_indices: (*const u32, usize),
    make: impl FnOnce(MeshOptions, MeshBuffers<'a>) -> Result<Mesh, crate::MeshError>,
) -> WeftStatus {
    // SAFETY: the buffers and `out_mesh` are as the caller promises.
    unsafe {
        make_mesh(out_mesh, || {
            let (options, buffers) = mesh_buffers(flags, positions, face_sizes, face_indices)?;
            Ok(make(options, buffers)?)
        })
    }
}

/// The options of `flags` and the three buffers, checked as
/// [`make_checked_mesh`] says.
///
/// # Safety
/// As [`make_checked_mesh`].
unsafe fn mesh_buffers<'a>(
    flags: u32,
    (positions, vertex_count): (*const f64, usize),
    (face_sizes, face_count): (*const u32, usize),
    (face_indices, index_count): (*const u32, usize),
) -> Result<(MeshOptions, MeshBuffers<'a>), Failure> {
    let unknown = flags & !WEFT_MESH_ALLOW_REPEATED_VERTICES;
    if unknown != 0 {
        return Err(Failure::invalid_argument(format!(
            "flags has unknown bits {unknown:#x}; the known flag is WEFT_MESH_ALLOW_REPEATED_VERTICES (1)"
        )));
    }
    let options = MeshOptions {
        allow_repeated_vertices: flags & WEFT_MESH_ALLOW_REPEATED_VERTICES != 0,
    };
    check_element_counts(vertex_count, face_count, index_count)?;
    let coordinate_count = vertex_count.checked_mul(3).ok_or_else(|| {
        Failure::new(
            WeftStatus::InputTooLarge,
            format!("vertex_count {vertex_count} is larger than memory can hold"),
        )
    })?;
    // SAFETY: each buffer holds its count of elements for 'a, as the caller promises.
    let (positions, face_sizes, face_indices) = unsafe {
        (
            input_slice(positions, coordinate_count, "positions")?,
            input_slice(face_sizes, face_count, "face_sizes")?,
            input_slice(face_indices, index_count, "face_indices")?,
        )
    };
    Ok((options, (positions, face_sizes, face_indices)))
}

/// Frees a mesh made by Weft. NULL is ignored.
///
/// # Safety
/// `mesh` is NULL or a handle from this library not yet freed; after the
/// call it and every pointer obtained from it are invalid.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_free(mesh: *mut WeftMesh) {
    // SAFETY: `mesh` is NULL or a handle from this library not yet
    // freed, as the `# Safety` section above requires.
    unsafe {
        if !mesh.is_null() {
            // Dropping cannot panic for these plain vectors; still keep unwinding out of the host.
            let _ = std::panic::catch_unwind(|| drop(Box::from_raw(mesh)));
        }
    }
}

/// Returns the number of vertices, or 0 when `mesh` is NULL.
///
/// # Safety
/// `mesh` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_vertex_count(mesh: *const WeftMesh) -> usize {
    // SAFETY: `mesh` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe { mesh.as_ref().map_or(0, |m| m.mesh.vertex_count()) }
}

/// Returns whether the mesh reads arrays a caller lent it
/// (`weft_mesh_new_borrowed`); false when `mesh` is NULL, and for every
/// mesh an operation returns.
///
/// # Safety
/// `mesh` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_is_borrowed(mesh: *const WeftMesh) -> bool {
    // SAFETY: `mesh` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe { mesh.as_ref().is_some_and(|m| m.mesh.is_borrowed()) }
}

/// Returns the number of faces, or 0 when `mesh` is NULL.
///
/// # Safety
/// `mesh` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_face_count(mesh: *const WeftMesh) -> usize {
    // SAFETY: `mesh` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe { mesh.as_ref().map_or(0, |m| m.mesh.face_count()) }
}

/// Returns the number of face corners (the sum of the face sizes), or 0 when
/// `mesh` is NULL.
///
/// # Safety
/// `mesh` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_index_count(mesh: *const WeftMesh) -> usize {
    // SAFETY: `mesh` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe { mesh.as_ref().map_or(0, |m| m.mesh.index_count()) }
}

/// Returns the positions, `3 * vertex_count` doubles, or NULL when `mesh` is
/// NULL or has no vertices.
///
/// The pointer is owned by the mesh and valid until it is freed.
///
/// # Safety
/// `mesh` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_positions(mesh: *const WeftMesh) -> *const f64 {
    // SAFETY: `mesh` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe {
        match mesh.as_ref() {
            Some(m) if m.mesh.vertex_count() > 0 => m.mesh.positions().as_ptr().cast(),
            _ => std::ptr::null(),
        }
    }
}

/// Returns the face sizes, `face_count` values, or NULL when `mesh` is NULL
/// or has no faces.
///
/// The pointer is owned by the mesh and valid until it is freed.
///
/// # Safety
/// `mesh` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_face_sizes(mesh: *const WeftMesh) -> *const u32 {
    // SAFETY: `mesh` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe {
        match mesh.as_ref() {
            Some(m) if m.mesh.face_count() > 0 => m.mesh.face_sizes().as_ptr(),
            _ => std::ptr::null(),
        }
    }
}

/// Returns the face indices, `index_count` values, or NULL when `mesh` is
/// NULL or has no faces.
///
/// The pointer is owned by the mesh and valid until it is freed.
///
/// # Safety
/// `mesh` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_face_indices(mesh: *const WeftMesh) -> *const u32 {
    // SAFETY: `mesh` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe {
        match mesh.as_ref() {
            Some(m) if m.mesh.index_count() > 0 => m.mesh.face_indices().as_ptr(),
            _ => std::ptr::null(),
        }
    }
}

/// Copies the positions into a caller buffer.
///
/// `mesh` must not be NULL.
/// `out_positions` must have room for `3 * vertex_count` doubles;
/// `capacity` is its length in doubles. When it is too small the call fails
/// with WEFT_STATUS_BUFFER_TOO_SMALL and writes nothing.
///
/// # Safety
/// `out_positions` points to `capacity` writable doubles (or is NULL with 0).
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_copy_positions(
    mesh: *const WeftMesh,
    out_positions: *mut f64,
    capacity: usize,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_positions` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let mesh = mesh_ref(mesh, "mesh")?;
            let needed = mesh.vertex_count() * 3;
            check_room("out_positions", capacity, needed)?;
            let out = output_slice(out_positions, capacity, "out_positions")?;
            for (chunk, p) in out.chunks_exact_mut(3).zip(mesh.positions()) {
                chunk.copy_from_slice(&p.to_array());
            }
            Ok(())
        })
    }
}

/// Copies the faces into caller buffers.
///
/// `mesh` must not be NULL.
/// `out_face_sizes` must have room for `face_count` values (`sizes_capacity`).
/// `out_face_indices` must have room for `index_count` values
/// (`indices_capacity`). When either is too small the call fails with
/// WEFT_STATUS_BUFFER_TOO_SMALL and writes nothing.
///
/// # Safety
/// Each buffer points to as many writable values as its capacity says (or is
/// NULL with 0).
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_copy_faces(
    mesh: *const WeftMesh,
    out_face_sizes: *mut u32,
    sizes_capacity: usize,
    out_face_indices: *mut u32,
    indices_capacity: usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `out_face_sizes` and `out_face_indices` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let mesh = mesh_ref(mesh, "mesh")?;
            check_room("out_face_sizes", sizes_capacity, mesh.face_count())?;
            check_room("out_face_indices", indices_capacity, mesh.index_count())?;
            let sizes = output_slice(out_face_sizes, sizes_capacity, "out_face_sizes")?;
            let indices = output_slice(out_face_indices, indices_capacity, "out_face_indices")?;
            sizes[..mesh.face_count()].copy_from_slice(mesh.face_sizes());
            indices[..mesh.index_count()].copy_from_slice(mesh.face_indices());
            Ok(())
        })
    }
}

/// Computes the counts and flags of a mesh's topology.
///
/// `mesh` and `out_info` must not be NULL; `out_info` is written on success only.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_info` is NULL or points to a writable `WeftMeshInfo`.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_info(
    mesh: *const WeftMesh,
    out_info: *mut WeftMeshInfo,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_info` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let out = out_param(out_info, "out_info")?;
            let mesh = mesh_ref(mesh, "mesh")?;
            let info = MeshInfo::of(mesh);
            *out = WeftMeshInfo {
                vertex_count: info.vertex_count,
                edge_count: info.edge_count,
                face_count: info.face_count,
                naked_edge_count: info.naked_edge_count,
                non_manifold_edge_count: info.non_manifold_edge_count,
                non_manifold_vertex_count: info.non_manifold_vertex_count,
                component_count: info.component_count,
                is_closed: info.is_closed,
                is_orientable: info.is_orientable,
                is_oriented: info.is_oriented,
            };
            Ok(())
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn version_constants_match_the_package() {
        assert_eq!(
            WEFT_VERSION_MAJOR.to_string(),
            env!("CARGO_PKG_VERSION_MAJOR")
        );
        assert_eq!(
            WEFT_VERSION_MINOR.to_string(),
            env!("CARGO_PKG_VERSION_MINOR")
        );
        assert_eq!(
            WEFT_VERSION_PATCH.to_string(),
            env!("CARGO_PKG_VERSION_PATCH")
        );
    }
}
