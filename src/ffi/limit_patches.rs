//! The Catmull-Clark limit surface as bicubic Bézier patches, for NURBS
//! export (`weft nurbs` writes them as STEP).

use crate::ffi::boundary::{check_room, guard, output_slice, required, Failure, WeftStatus};
use crate::ffi::creases::{options_arg, WeftSubdivisionOptions};
use crate::ffi::limit_surface::WeftLimitSurface;
use crate::ffi::mesh::{mesh_ref, WeftMesh};
use crate::mesh::Mesh;
use crate::subdivide::{limit_patch_count, limit_patches, Scheme, SubdivisionOptions};

/// Doubles per patch in `weft_limit_patches`'s control points: 4 × 4 points of 3.
pub const WEFT_PATCH_DOUBLES: usize = 48;

/// The limit surface of the Catmull-Clark subdivision `options` describes
/// (its scheme must be WEFT_SCHEME_CATMULL_CLARK) as one bicubic Bézier
/// patch per face of `cage` refined `isolation` levels (1 to 8), in the
/// refined faces' order, `weft_subdivision_counts_ex(cage, options,
/// isolation, ...)` of them.
///
/// Patch p's control point i along u and j along v (u from the refined
/// face's first corner towards its second, v towards its last, so du × dv
/// points out of a counter-clockwise face) is `out_control_points[48 p +
/// 12 i + 3 j + k]`, k = x, y, z: a B-spline surface of degree 3 × 3 with
/// knots 0, 0, 0, 0, 1, 1, 1, 1 in each direction. Patches that meet at an
/// edge share its boundary control points bit for bit. Where the limit
/// surface is a bicubic B-spline (away from extraordinary vertices, crease
/// ends and corners) a patch is exact; the others are fitted to exact limit
/// points. `out_errors[p]` is patch p's largest distance from the limit
/// points of an 8 × 8 grid of its face (0 where the patch is made as the
/// B-spline the surface is there), `out_cage_faces[p]` the cage face it
/// lies on; both may be NULL. `*out_patch_count` receives the number of
/// patches, `*out_max_error` (may be NULL) the largest error and
/// `*out_exact_count` (may be NULL) how many patches are exact (an error
/// within 1e-12 of the cage's bounding-box diagonal).
///
/// `capacity` is the room in patches: `out_control_points` holds 48 ×
/// `capacity` doubles (it may be NULL when `capacity` is 0), `out_cage_faces` and `out_errors` `capacity` elements
/// each; too little fails with WEFT_STATUS_BUFFER_TOO_SMALL. An isolation
/// outside 1 to 8 or another scheme is WEFT_STATUS_INVALID_ARGUMENT; the
/// options fail as `weft_subdivide_ex`'s; a face whose neighbours (the faces
/// sharing a vertex with it) would make more than 262,144 patches, a vertex
/// of very many faces at a high isolation, is WEFT_STATUS_RESULT_TOO_LARGE.
/// Nothing is written on failure.
///
/// # Safety
/// `cage` and `options` are NULL or valid; each non-NULL output holds what
/// `capacity` says; `out_patch_count` is writable.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn weft_limit_patches(
    cage: *const WeftMesh,
    options: *const WeftSubdivisionOptions,
    isolation: u32,
    out_control_points: *mut f64,
    out_cage_faces: *mut u32,
    out_errors: *mut f64,
    capacity: usize,
    out_patch_count: *mut usize,
    out_max_error: *mut f64,
    out_exact_count: *mut usize,
) -> WeftStatus {
    // SAFETY: the pointers are as the `# Safety` section above requires;
    // each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let mesh = mesh_ref(cage, "cage")?;
            let (scheme, options) = options_arg(options)?;
            let out = PatchBuffers {
                control_points: out_control_points,
                cage_faces: out_cage_faces,
                errors: out_errors,
                capacity,
                patch_count: out_patch_count,
                max_error: out_max_error,
                exact_count: out_exact_count,
            };
            fill_patches(mesh, scheme, &options, isolation, &out)
        })
    }
}

/// The limit surface's patches, as `weft_limit_patches` gives them for the
/// cage and options `surface` was made from (its scheme must be
/// WEFT_SCHEME_CATMULL_CLARK): the same buffers, the same rules, the same
/// errors, and WEFT_STATUS_NULL_POINTER for a NULL `surface`.
///
/// # Safety
/// `surface` is NULL or a live handle; the outputs as `weft_limit_patches`.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn weft_limit_surface_patches(
    surface: *const WeftLimitSurface,
    isolation: u32,
    out_control_points: *mut f64,
    out_cage_faces: *mut u32,
    out_errors: *mut f64,
    capacity: usize,
    out_patch_count: *mut usize,
    out_max_error: *mut f64,
    out_exact_count: *mut usize,
) -> WeftStatus {
    // SAFETY: `surface` and the outputs are as the `# Safety` section above
    // requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let surface = required(surface, "surface")?;
            let out = PatchBuffers {
                control_points: out_control_points,
                cage_faces: out_cage_faces,
                errors: out_errors,
                capacity,
                patch_count: out_patch_count,
                max_error: out_max_error,
                exact_count: out_exact_count,
            };
            let scheme = surface.surface.scheme();
            fill_patches(&surface.cage, scheme, &surface.options, isolation, &out)
        })
    }
}

/// The caller buffers of the two patch exports.
struct PatchBuffers {
    control_points: *mut f64,
    cage_faces: *mut u32,
    errors: *mut f64,
    capacity: usize,
    patch_count: *mut usize,
    max_error: *mut f64,
    exact_count: *mut usize,
}

/// Makes the patches and writes them, or writes nothing and fails.
///
/// # Safety
/// The buffers are as `weft_limit_patches` requires.
unsafe fn fill_patches(
    mesh: &Mesh,
    scheme: Scheme,
    options: &SubdivisionOptions,
    isolation: u32,
    out: &PatchBuffers,
) -> Result<(), Failure> {
    if out.patch_count.is_null() {
        return Err(Failure::new(
            WeftStatus::NullPointer,
            "out_patch_count is NULL",
        ));
    }
    if out.control_points.is_null() && out.capacity > 0 {
        return Err(Failure::new(
            WeftStatus::NullPointer,
            "out_control_points is NULL",
        ));
    }
    if scheme != Scheme::CatmullClark {
        return Err(Failure::invalid_argument(
            "the scheme is Loop; patches need WEFT_SCHEME_CATMULL_CLARK (Loop's limit surface is a quartic box spline, which no bicubic patch holds exactly)",
        ));
    }
    // Too little room is found before any patch is fitted.
    let count = limit_patch_count(mesh, options, isolation)?;
    check_room("capacity (in patches)", out.capacity, count)?;
    let patches = limit_patches(mesh, options, isolation)?;
    debug_assert_eq!(patches.patches.len(), count);
    let doubles = out
        .capacity
        .checked_mul(WEFT_PATCH_DOUBLES)
        .ok_or_else(|| {
            Failure::invalid_argument(format!(
                "capacity {} is larger than memory can hold",
                out.capacity
            ))
        })?;
    // SAFETY: each buffer holds what `capacity` says, as this function's
    // `# Safety` section requires; NULL ones are skipped.
    unsafe {
        let points = output_slice(out.control_points, doubles, "out_control_points")?;
        let faces = (!out.cage_faces.is_null())
            .then(|| output_slice(out.cage_faces, out.capacity, "out_cage_faces"))
            .transpose()?;
        let errors = (!out.errors.is_null())
            .then(|| output_slice(out.errors, out.capacity, "out_errors"))
            .transpose()?;
        for (patch, out) in patches
            .patches
            .iter()
            .zip(points.chunks_exact_mut(WEFT_PATCH_DOUBLES))
        {
            for (row, out) in patch.control.iter().zip(out.chunks_exact_mut(12)) {
                for (point, xyz) in row.iter().zip(out.chunks_exact_mut(3)) {
                    xyz.copy_from_slice(&point.to_array());
                }
            }
        }
        if let Some(faces) = faces {
            for (patch, out) in patches.patches.iter().zip(faces) {
                *out = patch.cage_face;
            }
        }
        if let Some(errors) = errors {
            for (patch, out) in patches.patches.iter().zip(errors) {
                *out = patch.error;
            }
        }
        *out.patch_count = count;
        if !out.max_error.is_null() {
            *out.max_error = patches.max_error;
        }
        if !out.exact_count.is_null() {
            *out.exact_count = patches.exact_count;
        }
    }
    Ok(())
}
