//! Split Polygons: Catmull-Clark's topology without its smoothing.

use crate::error::Result;
use crate::mesh::topology::Topology;
use crate::mesh::Mesh;

use super::{add_vertices_and_midpoints, corner_prev, face_centroid, repeat, Builder};

/// Splits each n-gon into n quads through its edge midpoints and its
/// centroid, `levels` times: the same topology as Catmull-Clark, with every
/// new point on the input surface (a "linear Catmull-Clark", Weaverbird's
/// Split Polygons). Neighbouring faces share their edge midpoints, so the
/// result is welded.
///
/// Output order per level: the input vertices, then one midpoint per edge
/// in [`Topology::edges`] order, then one centroid per face. Face f's
/// children are contiguous; child k starts at f's corner k and runs
/// `[corner, next midpoint, centroid, previous midpoint]`.
///
/// # Errors
/// [`crate::Error::InvalidArgument`] for more than [`super::MAX_LEVELS`]
/// levels; [`crate::Error::ResultTooLarge`] when the result would pass
/// [`crate::error::MAX_ELEMENTS`].
pub fn split_polygons(mesh: &Mesh, levels: u32) -> Result<Mesh> {
    repeat(mesh, levels, "split polygons", 4, split_once)
}

fn split_once(mesh: &Mesh) -> Result<Mesh> {
    let topology = Topology::try_new(mesh)?;
    let (v, e, f, corners) = (
        mesh.vertex_count() as u64,
        topology.edge_count() as u64,
        mesh.face_count() as u64,
        mesh.index_count() as u64,
    );
    let mut out = Builder::new("split polygons", v + e + f, corners, 4 * corners)?;
    add_vertices_and_midpoints(&mut out, mesh, &topology);
    for face in 0..mesh.face_count() {
        out.vertex(face_centroid(mesh, face));
    }
    let prev = corner_prev(mesh);
    let (edges, vertices) = (topology.corner_edges(), mesh.face_indices());
    let (edge_base, face_base) = (v as u32, (v + e) as u32);
    for (face, w) in mesh.face_offsets().windows(2).enumerate() {
        for c in w[0] as usize..w[1] as usize {
            out.face(&[
                vertices[c],
                edge_base + edges[c],
                face_base + face as u32,
                edge_base + edges[prev[c] as usize],
            ]);
        }
    }
    out.finish()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;

    #[test]
    fn children_start_at_their_corner() {
        let square = shapes::quad_grid(1, 1);
        let split = split_polygons(&square, 1).unwrap();
        // Vertices 0..4, midpoints 4..8 (edges sorted), centroid 8.
        assert_eq!(split.positions()[8], glam::DVec3::new(0.5, 0.5, 0.0));
        for (k, face) in split.faces().enumerate() {
            assert_eq!(face[0], square.face(0)[k]);
            assert_eq!(face[2], 8);
        }
    }
}
