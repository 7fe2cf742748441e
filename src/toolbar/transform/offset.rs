//! Offset Mesh and Mesh Thicken.

use glam::{DMat3, DVec3};

use crate::error::{Error, Result};
use crate::mesh::topology::Topology;
use crate::mesh::Mesh;
use crate::toolbar::split::{face_normal, moved, Builder};

use crate::mesh::linalg::symmetric_eigen;

/// Where an offset vertex goes (Weaverbird's offset types). `n_v` is the
/// vertex normal, the normalised sum of the unit normals of its faces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OffsetType {
    /// Distance on diagonals: `p + d·n_v`. Faces that meet at an angle move
    /// less than `d` from their plane.
    #[default]
    Diagonal,
    /// Hypotenuse average: along `n_v` by the average over its faces of
    /// `d / cos θ_f`, `θ_f` the angle between `n_v` and face f's normal (a
    /// cosine below 0.1 counts as 0.1, so a knife edge moves at most 10·d).
    /// At a vertex of three faces meeting symmetrically it lands where the
    /// offset planes meet.
    HypotenuseAverage,
    /// Planes intersection: the point where the planes of the vertex's
    /// faces, each moved by `d` along its normal, meet; with more than three
    /// faces the least-squares point. Where the planes are (nearly) parallel
    /// along some direction the point is not moved along it (the
    /// minimum-norm solution, directions with a relative eigenvalue below
    /// 1e-3 being dropped), so a flat vertex moves by `d` along the normal
    /// and a vertex on a crease of two faces lands on their moved line.
    PlanesIntersection,
}

/// The offset positions of every vertex. A vertex no face uses stays.
fn offset_positions(mesh: &Mesh, distance: f64, kind: OffsetType) -> Result<Vec<DVec3>> {
    if !distance.is_finite() {
        return Err(Error::InvalidArgument(format!(
            "distance is {distance}; it must be finite"
        )));
    }
    let normals: Vec<DVec3> = (0..mesh.face_count())
        .map(|f| face_normal(mesh, f))
        .collect();
    let topology = Topology::try_new(mesh)?;
    let faces = topology.corner_faces();
    let mut out = mesh.positions().to_vec();
    for (v, p) in out.iter_mut().enumerate() {
        let around = || {
            topology
                .vertex_corners(v)
                .iter()
                .map(|&c| normals[faces[c as usize] as usize])
        };
        let vertex_normal = around().sum::<DVec3>().normalize_or_zero();
        let step = match kind {
            OffsetType::Diagonal => vertex_normal * distance,
            OffsetType::HypotenuseAverage => {
                let count = around().count();
                if count == 0 {
                    DVec3::ZERO
                } else {
                    let sum: f64 = around()
                        .map(|n| distance / vertex_normal.dot(n).max(0.1))
                        .sum();
                    vertex_normal * (sum / count as f64)
                }
            }
            OffsetType::PlanesIntersection => planes_step(around(), distance),
        };
        *p += step;
    }
    Ok(out)
}

/// Least-squares displacement `x` with `n_f · x = d` for every face normal,
/// through the pseudo-inverse of `Σ n nᵀ`.
fn planes_step(normals: impl Iterator<Item = DVec3>, distance: f64) -> DVec3 {
    let (mut a, mut rhs) = (DMat3::ZERO, DVec3::ZERO);
    for n in normals {
        a += DMat3::from_cols(n * n.x, n * n.y, n * n.z);
        rhs += n * distance;
    }
    let (values, vectors) = symmetric_eigen(a);
    let largest = values[2];
    if largest <= 0.0 {
        return DVec3::ZERO;
    }
    values
        .iter()
        .zip(vectors)
        .filter(|(&value, _)| value > largest * 1e-3)
        .map(|(&value, vector)| vector * (vector.dot(rhs) / value))
        .sum()
}

/// Moves every vertex by `distance` along the surface's normal (positive:
/// towards the front), as [`OffsetType`] says; the faces are kept.
///
/// # Errors
/// [`Error::InvalidArgument`] when `distance` is not finite;
/// [`Error::DegenerateInput`] naming a vertex whose offset overflows `f64`
/// (a distance or coordinates near `f64::MAX`).
pub fn offset(mesh: &Mesh, distance: f64, kind: OffsetType) -> Result<Mesh> {
    let positions = offset_positions(mesh, distance, kind)?;
    moved(mesh, positions, "offset")
}

/// Makes a solid of a surface (Weaverbird's Mesh Thicken): the mesh, its
/// [`offset`] by `distance`, and a quad along every naked edge joining the
/// two. The faces are wound so the solid's outside faces out: with a
/// positive distance the offset keeps the input's winding and the input is
/// reversed; with a negative one the other way round. An open, consistently
/// oriented, manifold surface gives a closed solid.
///
/// Output order: the input's vertices, then their offsets (vertex `v`'s at
/// `V + v`); the input's faces, the offset faces, then the side quads in
/// corner order.
///
/// # Errors
/// [`Error::InvalidArgument`] when `distance` is not finite;
/// [`Error::ResultTooLarge`] past the size cap.
pub fn thicken(mesh: &Mesh, distance: f64, kind: OffsetType) -> Result<Mesh> {
    let positions = offset_positions(mesh, distance, kind)?;
    let topology = Topology::try_new(mesh)?;
    let next = topology.corner_next();
    let naked: Vec<usize> = (0..mesh.index_count())
        .filter(|&c| topology.is_naked_edge(topology.corner_edges()[c] as usize))
        .collect();
    let v = mesh.vertex_count() as u64;
    let mut out = Builder::new(
        "thicken",
        2 * v,
        2 * mesh.face_count() as u64 + naked.len() as u64,
        2 * mesh.index_count() as u64 + 4 * naked.len() as u64,
    )?;
    out.positions.extend_from_slice(mesh.positions());
    out.positions.extend_from_slice(&positions);
    let reverse_input = distance > 0.0;
    let mut polygon = Vec::new();
    for layer in [0u32, v as u32] {
        let reversed = reverse_input == (layer == 0);
        for face in mesh.faces() {
            polygon.clear();
            polygon.extend(face.iter().map(|&i| i + layer));
            if reversed {
                polygon.reverse();
            }
            out.face(&polygon);
        }
    }
    let vertices = mesh.face_indices();
    for c in naked {
        let (a, b) = (vertices[c], vertices[next[c] as usize]);
        let (a2, b2) = (a + v as u32, b + v as u32);
        if reverse_input {
            out.face(&[a, b, b2, a2]);
        } else {
            out.face(&[b, a, a2, b2]);
        }
    }
    out.finish()
}
