//! Creases found on a mesh, as Rhino's ToSubD finds them: unwelded seams
//! and sharp folds, for `weft_subdivide_ex`'s crease arrays.

use crate::ffi::boundary::{check_room, guard, out_param, output_slice, Failure, WeftStatus};
use crate::ffi::mesh::{mesh_ref, WeftMesh};
use crate::subdivide;

/// Prepares a mesh whose creases are unwelded seams or sharp folds for
/// creased subdivision, as Rhino's ToSubD does: welds vertices at exactly the
/// same position, and lists as creases every edge that was naked before
/// welding and has two faces after, and every edge whose faces' normals
/// differ by more than `angle_degrees` (180 or more: no fold test). Pass the
/// pairs as `crease_vertex_pairs` with `WEFT_SHARPNESS_INFINITE` sharpness.
/// `weft_crease_edges_from_mesh_ex` also gives which welded vertex each
/// input vertex became.
///
/// `mesh` must not be NULL. `angle_degrees` must be 0 or more.
/// `out_welded` receives the welded mesh (free it with `weft_mesh_free`); it
/// must not be NULL. `out_pairs` has room for `capacity` indices and receives
/// two per crease (indices of the welded mesh); `2 * weft_mesh_index_count(mesh)`
/// always suffices; too small a buffer fails with WEFT_STATUS_BUFFER_TOO_SMALL.
/// `out_crease_count` receives the number of creases; it must not be NULL.
/// Nothing is written on failure.
///
/// Fails with WEFT_STATUS_NULL_POINTER, WEFT_STATUS_INVALID_ARGUMENT (a NaN
/// or negative angle), WEFT_STATUS_BUFFER_TOO_SMALL or WEFT_STATUS_OUT_OF_MEMORY.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_pairs` is NULL or holds `capacity`
/// writable indices; the other outputs are NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_crease_edges_from_mesh(
    mesh: *const WeftMesh,
    angle_degrees: f64,
    out_welded: *mut *mut WeftMesh,
    out_pairs: *mut u32,
    capacity: usize,
    out_crease_count: *mut usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `out_welded`, `out_pairs` and `out_crease_count` are as the `# Safety`
    // section above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            crease_edges(
                mesh,
                angle_degrees,
                out_welded,
                (out_pairs, capacity),
                out_crease_count,
                None,
            )
        })
    }
}

/// As `weft_crease_edges_from_mesh`, and gives the vertex map of the weld:
/// for each vertex of `mesh`, the index of the vertex of the welded mesh it
/// became (the first of the vertices at its position). With it a host
/// carries per-vertex data given on the input (colours, weights, its own
/// creases and corners) onto the welded mesh: welded vertex
/// `out_vertex_map[v]` takes vertex `v`'s value.
///
/// `mesh`, `angle_degrees`, `out_welded`, `out_pairs`, `capacity` and
/// `out_crease_count` as `weft_crease_edges_from_mesh`.
/// `out_vertex_map` has room for `vertex_map_capacity` indices and receives
/// one per vertex of `mesh`: it needs `weft_mesh_vertex_count(mesh)`, else
/// the call fails with WEFT_STATUS_BUFFER_TOO_SMALL (checked before any
/// work is done). It may be NULL only when `vertex_map_capacity` is 0.
/// Nothing is written on failure.
///
/// Fails as `weft_crease_edges_from_mesh`.
///
/// # Safety
/// As `weft_crease_edges_from_mesh`; `out_vertex_map` is NULL or holds
/// `vertex_map_capacity` writable indices.
#[no_mangle]
pub unsafe extern "C" fn weft_crease_edges_from_mesh_ex(
    mesh: *const WeftMesh,
    angle_degrees: f64,
    out_welded: *mut *mut WeftMesh,
    out_pairs: *mut u32,
    capacity: usize,
    out_crease_count: *mut usize,
    out_vertex_map: *mut u32,
    vertex_map_capacity: usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `out_welded`, `out_pairs`, `out_crease_count` and `out_vertex_map` are as
    // the `# Safety` section above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            crease_edges(
                mesh,
                angle_degrees,
                out_welded,
                (out_pairs, capacity),
                out_crease_count,
                Some((out_vertex_map, vertex_map_capacity)),
            )
        })
    }
}

/// The body of both crease exports; `vertex_map` is the optional map buffer
/// and its capacity.
///
/// # Safety
/// As `weft_crease_edges_from_mesh_ex`.
unsafe fn crease_edges(
    mesh: *const WeftMesh,
    angle_degrees: f64,
    out_welded: *mut *mut WeftMesh,
    (out_pairs, capacity): (*mut u32, usize),
    out_crease_count: *mut usize,
    vertex_map: Option<(*mut u32, usize)>,
) -> Result<(), Failure> {
    // SAFETY: `mesh`, `out_welded` and `out_crease_count` are as this function's `# Safety` section
    // requires, which its callers promise.
    unsafe {
        let welded_out = out_param(out_welded, "out_welded")?;
        let count_out = out_param(out_crease_count, "out_crease_count")?;
        let mesh = mesh_ref(mesh, "mesh")?;
        if let Some((_, map_capacity)) = vertex_map {
            check_room("out_vertex_map", map_capacity, mesh.vertex_count())?;
        }
        let subdivide::CreasedMesh {
            mesh: welded,
            creases,
            vertex_map: map,
        } = subdivide::creases_from_mesh(mesh, angle_degrees)?;
        check_room("out_pairs", capacity, 2 * creases.len())?;
        // Every length is checked: the buffers are viewed only now.
        let pairs = output_slice(out_pairs, capacity, "out_pairs")?;
        let map_out = match vertex_map {
            Some((pointer, map_capacity)) => {
                Some(output_slice(pointer, map_capacity, "out_vertex_map")?)
            }
            None => None,
        };
        for (slot, (pair, _)) in pairs.chunks_exact_mut(2).zip(&creases) {
            slot.copy_from_slice(pair);
        }
        if let Some(out) = map_out {
            out[..map.len()].copy_from_slice(&map);
        }
        *count_out = creases.len();
        WeftMesh::write(welded_out, welded);
        Ok(())
    }
}
