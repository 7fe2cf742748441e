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

use super::gathers::{prefetch_at, sharp_vertex_point, Gathers, RefinedGathers};
use super::level::{Connectivity, Faces, NONE};
use crate::buffers::{fresh_zeroed, par_groups, split_by_offsets};
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
pub(crate) fn grandchild_faces(parent: &RefinedGathers, into: Option<&mut [u32]>) -> Result<Faces> {
    let corner_count = parent.face_count();
    let vertex_base = parent.vertex_count() as u32;
    let face_base = vertex_base + parent.edge_count() as u32;
    // The child quad c has corners 4c..4c + 4; each makes a quad
    // [v_k, e_k, c, e_prev(k)] of the grandchild level.
    let indices = par_groups(corner_count, into, "child faces", |c| {
        let (quad, edges) = (parent.quad(c), parent.quad_edges(c));
        let mut out = [0u32; 16];
        for j in 0..4 {
            out[4 * j..4 * j + 4].copy_from_slice(&[
                quad[j],
                vertex_base + edges[j],
                face_base + c as u32,
                vertex_base + edges[(j + 3) % 4],
            ]);
        }
        out
    })?;
    Ok(Faces {
        vertex_count: parent.vertex_count() + parent.edge_count() + corner_count,
        size: 4,
        offsets: Vec::new(),
        indices,
    })
}

#[inline]
fn face_point(level: &impl Gathers, points: &[DVec3], f: usize) -> DVec3 {
    let corners = level.face(f);
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
    }) as f64;
    divided(points[v] * (n - 2.0) + divided(neighbours + faces, n), n)
}

/// Applies one level's gathers: reads `points` (the level's V positions) and
/// fills `out` with the V + E + F positions of the next level.
pub(crate) fn apply(level: &impl Gathers, points: &[DVec3], out: &mut [DVec3]) {
    let (vertex_points, rest) = out.split_at_mut(level.vertex_count());
    let (edge_points, face_points) = rest.split_at_mut(level.edge_count());
    face_points
        .par_iter_mut()
        .with_min_len(CHUNK)
        .enumerate()
        .for_each(|(f, out)| *out = face_point(level, points, f));
    let face_points = &*face_points;
    let walked = match level.as_refined() {
        Some(refined) => {
            let slots = refined.parent.connectivity.vertex_edges.len();
            slot_points(&refined, points, face_points, &mut edge_points[..slots]);
            slots
        }
        None => 0,
    };
    edge_points[walked..]
        .par_iter_mut()
        .with_min_len(CHUNK)
        .enumerate()
        .for_each(|(i, out)| *out = edge_point(level, points, face_points, walked + i));
    vertex_points
        .par_iter_mut()
        .with_min_len(CHUNK)
        .enumerate()
        .for_each(|(v, out)| {
            level.prefetch_around(v + PREFETCH_AHEAD, points, face_points);
            *out = vertex_point(level, points, face_points, v)
        });
}

/// How many points ahead a pass brings in what it will read (see
/// [`Gathers::prefetch_around`]): the reads of a point wait on memory, and
/// their indices are known only from other arrays.
const PREFETCH_AHEAD: usize = 8;

/// The points of the refined level's first 2E edges, `[v, V + e]` for
/// each of the parent's vertices v and its edges e in order, vertex by
/// vertex: the gathers of [`edge_point`], with the wings of all of a
/// vertex's edges found in one walk around it
/// ([`RefinedGathers::slot_wings`]) instead of edge by edge.
fn slot_points(level: &RefinedGathers, points: &[DVec3], face_points: &[DVec3], out: &mut [DVec3]) {
    let connectivity = level.parent.connectivity;
    let offsets = &connectivity.vertex_edge_offsets;
    let v_count = level.parent.faces.vertex_count as u32;
    split_by_offsets(out, offsets, CHUNK)
        .into_par_iter()
        .for_each(|(vertices, part)| {
            let base = offsets[vertices.start] as usize;
            for v in vertices {
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
                let Some(wings) = level.slot_wings(v) else {
                    for (out, s) in outs.iter_mut().zip(slots) {
                        *out = edge_point(level, points, face_points, s);
                    }
                    continue;
                };
                let edges = connectivity.vertex_edges(v);
                for ((out, &e), [f0, f1]) in outs.iter_mut().zip(edges).zip(wings) {
                    *out = edge_point_of([v as u32, v_count + e, f0, f1], points, face_points);
                }
            }
        });
}

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
