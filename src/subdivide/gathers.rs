//! Plans and gathers: where the arithmetic pass finds the old points each
//! new point gathers.
//!
//! A [`Plan`] (made by [`plan`]) stores the gathers of a level once, for a refiner to re-apply
//! to new positions. A one-shot subdivision applies each level once, so it
//! reads the same gathers where they already lie: [`LevelGathers`] from the
//! level's faces, connectivity and tags, and for the last level
//! [`RefinedGathers`] (Catmull-Clark) or [`LoopRefinedGathers`] (Loop, in
//! `gathers/loop_refined.rs`) from its parent level's, so that the largest
//! connectivity is never built. All give the same gathers in the same
//! order, so all give the same bits.

use glam::DVec3;

use super::level::{position, Connectivity, Faces, NONE};
use super::rules::Tags;
use super::scheme::{Scheme, VertexRule};
use crate::buffers::{fill_by_offsets, par_map, par_offsets};
use crate::error::Result;

/// What the arithmetic pass needs to make one level from the previous one:
/// every new point as a gather of old points (and, for Catmull-Clark, of the
/// new face points).
#[derive(Debug, Clone)]
pub(crate) struct Plan {
    pub(crate) scheme: Scheme,
    /// Vertex count of the level the plan reads.
    pub(crate) vertex_count: usize,
    /// The faces of the level the plan reads (for face points; empty for
    /// Loop), without offsets when they are of one size (every refined
    /// level): their corners are found by arithmetic.
    pub(crate) faces: Faces<'static>,
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
    /// For a level refined from a parent level: where its elements group
    /// around the parent's, so that the plan is applied parent element by
    /// parent element, as one-shot subdivision makes its last level.
    pub(crate) parent: Option<ParentGroups>,
    /// Catmull-Clark: how the passes around the parent's elements go band
    /// by band (see [`super::bands`]), for a large level.
    pub(crate) bands: Option<super::bands::Bands>,
}

/// How the elements of a level refined from a parent level group around
/// the parent's elements, in the level's own order (see
/// `Connectivity::refine`): each list runs over the parent's elements,
/// plus the total.
#[derive(Debug, Clone)]
pub(crate) struct ParentGroups {
    /// Catmull-Clark: the level's faces made in parent face f, one per
    /// corner (empty for Loop).
    pub(crate) face_faces: Vec<u32>,
    /// The level's edges inside the parent's faces, grouped by the parent
    /// edge they meet (Catmull-Clark: one per corner of the edge; Loop:
    /// those whose lower parent edge it is), counted from the first of them.
    pub(crate) edge_inside: Vec<u32>,
    /// The level's halves of the parent's edges at parent vertex v, counted
    /// from the level's first edge.
    pub(crate) vertex_halves: Vec<u32>,
}

impl ParentGroups {
    /// The parent's vertex and edge counts.
    pub(crate) fn parent_counts(&self) -> (usize, usize) {
        (self.vertex_halves.len() - 1, self.edge_inside.len() - 1)
    }
}

impl Plan {
    /// The ring of vertex `v` (see [`Plan::vertex_ring`]).
    #[inline]
    pub(crate) fn ring(&self, v: usize) -> &[u32] {
        &self.vertex_ring
            [self.vertex_ring_offsets[v] as usize..self.vertex_ring_offsets[v + 1] as usize]
    }
}

/// The gathers that make the next level's points from this level's, stored
/// (see [`LevelGathers`] for where each is found).
pub(crate) fn plan(
    scheme: Scheme,
    faces: &Faces,
    connectivity: &Connectivity,
    tags: &Tags,
) -> Result<Plan> {
    let level = LevelGathers {
        scheme,
        faces,
        connectivity,
        tags,
        groups: None,
    };
    let vertex_count = faces.vertex_count;
    let edges = par_map(connectivity.edge_count(), "edge stencils", |e| {
        level.edge(e)
    })?;

    let per_neighbour = scheme.ring_stride() as u32;
    let ring_offsets = par_offsets(vertex_count, "vertex stencils", |v| {
        match tags.vertex_rules[v] {
            VertexRule::Smooth => per_neighbour * connectivity.vertex_corners(v).len() as u32,
            VertexRule::Crease => 2,
            VertexRule::Corner => 0,
        }
    })?;
    let ring = fill_by_offsets(&ring_offsets, "vertex stencils", |v, slot| {
        match tags.vertex_rules[v] {
            VertexRule::Smooth => {
                let n = slot.len() / per_neighbour as usize;
                let mut i = 0;
                level.around(v, |u, f| {
                    slot[i] = u;
                    if per_neighbour == 2 {
                        slot[n + i] = f;
                    }
                    i += 1;
                });
            }
            VertexRule::Crease => slot.copy_from_slice(&level.crease_neighbours(v)),
            VertexRule::Corner => {}
        }
    })?;

    // The caller moves the faces in for Catmull-Clark (see `Plan::faces`).
    Ok(Plan {
        scheme,
        vertex_count,
        faces: Faces::default(),
        edges,
        vertex_rules: tags.vertex_rules.clone(),
        vertex_ring_offsets: ring_offsets,
        vertex_ring: ring,
        parent: None,
        bands: None,
    })
}

/// Prefetches `values[i]` when there is one (see [`weft_pages::prefetch`]).
#[inline]
pub(crate) fn prefetch_at<T>(values: &[T], i: usize) {
    if let Some(value) = values.get(i) {
        weft_pages::prefetch(value);
    }
}

/// The gathers of one level, as the scheme's point rules read them.
/// Vertex `v`'s point when its rule is sharp, the same in both schemes: a
/// corner stays, a crease takes 3/4 of itself and 1/8 of each crease
/// neighbour. `None` for a smooth vertex, whose mask is the scheme's.
#[inline]
pub(crate) fn sharp_vertex_point(
    level: &impl Gathers,
    points: &[DVec3],
    v: usize,
) -> Option<DVec3> {
    let p = points[v];
    match level.rule(v) {
        VertexRule::Corner => Some(p),
        VertexRule::Crease => {
            let [a, b] = level.crease_neighbours(v);
            Some(crease_point(p, points[a as usize], points[b as usize]))
        }
        VertexRule::Smooth => None,
    }
}

/// Writes the points of `level`'s edges `first..first + outs.len()` into
/// `outs` by the scheme's edge `rule`, each edge's gather read straight
/// from the plan when `level` is one.
#[inline]
pub(crate) fn edge_points_into(
    level: &impl Gathers,
    first: usize,
    outs: &mut [DVec3],
    rule: impl Fn([u32; 4]) -> DVec3,
) {
    match level.as_plan() {
        Some(plan) => {
            let edges = &plan.edges[first..first + outs.len()];
            for (out, &edge) in outs.iter_mut().zip(edges) {
                *out = rule(edge);
            }
        }
        None => {
            for (k, out) in outs.iter_mut().enumerate() {
                *out = rule(level.edge(first + k));
            }
        }
    }
}

/// The point of a crease vertex at `p` whose crease neighbours are at `a`
/// and `b`.
#[inline]
fn crease_point(p: DVec3, a: DVec3, b: DVec3) -> DVec3 {
    p * 0.75 + (a + b) * 0.125
}

/// [`sharp_vertex_point`] of a plan's vertex `v` of a sharp `rule`, whose
/// `ring` holds its crease neighbours (see [`Plan::vertex_ring`]).
#[inline]
pub(crate) fn planned_sharp_point(
    rule: VertexRule,
    points: &[DVec3],
    v: usize,
    ring: &[u32],
) -> DVec3 {
    match (rule, ring) {
        (VertexRule::Crease, &[a, b]) => {
            crease_point(points[v], points[a as usize], points[b as usize])
        }
        _ => points[v],
    }
}

pub(crate) trait Gathers: Sync {
    /// Vertex count of the level read.
    fn vertex_count(&self) -> usize;
    /// Edge count of the level read, in edge-point order.
    fn edge_count(&self) -> usize;
    /// Face count of the level read (0 when the scheme makes no face points).
    fn face_count(&self) -> usize;
    /// The vertices of face `f`, in order.
    fn face(&self, f: usize) -> impl ExactSizeIterator<Item = u32> + '_;
    /// Edge `e` as `[a, b, wing, wing]` (see [`Plan::edges`]).
    fn edge(&self, e: usize) -> [u32; 4];
    /// How vertex `v`'s point is made.
    fn rule(&self, v: usize) -> VertexRule;
    /// A crease vertex's two sharp neighbours.
    fn crease_neighbours(&self, v: usize) -> [u32; 2];
    /// Visits a smooth vertex's neighbours around it, each with the face it
    /// is reached through (Catmull-Clark; [`NONE`] for Loop), and returns
    /// how many there are.
    fn around(&self, v: usize, visit: impl FnMut(u32, u32)) -> usize;
    /// These gathers as [`RefinedGathers`], when they are: their points
    /// are made around the parent's faces, edges and vertices.
    fn as_refined(&self) -> Option<RefinedGathers<'_>> {
        None
    }
    /// These gathers as [`LoopRefinedGathers`], when they are: their points
    /// are made around the parent's edges and vertices.
    fn as_loop_refined(&self) -> Option<&LoopRefinedGathers<'_>> {
        None
    }
    /// These gathers as a stored [`Plan`], when they are.
    fn as_plan(&self) -> Option<&Plan> {
        None
    }
    /// How the level's elements group around the level it was refined
    /// from, when known (see [`Plan::parent`]).
    fn parent_groups(&self) -> Option<&ParentGroups> {
        None
    }
}

impl Gathers for Plan {
    fn vertex_count(&self) -> usize {
        self.vertex_count
    }

    fn as_plan(&self) -> Option<&Plan> {
        Some(self)
    }

    fn parent_groups(&self) -> Option<&ParentGroups> {
        self.parent.as_ref()
    }

    fn edge_count(&self) -> usize {
        self.edges.len()
    }

    fn face_count(&self) -> usize {
        self.faces.face_count()
    }

    #[inline]
    fn face(&self, f: usize) -> impl ExactSizeIterator<Item = u32> + '_ {
        self.faces.face(f).iter().copied()
    }

    #[inline]
    fn edge(&self, e: usize) -> [u32; 4] {
        self.edges[e]
    }

    #[inline]
    fn rule(&self, v: usize) -> VertexRule {
        self.vertex_rules[v]
    }

    #[inline]
    fn crease_neighbours(&self, v: usize) -> [u32; 2] {
        let ring = self.ring(v);
        [ring[0], ring[1]]
    }

    #[inline]
    fn around(&self, v: usize, mut visit: impl FnMut(u32, u32)) -> usize {
        let ring = self.ring(v);
        let n = ring.len() / self.scheme.ring_stride();
        for i in 0..n {
            visit(ring[i], if n < ring.len() { ring[n + i] } else { NONE });
        }
        n
    }
}

/// The gathers of a level read from its faces, connectivity and tags.
#[derive(Clone, Copy)]
pub(crate) struct LevelGathers<'a> {
    pub(crate) scheme: Scheme,
    pub(crate) faces: &'a Faces<'a>,
    pub(crate) connectivity: &'a Connectivity,
    pub(crate) tags: &'a Tags,
    /// How the level groups around the level it was refined from, when
    /// known (see [`Plan::parent`]).
    pub(crate) groups: Option<&'a ParentGroups>,
}

impl LevelGathers<'_> {
    /// The vertex following corner `c` in its face.
    #[inline]
    fn next_vertex(&self, c: usize) -> u32 {
        self.faces.indices[self.next(c)]
    }

    #[inline]
    pub(crate) fn next(&self, c: usize) -> usize {
        self.faces.next(c, self.connectivity.face_of(c))
    }

    #[inline]
    fn prev(&self, c: usize) -> usize {
        self.faces.prev(c, self.connectivity.face_of(c))
    }

    /// The first two of `v`'s sharp edges in edge order ([`NONE`] past the
    /// last; a crease vertex has exactly two): each edge at `v` leaves it
    /// from one of its corners or arrives at one.
    fn crease_edges(&self, v: usize) -> [u32; 2] {
        let connectivity = self.connectivity;
        let mut sharp = [NONE; 2];
        for &c in connectivity.vertex_corners(v) {
            let c = c as usize;
            for e in [
                connectivity.corner_edges[c],
                connectivity.corner_edges[self.prev(c)],
            ] {
                if !self.tags.edge_sharp[e as usize] || sharp.contains(&e) {
                    continue;
                }
                if e < sharp[0] {
                    sharp = [e, sharp[0]];
                } else if e < sharp[1] {
                    sharp[1] = e;
                }
            }
        }
        sharp
    }
}

impl Gathers for LevelGathers<'_> {
    fn parent_groups(&self) -> Option<&ParentGroups> {
        self.groups
    }

    fn vertex_count(&self) -> usize {
        self.faces.vertex_count
    }

    fn edge_count(&self) -> usize {
        self.connectivity.edge_count()
    }

    fn face_count(&self) -> usize {
        self.scheme.face_point_count(self.faces.face_count())
    }

    #[inline]
    fn face(&self, f: usize) -> impl ExactSizeIterator<Item = u32> + '_ {
        self.faces.face(f).iter().copied()
    }

    #[inline]
    fn edge(&self, e: usize) -> [u32; 4] {
        let connectivity = self.connectivity;
        let [a, b] = connectivity.edges[e];
        let wings = match (self.tags.edge_sharp[e], connectivity.edge_corners(e)) {
            (false, &[c1, c2]) => match self.scheme {
                Scheme::CatmullClark => [c1, c2].map(|c| connectivity.face_of(c as usize) as u32),
                // The vertex opposite the edge in a triangle follows the edge's far end.
                Scheme::Loop => [c1, c2].map(|c| self.next_vertex(self.next(c as usize))),
            },
            _ => [NONE, NONE],
        };
        [a, b, wings[0], wings[1]]
    }

    #[inline]
    fn rule(&self, v: usize) -> VertexRule {
        self.tags.vertex_rules[v]
    }

    fn crease_neighbours(&self, v: usize) -> [u32; 2] {
        self.crease_edges(v).map(|e| match e {
            NONE => v as u32,
            e => {
                let [a, b] = self.connectivity.edges[e as usize];
                if a as usize == v {
                    b
                } else {
                    a
                }
            }
        })
    }

    #[inline]
    fn around(&self, v: usize, mut visit: impl FnMut(u32, u32)) -> usize {
        // Around a smooth (manifold, interior, oriented) vertex each edge
        // leaves v in exactly one face: the corners' next vertices are the ring.
        let corners = self.connectivity.vertex_corners(v);
        for &c in corners {
            let c = c as usize;
            let face = match self.scheme {
                Scheme::CatmullClark => self.connectivity.face_of(c) as u32,
                Scheme::Loop => NONE,
            };
            visit(self.next_vertex(c), face);
        }
        corners.len()
    }
}

/// The gathers of the level Catmull-Clark makes from `parent`, read from the
/// parent's faces, connectivity (with its vertices' edges) and tags: the
/// level's faces, edges, corners and rings are each a known function of the
/// parent's (as [`Connectivity::refine`] writes them), so they are worked
/// out where needed instead of stored.
///
/// With the parent's V vertices, E edges and F faces and corners c: the
/// level's vertices are the parent's vertices, then `V + e`, then `V + E + f`;
/// its face c is the quad `[v_c, V + e_c, V + E + f_c, V + e_prev(c)]`, whose
/// corners are `4c..4c + 4`; its edges are `[v, V + e]` for the parent's
/// vertex-edge slots (2E of them), then `[V + e, V + E + f]` for its
/// edge-corner slots.
#[derive(Clone, Copy)]
pub(crate) struct RefinedGathers<'a> {
    pub(crate) parent: LevelGathers<'a>,
}

impl RefinedGathers<'_> {
    fn parent_counts(&self) -> (usize, usize) {
        (
            self.parent.faces.vertex_count,
            self.parent.connectivity.edge_count(),
        )
    }

    /// The level's face c, made at the parent's corner c.
    #[inline]
    pub(crate) fn quad(&self, c: usize) -> [u32; 4] {
        let (v, e) = self.parent_counts();
        let parent = &self.parent;
        let corner_edges = &parent.connectivity.corner_edges;
        [
            parent.faces.indices[c],
            (v as u32) + corner_edges[c],
            (v + e + parent.connectivity.face_of(c)) as u32,
            (v as u32) + corner_edges[parent.prev(c)],
        ]
    }

    /// The edges of the level's face c, in its corners' order (the edge
    /// from each corner to the next).
    #[inline]
    pub(crate) fn quad_edges(&self, c: usize) -> [u32; 4] {
        self.parent
            .connectivity
            .child_quad_edges(self.parent.faces, c)
    }

    /// [`RefinedGathers::quad`] of the four corners of the parent's quad
    /// `q`, when the parent's faces are all quads: each corner's edge is
    /// read once for the two faces that name its point.
    #[inline]
    pub(crate) fn quads_of_quad(&self, q: usize) -> [[u32; 4]; 4] {
        let (v, e) = self.parent_counts();
        let first = 4 * q;
        let vertices = &self.parent.faces.indices[first..first + 4];
        let edges = &self.parent.connectivity.corner_edges[first..first + 4];
        let face_point = (v + e + q) as u32;
        let mut quads = [[0u32; 4]; 4];
        for (j, quad) in quads.iter_mut().enumerate() {
            let previous = (j + 3) % 4;
            let (edge, edge_before) = (v as u32 + edges[j], v as u32 + edges[previous]);
            *quad = [vertices[j], edge, face_point, edge_before];
        }
        quads
    }

    /// [`RefinedGathers::quad_edges`] of the four corners of the parent's
    /// quad `q`, when the parent's faces are all quads.
    #[inline]
    pub(crate) fn quad_edges_of_quad(&self, q: usize) -> [[u32; 4]; 4] {
        self.parent
            .connectivity
            .child_quad_edges_of_quad(self.parent.faces, q)
    }
}

/// The most edges [`RefinedGathers::slot_wings`] walks around at once.
pub(crate) const MAX_WALKED_EDGES: usize = 32;

impl RefinedGathers<'_> {
    /// The wings of the level's edges `[v, V + e]` at the parent's vertex
    /// `v`, one per slot of `v`'s edges in order, as [`Gathers::edge`] gives
    /// them, found in one walk around `v` instead of edge by edge: the
    /// child quad at each corner k of `v` lies beside the halves at `v` of
    /// both of k's edges. `None` where [`slot_wings_around`] is.
    #[inline]
    pub(crate) fn slot_wings(&self, v: usize) -> Option<[[u32; 2]; MAX_WALKED_EDGES]> {
        let k = |k: usize, _leaving: bool| (k as u32, k as u32);
        slot_wings_around(&self.parent, v, k)
    }
}

/// The wings of the halves at the parent's vertex `v` of its edges, one
/// per slot of `v`'s edges in order, found in one walk around `v`: each
/// corner k of `v` lies beside the halves of both its edges, the one
/// leaving v and the one arriving, and `wing(k, leaving)` gives that
/// half's wing there as (its order among the half's wings, the wing). The
/// half of a smooth edge has exactly two, in that order; a sharp edge's
/// are [`NONE`]. `None` for a vertex of more than [`MAX_WALKED_EDGES`]
/// edges, or where a smooth edge's half is not beside two corners: there
/// [`Gathers::edge`] gives them one by one.
#[inline]
pub(crate) fn slot_wings_around(
    parent: &LevelGathers,
    v: usize,
    wing: impl Fn(usize, bool) -> (u32, u32),
) -> Option<[[u32; 2]; MAX_WALKED_EDGES]> {
    let connectivity = parent.connectivity;
    let edges = connectivity.vertex_edges(v);
    if edges.len() > MAX_WALKED_EDGES {
        return None;
    }
    let mut wings = [[NONE; 2]; MAX_WALKED_EDGES];
    let mut first_orders = [0u32; MAX_WALKED_EDGES];
    let mut counts = [0u8; MAX_WALKED_EDGES];
    for &k in connectivity.vertex_corners(v) {
        let k = k as usize;
        let leaving = connectivity.corner_edges[k];
        let arriving = connectivity.corner_edges[parent.prev(k)];
        for (e, is_leaving) in [(leaving, true), (arriving, false)] {
            let i = position(edges, e) as usize;
            let (order, found) = wing(k, is_leaving);
            match counts[i] {
                0 => (wings[i][0], first_orders[i]) = (found, order),
                1 if order < first_orders[i] => wings[i] = [found, wings[i][0]],
                1 => wings[i][1] = found,
                _ => {}
            }
            counts[i] = counts[i].saturating_add(1);
        }
    }
    for (i, &e) in edges.iter().enumerate() {
        match parent.tags.edge_sharp[e as usize] {
            true => wings[i] = [NONE; 2],
            // Not met by a smooth edge: there, edge by edge.
            false if counts[i] != 2 => return None,
            false => {}
        }
    }
    Some(wings)
}

/// The two faces of a child edge from its two corners, in the order of the
/// corners (as the level's sorted edge corners list them).
#[inline]
fn faces_of_corners(k1: u32, k2: u32) -> [u32; 2] {
    [k1.min(k2) / 4, k1.max(k2) / 4]
}

impl Gathers for RefinedGathers<'_> {
    fn as_refined(&self) -> Option<RefinedGathers<'_>> {
        Some(*self)
    }

    fn vertex_count(&self) -> usize {
        let (v, e) = self.parent_counts();
        v + e + self.parent.faces.face_count()
    }

    fn edge_count(&self) -> usize {
        let (_, e) = self.parent_counts();
        2 * e + self.parent.faces.corner_count()
    }

    fn face_count(&self) -> usize {
        self.parent.faces.corner_count()
    }

    #[inline]
    fn face(&self, f: usize) -> impl ExactSizeIterator<Item = u32> + '_ {
        self.quad(f).into_iter()
    }

    #[inline]
    fn edge(&self, s: usize) -> [u32; 4] {
        let (v_count, e_count) = self.parent_counts();
        let parent = &self.parent;
        let connectivity = parent.connectivity;
        let idx = &parent.faces.indices;
        match s.checked_sub(2 * e_count) {
            None => {
                let e = connectivity.vertex_edges[s] as usize;
                let v = connectivity.slot_vertex(s) as usize;
                let wings = match (parent.tags.edge_sharp[e], connectivity.edge_corners(e)) {
                    (false, &[c1, c2]) => {
                        // The child quad at c holds the half of e at v, or the one after c.
                        let corner = |c: u32| {
                            let c = c as usize;
                            if idx[c] as usize == v {
                                4 * c as u32
                            } else {
                                4 * parent.next(c) as u32 + 3
                            }
                        };
                        faces_of_corners(corner(c1), corner(c2))
                    }
                    _ => [NONE, NONE],
                };
                [v as u32, (v_count + e) as u32, wings[0], wings[1]]
            }
            Some(k) => {
                let c = connectivity.edge_corners[k] as usize;
                let e = connectivity.corner_edges[c] as usize;
                let f = connectivity.face_of(c);
                let [f0, f1] = faces_of_corners(4 * c as u32 + 1, 4 * parent.next(c) as u32 + 2);
                [(v_count + e) as u32, (v_count + e_count + f) as u32, f0, f1]
            }
        }
    }

    #[inline]
    fn rule(&self, u: usize) -> VertexRule {
        let (v_count, e_count) = self.parent_counts();
        match u {
            u if u < v_count => self.parent.tags.vertex_rules[u],
            u if u < v_count + e_count && self.parent.tags.edge_sharp[u - v_count] => {
                VertexRule::Crease
            }
            _ => VertexRule::Smooth,
        }
    }

    fn crease_neighbours(&self, u: usize) -> [u32; 2] {
        let (v_count, e_count) = self.parent_counts();
        if u < v_count {
            // The halves of the parent's two sharp edges at u.
            self.parent.crease_edges(u).map(|e| match e {
                NONE => u as u32,
                e => v_count as u32 + e,
            })
        } else if u < v_count + e_count {
            // The point of a sharp edge: both halves are sharp.
            self.parent.connectivity.edges[u - v_count]
        } else {
            [u as u32; 2]
        }
    }

    #[inline]
    fn around(&self, u: usize, mut visit: impl FnMut(u32, u32)) -> usize {
        let (v_count, e_count) = self.parent_counts();
        let parent = &self.parent;
        let connectivity = parent.connectivity;
        let corner_edges = &connectivity.corner_edges;
        if u < v_count {
            // Child corner 4c of each parent corner c at u: next comes V + e_c.
            let corners = connectivity.vertex_corners(u);
            for &c in corners {
                visit(v_count as u32 + corner_edges[c as usize], c);
            }
            corners.len()
        } else if u < v_count + e_count {
            // Child corners 4c + 1 (next: the face point of c's face) and
            // 4 next(c) + 3 (next: next(c)'s vertex), visited in corner order.
            let mut ring = [(0u32, 0u32, 0u32); 4];
            let corners = connectivity.edge_corners(u - v_count);
            for (pair, &c) in ring.chunks_exact_mut(2).zip(corners) {
                let c = c as usize;
                let next = parent.next(c);
                let face_point = (v_count + e_count + connectivity.face_of(c)) as u32;
                pair[0] = (4 * c as u32 + 1, face_point, c as u32);
                pair[1] = (4 * next as u32 + 3, parent.faces.indices[next], next as u32);
            }
            // A smooth edge has two corners.
            let n = (2 * corners.len()).min(4);
            ring[..n].sort_unstable();
            for &(_, neighbour, face) in &ring[..n] {
                visit(neighbour, face);
            }
            n
        } else {
            // Child corner 4c + 2 of each corner c of the face: next comes V + e_prev(c).
            let corners = parent.faces.corners(u - v_count - e_count);
            let n = corners.len();
            for c in corners {
                visit(v_count as u32 + corner_edges[parent.prev(c)], c as u32);
            }
            n
        }
    }
}

mod loop_refined;
pub(crate) use loop_refined::LoopRefinedGathers;

#[cfg(test)]
mod tests;
