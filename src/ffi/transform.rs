//! Weaverbird's transforms through the C ABI: offsets, thickening, windows,
//! picture frames, the Sierpinski carpet, bevels and tiles. Each export
//! converts, checks and forwards to `transform` or `tile`.

use crate::error::Error;
use crate::ffi::boundary::{enum_arg, forward_mesh_op, input_slice, mesh_op, Failure, WeftStatus};
use crate::ffi::mesh::WeftMesh;
use crate::mesh::Mesh;
use crate::toolbar::tile::{self, TileFaces, TileFill};
use crate::toolbar::transform::{self, picture_frame, window, InsetMode, OffsetType};

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

/// The body of the offset and thicken exports: reads the offset type, then
/// runs `op` with it and the distance.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
unsafe fn offset_op(
    mesh: *const WeftMesh,
    out_mesh: *mut *mut WeftMesh,
    distance: f64,
    offset_type: u32,
    op: fn(&Mesh, f64, OffsetType) -> Result<Mesh, Error>,
) -> WeftStatus {
    // SAFETY: `mesh` and `out_mesh` are as this function's `# Safety`
    // section requires, which its callers promise.
    unsafe {
        mesh_op(mesh, out_mesh, |m| {
            let kind = self::offset_type(offset_type)?;
            Ok(op(m, distance, kind)?)
        })
    }
}

/// The arguments of the window and picture-frame exports: the inset mode
/// and the distances (one, or one per face of `mesh`).
///
/// # Safety
/// `distances` holds `distance_count` doubles (or is NULL with 0).
unsafe fn inset_args<'a>(
    mesh: &Mesh,
    distances: *const f64,
    distance_count: usize,
    inset_mode: u32,
) -> Result<(&'a [f64], InsetMode), Failure> {
    let mode = self::inset_mode(inset_mode)?;
    // The count is checked before the buffer is viewed.
    transform::check_distance_count(distance_count, mesh.face_count())?;
    // SAFETY: `distances` holds `distance_count` doubles, as the caller promises.
    let distances = unsafe { input_slice(distances, distance_count, "distances") }?;
    Ok((distances, mode))
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
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { offset_op(mesh, out_mesh, distance, offset_type, transform::offset) }
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
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { offset_op(mesh, out_mesh, distance, offset_type, transform::thicken) }
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
    // SAFETY: `mesh`, `distances` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        mesh_op(mesh, out_mesh, |m| {
            let (distances, mode) = inset_args(m, distances, distance_count, inset_mode)?;
            Ok(window(m, distances, mode)?)
        })
    }
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
    // SAFETY: `mesh`, `distances` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        mesh_op(mesh, out_mesh, |m| {
            let (distances, mode) = inset_args(m, distances, distance_count, inset_mode)?;
            Ok(picture_frame(m, distances, mode)?)
        })
    }
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
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { forward_mesh_op(mesh, out_mesh, |m| transform::sierpinski_carpet(m, levels)) }
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
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { forward_mesh_op(mesh, out_mesh, |m| transform::bevel_edges(m, fraction)) }
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
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe { forward_mesh_op(mesh, out_mesh, |m| transform::bevel_vertices(m, fraction)) }
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
    // SAFETY: `mesh` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        mesh_op(mesh, out_mesh, |m| {
            let fill = enum_arg(
                fill,
                "fill",
                |v| match v {
                    WEFT_TILE_FILL_SKIP => Some(TileFill::Skip),
                    WEFT_TILE_FILL_BEST => Some(TileFill::Best),
                    WEFT_TILE_FILL_TRIANGLE_FAN => Some(TileFill::TriangleFan),
                    WEFT_TILE_FILL_TRIANGLE_HAND => Some(TileFill::TriangleHand),
                    WEFT_TILE_FILL_TRIANGLE_KNIT => Some(TileFill::TriangleKnit),
                    WEFT_TILE_FILL_TRIANGLE_ZIGZAG => Some(TileFill::TriangleZigzag),
                    WEFT_TILE_FILL_QUAD_STITCH => Some(TileFill::QuadStitch),
                    WEFT_TILE_FILL_QUAD_FAN => Some(TileFill::QuadFan),
                    _ => None,
                },
                "a WEFT_TILE_FILL_* value, 0 to 7",
            )?;
            let faces = enum_arg(
                faces,
                "faces",
                |v| match v {
                WEFT_TILE_FACES_ALL => Some(TileFaces::All),
                WEFT_TILE_FACES_QUADS_AND_MORE => Some(TileFaces::QuadsAndMore),
                WEFT_TILE_FACES_PENTAGONS_AND_MORE => Some(TileFaces::PentagonsAndMore),
                WEFT_TILE_FACES_TRIANGLES => Some(TileFaces::Triangles),
                WEFT_TILE_FACES_QUADS => Some(TileFaces::Quads),
                _ => None,
            },
                "WEFT_TILE_FACES_ALL (0), _QUADS_AND_MORE (1), _PENTAGONS_AND_MORE (2), _TRIANGLES (9) or _QUADS (16)",
            )?;
            Ok(tile::tile(m, fill, faces)?)
        })
    }
}
