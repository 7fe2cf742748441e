//! One level of a subdivision: its faces, their connectivity, and the plan
//! that turns the level's positions into the next level's.
//!
//! The connectivity is flat index arrays, without the mesh's positions, so
//! that a refiner can plan every level before it sees a single coordinate.
//! The cage's is found by bucketing every face corner under its lower vertex
//! (as in [`crate::mesh::topology`]); every refined level's is written
//! arithmetically from its parent's ([`Connectivity::refine`]): the child
//! edges, corners and rings of each parent vertex, edge and face have a known
//! place, so no sorting of the whole level is needed.

use super::Scheme;
use crate::buffers::{
    fill_by_offsets, flatten, par_map, par_offsets, prefix_sum, try_copy, try_vec, zeroed,
};
use crate::error::Result;
use crate::mesh::adjacency::Adjacency;

/// Marks a missing index (a sharp edge has no wings).
pub(crate) const NONE: u32 = u32::MAX;

/// The faces of one level: sizes as offsets, vertices one face after another.
#[derive(Debug, Clone)]
pub(crate) struct Faces {
    pub(crate) vertex_count: usize,
    /// The corner count of every face when all have 3 or all have 4 (every
    /// refined level), else 0: corners then find their face and neighbours
    /// by arithmetic instead of reading the offsets.
    pub(crate) size: u32,
    /// `offsets[f]..offsets[f + 1]` are face f's corners; one longer than the
    /// face count, or empty for a last level of uniform `size`.
    pub(crate) offsets: Vec<u32>,
    pub(crate) indices: Vec<u32>,
}

impl Faces {
    /// The faces of a mesh (a cage).
    pub(crate) fn of_mesh(mesh: &crate::Mesh) -> Faces {
        let size = match mesh.face_sizes().first() {
            Some(&first @ (3 | 4)) if mesh.face_sizes().iter().all(|&s| s == first) => first,
            _ => 0,
        };
        Faces {
            vertex_count: mesh.vertex_count(),
            size,
            offsets: mesh.face_offsets().to_vec(),
            indices: mesh.face_indices().to_vec(),
        }
    }

    pub(crate) fn face_count(&self) -> usize {
        match self.offsets.len() {
            0 if self.size != 0 => self.indices.len() / self.size as usize,
            0 => 0,
            n => n - 1,
        }
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

/// Edges and adjacency of a [`Faces`]. Edges are unique `[low, high]` vertex
/// pairs sorted ascending: this is the order of the edge points.
#[derive(Debug, Clone, Default)]
pub(crate) struct Connectivity {
    pub(crate) edges: Vec<[u32; 2]>,
    /// The faces' [`Faces::size`]: when not 0, a corner's face is arithmetic.
    pub(crate) face_size: u32,
    /// For each corner, its face; empty when `face_size` is not 0 (see [`Connectivity::face_of`]).
    pub(crate) corner_faces: Vec<u32>,
    /// For each corner, the edge from it to the next corner of its face.
    pub(crate) corner_edges: Vec<u32>,
    /// `edge_corners[edge_offsets[e]..edge_offsets[e + 1]]`: the corners on edge e, ascending.
    pub(crate) edge_offsets: Vec<u32>,
    pub(crate) edge_corners: Vec<u32>,
    /// `vertex_corners[vertex_offsets[v]..vertex_offsets[v + 1]]`: the corners at vertex v, ascending.
    pub(crate) vertex_offsets: Vec<u32>,
    pub(crate) vertex_corners: Vec<u32>,
    /// `vertex_edges[vertex_edge_offsets[v]..vertex_edge_offsets[v + 1]]`: the edges at vertex v, ascending.
    pub(crate) vertex_edge_offsets: Vec<u32>,
    pub(crate) vertex_edges: Vec<u32>,
}

impl Connectivity {
    /// Finds the edges and adjacency of `faces`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`] when the arrays cannot be reserved.
    pub(crate) fn new(faces: &Faces) -> Result<Connectivity> {
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
        let Adjacency {
            edges,
            corner_edges,
            edge_offsets,
            edge_corners,
            vertex_offsets,
            vertex_corners,
        } = Adjacency::build(vertex_count, &faces.indices, |c| faces.next(c, face_of(c)))?;
        let (vertex_edge_offsets, vertex_edges) = vertex_edges_of(&edges, vertex_count)?;

        Ok(Connectivity {
            edges,
            face_size: faces.size,
            corner_faces,
            corner_edges,
            edge_offsets,
            edge_corners,
            vertex_offsets,
            vertex_corners,
            vertex_edge_offsets,
            vertex_edges,
        })
    }

    /// The connectivity of the level `scheme` makes from `faces`, whose
    /// connectivity is `self`, written from the parent's without sorting. Equal
    /// to [`Connectivity::new`] of the child faces. The vertices' edges, only
    /// needed to refine once more (as the one-shot's refined gathers do
    /// without building the result), are left empty unless `vertex_edges`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`].
    pub(crate) fn refine(
        &self,
        scheme: Scheme,
        faces: &Faces,
        vertex_edges: bool,
    ) -> Result<Connectivity> {
        match scheme {
            Scheme::CatmullClark => self.refine_catmull_clark(faces, vertex_edges),
            Scheme::Loop => self.refine_loop(faces, vertex_edges),
        }
    }

    /// Catmull-Clark: parent corner c of face f becomes quad c =
    /// `[v_c, V + e_c, V + E + f, V + e_prev]`. The child edges, sorted, are
    /// `[v, V + e]` for every vertex v and its edges e in order (the slots of
    /// `vertex_edges`), then `[V + e, V + E + f]` for every edge e and its
    /// corners in order (the slots of `edge_corners`).
    fn refine_catmull_clark(&self, faces: &Faces, with_vertex_edges: bool) -> Result<Connectivity> {
        let (v_count, e_count, c_count) =
            (faces.vertex_count, self.edge_count(), faces.corner_count());
        let idx = &faces.indices;
        let (v_base, f_base, two_e) = (v_count as u32, (v_count + e_count) as u32, 2 * e_count);
        let next = |c: usize| faces.next(c, self.face_of(c));
        let edge_slots = two_e + c_count;
        // Child edge s < 2E is [v, V + e] for vertex-edge slot s; child edge
        // 2E + k is [V + e, F + f] for edge-corner slot k (corner c on e, in
        // face f). Every array below is written slot by slot in parallel.
        let slot_vertex = |s: usize| self.slot_vertex(s);

        // The arrays are independent of each other: built side by side.
        let build_edges = || -> Result<Vec<[u32; 2]>> {
            par_map(edge_slots, "edges", |s| match s.checked_sub(two_e) {
                None => [slot_vertex(s), v_base + self.vertex_edges[s]],
                Some(k) => {
                    let c = self.edge_corners[k] as usize;
                    [
                        v_base + self.corner_edges[c],
                        f_base + self.face_of(c) as u32,
                    ]
                }
            })
        };

        // Quad c's edges: [v_c, e_c], [e_c, f], [f, e_prev], [e_prev, v_c].
        let build_corner_edges = || -> Result<Vec<u32>> {
            let quads = par_map(c_count, "corner edges", |c| self.child_quad_edges(faces, c))?;
            Ok(flatten(quads))
        };

        let build_edge_corners = || -> Result<(Vec<u32>, Vec<u32>)> {
            let edge_offsets = par_offsets(edge_slots, "edge offsets", |s| {
                if s < two_e {
                    self.edge_corners(self.vertex_edges[s] as usize).len() as u32
                } else {
                    2
                }
            })?;
            let edge_corners = fill_by_offsets(&edge_offsets, "edge corners", |s, out| {
                if s < two_e {
                    let v = slot_vertex(s);
                    let corners = self.edge_corners(self.vertex_edges[s] as usize);
                    for (out, &c) in out.iter_mut().zip(corners) {
                        let c = c as usize;
                        *out = if idx[c] == v {
                            4 * c as u32
                        } else {
                            4 * next(c) as u32 + 3
                        };
                    }
                    out.sort_unstable();
                } else {
                    let c = self.edge_corners[s - two_e] as usize;
                    let (a, b) = (4 * c as u32 + 1, 4 * next(c) as u32 + 2);
                    out.copy_from_slice(&[a.min(b), a.max(b)]);
                }
            })?;
            Ok((edge_offsets, edge_corners))
        };

        // Child vertex u is parent vertex u, then the points of the parent's
        // edges (from V), then of its faces (from V + E).
        let child_vertices = v_count + e_count + faces.face_count();
        let build_vertex_corners = || -> Result<(Vec<u32>, Vec<u32>)> {
            let vertex_offsets = par_offsets(child_vertices, "vertex corners", |u| {
                (match u {
                    u if u < v_count => self.vertex_corners(u).len(),
                    u if u < v_count + e_count => 2 * self.edge_corners(u - v_count).len(),
                    u => faces.corners(u - v_count - e_count).len(),
                }) as u32
            })?;
            let vertex_corners = fill_by_offsets(&vertex_offsets, "vertex corners", |u, out| {
                if u < v_count {
                    for (out, &c) in out.iter_mut().zip(self.vertex_corners(u)) {
                        *out = 4 * c;
                    }
                } else if u < v_count + e_count {
                    let corners = self.edge_corners(u - v_count);
                    for (pair, &c) in out.chunks_exact_mut(2).zip(corners) {
                        pair.copy_from_slice(&[4 * c + 1, 4 * next(c as usize) as u32 + 3]);
                    }
                    out.sort_unstable();
                } else {
                    for (out, c) in out.iter_mut().zip(faces.corners(u - v_count - e_count)) {
                        *out = 4 * c as u32 + 2;
                    }
                }
            })?;
            Ok((vertex_offsets, vertex_corners))
        };

        let build_vertex_edges = || -> Result<(Vec<u32>, Vec<u32>)> {
            if !with_vertex_edges {
                return Ok((Vec::new(), Vec::new()));
            }
            let vertex_edge_offsets = par_offsets(child_vertices, "vertex edges", |u| {
                (match u {
                    u if u < v_count => self.vertex_edges(u).len(),
                    u if u < v_count + e_count => 2 + self.edge_corners(u - v_count).len(),
                    u => faces.corners(u - v_count - e_count).len(),
                }) as u32
            })?;
            let vertex_edges = fill_by_offsets(&vertex_edge_offsets, "vertex edges", |u, out| {
                if u < v_count {
                    let slots = self.vertex_edge_offsets[u]..self.vertex_edge_offsets[u + 1];
                    for (out, slot) in out.iter_mut().zip(slots) {
                        *out = slot;
                    }
                } else if u < v_count + e_count {
                    let e = u - v_count;
                    let [a, b] = self.edges[e];
                    out[0] = self.vertex_edge_slot(a, e as u32);
                    out[1] = self.vertex_edge_slot(b, e as u32);
                    let slots = self.edge_offsets[e]..self.edge_offsets[e + 1];
                    for (out, slot) in out[2..].iter_mut().zip(slots) {
                        *out = two_e as u32 + slot;
                    }
                } else {
                    let corners = faces.corners(u - v_count - e_count);
                    for (out, c) in out.iter_mut().zip(corners) {
                        *out = two_e as u32 + self.edge_corner_slot(c);
                    }
                    out.sort_unstable();
                }
            })?;
            Ok((vertex_edge_offsets, vertex_edges))
        };

        let ((edges, corner_edges), ((edge_corners, vertex_corners), vertex_edges)) = rayon::join(
            || rayon::join(build_edges, build_corner_edges),
            || {
                rayon::join(
                    || rayon::join(build_edge_corners, build_vertex_corners),
                    build_vertex_edges,
                )
            },
        );
        let (edge_offsets, edge_corners) = edge_corners?;
        let (vertex_offsets, vertex_corners) = vertex_corners?;
        let (vertex_edge_offsets, vertex_edges) = vertex_edges?;
        Ok(Connectivity {
            edges: edges?,
            face_size: 4,
            corner_faces: Vec::new(),
            corner_edges: corner_edges?,
            edge_offsets,
            edge_corners,
            vertex_offsets,
            vertex_corners,
            vertex_edge_offsets,
            vertex_edges,
        })
    }

    /// Loop: triangle f = `[v0, v1, v2]` with edges `e_i = v_i v_(i+1)` and
    /// `E_i = V + e_i` becomes `T_i = [v_i, E_i, E_(i-1)]` (i < 3) and
    /// `T_3 = [E0, E1, E2]`. The child edges, sorted, are `[v, V + e]` as for
    /// Catmull-Clark, then the edges inside the triangles, `[V + m, V + h]`
    /// grouped by the lower parent edge m and sorted by h (two triangles that
    /// share two edges share that child edge).
    fn refine_loop(&self, faces: &Faces, with_vertex_edges: bool) -> Result<Connectivity> {
        let (v_count, e_count, f_count) =
            (faces.vertex_count, self.edge_count(), faces.face_count());
        let idx = &faces.indices;
        let v_base = v_count as u32;
        let two_e = 2 * e_count as u32;
        let face_edges = |f: usize| -> [u32; 3] {
            [
                self.corner_edges[3 * f],
                self.corner_edges[3 * f + 1],
                self.corner_edges[3 * f + 2],
            ]
        };

        // Inside edges grouped by their lower parent edge.
        let mut inner_offsets = try_vec(e_count + 1, "edges")?;
        let mut inner_high = try_vec(3 * f_count, "edges")?;
        inner_offsets.push(0u32);
        for m in 0..e_count as u32 {
            let start = inner_high.len();
            for &c in self.edge_corners(m as usize) {
                let (f, i) = (c as usize / 3, c as usize % 3);
                let edges = face_edges(f);
                inner_high.extend(
                    [edges[(i + 1) % 3], edges[(i + 2) % 3]]
                        .into_iter()
                        .filter(|&h| h > m),
                );
            }
            sort_and_dedup_from(&mut inner_high, start);
            inner_offsets.push(inner_high.len() as u32);
        }
        let inner = |x: u32, y: u32| -> u32 {
            let (m, h) = (x.min(y) as usize, x.max(y));
            let block = &inner_high[inner_offsets[m] as usize..inner_offsets[m + 1] as usize];
            two_e + inner_offsets[m] + position(block, h)
        };

        let edge_slots = 2 * e_count + inner_high.len();
        // The arrays are independent of each other: built side by side.
        let build_edges = || -> Result<(Vec<[u32; 2]>, Vec<u32>)> {
            let mut edges = try_vec(edge_slots, "edges")?;
            for v in 0..v_count {
                edges.extend(self.vertex_edges(v).iter().map(|&e| [v as u32, v_base + e]));
            }
            for m in 0..e_count {
                let block = &inner_high[inner_offsets[m] as usize..inner_offsets[m + 1] as usize];
                edges.extend(block.iter().map(|&h| [v_base + m as u32, v_base + h]));
            }

            let mut corner_edges = try_vec(12 * f_count, "corner edges")?;
            for f in 0..f_count {
                let e = face_edges(f);
                for i in 0..3 {
                    let (v, e_previous) = (idx[3 * f + i], e[(i + 2) % 3]);
                    corner_edges.extend_from_slice(&[
                        self.vertex_edge_slot(v, e[i]),
                        inner(e[i], e_previous),
                        self.vertex_edge_slot(v, e_previous),
                    ]);
                }
                corner_edges.extend_from_slice(&[
                    inner(e[0], e[1]),
                    inner(e[1], e[2]),
                    inner(e[2], e[0]),
                ]);
            }
            Ok((edges, corner_edges))
        };

        let build_edge_corners = || -> Result<(Vec<u32>, Vec<u32>)> {
            let mut edge_offsets = try_vec(edge_slots + 1, "edge offsets")?;
            let mut edge_corners = try_vec(12 * f_count, "edge corners")?;
            edge_offsets.push(0);
            for v in 0..v_count {
                for &e in self.vertex_edges(v) {
                    let start = edge_corners.len();
                    edge_corners.extend(self.edge_corners(e as usize).iter().map(|&c| {
                        let (f, i) = (c / 3, c % 3);
                        if idx[c as usize] == v as u32 {
                            12 * f + 3 * i
                        } else {
                            12 * f + 3 * ((i + 1) % 3) + 2
                        }
                    }));
                    edge_corners[start..].sort_unstable();
                    edge_offsets.push(edge_corners.len() as u32);
                }
            }
            for m in 0..e_count {
                for &h in &inner_high[inner_offsets[m] as usize..inner_offsets[m + 1] as usize] {
                    let start = edge_corners.len();
                    for &c in self.edge_corners(m) {
                        let (f, i) = (c / 3, c % 3);
                        let e = face_edges(f as usize);
                        // The inside edge {E_j, E_(j+1)} is T_(j+1)'s corner 1 and T_3's corner j.
                        let j = if e[(i as usize + 1) % 3] == h {
                            i
                        } else if e[(i as usize + 2) % 3] == h {
                            (i + 2) % 3
                        } else {
                            continue;
                        };
                        edge_corners
                            .extend_from_slice(&[12 * f + 3 * ((j + 1) % 3) + 1, 12 * f + 9 + j]);
                    }
                    edge_corners[start..].sort_unstable();
                    edge_offsets.push(edge_corners.len() as u32);
                }
            }
            Ok((edge_offsets, edge_corners))
        };

        let child_vertices = v_count + e_count;
        let build_vertex_corners = || -> Result<(Vec<u32>, Vec<u32>)> {
            let mut vertex_offsets = try_vec(child_vertices + 1, "vertex corners")?;
            let mut vertex_corners = try_vec(12 * f_count, "vertex corners")?;
            vertex_offsets.push(0);
            for v in 0..v_count {
                vertex_corners.extend(
                    self.vertex_corners(v)
                        .iter()
                        .map(|&c| 12 * (c / 3) + 3 * (c % 3)),
                );
                vertex_offsets.push(vertex_corners.len() as u32);
            }
            for e in 0..e_count {
                let start = vertex_corners.len();
                for &c in self.edge_corners(e) {
                    let (f, i) = (c / 3, c % 3);
                    vertex_corners.extend_from_slice(&[
                        12 * f + 3 * i + 1,
                        12 * f + 3 * ((i + 1) % 3) + 2,
                        12 * f + 9 + i,
                    ]);
                }
                vertex_corners[start..].sort_unstable();
                vertex_offsets.push(vertex_corners.len() as u32);
            }
            Ok((vertex_offsets, vertex_corners))
        };

        let build_vertex_edges = || -> Result<(Vec<u32>, Vec<u32>)> {
            let (mut vertex_edge_offsets, mut vertex_edges) = (Vec::new(), Vec::new());
            if with_vertex_edges {
                vertex_edge_offsets = try_vec(child_vertices + 1, "vertex edges")?;
                vertex_edges = try_vec(2 * edge_slots, "vertex edges")?;
                vertex_edge_offsets.push(0);
                for v in 0..v_count {
                    vertex_edges
                        .extend(self.vertex_edge_offsets[v]..self.vertex_edge_offsets[v + 1]);
                    vertex_edge_offsets.push(vertex_edges.len() as u32);
                }
                for (e, &[a, b]) in self.edges.iter().enumerate() {
                    let e32 = e as u32;
                    vertex_edges.extend_from_slice(&[
                        self.vertex_edge_slot(a, e32),
                        self.vertex_edge_slot(b, e32),
                    ]);
                    let start = vertex_edges.len();
                    for &c in self.edge_corners(e) {
                        let (f, i) = (c as usize / 3, c as usize % 3);
                        let edges = face_edges(f);
                        for x in [edges[(i + 1) % 3], edges[(i + 2) % 3]] {
                            if x < e32 {
                                vertex_edges.push(inner(x, e32));
                            }
                        }
                    }
                    sort_and_dedup_from(&mut vertex_edges, start);
                    vertex_edges.extend(two_e + inner_offsets[e]..two_e + inner_offsets[e + 1]);
                    vertex_edge_offsets.push(vertex_edges.len() as u32);
                }
            }
            Ok((vertex_edge_offsets, vertex_edges))
        };

        let ((edges, edge_corners), (vertex_corners, vertex_edges)) = rayon::join(
            || rayon::join(build_edges, build_edge_corners),
            || rayon::join(build_vertex_corners, build_vertex_edges),
        );
        let ((edges, corner_edges), (edge_offsets, edge_corners)) = (edges?, edge_corners?);
        let ((vertex_offsets, vertex_corners), (vertex_edge_offsets, vertex_edges)) =
            (vertex_corners?, vertex_edges?);
        Ok(Connectivity {
            edges,
            face_size: 3,
            corner_faces: Vec::new(),
            corner_edges,
            edge_offsets,
            edge_corners,
            vertex_offsets,
            vertex_corners,
            vertex_edge_offsets,
            vertex_edges,
        })
    }

    pub(crate) fn edge_count(&self) -> usize {
        self.edges.len()
    }

    /// The face of corner `c`.
    #[inline]
    pub(crate) fn face_of(&self, c: usize) -> usize {
        match self.face_size {
            0 => self.corner_faces[c] as usize,
            4 => c / 4,
            size => c / size as usize,
        }
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

    /// The edges at vertex `v`, ascending.
    #[inline]
    pub(crate) fn vertex_edges(&self, v: usize) -> &[u32] {
        &self.vertex_edges
            [self.vertex_edge_offsets[v] as usize..self.vertex_edge_offsets[v + 1] as usize]
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
            self.vertex_edge_slot(v, self.corner_edges[previous]),
        ]
    }

    /// Where edge `e` (one of vertex `v`'s) sits in `vertex_edges`.
    #[inline]
    pub(crate) fn vertex_edge_slot(&self, v: u32, e: u32) -> u32 {
        self.vertex_edge_offsets[v as usize] + position(self.vertex_edges(v as usize), e)
    }

    /// Where corner `c` sits in `edge_corners`.
    #[inline]
    pub(crate) fn edge_corner_slot(&self, c: usize) -> u32 {
        let e = self.corner_edges[c] as usize;
        self.edge_offsets[e] + position(self.edge_corners(e), c as u32)
    }
}

/// Sorts `list[start..]` and drops its repeats.
fn sort_and_dedup_from(list: &mut Vec<u32>, start: usize) {
    list[start..].sort_unstable();
    let mut kept = start;
    for k in start..list.len() {
        if k == start || list[k] != list[kept - 1] {
            list[kept] = list[k];
            kept += 1;
        }
    }
    list.truncate(kept);
}

/// The index of `x` in the short list `list`, which holds it.
#[inline]
fn position(list: &[u32], x: u32) -> u32 {
    list.iter().position(|&y| y == x).unwrap_or(0) as u32
}

/// Every vertex's edges, ascending, from the sorted edges.
fn vertex_edges_of(edges: &[[u32; 2]], vertex_count: usize) -> Result<(Vec<u32>, Vec<u32>)> {
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
    pub(crate) scheme: Scheme,
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
    /// Ring entries per neighbour of a smooth vertex: Catmull-Clark's rings
    /// hold the faces too.
    #[inline]
    pub(crate) fn ring_stride(&self) -> usize {
        match self.scheme {
            Scheme::CatmullClark => 2,
            Scheme::Loop => 1,
        }
    }

    /// The ring of vertex `v` (see [`Plan::vertex_ring`]).
    #[inline]
    pub(crate) fn ring(&self, v: usize) -> &[u32] {
        &self.vertex_ring
            [self.vertex_ring_offsets[v] as usize..self.vertex_ring_offsets[v + 1] as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn connectivity_of_two_triangles() {
        let faces = Faces {
            vertex_count: 4,
            size: 0,
            offsets: vec![0, 3, 6],
            indices: vec![0, 1, 2, 0, 2, 3],
        };
        let c = Connectivity::new(&faces).unwrap();
        assert_eq!(c.edges, vec![[0, 1], [0, 2], [0, 3], [1, 2], [2, 3]]);
        let diagonal = c.edges.iter().position(|&e| e == [0, 2]).unwrap();
        assert_eq!(c.edge_corners(diagonal), &[2, 3]);
        assert_eq!(c.vertex_corners(0), &[0, 3]);
        assert_eq!(c.corner_edges, vec![0, 3, 1, 1, 4, 2]);
        assert_eq!(c.vertex_edges(2), &[1, 3, 4]);
    }

    /// On faces of one size, corners find their face and neighbours by
    /// arithmetic exactly as through the offsets.
    #[test]
    fn uniform_faces_match_their_offsets() {
        use crate::mesh::shapes;
        for mesh in [
            shapes::cube(),
            shapes::icosahedron(),
            shapes::quad_grid(3, 2),
        ] {
            let uniform = Faces::of_mesh(&mesh);
            assert_ne!(uniform.size, 0);
            let general = Faces {
                size: 0,
                ..uniform.clone()
            };
            let (a, b) = (
                Connectivity::new(&uniform).unwrap(),
                Connectivity::new(&general).unwrap(),
            );
            assert!(a.corner_faces.is_empty());
            assert_same(&a, &b, "uniform");
            for c in 0..uniform.corner_count() {
                let f = b.face_of(c);
                assert_eq!(uniform.next(c, f), general.next(c, f), "next of {c}");
                assert_eq!(uniform.prev(c, f), general.prev(c, f), "prev of {c}");
                assert_eq!(uniform.face(f), general.face(f));
            }
            assert_eq!(uniform.face_count(), general.face_count());
        }
        assert_eq!(Faces::of_mesh(&shapes::mixed_polygons()).size, 0);
    }

    fn assert_same(derived: &Connectivity, bucketed: &Connectivity, what: &str) {
        assert_eq!(derived.edges, bucketed.edges, "{what}: edges");
        let faces_of = |c: &Connectivity| {
            (0..c.corner_edges.len())
                .map(|k| c.face_of(k))
                .collect::<Vec<_>>()
        };
        assert_eq!(
            faces_of(derived),
            faces_of(bucketed),
            "{what}: corner faces"
        );
        assert_eq!(
            derived.corner_edges, bucketed.corner_edges,
            "{what}: corner edges"
        );
        assert_eq!(
            derived.edge_offsets, bucketed.edge_offsets,
            "{what}: edge offsets"
        );
        assert_eq!(
            derived.edge_corners, bucketed.edge_corners,
            "{what}: edge corners"
        );
        assert_eq!(
            derived.vertex_offsets, bucketed.vertex_offsets,
            "{what}: vertex offsets"
        );
        assert_eq!(
            derived.vertex_corners, bucketed.vertex_corners,
            "{what}: vertex corners"
        );
        assert_eq!(
            derived.vertex_edge_offsets, bucketed.vertex_edge_offsets,
            "{what}: vertex edge offsets"
        );
        assert_eq!(
            derived.vertex_edges, bucketed.vertex_edges,
            "{what}: vertex edges"
        );
    }

    /// The arithmetic child connectivity equals bucketing the child faces,
    /// on closed, open, mixed and non-manifold shapes, over three levels.
    #[test]
    fn refined_connectivity_equals_bucketing() {
        use crate::mesh::shapes;
        let pillow = crate::Mesh::from_polygons(
            vec![crate::DVec3::ZERO, crate::DVec3::X, crate::DVec3::Y],
            [[0u32, 1, 2], [1, 0, 2]],
        )
        .unwrap();
        let polygons = [
            ("cube", shapes::cube()),
            ("grid", shapes::quad_grid(3, 2)),
            ("grid with hole", shapes::quad_grid_with_hole()),
            ("mixed", shapes::mixed_polygons()),
            ("fin", shapes::fin()),
            ("bow tie", shapes::bow_tie()),
            ("mobius", shapes::mobius_strip(6)),
        ];
        let triangles = [
            ("tetrahedron", shapes::tetrahedron()),
            ("icosahedron", shapes::icosahedron()),
            ("triangle grid", shapes::triangle_grid(3, 2)),
            ("triangle grid with hole", shapes::triangle_grid_with_hole()),
            ("pillow", pillow),
        ];
        let cases = polygons
            .into_iter()
            .map(|(n, m)| (n, m, Scheme::CatmullClark))
            .chain(
                triangles
                    .clone()
                    .into_iter()
                    .map(|(n, m)| (n, m, Scheme::Loop)),
            )
            .chain(
                triangles
                    .into_iter()
                    .map(|(n, m)| (n, m, Scheme::CatmullClark)),
            );
        for (name, mesh, scheme) in cases {
            if scheme == Scheme::Loop && mesh.first_non_triangle().is_some() {
                continue;
            }
            let mut faces = Faces::of_mesh(&mesh);
            let mut connectivity = Connectivity::new(&faces).unwrap();
            for level in 1..=3 {
                let child = match scheme {
                    Scheme::CatmullClark => {
                        super::super::catmull_clark::child_faces(&faces, &connectivity, true)
                    }
                    Scheme::Loop => {
                        super::super::loop_subdivision::child_faces(&faces, &connectivity, true)
                    }
                }
                .unwrap();
                let derived = connectivity.refine(scheme, &faces, true).unwrap();
                // Bucketed through the offsets, not the faces' uniform size.
                let offsets_only = Faces {
                    size: 0,
                    ..child.clone()
                };
                assert_same(
                    &derived,
                    &Connectivity::new(&offsets_only).unwrap(),
                    &format!("{name} {scheme:?} level {level}"),
                );
                (faces, connectivity) = (child, derived);
            }
        }
    }
}
