//! Reroute Faces: where each face starts.

use crate::mesh::Mesh;

/// Rotates every face's list of corners so that it starts `shift` corners
/// later (`[a, b, c, d]` shifted by 1 is `[b, c, d, a]`; a negative shift
/// goes the other way). The winding, the vertices and the face order do
/// not change: only which corner comes first, which is what a definition
/// that reads "vertex 0 of each face" sees (Weaverbird's Reroute Faces).
pub fn reroute_faces(mesh: &Mesh, shift: i64) -> Mesh {
    let mut indices = Vec::with_capacity(mesh.index_count());
    for face in mesh.faces() {
        let k = shift.rem_euclid(face.len() as i64) as usize;
        indices.extend_from_slice(&face[k..]);
        indices.extend_from_slice(&face[..k]);
    }
    Mesh::from_valid_parts(
        mesh.positions().to_vec(),
        mesh.face_sizes().to_vec(),
        indices,
    )
}
