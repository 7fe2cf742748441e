//! Subdivision and triangulation exports: Catmull-Clark, Loop, the parent
//! face of every refined face, and triangulation for chaining into Loop.

use crate::ffi::boundary::{
    check_room, copy_out, counted_mesh_op, enum_arg, guard, mesh_op, out_param, output_slice,
    Failure, WeftStatus,
};
use glam::DVec3;

use crate::ffi::mesh::{mesh_ref, WeftMesh};
use crate::mesh::triangulate::{as_triangles, triangulate};
use crate::mesh::Mesh;
use crate::subdivide::{self, NakedEdges, Scheme};

/// Naked edges stay where they are: boundary vertices do not move, new boundary vertices are edge midpoints.
pub const WEFT_NAKED_EDGES_FIXED: u32 = 0;
/// Naked edges tend to a cubic B-spline; every boundary vertex moves (OpenSubdiv VTX_BOUNDARY_EDGE_ONLY).
pub const WEFT_NAKED_EDGES_SMOOTH: u32 = 1;
/// As smooth, but a boundary vertex with a single face stays (OpenSubdiv VTX_BOUNDARY_EDGE_AND_CORNER).
pub const WEFT_NAKED_EDGES_CORNER_FIXED: u32 = 2;
/// No boundary surface: the faces at every vertex on a naked edge are left out as holes, the rest refined as smooth (OpenSubdiv VTX_BOUNDARY_NONE; beyond Weaverbird's three modes; subdivision only).
pub const WEFT_NAKED_EDGES_NONE: u32 = 3;
/// Catmull-Clark: any polygons in, quads out.
pub const WEFT_SCHEME_CATMULL_CLARK: u32 = 0;
/// Loop: triangles in, triangles out.
pub const WEFT_SCHEME_LOOP: u32 = 1;

pub(crate) fn naked_edges_arg(value: u32) -> Result<NakedEdges, Failure> {
    enum_arg(
        value,
        "naked_edges",
        |v| match v {
            WEFT_NAKED_EDGES_FIXED => Some(NakedEdges::Fixed),
            WEFT_NAKED_EDGES_SMOOTH => Some(NakedEdges::Smooth),
            WEFT_NAKED_EDGES_CORNER_FIXED => Some(NakedEdges::CornerFixed),
            WEFT_NAKED_EDGES_NONE => Some(NakedEdges::None),
            _ => None,
        },
        "WEFT_NAKED_EDGES_FIXED (0), WEFT_NAKED_EDGES_SMOOTH (1), WEFT_NAKED_EDGES_CORNER_FIXED (2) or WEFT_NAKED_EDGES_NONE (3)",
    )
}

pub(crate) fn scheme_arg(value: u32) -> Result<Scheme, Failure> {
    enum_arg(
        value,
        "scheme",
        |v| match v {
            WEFT_SCHEME_CATMULL_CLARK => Some(Scheme::CatmullClark),
            WEFT_SCHEME_LOOP => Some(Scheme::Loop),
            _ => None,
        },
        "WEFT_SCHEME_CATMULL_CLARK (0) or WEFT_SCHEME_LOOP (1)",
    )
}

/// Subdivides a mesh with Catmull-Clark, `levels` times, as OpenSubdiv's
/// Catmark scheme does; triangles, quads and n-gons may be mixed, and every
/// face of the result is a quad.
///
/// Output order: the input's vertices keep their indices, then one point per
/// edge (edges sorted by lower, then higher vertex index), then one per face;
/// face f of n corners becomes n consecutive quads, the first at f's first
/// corner. `weft_subdivision_parent_faces` maps the result's faces to the input's.
///
/// `mesh` is the input; it must not be NULL.
/// `levels` is the number of subdivision steps; 0 returns a copy.
/// `naked_edges` is one of the WEFT_NAKED_EDGES_* values.
/// `out_mesh` receives the new mesh on success (free it with `weft_mesh_free`)
/// and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_NULL_POINTER, WEFT_STATUS_INVALID_ARGUMENT (an
/// unknown naked-edge value), WEFT_STATUS_RESULT_TOO_LARGE (the result would
/// pass 2^31 - 1 vertices, faces or indices; checked before allocating) or
/// WEFT_STATUS_OUT_OF_MEMORY. Coordinates near the largest double are
/// subdivided at an exactly scaled size, so the rules never overflow; a
/// refined point beyond the largest double (only when the input spans
/// nearly the whole range) is WEFT_STATUS_DEGENERATE_INPUT naming the vertex.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_catmull_clark(
    mesh: *const WeftMesh,
    levels: u32,
    naked_edges: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { run_scheme(mesh, Scheme::CatmullClark, levels, naked_edges, out_mesh) }
}

/// Subdivides a triangle mesh with Loop, `levels` times, as OpenSubdiv's
/// Loop scheme does; each triangle becomes 4.
///
/// Output order: the input's vertices keep their indices, then one point per
/// edge (edges sorted by lower, then higher vertex index); triangle f becomes
/// triangles 4f to 4f + 3, the first at f's first corner.
///
/// Parameters as `weft_catmull_clark`.
///
/// Fails as `weft_catmull_clark`, and with WEFT_STATUS_NOT_TRIANGLES naming
/// the first face that is not a triangle (`weft_triangulate` first).
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_loop(
    mesh: *const WeftMesh,
    levels: u32,
    naked_edges: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { run_scheme(mesh, Scheme::Loop, levels, naked_edges, out_mesh) }
}

/// Subdivides with `scheme`: the body of `weft_catmull_clark` and `weft_loop`.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
unsafe fn run_scheme(
    mesh: *const WeftMesh,
    scheme: Scheme,
    levels: u32,
    naked_edges: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as this function's `# Safety` section
    // requires, which its callers promise.
    unsafe {
        mesh_op(mesh, out_mesh, |mesh| {
            let naked_edges = naked_edges_arg(naked_edges)?;
            // No pass over the result: subdivision refuses its own output
            // beyond the f64 range (`subdivide/scale.rs`).
            let result = subdivide::subdivide(mesh, scheme, levels, naked_edges)?;
            debug_assert!(result.first_non_finite_vertex().is_none());
            Ok(result)
        })
    }
}

/// Subdivides into the caller's buffers: the result of `weft_catmull_clark`
/// or `weft_loop` (by `scheme`, a WEFT_SCHEME_* value), bit for bit, written
/// into memory the caller keeps instead of a new mesh. A host that
/// subdivides again and again allocates once, from the counts of
/// `weft_subdivision_counts` (`weft_subdivision_counts_ex` for
/// WEFT_NAKED_EDGES_NONE, whose holes leave faces out), so no fresh memory
/// is faulted in for the output on each call, and the last level's points
/// are written where they belong, each once.
///
/// `mesh` is the input; it must not be NULL. `levels` and `naked_edges` as
/// for `weft_catmull_clark`.
/// `out_positions` receives x, y, z per vertex; `position_capacity` counts
/// its doubles (3 per vertex).
/// `out_face_indices` receives the faces' vertex indices, face after face;
/// `index_capacity` counts them. From level 1 on every face is a quad
/// (Catmull-Clark) or a triangle (Loop); at level 0 the faces are the
/// input's (`weft_mesh_face_sizes`).
///
/// Fails as `weft_catmull_clark` and `weft_loop`, and with
/// WEFT_STATUS_BUFFER_TOO_SMALL naming the buffer when one is shorter than
/// the result: found before anything is written. After any other failure
/// the buffers' contents are unspecified.
///
/// # Safety
/// `mesh` is NULL or a live handle; each buffer is NULL or holds as many
/// writable values as its capacity says, and the two do not overlap.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn weft_subdivide_into(
    mesh: *const WeftMesh,
    scheme: u32,
    levels: u32,
    naked_edges: u32,
    out_positions: *mut f64,
    position_capacity: usize,
    out_face_indices: *mut u32,
    index_capacity: usize,
) -> WeftStatus {
    // SAFETY: `mesh` and the buffers are as the `# Safety` section above
    // requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let mesh = mesh_ref(mesh, "mesh")?;
            let scheme = scheme_arg(scheme)?;
            let naked_edges = naked_edges_arg(naked_edges)?;
            let coordinates = output_slice(out_positions, position_capacity, "out_positions")?;
            let whole_vertices = position_capacity / 3 * 3;
            let positions: &mut [DVec3] =
                bytemuck::cast_slice_mut(&mut coordinates[..whole_vertices]);
            let indices = output_slice(out_face_indices, index_capacity, "out_face_indices")?;
            // As `weft_catmull_clark`: the output is checked where it is made.
            let counts =
                subdivide::subdivide_into(mesh, scheme, levels, naked_edges, positions, indices)?;
            debug_assert!(
                crate::mesh::first_non_finite(&positions[..counts.vertex_count]).is_none()
            );
            Ok(())
        })
    }
}

/// Gives the number of faces `levels` steps of `scheme` make from `cage`,
/// without subdividing: the length `weft_subdivision_parent_faces` needs.
///
/// `cage` must not be NULL. `scheme` is a WEFT_SCHEME_* value.
/// `out_face_count` receives the count on success; it must not be NULL.
///
/// Fails with WEFT_STATUS_NULL_POINTER, WEFT_STATUS_INVALID_ARGUMENT,
/// WEFT_STATUS_NOT_TRIANGLES (Loop) or WEFT_STATUS_RESULT_TOO_LARGE.
///
/// # Safety
/// `cage` is NULL or a live handle; `out_face_count` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_subdivision_face_count(
    cage: *const WeftMesh,
    scheme: u32,
    levels: u32,
    out_face_count: *mut usize,
) -> WeftStatus {
    // SAFETY: `cage` and `out_face_count` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let out = out_param(out_face_count, "out_face_count")?;
            let cage = mesh_ref(cage, "cage")?;
            let scheme = scheme_arg(scheme)?;
            *out = subdivide::refined_face_count(cage, scheme, levels)?;
            Ok(())
        })
    }
}

/// Writes, for every face of the mesh that `levels` steps of `scheme` make
/// from `cage`, the index of the cage face it comes from (the naked-edge
/// mode does not change it, except WEFT_NAKED_EDGES_NONE, whose holes
/// `weft_subdivision_parent_faces_ex` leaves out). Only the cage's face
/// sizes are used.
///
/// `cage` must not be NULL. `scheme` is a WEFT_SCHEME_* value.
/// `out_parents` must have room for `capacity` values; when `capacity` is
/// below the refined face count (`weft_subdivision_face_count`) the call
/// fails with WEFT_STATUS_BUFFER_TOO_SMALL and writes nothing.
///
/// Fails with WEFT_STATUS_NULL_POINTER, WEFT_STATUS_INVALID_ARGUMENT,
/// WEFT_STATUS_NOT_TRIANGLES (Loop), WEFT_STATUS_RESULT_TOO_LARGE or
/// WEFT_STATUS_BUFFER_TOO_SMALL.
///
/// # Safety
/// `cage` is NULL or a live handle; `out_parents` is NULL or holds
/// `capacity` writable values.
#[no_mangle]
pub unsafe extern "C" fn weft_subdivision_parent_faces(
    cage: *const WeftMesh,
    scheme: u32,
    levels: u32,
    out_parents: *mut u32,
    capacity: usize,
) -> WeftStatus {
    // SAFETY: `cage` and `out_parents` are as the `# Safety` section
    // above requires.
    unsafe {
        write_parents(cage, "cage", (out_parents, capacity), |cage| {
            // The room is checked before the parents are made.
            let scheme = scheme_arg(scheme)?;
            let needed = subdivide::refined_face_count(cage, scheme, levels)?;
            check_room("out_parents", capacity, needed)?;
            Ok(subdivide::parent_faces(cage, scheme, levels)?)
        })
    }
}

/// The parent-faces exports' shared steps: checks the mesh (named `name`),
/// then copies the parents `parents` finds into the caller's buffer.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out` is NULL or holds its count of
/// writable values.
pub(crate) unsafe fn write_parents(
    mesh: *const WeftMesh,
    name: &str,
    (out, capacity): (*mut u32, usize),
    parents: impl FnOnce(&Mesh) -> Result<Vec<u32>, Failure>,
) -> WeftStatus {
    // SAFETY: `mesh` and `out` are as this function's `# Safety` section
    // requires, which its callers promise; each is checked for NULL first.
    unsafe {
        guard(|| {
            let parents = parents(mesh_ref(mesh, name)?)?;
            copy_out(out, capacity, "out_parents", &parents)
        })
    }
}

/// Triangulates every face: triangles stay, a quad is split along its
/// shorter diagonal, an n-gon is ear-clipped in its best-fit plane (concave
/// n-gons included). Vertices keep their indices and positions; the
/// triangles of face f are consecutive, in face order (a face of n corners
/// makes n − 2).
///
/// `mesh` must not be NULL.
/// `out_mesh` receives the triangle mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_NULL_POINTER or WEFT_STATUS_OUT_OF_MEMORY.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_triangulate(
    mesh: *const WeftMesh,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        mesh_op(mesh, out_mesh, |mesh| {
            let result = triangulate(mesh)?;
            Ok(result.mesh)
        })
    }
}

/// Triangulates every face as `weft_triangulate` does, and gives the face
/// of the input that each triangle was cut from.
///
/// `mesh` must not be NULL.
/// `out_mesh` receives the triangle mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
/// `out_parent_faces` can be NULL; otherwise it must have room for the
/// output's face count, the sum over the input's faces of (size − 2)
/// values (`weft_mesh_index_count(mesh) - 2 * weft_mesh_face_count(mesh)`),
/// and receives the parent face of every output face on success.
///
/// Fails with WEFT_STATUS_NULL_POINTER or WEFT_STATUS_OUT_OF_MEMORY.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable;
/// `out_parent_faces` is NULL or holds as many writable values as the
/// output has faces.
#[no_mangle]
pub unsafe extern "C" fn weft_triangulate_ex(
    mesh: *const WeftMesh,
    out_mesh: *mut *mut WeftMesh,
    out_parent_faces: *mut u32,
) -> WeftStatus {
    // SAFETY: `mesh`, `out_mesh` and `out_parent_faces` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        mesh_op(mesh, out_mesh, |mesh| {
            let result = triangulate(mesh)?;
            if !out_parent_faces.is_null() {
                let parents = output_slice(
                    out_parent_faces,
                    result.parent_faces.len(),
                    "out_parent_faces",
                )?;
                parents.copy_from_slice(&result.parent_faces);
            }
            Ok(result.mesh)
        })
    }
}

/// Gives the mesh as triangles, for the operations that need them (Loop,
/// `weft_split_triangles`): a copy when every face is a triangle, else the
/// triangulation of `weft_triangulate`.
///
/// `mesh` must not be NULL.
/// `out_mesh` receives the triangle mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
/// `out_split_faces` can be NULL; otherwise it receives, on success, the
/// number of input faces that were not triangles (0 for a copy), so a
/// front-end can say "triangulated N faces".
///
/// Fails with WEFT_STATUS_NULL_POINTER or WEFT_STATUS_OUT_OF_MEMORY.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable;
/// `out_split_faces` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_as_triangles(
    mesh: *const WeftMesh,
    out_mesh: *mut *mut WeftMesh,
    out_split_faces: *mut usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `out_mesh` and `out_split_faces` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        counted_mesh_op(mesh, out_mesh, out_split_faces, |m| {
            let (triangles, split_faces) = as_triangles(m)?;
            Ok((triangles.mesh, split_faces))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_match_the_enumerations() {
        assert_eq!(WEFT_NAKED_EDGES_FIXED, NakedEdges::Fixed as u32);
        assert_eq!(WEFT_NAKED_EDGES_SMOOTH, NakedEdges::Smooth as u32);
        assert_eq!(
            WEFT_NAKED_EDGES_CORNER_FIXED,
            NakedEdges::CornerFixed as u32
        );
        assert_eq!(WEFT_NAKED_EDGES_NONE, NakedEdges::None as u32);
        assert_eq!(WEFT_SCHEME_CATMULL_CLARK, Scheme::CatmullClark as u32);
        assert_eq!(WEFT_SCHEME_LOOP, Scheme::Loop as u32);
    }
}
