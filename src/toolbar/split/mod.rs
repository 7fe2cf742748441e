//! Linear subdivisions of Weaverbird's toolbar: the faces are cut, the
//! surface does not move (no smoothing). Each takes a level count and
//! checks the size of its result before allocating it.
//!
//! - [`split_polygons`]: each n-gon into n quads (Catmull-Clark's topology).
//! - [`split_triangles`]: each triangle into 4 (Loop's topology).
//! - [`constant_quads_split`]: quads into 4 quads, triangles into 4
//!   triangles, larger polygons into quads.
//! - [`midedge`]: the mid-edge (Peters–Reif) scheme, a face per face and
//!   per vertex.
//! - [`inner_polygons`]: an inner face in each face, joined by quads.
//! - [`sierpinski_triangles`]: a triangle per corner, the middle left open.
//!
//! Outputs keep the input's vertices first (where they survive), then the
//! new points; the children of a face are contiguous.

mod build;
mod constant_quads;
mod inner;
mod midedge;
mod polygons;
mod sierpinski;
mod triangles;

pub use build::MAX_LEVELS;
pub(crate) use build::{
    check_levels, corner_prev, face_centroid, face_normal, moved, vertex_fans, Builder,
};
pub use constant_quads::constant_quads_split;
pub use inner::inner_polygons;
pub use midedge::midedge;
pub use polygons::split_polygons;
pub use sierpinski::sierpinski_triangles;
pub use triangles::split_triangles;

use glam::DVec3;

use crate::error::{Error, Result, MAX_ELEMENTS};
use crate::mesh::topology::Topology;
use crate::mesh::Mesh;

/// Applies `step` `levels` times (at most [`MAX_LEVELS`]); stops early on a
/// mesh without faces. `growth` is a lower bound of how many times the face
/// index count grows per level, so that a level count that cannot fit fails
/// at once rather than after building the levels below it.
pub(crate) fn repeat(
    mesh: &Mesh,
    levels: u32,
    what: &str,
    growth: u64,
    mut step: impl FnMut(&Mesh) -> Result<Mesh>,
) -> Result<Mesh> {
    check_levels(levels)?;
    let predicted =
        (mesh.index_count() as u128).saturating_mul((growth as u128).saturating_pow(levels));
    if mesh.face_count() > 0 && predicted > MAX_ELEMENTS as u128 {
        return Err(Error::ResultTooLarge(format!(
            "{levels} levels of {what} on {} face indices would make at least {predicted} face indices; the limit is {MAX_ELEMENTS}",
            mesh.index_count()
        )));
    }
    let mut current = mesh.clone();
    for _ in 0..levels {
        if current.face_count() == 0 {
            break;
        }
        current = step(&current)?;
    }
    Ok(current)
}

/// Midpoint of edge `e`.
pub(crate) fn edge_midpoint(mesh: &Mesh, edge: [u32; 2]) -> DVec3 {
    let p = mesh.positions();
    (p[edge[0] as usize] + p[edge[1] as usize]) * 0.5
}

/// Adds `mesh`'s vertices, then one midpoint per edge in
/// [`Topology::edges`] order: the first vertices of every linear split.
pub(crate) fn add_vertices_and_midpoints(out: &mut Builder, mesh: &Mesh, topology: &Topology) {
    out.positions.extend_from_slice(mesh.positions());
    for &edge in topology.edges() {
        out.vertex(edge_midpoint(mesh, edge));
    }
}

/// The start of a split whose only new vertices are the edge midpoints:
/// the mesh's topology and a builder that holds the vertices and midpoints
/// (see [`add_vertices_and_midpoints`]) with room for `faces` faces of
/// `indices` corners in all.
pub(crate) fn midpoint_split(
    mesh: &Mesh,
    what: &str,
    faces: u64,
    indices: u64,
) -> Result<(Topology, Builder)> {
    let topology = Topology::try_new(mesh)?;
    let vertices = mesh.vertex_count() as u64 + topology.edge_count() as u64;
    let mut out = Builder::new(what, vertices, faces, indices)?;
    add_vertices_and_midpoints(&mut out, mesh, &topology);
    Ok((topology, out))
}
