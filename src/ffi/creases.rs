//! Subdivision with creases, corners, carried data, face-varying values and
//! the limit surface: OpenSubdiv's `TopologyDescriptor` crease and corner
//! arrays beside the mesh, in a `WeftSubdivisionOptions`.

use glam::DVec3;

use crate::ffi::boundary::{
    check_room, enum_arg, guard, input_slice, make_mesh, out_param, output_slice, required,
    Failure, WeftStatus,
};
use crate::ffi::mesh::{mesh_ref, WeftMesh};
use crate::ffi::subdivide::{naked_edges_arg, scheme_arg, write_parents};
use crate::mesh::Mesh;
use crate::subdivide::{
    self, Creasing, FaceVaryingLinear, Scheme, Subdivider, SubdivisionOptions, TriangleRule,
};

/// Semi-sharp creases lose one level of sharpness per level (OpenSubdiv CREASE_UNIFORM).
pub const WEFT_CREASING_UNIFORM: u32 = 0;
/// Semi-sharp creases are averaged with their neighbours first (OpenSubdiv CREASE_CHAIKIN).
pub const WEFT_CREASING_CHAIKIN: u32 = 1;
/// Face-varying values are smooth everywhere (OpenSubdiv FVAR_LINEAR_NONE).
pub const WEFT_FACE_VARYING_SMOOTH: u32 = 0;
/// Face-varying values are linear at their corners only (FVAR_LINEAR_CORNERS_ONLY).
pub const WEFT_FACE_VARYING_CORNERS_ONLY: u32 = 1;
/// As corners only, and sharper at junctions of three or more regions (FVAR_LINEAR_CORNERS_PLUS1).
pub const WEFT_FACE_VARYING_CORNERS_PLUS1: u32 = 2;
/// As corners plus one, and sharper where boundaries meet (FVAR_LINEAR_CORNERS_PLUS2).
pub const WEFT_FACE_VARYING_CORNERS_PLUS2: u32 = 3;
/// Face-varying values are linear along every seam and boundary (FVAR_LINEAR_BOUNDARIES).
pub const WEFT_FACE_VARYING_BOUNDARIES: u32 = 4;
/// Face-varying values are linear everywhere (FVAR_LINEAR_ALL, OpenSubdiv's default).
pub const WEFT_FACE_VARYING_ALL: u32 = 5;
/// The sharpness at and above which a crease or corner never softens.
pub const WEFT_SHARPNESS_INFINITE: f64 = 10.0;
/// Catmull-Clark's own weights at triangles (OpenSubdiv TRI_SUB_CATMARK).
pub const WEFT_TRIANGLES_CATMARK: u32 = 0;
/// "Smooth triangle" weights, which round triangle regions of mixed cages (OpenSubdiv TRI_SUB_SMOOTH).
pub const WEFT_TRIANGLES_SMOOTH: u32 = 1;
/// How many reserved fields end a `WeftSubdivisionOptions`.
pub const WEFT_SUBDIVISION_OPTIONS_RESERVED: usize = 8;

/// What besides the mesh shapes a subdivision: the scheme, the naked-edge
/// mode, the creasing method, OpenSubdiv-style crease, corner and hole
/// arrays, and the triangle weights.
/// Zero-initialise it, then fill what you need: all zeros is Catmull-Clark
/// with fixed naked edges, nothing creased and no hole. Every field's 0 is
/// the default, and so it stays: later versions give the `reserved` fields
/// meanings whose 0 is today's behaviour, so a host that zero-initialises
/// keeps working when it is rebuilt against a newer header. A reserved
/// field that is not 0 is refused (WEFT_STATUS_INVALID_ARGUMENT).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct WeftSubdivisionOptions {
    /// A WEFT_SCHEME_* value.
    pub scheme: u32,
    /// A WEFT_NAKED_EDGES_* value.
    pub naked_edges: u32,
    /// A WEFT_CREASING_* value.
    pub creasing: u32,
    /// Number of creased edges.
    pub crease_count: usize,
    /// `2 * crease_count` vertex indices: the ends of each creased edge, which must be an edge of the mesh; NULL when `crease_count` is 0.
    pub crease_vertex_pairs: *const u32,
    /// `crease_count` sharpness values: 0 or more, WEFT_SHARPNESS_INFINITE or more (or INFINITY) for a hard crease.
    pub crease_sharpness: *const f64,
    /// Number of sharp vertices.
    pub corner_count: usize,
    /// `corner_count` vertex indices; NULL when `corner_count` is 0.
    pub corner_vertices: *const u32,
    /// `corner_count` sharpness values, as for creases.
    pub corner_sharpness: *const f64,
    /// Number of hole faces.
    pub hole_count: usize,
    /// `hole_count` face indices: faces left out of the result (OpenSubdiv's hole tags), whose vertices and edges still shape their neighbours; NULL when `hole_count` is 0.
    pub hole_faces: *const u32,
    /// A WEFT_TRIANGLES_* value: Catmull-Clark's weights at triangles (Loop ignores it).
    pub triangles: u32,
    /// Must be 0 (see above).
    pub reserved_flags: u32,
    /// Must be 0 (see above).
    pub reserved: [usize; WEFT_SUBDIVISION_OPTIONS_RESERVED],
}

/// Reads the options: enumerations checked, arrays copied.
///
/// # Safety
/// `options` is NULL or points to a readable `WeftSubdivisionOptions`
/// whose arrays hold the counts it states.
pub(crate) unsafe fn options_arg(
    options: *const WeftSubdivisionOptions,
) -> Result<(Scheme, SubdivisionOptions), Failure> {
    // SAFETY: `options` is as this function's `# Safety` section
    // requires, which its callers promise.
    unsafe {
        let options = required(options, "options")?;
        let scheme = scheme_arg(options.scheme)?;
        let naked_edges = naked_edges_arg(options.naked_edges)?;
        let creasing = enum_arg(
            options.creasing,
            "creasing",
            |v| match v {
                WEFT_CREASING_UNIFORM => Some(Creasing::Uniform),
                WEFT_CREASING_CHAIKIN => Some(Creasing::Chaikin),
                _ => None,
            },
            "WEFT_CREASING_UNIFORM (0) or WEFT_CREASING_CHAIKIN (1)",
        )?;
        let pair_count = options.crease_count.checked_mul(2).ok_or_else(|| {
            Failure::new(
                WeftStatus::InputTooLarge,
                format!("crease_count {} is too large", options.crease_count),
            )
        })?;
        let pairs = input_slice(
            options.crease_vertex_pairs,
            pair_count,
            "crease_vertex_pairs",
        )?;
        let crease_sharpness = input_slice(
            options.crease_sharpness,
            options.crease_count,
            "crease_sharpness",
        )?;
        let corners = input_slice(
            options.corner_vertices,
            options.corner_count,
            "corner_vertices",
        )?;
        let corner_sharpness = input_slice(
            options.corner_sharpness,
            options.corner_count,
            "corner_sharpness",
        )?;
        let holes = input_slice(options.hole_faces, options.hole_count, "hole_faces")?;
        let triangles = enum_arg(
            options.triangles,
            "triangles",
            |v| match v {
                WEFT_TRIANGLES_CATMARK => Some(TriangleRule::Catmark),
                WEFT_TRIANGLES_SMOOTH => Some(TriangleRule::Smooth),
                _ => None,
            },
            "WEFT_TRIANGLES_CATMARK (0) or WEFT_TRIANGLES_SMOOTH (1)",
        )?;
        if options.reserved_flags != 0 {
            return Err(Failure::invalid_argument(format!(
                "reserved_flags is {}; it must be 0",
                options.reserved_flags
            )));
        }
        if let Some(i) = options.reserved.iter().position(|&r| r != 0) {
            return Err(Failure::invalid_argument(format!(
                "reserved[{i}] is {}; it must be 0",
                options.reserved[i]
            )));
        }
        Ok((
            scheme,
            SubdivisionOptions {
                naked_edges,
                creasing,
                creases: pairs
                    .chunks_exact(2)
                    .zip(crease_sharpness)
                    .map(|(pair, &s)| ([pair[0], pair[1]], s))
                    .collect(),
                corners: corners
                    .iter()
                    .copied()
                    .zip(corner_sharpness.iter().copied())
                    .collect(),
                holes: holes.to_vec(),
                triangles,
            },
        ))
    }
}

/// `query` of `mesh` with the scheme and options `options` gives.
///
/// # Safety
/// `options` as for `options_arg`.
unsafe fn with_options<T>(
    mesh: &Mesh,
    options: *const WeftSubdivisionOptions,
    levels: u32,
    query: fn(&Mesh, Scheme, u32, &SubdivisionOptions) -> crate::Result<T>,
) -> Result<T, Failure> {
    // SAFETY: `options` is as this function's `# Safety` section requires.
    let (scheme, options) = unsafe { options_arg(options)? };
    Ok(query(mesh, scheme, levels, &options)?)
}

fn face_varying_arg(value: u32) -> Result<FaceVaryingLinear, Failure> {
    enum_arg(
        value,
        "face_varying_linear",
        |v| match v {
            WEFT_FACE_VARYING_SMOOTH => Some(FaceVaryingLinear::Smooth),
            WEFT_FACE_VARYING_CORNERS_ONLY => Some(FaceVaryingLinear::CornersOnly),
            WEFT_FACE_VARYING_CORNERS_PLUS1 => Some(FaceVaryingLinear::CornersPlus1),
            WEFT_FACE_VARYING_CORNERS_PLUS2 => Some(FaceVaryingLinear::CornersPlus2),
            WEFT_FACE_VARYING_BOUNDARIES => Some(FaceVaryingLinear::Boundaries),
            WEFT_FACE_VARYING_ALL => Some(FaceVaryingLinear::All),
            _ => None,
        },
        "one of the WEFT_FACE_VARYING_* values (0 to 5)",
    )
}

/// The mesh behind `mesh` and a subdivider of it with `options`.
///
/// # Safety
/// `mesh` is NULL or a live handle that outlives every use of the returned
/// reference (the export's call); `options` as for `options_arg`.
unsafe fn subdivider_arg(
    mesh: *const WeftMesh,
    options: *const WeftSubdivisionOptions,
    levels: u32,
) -> Result<(&'static Mesh, Subdivider), Failure> {
    // SAFETY: `mesh` and `options` are as this function's `# Safety` section
    // requires, which its callers promise.
    unsafe {
        let mesh = mesh_ref(mesh, "mesh")?;
        let (scheme, options) = options_arg(options)?;
        let subdivider = Subdivider::new(mesh, scheme, levels, &options)?;
        Ok((mesh, subdivider))
    }
}

/// Subdivides a mesh `levels` times with the scheme, naked-edge mode,
/// creases and corners of `options`, as OpenSubdiv does with the same
/// `Sdc::Options` and `TopologyDescriptor` arrays. Output order as
/// `weft_catmull_clark` and `weft_loop`.
///
/// `mesh` must not be NULL. `options` must not be NULL; see
/// `WeftSubdivisionOptions`. `levels` is the number of steps; 0 returns a copy.
/// `out_mesh` receives the new mesh on success (free it with
/// `weft_mesh_free`) and is left untouched on failure; it must not be NULL.
///
/// Fails with WEFT_STATUS_NULL_POINTER, WEFT_STATUS_INVALID_ARGUMENT (an
/// unknown enumeration value, a crease pair that is not an edge of the mesh,
/// a corner past the vertex count, a negative or NaN sharpness — the
/// message names which), WEFT_STATUS_NOT_TRIANGLES (Loop),
/// WEFT_STATUS_RESULT_TOO_LARGE or WEFT_STATUS_OUT_OF_MEMORY. Coordinates
/// near the largest double are subdivided at an exactly scaled size, so the
/// rules never overflow; a refined point beyond the largest double (only
/// when the input spans nearly the whole range) is
/// WEFT_STATUS_DEGENERATE_INPUT naming the vertex.
///
/// # Safety
/// `mesh` is NULL or a live handle; `options` is NULL or readable with
/// arrays of the lengths it states; `out_mesh` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_subdivide_ex(
    mesh: *const WeftMesh,
    options: *const WeftSubdivisionOptions,
    levels: u32,
    out_mesh: *mut *mut WeftMesh,
) -> WeftStatus {
    // SAFETY: `mesh`, `options` and `out_mesh` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        make_mesh(out_mesh, || {
            let (_, subdivider) = subdivider_arg(mesh, options, levels)?;
            Ok(subdivider.mesh()?)
        })
    }
}

/// Gives the vertex, face and face-index counts of the mesh `levels` steps
/// of `scheme` make from `mesh` (creases do not change them; holes do: see
/// `weft_subdivision_counts_ex`), without
/// subdividing: the sizes the buffers of `weft_subdivide_vertex_data`,
/// `weft_subdivide_face_varying` and `weft_subdivide_limit` need.
///
/// `mesh` must not be NULL. `scheme` is a WEFT_SCHEME_* value. Each
/// `out_*` receives its count on success; none may be NULL.
///
/// Fails with WEFT_STATUS_NULL_POINTER, WEFT_STATUS_INVALID_ARGUMENT,
/// WEFT_STATUS_NOT_TRIANGLES (Loop) or WEFT_STATUS_RESULT_TOO_LARGE.
///
/// # Safety
/// `mesh` is NULL or a live handle; the `out_*` are NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_subdivision_counts(
    mesh: *const WeftMesh,
    scheme: u32,
    levels: u32,
    out_vertex_count: *mut usize,
    out_face_count: *mut usize,
    out_index_count: *mut usize,
) -> WeftStatus {
    // SAFETY: `mesh` and the `out_*` are as the `# Safety` section above
    // requires.
    unsafe {
        let outs = [out_vertex_count, out_face_count, out_index_count];
        write_counts(mesh, outs, |mesh| {
            Ok(subdivide::refined_counts(
                mesh,
                scheme_arg(scheme)?,
                levels,
            )?)
        })
    }
}

/// The counts exports' shared steps: checks the three outputs and the mesh,
/// then writes the counts `count` finds for the mesh.
///
/// # Safety
/// `mesh` is NULL or a live handle; each of `outs` is NULL or writable.
unsafe fn write_counts(
    mesh: *const WeftMesh,
    outs: [*mut usize; 3],
    count: impl FnOnce(&Mesh) -> Result<subdivide::RefinedCounts, Failure>,
) -> WeftStatus {
    // SAFETY: `mesh` and `outs` are as this function's `# Safety` section
    // requires, which its callers promise; each is checked for NULL first.
    unsafe {
        guard(|| {
            let vertices = out_param(outs[0], "out_vertex_count")?;
            let faces = out_param(outs[1], "out_face_count")?;
            let indices = out_param(outs[2], "out_index_count")?;
            let counts = count(mesh_ref(mesh, "mesh")?)?;
            (*vertices, *faces, *indices) =
                (counts.vertex_count, counts.face_count, counts.index_count);
            Ok(())
        })
    }
}

/// As `weft_subdivision_counts`, for the subdivision `options` describe:
/// holes (and with WEFT_NAKED_EDGES_NONE the faces at the boundary) leave
/// their vertices but no faces, so these are the sizes of
/// `weft_subdivide_ex`'s result and of the buffers of
/// `weft_subdivide_face_varying` with the same options.
///
/// `mesh` and `options` must not be NULL. Each `out_*` receives its count
/// on success; none may be NULL.
///
/// Fails as `weft_subdivision_counts`, and with WEFT_STATUS_INVALID_ARGUMENT
/// for an unknown option value or a hole past the face count.
///
/// # Safety
/// `mesh` is NULL or a live handle; `options` is NULL or readable with
/// arrays of the lengths it states; the `out_*` are NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn weft_subdivision_counts_ex(
    mesh: *const WeftMesh,
    options: *const WeftSubdivisionOptions,
    levels: u32,
    out_vertex_count: *mut usize,
    out_face_count: *mut usize,
    out_index_count: *mut usize,
) -> WeftStatus {
    let outs = [out_vertex_count, out_face_count, out_index_count];
    // SAFETY: `mesh`, `options` and the `out_*` are as the `# Safety` section
    // above requires; `options` is read only once the rest is checked.
    unsafe {
        write_counts(mesh, outs, |mesh| {
            with_options(mesh, options, levels, subdivide::refined_counts_with)
        })
    }
}

/// As `weft_subdivision_parent_faces`, for the subdivision `options`
/// describe: the faces of `weft_subdivide_ex`'s result, without the
/// children of holes. `out_parents` needs room for the face count
/// `weft_subdivision_counts_ex` gives, else the call fails with
/// WEFT_STATUS_BUFFER_TOO_SMALL and writes nothing.
///
/// Fails as `weft_subdivision_counts_ex`, and with WEFT_STATUS_BUFFER_TOO_SMALL.
///
/// # Safety
/// As `weft_subdivision_counts_ex`; `out_parents` is NULL or holds
/// `capacity` writable values.
#[no_mangle]
pub unsafe extern "C" fn weft_subdivision_parent_faces_ex(
    mesh: *const WeftMesh,
    options: *const WeftSubdivisionOptions,
    levels: u32,
    out_parents: *mut u32,
    capacity: usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `options` and `out_parents` are as the `# Safety`
    // section above requires; `options` is read once the mesh is checked.
    unsafe {
        write_parents(mesh, "mesh", (out_parents, capacity), |mesh| {
            with_options(mesh, options, levels, subdivide::parent_faces_with)
        })
    }
}

/// Carries per-vertex data of any width (colours, weights) through the
/// subdivision of `weft_subdivide_ex`: every refined vertex gets the same
/// weighted sum of cage values as its position (OpenSubdiv's
/// `PrimvarRefiner::Interpolate`).
///
/// `mesh` and `options` must not be NULL; `levels` as `weft_subdivide_ex`.
/// `data` holds `width` doubles per cage vertex (`width` ≥ 1), `data_len` in all.
/// `out_data` has room for `capacity` doubles; it needs `width` times the
/// refined vertex count (`weft_subdivision_counts`), else the call fails with
/// WEFT_STATUS_BUFFER_TOO_SMALL and writes nothing.
///
/// Fails as `weft_subdivide_ex`, with WEFT_STATUS_COUNT_MISMATCH when
/// `data_len` is not `width` times the cage's vertex count, and
/// WEFT_STATUS_INVALID_ARGUMENT when `width` is 0 or a value is NaN or
/// infinite (the message names the vertex and component).
///
/// # Safety
/// As `weft_subdivide_ex`; `data` holds `data_len` doubles and `out_data`
/// `capacity` writable doubles (either may be NULL when its length is 0).
#[no_mangle]
pub unsafe extern "C" fn weft_subdivide_vertex_data(
    mesh: *const WeftMesh,
    options: *const WeftSubdivisionOptions,
    levels: u32,
    data: *const f64,
    data_len: usize,
    width: usize,
    out_data: *mut f64,
    capacity: usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `options`, `data` and `out_data` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            // The lengths are checked against the mesh before either buffer is viewed.
            let (mesh, subdivider) = subdivider_arg(mesh, options, levels)?;
            if width == 0 {
                return Err(Failure::invalid_argument(
                    "width is 0; it must be at least 1",
                ));
            }
            if Some(data_len) != mesh.vertex_count().checked_mul(width) {
                return Err(Failure::new(
                    WeftStatus::CountMismatch,
                    format!(
                        "data holds {data_len} doubles but {} vertices of width {width} need {}",
                        mesh.vertex_count(),
                        mesh.vertex_count().saturating_mul(width)
                    ),
                ));
            }
            let needed = subdivider.vertex_count().saturating_mul(width);
            check_room("out_data", capacity, needed)?;
            let data = input_slice(data, data_len, "data")?;
            let out = output_slice(out_data, capacity, "out_data")?;
            subdivider.vertex_data_into(data, width, &mut out[..needed])?;
            Ok(())
        })
    }
}

/// Carries per-face-corner values (UVs) through the subdivision of
/// `weft_subdivide_ex`, face-varying as OpenSubdiv's
/// `PrimvarRefiner::InterpolateFaceVarying`: corners of one vertex that use
/// different values are a seam, and `face_varying_linear` says where values
/// are interpolated linearly.
///
/// `mesh` and `options` must not be NULL; `levels` as `weft_subdivide_ex`.
/// `face_varying_linear` is a WEFT_FACE_VARYING_* value.
/// `values` holds `width` doubles for each of `value_count` values (`width` ≥ 1).
/// `value_indices` holds the value of every face corner of `mesh`, face
/// after face: `index_count` must equal the mesh's face-index count.
/// `out_values` has room for `capacity` doubles; it receives `width` doubles
/// per face corner of the refined mesh, face after face, and needs `width`
/// times the refined face-index count (`weft_subdivision_counts_ex` with the
/// same options: holes have no corners), else the call fails with
/// WEFT_STATUS_BUFFER_TOO_SMALL and writes nothing.
///
/// Fails as `weft_subdivide_ex`, with WEFT_STATUS_COUNT_MISMATCH (lengths),
/// WEFT_STATUS_INDEX_OUT_OF_RANGE (a value index past `value_count`) or
/// WEFT_STATUS_INVALID_ARGUMENT (also for a NaN or infinite value, naming it).
///
/// # Safety
/// As `weft_subdivide_ex`; the buffers hold the elements stated.
#[no_mangle]
pub unsafe extern "C" fn weft_subdivide_face_varying(
    mesh: *const WeftMesh,
    options: *const WeftSubdivisionOptions,
    levels: u32,
    face_varying_linear: u32,
    values: *const f64,
    value_count: usize,
    width: usize,
    value_indices: *const u32,
    index_count: usize,
    out_values: *mut f64,
    capacity: usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `options`, `values`, `value_indices` and `out_values` are as the `# Safety`
    // section above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let linear = face_varying_arg(face_varying_linear)?;
            if width == 0 {
                return Err(Failure::invalid_argument(
                    "width is 0; it must be at least 1",
                ));
            }
            let value_len = value_count.checked_mul(width).ok_or_else(|| {
                Failure::new(
                    WeftStatus::InputTooLarge,
                    "value_count * width is too large",
                )
            })?;
            let (mesh, subdivider) = subdivider_arg(mesh, options, levels)?;
            if index_count != mesh.index_count() {
                return Err(Failure::new(
                    WeftStatus::CountMismatch,
                    format!(
                        "value_indices holds {index_count} indices but the mesh has {} face corners",
                        mesh.index_count()
                    ),
                ));
            }
            let needed = subdivider.face_indices().len().saturating_mul(width);
            check_room("out_values", capacity, needed)?;
            // Only now, with every length checked, are the buffers viewed.
            let values = input_slice(values, value_len, "values")?;
            let indices = input_slice(value_indices, index_count, "value_indices")?;
            let out = output_slice(out_values, capacity, "out_values")?;
            if let Some(c) = indices.iter().position(|&i| i as usize >= value_count) {
                return Err(Failure::new(
                    WeftStatus::IndexOutOfRange,
                    format!(
                        "face corner {c} uses value {}, but there are {value_count} values",
                        indices[c]
                    ),
                ));
            }
            let refined = subdivider.face_varying(values, width, indices, linear)?;
            out[..needed].copy_from_slice(&refined);
            Ok(())
        })
    }
}

/// Projects the vertices of the subdivision of `weft_subdivide_ex` onto the
/// limit surface, and gives the surface's unit normals there (OpenSubdiv's
/// `PrimvarRefiner::Limit`; normal = du × dv normalised, outward for
/// counter-clockwise faces, zero where undefined).
///
/// `mesh` and `options` must not be NULL; `levels` as `weft_subdivide_ex`
/// (Catmull-Clark needs at least 1 unless every face is a quad).
/// `out_positions` and `out_normals` each have room for `capacity` doubles
/// and need 3 per refined vertex (`weft_subdivision_counts`), else the call
/// fails with WEFT_STATUS_BUFFER_TOO_SMALL and writes nothing;
/// `out_normals` may be NULL when the normals are not wanted.
///
/// Fails as `weft_subdivide_ex`, and with WEFT_STATUS_INVALID_ARGUMENT for
/// Catmull-Clark at level 0 on a mesh with faces that are not quads.
/// Coordinates near the largest double are evaluated at an exactly scaled
/// size; a limit position beyond it is WEFT_STATUS_DEGENERATE_INPUT naming
/// the vertex.
///
/// # Safety
/// As `weft_subdivide_ex`; the outputs are NULL or hold `capacity` writable doubles.
#[no_mangle]
pub unsafe extern "C" fn weft_subdivide_limit(
    mesh: *const WeftMesh,
    options: *const WeftSubdivisionOptions,
    levels: u32,
    out_positions: *mut f64,
    out_normals: *mut f64,
    capacity: usize,
) -> WeftStatus {
    // SAFETY: `mesh`, `options`, `out_positions` and `out_normals` are as the `# Safety` section
    // above requires; each is checked for NULL before it is used.
    unsafe {
        guard(|| {
            let positions = out_param(out_positions, "out_positions")?;
            let (_, subdivider) = subdivider_arg(mesh, options, levels)?;
            let needed = subdivider.vertex_count().saturating_mul(3);
            check_room("out_positions", capacity, needed)?;
            let positions = output_slice(positions, capacity, "out_positions")?;
            let normals = if out_normals.is_null() {
                None
            } else {
                Some(output_slice(out_normals, capacity, "out_normals")?)
            };
            let (limit_positions, limit_normals) = subdivider.limit_positions_and_normals()?;
            write_points(&limit_positions, positions);
            if let Some(normals) = normals {
                write_points(&limit_normals, normals);
            }
            Ok(())
        })
    }
}

fn write_points(points: &[DVec3], out: &mut [f64]) {
    for (p, xyz) in points.iter().zip(out.chunks_exact_mut(3)) {
        xyz.copy_from_slice(&p.to_array());
    }
}
