//! Inner Polygons: a smaller copy of each face, joined to it by quads.

use crate::error::{Error, Result};
use crate::mesh::Mesh;

use super::{face_centroid, repeat, Builder};

/// Gives each face an inner face whose corners are its own pulled towards
/// its centroid by `pull` (0 keeps the corner, 1 reaches the centroid), and
/// joins the two with one quad per edge, `levels` times. The outer quads
/// share the input's vertices, so the result stays welded; the surface does
/// not move when the faces are planar.
///
/// Face f's children are contiguous: the inner face (its corner k pulled
/// from f's corner k), then the quad of each edge in corner order,
/// `[corner k, corner k+1, inner k+1, inner k]`. New vertices follow the
/// input's, face by face.
///
/// # Errors
/// [`Error::InvalidArgument`] when `pull` is not in the open interval
/// (0, 1) or for more than [`super::MAX_LEVELS`] levels;
/// [`Error::ResultTooLarge`] past the size cap.
pub fn inner_polygons(mesh: &Mesh, levels: u32, pull: f64) -> Result<Mesh> {
    if !(pull > 0.0 && pull < 1.0) {
        return Err(Error::InvalidArgument(format!(
            "pull is {pull}; it must be between 0 and 1, both excluded"
        )));
    }
    repeat(mesh, levels, "inner polygons", 5, |m| inner_once(m, pull))
}

fn inner_once(mesh: &Mesh, pull: f64) -> Result<Mesh> {
    let corners = mesh.index_count() as u64;
    let mut out = Builder::new(
        "inner polygons",
        mesh.vertex_count() as u64 + corners,
        mesh.face_count() as u64 + corners,
        5 * corners,
    )?;
    out.positions.extend_from_slice(mesh.positions());
    for (face, w) in mesh.face_offsets().windows(2).enumerate() {
        let centre = face_centroid(mesh, face);
        let first_inner = out.positions.len() as u32;
        let outer = mesh.face(face);
        for &v in outer {
            let p = mesh.positions()[v as usize];
            out.vertex(p + (centre - p) * pull);
        }
        let n = w[1] - w[0];
        let inner: Vec<u32> = (first_inner..first_inner + n).collect();
        out.face(&inner);
        for k in 0..n as usize {
            let next = (k + 1) % n as usize;
            out.face(&[outer[k], outer[next], inner[next], inner[k]]);
        }
    }
    out.finish()
}
