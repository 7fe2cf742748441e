//! Bevel Vertices (truncation) and Bevel Edges (expansion).

use crate::error::{Error, Result};
use crate::mesh::topology::Topology;
use crate::mesh::Mesh;
use crate::toolbar::split::{corner_prev, face_centroid, vertex_fans, Builder};

fn check_fraction(fraction: f64, below: f64) -> Result<()> {
    if !(fraction > 0.0 && fraction < below) {
        return Err(Error::InvalidArgument(format!(
            "fraction is {fraction}; it must be above 0 and below {below}"
        )));
    }
    Ok(())
}

/// Cuts every vertex off: each edge gets two points, `fraction` of its
/// length from either end; each face becomes the polygon of the points on
/// its edges (an n-gon becomes a 2n-gon), and each vertex becomes a new face
/// from the points around it (Conway's truncation; a cube gives 6 octagons
/// and 8 triangles). `fraction` is in (0, 0.5); 0.5 would be
/// [`crate::toolbar::split::midedge`].
///
/// Boundary: as in midedge, a vertex on a naked edge is kept and closes its
/// face, so the outline of an open mesh keeps its place.
///
/// Output order: two points per edge in [`Topology::edges`] order (the one
/// near the lower vertex first), then the kept boundary vertices; the faces
/// in face order, then one face per vertex fan in vertex order.
///
/// # Errors
/// [`Error::InvalidArgument`] for a fraction outside (0, 0.5);
/// [`Error::ResultTooLarge`] past the size cap.
pub fn bevel_vertices(mesh: &Mesh, fraction: f64) -> Result<Mesh> {
    check_fraction(fraction, 0.5)?;
    let topology = Topology::try_new(mesh)?;
    let fans = vertex_fans(mesh, &topology);
    let e = topology.edge_count() as u64;
    let fan_indices: u64 = fans.iter().map(|f| f.corners.len() as u64 + 2).sum();
    let mut out = Builder::new(
        "bevel vertices",
        2 * e + mesh.vertex_count() as u64,
        mesh.face_count() as u64 + fans.len() as u64,
        2 * mesh.index_count() as u64 + fan_indices,
    )?;
    let p = mesh.positions();
    for &[a, b] in topology.edges() {
        let (a, b) = (p[a as usize], p[b as usize]);
        out.vertex(a + (b - a) * fraction);
        out.vertex(b + (a - b) * fraction);
    }
    // The point on edge `edge` near vertex `v`.
    let near = |edge: u32, v: u32| 2 * edge + u32::from(topology.edges()[edge as usize][0] != v);
    let (edges, vertices, next) = (
        topology.corner_edges(),
        mesh.face_indices(),
        topology.corner_next(),
    );
    let mut polygon = Vec::new();
    for w in mesh.face_offsets().windows(2) {
        polygon.clear();
        for c in w[0] as usize..w[1] as usize {
            polygon.push(near(edges[c], vertices[c]));
            polygon.push(near(edges[c], vertices[next[c] as usize]));
        }
        out.face(&polygon);
    }
    let prev = corner_prev(mesh);
    let mut kept = vec![u32::MAX; mesh.vertex_count()];
    for fan in &fans {
        let v = fan.vertex;
        polygon.clear();
        if !fan.closed {
            polygon.push(near(edges[fan.corners[0] as usize], v));
        }
        polygon.extend(
            fan.corners
                .iter()
                .map(|&c| near(edges[prev[c as usize] as usize], v)),
        );
        if !fan.closed {
            if kept[v as usize] == u32::MAX {
                kept[v as usize] = out.vertex(p[v as usize]);
            }
            polygon.push(kept[v as usize]);
        }
        if polygon.len() >= 3 {
            out.face(&polygon);
        }
    }
    out.finish()
}

/// Bevels every edge: each face shrinks towards its centroid by `fraction`
/// (0 keeps it, 1 would reach the centroid), each edge between two faces
/// becomes a quad joining their shrunk edges, and each vertex whose faces
/// close around it becomes a face joining their shrunk corners (Conway's
/// expansion; a cube gives a rhombicuboctahedron of 6 + 12 + 8 faces).
///
/// Boundary: a naked edge gets no quad and a vertex whose fan is open gets
/// no face, so an open mesh's border comes out notched; an edge between two
/// faces with opposite windings, or of three or more faces, also gets none.
///
/// Output order: one vertex per face corner, in corner order; the shrunk
/// faces in face order, the edge quads in edge order, then the vertex
/// faces in vertex order.
///
/// # Errors
/// [`Error::InvalidArgument`] for a fraction outside (0, 1);
/// [`Error::ResultTooLarge`] past the size cap.
pub fn bevel_edges(mesh: &Mesh, fraction: f64) -> Result<Mesh> {
    check_fraction(fraction, 1.0)?;
    let topology = Topology::try_new(mesh)?;
    let fans: Vec<_> = vertex_fans(mesh, &topology)
        .into_iter()
        .filter(|f| f.closed && f.corners.len() >= 3)
        .collect();
    let vertices = mesh.face_indices();
    let next = topology.corner_next();
    // Each edge's quad, from its two corners running it in opposite directions.
    let quads: Vec<[u32; 4]> = (0..topology.edge_count())
        .filter_map(|e| match topology.edge_corners(e) {
            &[f, g] if vertices[f as usize] != vertices[g as usize] => {
                Some([next[f as usize], f, next[g as usize], g])
            }
            _ => None,
        })
        .collect();
    let corners = mesh.index_count() as u64;
    let fan_indices: u64 = fans.iter().map(|f| f.corners.len() as u64).sum();
    let mut out = Builder::new(
        "bevel edges",
        corners,
        mesh.face_count() as u64 + quads.len() as u64 + fans.len() as u64,
        corners + 4 * quads.len() as u64 + fan_indices,
    )?;
    for (face, w) in mesh.face_offsets().windows(2).enumerate() {
        let centre = face_centroid(mesh, face);
        for c in w[0]..w[1] {
            let p = mesh.positions()[vertices[c as usize] as usize];
            out.vertex(p + (centre - p) * fraction);
        }
    }
    for w in mesh.face_offsets().windows(2) {
        let polygon: Vec<u32> = (w[0]..w[1]).collect();
        out.face(&polygon);
    }
    for quad in &quads {
        out.face(quad);
    }
    for fan in &fans {
        out.face(&fan.corners);
    }
    out.finish()
}
