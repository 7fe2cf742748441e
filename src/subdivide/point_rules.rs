//! Both schemes behind one call: the faces a level makes, and its points
//! from the previous level's. Above the schemes' own modules
//! ([`super::catmull_clark`], [`super::loop_subdivision`]), below the
//! refiner and the one-shot drivers that choose the scheme at run time.

use glam::DVec3;

use super::gathers::Gathers;
use super::level::{uniform_offsets, Connectivity, Faces};
use super::scheme::Scheme;
use super::{catmull_clark, loop_subdivision};
use crate::error::Result;

/// The faces of the level `scheme` makes from `faces`, with their offsets
/// when `with_offsets`.
pub(crate) fn child_faces(
    scheme: Scheme,
    faces: &Faces,
    connectivity: &Connectivity,
    with_offsets: bool,
) -> Result<Faces<'static>> {
    child_faces_into(scheme, faces, connectivity, with_offsets, None)
}

/// As [`child_faces`], the indices written `into` a caller's buffer when
/// given (which must have room), the returned faces then without them.
pub(crate) fn child_faces_into(
    scheme: Scheme,
    faces: &Faces,
    connectivity: &Connectivity,
    with_offsets: bool,
    into: Option<&mut [u32]>,
) -> Result<Faces<'static>> {
    let indices = match scheme {
        Scheme::CatmullClark => catmull_clark::child_indices(faces, connectivity, into)?,
        Scheme::Loop => loop_subdivision::child_indices(faces, connectivity, into)?,
    };
    let size = scheme.refined_face_size();
    let [_, _, face_count, _] =
        scheme.next_counts([0, 0, faces.face_count() as u64, faces.corner_count() as u64]);
    let face_count = face_count as usize;
    let vertex_count = faces.vertex_count
        + connectivity.edge_count()
        + scheme.face_point_count(faces.face_count());
    Ok(Faces {
        vertex_count,
        size,
        offsets: uniform_offsets(face_count, size, with_offsets)?.into(),
        indices: indices.into(),
    })
}

/// Applies one level's gathers of `scheme` into a new vector, each point
/// written once.
pub(crate) fn points(scheme: Scheme, level: &impl Gathers, points: &[DVec3]) -> Result<Vec<DVec3>> {
    match scheme {
        Scheme::CatmullClark => catmull_clark::points(level, points),
        Scheme::Loop => loop_subdivision::points(level, points),
    }
}

/// Applies one level's gathers (a plan, or gathers read where they lie)
/// of `scheme`: `out` receives the next level's points, as many as
/// [`point_count`] says.
pub(crate) fn apply(scheme: Scheme, level: &impl Gathers, points: &[DVec3], out: &mut [DVec3]) {
    match scheme {
        Scheme::CatmullClark => catmull_clark::apply(level, points, out),
        Scheme::Loop => loop_subdivision::apply(level, points, out),
    }
}

/// The number of points one level's gathers make.
pub(crate) fn point_count(scheme: Scheme, level: &impl Gathers) -> usize {
    level.vertex_count() + level.edge_count() + scheme.face_point_count(level.face_count())
}
