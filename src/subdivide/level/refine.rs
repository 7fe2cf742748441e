//! The connectivity of a refined level, written arithmetically from its
//! parent's: the child edges, corners and rings of each parent vertex, edge
//! and face have a known place, so no sorting of the whole level is needed.
//! Equal, array for array, to bucketing the child faces
//! ([`Connectivity::new`]); `tests.rs` checks it on every named shape.

use super::{Connectivity, Faces, SCANNED};
use crate::buffers::{fill_by_offsets, flatten, par_map, par_offsets, try_vec};
use crate::error::Result;
use crate::mesh::adjacency::Adjacency;
use crate::subdivide::scheme::Scheme;

/// Loop: the child's edges inside the parent's triangles, in the child's
/// order: grouped by their lower parent edge m, sorted within, each as
/// (higher parent edge, triangle, m).
pub(crate) struct LoopInsideEdges {
    /// Where each m's group starts (m from 0 to E, inclusive).
    pub(crate) offsets: Vec<u32>,
    pub(crate) edges: Vec<(u32, u32, u32)>,
}

impl LoopInsideEdges {
    /// The group of the edges whose lower parent edge is m.
    #[inline]
    pub(crate) fn group(&self, m: usize) -> &[(u32, u32, u32)] {
        &self.edges[self.offsets[m] as usize..self.offsets[m + 1] as usize]
    }

    /// The place, among the inside edges, of the one inside triangle f
    /// between the points of its parent edges x and y.
    #[inline]
    pub(crate) fn find(&self, f: usize, x: u32, y: u32) -> usize {
        let (m, h) = (x.min(y) as usize, x.max(y));
        let group = self.group(m);
        let key = (h, f as u32);
        // A group is long where many triangles share edge m.
        let k = if group.len() <= SCANNED {
            group
                .iter()
                .position(|&(high, face, _)| (high, face) == key)
        } else {
            let k = group.partition_point(|&(high, face, _)| (high, face) < key);
            group
                .get(k)
                .filter(|&&(high, face, _)| (high, face) == key)
                .map(|_| k)
        };
        self.offsets[m] as usize + k.unwrap_or(0)
    }
}

impl Connectivity {
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
        Ok(self.refine_with_inside(scheme, faces, vertex_edges)?.0)
    }

    /// As [`Connectivity::refine`], with Loop's inside-edge offsets (see
    /// [`Connectivity::loop_inside_offsets`]), which the refinement counts
    /// anyway and the parent's groups read (`None` for Catmull-Clark).
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`].
    pub(crate) fn refine_with_inside(
        &self,
        scheme: Scheme,
        faces: &Faces,
        vertex_edges: bool,
    ) -> Result<(Connectivity, Option<Vec<u32>>)> {
        match scheme {
            Scheme::CatmullClark => Ok((self.refine_catmull_clark(faces, vertex_edges)?, None)),
            Scheme::Loop => {
                let (connectivity, inside_offsets) = self.refine_loop(faces, vertex_edges)?;
                Ok((connectivity, Some(inside_offsets)))
            }
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
            if faces.size == 4 {
                // A quad's corners at once: they share their edges' slots.
                let quads = par_map(faces.face_count(), "corner edges", |q| {
                    bytemuck::cast::<[[u32; 4]; 4], [u32; 16]>(
                        self.child_quad_edges_of_quad(faces, q),
                    )
                })?;
                return Ok(flatten(quads));
            }
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
                        *out = if self.slot_leaves_at(s, v, c, idx) {
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
                    out[1] = self.vertex_edge_slot_arriving(b, e as u32);
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
        let (vertex_edge_offsets, vertex_edges) = vertex_edges?;
        Ok(Connectivity {
            adjacency: Adjacency::from_parts(
                (edges?, corner_edges?),
                edge_corners?,
                vertex_corners?,
            ),
            face_size: 4,
            corner_faces: Vec::new(),
            vertex_edge_offsets,
            vertex_edges,
        })
    }

    /// Loop: where the edges inside the child triangles whose lower parent
    /// edge is m start among the child's inside edges (m from 0 to E,
    /// inclusive).
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`].
    pub(crate) fn loop_inside_offsets(&self) -> Result<Vec<u32>> {
        par_offsets(self.edge_count(), "edges", |m| {
            let mut count = 0;
            self.loop_inside_edges(m, |_, _| count += 1);
            count
        })
    }

    /// Loop: the child's inside edges (see [`LoopInsideEdges`]).
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`].
    pub(crate) fn loop_inside_table(&self) -> Result<LoopInsideEdges> {
        let offsets = self.loop_inside_offsets()?;
        let edges = fill_by_offsets(&offsets, "edges", |m, out| {
            let mut k = 0;
            self.loop_inside_edges(m, |h, f| {
                out[k] = (h, f, m as u32);
                k += 1;
            });
            out.sort_unstable();
        })?;
        Ok(LoopInsideEdges { offsets, edges })
    }

    /// Loop: triangle f = `[v0, v1, v2]` with edges `e_i = v_i v_(i+1)` and
    /// `E_i = V + e_i` becomes `T_i = [v_i, E_i, E_(i-1)]` (i < 3) and
    /// `T_3 = [E0, E1, E2]`. The child edges, sorted, are `[v, V + e]` as for
    /// Catmull-Clark, then the edges inside the triangles, `[V + m, V + h]`
    /// grouped by the lower parent edge m and sorted by h, then by face:
    /// every triangle has its own three, even where two triangles share two
    /// edges and so the same two edge points (OpenSubdiv's child edges of a
    /// face belong to that face).
    fn refine_loop(
        &self,
        faces: &Faces,
        with_vertex_edges: bool,
    ) -> Result<(Connectivity, Vec<u32>)> {
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

        let inside = self.loop_inside_table()?;
        let inner_offsets = &inside.offsets;
        // The edge inside face f between its parent edges x and y.
        let inner = |f: usize, x: u32, y: u32| two_e + inside.find(f, x, y) as u32;

        let edge_slots = 2 * e_count + inside.edges.len();
        // The arrays are independent of each other: built side by side.
        let build_edges = || -> Result<(Vec<[u32; 2]>, Vec<u32>)> {
            let mut edges = try_vec(edge_slots, "edges")?;
            for v in 0..v_count {
                edges.extend(self.vertex_edges(v).iter().map(|&e| [v as u32, v_base + e]));
            }
            for m in 0..e_count {
                edges.extend(
                    inside
                        .group(m)
                        .iter()
                        .map(|&(h, _, _)| [v_base + m as u32, v_base + h]),
                );
            }

            let mut corner_edges = try_vec(12 * f_count, "corner edges")?;
            for f in 0..f_count {
                let e = face_edges(f);
                for i in 0..3 {
                    let (v, e_previous) = (idx[3 * f + i], e[(i + 2) % 3]);
                    corner_edges.extend_from_slice(&[
                        self.vertex_edge_slot(v, e[i]),
                        inner(f, e[i], e_previous),
                        self.vertex_edge_slot_arriving(v, e_previous),
                    ]);
                }
                corner_edges.extend_from_slice(&[
                    inner(f, e[0], e[1]),
                    inner(f, e[1], e[2]),
                    inner(f, e[2], e[0]),
                ]);
            }
            Ok((edges, corner_edges))
        };

        let build_edge_corners = || -> Result<(Vec<u32>, Vec<u32>)> {
            let mut edge_offsets = try_vec(edge_slots + 1, "edge offsets")?;
            let mut edge_corners = try_vec(12 * f_count, "edge corners")?;
            edge_offsets.push(0);
            for v in 0..v_count {
                let slots =
                    self.vertex_edge_offsets[v] as usize..self.vertex_edge_offsets[v + 1] as usize;
                for s in slots {
                    let e = self.vertex_edges[s];
                    let start = edge_corners.len();
                    edge_corners.extend(self.edge_corners(e as usize).iter().map(|&c| {
                        let (f, i) = (c / 3, c % 3);
                        if self.slot_leaves_at(s, v as u32, c as usize, idx) {
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
                for &(h, face, _) in inside.group(m) {
                    let start = edge_corners.len();
                    for &c in self.edge_corners(m) {
                        let (f, i) = (c / 3, c % 3);
                        if f != face {
                            continue;
                        }
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
                        self.vertex_edge_slot_arriving(b, e32),
                    ]);
                    let start = vertex_edges.len();
                    for &c in self.edge_corners(e) {
                        let (f, i) = (c as usize / 3, c as usize % 3);
                        let edges = face_edges(f);
                        for x in [edges[(i + 1) % 3], edges[(i + 2) % 3]] {
                            if x < e32 {
                                vertex_edges.push(inner(f, x, e32));
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
        let (vertex_edge_offsets, vertex_edges) = vertex_edges?;
        let connectivity = Connectivity {
            adjacency: Adjacency::from_parts(edges?, edge_corners?, vertex_corners?),
            face_size: 3,
            corner_faces: Vec::new(),
            vertex_edge_offsets,
            vertex_edges,
        };
        Ok((connectivity, inside.offsets))
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
