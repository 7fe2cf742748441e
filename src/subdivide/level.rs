//! One level of a subdivision: its faces and their connectivity.
//!
//! The connectivity is flat index arrays, without the mesh's positions, so
//! that a refiner can plan every level before it sees a single coordinate.
//! The cage's is found by bucketing every face corner under its lower vertex
//! (as in [`crate::mesh::topology`]); every refined level's is written
//! arithmetically from its parent's ([`Connectivity::refine`]): the child
//! edges, corners and rings of each parent vertex, edge and face have a known
//! place, so no sorting of the whole level is needed.

mod refine;

pub(crate) use refine::LoopInsideEdges;

use std::borrow::Cow;

use super::scheme::{check_counts, Scheme};
use crate::buffers::{par_map, prefix_sum, try_copy, try_vec, zeroed};
use crate::error::Result;
use crate::mesh::adjacency::Adjacency;

/// Marks a missing index (a sharp edge has no wings).
pub(crate) const NONE: u32 = u32::MAX;

/// The faces of one level: sizes as offsets, vertices one face after another.
/// A cage's faces read its mesh's indices in place (`'a`); a refined
/// level's faces own theirs (`Faces<'static>`).
#[derive(Debug, Clone, Default)]
pub(crate) struct Faces<'a> {
    pub(crate) vertex_count: usize,
    /// The corner count of every face when all have 3 or all have 4 (every
    /// refined level), else 0: corners then find their face and neighbours
    /// by arithmetic instead of reading the offsets.
    pub(crate) size: u32,
    /// `offsets[f]..offsets[f + 1]` are face f's corners; one longer than the
    /// face count, or empty for faces of uniform `size` that dropped them
    /// (see [`Faces::drop_uniform_offsets`]).
    pub(crate) offsets: Cow<'a, [u32]>,
    pub(crate) indices: Cow<'a, [u32]>,
}

impl<'a> Faces<'a> {
    /// The faces of a mesh (a cage), its indices (and offsets, when its
    /// faces differ in size) read in place.
    pub(crate) fn of_mesh(mesh: &'a crate::Mesh) -> Faces<'a> {
        let size = match mesh.face_count() {
            0 => 0,
            _ if mesh.is_quad_mesh() => 4,
            _ if mesh.is_triangle_mesh() => 3,
            _ => 0,
        };
        // Faces of one size have arithmetic offsets: the mesh need not
        // write its own.
        let offsets = match size {
            0 => Cow::Borrowed(mesh.face_offsets()),
            size => Cow::Owned((0..=mesh.face_count() as u32).map(|f| f * size).collect()),
        };
        Faces {
            vertex_count: mesh.vertex_count(),
            size,
            offsets,
            indices: Cow::Borrowed(mesh.face_indices()),
        }
    }

    /// The same faces with arrays of their own, copied when borrowed.
    pub(crate) fn into_owned(self) -> Faces<'static> {
        Faces {
            vertex_count: self.vertex_count,
            size: self.size,
            offsets: Cow::Owned(self.offsets.into_owned()),
            indices: Cow::Owned(self.indices.into_owned()),
        }
    }

    /// Drops the offsets of faces of one size, whose corners are then
    /// found by arithmetic (every refined level's faces are of one size).
    pub(crate) fn drop_uniform_offsets(&mut self) {
        if self.size != 0 {
            self.offsets = Cow::Owned(Vec::new());
        }
    }

    pub(crate) fn face_count(&self) -> usize {
        match self.offsets.len() {
            0 if self.size != 0 => self.indices.len() / self.size as usize,
            0 => 0,
            n => n - 1,
        }
    }

    /// Each face's corner count, read from the offsets (which these faces
    /// must have).
    pub(crate) fn sizes(&self) -> Vec<u32> {
        self.offsets.windows(2).map(|w| w[1] - w[0]).collect()
    }

    pub(crate) fn corner_count(&self) -> usize {
        self.indices.len()
    }

    /// The corners of face `f`.
    #[inline]
    pub(crate) fn corners(&self, f: usize) -> std::ops::Range<usize> {
        match self.size {
            0 => self.offsets[f] as usize..self.offsets[f + 1] as usize,
            size => f * size as usize..(f + 1) * size as usize,
        }
    }

    /// The vertices of face `f`.
    #[inline]
    pub(crate) fn face(&self, f: usize) -> &[u32] {
        &self.indices[self.corners(f)]
    }

    /// The next corner of the same face (`face` is the corner's).
    #[inline]
    pub(crate) fn next(&self, corner: usize, face: usize) -> usize {
        match self.size {
            4 => (corner & !3) | ((corner + 1) & 3),
            3 if corner % 3 == 2 => corner - 2,
            3 => corner + 1,
            _ if corner + 1 == self.offsets[face + 1] as usize => self.offsets[face] as usize,
            _ => corner + 1,
        }
    }

    /// The previous corner of the same face (`face` is the corner's).
    #[inline]
    pub(crate) fn prev(&self, corner: usize, face: usize) -> usize {
        match self.size {
            4 => (corner & !3) | ((corner + 3) & 3),
            3 if corner % 3 == 0 => corner + 2,
            3 => corner - 1,
            _ if corner == self.offsets[face] as usize => self.offsets[face + 1] as usize - 1,
            _ => corner - 1,
        }
    }
}

/// The offsets of `face_count` faces of `size` corners each, when
/// `wanted` (else empty: a last level of uniform size needs none).
///
/// # Errors
/// [`crate::Error::OutOfMemory`].
pub(crate) fn uniform_offsets(face_count: usize, size: u32, wanted: bool) -> Result<Vec<u32>> {
    if !wanted {
        return Ok(Vec::new());
    }
    par_map(face_count + 1, "child faces", |f| size * f as u32)
}

/// Edges and adjacency of a [`Faces`]: the mesh's [`Adjacency`] (read
/// through it: `connectivity.edges`, `connectivity.edge_corners(e)`), plus
/// each corner's face and each vertex's edges. Edges are unique
/// `[low, high]` vertex pairs sorted ascending: this is the order of the
/// edge points.
#[derive(Debug, Clone, Default)]
pub(crate) struct Connectivity {
    pub(crate) adjacency: Adjacency,
    /// The faces' [`Faces::size`]: when not 0, a corner's face is arithmetic.
    pub(crate) face_size: u32,
    /// For each corner, its face; empty when `face_size` is not 0 (see [`Connectivity::face_of`]).
    pub(crate) corner_faces: Vec<u32>,
    /// `vertex_edges[vertex_edge_offsets[v]..vertex_edge_offsets[v + 1]]`: the edges at vertex v, ascending.
    pub(crate) vertex_edge_offsets: Vec<u32>,
    pub(crate) vertex_edges: Vec<u32>,
}

impl std::ops::Deref for Connectivity {
    type Target = Adjacency;

    #[inline]
    fn deref(&self) -> &Adjacency {
        &self.adjacency
    }
}

impl Connectivity {
    /// The faces and connectivity of a cage that `levels` levels of
    /// `scheme` will refine, once every level's size is checked. Without
    /// `vertex_edges` the vertices' edges are left empty: only the
    /// refinement of a level and Catmull-Clark's refined gathers read them,
    /// so one level of plain subdivision never does.
    ///
    /// # Errors
    /// [`crate::Error::ResultTooLarge`] when a level would pass the size cap;
    /// [`crate::Error::OutOfMemory`].
    pub(crate) fn of_cage(
        cage: &crate::Mesh,
        scheme: Scheme,
        levels: u32,
        vertex_edges: bool,
    ) -> Result<(Faces<'_>, Connectivity)> {
        let faces = Faces::of_mesh(cage);
        let connectivity = Connectivity::build(&faces, vertex_edges)?;
        check_counts(
            scheme,
            cage.vertex_count() as u64,
            connectivity.edge_count() as u64,
            cage.face_count() as u64,
            cage.index_count() as u64,
            levels,
        )?;
        Ok((faces, connectivity))
    }

    /// Finds the edges and adjacency of `faces`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`] when the arrays cannot be reserved.
    pub(crate) fn new(faces: &Faces) -> Result<Connectivity> {
        Connectivity::build(faces, true)
    }

    /// As [`Connectivity::new`], the vertices' edges only when asked for.
    fn build(faces: &Faces, with_vertex_edges: bool) -> Result<Connectivity> {
        let corner_count = faces.corner_count();
        let vertex_count = faces.vertex_count;

        let mut corner_faces = Vec::new();
        if faces.size == 0 {
            corner_faces = try_vec(corner_count, "corner faces")?;
            for (f, w) in faces.offsets.windows(2).enumerate() {
                corner_faces.extend(std::iter::repeat_n(f as u32, (w[1] - w[0]) as usize));
            }
        }
        let face_of = |c: usize| match faces.size {
            0 => corner_faces[c] as usize,
            size => c / size as usize,
        };
        let adjacency = Adjacency::build(
            vertex_count,
            &faces.indices,
            |c| faces.next(c, face_of(c)),
            face_of,
        )?;
        let (vertex_edge_offsets, vertex_edges) = match with_vertex_edges {
            true => vertex_edges_of(&adjacency.edges, vertex_count)?,
            false => (Vec::new(), Vec::new()),
        };
        Ok(Connectivity {
            adjacency,
            face_size: faces.size,
            corner_faces,
            vertex_edge_offsets,
            vertex_edges,
        })
    }

    /// The face of corner `c`.
    #[inline]
    pub(crate) fn face_of(&self, c: usize) -> usize {
        match self.face_size {
            0 => self.corner_faces[c] as usize,
            // Known sizes divide by a constant: no division instruction.
            3 => c / 3,
            4 => c / 4,
            size => c / size as usize,
        }
    }

    /// Frees all but what the next level's faces are written from (the
    /// edges' count, each corner's edge and face): once a level's points
    /// are made, its faces are all that is left to write.
    pub(crate) fn keep_only_corner_edges(&mut self) {
        for list in [
            &mut self.adjacency.edge_offsets,
            &mut self.adjacency.edge_corners,
            &mut self.adjacency.vertex_offsets,
            &mut self.adjacency.vertex_corners,
            &mut self.vertex_edge_offsets,
            &mut self.vertex_edges,
        ] {
            *list = Vec::new();
        }
    }

    /// The edges at vertex `v`, ascending.
    #[inline]
    pub(crate) fn vertex_edges(&self, v: usize) -> &[u32] {
        &self.vertex_edges
            [self.vertex_edge_offsets[v] as usize..self.vertex_edge_offsets[v + 1] as usize]
    }

    /// The edge joining vertices `a` and `b` (either order), if there is one.
    pub(crate) fn find_edge(&self, a: u32, b: u32) -> Option<u32> {
        let (low, high) = (a.min(b), a.max(b));
        let vertex_count = self.vertex_edge_offsets.len().saturating_sub(1);
        if low == high || high as usize >= vertex_count {
            return None;
        }
        self.vertex_edges(low as usize)
            .iter()
            .copied()
            .find(|&e| self.edges[e as usize] == [low, high])
    }

    /// Loop: visits the edges inside the child triangles whose lower parent
    /// edge is m, unsorted, as (higher parent edge, triangle). Each corner
    /// of m, in triangle f, gives f's other two edges above m; m is never
    /// above itself, so f's three edges are read without finding m.
    #[inline]
    pub(crate) fn loop_inside_edges(&self, m: usize, mut visit: impl FnMut(u32, u32)) {
        for &c in self.edge_corners(m) {
            let f = c / 3;
            let first = 3 * f as usize;
            for &h in &self.corner_edges[first..first + 3] {
                if h as usize > m {
                    visit(h, f);
                }
            }
        }
    }

    /// The end of edge `vertex_edges[s]` whose list holds slot `s`.
    #[inline]
    pub(crate) fn slot_vertex(&self, s: usize) -> u32 {
        let [a, b] = self.edges[self.vertex_edges[s] as usize];
        // Of the edge's ends, the lower owns the lower range of slots.
        if (s as u32) < self.vertex_edge_offsets[a as usize + 1] {
            a
        } else {
            b
        }
    }

    /// Catmull-Clark: the edges of the child quad at corner `c` of `faces`
    /// (whose connectivity this is), in the quad's corner order:
    /// `[v_c, e_c]`, `[e_c, f]`, `[f, e_prev]`, `[e_prev, v_c]` (see
    /// [`Connectivity::refine`] for the child edges' order).
    #[inline]
    pub(crate) fn child_quad_edges(&self, faces: &Faces, c: usize) -> [u32; 4] {
        let two_e = 2 * self.edge_count() as u32;
        let v = faces.indices[c];
        let previous = faces.prev(c, self.face_of(c));
        [
            self.vertex_edge_slot(v, self.corner_edges[c]),
            two_e + self.edge_corner_slot(c),
            two_e + self.edge_corner_slot(previous),
            self.vertex_edge_slot_arriving(v, self.corner_edges[previous]),
        ]
    }

    /// [`Connectivity::child_quad_edges`] of the four corners of quad `q`
    /// of `faces`, which are all quads: each edge-corner slot, which two
    /// corners' child quads share, is found once.
    #[inline]
    pub(crate) fn child_quad_edges_of_quad(&self, faces: &Faces, q: usize) -> [[u32; 4]; 4] {
        let two_e = 2 * self.edge_count() as u32;
        let first = 4 * q;
        let edges = &self.corner_edges[first..first + 4];
        let vertices = &faces.indices[first..first + 4];
        let mut inside = [0u32; 4];
        for (j, slot) in inside.iter_mut().enumerate() {
            *slot = two_e + self.edge_corner_slot(first + j);
        }
        let mut quads = [[0u32; 4]; 4];
        for (j, quad) in quads.iter_mut().enumerate() {
            let previous = (j + 3) % 4;
            *quad = [
                self.vertex_edge_slot(vertices[j], edges[j]),
                inside[j],
                inside[previous],
                self.vertex_edge_slot_arriving(vertices[j], edges[previous]),
            ];
        }
        quads
    }

    /// Where edge `e` (one of vertex `v`'s) sits in `vertex_edges`; for a
    /// degenerate edge `[v, v]`, listed twice, the slot of the end it
    /// leaves `v` from.
    #[inline]
    pub(crate) fn vertex_edge_slot(&self, v: u32, e: u32) -> u32 {
        self.vertex_edge_offsets[v as usize] + position(self.vertex_edges(v as usize), e)
    }

    /// As [`Connectivity::vertex_edge_slot`], but for a degenerate edge the
    /// slot of the end it arrives at `v` by.
    #[inline]
    pub(crate) fn vertex_edge_slot_arriving(&self, v: u32, e: u32) -> u32 {
        self.vertex_edge_offsets[v as usize] + last_position(self.vertex_edges(v as usize), e)
    }

    /// Whether the child edge of vertex-edge slot `s` (the half of its edge
    /// at `v`) belongs to the child face at corner `c` of that edge, rather
    /// than to the one at the corner after `c`.
    #[inline]
    pub(crate) fn slot_leaves_at(&self, s: usize, v: u32, c: usize, indices: &[u32]) -> bool {
        let e = self.vertex_edges[s];
        let [a, b] = self.edges[e as usize];
        if a == b {
            s as u32 == self.vertex_edge_slot(v, e)
        } else {
            indices[c] == v
        }
    }

    /// Where corner `c` sits in `edge_corners`.
    #[inline]
    pub(crate) fn edge_corner_slot(&self, c: usize) -> u32 {
        let e = self.corner_edges[c] as usize;
        self.edge_offsets[e] + position(self.edge_corners(e), c as u32)
    }
}

/// Lists up to this long are scanned; longer ones (around a vertex of
/// high valence, along an edge of many faces) are searched by halves, so
/// that finding each of a vertex's edges is not quadratic in its valence.
pub(super) const SCANNED: usize = 16;

/// The first index of `x` in `list`, ascending, which holds it.
#[inline]
pub(crate) fn position(list: &[u32], x: u32) -> u32 {
    let k = if list.len() <= SCANNED {
        list.iter().position(|&y| y == x)
    } else {
        Some(list.partition_point(|&y| y < x)).filter(|&k| list.get(k) == Some(&x))
    };
    k.unwrap_or(0) as u32
}

/// The last index of `x` in `list`, ascending, which holds it.
#[inline]
pub(crate) fn last_position(list: &[u32], x: u32) -> u32 {
    let k = if list.len() <= SCANNED {
        list.iter().rposition(|&y| y == x)
    } else {
        let after = list.partition_point(|&y| y <= x);
        after.checked_sub(1).filter(|&k| list[k] == x)
    };
    k.unwrap_or(0) as u32
}

/// Every vertex's edges, ascending, from the sorted edges.
pub(crate) fn vertex_edges_of(
    edges: &[[u32; 2]],
    vertex_count: usize,
) -> Result<(Vec<u32>, Vec<u32>)> {
    let mut offsets = zeroed(vertex_count + 1, "vertex edges")?;
    for &[a, b] in edges {
        offsets[a as usize + 1] += 1;
        offsets[b as usize + 1] += 1;
    }
    prefix_sum(&mut offsets);
    let mut fill = try_copy(&offsets, "vertex edges")?;
    let mut list = zeroed(2 * edges.len(), "vertex edges")?;
    for (e, &[a, b]) in edges.iter().enumerate() {
        for v in [a as usize, b as usize] {
            list[fill[v] as usize] = e as u32;
            fill[v] += 1;
        }
    }
    Ok((offsets, list))
}

#[cfg(test)]
mod tests;
