//! Sierpinski Carpet on quads.

use crate::error::{Error, Result};
use crate::mesh::topology::Topology;
use crate::mesh::Mesh;
use crate::toolbar::split::{repeat, Builder};

/// Cuts each quad into a 3 × 3 grid of quads (bilinearly, so a non-planar
/// quad keeps its shape) and removes the middle one, `levels` times: one new
/// hole per quad and level (Weaverbird's Sierpinski Carpet). Neighbouring
/// quads share their edge points, so the result is welded.
///
/// Output order per level: the input vertices, two points per edge in
/// [`Topology::edges`] order (the one nearer the edge's lower vertex first),
/// then four inner points per face; each face's 8 quads are contiguous, row
/// by row from its first corner.
///
/// # Errors
/// [`Error::InvalidArgument`] naming the first face that is not a quad, or
/// for more than [`crate::toolbar::split::MAX_LEVELS`] levels;
/// [`Error::ResultTooLarge`] past the size cap.
pub fn sierpinski_carpet(mesh: &Mesh, levels: u32) -> Result<Mesh> {
    if let Some(face) = mesh.face_sizes().iter().position(|&s| s != 4) {
        return Err(Error::InvalidArgument(format!(
            "face {face} has {} vertices; Sierpinski carpet needs a quad mesh",
            mesh.face_sizes()[face]
        )));
    }
    repeat(mesh, levels, "Sierpinski carpet", 8, carpet_once)
}

#[allow(clippy::needless_range_loop)] // (i, j) are grid coordinates, not just indices
fn carpet_once(mesh: &Mesh) -> Result<Mesh> {
    let topology = Topology::try_new(mesh)?;
    let (v, e, f) = (
        mesh.vertex_count() as u64,
        topology.edge_count() as u64,
        mesh.face_count() as u64,
    );
    let mut out = Builder::new("Sierpinski carpet", v + 2 * e + 4 * f, 8 * f, 32 * f)?;
    let p = mesh.positions();
    out.positions.extend_from_slice(p);
    for &[a, b] in topology.edges() {
        let (a, b) = (p[a as usize], p[b as usize]);
        out.vertex(a + (b - a) / 3.0);
        out.vertex(a + (b - a) * (2.0 / 3.0));
    }
    let edges = topology.corner_edges();
    for (face, corners) in mesh.faces().enumerate() {
        let q: Vec<_> = corners.iter().map(|&i| p[i as usize]).collect();
        let bilinear = |u: f64, w: f64| {
            q[0] * ((1.0 - u) * (1.0 - w))
                + q[1] * (u * (1.0 - w))
                + q[2] * (u * w)
                + q[3] * ((1.0 - u) * w)
        };
        let mut grid = [[0u32; 4]; 4]; // grid[j][i]: i along corner 0 → 1, j along 0 → 3
        grid[0][0] = corners[0];
        grid[0][3] = corners[1];
        grid[3][3] = corners[2];
        grid[3][0] = corners[3];
        // The edge point a third of the way from `from` along corner k's edge.
        let third = |k: usize, from_start: bool| {
            let edge = edges[4 * face + k];
            let lower_first = topology.edges()[edge as usize][0] == corners[k];
            v as u32 + 2 * edge + u32::from(lower_first != from_start)
        };
        [grid[0][1], grid[0][2]] = [third(0, true), third(0, false)];
        [grid[1][3], grid[2][3]] = [third(1, true), third(1, false)];
        [grid[3][2], grid[3][1]] = [third(2, true), third(2, false)];
        [grid[2][0], grid[1][0]] = [third(3, true), third(3, false)];
        for j in 1..3 {
            for i in 1..3 {
                grid[j][i] = out.vertex(bilinear(i as f64 / 3.0, j as f64 / 3.0));
            }
        }
        for j in 0..3 {
            for i in 0..3 {
                if (i, j) != (1, 1) {
                    out.face(&[
                        grid[j][i],
                        grid[j][i + 1],
                        grid[j + 1][i + 1],
                        grid[j + 1][i],
                    ]);
                }
            }
        }
    }
    out.finish()
}
