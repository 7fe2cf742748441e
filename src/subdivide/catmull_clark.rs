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

use super::level::{Connectivity, Faces, Plan, VertexRule, NONE};
use crate::error::{try_vec, Result};

/// Items per rayon task: small enough to balance, large enough to amortise.
const CHUNK: usize = 2048;

/// The quads of the next level (see the module doc for their order).
pub(crate) fn child_faces(faces: &Faces, connectivity: &Connectivity) -> Result<Faces> {
    let vertex_count = faces.vertex_count;
    let edge_count = connectivity.edge_count();
    let corner_count = faces.corner_count();
    let mut offsets = try_vec(corner_count + 1, "child faces")?;
    offsets.extend((0..=corner_count as u32).map(|q| 4 * q));
    let mut indices = try_vec(4 * corner_count, "child faces")?;
    let edge_base = vertex_count as u32;
    let face_base = (vertex_count + edge_count) as u32;
    for (f, w) in faces.offsets.windows(2).enumerate() {
        let (start, end) = (w[0] as usize, w[1] as usize);
        let mut previous_edge = connectivity.corner_edges[end - 1];
        for c in start..end {
            let edge = connectivity.corner_edges[c];
            indices.extend_from_slice(&[
                faces.indices[c],
                edge_base + edge,
                face_base + f as u32,
                edge_base + previous_edge,
            ]);
            previous_edge = edge;
        }
    }
    Ok(Faces {
        vertex_count: vertex_count + edge_count + faces.face_count(),
        offsets,
        indices,
    })
}

/// Applies one level's plan: reads `points` (the level's V positions) and
/// fills `out` with the V + E + F positions of the next level.
pub(crate) fn apply(plan: &Plan, points: &[DVec3], out: &mut [DVec3]) {
    let (vertex_points, rest) = out.split_at_mut(plan.vertex_count);
    let (edge_points, face_points) = rest.split_at_mut(plan.edge_count());

    face_points
        .par_iter_mut()
        .with_min_len(CHUNK)
        .enumerate()
        .for_each(|(f, out)| {
            let corners = &plan.face_indices
                [plan.face_offsets[f] as usize..plan.face_offsets[f + 1] as usize];
            let sum = corners
                .iter()
                .fold(DVec3::ZERO, |s, &v| s + points[v as usize]);
            *out = sum / corners.len() as f64;
        });
    let face_points = &*face_points;

    edge_points
        .par_iter_mut()
        .with_min_len(CHUNK)
        .zip(plan.edges.par_iter())
        .for_each(|(out, &[a, b, f0, f1])| {
            let ends = points[a as usize] + points[b as usize];
            *out = if f0 == NONE {
                ends * 0.5
            } else {
                (ends + face_points[f0 as usize] + face_points[f1 as usize]) * 0.25
            };
        });

    vertex_points
        .par_iter_mut()
        .with_min_len(CHUNK)
        .enumerate()
        .for_each(|(v, out)| {
            let p = points[v];
            let ring = plan.ring(v);
            *out = match plan.vertex_rules[v] {
                VertexRule::Corner => p,
                VertexRule::Crease => {
                    p * 0.75 + (points[ring[0] as usize] + points[ring[1] as usize]) * 0.125
                }
                VertexRule::Smooth => {
                    let n = ring.len() / 2;
                    let (neighbours, faces) = ring.split_at(n);
                    let sum = neighbours
                        .iter()
                        .fold(DVec3::ZERO, |s, &u| s + points[u as usize])
                        + faces
                            .iter()
                            .fold(DVec3::ZERO, |s, &f| s + face_points[f as usize]);
                    let n = n as f64;
                    (p * (n - 2.0) + sum / n) / n
                }
            };
        });
}
