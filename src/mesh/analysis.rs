//! Measuring a mesh: face and vertex normals, planarity, face boundaries and
//! the naked boundary as polylines.

use glam::DVec3;
use rayon::prelude::*;

use crate::buffers::split_by_offsets;
use crate::error::Result;
use crate::mesh::topology::Topology;
use crate::mesh::Mesh;
use crate::mesh::{check_tolerance, linalg};

/// The unit normal of each face by Newell's method: the sum over its edges
/// of the cross products of consecutive corners, which is twice the area
/// vector of the polygon. It needs no choice of corners, so it stays robust
/// on non-planar and non-convex polygons (Sutherland, Sproull & Schumacker
/// 1974). A face of zero area gets the zero vector.
pub fn face_normals(mesh: &Mesh) -> Vec<DVec3> {
    // Each face's normal is its own: the same bits on any number of threads.
    (0..mesh.face_count())
        .into_par_iter()
        .with_min_len(NORMALS_RUN)
        .map(|f| face_normal(mesh, f))
        .collect()
}

/// Faces a thread takes at a time for their normals.
const NORMALS_RUN: usize = 8192;

/// The area vector of face `f` (its normal times its area), by Newell's method.
pub fn area_vector(mesh: &Mesh, f: usize) -> DVec3 {
    let (p, face) = (mesh.positions(), mesh.face(f));
    // The face's corners read where they lie, not copied out.
    newell_sum(face.len(), |i| p[face[i] as usize]) / 2.0
}

/// The unit Newell normal of face `f`; zero for a face of no area.
pub fn face_normal(mesh: &Mesh, f: usize) -> DVec3 {
    area_vector(mesh, f).normalize_or_zero()
}

/// The median length of the mesh's edges (0 for a mesh without faces): the
/// scale a tolerance is measured against in messages.
pub fn median_edge_length(mesh: &Mesh) -> f64 {
    let topology = crate::mesh::topology::Topology::new(mesh);
    let p = mesh.positions();
    median(
        topology
            .edges()
            .iter()
            .map(|&[a, b]| p[a as usize].distance(p[b as usize]))
            .collect(),
    )
}

/// The median length of the sides of at most `max_faces` faces spread
/// evenly over the mesh (all of them when there are fewer; 0 without
/// faces): [`median_edge_length`] at a cost that does not grow with the
/// mesh, for a hint to read before the mesh is taken apart. Every face's
/// sides count, so an inner edge counts twice; in a closed mesh every edge
/// does, and the median is that of the edges.
pub fn median_edge_length_sampled(mesh: &Mesh, max_faces: usize) -> f64 {
    let step = mesh.face_count().div_ceil(max_faces.max(1)).max(1);
    let p = mesh.positions();
    median(
        (0..mesh.face_count())
            .step_by(step)
            .flat_map(|f| {
                let face = mesh.face(f);
                (0..face.len()).map(move |i| {
                    p[face[i] as usize].distance(p[face[(i + 1) % face.len()] as usize])
                })
            })
            .collect(),
    )
}

/// The median of `lengths` (the upper of the two middle ones of an even
/// count), or 0 for none.
fn median(mut lengths: Vec<f64>) -> f64 {
    if lengths.is_empty() {
        return 0.0;
    }
    let middle = lengths.len() / 2;
    *lengths.select_nth_unstable_by(middle, f64::total_cmp).1
}

/// Newell's sum over a polygon's edges: a vector along the polygon's normal
/// whose length is twice its area. Taken about the first corner, which keeps
/// polygons far from the origin exact. Zero for fewer than 3 corners.
pub fn newell_vector(corners: &[DVec3]) -> DVec3 {
    newell_sum(corners.len(), |i| corners[i])
}

/// [`newell_vector`] of the `count` corners `corner(0), corner(1), …`.
#[inline]
fn newell_sum(count: usize, corner: impl Fn(usize) -> DVec3) -> DVec3 {
    if count == 0 {
        return DVec3::ZERO;
    }
    let origin = corner(0);
    (0..count)
        .map(|i| (corner(i) - origin).cross(corner((i + 1) % count) - origin))
        .sum()
}

/// The unit normal at each vertex: the faces' Newell normals weighted by
/// the angle of each face at the vertex (Thürmer & Wüthrich 1998).
///
/// Angle weighting is chosen over area weighting because it depends only
/// on the shape around the vertex, not on how the faces were cut: a quad
/// split into two triangles, or a large face beside small ones, leaves the
/// normal where it was. A vertex used by no face, or whose faces cancel,
/// gets the zero vector.
pub fn vertex_normals(mesh: &Mesh) -> Vec<DVec3> {
    let normals = face_normals(mesh);
    let (offsets, indices) = (mesh.face_offsets(), mesh.face_indices());
    let mut sums = vec![DVec3::ZERO; mesh.vertex_count()];
    let mut weighted = Vec::new();
    // Block by block: each corner's weighted normal on all threads, then
    // added to its vertex's sum corner after corner, in the order of the
    // faces, which keeps the sums' rounding whatever the threads.
    for first in (0..mesh.face_count()).step_by(SCATTER_BLOCK) {
        let last = (first + SCATTER_BLOCK).min(mesh.face_count());
        let corners = offsets[first] as usize..offsets[last] as usize;
        weighted.clear();
        weighted.resize(corners.len(), DVec3::ZERO);
        split_by_offsets(&mut weighted, &offsets[first..=last], WEIGHT_RUN)
            .into_par_iter()
            .for_each(|(faces, mut part)| {
                for f in faces {
                    let f = first + f;
                    let (own, rest) = std::mem::take(&mut part).split_at_mut(mesh.face(f).len());
                    weight_corners(mesh, f, normals[f], own);
                    part = rest;
                }
            });
        for (&v, &w) in indices[corners].iter().zip(&weighted) {
            sums[v as usize] += w;
        }
    }
    sums.into_par_iter()
        .with_min_len(NORMALS_RUN)
        .map(DVec3::normalize_or_zero)
        .collect()
}

/// Faces whose corners [`vertex_normals`] weighs at a time before adding
/// them up: their weights stay in the cache.
const SCATTER_BLOCK: usize = 1 << 14;

/// Faces of a block a thread weighs at a time.
const WEIGHT_RUN: usize = 1 << 10;

/// Face `f`'s `normal` weighted by its angle at each corner, into `out`.
fn weight_corners(mesh: &Mesh, f: usize, normal: DVec3, out: &mut [DVec3]) {
    let face = mesh.face(f);
    for (i, out) in out.iter_mut().enumerate() {
        *out = normal * corner_angle(mesh.positions(), face, i);
    }
}

/// The angle of `face` at its corner `i`.
fn corner_angle(p: &[DVec3], face: &[u32], i: usize) -> f64 {
    let n = face.len();
    let here = p[face[i] as usize];
    let to_next = p[face[(i + 1) % n] as usize] - here;
    let to_previous = p[face[(i + n - 1) % n] as usize] - here;
    // atan2 keeps small and near-straight angles accurate where acos does not.
    to_next
        .cross(to_previous)
        .length()
        .atan2(to_next.dot(to_previous))
}

/// Per face, the largest distance of its corners from its best-fit plane:
/// the plane through the corners' centroid that minimises the sum of the
/// squared (perpendicular) distances, whose normal is the eigenvector of
/// the corners' covariance with the smallest eigenvalue. Triangles give 0.
///
/// This is the planarity check of a planar-quad (PQ) mesh: a face whose
/// deviation is under the fabrication tolerance can be cut from a flat sheet.
pub fn planarity_deviations(mesh: &Mesh) -> Vec<f64> {
    let mut deviations = vec![0.0; mesh.face_count()];
    write_planarity_deviations(mesh, &mut deviations);
    deviations
}

/// [`planarity_deviations`] into `out`, which has one slot per face, on all
/// threads: each face's deviation is its own, whatever the order.
pub(crate) fn write_planarity_deviations(mesh: &Mesh, out: &mut [f64]) {
    out.par_iter_mut()
        .enumerate()
        .with_min_len(PLANARITY_RUN)
        .for_each_init(Vec::new, |corners, (f, slot)| {
            *slot = face_plane_deviation(mesh, f, corners);
        });
}

/// Faces a thread measures at a time: a face takes a small eigenproblem.
const PLANARITY_RUN: usize = 4096;

/// The deviation of face `f` from its best-fit plane, its corners gathered
/// into `corners`.
fn face_plane_deviation(mesh: &Mesh, f: usize, corners: &mut Vec<DVec3>) -> f64 {
    let face = mesh.face(f);
    if face.len() == 3 {
        return 0.0;
    }
    corners.clear();
    corners.extend(face.iter().map(|&v| mesh.positions()[v as usize]));
    plane_deviation(corners)
}

/// The planarity of a whole mesh against a tolerance (see
/// [`planarity_deviations`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Planarity {
    /// The largest deviation of any face (0 for a mesh without faces).
    pub largest_deviation: f64,
    /// How many faces are not within the tolerance.
    pub faces_beyond: usize,
}

/// The largest deviation of a face from its best-fit plane, and how many
/// faces are further than `tolerance`, measured on all threads without a
/// deviation per face kept.
///
/// # Errors
/// [`Error::InvalidArgument`](crate::Error::InvalidArgument) when
/// `tolerance` is negative, NaN or infinite.
pub fn planarity(mesh: &Mesh, tolerance: f64) -> Result<Planarity> {
    check_tolerance(tolerance)?;
    let start = Planarity {
        largest_deviation: 0.0,
        faces_beyond: 0,
    };
    // The largest and the count do not depend on the order of the faces.
    Ok((0..mesh.face_count())
        .into_par_iter()
        .with_min_len(PLANARITY_RUN)
        .fold(
            || (start, Vec::new()),
            |(sum, mut corners), f| {
                let deviation = face_plane_deviation(mesh, f, &mut corners);
                let sum = Planarity {
                    largest_deviation: sum.largest_deviation.max(deviation),
                    faces_beyond: sum.faces_beyond
                        + usize::from(deviation > tolerance || deviation.is_nan()),
                };
                (sum, corners)
            },
        )
        .map(|(sum, _)| sum)
        .reduce(
            || start,
            |a, b| Planarity {
                largest_deviation: a.largest_deviation.max(b.largest_deviation),
                faces_beyond: a.faces_beyond + b.faces_beyond,
            },
        ))
}

/// Whether every face lies within `tolerance` of its best-fit plane (see
/// [`planarity_deviations`]).
///
/// # Errors
/// [`Error::InvalidArgument`](crate::Error::InvalidArgument) when
/// `tolerance` is negative, NaN or infinite.
pub fn is_planar(mesh: &Mesh, tolerance: f64) -> Result<bool> {
    Ok(planarity(mesh, tolerance)?.faces_beyond == 0)
}

/// The largest distance of `points` from their least-squares plane.
pub fn plane_deviation(points: &[DVec3]) -> f64 {
    let count = points.len();
    if count < 4 {
        return 0.0;
    }
    let centroid = points.iter().sum::<DVec3>() / count as f64;
    // The best-fit plane's normal: the direction of least spread.
    let normal = linalg::least_spread_direction(linalg::covariance(points, centroid));
    points
        .iter()
        .map(|&p| (p - centroid).dot(normal).abs())
        .fold(0.0, f64::max)
}

/// A polyline through mesh vertices. A closed one returns from its last
/// vertex to its first; the first vertex is not repeated at the end.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Polyline {
    /// The vertex indices in order.
    pub vertices: Vec<u32>,
    /// Whether the last vertex joins back to the first.
    pub closed: bool,
}

impl Polyline {
    /// The positions of the polyline's vertices in `mesh`.
    pub fn points(&self, mesh: &Mesh) -> Vec<DVec3> {
        self.vertices
            .iter()
            .map(|&v| mesh.positions()[v as usize])
            .collect()
    }
}

/// Each face's boundary as a closed polyline, in the face's winding.
pub fn face_boundaries(mesh: &Mesh) -> Vec<Polyline> {
    mesh.faces()
        .map(|face| Polyline {
            vertices: face.to_vec(),
            closed: true,
        })
        .collect()
}

/// The naked edges (those with one face) chained into polylines.
///
/// Where every boundary vertex has two naked edges, as on a manifold mesh,
/// each hole and each outer border is one closed polyline that runs the way
/// its faces run their edges (counter-clockwise round the outside of a grid
/// seen from the front). At a vertex with one naked edge or with three or
/// more (a bow-tie, a fin), polylines stop: each chain from such a vertex
/// ends at the next one, and one that comes back to where it started is
/// closed. Every naked edge is in exactly one polyline.
pub fn naked_boundaries(mesh: &Mesh) -> Vec<Polyline> {
    let topology = Topology::new(mesh);
    let corner_vertices = topology.corner_vertices();
    let corner_next = topology.corner_next();
    // Each naked edge in its face's direction.
    let edges: Vec<[u32; 2]> = topology
        .naked_edges()
        .into_iter()
        .map(|e| {
            let c = topology.edge_corners(e as usize)[0] as usize;
            [corner_vertices[c], corner_vertices[corner_next[c] as usize]]
        })
        .collect();

    // The naked edges at each vertex.
    let mut offsets = vec![0u32; mesh.vertex_count() + 1];
    for &[a, b] in &edges {
        offsets[a as usize + 1] += 1;
        offsets[b as usize + 1] += 1;
    }
    for i in 1..offsets.len() {
        offsets[i] += offsets[i - 1];
    }
    let mut fill = offsets.clone();
    let mut incident = vec![0u32; 2 * edges.len()];
    for (k, &[a, b]) in edges.iter().enumerate() {
        for v in [a, b] {
            incident[fill[v as usize] as usize] = k as u32;
            fill[v as usize] += 1;
        }
    }
    let at = |v: u32| &incident[offsets[v as usize] as usize..offsets[v as usize + 1] as usize];
    let degree = |v: u32| at(v).len();

    let mut used = vec![false; edges.len()];
    let mut polylines = Vec::new();
    let walk = |start: u32, first: u32, used: &mut Vec<bool>| {
        let mut vertices = vec![start];
        let (mut here, mut edge) = (start, first);
        let mut closed = false;
        loop {
            used[edge as usize] = true;
            let [a, b] = edges[edge as usize];
            let next = if a == here { b } else { a };
            if next == start {
                closed = true;
                break;
            }
            vertices.push(next);
            if degree(next) != 2 {
                break;
            }
            match at(next).iter().find(|&&k| !used[k as usize]) {
                Some(&k) => (here, edge) = (next, k),
                None => break,
            }
        }
        // Run the way the first edge's face runs it.
        if edges[first as usize][0] != start {
            vertices[usize::from(closed)..].reverse();
        }
        Polyline { vertices, closed }
    };
    // Chains between junctions and ends first, then the loops that remain.
    for v in 0..mesh.vertex_count() as u32 {
        if degree(v) != 2 {
            for &k in at(v) {
                if !used[k as usize] {
                    polylines.push(walk(v, k, &mut used));
                }
            }
        }
    }
    for k in 0..edges.len() {
        if !used[k] {
            polylines.push(walk(edges[k][0], k as u32, &mut used));
        }
    }
    polylines
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;

    #[test]
    fn sampled_median_edge_reads_every_face_of_a_small_mesh_and_a_spread_of_a_large_one() {
        // A closed mesh: each edge is the side of two faces, so the median
        // of the sides is the median of the edges.
        let torus = shapes::torus(12, 20);
        assert_eq!(
            median_edge_length_sampled(&torus, usize::MAX),
            median_edge_length(&torus)
        );
        // 100 unit squares, then 200 squares of side 5: only a spread of
        // faces, not the first ones, finds the median of 5.
        let mut positions = Vec::new();
        let mut faces = Vec::new();
        for f in 0..300u32 {
            let side = if f < 100 { 1.0 } else { 5.0 };
            let x = f as f64 * 10.0;
            positions.extend([
                DVec3::new(x, 0.0, 0.0),
                DVec3::new(x + side, 0.0, 0.0),
                DVec3::new(x + side, side, 0.0),
                DVec3::new(x, side, 0.0),
            ]);
            faces.push([4 * f, 4 * f + 1, 4 * f + 2, 4 * f + 3]);
        }
        let squares = Mesh::from_polygons(positions, faces).unwrap();
        for max_faces in [usize::MAX, 150, 100, 7] {
            assert_eq!(
                median_edge_length_sampled(&squares, max_faces),
                5.0,
                "{max_faces}"
            );
        }
        // One face: the first, a unit square.
        assert_eq!(median_edge_length_sampled(&squares, 1), 1.0);
        assert_eq!(median_edge_length_sampled(&Mesh::empty(), 10), 0.0);
        assert_eq!(
            median_edge_length_sampled(&torus, 0),
            median_edge_length_sampled(&torus, 1)
        );
    }

    #[test]
    fn face_normals_on_all_threads_are_newells_sum_of_each_face_alone() {
        // Mixed sizes, a twisted surface, far from the origin, and many runs
        // of faces per thread.
        let mut mixed = shapes::torus(200, 120);
        let moved: Vec<DVec3> = mixed
            .positions()
            .iter()
            .map(|p| DVec3::new(p.x + 0.1 * p.y * p.z, p.y, p.z * 1.3) + 1e4)
            .collect();
        mixed = mixed.with_positions(moved).unwrap();
        let (positions, mut sizes, mut indices) = mixed.into_parts();
        sizes.extend([3, 5]);
        indices.extend([0, 1, 91, 2, 3, 4, 94, 93]);
        let mesh = Mesh::new(positions, sizes, indices).unwrap();
        let normals = face_normals(&mesh);
        for (f, &normal) in normals.iter().enumerate() {
            let corners: Vec<DVec3> = mesh.face_positions(f).collect();
            let area = newell_vector(&corners) / 2.0;
            assert_eq!(
                area_vector(&mesh, f).to_array(),
                area.to_array(),
                "face {f}"
            );
            assert_eq!(normal, area.normalize_or_zero(), "face {f}");
        }
    }

    #[test]
    fn vertex_normals_on_all_threads_keep_the_order_of_the_sums() {
        // Each corner's weight added to its vertex face after face, on one
        // thread: the sums the blocks must reproduce bit for bit.
        let one_thread = |mesh: &Mesh| {
            let mut sums = vec![DVec3::ZERO; mesh.vertex_count()];
            for f in 0..mesh.face_count() {
                let normal = face_normal(mesh, f);
                let face = mesh.face(f);
                for (i, &v) in face.iter().enumerate() {
                    sums[v as usize] += normal * corner_angle(mesh.positions(), face, i);
                }
            }
            sums.into_iter()
                .map(DVec3::normalize_or_zero)
                .collect::<Vec<_>>()
        };
        // More faces than a block, of mixed sizes, with an unused vertex.
        let torus = shapes::torus(240, 150);
        let wavy: Vec<DVec3> = torus
            .positions()
            .iter()
            .map(|p| *p + DVec3::new(0.0, 0.05 * (9.0 * p.x).sin(), 0.0))
            .chain([DVec3::splat(7.0)])
            .collect();
        let (_, mut sizes, mut indices) = torus.into_parts();
        sizes.extend([3, 5]);
        indices.extend([0, 1, 151, 2, 3, 4, 154, 153]);
        let mesh = Mesh::new(wavy, sizes, indices).unwrap();
        assert!(mesh.face_count() > 2 * SCATTER_BLOCK);
        let normals = vertex_normals(&mesh);
        assert_eq!(normals, one_thread(&mesh));
        assert_eq!(normals[mesh.vertex_count() - 1], DVec3::ZERO);
    }

    #[test]
    fn newell_normal_of_a_cube_face_points_out() {
        let normals = face_normals(&shapes::cube());
        assert_eq!(normals[0], -DVec3::Z);
        assert_eq!(normals[5], DVec3::X);
    }

    #[test]
    fn newell_normal_of_a_skew_quad_is_along_its_area_vector() {
        // A quad whose corner D lies well off the plane of A, B, C.
        let corners = [
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(3.0, 0.0, 1.0),
            DVec3::new(4.0, 2.0, -1.0),
            DVec3::new(1.0, 3.0, 2.0),
        ];
        let [a, b, c, d] = corners;
        let plane = (b - a).cross(c - a).normalize();
        assert!((d - a).dot(plane).abs() > 1.0, "the quad is not planar");
        let mesh = Mesh::from_polygons(corners.to_vec(), [[0u32, 1, 2, 3]]).unwrap();
        let normal = face_normals(&mesh)[0];
        // A quad's area vector is half the cross product of its diagonals,
        // whichever way it is bent.
        let expected = (c - a).cross(d - b).normalize();
        assert!(normal.distance(expected) < 1e-15, "{normal} {expected}");
        assert!((normal.length() - 1.0).abs() < 1e-15);
        // The normal of a corner's triangle is not the face's: at A and at C
        // the two halves of the quad tilt apart by a wide angle.
        let at_a = (b - a).cross(d - a).normalize();
        let at_c = (d - c).cross(b - c).normalize();
        assert!(at_a.dot(at_c) < 0.9);
        assert!(normal.dot(at_a) < 0.99 && normal.dot(at_c) < 0.99);
    }

    #[test]
    fn newell_normal_of_a_concave_non_planar_hexagon() {
        // An L-shaped hexagon over the XY plane (area 3, reflex corner at
        // (1, 1)) whose heights alternate 0, 1: it is not planar, yet its
        // shadows on the YZ and ZX planes enclose no area, so its area
        // vector is exactly (0, 0, 3).
        let l_shape = [
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(2.0, 0.0, 1.0),
            DVec3::new(2.0, 1.0, 0.0),
            DVec3::new(1.0, 1.0, 1.0),
            DVec3::new(1.0, 2.0, 0.0),
            DVec3::new(0.0, 2.0, 1.0),
        ];
        let polygon = [[0u32, 1, 2, 3, 4, 5]];
        let mesh = Mesh::from_polygons(l_shape.to_vec(), polygon).unwrap();
        assert!(
            planarity_deviations(&mesh)[0] > 0.1,
            "the hexagon is not planar"
        );
        assert_eq!(area_vector(&mesh, 0), DVec3::new(0.0, 0.0, 3.0));
        assert_eq!(face_normals(&mesh)[0], DVec3::Z);
        // The cross product at the reflex corner points the other way.
        let [_, _, p2, p3, p4, _] = l_shape;
        assert!((p3 - p2).cross(p4 - p3).z < 0.0);

        // Turned and moved far from the origin, the normal turns with it.
        let turn = glam::DQuat::from_axis_angle(DVec3::new(1.0, -2.0, 0.5).normalize(), 1.1);
        let far = DVec3::new(3.0e5, -2.0e5, 1.0e5);
        let moved: Vec<DVec3> = l_shape.iter().map(|&p| turn * p + far).collect();
        let mesh = Mesh::from_polygons(moved, polygon).unwrap();
        let normal = face_normals(&mesh)[0];
        let expected = turn * DVec3::Z;
        assert!(normal.distance(expected) < 1e-9, "{normal} {expected}");
        assert!((normal.length() - 1.0).abs() < 1e-15);
        assert!((area_vector(&mesh, 0).length() - 3.0).abs() < 1e-9);
    }

    #[test]
    fn vertex_normal_of_a_cube_corner_is_the_diagonal() {
        let normals = vertex_normals(&shapes::cube());
        let expected = DVec3::splat(-1.0).normalize();
        assert!(normals[0].distance(expected) < 1e-12);
    }

    #[test]
    fn vertex_normals_do_not_change_when_quads_are_split() {
        let quads = shapes::torus(8, 6);
        let triangles = shapes::triangle_torus(8, 6);
        for (a, b) in vertex_normals(&quads)
            .iter()
            .zip(vertex_normals(&triangles))
        {
            assert!(a.distance(b) < 1e-12, "{a} {b}");
        }
    }

    #[test]
    fn grid_boundary_is_one_counter_clockwise_loop() {
        let grid = shapes::quad_grid(3, 2);
        let loops = naked_boundaries(&grid);
        assert_eq!(loops.len(), 1);
        assert!(loops[0].closed);
        assert_eq!(loops[0].vertices, vec![0, 1, 2, 3, 7, 11, 10, 9, 8, 4]);
    }

    #[test]
    fn bow_tie_boundary_is_two_loops_through_the_junction() {
        let loops = naked_boundaries(&shapes::bow_tie());
        assert_eq!(loops.len(), 2);
        for l in &loops {
            assert!(l.closed);
            assert_eq!(l.vertices.len(), 4);
            assert_eq!(l.vertices[0], 0);
        }
        assert_eq!(loops[0].vertices, vec![0, 1, 2, 3]);
    }

    #[test]
    fn fin_boundary_stops_at_the_non_manifold_edge_ends() {
        // Edge 0-1 has three faces, so its ends have three naked edges each:
        // each triangle's two naked edges make one open chain from 0 to 1.
        let loops = naked_boundaries(&shapes::fin());
        assert_eq!(loops.len(), 3);
        assert!(loops.iter().all(|l| !l.closed && l.vertices.len() == 3));
        let edges: usize = loops.iter().map(|l| l.vertices.len() - 1).sum();
        assert_eq!(edges, 6);
    }

    #[test]
    fn closed_mesh_has_no_naked_boundary() {
        assert!(naked_boundaries(&shapes::cube()).is_empty());
        assert_eq!(
            face_boundaries(&shapes::cube())[1].vertices,
            vec![4, 5, 7, 6]
        );
    }
}
