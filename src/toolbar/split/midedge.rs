//! Midedge: the mid-edge subdivision of Peters and Reif.

use crate::error::Result;
use crate::mesh::topology::Topology;
use crate::mesh::Mesh;

use super::{corner_prev, edge_midpoint, repeat, vertex_fans, Builder};

/// The mid-edge subdivision (J. Peters, U. Reif, "The simplest subdivision
/// scheme for smoothing polyhedra", ACM ToG 16(4), 1997), `levels` times:
/// the new vertices are the edge midpoints; each face becomes the polygon of
/// its edge midpoints, and each vertex becomes the polygon of the midpoints
/// of its edges. A cube becomes a cuboctahedron (12 vertices, 6 squares,
/// 8 triangles).
///
/// Boundary: so the outline of an open mesh stays where it was, a vertex on
/// a naked edge is kept, and its polygon is the chain of midpoints around
/// it closed through the vertex itself (a corner with one face gives a
/// triangle). The same holds wherever a vertex's fan of faces breaks: at a
/// non-manifold edge, or between two faces with opposite windings (unify
/// the windings first for a clean result). When such a broken fan wraps all
/// the way around its vertex and ends at the non-manifold edge it started
/// from, that edge's midpoint is used once, so every polygon keeps distinct
/// corners.
///
/// Output order per level: one midpoint per edge in [`Topology::edges`]
/// order, then the kept boundary vertices; the face polygons in face
/// order, then the vertex polygons in vertex order.
///
/// # Errors
/// [`crate::Error::InvalidArgument`] for more than [`super::MAX_LEVELS`]
/// levels; [`crate::Error::ResultTooLarge`] past the size cap.
pub fn midedge(mesh: &Mesh, levels: u32) -> Result<Mesh> {
    repeat(mesh, levels, "midedge", 2, midedge_once)
}

fn midedge_once(mesh: &Mesh) -> Result<Mesh> {
    let topology = Topology::try_new(mesh)?;
    let fans = vertex_fans(mesh, &topology);
    let e = topology.edge_count() as u64;
    let fan_indices: u64 = fans.iter().map(|f| f.corners.len() as u64 + 2).sum();
    let mut out = Builder::new(
        "midedge",
        e + mesh.vertex_count() as u64,
        mesh.face_count() as u64 + fans.len() as u64,
        mesh.index_count() as u64 + fan_indices,
    )?;
    for &edge in topology.edges() {
        out.vertex(edge_midpoint(mesh, edge));
    }
    let edges = topology.corner_edges();
    for w in mesh.face_offsets().windows(2) {
        let polygon: Vec<u32> = (w[0]..w[1]).map(|c| edges[c as usize]).collect();
        out.face(&polygon);
    }
    let prev = corner_prev(mesh);
    let incoming = |c: u32| edges[prev[c as usize] as usize];
    let mut kept = vec![u32::MAX; mesh.vertex_count()];
    let mut polygon = Vec::new();
    for fan in &fans {
        polygon.clear();
        if fan.closed {
            polygon.extend(fan.corners.iter().map(|&c| incoming(c)));
            if polygon.len() < 3 {
                continue;
            }
        } else {
            let first = edges[fan.corners[0] as usize];
            polygon.push(first);
            polygon.extend(fan.corners.iter().map(|&c| incoming(c)));
            // Only a non-manifold edge can both start and end an open fan.
            if polygon.len() > 2 && polygon.last() == Some(&first) {
                polygon.pop();
            }
            let v = fan.vertex as usize;
            if kept[v] == u32::MAX {
                kept[v] = out.vertex(mesh.positions()[v]);
            }
            polygon.push(kept[v]);
        }
        out.face(&polygon);
    }
    out.finish()
}
