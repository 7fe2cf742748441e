//! Dual mesh.

use crate::error::Result;
use crate::mesh::topology::Topology;
use crate::mesh::Mesh;
use crate::toolbar::split::{face_centroid, moved, vertex_fans, Builder};

/// How the dual's vertices are placed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DualMode {
    /// Each face's vertex sits at the face's centroid (the average of its
    /// corners).
    #[default]
    VertexAverage,
    /// As `VertexAverage`, then scaled uniformly about its bounding box
    /// centre and moved so the box has the input's centre and the input's
    /// diagonal length (the dual of a convex solid otherwise shrinks).
    KeepSize,
}

/// The dual mesh (Weaverbird's Dual): a vertex per face, and a face per
/// vertex joining the vertices of the faces around it, in order, wound like
/// the input. The dual of a cube is an octahedron, of an icosahedron a
/// dodecahedron.
///
/// Boundary: only a vertex whose faces close around it (an interior,
/// manifold vertex between consistently wound faces) gets a face; a vertex
/// on a naked or non-manifold edge gets none, so the dual of an open mesh
/// stops half a face inside its border. Face vertices that no dual face
/// uses are left out.
///
/// Output order: the used face vertices in face order; the dual faces in
/// vertex order.
///
/// # Errors
/// [`crate::Error::ResultTooLarge`] past the size cap (never for a valid
/// mesh, whose dual is no larger); [`crate::Error::DegenerateInput`] when
/// keeping the size scales a vertex past `f64` (coordinates near
/// `f64::MAX`).
pub fn dual(mesh: &Mesh, mode: DualMode) -> Result<Mesh> {
    let topology = Topology::try_new(mesh)?;
    let fans: Vec<_> = vertex_fans(mesh, &topology)
        .into_iter()
        .filter(|f| f.closed && f.corners.len() >= 3)
        .collect();
    let faces = topology.corner_faces();
    let mut index = vec![u32::MAX; mesh.face_count()];
    for fan in &fans {
        for &c in &fan.corners {
            index[faces[c as usize] as usize] = 0;
        }
    }
    let used = index.iter().filter(|&&i| i == 0).count() as u64;
    let fan_indices: u64 = fans.iter().map(|f| f.corners.len() as u64).sum();
    let mut out = Builder::new("dual", used, fans.len() as u64, fan_indices)?;
    for (f, slot) in index.iter_mut().enumerate() {
        if *slot == 0 {
            *slot = out.vertex(face_centroid(mesh, f));
        }
    }
    let mut polygon = Vec::new();
    for fan in &fans {
        polygon.clear();
        polygon.extend(
            fan.corners
                .iter()
                .map(|&c| index[faces[c as usize] as usize]),
        );
        out.face(&polygon);
    }
    let result = out.finish()?;
    if mode == DualMode::KeepSize {
        if let (Some((lo, hi)), Some((dlo, dhi))) = (mesh.bounding_box(), result.bounding_box()) {
            let (size, dual_size) = ((hi - lo).length(), (dhi - dlo).length());
            if dual_size > 0.0 {
                let (centre, dual_centre) = ((lo + hi) * 0.5, (dlo + dhi) * 0.5);
                let scale = size / dual_size;
                let scaled = result
                    .positions()
                    .iter()
                    .map(|&p| centre + (p - dual_centre) * scale)
                    .collect();
                return moved(&result, scaled, "dual");
            }
        }
    }
    Ok(result)
}
