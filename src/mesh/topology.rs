//! Edges, adjacency, boundary and manifoldness of a [`Mesh`].
//!
//! Everything is flat index arrays built by bucketing, never by hashing
//! pairs or comparing all faces: the edges come from the one builder in
//! `mesh/adjacency.rs`, which the subdivision's levels share, so a
//! mesh of a million faces takes a few tens of milliseconds.
//!
//! Names used throughout: a *corner* is a position in [`Mesh::face_indices`];
//! the *edge of a corner* runs from that corner's vertex to the next corner's
//! vertex in the same face.

use rayon::prelude::*;

use crate::buffers::{try_vec, CHUNK};
use crate::error::Result;
use crate::mesh::adjacency::Adjacency;
use crate::mesh::corners::CornerFaces;
use crate::mesh::Mesh;

/// Edges and adjacency of one mesh. Build it with [`Topology::new`]; it does
/// not keep a reference to the mesh.
#[derive(Debug, Clone)]
pub struct Topology {
    /// Unique edges (`[low, high]`, sorted), each corner's edge, the corners
    /// on each edge and at each vertex.
    adjacency: Adjacency,
    /// Each corner's face and next corner.
    corners: CornerFaces,
    face_vertices: Vec<u32>,
}

/// The edges of a mesh and each corner's edge, without the rest of a
/// [`Topology`] (the corners' faces, next corners and vertices): what a
/// pass that only asks which edges are naked needs, at a little over half
/// the memory. Built by the same edge builder.
#[derive(Debug, Clone)]
pub(crate) struct Edges {
    adjacency: Adjacency,
}

impl Edges {
    /// The edges of `mesh`.
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`] when the arrays cannot be reserved.
    pub(crate) fn try_new(mesh: &Mesh) -> Result<Edges> {
        // Each corner's face and next corner: arithmetic for faces of one size.
        let corners = CornerFaces::of_mesh(mesh)?;
        let adjacency = Adjacency::build_edges(
            mesh.vertex_count(),
            mesh.face_indices(),
            |c| corners.next(c),
            |c| corners.face(c),
        )?;
        Ok(Edges { adjacency })
    }

    /// For each corner of `mesh`, whether its edge is naked (what
    /// [`Edges::is_naked_edge`] says of the corner's edge), without
    /// building the edges.
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`] when the arrays cannot be reserved.
    pub(crate) fn naked_corners(mesh: &Mesh) -> Result<Vec<bool>> {
        Edges::naked_corners_with(mesh, &CornerFaces::of_mesh(mesh)?)
    }

    /// [`Edges::naked_corners`] with the mesh's corners already found.
    pub(crate) fn naked_corners_with(mesh: &Mesh, corners: &CornerFaces) -> Result<Vec<bool>> {
        // No vertex named twice (STL as stored): no two corners start the
        // same edge, so every edge is naked.
        if mesh.corners_share_no_vertex() {
            return Ok(vec![true; mesh.index_count()]);
        }
        Adjacency::naked_corners(
            mesh.vertex_count(),
            mesh.face_indices(),
            |c| corners.next(c),
            |c| corners.face(c),
        )
    }

    /// For each corner, the edge from it to the next corner of its face.
    #[inline]
    pub(crate) fn corner_edges(&self) -> &[u32] {
        &self.adjacency.corner_edges
    }

    /// Number of unique edges.
    #[inline]
    pub(crate) fn edge_count(&self) -> usize {
        self.adjacency.edges.len()
    }

    /// Whether edge `e` has exactly one face.
    #[inline]
    pub(crate) fn is_naked_edge(&self, e: usize) -> bool {
        self.adjacency.edge_offsets[e + 1] - self.adjacency.edge_offsets[e] == 1
    }

    /// The edge between vertices `a` and `b`, if there is one (the first,
    /// where a face repeating a vertex gives the pair more than one), as
    /// [`Topology::find_edge`].
    pub(crate) fn find_edge(&self, a: u32, b: u32) -> Option<usize> {
        let pair = [a.min(b), a.max(b)];
        let edges = &self.adjacency.edges;
        let first = edges.partition_point(|&e| e < pair);
        (edges.get(first) == Some(&pair)).then_some(first)
    }
}

/// What [`Topology::info`] counts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct MeshInfo {
    pub vertex_count: usize,
    pub edge_count: usize,
    pub face_count: usize,
    /// Edges with exactly one face.
    pub naked_edge_count: usize,
    /// Edges with three or more faces.
    pub non_manifold_edge_count: usize,
    /// Vertices whose faces do not form one fan, or that lie on a non-manifold edge.
    pub non_manifold_vertex_count: usize,
    /// Connected pieces of faces (vertices used by no face are not counted).
    pub component_count: usize,
    /// No naked and no non-manifold edge (a mesh without faces is not closed).
    pub is_closed: bool,
    /// Every component can be given one consistent winding.
    pub is_orientable: bool,
    /// Every two faces sharing a manifold edge already run it in opposite directions.
    pub is_oriented: bool,
}

impl MeshInfo {
    /// The counts and flags of `mesh`, as [`Topology::info`] finds them.
    /// When no two corners name one vertex (an STL file read as it is
    /// stored, each triangle with corners of its own) the answer is known
    /// without finding the edges: every corner starts an edge of its own,
    /// naked, and every face is a piece of its own.
    ///
    /// # Panics
    /// As [`Topology::new`], when memory for its arrays runs out.
    pub fn of(mesh: &Mesh) -> MeshInfo {
        if !mesh.corners_share_no_vertex() {
            return Topology::new(mesh).info(mesh);
        }
        let faces = mesh.face_count();
        MeshInfo {
            vertex_count: mesh.vertex_count(),
            edge_count: mesh.index_count(),
            face_count: faces,
            naked_edge_count: mesh.index_count(),
            non_manifold_edge_count: 0,
            non_manifold_vertex_count: 0,
            component_count: faces,
            // A face of three or more corners on distinct vertices has a
            // naked edge: closed only without faces, and then not either.
            is_closed: false,
            is_orientable: true,
            is_oriented: true,
        }
    }
}

/// A consistent winding of each component, as far as one exists.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Orientation {
    /// Component of each face.
    pub face_component: Vec<u32>,
    /// Whether each face must be reversed to agree with its component's first face.
    pub face_flip: Vec<bool>,
    /// Per component: whether the assignment above is consistent across every manifold edge.
    pub component_orientable: Vec<bool>,
}

impl Topology {
    /// Finds the edges and adjacency of `mesh`.
    ///
    /// # Panics
    /// When memory for the arrays runs out; [`Topology::try_new`] returns
    /// that as an error instead.
    pub fn new(mesh: &Mesh) -> Topology {
        Topology::try_new(mesh).unwrap_or_else(|error| panic!("{error}"))
    }

    /// Finds the edges and adjacency of `mesh`, reporting rather than
    /// aborting when memory runs out.
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`] when the arrays cannot be reserved.
    pub fn try_new(mesh: &Mesh) -> Result<Topology> {
        let indices = mesh.face_indices();
        // Each corner's face and next corner (arithmetic for faces of one
        // size); then the edges beside the copy of the corners' vertices.
        let corners = CornerFaces::of_mesh(mesh)?;
        let (adjacency, face_vertices) = rayon::join(
            || {
                Adjacency::build(
                    mesh.vertex_count(),
                    indices,
                    |c| corners.next(c),
                    |c| corners.face(c),
                )
            },
            || -> Result<Vec<u32>> {
                let mut face_vertices = try_vec(indices.len(), "corner vertices")?;
                face_vertices.par_extend(indices.par_iter().copied().with_min_len(CHUNK));
                Ok(face_vertices)
            },
        );
        Ok(Topology {
            adjacency: adjacency?,
            corners,
            face_vertices: face_vertices?,
        })
    }

    /// Number of unique edges.
    #[inline]
    pub fn edge_count(&self) -> usize {
        self.adjacency.edges.len()
    }

    /// The unique edges as `[low, high]` vertex pairs, sorted.
    #[inline]
    pub fn edges(&self) -> &[[u32; 2]] {
        &self.adjacency.edges
    }

    /// For each corner, the edge from it to the next corner of its face.
    #[inline]
    pub fn corner_edges(&self) -> &[u32] {
        &self.adjacency.corner_edges
    }

    /// For each corner, its face.
    #[inline]
    pub fn corner_faces(&self) -> &[u32] {
        self.corners.faces()
    }

    /// For each corner, the next corner (counter-clockwise) of the same face.
    #[inline]
    pub fn corner_next(&self) -> &[u32] {
        self.corners.next_corners()
    }

    /// The vertex at each corner (the mesh's face indices).
    #[inline]
    pub fn corner_vertices(&self) -> &[u32] {
        &self.face_vertices
    }

    /// The corners whose edge is `e`, ascending (so their faces ascend too).
    #[inline]
    pub fn edge_corners(&self, e: usize) -> &[u32] {
        self.adjacency.edge_corners(e)
    }

    /// Where each edge's corners start in the flat corner list, plus the total.
    #[inline]
    pub fn edge_offsets(&self) -> &[u32] {
        &self.adjacency.edge_offsets
    }

    /// The faces on edge `e`, ascending (a face appears once per corner on it).
    pub fn edge_faces(&self, e: usize) -> impl ExactSizeIterator<Item = u32> + '_ {
        self.edge_corners(e)
            .iter()
            .map(move |&c| self.corners.face(c as usize) as u32)
    }

    /// How many face corners use edge `e`: 1 naked, 2 manifold, more non-manifold.
    #[inline]
    pub fn edge_face_count(&self, e: usize) -> usize {
        (self.adjacency.edge_offsets[e + 1] - self.adjacency.edge_offsets[e]) as usize
    }

    /// Whether edge `e` has exactly one face.
    #[inline]
    pub fn is_naked_edge(&self, e: usize) -> bool {
        self.edge_face_count(e) == 1
    }

    /// Whether edge `e` has three or more faces.
    #[inline]
    pub fn is_non_manifold_edge(&self, e: usize) -> bool {
        self.edge_face_count(e) > 2
    }

    /// The edge between vertices `a` and `b`, if there is one (the first,
    /// where a face repeating a vertex gives the pair more than one).
    pub fn find_edge(&self, a: u32, b: u32) -> Option<usize> {
        let pair = [a.min(b), a.max(b)];
        let edges = &self.adjacency.edges;
        let first = edges.partition_point(|&e| e < pair);
        (edges.get(first) == Some(&pair)).then_some(first)
    }

    /// The corners at vertex `v`, ascending.
    #[inline]
    pub fn vertex_corners(&self, v: usize) -> &[u32] {
        self.adjacency.vertex_corners(v)
    }

    /// Number of faces at each vertex (a face counts once per corner at it).
    pub fn vertex_face_counts(&self) -> Vec<u32> {
        self.adjacency
            .vertex_offsets
            .windows(2)
            .map(|w| w[1] - w[0])
            .collect()
    }

    /// Number of edges at each vertex.
    pub fn vertex_valences(&self) -> Vec<u32> {
        let mut valence = vec![0u32; self.adjacency.vertex_offsets.len() - 1];
        for &[a, b] in &self.adjacency.edges {
            valence[a as usize] += 1;
            valence[b as usize] += 1;
        }
        valence
    }

    /// The edges with exactly one face.
    pub fn naked_edges(&self) -> Vec<u32> {
        (0..self.edge_count())
            .filter(|&e| self.is_naked_edge(e))
            .map(|e| e as u32)
            .collect()
    }

    /// The edges with three or more faces.
    pub fn non_manifold_edges(&self) -> Vec<u32> {
        (0..self.edge_count())
            .filter(|&e| self.is_non_manifold_edge(e))
            .map(|e| e as u32)
            .collect()
    }

    /// Whether each vertex is on a naked edge.
    pub fn boundary_vertices(&self) -> Vec<bool> {
        let mut on_boundary = vec![false; self.adjacency.vertex_offsets.len() - 1];
        for (e, &[a, b]) in self.adjacency.edges.iter().enumerate() {
            if self.is_naked_edge(e) {
                on_boundary[a as usize] = true;
                on_boundary[b as usize] = true;
            }
        }
        on_boundary
    }

    /// The vertices whose faces do not form one fan (a bow-tie), or that lie on
    /// an edge of three or more faces. Unused vertices are not listed.
    pub fn non_manifold_vertices(&self) -> Vec<u32> {
        // Corners at the same vertex are in one fan when a chain of manifold
        // edges through that vertex links their faces.
        let mut fans = UnionFind::new(self.adjacency.corner_edges.len());
        let mut on_non_manifold_edge = vec![false; self.adjacency.vertex_offsets.len() - 1];
        for e in 0..self.edge_count() {
            let corners = self.edge_corners(e);
            match corners {
                &[c1, c2] => {
                    let (n1, n2) = (
                        self.corners.next(c1 as usize) as u32,
                        self.corners.next(c2 as usize) as u32,
                    );
                    if self.face_vertices[c1 as usize] == self.face_vertices[c2 as usize] {
                        fans.union(c1, c2);
                        fans.union(n1, n2);
                    } else {
                        fans.union(c1, n2);
                        fans.union(n1, c2);
                    }
                }
                [_] => {}
                _ => {
                    let [a, b] = self.adjacency.edges[e];
                    on_non_manifold_edge[a as usize] = true;
                    on_non_manifold_edge[b as usize] = true;
                }
            }
        }
        (0..self.adjacency.vertex_offsets.len() - 1)
            .filter(|&v| {
                let corners = self.vertex_corners(v);
                on_non_manifold_edge[v]
                    || corners.split_first().is_some_and(|(&first, rest)| {
                        let root = fans.find(first);
                        rest.iter().any(|&c| fans.find(c) != root)
                    })
            })
            .map(|v| v as u32)
            .collect()
    }

    /// How many vertices [`Topology::non_manifold_vertices`] lists, worked
    /// out vertex by vertex in parallel: the corners at a vertex are joined
    /// across each manifold edge there (the edge's two faces' corners at
    /// the vertex), which are exactly the joins of that method's fans, so
    /// the count is the same without a union-find over all corners. Most
    /// vertices are one fan, which a walk around them finds first.
    fn non_manifold_vertex_count(&self) -> usize {
        let vertex_count = self.adjacency.vertex_offsets.len() - 1;
        (0..vertex_count)
            .into_par_iter()
            .with_min_len(CHUNK)
            .fold(
                || (0usize, Vec::new()),
                |(count, mut scratch): (usize, Vec<u32>), v| {
                    let corners = self.vertex_corners(v);
                    let non_manifold = match self.walk_one_fan(v, corners, &mut scratch) {
                        Some(answer) => answer,
                        None => self.joins_leave_several_fans(v, corners, &mut scratch),
                    };
                    (count + non_manifold as usize, scratch)
                },
            )
            .map(|(count, _)| count)
            .sum()
    }

    /// Whether vertex `v` is non-manifold, found by walking around it from
    /// its first corner across manifold edges, one way and then the other,
    /// as a manifold vertex's one fan is walked: `Some(false)` when the
    /// walk reaches every corner at `v` once, `Some(true)` when it meets a
    /// non-manifold edge, `None` when it cannot tell (several fans, or a
    /// face that meets `v` twice), which the union-find then decides.
    fn walk_one_fan(&self, v: usize, corners: &[u32], walked: &mut Vec<u32>) -> Option<bool> {
        let Some(&start) = corners.first() else {
            return Some(false);
        };
        let corner_edges = &self.adjacency.corner_edges;
        let previous = |c: u32| self.corners.previous(c as usize) as u32;
        walked.clear();
        walked.push(start);
        // Out of `start` through its edge out of v, then through its edge
        // into v; each step enters a corner through one of its two edges at
        // v and leaves through the other.
        let start_in = previous(start);
        'ways: for (mut own, mut edge) in [
            (start, corner_edges[start as usize]),
            (start_in, corner_edges[start_in as usize]),
        ] {
            loop {
                let (at_v, by_edge_into_v) = match self.across(v, own, edge) {
                    Across::Joined(at_v, by_edge_into_v) => (at_v, by_edge_into_v),
                    Across::Naked => continue 'ways,
                    Across::NonManifold => return Some(true),
                };
                if at_v == start {
                    // Round to the start through its edge into v: one closed fan.
                    if !by_edge_into_v {
                        return None;
                    }
                    break 'ways;
                }
                // Out through the other of its two edges at v.
                let next_own = if by_edge_into_v { at_v } else { previous(at_v) };
                let next_edge = corner_edges[next_own as usize];
                if next_edge == edge || walked.len() == corners.len() {
                    return None;
                }
                walked.push(at_v);
                (own, edge) = (next_own, next_edge);
            }
        }
        if walked.len() != corners.len() {
            return None;
        }
        walked.sort_unstable();
        (walked[..] == corners[..]).then_some(false)
    }

    /// Whether the corners at vertex `v`, joined across each manifold edge
    /// there, form more than one fan, or `v` is on a non-manifold edge.
    fn joins_leave_several_fans(&self, v: usize, corners: &[u32], parent: &mut Vec<u32>) -> bool {
        let corner_edges = &self.adjacency.corner_edges;
        let previous = |c: u32| self.corners.previous(c as usize) as u32;
        parent.clear();
        parent.extend(0..corners.len() as u32);
        let mut non_manifold = false;
        for (i, &c) in corners.iter().enumerate() {
            // The edge out of v and the edge into v in c's face, each with
            // the corner whose edge it is.
            let before = previous(c);
            for (own, edge) in [
                (c, corner_edges[c as usize]),
                (before, corner_edges[before as usize]),
            ] {
                match self.across(v, own, edge) {
                    Across::Joined(at_v, _) => {
                        if let Ok(j) = corners.binary_search(&at_v) {
                            let (a, b) = (root(parent, i as u32), root(parent, j as u32));
                            parent[a.max(b) as usize] = a.min(b);
                        }
                    }
                    Across::Naked => {}
                    Across::NonManifold => non_manifold = true,
                }
            }
        }
        non_manifold || (1..corners.len() as u32).any(|i| root(parent, i) != 0)
    }

    /// What lies across `edge` from corner `own` (the corner whose edge it
    /// is, in a face at vertex `v`): the other face's corner at `v`, and
    /// whether `edge` is that corner's edge into `v` (else its edge out).
    // Inlined into both callers' loops, which run at every corner of every
    // vertex: as a call, `info`'s counts took a tenth longer.
    #[inline(always)]
    fn across(&self, v: usize, own: u32, edge: u32) -> Across {
        match self.edge_corners(edge as usize) {
            &[c1, c2] => {
                let other = if c1 == own { c2 } else { c1 };
                if self.face_vertices[other as usize] as usize == v {
                    Across::Joined(other, false)
                } else {
                    Across::Joined(self.corners.next(other as usize) as u32, true)
                }
            }
            [_] => Across::Naked,
            _ => Across::NonManifold,
        }
    }

    /// The connected component of each face (faces sharing any edge are
    /// connected), numbered from 0 in order of their first face, and the count.
    pub fn face_components(&self) -> (Vec<u32>, usize) {
        let face_count = self.face_count();
        let mut pieces = UnionFind::new(face_count);
        for e in 0..self.edge_count() {
            let corners = self.edge_corners(e);
            let first = self.corners.face(corners[0] as usize) as u32;
            for &c in &corners[1..] {
                pieces.union(first, self.corners.face(c as usize) as u32);
            }
        }
        pieces.into_labels()
    }

    /// Whether each connected component (numbered as by
    /// [`Topology::face_components`]) is closed: none of its edges is naked
    /// or non-manifold. [`MeshInfo::is_closed`] is true exactly when every
    /// component is closed and there is at least one.
    pub fn component_closed(&self) -> Vec<bool> {
        let (face_component, component_count) = self.face_components();
        let mut closed = vec![true; component_count];
        for e in 0..self.edge_count() {
            if self.edge_face_count(e) != 2 {
                // All faces on an edge are in one component: its first face's.
                let face = self.corners.face(self.edge_corners(e)[0] as usize);
                closed[face_component[face] as usize] = false;
            }
        }
        closed
    }

    /// Number of faces.
    pub fn face_count(&self) -> usize {
        self.corners.face_count()
    }

    /// Gives every face a winding relative to the first face of its component,
    /// walking across manifold edges; non-manifold edges do not constrain.
    pub fn orientation(&self) -> Orientation {
        // The components on one thread, the walk on the other; the walk's
        // disagreements are charged to their components afterwards.
        let ((face_component, component_count), (face_flip, disagreeing)) =
            rayon::join(|| self.face_components(), || self.walk_windings());
        let mut component_orientable = vec![true; component_count];
        for g in disagreeing {
            component_orientable[face_component[g as usize] as usize] = false;
        }
        Orientation {
            face_component,
            face_flip,
            component_orientable,
        }
    }

    /// The walk of [`Topology::orientation`] across manifold edges: each
    /// face's flip relative to the first face of its walk, and the faces
    /// where an edge disagrees with a flip already given.
    fn walk_windings(&self) -> (Vec<bool>, Vec<u32>) {
        let face_count = self.face_count();
        let mut face_flip = vec![false; face_count];
        let mut disagreeing = Vec::new();
        let mut visited = vec![false; face_count];
        let mut stack = Vec::new();
        for seed in 0..face_count {
            if visited[seed] {
                continue;
            }
            visited[seed] = true;
            stack.push(seed as u32);
            while let Some(f) = stack.pop() {
                let start = self.corners.first_corner(f as usize) as u32;
                let mut c = start;
                loop {
                    let e = self.adjacency.corner_edges[c as usize] as usize;
                    if let &[c1, c2] = self.edge_corners(e) {
                        let other = if c1 == c { c2 } else { c1 };
                        let g = self.corners.face(other as usize);
                        // The same start vertex on both sides means both faces run the edge the same way.
                        let same_direction =
                            self.face_vertices[c as usize] == self.face_vertices[other as usize];
                        let wanted = face_flip[f as usize] ^ same_direction;
                        if g != f as usize {
                            if !visited[g] {
                                visited[g] = true;
                                face_flip[g] = wanted;
                                stack.push(g as u32);
                            } else if face_flip[g] != wanted {
                                disagreeing.push(g as u32);
                            }
                        }
                    }
                    c = self.corners.next(c as usize) as u32;
                    if c == start {
                        break;
                    }
                }
            }
        }
        (face_flip, disagreeing)
    }

    /// The counts and flags that `weft info` and `weft_mesh_info` report.
    pub fn info(&self, mesh: &Mesh) -> MeshInfo {
        // Edges by how many corners they have, and whether the manifold
        // ones already run opposite ways in their two faces: one parallel
        // pass; the orientation walk and the fans beside it.
        let offsets = &self.adjacency.edge_offsets;
        let ((naked_edge_count, non_manifold_edge_count, is_oriented), (orientation, fans)) =
            rayon::join(
                || {
                    (0..self.edge_count())
                        .into_par_iter()
                        .with_min_len(CHUNK)
                        .fold(
                            || (0usize, 0usize, true),
                            |(naked, non_manifold, oriented), e| {
                                let corners = offsets[e + 1] - offsets[e];
                                let opposite = corners != 2 || {
                                    let c = &self.adjacency.edge_corners[offsets[e] as usize..];
                                    self.face_vertices[c[0] as usize]
                                        != self.face_vertices[c[1] as usize]
                                };
                                (
                                    naked + (corners == 1) as usize,
                                    non_manifold + (corners > 2) as usize,
                                    oriented && opposite,
                                )
                            },
                        )
                        .reduce(|| (0, 0, true), |a, b| (a.0 + b.0, a.1 + b.1, a.2 && b.2))
                },
                || rayon::join(|| self.orientation(), || self.non_manifold_vertex_count()),
            );
        MeshInfo {
            vertex_count: mesh.vertex_count(),
            edge_count: self.edge_count(),
            face_count: mesh.face_count(),
            naked_edge_count,
            non_manifold_edge_count,
            non_manifold_vertex_count: fans,
            component_count: orientation.component_orientable.len(),
            is_closed: mesh.face_count() > 0
                && naked_edge_count == 0
                && non_manifold_edge_count == 0,
            is_orientable: orientation.component_orientable.iter().all(|&o| o),
            is_oriented,
        }
    }
}

/// What lies across an edge at a vertex, from one of its corners there.
enum Across {
    /// A naked edge: nothing.
    Naked,
    /// A manifold edge: the other face's corner at the vertex, and whether
    /// the edge runs into the vertex in that face.
    Joined(u32, bool),
    /// An edge of three or more faces.
    NonManifold,
}

/// The root of `x` in a small forest of parent links, halving the path.
fn root(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let grandparent = parent[parent[x as usize] as usize];
        parent[x as usize] = grandparent;
        x = grandparent;
    }
    x
}

/// Disjoint sets over `0..n` with path halving, each set's root its lowest
/// member: a union links the higher root under the lower, so every parent
/// lies below its child, which lets [`UnionFind::into_labels`] number the
/// sets in one pass over the parents themselves.
pub(crate) struct UnionFind {
    parent: Vec<u32>,
    /// Unions that joined two sets: the sets are `n - joined`.
    joined: usize,
}

impl UnionFind {
    pub(crate) fn new(n: usize) -> UnionFind {
        // Fresh, large and written once: on all threads, in huge pages.
        UnionFind {
            parent: crate::buffers::advised_map(n, |i| i as u32),
            joined: 0,
        }
    }

    pub(crate) fn find(&mut self, mut x: u32) -> u32 {
        while self.parent[x as usize] != x {
            let grandparent = self.parent[self.parent[x as usize] as usize];
            self.parent[x as usize] = grandparent;
            x = grandparent;
        }
        x
    }

    /// Joins the sets of `a` and `b`; returns the root of the union, the
    /// lowest member of both.
    pub(crate) fn union(&mut self, a: u32, b: u32) -> u32 {
        let (a, b) = (self.find(a), self.find(b));
        let (low, high) = (a.min(b), a.max(b));
        self.parent[high as usize] = low;
        self.joined += usize::from(low != high);
        low
    }

    /// Each element's set, numbered from 0 in order of the sets' lowest
    /// members, and the number of sets: written over the parents, in order,
    /// each element's from its parent's (which lies below it, so is numbered
    /// already).
    pub(crate) fn into_labels(self) -> (Vec<u32>, usize) {
        let mut labels = self.parent;
        if self.joined == 0 {
            // Every element its own set: the parents are the labels.
            let count = labels.len();
            return (labels, count);
        }
        let mut count = 0;
        for x in 0..labels.len() {
            let parent = labels[x] as usize;
            labels[x] = if parent == x {
                count += 1;
                count as u32 - 1
            } else {
                labels[parent]
            };
        }
        debug_assert_eq!(count, labels.len() - self.joined);
        (labels, count)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;

    #[test]
    fn union_find_numbers_its_sets_by_their_lowest_member() {
        // Unions in an order that links high roots first and leaves long
        // paths: {0, 4, 7}, {1}, {2, 3, 5, 8}, {6}.
        let mut sets = UnionFind::new(9);
        for (a, b) in [(8, 5), (5, 3), (7, 4), (3, 2), (4, 0), (8, 2), (7, 7)] {
            sets.union(a, b);
        }
        assert_eq!(sets.find(8), 2);
        let (labels, count) = sets.into_labels();
        assert_eq!(count, 4);
        assert_eq!(labels, [0, 1, 2, 2, 0, 2, 3, 0, 2]);
        assert_eq!(UnionFind::new(0).into_labels(), (Vec::new(), 0));
    }

    #[test]
    fn union_find_counts_only_the_unions_that_join_two_sets() {
        // Nothing joined: every element its own set.
        let mut sets = UnionFind::new(4);
        sets.union(2, 2);
        assert_eq!(sets.into_labels(), (vec![0, 1, 2, 3], 4));
        // One union, nothing repeated.
        let mut sets = UnionFind::new(3);
        sets.union(2, 0);
        assert_eq!(sets.into_labels(), (vec![0, 1, 0], 2));
        // A union of two members of one set joins nothing.
        let mut sets = UnionFind::new(4);
        for (a, b) in [(3, 1), (1, 3), (3, 3)] {
            sets.union(a, b);
        }
        assert_eq!(sets.joined, 1);
        assert_eq!(sets.into_labels(), (vec![0, 1, 2, 1], 3));
    }

    #[test]
    fn cube_is_closed_and_orientable() {
        let cube = shapes::cube();
        let topology = Topology::new(&cube);
        let info = topology.info(&cube);
        assert_eq!(
            (info.vertex_count, info.edge_count, info.face_count),
            (8, 12, 6)
        );
        assert_eq!(info.naked_edge_count, 0);
        assert_eq!(info.component_count, 1);
        assert!(info.is_closed && info.is_orientable && info.is_oriented);
        assert!(topology.vertex_valences().iter().all(|&v| v == 3));
    }

    #[test]
    fn open_grid_counts_its_naked_edges() {
        let grid = shapes::quad_grid(3, 2);
        let topology = Topology::new(&grid);
        let info = topology.info(&grid);
        assert_eq!(info.edge_count, 3 * 3 + 4 * 2);
        assert_eq!(info.naked_edge_count, 2 * (3 + 2));
        assert!(!info.is_closed);
        assert_eq!(info.non_manifold_vertex_count, 0);
    }

    #[test]
    fn fin_and_bow_tie_are_non_manifold() {
        let fin = shapes::fin();
        let info = Topology::new(&fin).info(&fin);
        assert_eq!(info.non_manifold_edge_count, 1);
        assert_eq!(info.non_manifold_vertex_count, 2);
        let bow_tie = shapes::bow_tie();
        let info = Topology::new(&bow_tie).info(&bow_tie);
        assert_eq!(info.non_manifold_edge_count, 0);
        assert_eq!(info.non_manifold_vertex_count, 1);
        // Components are joined through edges: the two fans meet only at a vertex.
        assert_eq!(info.component_count, 2);
    }

    #[test]
    fn flipped_face_is_orientable_but_not_oriented() {
        let cube = shapes::cube();
        let mut faces: Vec<Vec<u32>> = cube.faces().map(|f| f.to_vec()).collect();
        faces[2].reverse();
        let mesh = Mesh::from_polygons(cube.positions().to_vec(), faces).unwrap();
        let topology = Topology::new(&mesh);
        let info = topology.info(&mesh);
        assert!(info.is_orientable && !info.is_oriented);
        let orientation = topology.orientation();
        assert_eq!(orientation.face_flip.iter().filter(|&&f| f).count(), 1);
        assert!(orientation.face_flip[2]);
    }

    #[test]
    fn mobius_strip_is_not_orientable() {
        let strip = shapes::mobius_strip(8);
        let info = Topology::new(&strip).info(&strip);
        assert!(!info.is_orientable);
        assert_eq!(info.naked_edge_count, 16);
    }

    #[test]
    fn fan_count_equals_the_listed_non_manifold_vertices() {
        // Shapes with bow-ties, fins, flipped faces (edges run the same
        // way in both faces), n-gons, holes and a Möbius strip.
        let cube = shapes::cube();
        let mut flipped: Vec<Vec<u32>> = cube.faces().map(|f| f.to_vec()).collect();
        flipped[1].reverse();
        flipped[4].reverse();
        let flipped = Mesh::from_polygons(cube.positions().to_vec(), flipped).unwrap();
        let grid = shapes::quad_grid(4, 3);
        let mut pinched: Vec<Vec<u32>> = grid.faces().map(|f| f.to_vec()).collect();
        pinched.retain(|f| !f.contains(&6) || f.contains(&0));
        let pinched = Mesh::from_polygons(grid.positions().to_vec(), pinched).unwrap();
        let fin = shapes::fin();
        let mut fin_flipped: Vec<Vec<u32>> = fin.faces().map(|f| f.to_vec()).collect();
        fin_flipped[0].reverse();
        let fin_flipped = Mesh::from_polygons(fin.positions().to_vec(), fin_flipped).unwrap();
        // Faces that repeat a vertex (a pinched quad, a face meeting a pair
        // twice), as meshes built to allow them may hold.
        let repeats = Mesh::new_with(
            (0..7)
                .map(|i| glam::DVec3::new(i as f64, (i * i % 5) as f64, 0.0))
                .collect(),
            vec![4, 3, 5, 3],
            vec![0, 1, 0, 2, 0, 1, 3, 1, 2, 3, 4, 5, 3, 5, 6],
            crate::mesh::MeshOptions {
                allow_repeated_vertices: true,
            },
        )
        .unwrap();
        for mesh in [
            repeats,
            cube,
            flipped,
            pinched,
            fin,
            fin_flipped,
            shapes::bow_tie(),
            shapes::mobius_strip(7),
            shapes::mixed_polygons(),
            shapes::quad_grid_with_hole(),
            shapes::triangle_grid_with_hole(),
            shapes::l_shaped_hexagon(0.0),
            shapes::torus(5, 4),
        ] {
            let topology = Topology::new(&mesh);
            assert_eq!(
                topology.non_manifold_vertex_count(),
                topology.non_manifold_vertices().len()
            );
        }
    }

    #[test]
    fn find_edge_and_edge_faces_agree() {
        let cube = shapes::cube();
        let topology = Topology::new(&cube);
        for (e, &[a, b]) in topology.edges().iter().enumerate() {
            assert_eq!(topology.find_edge(b, a), Some(e));
            assert_eq!(topology.edge_faces(e).len(), 2);
        }
        assert_eq!(topology.find_edge(0, 7), None);
    }

    #[test]
    fn soup_info_is_known_without_the_edges() {
        let sizes = [3, 3, 4, 5, 3, 6];
        let info = MeshInfo::of(&shapes::soup(&sizes, 2, 9, false));
        assert_eq!(
            (info.vertex_count, info.edge_count, info.face_count),
            (26, 24, 6)
        );
        assert_eq!((info.naked_edge_count, info.component_count), (24, 6));
        assert!(!info.is_closed && info.is_orientable && info.is_oriented);
        // One vertex named twice, found through the edges: a bow tie, which
        // joins no pieces (pieces are joined through edges).
        let bow_tie = shapes::soup(&sizes, 2, 9, true);
        let info = MeshInfo::of(&bow_tie);
        assert_eq!(
            (info.component_count, info.non_manifold_vertex_count),
            (6, 1)
        );
        let empty = Mesh::empty();
        assert_eq!(MeshInfo::of(&empty), Topology::new(&empty).info(&empty));
    }

    proptest::proptest! {
        #[test]
        fn mesh_info_is_the_topology_s_info(mesh in shapes::soups()) {
            proptest::prop_assert_eq!(MeshInfo::of(&mesh), Topology::new(&mesh).info(&mesh));
        }

        #[test]
        fn the_walk_around_a_vertex_agrees_with_the_union_of_its_fans(mesh in shapes::tangles()) {
            let topology = Topology::new(&mesh);
            let mut scratch = Vec::new();
            for v in 0..mesh.vertex_count() {
                let corners = topology.vertex_corners(v);
                if let Some(walked) = topology.walk_one_fan(v, corners, &mut scratch) {
                    let joined = topology.joins_leave_several_fans(v, corners, &mut scratch);
                    proptest::prop_assert_eq!(walked, joined, "vertex {}", v);
                }
            }
            proptest::prop_assert_eq!(
                topology.non_manifold_vertex_count(),
                topology.non_manifold_vertices().len()
            );
        }
    }
}
