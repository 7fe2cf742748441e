//! Weaverbird's linear subdivisions and smoothing through the C ABI: split
//! polygons, split triangles, constant quads, mid-edge, inner polygons,
//! Sierpinski triangles, Laplacian and HC smoothing, blurred values. Each
//! export converts, checks and forwards to `split` or `smooth`; the offsets
//! and bevels are in `transform`, the dual and edges in `extract`.

use crate::error::Error;
use crate::ffi::boundary::{
    check_room, enum_arg, forward_mesh_op, guard, input_slice, mesh_op, output_slice, Failure,
    WeftStatus,
};
use crate::ffi::mesh::{mesh_ref, WeftMesh};
use crate::mesh::Mesh;
use crate::toolbar::smooth::{self, HcOptions, NakedEdges, SmoothDirection};
use crate::toolbar::split;

/// Smoothing direction: vertices move freely (the published HC algorithm).
pub const WEFT_SMOOTH_DIRECTION_FREE: u32 = 0;
/// Smoothing direction: each vertex moves only along the line of its
/// original vertex normal, so nothing slides across the surface.
pub const WEFT_SMOOTH_DIRECTION_ALONG_NORMAL: u32 = 1;
/// Smoothing direction: each vertex moves only within the plane through its
/// original position across its original normal (relaxation).
pub const WEFT_SMOOTH_DIRECTION_TANGENTIAL: u32 = 2;

fn naked_edges(value: u32) -> Result<NakedEdges, Failure> {
    crate::ffi::subdivide::naked_edges_arg(value)
}

/// The body of the smoothing exports: reads the naked-edge rule, then runs
/// `op` with it.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
unsafe fn smooth_op(
    mesh: *const WeftMesh,
    out_mesh: *mut *mut WeftMesh,
    naked_edges: u32,
    op: impl FnOnce(&Mesh, NakedEdges) -> Result<Mesh, Error>,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as this function's `# Safety`
    // section requires, which its callers promise.
    unsafe {
        mesh_op(mesh, out_mesh, |m| {
            let naked = self::naked_edges(naked_edges)?;
            Ok(op(m, naked)?)
        })
    }
}

/// Splits each n-gon into n quads through its edge midpoints and centroid,
/// `levels` times, without smoothing (Weaverbird's Split Polygons: the
/// topology of Catmull-Clark, the surface unchanged, the result welded).
///
/// `mesh` is the input; it must not be NULL.
/// `levels` is the number of splits, 0 to 20; 0 returns a copy.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for more than 20 levels and
/// WEFT_STATUS_RESULT_TOO_LARGE when the result would pass the size cap.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_split_polygons(
    mesh: *const WeftMesh,
    levels: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { forward_mesh_op(mesh, out_mesh, |m| split::split_polygons(m, levels)) }
}

/// Splits each triangle into four through its edge midpoints, `levels`
/// times, without smoothing (Weaverbird's Split Triangles).
///
/// `mesh` is the input, a triangle mesh; it must not be NULL.
/// `levels` is the number of splits, 0 to 20.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_NOT_TRIANGLES naming the first other face,
/// WEFT_STATUS_INVALID_ARGUMENT for more than 20 levels and
/// WEFT_STATUS_RESULT_TOO_LARGE past the size cap.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_split_triangles(
    mesh: *const WeftMesh,
    levels: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { forward_mesh_op(mesh, out_mesh, |m| split::split_triangles(m, levels)) }
}

/// Splits each quad into four quads, each triangle into four triangles and
/// each larger polygon into quads around its centroid, `levels` times,
/// without smoothing (Weaverbird's Constant Quads Split).
///
/// `mesh` is the input; it must not be NULL.
/// `levels` is the number of splits, 0 to 20.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for more than 20 levels and
/// WEFT_STATUS_RESULT_TOO_LARGE past the size cap.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_constant_quads_split(
    mesh: *const WeftMesh,
    levels: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { forward_mesh_op(mesh, out_mesh, |m| split::constant_quads_split(m, levels)) }
}

/// The mid-edge subdivision (Peters and Reif), `levels` times: a face of
/// edge midpoints per face and per vertex; boundary vertices are kept so an
/// open mesh keeps its outline.
///
/// `mesh` is the input; it must not be NULL.
/// `levels` is the number of steps, 0 to 20.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for more than 20 levels and
/// WEFT_STATUS_RESULT_TOO_LARGE past the size cap.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_midedge(
    mesh: *const WeftMesh,
    levels: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { forward_mesh_op(mesh, out_mesh, |m| split::midedge(m, levels)) }
}

/// Gives each face an inner face, its corners pulled towards its centroid,
/// joined to it by one quad per edge, `levels` times (Weaverbird's Inner
/// Polygons).
///
/// `mesh` is the input; it must not be NULL.
/// `levels` is the number of steps, 0 to 20.
/// `pull` is how far the inner corners move towards the centroid, strictly
/// between 0 and 1 (0.5 is halfway).
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for a `pull` out of range or
/// more than 20 levels, WEFT_STATUS_RESULT_TOO_LARGE past the size cap.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_inner_polygons(
    mesh: *const WeftMesh,
    levels: u32,
    pull: f64,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { forward_mesh_op(mesh, out_mesh, |m| split::inner_polygons(m, levels, pull)) }
}

/// Places a triangle in each corner of each face and leaves the middle
/// open, `levels` times (Weaverbird's Sierpinski Triangles): one new hole
/// per face and level.
///
/// `mesh` is the input; it must not be NULL.
/// `levels` is the number of steps, 0 to 20.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for more than 20 levels and
/// WEFT_STATUS_RESULT_TOO_LARGE past the size cap.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_sierpinski_triangles(
    mesh: *const WeftMesh,
    levels: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { forward_mesh_op(mesh, out_mesh, |m| split::sierpinski_triangles(m, levels)) }
}

/// Laplacian smoothing: each iteration moves every vertex `blend` of the
/// way towards the average of its neighbours (Weaverbird's Laplacian
/// Smoothing). The faces do not change.
///
/// `mesh` is the input; it must not be NULL.
/// `iterations` is the number of steps, 0 to 10000.
/// `blend` is in [0, 1]: 1 jumps to the average, 0 does nothing.
/// `naked_edges` is one of the WEFT_NAKED_EDGES_* values.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT naming the argument out of range.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_laplacian_smooth(
    mesh: *const WeftMesh,
    iterations: u32,
    blend: f64,
    naked_edges: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        smooth_op(mesh, out_mesh, naked_edges, |m, naked| {
            smooth::laplacian(m, iterations, blend, naked)
        })
    }
}

/// Volume-preserving Laplacian smoothing, the HC algorithm of Vollmer,
/// Mann and Müller (1999): each iteration averages, then pushes every
/// vertex back by `beta` of its own displacement and `1 - beta` of its
/// neighbours' (Weaverbird's LaplacianHC).
///
/// `mesh` is the input; it must not be NULL.
/// `iterations` is the number of steps, 0 to 10000.
/// `alpha` is in [0, 1]: how much the push-back aims at the original
/// positions rather than the previous iteration's (0 is usual).
/// `beta` is in [0, 1]: the share of a vertex's own displacement undone
/// (above 0.5 is recommended; 0.6 is a good start).
/// `naked_edges` is one of the WEFT_NAKED_EDGES_* values.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT naming the argument out of range.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_laplacian_hc_smooth(
    mesh: *const WeftMesh,
    iterations: u32,
    alpha: f64,
    beta: f64,
    naked_edges: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        smooth_op(mesh, out_mesh, naked_edges, |m, naked| {
            smooth::laplacian_hc(m, iterations, alpha, beta, naked)
        })
    }
}

/// `weft_laplacian_hc_smooth` with Weaverbird's remaining LaplacianHC
/// inputs: a direction (its orientation input) and per-vertex activation
/// weights. Each weight scales the steps its vertex takes (0 keeps it where
/// it is and it anchors its neighbours, 1 is the full step); the direction
/// then restricts each vertex to its original normal line or tangent plane.
///
/// `mesh` is the input; it must not be NULL.
/// `iterations`, `alpha`, `beta` and `naked_edges` are as for
/// `weft_laplacian_hc_smooth`.
/// `direction` is one of the WEFT_SMOOTH_DIRECTION_* values.
/// `activation` holds `activation_count` weights in [0, 1], one per vertex;
/// it may be NULL (with `activation_count` 0) to move every vertex fully.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT naming the argument out of
/// range, an activation count other than the vertex count (naming both) or
/// a weight outside [0, 1] (naming the vertex).
///
/// # Safety
/// `mesh` is NULL or a live handle; `activation` is NULL or holds
/// `activation_count` doubles; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_laplacian_hc_smooth_ex(
    mesh: *const WeftMesh,
    iterations: u32,
    alpha: f64,
    beta: f64,
    naked_edges: u32,
    direction: u32,
    activation: *const f64,
    activation_count: usize,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh`, `activation` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        mesh_op(mesh, out_mesh, |m| {
            let naked = self::naked_edges(naked_edges)?;
            let direction = enum_arg(
                direction,
                "direction",
                |v| match v {
                    WEFT_SMOOTH_DIRECTION_FREE => Some(SmoothDirection::Free),
                    WEFT_SMOOTH_DIRECTION_ALONG_NORMAL => Some(SmoothDirection::AlongNormal),
                    WEFT_SMOOTH_DIRECTION_TANGENTIAL => Some(SmoothDirection::Tangential),
                    _ => None,
                },
                "WEFT_SMOOTH_DIRECTION_FREE (0), WEFT_SMOOTH_DIRECTION_ALONG_NORMAL (1) or WEFT_SMOOTH_DIRECTION_TANGENTIAL (2)",
            )?;
            let activation_count = match activation.is_null() && activation_count == 0 {
                true => None,
                false => Some(activation_count),
            };
            // Every count is checked before the buffer is viewed.
            smooth::check_hc_arguments(m, iterations, alpha, beta, activation_count)?;
            let activation = match activation_count {
                None => None,
                Some(count) => Some(input_slice(activation, count, "activation")?),
            };
            let options = HcOptions {
                alpha,
                beta,
                naked,
                direction,
                activation,
            };
            Ok(smooth::laplacian_hc_with(m, iterations, &options)?)
        })
    }
}

/// Blurs a per-vertex value (a colour, a weight) over the mesh: each
/// iteration moves every vertex's value `blend` of the way towards the
/// average of its neighbours' (Weaverbird's Blur). The mesh is unchanged.
///
/// `mesh` is the input; it must not be NULL.
/// `values` holds `value_count` doubles, `components` per vertex, vertex
/// after vertex; `value_count` must be `components * vertex_count`. It may
/// be NULL only when `value_count` is 0.
/// `components` is the number of values per vertex (3 or 4 for a colour),
/// at least 1.
/// `iterations` is the number of steps, 0 to 10000.
/// `blend` is in [0, 1].
/// `naked_edges` is one of the WEFT_NAKED_EDGES_* values.
/// `out_values` receives the blurred values in the same layout; it must
/// have room for `value_count` doubles (`out_len`), may be the same buffer
/// as `values`, and is written only on success.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for a wrong value count (naming
/// both numbers) or an argument out of range, WEFT_STATUS_BUFFER_TOO_SMALL
/// when `out_len` is below `value_count`.
///
/// # Safety
/// `mesh` is NULL or a live handle; each non-NULL buffer holds the number
/// of elements stated.
#[no_mangle]
pub unsafe extern "C" fn weft_blur_values(
    mesh: *const WeftMesh,
    values: *const f64,
    value_count: usize,
    components: usize,
    iterations: u32,
    blend: f64,
    naked_edges: u32,
    out_values: *mut f64,
    out_len: usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `values` and `out_values` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let mesh = mesh_ref(mesh, "mesh")?;
            let naked = self::naked_edges(naked_edges)?;
            let blurred = {
                // Every count is checked before the buffer is viewed.
                smooth::check_blur_arguments(mesh, value_count, components, iterations, blend)?;
                let values = input_slice(values, value_count, "values")?;
                smooth::blur(mesh, values, components, iterations, blend, naked)?
            };
            check_room("out_values", out_len, blurred.len())?;
            let out = output_slice(out_values, blurred.len(), "out_values")?;
            out.copy_from_slice(&blurred);
            Ok(())
        })
    }
}
