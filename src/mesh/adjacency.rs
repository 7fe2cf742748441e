//! The one builder of edges and adjacency, shared by [`Topology`] and the
//! subdivision's levels: every face corner's edge is bucketed under its
//! lower vertex and each small bucket sorted by the higher vertex, so the
//! edges come out sorted without hashing pairs or comparing faces. Every
//! array is reserved fallibly: a mesh too large for memory is an error.
//!
//! Names used throughout: a *corner* is a position in the face indices; the
//! *edge of a corner* runs from that corner's vertex to the next corner's
//! vertex in the same face.
//!
//! [`Topology`]: crate::mesh::topology::Topology

use crate::buffers::{prefix_sum, try_copy, try_vec, zeroed};
use crate::error::Result;

/// Edges, and the corners on each edge and at each vertex.
#[derive(Debug, Clone, Default)]
pub(crate) struct Adjacency {
    /// Edges as `[low, high]` vertex pairs, sorted. A pair is unique except
    /// where a face repeats a vertex: a degenerate edge `[v, v]`, and a pair
    /// a face meets twice, get one edge per such corner (after the shared
    /// first), as OpenSubdiv gives them.
    pub(crate) edges: Vec<[u32; 2]>,
    /// For each corner, the edge from it to the next corner of its face.
    pub(crate) corner_edges: Vec<u32>,
    /// `edge_corners[edge_offsets[e]..edge_offsets[e + 1]]` are the corners whose edge is e, ascending.
    pub(crate) edge_offsets: Vec<u32>,
    pub(crate) edge_corners: Vec<u32>,
    /// `vertex_corners[vertex_offsets[v]..vertex_offsets[v + 1]]` are the corners at vertex v, ascending.
    pub(crate) vertex_offsets: Vec<u32>,
    pub(crate) vertex_corners: Vec<u32>,
}

impl Adjacency {
    /// The edges and adjacency of faces over `vertex_count` vertices whose
    /// corners hold the vertices `indices`; `next(c)` is the corner after
    /// `c` in its face, `face_of(c)` its face.
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`] when the arrays cannot be reserved.
    pub(crate) fn build(
        vertex_count: usize,
        indices: &[u32],
        next: impl Fn(usize) -> usize,
        face_of: impl Fn(usize) -> usize,
    ) -> Result<Adjacency> {
        let corner_count = indices.len();
        let edge_ends = |c: usize| {
            let (a, b) = (indices[c], indices[next(c)]);
            (a.min(b), a.max(b))
        };

        // Bucket each corner's edge under its lower vertex; sorting each small
        // bucket by the higher vertex gives the edges in sorted order.
        let mut bucket_offsets = zeroed(vertex_count + 1, "edge buckets")?;
        for c in 0..corner_count {
            bucket_offsets[edge_ends(c).0 as usize + 1] += 1;
        }
        prefix_sum(&mut bucket_offsets);
        let mut fill = try_copy(&bucket_offsets, "edge buckets")?;
        let mut bucket: Vec<u64> = zeroed(corner_count, "edge buckets")?;
        for c in 0..corner_count {
            let (low, high) = edge_ends(c);
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
        let mut add_edge = |pair: [u32; 2], corners: &mut dyn Iterator<Item = u32>| {
            let e = edges.len() as u32;
            edges.push(pair);
            for corner in corners {
                corner_edges[corner as usize] = e;
                edge_corners.push(corner);
            }
            edge_offsets.push(edge_corners.len() as u32);
        };
        let corner_of = |entry: u64| entry as u32;
        let high_of = |entry: u64| (entry >> 32) as u32;
        for low in 0..vertex_count {
            let entries =
                &mut bucket[bucket_offsets[low] as usize..bucket_offsets[low + 1] as usize];
            entries.sort_unstable();
            for run in entries.chunk_by(|x, y| high_of(*x) == high_of(*y)) {
                let pair = [low as u32, high_of(run[0])];
                // Corners of one face are contiguous, so a face meeting the
                // pair again follows its earlier corner in the run.
                let again = |k: usize| {
                    k > 0
                        && face_of(corner_of(run[k - 1]) as usize)
                            == face_of(corner_of(run[k]) as usize)
                };
                let degenerate = pair[0] == pair[1];
                if !degenerate && (1..run.len()).all(|k| !again(k)) {
                    add_edge(pair, &mut run.iter().map(|&x| corner_of(x)));
                    continue;
                }
                // As OpenSubdiv builds edges from faces: every corner of a
                // degenerate edge, and every corner meeting the pair again in
                // its face, has an edge of its own; the other corners share
                // the first.
                if !degenerate {
                    add_edge(
                        pair,
                        &mut (0..run.len())
                            .filter(|&k| !again(k))
                            .map(|k| corner_of(run[k])),
                    );
                }
                for k in (0..run.len()).filter(|&k| degenerate || again(k)) {
                    add_edge(pair, &mut std::iter::once(corner_of(run[k])));
                }
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
        let mut fill = try_copy(&vertex_offsets, "vertex corners")?;
        let mut vertex_corners = zeroed(corner_count, "vertex corners")?;
        for (c, &v) in indices.iter().enumerate() {
            vertex_corners[fill[v as usize] as usize] = c as u32;
            fill[v as usize] += 1;
        }

        Ok(Adjacency::from_parts(
            (edges, corner_edges),
            (edge_offsets, edge_corners),
            (vertex_offsets, vertex_corners),
        ))
    }

    /// The adjacency of its three parts as the builders make them: the
    /// edges and each corner's edge, each edge's corners (offsets and
    /// list), each vertex's corners (offsets and list).
    pub(crate) fn from_parts(
        (edges, corner_edges): (Vec<[u32; 2]>, Vec<u32>),
        (edge_offsets, edge_corners): (Vec<u32>, Vec<u32>),
        (vertex_offsets, vertex_corners): (Vec<u32>, Vec<u32>),
    ) -> Adjacency {
        Adjacency {
            edges,
            corner_edges,
            edge_offsets,
            edge_corners,
            vertex_offsets,
            vertex_corners,
        }
    }

    /// Number of edges.
    #[inline]
    pub(crate) fn edge_count(&self) -> usize {
        self.edges.len()
    }

    /// The corners whose edge is `e`, ascending (so their faces ascend too).
    #[inline]
    pub(crate) fn edge_corners(&self, e: usize) -> &[u32] {
        &self.edge_corners[self.edge_offsets[e] as usize..self.edge_offsets[e + 1] as usize]
    }

    /// The corners at vertex `v`, ascending.
    #[inline]
    pub(crate) fn vertex_corners(&self, v: usize) -> &[u32] {
        &self.vertex_corners[self.vertex_offsets[v] as usize..self.vertex_offsets[v + 1] as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::Adjacency;

    /// Builds the adjacency of polygons given as vertex lists.
    fn adjacency(vertex_count: usize, faces: &[&[u32]]) -> Adjacency {
        let indices: Vec<u32> = faces.iter().flat_map(|f| f.iter().copied()).collect();
        let mut face_of = Vec::new();
        let mut next = Vec::new();
        for (f, face) in faces.iter().enumerate() {
            let start = face_of.len();
            face_of.extend(std::iter::repeat_n(f, face.len()));
            next.extend((1..face.len()).map(|k| start + k));
            next.push(start);
        }
        Adjacency::build(vertex_count, &indices, |c| next[c], |c| face_of[c]).unwrap()
    }

    #[test]
    fn a_face_repeating_a_vertex_gets_edges_as_opensubdiv_gives_them() {
        // Face 0 meets {1, 4} three times and has a degenerate edge [2, 2];
        // face 1 runs 4 -> 1 again: it shares the pair's first edge.
        let a = adjacency(6, &[&[1, 2, 2, 5, 4, 1, 4], &[4, 1, 0]]);
        let edges_of = |pair: [u32; 2]| -> Vec<usize> {
            (0..a.edge_count())
                .filter(|&e| a.edges[e] == pair)
                .collect()
        };
        let pair = edges_of([1, 4]);
        assert_eq!(pair.len(), 3);
        // Face 0's corners 4 (4 -> 1), 5 (1 -> 4), 6 (4 -> 1), face 1's corner 7 (4 -> 1).
        assert_eq!(a.edge_corners(pair[0]), &[4, 7]);
        assert_eq!(a.edge_corners(pair[1]), &[5]);
        assert_eq!(a.edge_corners(pair[2]), &[6]);
        assert_eq!(edges_of([2, 2]).len(), 1);
        assert!(a.edges.windows(2).all(|w| w[0] <= w[1]));
        for c in 0..9 {
            assert!(a
                .edge_corners(a.corner_edges[c] as usize)
                .contains(&(c as u32)));
        }
        // Without repeats every pair has one edge.
        let plain = adjacency(4, &[&[0, 1, 2], &[2, 1, 3]]);
        assert_eq!(plain.edge_count(), 5);
    }
}
