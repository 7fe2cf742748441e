//! Vertices and Mesh Edges.

use glam::DVec3;

use crate::mesh::topology::Topology;
use crate::mesh::Mesh;

/// The vertex positions, in index order (Weaverbird's Vertices).
pub fn vertices(mesh: &Mesh) -> Vec<DVec3> {
    mesh.positions().to_vec()
}

/// The unique edges as `[low, high]` vertex index pairs, sorted (each edge
/// once, whatever the number of its faces).
pub fn mesh_edges(mesh: &Mesh) -> Vec<[u32; 2]> {
    Topology::new(mesh).edges().to_vec()
}

/// The unique edges as line segments, in the order of [`mesh_edges`]
/// (Weaverbird's Mesh Edges).
pub fn edge_segments(mesh: &Mesh) -> Vec<[DVec3; 2]> {
    let p = mesh.positions();
    Topology::new(mesh)
        .edges()
        .iter()
        .map(|&[a, b]| [p[a as usize], p[b as usize]])
        .collect()
}
