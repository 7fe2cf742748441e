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
    /// Unique edges as `[low, high]` vertex pairs, sorted.
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
    /// `c` in its face.
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`] when the arrays cannot be reserved.
    pub(crate) fn build(
        vertex_count: usize,
        indices: &[u32],
        next: impl Fn(usize) -> usize,
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

    /// Number of unique edges.
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
