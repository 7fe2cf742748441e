//! The refiner handle: plan a cage's subdivision once, re-evaluate it for
//! new cage positions (a slider dragged on the canvas) without allocating.

use glam::DVec3;

use crate::ffi::boundary::{
    check_room, guard, input_slice, make_mesh, out_param, output_slice, required, Failure,
    WeftStatus,
};
use crate::ffi::creases::{options_arg, WeftSubdivisionOptions};
use crate::ffi::mesh::{finite_result, mesh_ref, WeftMesh};
use crate::ffi::subdivide::{naked_edges_arg, scheme_arg};
use crate::mesh::Mesh;
use crate::subdivide::Refiner;

/// The subdivision of one cage topology, planned for every level. Create it
/// with `weft_refiner_new`, free it with `weft_refiner_free`. Evaluating is
/// thread-safe (calls on one refiner take turns).
pub struct WeftRefiner {
    refiner: Refiner,
}

impl WeftRefiner {
    /// A new handle owning `refiner`, for the other exports that make one.
    pub(crate) fn boxed(refiner: Refiner) -> *mut WeftRefiner {
        Box::into_raw(Box::new(WeftRefiner { refiner }))
    }
}

/// Runs an export that plans a refiner of `cage`: checks `out_refiner`
/// first and writes the new handle only on success.
///
/// # Safety
/// `cage` is NULL or a live handle; `out_refiner` is NULL or writable.
unsafe fn refiner_op(
    cage: *const WeftMesh,
    out_refiner: *mut *mut WeftRefiner,
    plan: impl FnOnce(&Mesh) -> Result<Refiner, Failure>,
) -> WeftStatus {
    guard(|| {
        let out = out_param(out_refiner, "out_refiner")?;
        // SAFETY: `cage` is NULL or a live handle, as the caller promises.
        let cage = unsafe { mesh_ref(cage, "cage") }?;
        let refiner = plan(cage)?;
        // SAFETY: `out` is the caller's writable `out_refiner`, checked not NULL.
        unsafe { *out = WeftRefiner::boxed(refiner) };
        Ok(())
    })
}

/// Plans `levels` steps of `scheme` on the faces of `cage`: everything that
/// depends only on its topology (the faces of each level and what each new
/// vertex is made of) is computed here, once.
///
/// `cage` must not be NULL; its positions are kept for `weft_refiner_mesh`.
/// `scheme` is a WEFT_SCHEME_* value, `naked_edges` a WEFT_NAKED_EDGES_* value.
/// `out_refiner` receives the refiner on success (free it with
/// `weft_refiner_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_NULL_POINTER, WEFT_STATUS_INVALID_ARGUMENT,
/// WEFT_STATUS_NOT_TRIANGLES (Loop on another polygon),
/// WEFT_STATUS_RESULT_TOO_LARGE or WEFT_STATUS_OUT_OF_MEMORY.
///
/// # Safety
/// `cage` is NULL or a live handle; `out_refiner` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_refiner_new(
    cage: *const WeftMesh,
    scheme: u32,
    levels: u32,
    naked_edges: u32,
    out_refiner: *mut *mut WeftRefiner,
) -> WeftStatus {
    // SAFETY: `cage` and `out_refiner` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        refiner_op(cage, out_refiner, |cage| {
            let scheme = scheme_arg(scheme)?;
            let naked_edges = naked_edges_arg(naked_edges)?;
            Ok(Refiner::new(cage, scheme, levels, naked_edges)?)
        })
    }
}

/// Plans a subdivision with the scheme, naked-edge mode, creases and corners
/// of `options` once, for re-evaluation with `weft_refiner_evaluate` (the
/// other `weft_refiner_*` functions work on it as on one from
/// `weft_refiner_new`).
///
/// `cage` and `options` must not be NULL; the cage's positions are kept for
/// `weft_refiner_mesh`. `out_refiner` receives the refiner on success (free
/// it with `weft_refiner_free`) and is left untouched on failure; it must
/// not be NULL.
///
/// Fails as `weft_subdivide_ex`.
///
/// # Safety
/// `cage` is NULL or a live handle; `options` as in `weft_subdivide_ex`;
/// `out_refiner` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_refiner_new_ex(
    cage: *const WeftMesh,
    options: *const WeftSubdivisionOptions,
    levels: u32,
    out_refiner: *mut *mut WeftRefiner,
) -> WeftStatus {
    // SAFETY: `cage`, `options` and `out_refiner` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        refiner_op(cage, out_refiner, |cage| {
            let (scheme, options) = options_arg(options)?;
            Ok(Refiner::with_options(cage, scheme, levels, &options)?)
        })
    }
}

/// Computes the refined positions for new cage positions, without
/// allocating: the cage's faces must be those the refiner was built from.
///
/// `refiner` must not be NULL.
/// `cage_positions` holds `3 * vertex_count` doubles; `vertex_count` must
/// equal the cage's vertex count.
/// `out_positions` has room for `out_len` doubles, at least
/// `3 * weft_refiner_vertex_count(refiner)`; too small a buffer fails with
/// WEFT_STATUS_BUFFER_TOO_SMALL and nothing is written.
///
/// Fails with WEFT_STATUS_NULL_POINTER, WEFT_STATUS_COUNT_MISMATCH,
/// WEFT_STATUS_BUFFER_TOO_SMALL or WEFT_STATUS_NON_FINITE_COORDINATE, with
/// nothing written. Coordinates near the largest double are refined at an
/// exactly scaled size, so the rules never overflow; a refined point beyond
/// the largest double (only when the cage spans nearly the whole range) is
/// WEFT_STATUS_DEGENERATE_INPUT naming the vertex, and the contents of
/// `out_positions` are then unspecified.
///
/// # Safety
/// `refiner` is NULL or live; the buffers hold the elements stated.
#[no_mangle]
pub unsafe extern "C" fn weft_refiner_evaluate(
    refiner: *const WeftRefiner,
    cage_positions: *const f64,
    vertex_count: usize,
    out_positions: *mut f64,
    out_len: usize,
) -> WeftStatus {
    // SAFETY: `refiner`, `cage_positions` and `out_positions` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let refiner = &required(refiner, "refiner")?.refiner;
            if vertex_count != refiner.cage_vertex_count() {
                return Err(Failure::new(
                    WeftStatus::CountMismatch,
                    format!(
                        "vertex_count is {vertex_count} but the refiner's cage has {} vertices",
                        refiner.cage_vertex_count()
                    ),
                ));
            }
            let needed = 3 * refiner.vertex_count();
            check_room("out_positions", out_len, needed)?;
            let cage = input_slice(cage_positions, 3 * vertex_count, "cage_positions")?;
            let out = output_slice(out_positions, out_len, "out_positions")?;
            if let Some(i) = cage.iter().position(|c| !c.is_finite()) {
                return Err(Failure::new(
                    WeftStatus::NonFiniteCoordinate,
                    format!("cage vertex {} has a non-finite coordinate", i / 3),
                ));
            }
            // DVec3 is three f64 in a row (`#[repr(C)]`, alignment of f64).
            let cage = std::slice::from_raw_parts(cage.as_ptr().cast::<DVec3>(), vertex_count);
            let out = std::slice::from_raw_parts_mut(
                out.as_mut_ptr().cast::<DVec3>(),
                refiner.vertex_count(),
            );
            refiner.evaluate(cage, out)?;
            Ok(())
        })
    }
}

/// Makes the refined mesh at the cage positions the refiner was built from.
///
/// `refiner` must not be NULL. `out_mesh` receives the mesh on success (free
/// it with `weft_mesh_free`); it must not be NULL.
///
/// Fails with WEFT_STATUS_NULL_POINTER or WEFT_STATUS_OUT_OF_MEMORY, and
/// with WEFT_STATUS_DEGENERATE_INPUT naming the vertex when a refined point
/// lies beyond the largest double (see `weft_refiner_evaluate`).
///
/// # Safety
/// `refiner` is NULL or live; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_refiner_mesh(
    refiner: *const WeftRefiner,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `refiner` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        make_mesh(out_mesh, || {
            let refiner = &required(refiner, "refiner")?.refiner;
            finite_result(refiner.mesh()?, "subdivision")
        })
    }
}

/// Returns the number of refined vertices (the output of
/// `weft_refiner_evaluate` holds three doubles each), or 0 when `refiner` is NULL.
///
/// # Safety
/// `refiner` is NULL or live.
#[no_mangle]
pub unsafe extern "C" fn weft_refiner_vertex_count(refiner: *const WeftRefiner) -> usize {
    // SAFETY: `refiner` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe { refiner.as_ref().map_or(0, |r| r.refiner.vertex_count()) }
}

/// Returns the number of refined faces, or 0 when `refiner` is NULL.
///
/// # Safety
/// `refiner` is NULL or live.
#[no_mangle]
pub unsafe extern "C" fn weft_refiner_face_count(refiner: *const WeftRefiner) -> usize {
    // SAFETY: `refiner` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe { refiner.as_ref().map_or(0, |r| r.refiner.face_count()) }
}

/// Frees a refiner. NULL is ignored.
///
/// # Safety
/// `refiner` is NULL or a refiner not yet freed; it is invalid afterwards.
#[no_mangle]
pub unsafe extern "C" fn weft_refiner_free(refiner: *mut WeftRefiner) {
    // SAFETY: `refiner` is NULL or a handle from this library not yet
    // freed, as the `# Safety` section above requires.
    unsafe {
        if !refiner.is_null() {
            let _ = std::panic::catch_unwind(|| drop(Box::from_raw(refiner)));
        }
    }
}
