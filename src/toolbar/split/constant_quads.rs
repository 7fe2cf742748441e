//! Constant Quads Split: every face keeps its kind.

use crate::error::Result;
use crate::mesh::topology::Topology;
use crate::mesh::Mesh;

use super::{add_vertices_and_midpoints, corner_prev, face_centroid, repeat, Builder};

/// Splits each quad into four quads through its edge midpoints and its
/// centroid, `levels` times, so a quad mesh stays a quad mesh of the same
/// look at every level (Weaverbird's Constant Quads Split).
///
/// Other faces, where Weaverbird says nothing, do what keeps a mixed mesh
/// readable: a triangle becomes four triangles through its edge midpoints
/// (so triangles stay triangles, like quads stay quads), and a polygon of
/// five or more corners becomes one quad per corner around its centroid, as
/// in [`super::split_polygons`]. Every new point is an edge midpoint or a
/// centroid, so the surface does not move and neighbours stay welded.
///
/// Output order per level: the input vertices, one midpoint per edge in
/// [`Topology::edges`] order, then one centroid per face that is not a
/// triangle, in face order.
///
/// # Errors
/// [`crate::Error::InvalidArgument`] for more than [`super::MAX_LEVELS`]
/// levels; [`crate::Error::ResultTooLarge`] past the size cap.
pub fn constant_quads_split(mesh: &Mesh, levels: u32) -> Result<Mesh> {
    repeat(mesh, levels, "constant quads split", 4, split_once)
}

fn split_once(mesh: &Mesh) -> Result<Mesh> {
    let topology = Topology::try_new(mesh)?;
    let (v, e) = (mesh.vertex_count() as u64, topology.edge_count() as u64);
    let (mut centres, mut faces, mut indices) = (0u64, 0u64, 0u64);
    for &size in mesh.face_sizes() {
        let size = size as u64;
        if size == 3 {
            faces += 4;
            indices += 12;
        } else {
            centres += 1;
            faces += size;
            indices += 4 * size;
        }
    }
    let mut out = Builder::new("constant quads split", v + e + centres, faces, indices)?;
    add_vertices_and_midpoints(&mut out, mesh, &topology);
    let prev = corner_prev(mesh);
    let (edges, vertices) = (topology.corner_edges(), mesh.face_indices());
    let mid = |c: usize| v as u32 + edges[c];
    for (face, w) in mesh.face_offsets().windows(2).enumerate() {
        let (start, end) = (w[0] as usize, w[1] as usize);
        if end - start == 3 {
            let [a, b, c] = [vertices[start], vertices[start + 1], vertices[start + 2]];
            let (ab, bc, ca) = (mid(start), mid(start + 1), mid(start + 2));
            out.face(&[a, ab, ca]);
            out.face(&[ab, b, bc]);
            out.face(&[ca, bc, c]);
            out.face(&[ab, bc, ca]);
        } else {
            let centre = out.vertex(face_centroid(mesh, face));
            for c in start..end {
                out.face(&[vertices[c], mid(c), centre, mid(prev[c] as usize)]);
            }
        }
    }
    out.finish()
}
