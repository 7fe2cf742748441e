//! Mending exports: join and weld, unused vertices, T-nodes, cull adjacent
//! faces, normals, planarity and the naked boundary (orientation is in
//! `orient`).

use crate::ffi::boundary::{
    check_room, counted_mesh_op, guard, input_slice, make_mesh, mesh_op, out_param, output_slice,
    write_optional, Failure, WeftStatus,
};
use crate::ffi::mesh::{mesh_ref, WeftMesh};
use crate::mend::cull;
use crate::mend::t_nodes;
use crate::mend::weld;
use crate::mesh::analysis;
use crate::mesh::Mesh;

/// An absolute weld tolerance: 0.001 model units, Rhino's default absolute
/// tolerance (a millimetre in a model in metres). It can collapse the faces
/// of small or dense meshes: without a tolerance of the host's own, prefer
/// `weft_weld_relative_tolerance`.
pub const WEFT_DEFAULT_WELD_TOLERANCE: f64 = 0.001;

/// What `weft_weld` changed.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct WeftWeldReport {
    /// Vertices that merged into another: the input's vertex count minus the
    /// number of clusters.
    pub merged_vertex_count: usize,
    /// Faces left with fewer than 3 distinct vertices, and so removed.
    pub removed_face_count: usize,
    /// Merged vertices that no remaining face uses, and so were left out.
    pub unused_vertex_count: usize,
}

/// A vertex lying inside a naked edge of a face it does not belong to.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct WeftTNode {
    /// The vertex that lies on the edge.
    pub vertex: u32,
    /// The edge's first vertex, in the direction the face runs it.
    pub edge_start: u32,
    /// The edge's second vertex.
    pub edge_end: u32,
    /// The face whose edge it is.
    pub face: u32,
    /// Where the vertex lies along the edge: 0 at `edge_start`, 1 at
    /// `edge_end`, always strictly between.
    pub parameter: f64,
}

/// Joins meshes into one: the vertices of each follow those of the meshes
/// before it and its face indices are offset to match; faces keep their order.
///
/// `meshes` holds `count` mesh handles, none of them NULL; it may be NULL
/// only when `count` is 0 (the result is then the empty mesh).
/// `out_mesh` receives the joined mesh (free it with `weft_mesh_free`); it
/// must not be NULL and is written on success only.
///
/// Fails with WEFT_STATUS_RESULT_TOO_LARGE when the joined vertex or index
/// count passes 2^31 - 1, or WEFT_STATUS_NULL_POINTER naming a NULL element.
///
/// # Safety
/// `meshes` points to `count` readable handle pointers (or is NULL with 0),
/// each a live handle or NULL.
#[no_mangle]
pub unsafe extern "C" fn weft_join(
    meshes: *const *const WeftMesh,
    count: usize,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `meshes` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        make_mesh(out_mesh, || {
            let handles = input_slice(meshes, count, "meshes")?;
            let mut parts: Vec<&Mesh> = Vec::with_capacity(handles.len());
            for (i, &handle) in handles.iter().enumerate() {
                parts.push(mesh_ref(handle, &format!("meshes[{i}]"))?);
            }
            Ok(weld::join(&parts)?)
        })
    }
}

/// The tolerance to weld `mesh` with when the host has none of its own: a
/// millionth of the mesh's bounding-box diagonal (0 for an empty mesh or a
/// single point). Unlike the absolute WEFT_DEFAULT_WELD_TOLERANCE, it never
/// collapses the faces of a small part or a dense scan, whatever the units.
/// The command line's `weld` and `t-nodes` use it when no tolerance is given.
///
/// `mesh` must not be NULL.
/// `out_tolerance` receives the tolerance; it must not be NULL and is
/// written on success only.
///
/// Fails with WEFT_STATUS_NULL_POINTER.
///
/// # Safety
/// `mesh` is a live handle; `out_tolerance` is writable.
#[no_mangle]
pub unsafe extern "C" fn weft_weld_relative_tolerance(
    mesh: *const WeftMesh,
    out_tolerance: *mut f64,
) -> WeftStatus {
    guard(|| {
        let out = out_param(out_tolerance, "out_tolerance")?;
        // SAFETY: `mesh` is NULL or a live handle, as the `# Safety` section requires.
        let mesh = unsafe { mesh_ref(mesh, "mesh") }?;
        // SAFETY: `out_param` refused NULL; the caller guarantees it is writable.
        unsafe { out.write(weld::relative_tolerance(mesh)) };
        Ok(())
    })
}

/// Returns how many vertices no face uses, or 0 when `mesh` is NULL.
/// Subdivision keeps such bare vertices in place (OpenSubdiv cages carry
/// them on purpose); `weft_remove_unused_vertices` leaves them out.
///
/// # Safety
/// `mesh` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_unused_vertex_count(mesh: *const WeftMesh) -> usize {
    // SAFETY: the caller passes NULL or a live handle.
    unsafe { mesh.as_ref() }.map_or(0, |m| weld::unused_vertex_count(&m.mesh))
}

/// Leaves out the vertices no face uses; the others keep their order (the
/// face indices are renumbered to match).
///
/// `mesh` must not be NULL.
/// `out_mesh` receives the result (free it with `weft_mesh_free`); it must
/// not be NULL and is written on success only.
/// `out_removed` receives how many vertices were left out; it may be NULL.
///
/// # Safety
/// `mesh` is a live handle; `out_mesh` is writable; `out_removed` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_remove_unused_vertices(
    mesh: *const WeftMesh,
    out_mesh: *mut *mut WeftMesh,
    out_removed: *mut usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `out_mesh` and `out_removed` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        counted_mesh_op(mesh, out_mesh, out_removed, |m| {
            Ok(weld::remove_unused_vertices(m))
        })
    }
}

/// Welds vertices: every two vertices at most `tolerance` apart become one,
/// transitively. The merged vertex keeps the position of its cluster's
/// lowest-index vertex (seams stay where the surface put them, and welding
/// twice changes nothing). Faces drop repeated corners (a quad with two
/// merged corners becomes a triangle); faces left with fewer than 3 vertices
/// are removed; vertices no face uses are left out.
///
/// `mesh` must not be NULL.
/// `tolerance` is a distance in model units, finite and not negative; 0
/// merges exact duplicates only; `weft_weld_relative_tolerance` gives one
/// that suits the mesh's size (WEFT_DEFAULT_WELD_TOLERANCE, an absolute
/// 0.001, suits models of ordinary size in metres or millimetres).
/// `out_mesh` receives the welded mesh (free it with `weft_mesh_free`); it
/// must not be NULL and is written on success only.
/// `out_report` receives what changed; it may be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for a negative, NaN or infinite
/// tolerance.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable; `out_report` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_weld(
    mesh: *const WeftMesh,
    tolerance: f64,
    out_mesh: *mut *mut WeftMesh,
    out_report: *mut WeftWeldReport,
) -> WeftStatus {
    // SAFETY: `mesh`, `out_mesh` and `out_report` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        mesh_op(mesh, out_mesh, |mesh| {
            let (welded, report) = weld::weld(mesh, tolerance)?;
            write_optional(
                out_report,
                WeftWeldReport {
                    merged_vertex_count: report.merged_vertex_count,
                    removed_face_count: report.removed_face_count,
                    unused_vertex_count: report.unused_vertex_count,
                },
            );
            Ok(welded)
        })
    }
}

/// Finds the T-nodes: vertices on the naked boundary that lie within
/// `tolerance` of the inside of another face's naked edge (and further than
/// `tolerance` from its ends). They are sorted by face, then by the edge's
/// place in the face, then by parameter.
///
/// Call it first with `out_nodes` NULL to learn the count, then with a
/// buffer of that many elements.
///
/// `mesh` must not be NULL.
/// `tolerance` is finite and not negative (WEFT_DEFAULT_WELD_TOLERANCE suits
/// most models).
/// `out_nodes` receives the T-nodes; NULL asks for the count only. When it
/// is not NULL and `capacity` is below the count the call fails with
/// WEFT_STATUS_BUFFER_TOO_SMALL and writes nothing.
/// `capacity` is the number of elements `out_nodes` has room for.
/// `out_count` receives the number of T-nodes; it must not be NULL.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_nodes` is NULL or has room for `capacity`
/// elements; `out_count` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_find_t_nodes(
    mesh: *const WeftMesh,
    tolerance: f64,
    out_nodes: *mut WeftTNode,
    capacity: usize,
    out_count: *mut usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `out_nodes` and `out_count` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let count_out = out_param(out_count, "out_count")?;
            let mesh = mesh_ref(mesh, "mesh")?;
            let nodes = t_nodes::find_t_nodes(mesh, tolerance)?;
            if !out_nodes.is_null() {
                check_room("out_nodes", capacity, nodes.len())?;
                let out = output_slice(out_nodes, capacity, "out_nodes")?;
                for (slot, node) in out.iter_mut().zip(&nodes) {
                    *slot = WeftTNode {
                        vertex: node.vertex,
                        edge_start: node.edge[0],
                        edge_end: node.edge[1],
                        face: node.face,
                        parameter: node.parameter,
                    };
                }
            }
            *count_out = nodes.len();
            Ok(())
        })
    }
}

/// Repairs the T-nodes that `weft_find_t_nodes` reports: each vertex is
/// inserted into the edge it lies on (several on one edge in order), so
/// the face becomes an n-gon and both sides share the seam. Positions do
/// not change.
///
/// `mesh` must not be NULL.
/// `tolerance` is finite and not negative.
/// `out_mesh` receives the repaired mesh (free it with `weft_mesh_free`); it
/// must not be NULL and is written on success only.
/// `out_inserted` receives the number of vertices inserted; it may be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for a negative, NaN or infinite
/// tolerance.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable; `out_inserted` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_repair_t_nodes(
    mesh: *const WeftMesh,
    tolerance: f64,
    out_mesh: *mut *mut WeftMesh,
    out_inserted: *mut usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `out_mesh` and `out_inserted` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        counted_mesh_op(mesh, out_mesh, out_inserted, |m| {
            Ok(t_nodes::repair_t_nodes(m, tolerance)?)
        })
    }
}

/// Removes every face that has a twin with the same vertices (in either
/// orientation, from any corner): all copies go. These are the walls inside
/// an aggregation of joined and welded boxes. Vertices are kept as they are.
///
/// `mesh` must not be NULL; weld it first, as faces are compared by index.
/// `out_mesh` receives the culled mesh (free it with `weft_mesh_free`); it
/// must not be NULL and is written on success only.
/// `out_removed` receives the number of faces removed; it may be NULL.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable; `out_removed` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_cull_adjacent(
    mesh: *const WeftMesh,
    out_mesh: *mut *mut WeftMesh,
    out_removed: *mut usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `out_mesh` and `out_removed` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { counted_mesh_op(mesh, out_mesh, out_removed, |m| Ok(cull::cull_adjacent(m))) }
}

/// Copies `vectors`, three doubles each into a caller buffer.
///
/// # Safety
/// As `output_slice`.
unsafe fn write_vectors(
    vectors: &[glam::DVec3],
    out: *mut f64,
    capacity: usize,
    name: &str,
) -> Result<(), Failure> {
    // SAFETY: `out` is as this function's `# Safety` section
    // requires, which its callers promise.
    unsafe {
        check_room(name, capacity, vectors.len() * 3)?;
        let out = output_slice(out, capacity, name)?;
        for (chunk, v) in out.chunks_exact_mut(3).zip(vectors) {
            chunk.copy_from_slice(&v.to_array());
        }
        Ok(())
    }
}

/// Which normals an export copies out: how many there are, so the room is
/// checked before they are computed, and how to compute them.
struct Normals {
    count: fn(&Mesh) -> usize,
    compute: fn(&Mesh) -> Vec<glam::DVec3>,
}

const FACE_NORMALS: Normals = Normals {
    count: Mesh::face_count,
    compute: analysis::face_normals,
};

const VERTEX_NORMALS: Normals = Normals {
    count: Mesh::vertex_count,
    compute: analysis::vertex_normals,
};

/// The body of the normal exports: checks that `out_normals` has room for
/// the normals before computing them, then copies them in.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_normals` has room for `capacity`
/// doubles (or is NULL with 0).
unsafe fn normals_op(
    mesh: *const WeftMesh,
    out_normals: *mut f64,
    capacity: usize,
    normals: Normals,
) -> WeftStatus {
    guard(|| {
        // SAFETY: `mesh` is NULL or a live handle, as the caller promises.
        let mesh = unsafe { mesh_ref(mesh, "mesh") }?;
        check_room("out_normals", capacity, (normals.count)(mesh) * 3)?;
        let vectors = (normals.compute)(mesh);
        // SAFETY: `out_normals` has room for `capacity` doubles, as the caller promises.
        unsafe { write_vectors(&vectors, out_normals, capacity, "out_normals") }
    })
}

/// Computes the unit normal of each face by Newell's method (robust on
/// non-planar polygons); a face of zero area gets (0, 0, 0).
///
/// `mesh` must not be NULL.
/// `out_normals` receives x, y, z per face and must have room for
/// `3 * face_count` doubles; `capacity` is its length in doubles. When it is
/// too small the call fails with WEFT_STATUS_BUFFER_TOO_SMALL and writes nothing.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_normals` has room for `capacity` doubles
/// (or is NULL with 0).
#[no_mangle]
pub unsafe extern "C" fn weft_face_normals(
    mesh: *const WeftMesh,
    out_normals: *mut f64,
    capacity: usize,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_normals` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { normals_op(mesh, out_normals, capacity, FACE_NORMALS) }
}

/// Computes the unit normal of each vertex: the face normals weighted by the
/// face's angle at the vertex (unchanged when faces are split into
/// triangles). A vertex no face uses gets (0, 0, 0).
///
/// `mesh` must not be NULL.
/// `out_normals` receives x, y, z per vertex and must have room for
/// `3 * vertex_count` doubles; `capacity` is its length in doubles. When it
/// is too small the call fails with WEFT_STATUS_BUFFER_TOO_SMALL and writes
/// nothing.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_normals` has room for `capacity` doubles
/// (or is NULL with 0).
#[no_mangle]
pub unsafe extern "C" fn weft_vertex_normals(
    mesh: *const WeftMesh,
    out_normals: *mut f64,
    capacity: usize,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_normals` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { normals_op(mesh, out_normals, capacity, VERTEX_NORMALS) }
}

/// Computes, per face, the largest distance of its corners from its
/// best-fit (least-squares) plane; 0 for triangles. A face is planar within
/// a tolerance when its value is at most the tolerance (the planar-quad
/// mesh check).
///
/// `mesh` must not be NULL.
/// `out_deviations` receives one double per face and must have room for
/// `face_count`; `capacity` is its length. When it is too small the call
/// fails with WEFT_STATUS_BUFFER_TOO_SMALL and writes nothing.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_deviations` has room for `capacity`
/// doubles (or is NULL with 0).
#[no_mangle]
pub unsafe extern "C" fn weft_planarity(
    mesh: *const WeftMesh,
    out_deviations: *mut f64,
    capacity: usize,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_deviations` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let mesh = mesh_ref(mesh, "mesh")?;
            check_room("out_deviations", capacity, mesh.face_count())?;
            let out = output_slice(out_deviations, capacity, "out_deviations")?;
            analysis::write_planarity_deviations(mesh, &mut out[..mesh.face_count()]);
            Ok(())
        })
    }
}

/// Chains the naked edges (edges with one face) into polylines. On a
/// manifold mesh each border is one closed polyline running the way its
/// faces run their edges; at a vertex with one or three or more naked edges
/// polylines stop, and one that returns to its start is closed. A closed
/// polyline does not repeat its first point at the end.
///
/// Call it first with `out_points` NULL to learn the totals, then with
/// buffers of those sizes. The polylines' points follow one another in
/// `out_points`; polyline i has `out_point_counts[i]` of them.
///
/// `mesh` must not be NULL.
/// `out_points` receives x, y, z per point; NULL asks for the totals only.
/// `points_capacity` is its length in doubles (3 per point).
/// `out_point_counts` receives the number of points of each polyline; it
/// must not be NULL when `out_points` is not.
/// `out_closed` receives whether each polyline is closed; it may be NULL.
/// `polylines_capacity` is the number of elements `out_point_counts` (and
/// `out_closed`, when given) have room for.
/// When a buffer is too small the call fails with
/// WEFT_STATUS_BUFFER_TOO_SMALL and writes nothing.
/// `out_point_total` receives the number of points in all; must not be NULL.
/// `out_polyline_count` receives the number of polylines; must not be NULL.
///
/// # Safety
/// `mesh` is NULL or a live handle; each buffer is NULL or has room for its capacity.
#[no_mangle]
pub unsafe extern "C" fn weft_naked_boundaries(
    mesh: *const WeftMesh,
    out_points: *mut f64,
    points_capacity: usize,
    out_point_counts: *mut usize,
    out_closed: *mut bool,
    polylines_capacity: usize,
    out_point_total: *mut usize,
    out_polyline_count: *mut usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `out_points`, `out_point_counts`, `out_closed`, `out_point_total` and
    // `out_polyline_count` are as the `# Safety` section above requires; each is checked for NULL
    // before it is used.
    unsafe {
        guard(|| {
            let total_out = out_param(out_point_total, "out_point_total")?;
            let count_out = out_param(out_polyline_count, "out_polyline_count")?;
            let mesh = mesh_ref(mesh, "mesh")?;
            let polylines = analysis::naked_boundaries(mesh);
            let total: usize = polylines.iter().map(|p| p.vertices.len()).sum();
            if !out_points.is_null() {
                out_param(out_point_counts, "out_point_counts")?;
                check_room("out_points", points_capacity, total * 3)?;
                check_room("out_point_counts", polylines_capacity, polylines.len())?;
                let points = output_slice(out_points, points_capacity, "out_points")?;
                let counts =
                    output_slice(out_point_counts, polylines_capacity, "out_point_counts")?;
                let closed = if out_closed.is_null() {
                    None
                } else {
                    Some(output_slice(out_closed, polylines_capacity, "out_closed")?)
                };
                let mut chunks = points.chunks_exact_mut(3);
                for (i, polyline) in polylines.iter().enumerate() {
                    counts[i] = polyline.vertices.len();
                    for (chunk, &v) in chunks.by_ref().zip(&polyline.vertices) {
                        chunk.copy_from_slice(&mesh.positions()[v as usize].to_array());
                    }
                }
                if let Some(closed) = closed {
                    for (slot, polyline) in closed.iter_mut().zip(&polylines) {
                        *slot = polyline.closed;
                    }
                }
            }
            *total_out = total;
            *count_out = polylines.len();
            Ok(())
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_tolerance_matches_the_library() {
        assert_eq!(WEFT_DEFAULT_WELD_TOLERANCE, weld::DEFAULT_WELD_TOLERANCE);
    }
}
