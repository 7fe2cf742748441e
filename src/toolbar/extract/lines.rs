//! Mesh From Lines: the faces a set of line segments encloses.

use std::collections::HashMap;

use glam::DVec3;

use crate::error::{Error, Result};
use crate::mend::weld::position_clusters;
use crate::mesh::analysis::newell_vector;
use crate::mesh::linalg::{covariance, symmetric_eigen};
use crate::mesh::Mesh;
use crate::toolbar::split::Builder;

/// Builds the faces that a set of line segments encloses (Weaverbird's Mesh
/// From Lines), each at most `max_valence` corners.
///
/// The algorithm:
/// 1. Endpoints at most `tolerance` apart are welded (transitively, through
///    the weld's spatial hash; 0 welds only identical points) to their
///    average. Segments that collapse to a point and repeated segments are
///    dropped.
/// 2. Dangling segments (ends of degree 1) are pruned, repeatedly.
/// 3. The welded points are projected onto their best-fit plane (least
///    squares), its normal pointing along its largest positive axis (+z for
///    lines in the XY plane); around each point its segments are sorted by
///    angle in that plane.
/// 4. Every face of that planar embedding is traced (from segment u→v the
///    walk turns to the segment just clockwise of u around v), which finds
///    the smallest cycles. The faces counter-clockwise about the normal are
///    kept; the outer boundary of each connected piece comes out clockwise
///    and is dropped, as is any cycle with more than `max_valence` corners
///    or that passes a point twice.
///
/// Limits: the faces are found in one projection plane, so lines that lie
/// on a gently curved surface work, but lines that fold over in that plane
/// (a closed tube, a sphere) do not give their faces. Segments that cross
/// without sharing an endpoint are not split.
///
/// Output: the points that faces use, in order of first appearance among
/// the segments; the faces in tracing order, front towards the normal.
///
/// # Errors
/// [`Error::InvalidArgument`] for a non-finite coordinate (naming the
/// segment), a negative or non-finite tolerance, or `max_valence` below 3.
pub fn mesh_from_lines(segments: &[[DVec3; 2]], tolerance: f64, max_valence: u32) -> Result<Mesh> {
    if !(tolerance >= 0.0 && tolerance.is_finite()) {
        return Err(Error::InvalidArgument(format!(
            "tolerance is {tolerance}; it must be finite and at least 0"
        )));
    }
    if max_valence < 3 {
        return Err(Error::InvalidArgument(format!(
            "max_valence is {max_valence}; a face needs at least 3 corners"
        )));
    }
    if let Some(j) = segments
        .iter()
        .position(|s| !s[0].is_finite() || !s[1].is_finite())
    {
        return Err(Error::InvalidArgument(format!(
            "segment {j} has a non-finite coordinate"
        )));
    }
    let (points, edges) = weld(segments, tolerance)?;
    let neighbours = prune(points.len(), &edges);
    let normal = best_fit_normal(&points, &neighbours);
    let u = normal.any_orthonormal_vector();
    let w = normal.cross(u);
    // Neighbours of each point, counter-clockwise about the normal.
    let sorted: Vec<Vec<u32>> = neighbours
        .iter()
        .enumerate()
        .map(|(i, around)| {
            let mut around = around.clone();
            let angle = |j: &u32| {
                let d = points[*j as usize] - points[i];
                d.dot(w).atan2(d.dot(u))
            };
            around.sort_by(|a, b| angle(a).total_cmp(&angle(b)));
            around
        })
        .collect();
    // Where each point stands around each of its neighbours: the walk
    // turns at b from a without searching b's neighbours (a point with
    // thousands of segments would square the walk).
    let place: HashMap<(u32, u32), u32> = sorted
        .iter()
        .enumerate()
        .flat_map(|(b, around)| {
            around
                .iter()
                .enumerate()
                .map(move |(k, &a)| ((b as u32, a), k as u32))
        })
        .collect();
    // Each segment walked each way once: the walk from a to b is slot
    // `first_slot[a] + (b's place around a)`.
    let mut first_slot = Vec::with_capacity(sorted.len());
    let mut slots = 0;
    for around in &sorted {
        first_slot.push(slots);
        slots += around.len();
    }
    let mut used = vec![false; slots];
    let mut faces: Vec<Vec<u32>> = Vec::new();
    for (start, around) in sorted.iter().enumerate() {
        for (place_of_first, &first) in around.iter().enumerate() {
            let (mut a, mut b) = (start as u32, first);
            let mut slot = first_slot[start] + place_of_first;
            if used[slot] {
                continue;
            }
            let mut cycle = Vec::new();
            while !used[slot] {
                used[slot] = true;
                cycle.push(a);
                let at_b = &sorted[b as usize];
                let k = place.get(&(b, a)).map_or(0, |&k| k as usize);
                let turn = (k + at_b.len() - 1) % at_b.len();
                slot = first_slot[b as usize] + turn;
                (a, b) = (b, at_b[turn]);
            }
            let repeated = {
                let mut s = cycle.clone();
                s.sort_unstable();
                s.windows(2).any(|w| w[0] == w[1])
            };
            let corners: Vec<DVec3> = cycle.iter().map(|&i| points[i as usize]).collect();
            let area = newell_vector(&corners).dot(normal);
            if cycle.len() >= 3 && cycle.len() <= max_valence as usize && !repeated && area > 0.0 {
                faces.push(cycle);
            }
        }
    }
    // Keep only the points faces use.
    let mut index = vec![u32::MAX; points.len()];
    let mut order = Vec::new();
    for face in &faces {
        for &i in face {
            if index[i as usize] == u32::MAX {
                index[i as usize] = 0;
                order.push(i);
            }
        }
    }
    order.sort_unstable();
    let corner_count: u64 = faces.iter().map(|f| f.len() as u64).sum();
    let mut out = Builder::new(
        "mesh from lines",
        order.len() as u64,
        faces.len() as u64,
        corner_count,
    )?;
    for &i in &order {
        index[i as usize] = out.vertex(points[i as usize]);
    }
    for face in &mut faces {
        for i in face.iter_mut() {
            *i = index[*i as usize];
        }
        out.face(face);
    }
    out.finish()
}

/// Welds endpoints within `tolerance` (as the weld does, crowded ends
/// included); returns the points (cluster averages, in order of first
/// appearance) and the unique edges between them.
fn weld(segments: &[[DVec3; 2]], tolerance: f64) -> Result<(Vec<DVec3>, Vec<[u32; 2]>)> {
    let ends: Vec<DVec3> = segments.iter().flat_map(|s| [s[0], s[1]]).collect();
    let (point_of, count) = position_clusters(&ends, tolerance)?;
    let (mut sums, mut counts) = (vec![DVec3::ZERO; count], vec![0.0; count]);
    for (&p, &k) in ends.iter().zip(&point_of) {
        sums[k as usize] += p;
        counts[k as usize] += 1.0;
    }
    let points = sums.iter().zip(&counts).map(|(s, n)| *s / *n).collect();
    let mut edges: Vec<[u32; 2]> = point_of
        .chunks_exact(2)
        .filter(|e| e[0] != e[1])
        .map(|e| [e[0].min(e[1]), e[0].max(e[1])])
        .collect();
    edges.sort_unstable();
    edges.dedup();
    Ok((points, edges))
}

/// Adjacency lists after removing dangling edges, repeatedly.
fn prune(point_count: usize, edges: &[[u32; 2]]) -> Vec<Vec<u32>> {
    let mut around = vec![Vec::new(); point_count];
    for &[a, b] in edges {
        around[a as usize].push(b);
        around[b as usize].push(a);
    }
    let mut stack: Vec<usize> = (0..point_count).filter(|&i| around[i].len() == 1).collect();
    while let Some(i) = stack.pop() {
        if let Some(j) = around[i].pop() {
            let list = &mut around[j as usize];
            list.retain(|&x| x as usize != i);
            if list.len() == 1 {
                stack.push(j as usize);
            }
        }
    }
    around
}

/// The unit normal of the least-squares plane through the points that have
/// segments left, pointing along its largest component's positive axis.
fn best_fit_normal(points: &[DVec3], around: &[Vec<u32>]) -> DVec3 {
    let live: Vec<DVec3> = points
        .iter()
        .zip(around)
        .filter(|(_, a)| !a.is_empty())
        .map(|(p, _)| *p)
        .collect();
    if live.len() < 3 {
        return DVec3::Z;
    }
    let centre = live.iter().sum::<DVec3>() / live.len() as f64;
    let (_, vectors) = symmetric_eigen(covariance(&live, centre));
    let n = vectors[0];
    let largest = n.abs().max_element();
    let axis = if n.x.abs() == largest {
        n.x
    } else if n.y.abs() == largest {
        n.y
    } else {
        n.z
    };
    if axis < 0.0 {
        -n
    } else {
        n
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weld_joins_close_ends_and_drops_collapsed_segments() {
        let segments = [
            [DVec3::ZERO, DVec3::X],
            [DVec3::X + DVec3::splat(1e-4), DVec3::Y],
            [DVec3::Y, DVec3::Y * (1.0 + 1e-4)],
        ];
        let (points, edges) = weld(&segments, 1e-3).unwrap();
        assert_eq!(points.len(), 3);
        assert_eq!(edges, [[0, 1], [1, 2]]);
        let (points, _) = weld(&segments, 0.0).unwrap();
        assert_eq!(points.len(), 5); // only the two identical ends of Y weld
    }

    #[test]
    fn weld_at_tolerance_zero_joins_signed_zeros() {
        let segments = [[DVec3::ZERO, DVec3::X], [DVec3::NEG_Y, -DVec3::ZERO]];
        let (points, edges) = weld(&segments, 0.0).unwrap();
        assert_eq!(points.len(), 3);
        assert_eq!(edges, [[0, 1], [0, 2]]);
    }

    #[test]
    fn weld_measures_tiny_and_huge_distances_without_underflow() {
        // 1e-300 apart: the squared distance underflows to 0.
        let tiny = [[DVec3::ZERO, DVec3::X], [DVec3::splat(1e-300), DVec3::Y]];
        assert_eq!(weld(&tiny, 1e-310).unwrap().0.len(), 4);
        assert_eq!(weld(&tiny, 2e-300).unwrap().0.len(), 3);
        // Near 1e300 the squares overflow; 0.5e300 apart is within 1e300.
        let (a, b) = (DVec3::splat(1e300), DVec3::new(1.5e300, 1e300, 1e300));
        let huge = [[a, DVec3::ZERO], [b, DVec3::ZERO]];
        assert_eq!(weld(&huge, 0.4e300).unwrap().0.len(), 3);
        assert_eq!(weld(&huge, 1e300).unwrap().0.len(), 2);
    }

    #[test]
    fn prune_removes_dangling_chains() {
        // A triangle 0-1-2 with a tail 2-3-4.
        let around = prune(5, &[[0, 1], [1, 2], [0, 2], [2, 3], [3, 4]]);
        assert!(around[3].is_empty() && around[4].is_empty());
        assert_eq!(around[2].len(), 2);
    }

    /// A wheel of 2,000 spokes whose inner ends lie scattered within the
    /// tolerance of the hub, and a rim: one hub of valence 2,000, and a
    /// triangle between each two spokes.
    #[test]
    fn a_wheel_of_many_spokes_gives_a_triangle_between_each_two() {
        let n = 2000;
        let rim = |k: usize| {
            let (y, x) = (std::f64::consts::TAU * k as f64 / n as f64).sin_cos();
            DVec3::new(x, y, 0.0)
        };
        let mut segments = Vec::new();
        for k in 0..n {
            let jitter = DVec3::new((k % 7) as f64, (k % 11) as f64, 0.0) * 1e-5;
            segments.push([jitter, rim(k)]);
            segments.push([rim(k), rim(k + 1)]);
        }
        let mesh = mesh_from_lines(&segments, 1e-3, 3).unwrap();
        assert_eq!((mesh.vertex_count(), mesh.face_count()), (n + 1, n));
        // Every triangle has the hub for a corner.
        let hub = (0..mesh.vertex_count())
            .find(|&v| mesh.positions()[v].length() < 1e-3)
            .unwrap() as u32;
        assert!(mesh.faces().all(|f| f.contains(&hub)));
    }

    #[test]
    fn a_square_with_a_diagonal_gives_two_triangles() {
        let p = [DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
        let segments = [
            [p[0], p[1]],
            [p[1], p[2]],
            [p[2], p[3]],
            [p[3], p[0]],
            [p[0], p[2]],
        ];
        let mesh = mesh_from_lines(&segments, 0.0, 4).unwrap();
        assert_eq!((mesh.vertex_count(), mesh.face_count()), (4, 2));
        assert!(mesh.is_triangle_mesh());
    }
}
