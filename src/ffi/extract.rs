//! What Weaverbird extracts from a mesh, through the C ABI: the dual, the
//! edges (as vertex pairs or segments), rerouted faces and a mesh from
//! lines. Each export converts, checks and forwards to `extract`.

use glam::DVec3;

use crate::ffi::boundary::{
    check_room, enum_arg, guard, input_slice, make_mesh, mesh_op, out_param, output_slice, Failure,
    WeftStatus,
};
use crate::ffi::mesh::{mesh_ref, WeftMesh};
use crate::mesh::topology::Topology;
use crate::toolbar::extract::{self, DualMode};

/// Dual mode: a vertex at each face's centroid.
pub const WEFT_DUAL_VERTEX_AVERAGE: u32 = 0;
/// Dual mode: as VERTEX_AVERAGE, scaled to the input's bounding box size.
pub const WEFT_DUAL_KEEP_SIZE: u32 = 1;

/// The dual mesh: a vertex per face, a face per interior vertex joining
/// the faces around it (Weaverbird's Dual). Vertices on naked or
/// non-manifold edges get no face.
///
/// `mesh` is the input; it must not be NULL.
/// `dual_mode` is one of the WEFT_DUAL_* values.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for an unknown mode.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_dual(
    mesh: *const WeftMesh,
    dual_mode: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        mesh_op(mesh, out_mesh, |m| {
            let mode = enum_arg(
                dual_mode,
                "dual_mode",
                |v| match v {
                    WEFT_DUAL_VERTEX_AVERAGE => Some(DualMode::VertexAverage),
                    WEFT_DUAL_KEEP_SIZE => Some(DualMode::KeepSize),
                    _ => None,
                },
                "WEFT_DUAL_VERTEX_AVERAGE (0) or WEFT_DUAL_KEEP_SIZE (1)",
            )?;
            Ok(extract::dual(m, mode)?)
        })
    }
}

/// Counts the unique edges of a mesh, to size the buffers of
/// `weft_mesh_copy_edges` and `weft_mesh_copy_edge_segments`.
///
/// `mesh` is the input; it must not be NULL.
/// `out_count` receives the number of edges on success; it must not be NULL.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_count` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_edge_count(
    mesh: *const WeftMesh,
    out_count: *mut usize,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_count` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let out = out_param(out_count, "out_count")?;
            let mesh = mesh_ref(mesh, "mesh")?;
            *out = Topology::new(mesh).edge_count();
            Ok(())
        })
    }
}

/// Copies the unique edges as vertex index pairs `(low, high)`, sorted
/// (Weaverbird's Mesh Edges, as indices).
///
/// `mesh` is the input; it must not be NULL.
/// `out_pairs` receives `2 * edge_count` indices; `out_len` is its room.
/// A buffer that is too small is an error and is not written.
///
/// Fails with WEFT_STATUS_BUFFER_TOO_SMALL naming the room needed.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_pairs` is NULL or has room for
/// `out_len` values.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_copy_edges(
    mesh: *const WeftMesh,
    out_pairs: *mut u32,
    out_len: usize,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_pairs` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let mesh = mesh_ref(mesh, "mesh")?;
            let edges = extract::mesh_edges(mesh);
            check_room("out_pairs", out_len, 2 * edges.len())?;
            let out = output_slice(out_pairs, 2 * edges.len(), "out_pairs")?;
            out.copy_from_slice(edges.as_flattened());
            Ok(())
        })
    }
}

/// Copies the unique edges as line segments, six doubles each (start x, y,
/// z, end x, y, z), in the order of `weft_mesh_copy_edges` (Weaverbird's
/// Mesh Edges).
///
/// `mesh` is the input; it must not be NULL.
/// `out_segments` receives `6 * edge_count` doubles; `out_len` is its room.
/// A buffer that is too small is an error and is not written.
///
/// Fails with WEFT_STATUS_BUFFER_TOO_SMALL naming the room needed.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_segments` is NULL or has room for
/// `out_len` values.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_copy_edge_segments(
    mesh: *const WeftMesh,
    out_segments: *mut f64,
    out_len: usize,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_segments` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let mesh = mesh_ref(mesh, "mesh")?;
            let segments = extract::edge_segments(mesh);
            check_room("out_segments", out_len, 6 * segments.len())?;
            let out = output_slice(out_segments, 6 * segments.len(), "out_segments")?;
            for (chunk, s) in out.chunks_exact_mut(6).zip(&segments) {
                chunk[..3].copy_from_slice(&s[0].to_array());
                chunk[3..].copy_from_slice(&s[1].to_array());
            }
            Ok(())
        })
    }
}

/// Rotates every face's corner list so it starts `shift` corners later
/// (`[a, b, c, d]` by 1 is `[b, c, d, a]`; negative goes back); the
/// winding and vertices are unchanged (Weaverbird's Reroute Faces).
///
/// `mesh` is the input; it must not be NULL.
/// `shift` is any number of corners; it wraps around each face.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_reroute_faces(
    mesh: *const WeftMesh,
    shift: i64,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { mesh_op(mesh, out_mesh, |m| Ok(extract::reroute_faces(m, shift))) }
}

/// Builds the faces a set of line segments encloses (Weaverbird's Mesh From
/// Lines): endpoints within `tolerance` are welded, dangling segments
/// ignored, and the smallest cycles of the segments, seen in their
/// best-fit plane, become faces wound about its normal.
///
/// `segments` holds `segment_count` segments of six doubles each (start x,
/// y, z, end x, y, z); it may be NULL only when `segment_count` is 0.
/// `tolerance` is the welding distance, finite and at least 0.
/// `max_valence` is the largest face size kept, at least 3.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for a non-finite coordinate
/// (naming the segment), a bad tolerance or a `max_valence` below 3.
///
/// # Safety
/// `segments` is NULL or holds `6 * segment_count` doubles; `out_mesh` is
/// NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_from_lines(
    segments: *const f64,
    segment_count: usize,
    tolerance: f64,
    max_valence: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `segments` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        make_mesh(out_mesh, || {
            let count = segment_count.checked_mul(6).ok_or_else(|| {
                Failure::new(
                    WeftStatus::InputTooLarge,
                    format!("segment_count {segment_count} is larger than memory can hold"),
                )
            })?;
            let flat = input_slice(segments, count, "segments")?;
            let segments: Vec<[DVec3; 2]> = flat
                .chunks_exact(6)
                .map(|c| [DVec3::new(c[0], c[1], c[2]), DVec3::new(c[3], c[4], c[5])])
                .collect();
            let mesh = extract::mesh_from_lines(&segments, tolerance, max_valence)?;
            Ok(mesh)
        })
    }
}
