//! Pieces the toolbar operations share: an output builder that checks the
//! result size before allocating, face centroids and normals, and the fans
//! of faces around each vertex.

use glam::DVec3;

use crate::buffers::try_vec;
use crate::error::{Error, Result, MAX_ELEMENTS};
use crate::mesh::topology::Topology;
use crate::mesh::Mesh;

/// Most levels any repeated operation accepts; every level at least
/// multiplies the face count, so more would pass the size cap anyway.
pub const MAX_LEVELS: u32 = 20;

/// Rejects a level count above [`MAX_LEVELS`].
pub(crate) fn check_levels(levels: u32) -> Result<()> {
    if levels > MAX_LEVELS {
        return Err(Error::InvalidArgument(format!(
            "levels is {levels}; it must be at most {MAX_LEVELS}"
        )));
    }
    Ok(())
}

/// Fails with [`Error::ResultTooLarge`] when a result of these counts would
/// pass [`MAX_ELEMENTS`].
pub(crate) fn check_size(what: &str, vertices: u64, faces: u64, indices: u64) -> Result<()> {
    if vertices > MAX_ELEMENTS || faces > MAX_ELEMENTS || indices > MAX_ELEMENTS {
        return Err(Error::ResultTooLarge(format!(
            "{what} would make {vertices} vertices, {faces} faces and {indices} face indices; the limit is {MAX_ELEMENTS} of each"
        )));
    }
    Ok(())
}

/// Collects an output mesh whose size was checked beforehand.
pub(crate) struct Builder {
    what: String,
    pub(crate) positions: Vec<DVec3>,
    sizes: Vec<u32>,
    indices: Vec<u32>,
}

impl Builder {
    /// Checks the counts against the cap, then reserves them.
    pub(crate) fn new(what: &str, vertices: u64, faces: u64, indices: u64) -> Result<Builder> {
        check_size(what, vertices, faces, indices)?;
        Ok(Builder {
            what: what.to_owned(),
            positions: try_vec(vertices as usize, what)?,
            sizes: try_vec(faces as usize, what)?,
            indices: try_vec(indices as usize, what)?,
        })
    }

    /// Adds a vertex and returns its index.
    pub(crate) fn vertex(&mut self, p: DVec3) -> u32 {
        self.positions.push(p);
        self.positions.len() as u32 - 1
    }

    pub(crate) fn face(&mut self, corners: &[u32]) {
        self.sizes.push(corners.len() as u32);
        self.indices.extend_from_slice(corners);
    }

    /// The mesh, checked as [`Mesh::new`] checks a host's buffers. The
    /// operations build valid faces by construction; the check is linear and
    /// cheap next to them, and turns a case they missed (say, a coordinate
    /// pushed past `f64::MAX` by a huge argument) into an error instead of an
    /// invalid mesh.
    ///
    /// # Errors
    /// [`Error::DegenerateInput`] naming the operation and what is wrong.
    pub(crate) fn finish(self) -> Result<Mesh> {
        Mesh::new(self.positions, self.sizes, self.indices).map_err(|e| {
            Error::DegenerateInput(format!(
                "{} cannot make a valid mesh from this input: {e}",
                self.what
            ))
        })
    }
}

/// The mesh with its vertices moved by an operation that keeps the faces
/// (smoothing, offset, scaling).
///
/// # Errors
/// [`Error::DegenerateInput`] naming the first vertex moved to a non-finite
/// position: coordinates or arguments so large that the arithmetic
/// overflowed `f64`.
pub(crate) fn moved(mesh: &Mesh, positions: Vec<DVec3>, what: &str) -> Result<Mesh> {
    if let Some(v) = positions.iter().position(|p| !p.is_finite()) {
        let p = positions[v];
        return Err(Error::DegenerateInput(format!(
            "{what} moves vertex {v} to ({}, {}, {}); the coordinates or arguments are too large for f64 arithmetic",
            p.x, p.y, p.z
        )));
    }
    mesh.with_positions(positions).map_err(Error::from)
}

/// The average of a face's corners.
pub(crate) fn face_centroid(mesh: &Mesh, f: usize) -> DVec3 {
    let n = mesh.face(f).len() as f64;
    mesh.face_positions(f).sum::<DVec3>() / n
}

pub(crate) use crate::mesh::analysis::face_normal;

/// For each corner, the previous corner of its face.
pub(crate) fn corner_prev(mesh: &Mesh) -> Vec<u32> {
    let mut prev = vec![0u32; mesh.index_count()];
    for w in mesh.face_offsets().windows(2) {
        let (start, end) = (w[0], w[1]);
        prev[start as usize] = end - 1;
        for c in start + 1..end {
            prev[c as usize] = c - 1;
        }
    }
    prev
}

/// The faces around one vertex in order, as their corners at it.
#[derive(Debug, Clone)]
pub(crate) struct Fan {
    pub(crate) vertex: u32,
    /// Corners at `vertex`, counter-clockwise seen from the front: corner
    /// `k + 1`'s outgoing edge is corner `k`'s incoming edge.
    pub(crate) corners: Vec<u32>,
    /// Whether the last corner's incoming edge is the first's outgoing one.
    pub(crate) closed: bool,
}

/// The fans of every vertex, vertex by vertex. A fan stops at a naked edge,
/// a non-manifold edge, or an edge whose two faces run it the same way, so a
/// bow-tie vertex has two fans and a boundary vertex an open one.
pub(crate) fn vertex_fans(mesh: &Mesh, topology: &Topology) -> Vec<Fan> {
    let prev = corner_prev(mesh);
    let edges = topology.corner_edges();
    let vertices = topology.corner_vertices();
    // The corner at the same vertex across the incoming edge, if the fan goes on.
    let successor = |c: usize| -> Option<u32> {
        let e = edges[prev[c] as usize] as usize;
        match topology.edge_corners(e) {
            &[a, b] => {
                let other = if a as usize == prev[c] as usize { b } else { a };
                (vertices[other as usize] == vertices[c]).then_some(other)
            }
            _ => None,
        }
    };
    let mut has_predecessor = vec![false; mesh.index_count()];
    for c in 0..mesh.index_count() {
        if let Some(s) = successor(c) {
            has_predecessor[s as usize] = true;
        }
    }
    let mut visited = vec![false; mesh.index_count()];
    let mut fans = Vec::new();
    for v in 0..mesh.vertex_count() {
        let at_v = topology.vertex_corners(v);
        // Open fans first start where nothing leads in, then the cycles.
        let starts = at_v
            .iter()
            .filter(|&&c| !has_predecessor[c as usize])
            .chain(at_v.iter());
        for &start in starts {
            if visited[start as usize] {
                continue;
            }
            let mut corners = vec![start];
            visited[start as usize] = true;
            let mut closed = false;
            let mut c = start as usize;
            while let Some(s) = successor(c) {
                if s == start {
                    closed = true;
                    break;
                }
                if visited[s as usize] {
                    break;
                }
                visited[s as usize] = true;
                corners.push(s);
                c = s as usize;
            }
            fans.push(Fan {
                vertex: v as u32,
                corners,
                closed,
            });
        }
    }
    fans
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;

    #[test]
    fn cube_fans_are_closed_triples() {
        let cube = shapes::cube();
        let fans = vertex_fans(&cube, &Topology::new(&cube));
        assert_eq!(fans.len(), 8);
        assert!(fans.iter().all(|f| f.closed && f.corners.len() == 3));
    }

    #[test]
    fn grid_corner_fans_are_open() {
        let grid = shapes::quad_grid(2, 2);
        let fans = vertex_fans(&grid, &Topology::new(&grid));
        assert_eq!(fans.len(), 9);
        assert_eq!(fans.iter().filter(|f| f.closed).count(), 1);
        assert_eq!(fans[0].corners.len(), 1);
        assert_eq!(fans[1].corners.len(), 2);
    }

    #[test]
    fn size_check_names_the_counts() {
        let err = check_size("test", MAX_ELEMENTS + 1, 1, 1).unwrap_err();
        assert!(matches!(err, Error::ResultTooLarge(_)));
        assert!(err.to_string().contains(&(MAX_ELEMENTS + 1).to_string()));
    }
}
