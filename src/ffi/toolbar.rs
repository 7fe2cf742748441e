//! The rest of Weaverbird's toolbar through the C ABI: linear subdivisions,
//! smoothing, offsets, insets, bevels, dual, edges, reroute and mesh from
//! lines. Each export converts, checks and forwards to `split`, `smooth`,
//! `transform` or `extract`.

use glam::DVec3;

use crate::ffi::boundary::{
    check_room, enum_arg, guard, input_slice, out_param, output_slice, Failure, WeftStatus,
};
use crate::ffi::mesh::{mesh_ref, WeftMesh};
use crate::mesh::topology::Topology;
use crate::toolbar::extract::{self, DualMode};
use crate::toolbar::smooth::{self, HcOptions, NakedEdges, SmoothDirection};
use crate::toolbar::split;
use crate::toolbar::tile::{self, TileFaces, TileFill};
use crate::toolbar::transform::{self, InsetMode, OffsetType};

/// Offset type: each vertex moves by the distance along its vertex normal.
pub const WEFT_OFFSET_DIAGONAL: u32 = 0;
/// Offset type: along the vertex normal by the average of distance / cos of
/// the angle to each face normal.
pub const WEFT_OFFSET_HYPOTENUSE_AVERAGE: u32 = 1;
/// Offset type: to where the moved face planes meet (least squares for more
/// than three faces).
pub const WEFT_OFFSET_PLANES_INTERSECTION: u32 = 2;

/// Inset mode: the distance is a share of the edges, in [0, 0.5).
pub const WEFT_INSET_EDGE_FRACTION: u32 = 0;
/// Inset mode: the distance is a width in model units (parallelogram rule).
pub const WEFT_INSET_PARALLELOGRAM: u32 = 1;

/// Smoothing direction: vertices move freely (the published HC algorithm).
pub const WEFT_SMOOTH_DIRECTION_FREE: u32 = 0;
/// Smoothing direction: each vertex moves only along the line of its
/// original vertex normal, so nothing slides across the surface.
pub const WEFT_SMOOTH_DIRECTION_ALONG_NORMAL: u32 = 1;
/// Smoothing direction: each vertex moves only within the plane through its
/// original position across its original normal (relaxation).
pub const WEFT_SMOOTH_DIRECTION_TANGENTIAL: u32 = 2;

/// Tile fill: the chosen faces stay as they are.
pub const WEFT_TILE_FILL_SKIP: u32 = 0;
/// Tile fill: the most robust triangulation (a quad along its shorter
/// diagonal, larger polygons ear-clipped, right for concave faces).
pub const WEFT_TILE_FILL_BEST: u32 = 1;
/// Tile fill: a centroid and a triangle from it to each edge.
pub const WEFT_TILE_FILL_TRIANGLE_FAN: u32 = 2;
/// Tile fill: triangles all sharing the face's first corner.
pub const WEFT_TILE_FILL_TRIANGLE_HAND: u32 = 3;
/// Tile fill: the quad stitch with each quad cut the same way.
pub const WEFT_TILE_FILL_TRIANGLE_KNIT: u32 = 4;
/// Tile fill: a strip of triangles from the first corner whose diagonals
/// zigzag.
pub const WEFT_TILE_FILL_TRIANGLE_ZIGZAG: u32 = 5;
/// Tile fill: a strip of quads from the first corner, a triangle last when
/// the corner count is odd.
pub const WEFT_TILE_FILL_QUAD_STITCH: u32 = 6;
/// Tile fill: a centroid and a quad from it over every two edges.
pub const WEFT_TILE_FILL_QUAD_FAN: u32 = 7;

/// Tile faces: every face is filled.
pub const WEFT_TILE_FACES_ALL: u32 = 0;
/// Tile faces: every face but triangles.
pub const WEFT_TILE_FACES_QUADS_AND_MORE: u32 = 1;
/// Tile faces: pentagons and larger.
pub const WEFT_TILE_FACES_PENTAGONS_AND_MORE: u32 = 2;
/// Tile faces: triangles only (Weaverbird's number 9).
pub const WEFT_TILE_FACES_TRIANGLES: u32 = 9;
/// Tile faces: quads only (Weaverbird's number 16).
pub const WEFT_TILE_FACES_QUADS: u32 = 16;

/// Dual mode: a vertex at each face's centroid.
pub const WEFT_DUAL_VERTEX_AVERAGE: u32 = 0;
/// Dual mode: as VERTEX_AVERAGE, scaled to the input's bounding box size.
pub const WEFT_DUAL_KEEP_SIZE: u32 = 1;

fn naked_edges(value: u32) -> Result<NakedEdges, Failure> {
    crate::ffi::subdivide::naked_edges_arg(value)
}

fn offset_type(value: u32) -> Result<OffsetType, Failure> {
    enum_arg(
        value,
        "offset_type",
        |v| match v {
            WEFT_OFFSET_DIAGONAL => Some(OffsetType::Diagonal),
            WEFT_OFFSET_HYPOTENUSE_AVERAGE => Some(OffsetType::HypotenuseAverage),
            WEFT_OFFSET_PLANES_INTERSECTION => Some(OffsetType::PlanesIntersection),
            _ => None,
        },
        "WEFT_OFFSET_DIAGONAL (0), WEFT_OFFSET_HYPOTENUSE_AVERAGE (1) or WEFT_OFFSET_PLANES_INTERSECTION (2)",
    )
}

fn inset_mode(value: u32) -> Result<InsetMode, Failure> {
    enum_arg(
        value,
        "inset_mode",
        |v| match v {
            WEFT_INSET_EDGE_FRACTION => Some(InsetMode::EdgeFraction),
            WEFT_INSET_PARALLELOGRAM => Some(InsetMode::Parallelogram),
            _ => None,
        },
        "WEFT_INSET_EDGE_FRACTION (0) or WEFT_INSET_PARALLELOGRAM (1)",
    )
}

/// Runs a mesh-to-mesh operation: checks `out` first, borrows the input,
/// writes the result only on success.
unsafe fn mesh_op(
    mesh: *const WeftMesh,
    out_mesh: *mut *mut WeftMesh,
    op: impl FnOnce(&crate::Mesh) -> Result<crate::Mesh, Failure>,
) -> WeftStatus {
    guard(|| {
        let out = out_param(out_mesh, "out_mesh")?;
        let mesh = mesh_ref(mesh, "mesh")?;
        let result = op(mesh)?;
        WeftMesh::write(out, result);
        Ok(())
    })
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
    mesh_op(mesh, out_mesh, |m| Ok(split::split_polygons(m, levels)?))
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
    mesh_op(mesh, out_mesh, |m| Ok(split::split_triangles(m, levels)?))
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
    mesh_op(mesh, out_mesh, |m| {
        Ok(split::constant_quads_split(m, levels)?)
    })
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
    mesh_op(mesh, out_mesh, |m| Ok(split::midedge(m, levels)?))
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
    mesh_op(mesh, out_mesh, |m| {
        Ok(split::inner_polygons(m, levels, pull)?)
    })
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
    mesh_op(mesh, out_mesh, |m| {
        Ok(split::sierpinski_triangles(m, levels)?)
    })
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
    mesh_op(mesh, out_mesh, |m| {
        let naked = self::naked_edges(naked_edges)?;
        Ok(smooth::laplacian(m, iterations, blend, naked)?)
    })
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
    mesh_op(mesh, out_mesh, |m| {
        let naked = self::naked_edges(naked_edges)?;
        Ok(smooth::laplacian_hc(m, iterations, alpha, beta, naked)?)
    })
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

/// Moves every vertex by `distance` along the surface normal (positive:
/// towards the front); the faces are kept (Weaverbird's Offset Mesh).
///
/// `mesh` is the input; it must not be NULL.
/// `distance` is the offset, finite, in model units.
/// `offset_type` is one of the WEFT_OFFSET_* values.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for a non-finite distance or an
/// unknown offset type.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_offset_mesh(
    mesh: *const WeftMesh,
    distance: f64,
    offset_type: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    mesh_op(mesh, out_mesh, |m| {
        let kind = self::offset_type(offset_type)?;
        Ok(transform::offset(m, distance, kind)?)
    })
}

/// Makes a solid of a surface: the input, its offset by `distance`, and a
/// quad along every naked edge joining them, wound to face outwards
/// (Weaverbird's Mesh Thicken). Vertex `v`'s offset is vertex
/// `vertex_count + v`.
///
/// `mesh` is the input; it must not be NULL.
/// `distance` is the thickness, finite, in model units (its sign says on
/// which side the offset lies).
/// `offset_type` is one of the WEFT_OFFSET_* values.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for a non-finite distance or an
/// unknown offset type, WEFT_STATUS_RESULT_TOO_LARGE past the size cap.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_thicken_mesh(
    mesh: *const WeftMesh,
    distance: f64,
    offset_type: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    mesh_op(mesh, out_mesh, |m| {
        let kind = self::offset_type(offset_type)?;
        Ok(transform::thicken(m, distance, kind)?)
    })
}

/// Insets each face and keeps both the frame of quads and the inner face
/// (Weaverbird's Mesh Window).
///
/// `mesh` is the input; it must not be NULL.
/// `distances` holds `distance_count` values: 1 for every face, or one per
/// face; it must not be NULL.
/// `inset_mode` is one of the WEFT_INSET_* values: with EDGE_FRACTION the
/// distances are shares of the edges in [0, 0.5), with PARALLELOGRAM
/// widths in model units, at least 0.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT when `distance_count` is neither
/// 1 nor the face count (naming both), or a distance is out of range.
///
/// # Safety
/// `mesh` is NULL or a live handle; `distances` holds `distance_count`
/// doubles; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_mesh_window(
    mesh: *const WeftMesh,
    distances: *const f64,
    distance_count: usize,
    inset_mode: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    mesh_op(mesh, out_mesh, |m| {
        let mode = self::inset_mode(inset_mode)?;
        // The count is checked before the buffer is viewed.
        transform::check_distance_count(distance_count, m.face_count())?;
        let distances = input_slice(distances, distance_count, "distances")?;
        Ok(transform::window(m, distances, mode)?)
    })
}

/// Insets each face and keeps only the frame of quads: each face becomes a
/// ring around a new hole (Weaverbird's Picture Frame).
///
/// `mesh` is the input; it must not be NULL.
/// `distances` holds `distance_count` values: 1 for every face, or one per
/// face; it must not be NULL.
/// `inset_mode` is one of the WEFT_INSET_* values, as for
/// `weft_mesh_window`.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT when `distance_count` is neither
/// 1 nor the face count (naming both), or a distance is out of range.
///
/// # Safety
/// `mesh` is NULL or a live handle; `distances` holds `distance_count`
/// doubles; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_picture_frame(
    mesh: *const WeftMesh,
    distances: *const f64,
    distance_count: usize,
    inset_mode: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    mesh_op(mesh, out_mesh, |m| {
        let mode = self::inset_mode(inset_mode)?;
        // The count is checked before the buffer is viewed.
        transform::check_distance_count(distance_count, m.face_count())?;
        let distances = input_slice(distances, distance_count, "distances")?;
        Ok(transform::picture_frame(m, distances, mode)?)
    })
}

/// Cuts each quad into 3 × 3 quads and removes the middle one, `levels`
/// times (Weaverbird's Sierpinski Carpet).
///
/// `mesh` is the input, a quad mesh; it must not be NULL.
/// `levels` is the number of steps, 0 to 20.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT naming the first face that is
/// not a quad or for more than 20 levels, WEFT_STATUS_RESULT_TOO_LARGE past
/// the size cap.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_sierpinski_carpet(
    mesh: *const WeftMesh,
    levels: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    mesh_op(mesh, out_mesh, |m| {
        Ok(transform::sierpinski_carpet(m, levels)?)
    })
}

/// Bevels every edge: faces shrink towards their centroids by `fraction`,
/// each edge between two faces becomes a quad and each interior vertex a
/// face (Conway's expansion: a cube gives a rhombicuboctahedron).
///
/// `mesh` is the input; it must not be NULL.
/// `fraction` is strictly between 0 and 1.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for a fraction out of range.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_bevel_edges(
    mesh: *const WeftMesh,
    fraction: f64,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    mesh_op(mesh, out_mesh, |m| Ok(transform::bevel_edges(m, fraction)?))
}

/// Cuts every vertex off at `fraction` of each edge's length, adding a face
/// per vertex (Conway's truncation: a cube gives 6 octagons and 8
/// triangles); boundary vertices are kept so the outline stays.
///
/// `mesh` is the input; it must not be NULL.
/// `fraction` is strictly between 0 and 0.5.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for a fraction out of range.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_bevel_vertices(
    mesh: *const WeftMesh,
    fraction: f64,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    mesh_op(mesh, out_mesh, |m| {
        Ok(transform::bevel_vertices(m, fraction)?)
    })
}

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
    guard(|| {
        let out = out_param(out_count, "out_count")?;
        let mesh = mesh_ref(mesh, "mesh")?;
        *out = Topology::new(mesh).edge_count();
        Ok(())
    })
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
    guard(|| {
        let mesh = mesh_ref(mesh, "mesh")?;
        let edges = extract::mesh_edges(mesh);
        check_room("out_pairs", out_len, 2 * edges.len())?;
        let out = output_slice(out_pairs, 2 * edges.len(), "out_pairs")?;
        out.copy_from_slice(edges.as_flattened());
        Ok(())
    })
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
    mesh_op(mesh, out_mesh, |m| Ok(extract::reroute_faces(m, shift)))
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
    guard(|| {
        let out = out_param(out_mesh, "out_mesh")?;
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
        WeftMesh::write(out, mesh);
        Ok(())
    })
}

/// Re-fills the chosen faces of a mesh by a pattern of triangles or quads
/// (Weaverbird's Tile, with its numbers for both choices). Every pattern
/// keeps each face's outline and winding and the input's vertices (their
/// indices too), so seams stay welded and a closed mesh stays closed; the
/// fans' centroids follow the input's vertices, one per filled face.
///
/// `mesh` is the input; it must not be NULL.
/// `fill` is one of the WEFT_TILE_FILL_* values.
/// `faces` is one of the WEFT_TILE_FACES_* values; the other faces are kept.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_INVALID_ARGUMENT for an unknown fill or faces
/// value, WEFT_STATUS_RESULT_TOO_LARGE past the size cap.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_tile(
    mesh: *const WeftMesh,
    fill: u32,
    faces: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    mesh_op(mesh, out_mesh, |m| {
        let fill = enum_arg(
            fill,
            "fill",
            TileFill::from_number,
            "a WEFT_TILE_FILL_* value, 0 to 7",
        )?;
        let faces = enum_arg(
            faces,
            "faces",
            TileFaces::from_number,
            "WEFT_TILE_FACES_ALL (0), _QUADS_AND_MORE (1), _PENTAGONS_AND_MORE (2), _TRIANGLES (9) or _QUADS (16)",
        )?;
        Ok(tile::tile(m, fill, faces)?)
    })
}
