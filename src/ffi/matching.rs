//! Points and lines matched to a mesh's vertices and edges: how a host turns
//! picked points and drawn lines into the vertex indices that corners and
//! creases are given by. The search is the core's (`weld`); these exports
//! only check and convert.

use glam::DVec3;

use crate::ffi::boundary::{guard, input_slice, output_slice, points_arg, Failure, WeftStatus};
use crate::ffi::mesh::{mesh_ref, WeftMesh};
use crate::mend::matching;

/// Reads `count` lines of six doubles (start x, y, z, end x, y, z), naming
/// the first end point that is not finite.
///
/// # Safety
/// `lines` is NULL or holds `6 * count` doubles.
unsafe fn lines_arg(lines: *const f64, count: usize) -> Result<Vec<[DVec3; 2]>, Failure> {
    // SAFETY: `lines` is as this function's `# Safety` section
    // requires, which its callers promise.
    unsafe {
        let length = count.checked_mul(6).ok_or_else(|| {
            Failure::new(
                WeftStatus::InputTooLarge,
                format!("line_count {count} is larger than memory can hold"),
            )
        })?;
        let flat = input_slice(lines, length, "lines")?;
        let mut out = Vec::new();
        out.try_reserve_exact(count).map_err(|_| {
            Failure::new(
                WeftStatus::OutOfMemory,
                format!("could not copy the {count} lines"),
            )
        })?;
        for (i, c) in flat.chunks_exact(6).enumerate() {
            let ends = [DVec3::new(c[0], c[1], c[2]), DVec3::new(c[3], c[4], c[5])];
            for (end, p) in ["start", "end"].iter().zip(ends) {
                if !p.is_finite() {
                    return Err(Failure::new(
                        WeftStatus::NonFiniteCoordinate,
                        format!(
                            "lines: the {end} of line {i} has a non-finite coordinate ({}, {}, {})",
                            p.x, p.y, p.z
                        ),
                    ));
                }
            }
            out.push(ends);
        }
        Ok(out)
    }
}

/// Finds, for each point, the nearest vertex of the mesh within a tolerance
/// (the lower index when two are equally near), through the spatial hash
/// that `weft_weld` uses.
///
/// `mesh` must not be NULL.
/// `points` holds `point_count` points of three doubles (x, y, z); it may be
/// NULL only when `point_count` is 0.
/// `tolerance` is the largest distance from a point to its vertex, finite
/// and at least 0.
/// `out_vertices` must have room for `point_count` values and receives one
/// vertex index per point on success; it may be NULL only when
/// `point_count` is 0. Nothing is written on failure.
///
/// Fails with WEFT_STATUS_NULL_POINTER, WEFT_STATUS_NON_FINITE_COORDINATE
/// (naming the point), WEFT_STATUS_INVALID_ARGUMENT for a negative, NaN or
/// infinite tolerance or for a point with no vertex within reach (naming
/// the point's index, its coordinates and the tolerance), or
/// WEFT_STATUS_OUT_OF_MEMORY.
///
/// # Safety
/// `mesh` is NULL or a live handle; `points` is NULL or holds
/// `3 * point_count` doubles; `out_vertices` is NULL or holds `point_count`
/// writable values.
#[no_mangle]
pub unsafe extern "C" fn weft_match_points_to_vertices(
    mesh: *const WeftMesh,
    point_count: usize,
    points: *const f64,
    tolerance: f64,
    out_vertices: *mut u32,
) -> WeftStatus {
    // SAFETY: `mesh`, `points` and `out_vertices` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let mesh = mesh_ref(mesh, "mesh")?;
            let points = points_arg(points, point_count, "points")?;
            let out = output_slice(out_vertices, point_count, "out_vertices")?;
            let vertices = matching::match_points_to_vertices(mesh, &points, tolerance)?;
            out.copy_from_slice(&vertices);
            Ok(())
        })
    }
}

/// Finds, for each line, the edge of the mesh whose end points lie within a
/// tolerance of the line's, in either direction. When several vertices are
/// within reach of an end, the pair that is an edge wins, the nearest (the
/// smallest sum of the two distances) first.
///
/// `mesh` must not be NULL.
/// `lines` holds `line_count` lines of six doubles (start x, y, z, end x,
/// y, z); it may be NULL only when `line_count` is 0.
/// `tolerance` is the largest distance from a line's end to its vertex,
/// finite and at least 0.
/// `out_vertex_pairs` must have room for `2 * line_count` values and
/// receives, on success, the two vertex indices of each line's edge in the
/// line's direction (the vertex at its start first); it may be NULL only
/// when `line_count` is 0. Nothing is written on failure.
///
/// Fails with WEFT_STATUS_NULL_POINTER, WEFT_STATUS_NON_FINITE_COORDINATE
/// (naming the line), WEFT_STATUS_INVALID_ARGUMENT for a negative, NaN or
/// infinite tolerance or for a line that matches no edge (naming the line's
/// index, its end points, the tolerance and which end found no vertex), or
/// WEFT_STATUS_OUT_OF_MEMORY.
///
/// # Safety
/// `mesh` is NULL or a live handle; `lines` is NULL or holds
/// `6 * line_count` doubles; `out_vertex_pairs` is NULL or holds
/// `2 * line_count` writable values.
#[no_mangle]
pub unsafe extern "C" fn weft_match_lines_to_edges(
    mesh: *const WeftMesh,
    line_count: usize,
    lines: *const f64,
    tolerance: f64,
    out_vertex_pairs: *mut u32,
) -> WeftStatus {
    // SAFETY: `mesh`, `lines` and `out_vertex_pairs` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let mesh = mesh_ref(mesh, "mesh")?;
            let lines = lines_arg(lines, line_count)?;
            // `lines_arg` has checked that 6 * line_count fits, so 2 * line_count does.
            let out = output_slice(out_vertex_pairs, 2 * line_count, "out_vertex_pairs")?;
            let pairs = matching::match_lines_to_edges(mesh, &lines, tolerance)?;
            for (slot, pair) in out.chunks_exact_mut(2).zip(pairs) {
                slot.copy_from_slice(&pair);
            }
            Ok(())
        })
    }
}
