//! Loop (1987) on triangle meshes, with the masks of OpenSubdiv's
//! `Sdc::Scheme<SCHEME_LOOP>`:
//! - edge point: smooth `3/8 (a + b) + 1/8 (c + d)` with the two opposite
//!   vertices, sharp the midpoint;
//! - vertex point: smooth `(1 - nβ) v + β Σ neighbours` with
//!   `β = (5/8 - (3/8 + 1/4 cos(2π/n))²) / n` (1/16 at valence 6), crease
//!   `3/4 v + 1/8 (a + b)` along its two sharp edges, corner `v`.
//!
//! Output order of one level of V vertices and E edges: the V vertex points,
//! then the E edge points (edges sorted by their lower, then higher vertex).
//! Triangle f = `[v0, v1, v2]` with edge points `e_i` on `v_i v_(i+1)` becomes
//! the four triangles `[v0, e0, e2]`, `[v1, e1, e0]`, `[v2, e2, e1]`,
//! `[e0, e1, e2]` at positions `4f..4f + 4`.

use glam::DVec3;
use rayon::prelude::*;

use super::gathers::{
    edge_points_into, planned_sharp_point, sharp_vertex_point, Gathers, LoopRefinedGathers,
    ParentGroups, Plan,
};
use super::level::{Connectivity, Faces, NONE};
use super::scheme::{loop_smooth_weights, VertexRule};
use crate::buffers::{fill_groups, fresh_zeroed, par_groups, try_vec};
use crate::error::Result;

const CHUNK: usize = 2048;

/// The corners of the next level's triangles, triangle after triangle (see
/// the module doc for their order). Every face of `faces` is a triangle.
/// In a new buffer or `into` a caller's (see [`par_groups`]).
pub(crate) fn child_indices(
    faces: &Faces,
    connectivity: &Connectivity,
    into: Option<&mut [u32]>,
) -> Result<Vec<u32>> {
    let base = faces.vertex_count as u32;
    let corner_edges = &connectivity.corner_edges;
    // Where each of the 12 indices of a triangle's children comes from: a
    // corner (0..3) or an edge (3..6) of the parent.
    const SOURCE: [usize; 12] = [0, 3, 5, 1, 4, 3, 2, 5, 4, 3, 4, 5];
    par_groups(faces.face_count(), into, "child faces", |f| {
        SOURCE.map(|source| {
            if source < 3 {
                faces.indices[3 * f + source]
            } else {
                base + corner_edges[3 * f + source - 3]
            }
        })
    })
}

/// The triangles two levels down from `level`'s parent, written from the
/// parent alone (see [`LoopRefinedGathers`]): the level between is never
/// built. Their order is that of [`child_indices`] applied twice; without
/// offsets. The indices go `into` a caller's buffer when given (see
/// [`par_groups`]).
pub(crate) fn grandchild_faces(
    level: &LoopRefinedGathers,
    into: Option<&mut [u32]>,
) -> Result<Faces<'static>> {
    let base = level.vertex_count() as u32;
    let parent_faces = level.parent.faces.face_count();
    // Each of a parent triangle's four children makes four triangles, as
    // `child_indices` makes them from its vertices and edge points.
    let indices = par_groups(parent_faces, into, "child faces", |f| {
        let mut out = [0u32; 48];
        for (group, (w, edges)) in out.chunks_exact_mut(12).zip(level.children(f)) {
            let x = edges.map(|e| base + e);
            group.copy_from_slice(&[
                w[0], x[0], x[2], w[1], x[1], x[0], w[2], x[2], x[1], x[0], x[1], x[2],
            ]);
        }
        out
    })?;
    Ok(Faces {
        vertex_count: level.vertex_count() + level.edge_count(),
        size: 3,
        offsets: Vec::new().into(),
        indices: indices.into(),
    })
}

#[inline]
fn edge_point(level: &impl Gathers, points: &[DVec3], e: usize) -> DVec3 {
    edge_point_of(level.edge(e), points)
}

/// The point of the edge `[a, b, c, d]` (see [`Gathers::edge`]).
#[inline]
fn edge_point_of([a, b, c, d]: [u32; 4], points: &[DVec3]) -> DVec3 {
    let ends = points[a as usize] + points[b as usize];
    if c == NONE {
        ends * 0.5
    } else {
        ends * 0.375 + (points[c as usize] + points[d as usize]) * 0.125
    }
}

#[inline]
fn vertex_point(level: &impl Gathers, points: &[DVec3], v: usize) -> DVec3 {
    if let Some(sharp) = sharp_vertex_point(level, points, v) {
        return sharp;
    }
    let mut sum = DVec3::ZERO;
    let n = level.around(v, |u, _| sum += points[u as usize]);
    let (own, each) = loop_smooth_weights(n);
    points[v] * own + sum * each
}

/// Applies one level's gathers: reads `points` (the level's V positions) and
/// fills `out` with the V + E positions of the next level.
pub(crate) fn apply(level: &impl Gathers, points: &[DVec3], out: &mut [DVec3]) {
    if let Some(refined) = level.as_loop_refined() {
        return apply_refined(refined, points, out);
    }
    if let Some(plan) = level.as_plan() {
        return apply_planned(plan, points, out);
    }
    if let Some(groups) = level.parent_groups() {
        return apply_grouped(level, groups, points, out);
    }
    let (vertex_points, edge_points) = out.split_at_mut(level.vertex_count());
    edge_points
        .par_iter_mut()
        .with_min_len(CHUNK)
        .enumerate()
        .for_each(|(e, out)| *out = edge_point(level, points, e));
    vertex_points
        .par_iter_mut()
        .with_min_len(CHUNK)
        .enumerate()
        .for_each(|(v, out)| *out = vertex_point(level, points, v));
}

/// [`apply`] for a plan, its gathers read straight from its arrays: in
/// the passes of [`around_parents`] when its level groups around a parent
/// level, else point after point. The same sums in the same order as
/// [`apply`] on the level the plan was read from, so the same bits.
fn apply_planned(plan: &Plan, points: &[DVec3], out: &mut [DVec3]) {
    let planned = Planned {
        edges: &plan.edges,
        rings: PlannedRings::of(plan),
        points,
    };
    let Some(groups) = &plan.parent else {
        let (vertex_points, edge_points) = out.split_at_mut(plan.vertex_count);
        edge_points
            .par_chunks_mut(CHUNK)
            .enumerate()
            .for_each(|(k, outs)| planned.edge_points(k * CHUNK, outs));
        vertex_points
            .par_iter_mut()
            .with_min_len(CHUNK)
            .enumerate()
            .for_each(|(v, out)| *out = planned.vertex_point(v));
        return;
    };
    let offsets = (&groups.edge_inside[..], &groups.vertex_halves[..]);
    around_parents(plan.vertex_count, offsets, out, &planned);
}

/// [`apply`] for a level whose elements are known to group around those
/// of the level it was refined from (an intermediate level of one-shot
/// subdivision), in the passes of [`around_parents`]. The same gathers in
/// the same order, so the same bits.
fn apply_grouped(level: &impl Gathers, groups: &ParentGroups, points: &[DVec3], out: &mut [DVec3]) {
    let gathered = Gathered { level, points };
    let offsets = (&groups.edge_inside[..], &groups.vertex_halves[..]);
    around_parents(level.vertex_count(), offsets, out, &gathered);
}

/// [`apply`] for the level refined from `level.parent`, in two passes over
/// the parent's edges and vertices instead of one per kind of point: the
/// points each parent element's neighbourhood makes are made while its
/// points are in the cache (as Catmull-Clark's last level is made). Each
/// point is the same gather as [`apply`]'s, so the same bits.
fn apply_refined(level: &LoopRefinedGathers, points: &[DVec3], out: &mut [DVec3]) {
    let connectivity = level.parent.connectivity;
    let refined = Refined(Gathered { level, points });
    let offsets = (
        level.inside_offsets(),
        &connectivity.vertex_edge_offsets[..],
    );
    around_parents(level.vertex_count(), offsets, out, &refined);
}

/// What [`around_parents`] makes around each parent element, from the
/// level's points.
trait GroupPoints: Sync {
    /// The points of the level's edges from edge `first` on.
    fn edge_points(&self, first: usize, outs: &mut [DVec3]);
    /// The points of the halves at parent vertex `v`, the level's edges
    /// from `first` on.
    #[inline]
    fn halves(&self, _v: usize, first: usize, outs: &mut [DVec3]) {
        self.edge_points(first, outs);
    }
    /// The vertex point of the level's vertex `v`.
    fn vertex_point(&self, v: usize) -> DVec3;
}

/// The two passes of [`apply_grouped`], [`apply_planned`] and
/// [`apply_refined`], writing the next level (`vertex_count` vertex points
/// and the edge points) into `out`: around each parent edge m, the edges
/// inside triangles whose lower parent edge is m (`edge_inside`, see
/// [`ParentGroups::edge_inside`]) and its point's vertex point; around
/// each parent vertex v, the halves of its edges at v (`vertex_halves`)
/// and its vertex point.
fn around_parents(
    vertex_count: usize,
    (edge_inside, vertex_halves): (&[u32], &[u32]),
    out: &mut [DVec3],
    make: &impl GroupPoints,
) {
    let (parent_vertices, parent_edges) = (vertex_halves.len() - 1, edge_inside.len() - 1);
    let (vertex_points, edge_points) = out.split_at_mut(vertex_count);
    let (at_vertices, at_edges) = vertex_points.split_at_mut(parent_vertices);
    let (half_points, inside_points) = edge_points.split_at_mut(2 * parent_edges);
    fill_groups(
        inside_points,
        edge_inside,
        at_edges,
        CHUNK,
        |m, first, outs| {
            make.edge_points(2 * parent_edges + first, outs);
            make.vertex_point(parent_vertices + m)
        },
    );
    fill_groups(
        half_points,
        vertex_halves,
        at_vertices,
        CHUNK,
        |v, first, outs| {
            make.halves(v, first, outs);
            make.vertex_point(v)
        },
    );
}

/// A plan's gathers, as slices.
struct Planned<'a> {
    edges: &'a [[u32; 4]],
    rings: PlannedRings<'a>,
    points: &'a [DVec3],
}

impl GroupPoints for Planned<'_> {
    #[inline(always)]
    fn edge_points(&self, first: usize, outs: &mut [DVec3]) {
        for (out, &edge) in outs.iter_mut().zip(&self.edges[first..]) {
            *out = edge_point_of(edge, self.points);
        }
    }

    #[inline(always)]
    fn vertex_point(&self, v: usize) -> DVec3 {
        self.rings.vertex_point(self.points, v)
    }
}

/// A plan's vertex rules and rings, as slices.
struct PlannedRings<'a> {
    rules: &'a [VertexRule],
    offsets: &'a [u32],
    ring: &'a [u32],
}

impl<'a> PlannedRings<'a> {
    fn of(plan: &'a Plan) -> Self {
        PlannedRings {
            rules: &plan.vertex_rules,
            offsets: &plan.vertex_ring_offsets,
            ring: &plan.vertex_ring,
        }
    }

    /// [`vertex_point`] of the plan's vertex `v`, read from its ring; a
    /// regular ring's sum unrolled, in the same order.
    #[inline(always)]
    fn vertex_point(&self, points: &[DVec3], v: usize) -> DVec3 {
        let ring = &self.ring[self.offsets[v] as usize..self.offsets[v + 1] as usize];
        match (self.rules[v], ring) {
            (VertexRule::Smooth, &[a, b, c, d, e, f]) => {
                let p = |u: u32| points[u as usize];
                let sum = DVec3::ZERO + p(a) + p(b) + p(c) + p(d) + p(e) + p(f);
                let (own, each) = loop_smooth_weights(6);
                points[v] * own + sum * each
            }
            (VertexRule::Smooth, _) => {
                let sum = ring
                    .iter()
                    .fold(DVec3::ZERO, |sum, &u| sum + points[u as usize]);
                let (own, each) = loop_smooth_weights(ring.len());
                points[v] * own + sum * each
            }
            (rule, _) => planned_sharp_point(rule, points, v, ring),
        }
    }
}

/// A level's gathers, read where they lie.
struct Gathered<'a, G> {
    level: &'a G,
    points: &'a [DVec3],
}

impl<G: Gathers> GroupPoints for Gathered<'_, G> {
    #[inline]
    fn edge_points(&self, first: usize, outs: &mut [DVec3]) {
        edge_points_into(self.level, first, outs, |edge| {
            edge_point_of(edge, self.points)
        });
    }

    #[inline]
    fn vertex_point(&self, v: usize) -> DVec3 {
        vertex_point(self.level, self.points, v)
    }
}

/// One-shot's last level: as [`Gathered`], the halves at a parent vertex
/// with their wings found in one walk around it.
struct Refined<'a, 'b>(Gathered<'a, LoopRefinedGathers<'b>>);

impl GroupPoints for Refined<'_, '_> {
    #[inline]
    fn edge_points(&self, first: usize, outs: &mut [DVec3]) {
        self.0.edge_points(first, outs);
    }

    #[inline]
    fn halves(&self, v: usize, first: usize, outs: &mut [DVec3]) {
        let Gathered { level, points } = self.0;
        let Some(wings) = level.slot_wings(v) else {
            return self.0.edge_points(first, outs);
        };
        let parent_vertices = level.parent.faces.vertex_count as u32;
        let edges = level.parent.connectivity.vertex_edges(v);
        for ((out, &e), [c, d]) in outs.iter_mut().zip(edges).zip(wings) {
            *out = edge_point_of([v as u32, parent_vertices + e, c, d], points);
        }
    }

    #[inline]
    fn vertex_point(&self, v: usize) -> DVec3 {
        self.0.vertex_point(v)
    }
}

/// As [`apply`], into a new vector written once (no zero-filling).
///
/// # Errors
/// [`crate::Error::OutOfMemory`].
pub(crate) fn points(level: &impl Gathers, points: &[DVec3]) -> Result<Vec<DVec3>> {
    let (v, e) = (level.vertex_count(), level.edge_count());
    if let Some(refined) = level.as_loop_refined() {
        // The allocator's untouched zeroed memory, written once in any order.
        let mut out = fresh_zeroed(v + e, "refined positions")?;
        apply_refined(refined, points, &mut out);
        return Ok(out);
    }
    let mut out = try_vec(v + e, "refined positions")?;
    out.par_extend(
        (0..v)
            .into_par_iter()
            .with_min_len(CHUNK)
            .map(|v| vertex_point(level, points, v)),
    );
    out.par_extend(
        (0..e)
            .into_par_iter()
            .with_min_len(CHUNK)
            .map(|e| edge_point(level, points, e)),
    );
    Ok(out)
}
