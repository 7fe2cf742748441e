//! Both schemes behind one call: the faces a level makes, and its points
//! from the previous level's. Above the schemes' own modules
//! ([`super::catmull_clark`], [`super::loop_subdivision`]), below the
//! refiner and the one-shot drivers that choose the scheme at run time.

use glam::DVec3;

use super::gathers::{Gathers, Plan};
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
) -> Result<Faces> {
    let indices = match scheme {
        Scheme::CatmullClark => catmull_clark::child_indices(faces, connectivity)?,
        Scheme::Loop => loop_subdivision::child_indices(faces, connectivity)?,
    };
    let size = scheme.refined_face_size();
    let vertex_count = faces.vertex_count
        + connectivity.edge_count()
        + scheme.face_point_count(faces.face_count());
    Ok(Faces {
        vertex_count,
        size,
        offsets: uniform_offsets(indices.len() / size as usize, size, with_offsets)?,
        indices,
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

/// Applies one plan of `scheme`.
pub(crate) fn apply(scheme: Scheme, plan: &Plan, points: &[DVec3], out: &mut [DVec3]) {
    match scheme {
        Scheme::CatmullClark => catmull_clark::apply(plan, points, out),
        Scheme::Loop => loop_subdivision::apply(plan, points, out),
    }
}
