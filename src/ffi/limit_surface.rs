//! The limit surface handle: evaluation anywhere on the smooth surface of a
//! cage, with derivatives.

use glam::DVec3;

use crate::ffi::boundary::{
    guard, input_slice, out_param, output_slice, point_count_arg, points_arg, required, Failure,
    WeftStatus,
};
use crate::ffi::creases::{options_arg, WeftSubdivisionOptions};
use crate::ffi::mesh::{mesh_ref, WeftMesh};
use crate::mesh::Mesh;
use crate::subdivide::{LimitSurface, SubdivisionOptions};

/// The limit surface of one cage, prepared for evaluation anywhere. Create
/// it with `weft_limit_surface_new`, free it with `weft_limit_surface_free`.
/// Evaluating is thread-safe.
pub struct WeftLimitSurface {
    pub(crate) surface: LimitSurface,
    /// The cage and options it was made from, for its patches
    /// (`weft_limit_surface_patches`).
    pub(crate) cage: Mesh,
    pub(crate) options: SubdivisionOptions,
}

/// Prepares the limit surface of `cage` subdivided as `options` say
/// (scheme, naked-edge mode, creases, corners, holes, creasing, triangle
/// weights), for evaluation anywhere with `weft_limit_surface_evaluate`.
///
/// Evaluation is exact: a regular face is its bicubic B-spline
/// (Catmull-Clark) or quartic box-spline (Loop) patch; any other face is
/// refined locally with the subdivision's own rules, once here, until every
/// part of it is such a patch, and evaluation follows that refinement as
/// deep as a sample needs. Results equal OpenSubdiv's Bfr on regular faces
/// to about 1e-15 of the cage's size, and its approximation converges to
/// them elsewhere.
///
/// `cage` and `options` must not be NULL. `out_surface` receives the surface
/// on success (free it with `weft_limit_surface_free`) and is left untouched
/// on failure; it must not be NULL.
///
/// Fails as `weft_subdivide_ex` (WEFT_STATUS_NOT_TRIANGLES for Loop on
/// another polygon, a bad crease, corner or hole), with
/// WEFT_STATUS_NON_FINITE_COORDINATE for a cage coordinate that is not
/// finite, WEFT_STATUS_INVALID_ARGUMENT for a face whose semi-sharp
/// creases would need more than 65536 local refinements, and
/// WEFT_STATUS_RESULT_TOO_LARGE for a vertex with more than 1024 faces
/// around it (each face around a vertex refines the vertex's whole ring on
/// its own, so memory and time grow as the square of the count).
///
/// # Safety
/// `cage` is NULL or a live handle; `options` as in `weft_subdivide_ex`;
/// `out_surface` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_limit_surface_new(
    cage: *const WeftMesh,
    options: *const WeftSubdivisionOptions,
    out_surface: *mut *mut WeftLimitSurface,
) -> WeftStatus {
    // SAFETY: `cage`, `options` and `out_surface` are as the `# Safety`
    // section above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let out = out_param(out_surface, "out_surface")?;
            let cage = mesh_ref(cage, "cage")?;
            let (scheme, options) = options_arg(options)?;
            if let Some(v) = cage.positions().iter().position(|p| !p.is_finite()) {
                return Err(Failure::new(
                    WeftStatus::NonFiniteCoordinate,
                    format!("cage vertex {v} has a non-finite coordinate"),
                ));
            }
            let surface = LimitSurface::new(cage, scheme, &options)?;
            *out = Box::into_raw(Box::new(WeftLimitSurface {
                surface,
                cage: cage.clone(),
                options,
            }));
            Ok(())
        })
    }
}

/// Evaluates the limit surface at `count` samples: sample i lies on cage
/// face `faces[i]` at `(uvs[2 i], uvs[2 i + 1])`. Parallel; nothing is
/// allocated per sample.
///
/// Parameters, per face:
/// - a quad (Catmull-Clark): 0 ≤ u, v ≤ 1 from its first corner, u towards
///   the second corner and v towards the last;
/// - a triangle (Loop): barycentric, u, v ≥ 0 and u + v ≤ 1, corner 0 at
///   (0, 0), corner 1 at (1, 0), corner 2 at (0, 1);
/// - any other face of n corners (Catmull-Clark triangles and n-gons) as
///   OpenSubdiv's Bfr::Parameterization QUAD_SUBFACES: the face is the n
///   quads of its first subdivision, quad i (at corner i) the tile
///   [x, x + 1/2] × [y, y + 1/2] with x = i mod w, y = i div w, and w = 2
///   for n < 5, 3 for n < 10, else 1 + floor(sqrt(n - 1)); in the tile u runs
///   from corner i towards the middle of edge i (corner i to i + 1), v
///   towards the middle of the edge before it. Corner i is at (x, y).
///
/// `surface` must not be NULL. `faces` holds `count` face indices; `uvs`
/// holds `2 * count` doubles. `out_positions` must have room for
/// `3 * count` doubles. `out_du` and `out_dv` receive the derivatives by u
/// and by v (3 doubles per sample) and may each be NULL. At an
/// extraordinary vertex or the end of a crease, where the parameterisation
/// has no derivative, they are the limit tangents, whose cross product is
/// the limit normal that `weft_subdivide_limit` gives; at a corner (an
/// infinitely sharp vertex) they are the one-sided derivatives of the face
/// evaluated. The normal is `du × dv` normalised.
///
/// Accuracy: exact to rounding (about 1e-15 of the cage's size in the
/// positions); a sample within 2^-60 of a face's size of an irregular point
/// takes that point's limit, far below rounding.
///
/// Fails with WEFT_STATUS_NULL_POINTER (a NULL surface or buffer),
/// WEFT_STATUS_INDEX_OUT_OF_RANGE (a face past the cage's),
/// WEFT_STATUS_NON_FINITE_COORDINATE (a NaN or infinite parameter) or
/// WEFT_STATUS_INVALID_ARGUMENT (a parameter outside the face's domain, or a
/// face that is a hole), the message naming the sample and its face;
/// nothing is written then.
///
/// # Safety
/// `surface` is NULL or live; the buffers are NULL or hold the elements stated.
#[no_mangle]
pub unsafe extern "C" fn weft_limit_surface_evaluate(
    surface: *const WeftLimitSurface,
    count: usize,
    faces: *const u32,
    uvs: *const f64,
    out_positions: *mut f64,
    out_du: *mut f64,
    out_dv: *mut f64,
) -> WeftStatus {
    // SAFETY: `surface` and the buffers are as the `# Safety` section above
    // requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let surface = &required(surface, "surface")?.surface;
            let doubles = point_count_arg(count, "count")?;
            let faces = input_slice(faces, count, "faces")?;
            let uvs = input_slice(uvs, 2 * count, "uvs")?;
            let face_count = surface.face_count();
            for (i, &f) in faces.iter().enumerate() {
                if f as usize >= face_count {
                    return Err(Failure::new(
                        WeftStatus::IndexOutOfRange,
                        format!(
                            "sample {i}: face {f} is out of range (the cage has {face_count} faces)"
                        ),
                    ));
                }
                let (u, v) = (uvs[2 * i], uvs[2 * i + 1]);
                if !u.is_finite() || !v.is_finite() {
                    return Err(Failure::new(
                        WeftStatus::NonFiniteCoordinate,
                        format!("sample {i} on face {f}: (u, v) = ({u}, {v}) is not finite"),
                    ));
                }
            }
            let positions = output_slice(out_positions, doubles, "out_positions")?;
            let optional = |pointer: *mut f64, name: &str| -> Result<_, Failure> {
                if pointer.is_null() {
                    return Ok(None);
                }
                let out = output_slice(pointer, doubles, name)?;
                // DVec3 is three f64 in a row (`#[repr(C)]`, alignment of f64).
                Ok(Some(std::slice::from_raw_parts_mut(
                    out.as_mut_ptr().cast::<DVec3>(),
                    count,
                )))
            };
            let du = optional(out_du, "out_du")?;
            let dv = optional(out_dv, "out_dv")?;
            let positions =
                std::slice::from_raw_parts_mut(positions.as_mut_ptr().cast::<DVec3>(), count);
            surface.evaluate(faces, uvs, positions, du, dv)?;
            Ok(())
        })
    }
}

/// Finds the nearest point of the limit surface to each of `count` query
/// points: its face, its (u, v) on that face (parameters as
/// `weft_limit_surface_evaluate`) and its position, which is the surface
/// evaluated there.
///
/// Candidate faces come from a grid of their bounding boxes (built on the
/// first call), nearest first; on each, Gauss-Newton projects the query
/// from the nearest surface samples, staying in the face's domain, until no
/// other face can be nearer. Accuracy: the distance is that of the nearest
/// point to rounding where the surface is smooth (tested against dense
/// sampling on open and closed cages to about 1e-15 of the cage's size);
/// where several points are equally near, any one of them is returned.
///
/// `surface` must not be NULL. `points` holds `3 * count` doubles;
/// `out_faces` has room for `count` indices, `out_uvs` for `2 * count`
/// doubles, `out_positions` for `3 * count` doubles; none may be NULL
/// unless `count` is 0.
///
/// Fails with WEFT_STATUS_NULL_POINTER, WEFT_STATUS_NON_FINITE_COORDINATE
/// (naming the query point) or WEFT_STATUS_INVALID_ARGUMENT (every face a
/// hole), with nothing written.
///
/// # Safety
/// `surface` is NULL or live; the buffers are NULL or hold the elements stated.
#[no_mangle]
pub unsafe extern "C" fn weft_limit_surface_closest_point(
    surface: *const WeftLimitSurface,
    count: usize,
    points: *const f64,
    out_faces: *mut u32,
    out_uvs: *mut f64,
    out_positions: *mut f64,
) -> WeftStatus {
    // SAFETY: `surface` and the buffers are as the `# Safety` section above
    // requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let surface = &required(surface, "surface")?.surface;
            let doubles = point_count_arg(count, "count")?;
            let queries = points_arg(points, count, "points")?;
            let faces = output_slice(out_faces, count, "out_faces")?;
            let uvs = output_slice(out_uvs, 2 * count, "out_uvs")?;
            let positions = output_slice(out_positions, doubles, "out_positions")?;
            // DVec3 is three f64 in a row (`#[repr(C)]`, alignment of f64).
            let positions =
                std::slice::from_raw_parts_mut(positions.as_mut_ptr().cast::<DVec3>(), count);
            surface.closest_points(&queries, faces, uvs, positions)?;
            Ok(())
        })
    }
}

/// Frees a limit surface. NULL is ignored.
///
/// # Safety
/// `surface` is NULL or a surface not yet freed; it is invalid afterwards.
#[no_mangle]
pub unsafe extern "C" fn weft_limit_surface_free(surface: *mut WeftLimitSurface) {
    // SAFETY: `surface` is NULL or a handle from this library not yet
    // freed, as the `# Safety` section above requires.
    unsafe {
        if !surface.is_null() {
            let _ = std::panic::catch_unwind(|| drop(Box::from_raw(surface)));
        }
    }
}
