//! The gathers of the level Loop makes from a parent level, read from the
//! parent's faces, connectivity (with its vertices' edges) and tags, as
//! [`RefinedGathers`](super::RefinedGathers) reads Catmull-Clark's: the
//! level's faces, edges, corners and rings are each a known function of
//! the parent's (as `Connectivity::refine` writes them for Loop), so a
//! one-shot Loop subdivision never builds the connectivity of the level
//! before its last, the largest it would build. Only the order of the
//! edges inside the faces takes a table.
//!
//! With the parent's V vertices, E edges and triangles f of corners
//! `3f + i` at `v_i`, whose edge `e_i` runs from `v_i` to `v_(i+1)`, and
//! `E_i = V + e_i`: the level's vertices are the parent's, then `V + e`;
//! its triangle `4f + i` (i < 3) is `[v_i, E_i, E_(i-1)]` and `4f + 3` is
//! `[E_0, E_1, E_2]`, with corners `12f + 3k + j`; its edges are
//! `[v, V + e]` for the parent's vertex-edge slots (2E of them), then the
//! edges inside the triangles, `[V + m, V + h]` grouped by the lower parent
//! edge m, sorted by h, then by triangle.

use super::{slot_wings_around, Gathers, LevelGathers, MAX_WALKED_EDGES};
use crate::error::Result;
use crate::subdivide::level::{LoopInsideEdges, NONE};
use crate::subdivide::scheme::VertexRule;

/// A Loop level's gathers worked out from its parent's (see the module doc).
pub(crate) struct LoopRefinedGathers<'a> {
    pub(crate) parent: LevelGathers<'a>,
    /// The level's edges inside the parent's triangles.
    inside: LoopInsideEdges,
}

impl<'a> LoopRefinedGathers<'a> {
    /// The gathers of the level Loop makes from `parent`, whose
    /// connectivity has its vertices' edges.
    ///
    /// # Errors
    /// [`crate::Error::OutOfMemory`].
    pub(crate) fn new(parent: LevelGathers<'a>) -> Result<LoopRefinedGathers<'a>> {
        let inside = parent.connectivity.loop_inside_table()?;
        Ok(LoopRefinedGathers { parent, inside })
    }

    /// Where the edges inside triangles whose lower parent edge is m start
    /// among the level's inside edges (m from 0 to E, inclusive).
    pub(crate) fn inside_offsets(&self) -> &[u32] {
        &self.inside.offsets
    }

    fn parent_counts(&self) -> (usize, usize) {
        (
            self.parent.faces.vertex_count,
            self.parent.connectivity.edge_count(),
        )
    }

    #[inline]
    fn edges_from(&self, c: usize) -> [u32; 3] {
        edges_from(&self.parent.connectivity.corner_edges, c)
    }

    /// The level's edge inside parent triangle f between the points of its
    /// edges x and y.
    #[inline]
    fn inside(&self, f: usize, x: u32, y: u32) -> u32 {
        (2 * self.parent_counts().1 + self.inside.find(f, x, y)) as u32
    }

    /// The wings of the level's edges `[v, V + e]` at the parent's vertex
    /// `v`, one per slot of `v`'s edges in order, as [`Gathers::edge`] gives
    /// them, found in one walk around `v` (see [`slot_wings_around`]):
    /// `v`'s corner `3f + i` makes the triangle `[v_i, E_i, E_(i-1)]`, child
    /// corner `12f + 3i`, beside the half leaving `v` opposite `E_(i-1)`
    /// and the half arriving opposite `E_i`.
    #[inline]
    pub(crate) fn slot_wings(&self, v: usize) -> Option<[[u32; 2]; MAX_WALKED_EDGES]> {
        let v_count = self.parent_counts().0 as u32;
        slot_wings_around(&self.parent, v, |k, leaving| {
            let [own, _, previous] = self.edges_from(k);
            let child = 12 * (k / 3) as u32 + 3 * (k % 3) as u32;
            match leaving {
                true => (child, v_count + previous),
                false => (child + 2, v_count + own),
            }
        })
    }

    /// The level's four triangles made from parent triangle f, in order,
    /// each as its vertices and its edges (from each corner to the next).
    #[inline]
    pub(crate) fn children(&self, f: usize) -> [([u32; 3], [u32; 3]); 4] {
        let (v_count, _) = self.parent_counts();
        let connectivity = self.parent.connectivity;
        let idx = &self.parent.faces.indices;
        let v = [idx[3 * f], idx[3 * f + 1], idx[3 * f + 2]];
        let corner_edges = &connectivity.corner_edges;
        let e = [
            corner_edges[3 * f],
            corner_edges[3 * f + 1],
            corner_edges[3 * f + 2],
        ];
        let points = [
            v_count as u32 + e[0],
            v_count as u32 + e[1],
            v_count as u32 + e[2],
        ];
        // The edge inside f between E_i and E_(i+1), found once for the
        // two children it bounds.
        let inner = [
            self.inside(f, e[0], e[1]),
            self.inside(f, e[1], e[2]),
            self.inside(f, e[2], e[0]),
        ];
        let corner = |i: usize| {
            let previous = PREVIOUS[i];
            (
                [v[i], points[i], points[previous]],
                [
                    connectivity.vertex_edge_slot(v[i], e[i]),
                    inner[previous],
                    connectivity.vertex_edge_slot_arriving(v[i], e[previous]),
                ],
            )
        };
        [corner(0), corner(1), corner(2), (points, inner)]
    }
}

/// The edges of corner c's triangle: c's own, then the next corner's,
/// then the previous corner's.
#[inline]
fn edges_from(corner_edges: &[u32], c: usize) -> [u32; 3] {
    let first = c - c % 3;
    [
        corner_edges[c],
        corner_edges[first + NEXT[c - first]],
        corner_edges[first + PREVIOUS[c - first]],
    ]
}

/// The corner after and the corner before each of a triangle's three.
const NEXT: [usize; 3] = [1, 2, 0];
const PREVIOUS: [usize; 3] = [2, 0, 1];

impl Gathers for LoopRefinedGathers<'_> {
    fn as_loop_refined(&self) -> Option<&LoopRefinedGathers<'_>> {
        Some(self)
    }

    fn vertex_count(&self) -> usize {
        let (v, e) = self.parent_counts();
        v + e
    }

    fn edge_count(&self) -> usize {
        2 * self.parent_counts().1 + self.inside.edges.len()
    }

    fn face_count(&self) -> usize {
        0
    }

    fn face(&self, f: usize) -> impl ExactSizeIterator<Item = u32> + '_ {
        self.children(f / 4)[f % 4].0.into_iter()
    }

    #[inline]
    fn edge(&self, s: usize) -> [u32; 4] {
        let (v_count, e_count) = self.parent_counts();
        let parent = &self.parent;
        let connectivity = parent.connectivity;
        let idx = &parent.faces.indices;
        let point = |e: u32| v_count as u32 + e;
        match s.checked_sub(2 * e_count) {
            None => {
                let e = connectivity.vertex_edges[s] as usize;
                let v = connectivity.slot_vertex(s);
                let wings = match (parent.tags.edge_sharp[e], connectivity.edge_corners(e)) {
                    (false, &[c1, c2]) => {
                        // The half at v lies in [v_i, E_i, E_(i-1)] when the
                        // corner is at v, else in [v_(i+1), E_(i+1), E_i]:
                        // each with its child corner and the vertex opposite.
                        let wing = |c: u32| {
                            let [_, next, previous] = self.edges_from(c as usize);
                            let (f, i) = (c / 3, c % 3);
                            if idx[c as usize] == v {
                                (12 * f + 3 * i, point(previous))
                            } else {
                                (12 * f + 3 * NEXT[i as usize] as u32 + 2, point(next))
                            }
                        };
                        let (w1, w2) = (wing(c1), wing(c2));
                        let (w1, w2) = if w1.0 < w2.0 { (w1, w2) } else { (w2, w1) };
                        [w1.1, w2.1]
                    }
                    _ => [NONE, NONE],
                };
                [v, point(e as u32), wings[0], wings[1]]
            }
            Some(k) => {
                // The edge between E_j and E_(j+1) of triangle f lies in
                // [v_(j+1), E_(j+1), E_j], opposite v_(j+1), and in
                // [E_0, E_1, E_2], opposite E_(j+2).
                let (h, f, m) = self.inside.edges[k];
                let f = f as usize;
                let edges = &connectivity.corner_edges[3 * f..3 * f + 3];
                let i = edges.iter().position(|&e| e == m).unwrap_or(0);
                let j = if edges[NEXT[i]] == h { i } else { PREVIOUS[i] };
                [
                    point(m),
                    point(h),
                    idx[3 * f + NEXT[j]],
                    point(edges[PREVIOUS[j]]),
                ]
            }
        }
    }

    #[inline]
    fn rule(&self, u: usize) -> VertexRule {
        let (v_count, _) = self.parent_counts();
        match u.checked_sub(v_count) {
            None => self.parent.tags.vertex_rules[u],
            Some(e) if self.parent.tags.edge_sharp[e] => VertexRule::Crease,
            Some(_) => VertexRule::Smooth,
        }
    }

    fn crease_neighbours(&self, u: usize) -> [u32; 2] {
        let (v_count, _) = self.parent_counts();
        match u.checked_sub(v_count) {
            // The halves of the parent's two sharp edges at u.
            None => self.parent.crease_edges(u).map(|e| match e {
                NONE => u as u32,
                e => v_count as u32 + e,
            }),
            // The point of a sharp edge: both halves are sharp.
            Some(e) => self.parent.connectivity.edges[e],
        }
    }

    #[inline]
    fn around(&self, u: usize, mut visit: impl FnMut(u32, u32)) -> usize {
        let (v_count, _) = self.parent_counts();
        let parent = &self.parent;
        let connectivity = parent.connectivity;
        let Some(e) = u.checked_sub(v_count) else {
            // Child corner 0 of [v_i, E_i, E_(i-1)]: next comes E_i.
            let corners = connectivity.vertex_corners(u);
            for &c in corners {
                visit(v_count as u32 + connectivity.corner_edges[c as usize], NONE);
            }
            return corners.len();
        };
        // The point of e is corner 1 of [v_i, E_i, E_(i-1)] (next E_(i-1)),
        // corner 2 of [v_(i+1), E_(i+1), E_i] (next v_(i+1)) and corner i of
        // [E_0, E_1, E_2] (next E_(i+1)), for each corner 3f + i of e,
        // visited in child corner order: a triangle's three in the order of
        // their child corners (3i + 1, 3i + 5 mod 9, 9 + i), the lower
        // triangle's first.
        let mut ring = [(0u32, 0u32); 6];
        let corners = connectivity.edge_corners(e);
        for (triple, &c) in ring.chunks_exact_mut(3).zip(corners) {
            let [_, next, previous] = self.edges_from(c as usize);
            let (f, i) = (c / 3, c % 3);
            let following = parent.faces.indices[3 * f as usize + NEXT[i as usize]];
            triple.copy_from_slice(&[
                (12 * f + 3 * i + 1, v_count as u32 + previous),
                (12 * f + 3 * NEXT[i as usize] as u32 + 2, following),
                (12 * f + 9 + i, v_count as u32 + next),
            ]);
            if i == 2 {
                triple.swap(0, 1);
            }
        }
        // A smooth edge has two corners.
        let n = (3 * corners.len()).min(6);
        match corners {
            [c1, c2] if c1 / 3 > c2 / 3 => {
                let (lower, higher) = ring.split_at_mut(3);
                lower.swap_with_slice(higher);
            }
            [c1, c2] if c1 / 3 < c2 / 3 => {}
            _ => ring[..n].sort_unstable(),
        }
        for &(_, neighbour) in &ring[..n] {
            visit(neighbour, NONE);
        }
        n
    }
}
