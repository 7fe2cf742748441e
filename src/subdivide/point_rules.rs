//! Both schemes behind one call: the faces a level makes, and its points
//! from the previous level's. Above the schemes' own modules
//! ([`super::catmull_clark`], [`super::loop_subdivision`]), below the
//! refiner and the one-shot drivers that choose the scheme at run time.

use glam::DVec3;

use super::gathers::{Gathers, Plan};
use super::level::{Connectivity, Faces};
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
    match scheme {
        Scheme::CatmullClark => catmull_clark::child_faces(faces, connectivity, with_offsets),
        Scheme::Loop => loop_subdivision::child_faces(faces, connectivity, with_offsets),
    }
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
