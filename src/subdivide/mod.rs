//! Subdivision surfaces: Catmull-Clark and Loop with Weaverbird's three
//! naked-edge modes, equal to OpenSubdiv 3.5's uniform refinement.
//!
//! Each level runs in two passes. A topology pass finds the level's edges by
//! bucketing, tags every edge and vertex with its rule (`rules.rs`: boundary,
//! corner, non-manifold) and writes the next level's faces arithmetically;
//! every new point is then a gather of old points. An arithmetic pass applies
//! the gathers to positions in parallel, with no atomics. [`Refiner`] stores
//! them once as *plans* for re-evaluation; a one-shot subdivision reads them
//! where they lie, the last level's from the level before it
//! (`gathers.rs`), so the largest connectivity is never built.
//!
//! # Layers
//! Each file reads only the ones below it:
//! 1. `scheme.rs`: the vocabulary — [`Scheme`] (with what one level makes of
//!    a level's counts and sizes), [`NakedEdges`], the vertex rules, the size
//!    cap; `scale.rs`, the exact scaling of huge coordinates.
//! 2. `level.rs`: a level's faces and connectivity (the cage's from the
//!    mesh's one builder, refined levels' written arithmetically).
//! 3. `rules.rs` (boundary and non-manifold tags), `creases.rs`
//!    (sharpness and the options) and `holes.rs` (the faces the result
//!    leaves out).
//! 4. `gathers.rs`: plans and gathers, where each new point finds its old
//!    points; `stencils.rs`, the weighted sums of the creased path.
//! 5. `catmull_clark.rs`, `loop_subdivision.rs`: each scheme's faces and
//!    point rules; `point_rules.rs` puts both behind one call.
//! 6. `refiner.rs` and `subdivider.rs` (with `face_varying.rs`, `limit.rs`),
//!    and on top this file's one-shot drivers.
//!
//! # Output order
//! One level of V vertices, E edges and F faces makes, in order: the V
//! vertex points (the input's vertices keep their indices), the E edge points
//! (edges sorted by lower, then higher vertex index), and for Catmull-Clark
//! the F face points. The children of face f are contiguous, in the order of
//! f's corners, the first at f's first corner: Catmull-Clark turns face f of
//! n corners into n quads starting at child face `Σ_{g<f} size(g)`; Loop turns
//! triangle f into 4 triangles starting at `4f`. [`parent_faces`] gives the
//! cage face of every refined face.
//!
//! # Non-manifold input
//! Edges with three or more faces, or whose two faces run them the same way,
//! are infinitely sharp creases; bow-tie and other non-manifold vertices are
//! corners — as OpenSubdiv does. No face is ever dropped.
//!
//! # Creases, carried data and the limit
//! [`Subdivider`] (and [`subdivide_with`], [`Refiner::with_options`]) takes
//! [`SubdivisionOptions`]: semi-sharp and infinite edge creases and vertex
//! corners with Uniform or Chaikin creasing, as OpenSubdiv's
//! `TopologyDescriptor` and `Sdc::Options`; it carries per-vertex data of any
//! width and face-varying values ([`FaceVaryingLinear`]), and projects the
//! last level onto the limit surface ([`Limit`]). [`creases_from_mesh`]
//! turns unwelded seams and sharp folds into creases.

mod bands;
mod catmull_clark;
mod creases;
mod face_varying;
mod gathers;
mod holes;
mod level;
mod limit;
mod limit_patches;
mod limit_surface;
mod loop_subdivision;
mod point_rules;
mod refiner;
pub(crate) mod rules;
mod scale;
mod scheme;
mod stencils;
mod subdivider;

use glam::DVec3;

pub use creases::{
    creases_from_mesh, Crease, CreasedMesh, Creasing, SubdivisionOptions, TriangleRule,
    SHARPNESS_INFINITE,
};
pub use face_varying::FaceVaryingLinear;
pub use limit::Limit;
pub use limit_patches::{
    limit_patch_count, limit_patches, BezierPatch, LimitPatches, MAX_ISOLATION,
};
pub use limit_surface::{LimitSurface, MAX_LIMIT_VALENCE};
pub use refiner::Refiner;
use refiner::{Points, Step};
pub(crate) use scheme::check_counts;
use scheme::too_large;
pub use scheme::{NakedEdges, RefinedCounts, Scheme};
pub use subdivider::{subdivide_with, Subdivider};

use crate::buffers::try_vec;
use crate::error::{Result, MAX_ELEMENTS};
use crate::mesh::Mesh;

/// Catmull-Clark subdivision, `levels` times (0 returns a copy).
///
/// Works on triangles, quads and n-gons mixed; after one level every face is
/// a quad. Rules as OpenSubdiv's Catmark scheme; order as in the module doc.
///
/// # Errors
/// [`crate::Error::ResultTooLarge`] when a level would make more than
/// [`MAX_ELEMENTS`] vertices, faces or indices (checked before allocating);
/// [`crate::Error::OutOfMemory`]; [`crate::Error::DegenerateInput`] naming the vertex when
/// a refined point lies beyond the largest `f64` (coordinates near
/// `f64::MAX` are subdivided at an exactly scaled-down size, so sums inside
/// the rules never overflow).
pub fn catmull_clark(mesh: &Mesh, levels: u32, naked_edges: NakedEdges) -> Result<Mesh> {
    subdivide(mesh, Scheme::CatmullClark, levels, naked_edges)
}

/// Loop subdivision, `levels` times (0 returns a copy). Requires a triangle
/// mesh; each triangle becomes 4. Rules as OpenSubdiv's Loop scheme.
///
/// # Errors
/// [`crate::Error::NotTriangles`] naming the first face that is not a triangle
/// (triangulate first with [`crate::mesh::triangulate::triangulate`]);
/// [`crate::Error::ResultTooLarge`]; [`crate::Error::OutOfMemory`];
/// [`crate::Error::DegenerateInput`] as [`catmull_clark`].
pub fn loop_subdivision(mesh: &Mesh, levels: u32, naked_edges: NakedEdges) -> Result<Mesh> {
    subdivide(mesh, Scheme::Loop, levels, naked_edges)
}

/// Subdivides `mesh` with `scheme`, `levels` times: one topology pass and one
/// arithmetic pass per level, the intermediate levels freed as soon as used.
///
/// # Errors
/// As [`catmull_clark`] and [`loop_subdivision`].
pub fn subdivide(
    mesh: &Mesh,
    scheme: Scheme,
    levels: u32,
    naked_edges: NakedEdges,
) -> Result<Mesh> {
    if naked_edges == NakedEdges::None {
        // Holes at the boundary: the creased path filters the faces.
        return subdivide_with(mesh, scheme, levels, &SubdivisionOptions::new(naked_edges));
    }
    let request = refiner::Levels {
        cage: mesh,
        scheme,
        levels,
        naked_edges,
    };
    let (faces, positions) = refine_points(request, None, |_| Ok(()))?;
    let positions = positions.unwrap_or_else(|| mesh.positions().to_vec());
    if !faces.offsets.is_empty() {
        // Level 0, or no faces: the cage's own sizes.
        let sizes = faces.sizes();
        return Ok(Mesh::from_valid_parts(
            positions,
            sizes,
            faces.indices.into_owned(),
        ));
    }
    // A refined level: all quads (Catmull-Clark) or all triangles (Loop).
    Mesh::from_valid_uniform_parts(
        positions,
        scheme.refined_face_size(),
        faces.indices.into_owned(),
    )
}

/// As [`subdivide`], into a caller's buffers instead of a new mesh: the
/// result's positions go to the start of `positions` and its face indices
/// to the start of `face_indices` (its faces are all quads for
/// Catmull-Clark and all triangles for Loop from level 1 on, the cage's
/// at level 0). A host that subdivides again and again keeps its buffers,
/// so the output's memory is not faulted in afresh on every call, and the
/// last level's points are written where they belong, each once. The
/// values are those of [`subdivide`], bit for bit. Returns the counts
/// written.
///
/// # Errors
/// As [`subdivide`]; [`Error::BufferTooSmall`](crate::Error::BufferTooSmall)
/// naming the buffer when one is shorter than the result (the counts of
/// [`refined_counts`]), found before anything is written. On any other
/// error the buffers' contents are unspecified.
pub fn subdivide_into(
    mesh: &Mesh,
    scheme: Scheme,
    levels: u32,
    naked_edges: NakedEdges,
    positions: &mut [DVec3],
    face_indices: &mut [u32],
) -> Result<RefinedCounts> {
    let room = (positions.len(), face_indices.len());
    if naked_edges == NakedEdges::None || levels == 0 || mesh.face_count() == 0 {
        // Holes filter the faces after refining, and level 0 is a copy.
        let result = subdivide(mesh, scheme, levels, naked_edges)?;
        let counts = RefinedCounts {
            vertex_count: result.vertex_count(),
            face_count: result.face_count(),
            index_count: result.index_count(),
        };
        check_room(counts, room)?;
        positions[..counts.vertex_count].copy_from_slice(result.positions());
        face_indices[..counts.index_count].copy_from_slice(result.face_indices());
        return Ok(counts);
    }
    let request = refiner::Levels {
        cage: mesh,
        scheme,
        levels,
        naked_edges,
    };
    let mut counts = None;
    refine_points(request, Some((positions, face_indices)), |found| {
        counts = Some(found);
        check_room(found, room)
    })?;
    Ok(counts.expect("a refined level reports its counts"))
}

/// The one-shot levels of `request` with their points, each level's
/// positions freed once the next is made. Returns the last level's faces
/// (see [`refiner::gather_levels`]) and its positions, or none at level 0.
/// With `into`, a caller's buffers, the last level's positions and face
/// indices are written there instead, once `room` has accepted the counts.
fn refine_points<'a>(
    request: refiner::Levels<'a>,
    into: Option<(&mut [DVec3], &mut [u32])>,
    room: impl FnOnce(RefinedCounts) -> Result<()>,
) -> Result<(level::Faces<'a>, Option<Vec<DVec3>>)> {
    let (mesh, scheme) = (request.cage, request.scheme);
    // The first level reads the cage's positions in place, unless they are
    // near the top of the f64 range (see `scale.rs`).
    let scale = match request.levels == 0 || mesh.face_count() == 0 {
        true => None,
        false => scale::for_points(mesh.positions()),
    };
    let mut positions: Option<Vec<DVec3>> =
        scale.map(|scale| scale::scaled_points(mesh.positions(), scale));
    let (mut into_points, into_indices) = match into {
        Some((points, indices)) => (Some(points), Some(indices)),
        None => (None, None),
    };
    let mut written = 0;
    let faces = refiner::gather_levels(request, into_indices, room, |step, points| {
        let made = positions.as_deref().unwrap_or(mesh.positions());
        match (points, into_points.as_deref_mut()) {
            (Points::NextInto(out), _) => {
                write_points(scheme, &step, made, out);
                // The last level reads the points from `out`.
                positions = None;
            }
            (Points::Last(source), Some(out)) => {
                written = write_points(scheme, &step, source.unwrap_or(made), out);
            }
            (Points::Last(source), None) => {
                positions = Some(new_points(scheme, &step, source.unwrap_or(made))?);
            }
            (Points::Next, _) => positions = Some(new_points(scheme, &step, made)?),
        }
        Ok(())
    })?;
    if let (Some(out), Some(scale)) = (into_points, scale) {
        scale::restore_points(&mut out[..written], scale, "the position")?;
        return Ok((faces, None));
    }
    if let (Some(positions), Some(scale)) = (positions.as_mut(), scale) {
        scale::restore_points(positions, scale, "the position")?;
    }
    Ok((faces, positions))
}

/// Writes one level's points into the start of `out`; returns how many.
fn write_points(scheme: Scheme, step: &Step<'_>, source: &[DVec3], out: &mut [DVec3]) -> usize {
    fn write(
        scheme: Scheme,
        level: &impl gathers::Gathers,
        source: &[DVec3],
        out: &mut [DVec3],
    ) -> usize {
        let count = point_rules::point_count(scheme, level);
        point_rules::apply(scheme, level, source, &mut out[..count]);
        count
    }
    match step {
        Step::Level(level) => write(scheme, level, source, out),
        Step::Refined(level) => write(scheme, level, source, out),
        Step::LoopRefined(level) => write(scheme, *level, source, out),
    }
}

/// One level's points, in a new buffer.
fn new_points(scheme: Scheme, step: &Step<'_>, source: &[DVec3]) -> Result<Vec<DVec3>> {
    match step {
        Step::Level(level) => point_rules::points(scheme, level, source),
        Step::Refined(level) => point_rules::points(scheme, level, source),
        Step::LoopRefined(level) => point_rules::points(scheme, *level, source),
    }
}

/// Refuses buffers of `(positions, face indices)` lengths too short for `counts`.
fn check_room(counts: RefinedCounts, (positions, indices): (usize, usize)) -> Result<()> {
    for (name, length, needed, what) in [
        ("positions", positions, counts.vertex_count, "vertices"),
        ("face_indices", indices, counts.index_count, "face indices"),
    ] {
        if length < needed {
            return Err(crate::Error::BufferTooSmall(format!(
                "{name} has room for {length} {what} but the result has {needed}"
            )));
        }
    }
    Ok(())
}

/// The cage face each face of the refined mesh comes from, in the refined
/// mesh's face order. Needs only the cage's face sizes.
///
/// # Errors
/// [`crate::Error::NotTriangles`] for Loop on a non-triangle; [`crate::Error::ResultTooLarge`].
pub fn parent_faces(cage: &Mesh, scheme: Scheme, levels: u32) -> Result<Vec<u32>> {
    let face_count = refined_face_count(cage, scheme, levels)?;
    let mut parents = try_vec(face_count, "parent faces")?;
    parents.extend(scheme.parents_of(cage.face_sizes().iter().copied(), levels as usize));
    Ok(parents)
}

/// [`parent_faces`] of the subdivision `options` describe: the children of
/// holes (and with [`NakedEdges::None`], of the faces at the boundary) are
/// not there.
///
/// # Errors
/// As [`parent_faces`]; [`crate::Error::InvalidArgument`] for a hole past
/// the face count.
pub fn parent_faces_with(
    cage: &Mesh,
    scheme: Scheme,
    levels: u32,
    options: &SubdivisionOptions,
) -> Result<Vec<u32>> {
    let mut parents = parent_faces(cage, scheme, levels)?;
    if let Some(holes) = holes::mesh_holes(cage, options)? {
        parents.retain(|&f| !holes[f as usize]);
    }
    Ok(parents)
}

/// Number of faces after `levels` levels of `scheme`, from the face sizes
/// alone (`Σ size · 4^(levels-1)` for Catmull-Clark, `4^levels · F` for Loop).
///
/// # Errors
/// [`crate::Error::NotTriangles`] for Loop on a non-triangle; [`crate::Error::ResultTooLarge`]
/// past [`MAX_ELEMENTS`].
pub fn refined_face_count(cage: &Mesh, scheme: Scheme, levels: u32) -> Result<usize> {
    scheme.check_cage(cage)?;
    let mut faces = cage.face_count() as u64;
    let mut corners = cage.index_count() as u64;
    for level in 1..=levels {
        if faces == 0 {
            break;
        }
        let [_, _, f, c] = scheme.next_counts([0, 0, faces, corners]);
        (faces, corners) = (f, c);
        if faces > MAX_ELEMENTS || corners > MAX_ELEMENTS {
            return Err(too_large(levels, level, faces, corners));
        }
    }
    Ok(faces as usize)
}

/// Vertex, face and index counts after `levels` levels, found from the
/// cage's edges; nothing of the result is allocated.
///
/// # Errors
/// As [`refined_face_count`]; [`crate::Error::OutOfMemory`].
pub fn refined_counts(cage: &Mesh, scheme: Scheme, levels: u32) -> Result<RefinedCounts> {
    let face_count = refined_face_count(cage, scheme, levels)?;
    let edges = crate::mesh::topology::Topology::try_new(cage)?.edge_count() as u64;
    let (vertices, faces, indices) = check_counts(
        scheme,
        cage.vertex_count() as u64,
        edges,
        cage.face_count() as u64,
        cage.index_count() as u64,
        if cage.face_count() == 0 { 0 } else { levels },
    )?;
    debug_assert_eq!(faces as usize, face_count);
    Ok(RefinedCounts {
        vertex_count: vertices as usize,
        face_count: faces as usize,
        index_count: indices as usize,
    })
}

/// [`refined_counts`] of the subdivision `options` describe: holes leave
/// their vertices but not their faces. Creases and corners change nothing.
///
/// # Errors
/// As [`refined_counts`]; [`crate::Error::InvalidArgument`] for a hole past
/// the face count.
pub fn refined_counts_with(
    cage: &Mesh,
    scheme: Scheme,
    levels: u32,
    options: &SubdivisionOptions,
) -> Result<RefinedCounts> {
    let mut counts = refined_counts(cage, scheme, levels)?;
    if let Some(holes) = holes::mesh_holes(cage, options)? {
        let levels = if cage.face_count() == 0 {
            0
        } else {
            levels as usize
        };
        for (&size, _) in cage.face_sizes().iter().zip(&holes).filter(|(_, &h)| h) {
            let faces = scheme.descendants_of_face(size, levels);
            let corners = match levels {
                0 => size as usize,
                _ => scheme.refined_face_size() as usize,
            };
            counts.face_count -= faces;
            counts.index_count -= faces * corners;
        }
    }
    Ok(counts)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;
    use crate::Error;

    #[test]
    fn level_zero_is_a_copy() {
        let cube = shapes::cube();
        assert_eq!(catmull_clark(&cube, 0, NakedEdges::Smooth).unwrap(), cube);
    }

    #[test]
    fn cube_level_one_has_known_points() {
        let cube = shapes::cube();
        let out = catmull_clark(&cube, 1, NakedEdges::Smooth).unwrap();
        assert_eq!(out.vertex_count(), 8 + 12 + 6);
        assert_eq!(out.face_count(), 24);
        // Corner (0,0,0): n = 3, ((n-2) v + (Σ edge ends + Σ face points)/n)/n.
        let expected = DVec3::splat(2.0 / 9.0);
        assert!((out.positions()[0] - expected).length() < 1e-15);
        // Face points are the last 6, the -z face first.
        assert_eq!(out.positions()[8 + 12], DVec3::new(0.5, 0.5, 0.0));
        // The first child of face 0 starts at its first corner.
        assert_eq!(out.face(0)[0], 0);
        assert_eq!(out.face(0)[2], 20);
    }

    #[test]
    fn level_sixteen_of_a_cube_is_refused() {
        let cube = shapes::cube();
        let err = catmull_clark(&cube, 16, NakedEdges::Smooth).unwrap_err();
        assert!(matches!(err, Error::ResultTooLarge(_)));
        assert_eq!(
            err.to_string(),
            "result too large: 16 levels of subdivision: level 14 would make 1610612736 faces \
             (6442450944 face indices), past the limit of 2147483647 vertices, faces or \
             indices; use at most 13 levels"
        );
    }
}
