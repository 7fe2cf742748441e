//! Catmull-Clark (1978) on triangles, quads and n-gons mixed, with the
//! masks of OpenSubdiv's `Sdc::Scheme<SCHEME_CATMARK>`:
//! - face point: the centroid;
//! - edge point: smooth `(a + b + f0 + f1) / 4` with the two face points,
//!   sharp the midpoint;
//! - vertex point: smooth `((n - 2) v + (Σ neighbours + Σ face points) / n) / n`
//!   (the rule `(Q + 2R + (n - 3) S) / n`), crease `3/4 v + 1/8 (a + b)` along
//!   its two sharp edges, corner `v`.
//!
//! Output order of one level of V vertices, E edges, F faces: the V vertex
//! points, the E edge points (edges sorted by their lower, then higher vertex),
//! the F face points. Face f of n corners becomes the n quads
//! `[v_i, e_i, f, e_(i-1)]` at its corners in order, starting at position
//! `offsets[f]` of the child faces.

use glam::DVec3;
use rayon::prelude::*;

use super::bands::{band_runs, runs_of};
use super::gathers::{
    edge_points_into, planned_sharp_point, prefetch_at, sharp_vertex_point, Gathers, ParentGroups,
    Plan, RefinedGathers,
};
use super::level::{Connectivity, Faces, NONE};
use super::scheme::VertexRule;
use crate::buffers::{fill_groups, fill_items, fresh_zeroed, par_groups, split_by_offsets};
use crate::error::Result;

/// Items per rayon task: small enough to balance, large enough to amortise.
const CHUNK: usize = 2048;

/// The corners of the next level's quads, quad after quad (see the module
/// doc for their order), in a new buffer or `into` a caller's (see
/// [`par_groups`]).
pub(crate) fn child_indices(
    faces: &Faces,
    connectivity: &Connectivity,
    into: Option<&mut [u32]>,
) -> Result<Vec<u32>> {
    let edge_base = faces.vertex_count as u32;
    let face_base = (faces.vertex_count + connectivity.edge_count()) as u32;
    let corner_edges = &connectivity.corner_edges;
    // Quad c = [v_c, e_c, f, e_prev(c)]: each written once, in place.
    par_groups(faces.corner_count(), into, "child faces", |c| {
        let f = connectivity.face_of(c);
        [
            faces.indices[c],
            edge_base + corner_edges[c],
            face_base + f as u32,
            edge_base + corner_edges[faces.prev(c, f)],
        ]
    })
}

/// The quads two levels down from `parent`, written from the parent level
/// alone (see [`RefinedGathers`]): the level between is never built. Their
/// order is that of [`child_indices`] applied twice; without offsets. The
/// indices go `into` a caller's buffer when given (see [`par_groups`]).
pub(crate) fn grandchild_faces(
    parent: &RefinedGathers,
    into: Option<&mut [u32]>,
) -> Result<Faces<'static>> {
    let corner_count = parent.face_count();
    let vertex_base = parent.vertex_count() as u32;
    let face_base = vertex_base + parent.edge_count() as u32;
    // The child quad c has corners 4c..4c + 4; each makes a quad
    // [v_k, e_k, c, e_prev(k)] of the grandchild level.
    let grandchildren = |c: usize, quad: [u32; 4], edges: [u32; 4], out: &mut [u32]| {
        for j in 0..4 {
            out[4 * j..4 * j + 4].copy_from_slice(&[
                quad[j],
                vertex_base + edges[j],
                face_base + c as u32,
                vertex_base + edges[(j + 3) % 4],
            ]);
        }
    };
    let indices = if parent.parent.faces.size == 4 {
        // A parent quad's corners at once: they share their edges' slots.
        par_groups(corner_count / 4, into, "child faces", |q| {
            let (quads, edges) = (parent.quads_of_quad(q), parent.quad_edges_of_quad(q));
            let mut out = [0u32; 64];
            for (j, group) in out.chunks_exact_mut(16).enumerate() {
                grandchildren(4 * q + j, quads[j], edges[j], group);
            }
            out
        })?
    } else {
        par_groups(corner_count, into, "child faces", |c| {
            let mut out = [0u32; 16];
            grandchildren(c, parent.quad(c), parent.quad_edges(c), &mut out);
            out
        })?
    };
    Ok(Faces {
        vertex_count: parent.vertex_count() + parent.edge_count() + corner_count,
        size: 4,
        offsets: Vec::new().into(),
        indices: indices.into(),
    })
}

#[inline]
fn face_point(level: &impl Gathers, points: &[DVec3], f: usize) -> DVec3 {
    mean_of(level.face(f), points)
}

/// The mean of the points at `corners`, summed in their order.
#[inline]
fn mean_of(corners: impl ExactSizeIterator<Item = u32>, points: &[DVec3]) -> DVec3 {
    let n = corners.len() as f64;
    let sum = corners.fold(DVec3::ZERO, |s, v| s + points[v as usize]);
    divided(sum, n)
}

/// `value / n`, multiplied by 0.25 when n is 4 (a quad, a regular vertex):
/// both round the same real number, so the bits are the same, and a
/// division takes several times as long as a multiplication.
#[inline]
fn divided(value: DVec3, n: f64) -> DVec3 {
    if n == 4.0 {
        value * 0.25
    } else {
        value / n
    }
}

#[inline]
fn edge_point(level: &impl Gathers, points: &[DVec3], face_points: &[DVec3], e: usize) -> DVec3 {
    edge_point_of(level.edge(e), points, face_points)
}

/// The point of the edge `[a, b, f0, f1]` (see [`Gathers::edge`]).
#[inline]
fn edge_point_of([a, b, f0, f1]: [u32; 4], points: &[DVec3], face_points: &[DVec3]) -> DVec3 {
    let ends = points[a as usize] + points[b as usize];
    if f0 == NONE {
        ends * 0.5
    } else {
        (ends + face_points[f0 as usize] + face_points[f1 as usize]) * 0.25
    }
}

#[inline]
fn vertex_point(level: &impl Gathers, points: &[DVec3], face_points: &[DVec3], v: usize) -> DVec3 {
    if let Some(sharp) = sharp_vertex_point(level, points, v) {
        return sharp;
    }
    // Two sums side by side, each in ring order.
    let (mut neighbours, mut faces) = (DVec3::ZERO, DVec3::ZERO);
    let n = level.around(v, |u, f| {
        neighbours += points[u as usize];
        faces += face_points[f as usize];
    });
    smooth_vertex_point(points[v], neighbours, faces, n)
}

/// The smooth rule on a vertex at `p` of valence `n`, from the sums of its
/// neighbours and of its face points, each summed in ring order.
#[inline]
fn smooth_vertex_point(p: DVec3, neighbours: DVec3, faces: DVec3, n: usize) -> DVec3 {
    let n = n as f64;
    divided(p * (n - 2.0) + divided(neighbours + faces, n), n)
}

/// Applies one level's gathers: reads `points` (the level's V positions) and
/// fills `out` with the V + E + F positions of the next level.
pub(crate) fn apply(level: &impl Gathers, points: &[DVec3], out: &mut [DVec3]) {
    if let Some(refined) = level.as_refined() {
        return apply_refined(&refined, points, out);
    }
    if let Some(groups) = level.parent_groups() {
        return apply_grouped(level, groups, points, out);
    }
    if let Some(plan) = level.as_plan() {
        return apply_planned(plan, points, out);
    }
    three_passes(
        out,
        level.vertex_count(),
        level.edge_count(),
        |f| face_point(level, points, f),
        |face_points, e| edge_point(level, points, face_points, e),
        |face_points, v| vertex_point(level, points, face_points, v),
    );
}

/// [`apply`] for a plan whose level groups around no parent (a refiner's
/// cage): point after point, each read straight from the plan's arrays,
/// the quads and valence-4 rings unrolled. The same sums in the same order
/// as [`apply`] on the level the plan was read from, so the same bits.
fn apply_planned(plan: &Plan, points: &[DVec3], out: &mut [DVec3]) {
    three_passes(
        out,
        plan.vertex_count,
        plan.edges.len(),
        |f| planned_face_point(plan, points, f),
        |face_points, e| edge_point_of(plan.edges[e], points, face_points),
        |face_points, v| planned_vertex_point(plan, points, face_points, 0, v),
    );
}

/// Fills `out` with a level's vertex, edge and face points (`vertex_count`
/// and `edge_count` of the first two) in three passes over all threads:
/// the face points first, which the edge and vertex points read.
fn three_passes(
    out: &mut [DVec3],
    vertex_count: usize,
    edge_count: usize,
    face: impl Fn(usize) -> DVec3 + Sync,
    edge: impl Fn(&[DVec3], usize) -> DVec3 + Sync,
    vertex: impl Fn(&[DVec3], usize) -> DVec3 + Sync,
) {
    let (vertex_points, rest) = out.split_at_mut(vertex_count);
    let (edge_points, face_points) = rest.split_at_mut(edge_count);
    face_points
        .par_iter_mut()
        .with_min_len(CHUNK)
        .enumerate()
        .for_each(|(f, out)| *out = face(f));
    let face_points = &*face_points;
    edge_points
        .par_iter_mut()
        .with_min_len(CHUNK)
        .enumerate()
        .for_each(|(e, out)| *out = edge(face_points, e));
    vertex_points
        .par_iter_mut()
        .with_min_len(CHUNK)
        .enumerate()
        .for_each(|(v, out)| *out = vertex(face_points, v));
}

/// [`apply`] for the level refined from `level.parent`, in three passes
/// over the parent's faces, edges and vertices instead of one per kind of
/// point: every point a parent element's neighbourhood makes is made while
/// that neighbourhood's points are in the cache (each level's points are
/// larger than the cache, and a pass per kind read them all again).
/// Each point is the same sum in the same order as [`apply`]'s, so the
/// same bits.
fn apply_refined(level: &RefinedGathers, points: &[DVec3], out: &mut [DVec3]) {
    let (vertex_points, rest) = out.split_at_mut(level.vertex_count());
    let (edge_points, face_points) = rest.split_at_mut(level.edge_count());
    let parent_vertices = level.parent.faces.vertex_count;
    let parent_edges = level.parent.connectivity.edge_count();
    let (at_vertices, rest) = vertex_points.split_at_mut(parent_vertices);
    let (at_edges, at_faces) = rest.split_at_mut(parent_edges);
    let (halves, inside) = edge_points.split_at_mut(2 * parent_edges);
    around_parent_faces(level, points, face_points, at_faces);
    let face_points = &*face_points;
    around_parent_edges(level, points, face_points, at_edges, inside);
    around_parent_vertices(level, points, face_points, at_vertices, halves);
}

/// [`apply`] for a level whose elements are known to group around those
/// of the level it was refined from (a refiner's plan, or an intermediate
/// level of one-shot subdivision), in the three passes of
/// [`apply_refined`], around the parent's faces, edges and vertices: each
/// pass reads the points and face points near one parent element while
/// they are in the cache, where a pass per kind of point reads them all
/// again. A large plan goes band by band (see [`super::bands`]): the
/// edge and vertex passes read the face points the face pass wrote tens
/// of megabytes before, which a band reads back from the cache. The same
/// gathers, so the same bits.
fn apply_grouped(level: &impl Gathers, groups: &ParentGroups, points: &[DVec3], out: &mut [DVec3]) {
    let (vertex_points, rest) = out.split_at_mut(level.vertex_count());
    let (edge_points, face_points) = rest.split_at_mut(level.edge_count());
    let (parent_vertices, parent_edges) = groups.parent_counts();
    let (at_vertices, rest) = vertex_points.split_at_mut(parent_vertices);
    let (at_edges, at_faces) = rest.split_at_mut(parent_edges);
    let (halves, inside) = edge_points.split_at_mut(2 * parent_edges);
    let face_base = parent_vertices + parent_edges;
    let inside_base = 2 * parent_edges;
    // Around parent face f: the faces made in it, then the point of its
    // own face point, whose ring are those faces.
    let around_face = |f: usize, first: usize, face_points: &mut [DVec3]| {
        for (k, out) in face_points.iter_mut().enumerate() {
            *out = grouped_face_point(level, points, first + k);
        }
        grouped_vertex_point(level, points, face_points, first, face_base + f)
    };
    let bands = level.as_plan().and_then(|plan| plan.bands.as_ref());
    let Some(bands) = bands else {
        fill_groups(
            face_points,
            &groups.face_faces,
            at_faces,
            CHUNK,
            around_face,
        );
        let face_points = &*face_points;
        // Around parent edge m: the edges inside its faces, then its point's point.
        fill_groups(
            inside,
            &groups.edge_inside,
            at_edges,
            CHUNK,
            |m, first, outs| {
                around_edge(
                    level,
                    points,
                    face_points,
                    inside_base + first,
                    outs,
                    parent_vertices + m,
                )
            },
        );
        // Around parent vertex v: the halves of its edges at v, then its point.
        fill_groups(
            halves,
            &groups.vertex_halves,
            at_vertices,
            CHUNK,
            |v, first, outs| around_edge(level, points, face_points, first, outs, v),
        );
        return;
    };
    // Band by band: the face points of a band's parent faces, then the
    // points around the parent edges and vertices whose reads they
    // complete, while those face points are still in the cache.
    let mut edge_runs = runs_of(&bands.edge_runs, &groups.edge_inside, inside, at_edges);
    let mut vertex_runs = runs_of(
        &bands.vertex_runs,
        &groups.vertex_halves,
        halves,
        at_vertices,
    );
    let mut faces_done = 0;
    for (band, &faces_end) in bands.face_ends.iter().enumerate() {
        let faces = faces_done..faces_end as usize;
        let (values, singles) =
            group_parts(&groups.face_faces, face_points, at_faces, faces.clone());
        fill_groups(
            values,
            &groups.face_faces[faces.start..=faces.end],
            singles,
            CHUNK,
            |i, first, part| around_face(faces.start + i, first, part),
        );
        faces_done = faces.end;
        let face_points = &*face_points;
        let (edges, vertices) = (
            band_runs(&mut edge_runs, band),
            band_runs(&mut vertex_runs, band),
        );
        let edge_tasks = edges.into_par_iter().map(|run| (run, true));
        let vertex_tasks = vertices.into_par_iter().map(|run| (run, false));
        // One task per run, for the same reason as `fill_groups`'s blocks.
        let tasks = edge_tasks.chain(vertex_tasks).with_max_len(1);
        tasks.for_each(|(run, at_edge)| {
            let (offsets, base_edge, base_vertex) = match at_edge {
                true => (&groups.edge_inside, inside_base, parent_vertices),
                false => (&groups.vertex_halves, 0, 0),
            };
            fill_items(
                run.values,
                offsets,
                run.items,
                run.singles,
                &|i, first, outs: &mut [DVec3]| {
                    let first = base_edge + first;
                    around_edge(level, points, face_points, first, outs, base_vertex + i)
                },
            );
        });
    }
    // Every group's band is one of the plan's bands, so every run was made.
    debug_assert!(edge_runs.iter().chain(&vertex_runs).all(Option::is_none));
}

/// The edge points of a group of edges (from edge `first` of the level)
/// and the vertex point of `v`, whose ring they surround.
#[inline]
fn around_edge(
    level: &impl Gathers,
    points: &[DVec3],
    face_points: &[DVec3],
    first: usize,
    outs: &mut [DVec3],
    v: usize,
) -> DVec3 {
    edge_points_into(level, first, outs, |edge| {
        edge_point_of(edge, points, face_points)
    });
    grouped_vertex_point(level, points, face_points, 0, v)
}

/// The values and singles of the groups `items` (see [`fill_groups`]).
fn group_parts<'a, T, S>(
    offsets: &[u32],
    values: &'a mut [T],
    singles: &'a mut [S],
    items: std::ops::Range<usize>,
) -> (&'a mut [T], &'a mut [S]) {
    let base = offsets[0] as usize;
    let values =
        &mut values[offsets[items.start] as usize - base..offsets[items.end] as usize - base];
    (values, &mut singles[items])
}

/// A face point of [`apply_grouped`]: read straight from a plan.
#[inline]
fn grouped_face_point(level: &impl Gathers, points: &[DVec3], f: usize) -> DVec3 {
    match level.as_plan() {
        Some(plan) => planned_face_point(plan, points, f),
        None => face_point(level, points, f),
    }
}

/// A vertex point of [`apply_grouped`], whose faces are among
/// `face_points`, the first of which is face `first_face`: read straight
/// from a plan.
#[inline(always)]
fn grouped_vertex_point(
    level: &impl Gathers,
    points: &[DVec3],
    face_points: &[DVec3],
    first_face: usize,
    v: usize,
) -> DVec3 {
    if let Some(plan) = level.as_plan() {
        return planned_vertex_point(plan, points, face_points, first_face, v);
    }
    if let Some(sharp) = sharp_vertex_point(level, points, v) {
        return sharp;
    }
    let (mut neighbours, mut faces) = (DVec3::ZERO, DVec3::ZERO);
    let n = level.around(v, |u, f| {
        neighbours += points[u as usize];
        faces += face_points[f as usize - first_face];
    });
    smooth_vertex_point(points[v], neighbours, faces, n)
}

/// [`face_point`] of a plan's face `f`: the same sum, a quad's unrolled.
#[inline]
fn planned_face_point(plan: &Plan, points: &[DVec3], f: usize) -> DVec3 {
    match *plan.faces.face(f) {
        [a, b, c, d] => {
            let sum = DVec3::ZERO + points[a as usize] + points[b as usize];
            (sum + points[c as usize] + points[d as usize]) * 0.25
        }
        ref corners => {
            let sum = corners
                .iter()
                .fold(DVec3::ZERO, |s, &v| s + points[v as usize]);
            divided(sum, corners.len() as f64)
        }
    }
}

/// [`vertex_point`] of a plan's vertex `v`, read from its ring, whose
/// faces are among `face_points`, the first of which is face `first_face`.
#[inline(always)]
fn planned_vertex_point(
    plan: &Plan,
    points: &[DVec3],
    face_points: &[DVec3],
    first_face: usize,
    v: usize,
) -> DVec3 {
    let ring = plan.ring(v);
    match plan.vertex_rules[v] {
        VertexRule::Smooth => {
            // Two sums side by side, each in ring order.
            let (neighbour_ring, face_ring) = ring.split_at(ring.len() / 2);
            // Valence 4, nearly every vertex of a refined level, unrolled:
            // the same sums without the loop's counters and checks.
            if let (&[a, b, c, d], &[e, f, g, h]) = (neighbour_ring, face_ring) {
                let at = |u: u32| points[u as usize];
                let face = |f: u32| face_points[f as usize - first_face];
                let neighbours = DVec3::ZERO + at(a) + at(b) + at(c) + at(d);
                let faces = DVec3::ZERO + face(e) + face(f) + face(g) + face(h);
                return smooth_vertex_point(points[v], neighbours, faces, 4);
            }
            let (mut neighbours, mut faces) = (DVec3::ZERO, DVec3::ZERO);
            for (&u, &f) in neighbour_ring.iter().zip(face_ring) {
                neighbours += points[u as usize];
                faces += face_points[f as usize - first_face];
            }
            smooth_vertex_point(points[v], neighbours, faces, neighbour_ring.len())
        }
        rule => planned_sharp_point(rule, points, v, ring),
    }
}

/// The face points (one per parent corner) and the vertex points of the
/// parent's face points, face by face.
fn around_parent_faces(
    level: &RefinedGathers,
    points: &[DVec3],
    face_points: &mut [DVec3],
    vertex_points: &mut [DVec3],
) {
    let parent = &level.parent;
    let faces = parent.faces;
    let corner_edges = &parent.connectivity.corner_edges;
    let edge_base = faces.vertex_count;
    let face_base = edge_base + parent.connectivity.edge_count();
    let face_count = faces.face_count();
    let mut blocks = Vec::with_capacity(face_count.div_ceil(CHUNK));
    let (mut face_rest, mut vertex_rest) = (face_points, vertex_points);
    for first in (0..face_count).step_by(CHUNK) {
        let last = (first + CHUNK).min(face_count);
        let corners = faces.corners(first).start..faces.corners(last - 1).end;
        let (block_faces, rest) = std::mem::take(&mut face_rest).split_at_mut(corners.len());
        face_rest = rest;
        let (block_vertices, rest) = std::mem::take(&mut vertex_rest).split_at_mut(last - first);
        vertex_rest = rest;
        blocks.push((first..last, corners.start, block_faces, block_vertices));
    }
    blocks
        .into_par_iter()
        .for_each(|(block, first_corner, face_points, vertex_points)| {
            for f in block.clone() {
                let corners = faces.corners(f);
                if faces.size == 4 {
                    // The quad's four faces read its corners' edges once.
                    for (c, quad) in corners.clone().zip(level.quads_of_quad(f)) {
                        face_points[c - first_corner] = mean_of(quad.into_iter(), points);
                    }
                } else {
                    for c in corners.clone() {
                        face_points[c - first_corner] = face_point(level, points, c);
                    }
                }
                // The ring of face f's point (see `RefinedGathers::around`):
                // the points of the edges before its corners, its face points.
                let (mut neighbours, mut rings) = (DVec3::ZERO, DVec3::ZERO);
                for c in corners.clone() {
                    let previous = corner_edges[faces.prev(c, f)] as usize;
                    neighbours += points[edge_base + previous];
                    rings += face_points[c - first_corner];
                }
                let u = face_base + f;
                vertex_points[f - block.start] =
                    smooth_vertex_point(points[u], neighbours, rings, corners.len());
            }
        });
}

/// The points of the edges inside the parent's faces (one per parent
/// corner, in the parent's edge-corner order) and the vertex points of the
/// parent's edge points, edge by edge.
fn around_parent_edges(
    level: &RefinedGathers,
    points: &[DVec3],
    face_points: &[DVec3],
    vertex_points: &mut [DVec3],
    inside: &mut [DVec3],
) {
    let parent = &level.parent;
    let connectivity = parent.connectivity;
    let edge_base = parent.faces.vertex_count;
    let edge_count = connectivity.edge_count();
    let face_base = edge_base + edge_count;
    let slot_base = 2 * edge_count;
    split_by_offsets(inside, &connectivity.edge_offsets, CHUNK)
        .into_par_iter()
        .zip(vertex_points.par_chunks_mut(CHUNK))
        .for_each(|((edges, inside), vertex_points)| {
            let first_slot = connectivity.edge_offsets[edges.start] as usize;
            for e in edges.clone() {
                let slots = connectivity.edge_offsets[e] as usize
                    ..connectivity.edge_offsets[e + 1] as usize;
                let u = edge_base + e;
                let corners = connectivity.edge_corners(e);
                let &[c1, c2] = corners else {
                    for s in slots {
                        inside[s - first_slot] =
                            edge_point(level, points, face_points, slot_base + s);
                    }
                    vertex_points[e - edges.start] = vertex_point(level, points, face_points, u);
                    continue;
                };
                // Each corner's inside edge joins u to its face's point; its
                // wings are the child quads at the corner and the next one.
                let mut ring = [(0u32, 0u32, 0u32); 4];
                for (j, c) in [c1, c2].into_iter().enumerate() {
                    let c = c as usize;
                    let next = parent.next(c);
                    let face = (face_base + connectivity.face_of(c)) as u32;
                    let wings = [c.min(next) as u32, c.max(next) as u32];
                    inside[slots.start + j - first_slot] =
                        edge_point_of([u as u32, face, wings[0], wings[1]], points, face_points);
                    ring[2 * j] = (4 * c as u32 + 1, face, c as u32);
                    ring[2 * j + 1] =
                        (4 * next as u32 + 3, parent.faces.indices[next], next as u32);
                }
                vertex_points[e - edges.start] = match parent.tags.edge_sharp[e] {
                    true => vertex_point(level, points, face_points, u),
                    false => {
                        // In child corner order, as `RefinedGathers::around` visits them.
                        ring.sort_unstable();
                        let (mut neighbours, mut rings) = (DVec3::ZERO, DVec3::ZERO);
                        for (_, neighbour, face) in ring {
                            neighbours += points[neighbour as usize];
                            rings += face_points[face as usize];
                        }
                        smooth_vertex_point(points[u], neighbours, rings, 4)
                    }
                };
            }
        });
}

/// The points of the halves of the parent's edges, `[v, V + e]` for each
/// parent vertex v and its edges e in order (the wings of all of a
/// vertex's edges found in one walk around it,
/// [`RefinedGathers::slot_wings`]), and the vertex points of the parent's
/// vertices, vertex by vertex.
fn around_parent_vertices(
    level: &RefinedGathers,
    points: &[DVec3],
    face_points: &[DVec3],
    vertex_points: &mut [DVec3],
    halves: &mut [DVec3],
) {
    let connectivity = level.parent.connectivity;
    let offsets = &connectivity.vertex_edge_offsets;
    let v_count = level.parent.faces.vertex_count as u32;
    split_by_offsets(halves, offsets, CHUNK)
        .into_par_iter()
        .zip(vertex_points.par_chunks_mut(CHUNK))
        .for_each(|((vertices, part), vertex_points)| {
            let base = offsets[vertices.start] as usize;
            for v in vertices.clone() {
                if v + PREFETCH_AHEAD < v_count as usize {
                    let ahead = v + PREFETCH_AHEAD;
                    for &e in connectivity.vertex_edges(ahead) {
                        prefetch_at(points, v_count as usize + e as usize);
                    }
                    for &k in connectivity.vertex_corners(ahead) {
                        prefetch_at(face_points, k as usize);
                    }
                }
                let slots = offsets[v] as usize..offsets[v + 1] as usize;
                let outs = &mut part[slots.start - base..slots.end - base];
                match level.slot_wings(v) {
                    Some(wings) => {
                        let edges = connectivity.vertex_edges(v);
                        for ((out, &e), [f0, f1]) in outs.iter_mut().zip(edges).zip(wings) {
                            *out =
                                edge_point_of([v as u32, v_count + e, f0, f1], points, face_points);
                        }
                    }
                    None => {
                        for (out, s) in outs.iter_mut().zip(slots) {
                            *out = edge_point(level, points, face_points, s);
                        }
                    }
                }
                vertex_points[v - vertices.start] = vertex_point(level, points, face_points, v);
            }
        });
}

/// How many vertices ahead [`around_parent_vertices`] brings in what it
/// will read: the reads of a vertex's ring wait on memory, and their
/// places are known only from the parent's lists.
const PREFETCH_AHEAD: usize = 8;

/// As [`apply`], into a new vector of the allocator's untouched zeroed
/// memory: the face points are written into its tail first, where the edge
/// and vertex points read them, and every point is written once.
///
/// # Errors
/// [`crate::Error::OutOfMemory`].
pub(crate) fn points(level: &impl Gathers, points: &[DVec3]) -> Result<Vec<DVec3>> {
    let (v, e, f) = (level.vertex_count(), level.edge_count(), level.face_count());
    let mut out = fresh_zeroed(v + e + f, "refined positions")?;
    apply(level, points, &mut out);
    Ok(out)
}
