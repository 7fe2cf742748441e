//! One level of a subdivision: its faces, their connectivity, and the plan
//! that turns the level's positions into the next level's.
//!
//! The connectivity is flat index arrays found by bucketing every face corner
//! under its lower vertex (as in [`crate::topology`]), without the mesh's
//! positions, so that a refiner can plan every level before it sees a single
//! coordinate.

use crate::error::{try_vec, Result};

/// Marks a missing index (a sharp edge has no wings).
pub(crate) const NONE: u32 = u32::MAX;

/// The faces of one level: sizes as offsets, vertices one face after another.
#[derive(Debug, Clone)]
pub(crate) struct Faces {
    pub(crate) vertex_count: usize,
    /// `offsets[f]..offsets[f + 1]` are face f's corners; one longer than the face count.
    pub(crate) offsets: Vec<u32>,
    pub(crate) indices: Vec<u32>,
}

impl Faces {
    pub(crate) fn face_count(&self) -> usize {
        self.offsets.len() - 1
    }

    pub(crate) fn corner_count(&self) -> usize {
        self.indices.len()
    }

    /// The next corner of the same face.
    #[inline]
    pub(crate) fn next(&self, corner: usize, face: usize) -> usize {
        if corner + 1 == self.offsets[face + 1] as usize {
            self.offsets[face] as usize
        } else {
            corner + 1
        }
    }

    /// The previous corner of the same face.
    #[inline]
    pub(crate) fn prev(&self, corner: usize, face: usize) -> usize {
        if corner == self.offsets[face] as usize {
            self.offsets[face + 1] as usize - 1
        } else {
            corner - 1
        }
    }
}

/// Edges and adjacency of a [`Faces`]. Edges are unique `[low, high]` vertex
/// pairs sorted ascending: this is the order of the edge points.
#[derive(Debug, Clone)]
pub(crate) struct Connectivity {
    pub(crate) edges: Vec<[u32; 2]>,
    /// For each corner, its face.
    pub(crate) corner_faces: Vec<u32>,
    /// For each corner, the edge from it to the next corner of its face.
    pub(crate) corner_edges: Vec<u32>,
    /// `edge_corners[edge_offsets[e]..edge_offsets[e + 1]]`: the corners on edge e, ascending.
    pub(crate) edge_offsets: Vec<u32>,
    pub(crate) edge_corners: Vec<u32>,
    /// `vertex_corners[vertex_offsets[v]..vertex_offsets[v + 1]]`: the corners at vertex v, ascending.
    pub(crate) vertex_offsets: Vec<u32>,
    pub(crate) vertex_corners: Vec<u32>,
}

impl Connectivity {
    /// Finds the edges and adjacency of `faces`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`] when the arrays cannot be reserved.
    pub(crate) fn new(faces: &Faces) -> Result<Connectivity> {
        let corner_count = faces.corner_count();
        let vertex_count = faces.vertex_count;
        let indices = &faces.indices;

        let mut corner_faces = try_vec(corner_count, "corner faces")?;
        for (f, w) in faces.offsets.windows(2).enumerate() {
            corner_faces.extend(std::iter::repeat_n(f as u32, (w[1] - w[0]) as usize));
        }

        // Bucket each corner's edge under its lower vertex; sorting each small
        // bucket by the higher vertex gives the edges in sorted order.
        let mut bucket_offsets = zeroed(vertex_count + 1, "edge buckets")?;
        let edge_end = |c: usize| {
            let a = indices[c];
            let b = indices[faces.next(c, corner_faces[c] as usize)];
            (a.min(b), a.max(b))
        };
        for c in 0..corner_count {
            bucket_offsets[edge_end(c).0 as usize + 1] += 1;
        }
        prefix_sum(&mut bucket_offsets);
        let mut fill = try_vec(vertex_count + 1, "edge buckets")?;
        fill.extend_from_slice(&bucket_offsets);
        let mut bucket: Vec<u64> = zeroed(corner_count, "edge buckets")?;
        for c in 0..corner_count {
            let (low, high) = edge_end(c);
            let slot = &mut fill[low as usize];
            bucket[*slot as usize] = (u64::from(high) << 32) | c as u64;
            *slot += 1;
        }
        drop(fill);

        let mut edges = try_vec(corner_count, "edges")?;
        let mut edge_offsets = try_vec(corner_count + 1, "edge offsets")?;
        let mut edge_corners = try_vec(corner_count, "edge corners")?;
        let mut corner_edges = zeroed(corner_count, "corner edges")?;
        edge_offsets.push(0u32);
        for low in 0..vertex_count {
            let entries =
                &mut bucket[bucket_offsets[low] as usize..bucket_offsets[low + 1] as usize];
            entries.sort_unstable();
            let mut previous_high = u32::MAX;
            for &entry in entries.iter() {
                let (high, corner) = ((entry >> 32) as u32, entry as u32);
                if high != previous_high {
                    if previous_high != u32::MAX {
                        edge_offsets.push(edge_corners.len() as u32);
                    }
                    edges.push([low as u32, high]);
                    previous_high = high;
                }
                corner_edges[corner as usize] = edges.len() as u32 - 1;
                edge_corners.push(corner);
            }
            if previous_high != u32::MAX {
                edge_offsets.push(edge_corners.len() as u32);
            }
        }
        drop(bucket);
        edges.shrink_to_fit();
        edge_offsets.shrink_to_fit();

        let mut vertex_offsets = zeroed(vertex_count + 1, "vertex corners")?;
        for &v in indices {
            vertex_offsets[v as usize + 1] += 1;
        }
        prefix_sum(&mut vertex_offsets);
        let mut fill = try_vec(vertex_count + 1, "vertex corners")?;
        fill.extend_from_slice(&vertex_offsets);
        let mut vertex_corners = zeroed(corner_count, "vertex corners")?;
        for (c, &v) in indices.iter().enumerate() {
            vertex_corners[fill[v as usize] as usize] = c as u32;
            fill[v as usize] += 1;
        }

        Ok(Connectivity {
            edges,
            corner_faces,
            corner_edges,
            edge_offsets,
            edge_corners,
            vertex_offsets,
            vertex_corners,
        })
    }

    pub(crate) fn edge_count(&self) -> usize {
        self.edges.len()
    }

    /// The corners on edge `e`: one per face using it.
    #[inline]
    pub(crate) fn edge_corners(&self, e: usize) -> &[u32] {
        &self.edge_corners[self.edge_offsets[e] as usize..self.edge_offsets[e + 1] as usize]
    }

    /// The corners at vertex `v`: one per face around it.
    #[inline]
    pub(crate) fn vertex_corners(&self, v: usize) -> &[u32] {
        &self.vertex_corners[self.vertex_offsets[v] as usize..self.vertex_offsets[v + 1] as usize]
    }
}

/// How a vertex point is made from its neighbourhood (OpenSubdiv's
/// `Sdc::Crease::Rule`, with the dart folded into smooth, which shares its mask).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub(crate) enum VertexRule {
    /// Interior manifold vertex: the scheme's smooth mask.
    Smooth = 0,
    /// On exactly two sharp edges: 3/4 the vertex, 1/8 each sharp neighbour.
    Crease = 1,
    /// Infinitely sharp: the vertex stays where it is.
    Corner = 2,
}

/// What the arithmetic pass needs to make one level from the previous one:
/// every new point as a gather of old points (and, for Catmull-Clark, of the
/// new face points).
#[derive(Debug, Clone)]
pub(crate) struct Plan {
    /// Vertex count of the level the plan reads.
    pub(crate) vertex_count: usize,
    /// The faces of the level the plan reads (for face points; empty for Loop).
    pub(crate) face_offsets: Vec<u32>,
    pub(crate) face_indices: Vec<u32>,
    /// Per edge `[a, b, wing, wing]`: the end vertices, then the two faces
    /// (Catmull-Clark) or opposite vertices (Loop) of a smooth edge, or
    /// [`NONE`] for a sharp edge, whose point is the midpoint.
    pub(crate) edges: Vec<[u32; 4]>,
    pub(crate) vertex_rules: Vec<VertexRule>,
    /// `vertex_ring[vertex_ring_offsets[v]..]`: a smooth vertex's neighbours
    /// (then, for Catmull-Clark, its faces); a crease vertex's two sharp
    /// neighbours; nothing for a corner.
    pub(crate) vertex_ring_offsets: Vec<u32>,
    pub(crate) vertex_ring: Vec<u32>,
}

impl Plan {
    pub(crate) fn edge_count(&self) -> usize {
        self.edges.len()
    }

    pub(crate) fn face_count(&self) -> usize {
        self.face_offsets.len().saturating_sub(1)
    }

    /// The ring of vertex `v` (see [`Plan::vertex_ring`]).
    #[inline]
    pub(crate) fn ring(&self, v: usize) -> &[u32] {
        &self.vertex_ring
            [self.vertex_ring_offsets[v] as usize..self.vertex_ring_offsets[v + 1] as usize]
    }
}

/// A vector of `n` zeros, reserved fallibly.
pub(crate) fn zeroed<T: Default + Clone>(n: usize, what: &str) -> Result<Vec<T>> {
    let mut v = try_vec(n, what)?;
    v.resize(n, T::default());
    Ok(v)
}

pub(crate) fn prefix_sum(counts: &mut [u32]) {
    for i in 1..counts.len() {
        counts[i] += counts[i - 1];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn connectivity_of_two_triangles() {
        let faces = Faces {
            vertex_count: 4,
            offsets: vec![0, 3, 6],
            indices: vec![0, 1, 2, 0, 2, 3],
        };
        let c = Connectivity::new(&faces).unwrap();
        assert_eq!(c.edges, vec![[0, 1], [0, 2], [0, 3], [1, 2], [2, 3]]);
        let diagonal = c.edges.iter().position(|&e| e == [0, 2]).unwrap();
        assert_eq!(c.edge_corners(diagonal), &[2, 3]);
        assert_eq!(c.vertex_corners(0), &[0, 3]);
        assert_eq!(c.corner_edges, vec![0, 3, 1, 1, 4, 2]);
    }
}
