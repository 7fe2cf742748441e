//! Split Triangles: Loop's topology without its smoothing.

use crate::error::{Error, Result};
use crate::mesh::Mesh;

use super::{midpoint_split, repeat};

/// Splits each triangle into four through its edge midpoints, `levels`
/// times; the surface and its area do not change. Output order per level:
/// the input vertices, then one midpoint per edge in [`Topology::edges`]
/// order; triangle `[a, b, c]` becomes `[a, ab, ca]`, `[ab, b, bc]`,
/// `[ca, bc, c]` and the middle `[ab, bc, ca]`, in that order.
///
/// [`Topology::edges`]: crate::mesh::topology::Topology::edges
///
/// # Errors
/// [`Error::NotTriangles`] naming the first face that is not a triangle;
/// [`Error::InvalidArgument`] for more than [`super::MAX_LEVELS`] levels;
/// [`Error::ResultTooLarge`] past [`crate::error::MAX_ELEMENTS`].
pub fn split_triangles(mesh: &Mesh, levels: u32) -> Result<Mesh> {
    if let Some((face, size)) = mesh.first_non_triangle() {
        return Err(Error::NotTriangles { face, size });
    }
    repeat(mesh, levels, "split triangles", 4, split_once)
}

fn split_once(mesh: &Mesh) -> Result<Mesh> {
    let f = mesh.face_count() as u64;
    let (topology, mut out) = midpoint_split(mesh, "split triangles", 4 * f, 12 * f)?;
    let v = mesh.vertex_count() as u32;
    let edges = topology.corner_edges();
    for (face, corners) in mesh.faces().enumerate() {
        let [a, b, c] = [corners[0], corners[1], corners[2]];
        let m = |k: usize| v + edges[3 * face + k];
        let (ab, bc, ca) = (m(0), m(1), m(2));
        out.face(&[a, ab, ca]);
        out.face(&[ab, b, bc]);
        out.face(&[ca, bc, c]);
        out.face(&[ab, bc, ca]);
    }
    out.finish()
}
