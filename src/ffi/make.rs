//! Making meshes through the C ABI: Delaunay, Voronoi cells, mesh from a
//! grid of points, stellate, primitives.
//!
//! Point lists cross as flat `x, y, z` doubles. Voronoi cells come back in a
//! `WeftCells` handle (cells as per-cell corner counts plus flat corners),
//! read through accessors or copied into caller buffers, and freed with
//! `weft_cells_free`.

use glam::DVec3;

use crate::ffi::boundary::{
    check_room, enum_arg, guard, input_slice, make_mesh, mesh_op, out_param, output_slice,
    point_count_arg, points_arg, required, Failure, WeftStatus,
};
use crate::ffi::mesh::WeftMesh;
use crate::make::delaunay::delaunay;
use crate::make::grid::{check_grid_counts, mesh_from_grid};
use crate::make::plane::Plane;
use crate::make::primitives::{box_grid, plane_grid, platonic, sided, uv_sphere, Platonic, Sided};
use crate::make::stellate::{check_height_count, stellate, Heights};
use crate::make::voronoi::{cells_to_mesh, voronoi};

/// A plane for `weft_delaunay` and `weft_voronoi`: an origin and two axes.
/// The axes need not be unit length or orthogonal (they are
/// orthonormalised, keeping the x axis's direction); the normal, the front
/// side, is `x_axis × y_axis`.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct WeftPlane {
    /// A point of the plane.
    pub origin: [f64; 3],
    /// The plane's x direction; must not be zero.
    pub x_axis: [f64; 3],
    /// The plane's y direction; must not be zero or parallel to `x_axis`.
    pub y_axis: [f64; 3],
}

/// Platonic solid for `weft_platonic`: the tetrahedron (4 triangles).
pub const WEFT_PLATONIC_TETRAHEDRON: u32 = 0;
/// Platonic solid for `weft_platonic`: the cube (6 quads).
pub const WEFT_PLATONIC_HEXAHEDRON: u32 = 1;
/// Platonic solid for `weft_platonic`: the octahedron (8 triangles).
pub const WEFT_PLATONIC_OCTAHEDRON: u32 = 2;
/// Platonic solid for `weft_platonic`: the dodecahedron (12 pentagons).
pub const WEFT_PLATONIC_DODECAHEDRON: u32 = 3;
/// Platonic solid for `weft_platonic`: the icosahedron (20 triangles).
pub const WEFT_PLATONIC_ICOSAHEDRON: u32 = 4;

/// Solid for `weft_sided_solid`: two n-gons joined by n quads.
pub const WEFT_SIDED_PRISM: u32 = 0;
/// Solid for `weft_sided_solid`: two n-gons, one turned by half a side,
/// joined by 2n triangles.
pub const WEFT_SIDED_ANTIPRISM: u32 = 1;
/// Solid for `weft_sided_solid`: an n-gon base and n triangles to the apex.
pub const WEFT_SIDED_PYRAMID: u32 = 2;
/// Solid for `weft_sided_solid`: two pyramids base to base (2n triangles).
pub const WEFT_SIDED_DIPYRAMID: u32 = 3;

/// Voronoi cells made by `weft_voronoi`: one polygon per input point, an
/// empty one for a point outside the boundary or repeating an earlier point.
/// Free it with `weft_cells_free`.
pub struct WeftCells {
    sizes: Vec<u32>,
    corners: Vec<DVec3>,
    cells: Vec<Vec<DVec3>>,
}

/// The plane behind a pointer; NULL is the world XY plane.
///
/// # Safety
/// `plane` is NULL or points to a readable `WeftPlane`.
unsafe fn plane_arg(plane: *const WeftPlane) -> Result<Plane, Failure> {
    // SAFETY: `plane` is as this function's `# Safety` section
    // requires, which its callers promise.
    unsafe {
        match plane.as_ref() {
            None => Ok(Plane::xy()),
            Some(p) => Ok(Plane::new(
                DVec3::from_array(p.origin),
                DVec3::from_array(p.x_axis),
                DVec3::from_array(p.y_axis),
            )?),
        }
    }
}

/// Triangulates points by the Delaunay criterion of their projections onto
/// a plane; the mesh's vertices are the original 3-D points, its triangles
/// front-facing along the plane's normal.
///
/// Points whose projections coincide are merged: the first is kept, so the
/// mesh's vertices are the distinct points in input order.
///
/// `points` holds `3 * point_count` doubles; it may be NULL only when
/// `point_count` is 0 (which then fails as too few points).
/// `plane` may be NULL for the world XY plane.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`); it must not be NULL.
/// `out_merged` receives the number of points merged into an earlier one;
/// it may be NULL.
///
/// Fails with WEFT_STATUS_DEGENERATE_INPUT for fewer than 3 distinct points,
/// all collinear points or a degenerate plane, and with
/// WEFT_STATUS_NON_FINITE_COORDINATE naming the point with a NaN or infinite
/// coordinate. More than 2^31 − 1 points fail with
/// WEFT_STATUS_INPUT_TOO_LARGE before the buffer is read; more than a sixth
/// of that (up to two triangles per point must fit the cap) with
/// WEFT_STATUS_RESULT_TOO_LARGE.
///
/// # Safety
/// `points` holds the doubles stated; `plane` is NULL or readable;
/// `out_mesh` and a non-NULL `out_merged` are writable.
#[no_mangle]
pub unsafe extern "C" fn weft_delaunay(
    points: *const f64,
    point_count: usize,
    plane: *const WeftPlane,
    out_mesh: *mut *mut WeftMesh,
    out_merged: *mut usize,
) -> WeftStatus {
    // SAFETY: `points`, `plane`, `out_mesh` and `out_merged` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        make_mesh(out_mesh, || {
            let points = points_arg(points, point_count, "points")?;
            let plane = plane_arg(plane)?;
            let (mesh, report) = delaunay(&points, &plane)?;
            if let Some(merged) = out_merged.as_mut() {
                *merged = report.merged_duplicates;
            }
            Ok(mesh)
        })
    }
}

/// Computes the Voronoi cell of each point on a plane, clipped to a boundary
/// polygon and, when `radius` is positive, to the 64-gon inscribed in the
/// circle of that radius around the point.
///
/// Cells lie in the plane, counter-clockwise seen from its normal, without
/// a repeated closing corner. A point outside the boundary, or repeating an
/// earlier point's projection, gets an empty cell (size 0). With a concave
/// boundary, a cell that meets it in several pieces keeps the piece holding
/// its point.
///
/// `points` holds `3 * point_count` doubles; it may be NULL only when
/// `point_count` is 0.
/// `plane` may be NULL for the world XY plane.
/// `boundary` holds `3 * boundary_count` doubles, the corners of a simple
/// polygon (convex or not, either winding), projected onto the plane; with
/// `boundary_count` 0 (and `boundary` NULL or not) the boundary is the
/// points' bounding rectangle on the plane grown by 10 % of its larger side
/// on every side.
/// `radius` 0 means no circle; otherwise it must be positive and finite.
/// `out_cells` receives the cells on success (free them with
/// `weft_cells_free`); it must not be NULL.
///
/// Fails with WEFT_STATUS_NON_FINITE_COORDINATE naming a point or boundary
/// corner, WEFT_STATUS_INVALID_ARGUMENT for a bad radius or a boundary that
/// crosses itself or has fewer than 3 corners, WEFT_STATUS_DEGENERATE_INPUT
/// for a degenerate plane or a boundary without area. More than 2^31 − 1
/// points or boundary corners fail with WEFT_STATUS_INPUT_TOO_LARGE before
/// the buffers are read.
///
/// # Safety
/// Each non-NULL buffer holds the doubles stated; `plane` is NULL or
/// readable; `out_cells` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_voronoi(
    points: *const f64,
    point_count: usize,
    plane: *const WeftPlane,
    boundary: *const f64,
    boundary_count: usize,
    radius: f64,
    out_cells: *mut *mut WeftCells,
) -> WeftStatus {
    // SAFETY: `points`, `plane`, `boundary` and `out_cells` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let out = out_param(out_cells, "out_cells")?;
            let points = points_arg(points, point_count, "points")?;
            let boundary = points_arg(boundary, boundary_count, "boundary")?;
            let plane = plane_arg(plane)?;
            let radius = if radius == 0.0 { None } else { Some(radius) };
            let boundary = (!boundary.is_empty()).then_some(&boundary[..]);
            let cells = voronoi(&points, &plane, boundary, radius)?;
            let sizes = cells.iter().map(|c| c.len() as u32).collect();
            let corners = cells.iter().flatten().copied().collect();
            *out = Box::into_raw(Box::new(WeftCells {
                sizes,
                corners,
                cells,
            }));
            Ok(())
        })
    }
}

/// Returns the number of cells (the number of input points), or 0 when
/// `cells` is NULL.
///
/// # Safety
/// `cells` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn weft_cells_count(cells: *const WeftCells) -> usize {
    // SAFETY: `cells` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe { cells.as_ref().map_or(0, |c| c.sizes.len()) }
}

/// Returns the number of corners of all cells together, or 0 when `cells`
/// is NULL.
///
/// # Safety
/// `cells` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn weft_cells_corner_count(cells: *const WeftCells) -> usize {
    // SAFETY: `cells` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe { cells.as_ref().map_or(0, |c| c.corners.len()) }
}

/// Returns the number of corners of each cell (`weft_cells_count` values,
/// 0 for an empty cell), or NULL when `cells` is NULL or holds no cells.
///
/// The pointer is owned by the handle and valid until it is freed.
///
/// # Safety
/// `cells` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn weft_cells_sizes(cells: *const WeftCells) -> *const u32 {
    // SAFETY: `cells` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe {
        match cells.as_ref() {
            Some(c) if !c.sizes.is_empty() => c.sizes.as_ptr(),
            _ => std::ptr::null(),
        }
    }
}

/// Returns the corners of all cells, one cell after another,
/// `3 * weft_cells_corner_count` doubles, or NULL when `cells` is NULL or
/// every cell is empty.
///
/// The pointer is owned by the handle and valid until it is freed.
///
/// # Safety
/// `cells` is NULL or a live handle.
#[no_mangle]
pub unsafe extern "C" fn weft_cells_corners(cells: *const WeftCells) -> *const f64 {
    // SAFETY: `cells` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe {
        match cells.as_ref() {
            Some(c) if !c.corners.is_empty() => c.corners.as_ptr().cast(),
            _ => std::ptr::null(),
        }
    }
}

/// Copies the cells into caller buffers.
///
/// `cells` must not be NULL.
/// `out_sizes` must have room for `weft_cells_count` values
/// (`sizes_capacity`).
/// `out_corners` must have room for `3 * weft_cells_corner_count` doubles
/// (`corners_capacity`). When either is too small the call fails with
/// WEFT_STATUS_BUFFER_TOO_SMALL and writes nothing.
///
/// # Safety
/// Each buffer points to as many writable values as its capacity says (or
/// is NULL with 0).
#[no_mangle]
pub unsafe extern "C" fn weft_cells_copy(
    cells: *const WeftCells,
    out_sizes: *mut u32,
    sizes_capacity: usize,
    out_corners: *mut f64,
    corners_capacity: usize,
) -> WeftStatus {
    // SAFETY: `cells`, `out_sizes` and `out_corners` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let cells = required(cells, "cells")?;
            check_room("out_sizes", sizes_capacity, cells.sizes.len())?;
            check_room("out_corners", corners_capacity, cells.corners.len() * 3)?;
            let sizes = output_slice(out_sizes, sizes_capacity, "out_sizes")?;
            let corners = output_slice(out_corners, corners_capacity, "out_corners")?;
            sizes[..cells.sizes.len()].copy_from_slice(&cells.sizes);
            for (chunk, p) in corners.chunks_exact_mut(3).zip(&cells.corners) {
                chunk.copy_from_slice(&p.to_array());
            }
            Ok(())
        })
    }
}

/// Makes a mesh with one n-gon face per non-empty cell, in cell order; the
/// cells share no vertices (weld the mesh to join them).
///
/// `cells` and `out_mesh` must not be NULL; the new mesh is written on
/// success only (free it with `weft_mesh_free`).
///
/// # Safety
/// `cells` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_cells_to_mesh(
    cells: *const WeftCells,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `cells` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        make_mesh(out_mesh, || {
            let cells = required(cells, "cells")?;
            Ok(cells_to_mesh(&cells.cells)?)
        })
    }
}

/// Frees cells made by `weft_voronoi`. NULL is ignored.
///
/// # Safety
/// `cells` is NULL or a handle from this library not yet freed; after the
/// call it and every pointer obtained from it are invalid.
#[no_mangle]
pub unsafe extern "C" fn weft_cells_free(cells: *mut WeftCells) {
    // SAFETY: `cells` is NULL or a handle from this library not yet
    // freed, as the `# Safety` section above requires.
    unsafe {
        if !cells.is_null() {
            let _ = std::panic::catch_unwind(|| drop(Box::from_raw(cells)));
        }
    }
}

/// Connects a `u_count × v_count` grid of points (a sampled surface) into a
/// quad mesh, or triangles.
///
/// Point `(u, v)` is at `points[3 * (v * u_count + u)]`: u runs fastest.
/// The quad at `(u, v)` runs `(u, v), (u+1, v), (u+1, v+1), (u, v+1)`, so
/// faces front the side `∂/∂u × ∂/∂v` points to; faces come row by row.
///
/// `points` holds `3 * point_count` doubles and `point_count` must equal
/// `u_count * v_count`, each count at least 2.
/// `closed_u` / `closed_v` wrap that direction around: the last point of a
/// row connects to the first, which is not repeated (at least 3 points
/// needed in a closed direction).
/// `triangulate` splits each quad along its shorter diagonal.
/// `out_mesh` receives the new mesh on success; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT naming both counts when they do
/// not match, and with WEFT_STATUS_NON_FINITE_COORDINATE naming a point.
/// The counts are checked before `points` is read; more than 2^31 − 1
/// points fail with WEFT_STATUS_INPUT_TOO_LARGE.
///
/// # Safety
/// `points` holds the doubles stated; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_from_grid(
    points: *const f64,
    point_count: usize,
    u_count: usize,
    v_count: usize,
    closed_u: bool,
    closed_v: bool,
    triangulate: bool,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `points` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        make_mesh(out_mesh, || {
            // The counts are checked, against the cap and each other, before the buffer is viewed.
            point_count_arg(point_count, "points")?;
            check_grid_counts(point_count, u_count, v_count, closed_u, closed_v)?;
            let points = points_arg(points, point_count, "points")?;
            let mesh = mesh_from_grid(&points, u_count, v_count, closed_u, closed_v, triangulate)?;
            Ok(mesh)
        })
    }
}

/// Raises a pyramid on every face: a new vertex at the face's centroid moved
/// along its normal by the face's height, and a fan of triangles.
///
/// Output order: the input's vertices, then one apex per face (face f's is
/// vertex `vertex_count + f`); face f's fan of triangles is contiguous.
///
/// `mesh` must not be NULL.
/// `heights` holds `height_count` doubles: 1 for one height for every face,
/// or one per face; negative heights point into the face's back side.
/// `out_mesh` receives the new mesh on success; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT when `height_count` is neither 1
/// nor the face count (naming both), or naming the face whose height is not
/// finite.
///
/// # Safety
/// `mesh` is NULL or a live handle; `heights` holds `height_count` doubles;
/// `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_stellate(
    mesh: *const WeftMesh,
    heights: *const f64,
    height_count: usize,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh`, `heights` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        mesh_op(mesh, out_mesh, |mesh| {
            // The count is checked before the buffer is viewed.
            if height_count != 1 {
                check_height_count(height_count, mesh.face_count())?;
            }
            let heights = input_slice(heights, height_count, "heights")?;
            let heights = match heights {
                [one] => Heights::One(*one),
                many => Heights::PerFace(many),
            };
            Ok(stellate(mesh, heights)?)
        })
    }
}

/// Makes a flat rectangle of `size_x × size_y` on the XY plane, centred on
/// the origin and facing +z, of `u_count × v_count` quads.
///
/// Sizes must be positive and finite, counts at least 1. Counts whose
/// result would pass 2^31 − 1 face corners (any count near SIZE_MAX
/// included) fail with WEFT_STATUS_RESULT_TOO_LARGE before anything is
/// allocated.
/// `out_mesh` receives the new mesh on success; it must not be NULL.
///
/// # Safety
/// `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_plane_grid(
    size_x: f64,
    size_y: f64,
    u_count: usize,
    v_count: usize,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `out_mesh` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe {
        make_mesh(out_mesh, || {
            Ok(plane_grid(size_x, size_y, u_count, v_count)?)
        })
    }
}

/// Makes a closed, welded box centred on the origin whose sides are divided
/// into quads: `u_count` along x, `v_count` along y, `w_count` along z.
///
/// Sizes must be positive and finite, counts at least 1. Counts whose
/// result would pass 2^31 − 1 face corners (any count near SIZE_MAX
/// included) fail with WEFT_STATUS_RESULT_TOO_LARGE before anything is
/// allocated.
/// `out_mesh` receives the new mesh on success; it must not be NULL.
///
/// # Safety
/// `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_box(
    size_x: f64,
    size_y: f64,
    size_z: f64,
    u_count: usize,
    v_count: usize,
    w_count: usize,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `out_mesh` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe {
        make_mesh(out_mesh, || {
            let size = DVec3::new(size_x, size_y, size_z);
            Ok(box_grid(size, u_count, v_count, w_count)?)
        })
    }
}

/// Makes a sphere of `radius` centred on the origin with `u_count` segments
/// around the z axis (at least 3) and `v_count` from pole to pole (at least
/// 2); each pole is one vertex with a fan of triangles, the rest are quads.
/// Counts whose result would pass 2^31 − 1 face corners (any count
/// near SIZE_MAX included) fail with WEFT_STATUS_RESULT_TOO_LARGE before
/// anything is allocated.
///
/// `out_mesh` receives the new mesh on success; it must not be NULL.
///
/// # Safety
/// `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_uv_sphere(
    radius: f64,
    u_count: usize,
    v_count: usize,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `out_mesh` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe { make_mesh(out_mesh, || Ok(uv_sphere(radius, u_count, v_count)?)) }
}

fn platonic_kind(value: u32) -> Result<Platonic, Failure> {
    enum_arg(
        value,
        "kind",
        |k| match k {
            WEFT_PLATONIC_TETRAHEDRON => Some(Platonic::Tetrahedron),
            WEFT_PLATONIC_HEXAHEDRON => Some(Platonic::Hexahedron),
            WEFT_PLATONIC_OCTAHEDRON => Some(Platonic::Octahedron),
            WEFT_PLATONIC_DODECAHEDRON => Some(Platonic::Dodecahedron),
            WEFT_PLATONIC_ICOSAHEDRON => Some(Platonic::Icosahedron),
            _ => None,
        },
        "a WEFT_PLATONIC_* value (0 to 4)",
    )
}

/// Makes a platonic solid centred on the origin with its vertices on the
/// sphere of `radius`.
///
/// `kind` is one of the WEFT_PLATONIC_* values; another value fails with
/// WEFT_STATUS_INVALID_ARGUMENT.
/// `radius` must be positive and finite.
/// `out_mesh` receives the new mesh on success; it must not be NULL.
///
/// # Safety
/// `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_platonic(
    kind: u32,
    radius: f64,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `out_mesh` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe { make_mesh(out_mesh, || Ok(platonic(platonic_kind(kind)?, radius)?)) }
}

fn sided_kind(value: u32) -> Result<Sided, Failure> {
    enum_arg(
        value,
        "kind",
        |k| match k {
            WEFT_SIDED_PRISM => Some(Sided::Prism),
            WEFT_SIDED_ANTIPRISM => Some(Sided::Antiprism),
            WEFT_SIDED_PYRAMID => Some(Sided::Pyramid),
            WEFT_SIDED_DIPYRAMID => Some(Sided::Dipyramid),
            _ => None,
        },
        "a WEFT_SIDED_* value (0 to 3)",
    )
}

/// Makes a prism, antiprism, pyramid or dipyramid on a regular n-gon of
/// circumradius `radius` about the z axis, `height` tall and centred on the
/// origin.
///
/// `kind` is one of the WEFT_SIDED_* values; another value fails with
/// WEFT_STATUS_INVALID_ARGUMENT.
/// `sides` is n, at least 3; a count whose result would pass 2^31 − 1 face
/// corners fails with WEFT_STATUS_RESULT_TOO_LARGE before anything is
/// allocated. `radius` and `height` must be positive and finite.
/// `out_mesh` receives the new mesh on success; it must not be NULL.
///
/// # Safety
/// `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_sided_solid(
    kind: u32,
    sides: usize,
    radius: f64,
    height: f64,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `out_mesh` is as the `# Safety` section above requires;
    // it is checked for NULL before it is used.
    unsafe {
        make_mesh(out_mesh, || {
            Ok(sided(sided_kind(kind)?, sides, radius, height)?)
        })
    }
}
