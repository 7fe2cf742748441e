//! Sierpinski Triangles: a triangle per corner, the middle left open.

use crate::error::Result;
use crate::mesh::Mesh;

use super::{corner_prev, midpoint_split, repeat};

/// Places a triangle in each corner of each face, from the corner to the
/// midpoints of its two edges, and leaves the middle open: one new hole per
/// face, `levels` times (Weaverbird's Sierpinski Triangles). A triangle
/// gives 3 triangles and a polygon of n corners gives n; neighbouring faces
/// share their edge midpoints, so the pieces stay welded at them.
///
/// Output order per level: the input vertices, then one midpoint per edge
/// in [`Topology::edges`] order; face f's triangles are contiguous, one per
/// corner in corner order, each `[corner, next midpoint, previous midpoint]`.
///
/// [`Topology::edges`]: crate::mesh::topology::Topology::edges
///
/// # Errors
/// [`crate::Error::InvalidArgument`] for more than [`super::MAX_LEVELS`]
/// levels; [`crate::Error::ResultTooLarge`] past the size cap.
pub fn sierpinski_triangles(mesh: &Mesh, levels: u32) -> Result<Mesh> {
    repeat(mesh, levels, "Sierpinski triangles", 3, sierpinski_once)
}

fn sierpinski_once(mesh: &Mesh) -> Result<Mesh> {
    let corners = mesh.index_count() as u64;
    let (topology, mut out) = midpoint_split(mesh, "Sierpinski triangles", corners, 3 * corners)?;
    let v = mesh.vertex_count() as u32;
    let prev = corner_prev(mesh);
    let edges = topology.corner_edges();
    for (c, &vertex) in mesh.face_indices().iter().enumerate() {
        out.face(&[vertex, v + edges[c], v + edges[prev[c] as usize]]);
    }
    out.finish()
}
