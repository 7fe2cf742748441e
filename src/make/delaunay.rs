//! Delaunay triangulation of points on a plane.
//!
//! The points are projected orthogonally onto the plane and triangulated
//! there with the `spade` crate (incremental insertion with exact
//! predicates); the mesh keeps the original 3-D points as its vertices, so a
//! triangulated terrain keeps its heights.

use glam::DVec3;
use spade::{DelaunayTriangulation, HierarchyHintGenerator, InsertionError, Point2, Triangulation};

use crate::buffers::try_vec;
use crate::error::{Error, Result, MAX_ELEMENTS};
use crate::make::plane::{check_points, Plane};
use crate::mesh::Mesh;

/// What [`delaunay`] did besides triangulating.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DelaunayReport {
    /// Points dropped because an earlier point has the same projection.
    pub merged_duplicates: usize,
    /// For each input point, the mesh vertex it became (a merged duplicate
    /// maps to the vertex of the first point with its projection).
    pub point_vertices: Vec<u32>,
}

/// spade's triangulation, each point located from a hierarchy of coarser
/// triangulations: with the default (a walk from the last point inserted)
/// 300,000 random points took 11 s, the walks growing with the point count.
pub(crate) type PlaneTriangulation =
    DelaunayTriangulation<Point2<f64>, (), (), (), HierarchyHintGenerator<f64>>;

/// The distinct projections of some points, triangulated by spade.
pub(crate) struct Projected {
    pub(crate) triangulation: PlaneTriangulation,
    /// For each spade vertex (by index), the input point it came from: the
    /// first point with that projection.
    pub(crate) vertex_points: Vec<usize>,
    /// For each input point, its spade vertex index.
    pub(crate) point_vertices: Vec<u32>,
}

/// Projects the points and inserts them into a Delaunay triangulation.
///
/// # Errors
/// A non-finite point, or one whose projection lies beyond spade's range
/// (about 1e60 from the origin): [`Error::InvalidArgument`] naming it.
pub(crate) fn project_and_triangulate(points: &[DVec3], plane: &Plane) -> Result<Projected> {
    check_points(points, "point")?;
    if points.len() as u64 > MAX_ELEMENTS {
        return Err(Error::ResultTooLarge(format!(
            "{} points exceed the limit of {MAX_ELEMENTS}",
            points.len()
        )));
    }
    let mut triangulation = PlaneTriangulation::new();
    let mut vertex_points = try_vec(points.len(), "the triangulation's vertices")?;
    let mut point_vertices = try_vec(points.len(), "the point to vertex map")?;
    for (i, &point) in points.iter().enumerate() {
        let uv = plane.to_plane(point);
        // Coordinates too close to zero for spade's predicates are zero for any design.
        let position = spade::mitigate_underflow(Point2::new(uv.x, uv.y));
        let handle = triangulation.insert(position).map_err(|e| {
            let why = match e {
                InsertionError::TooLarge => "too far from the plane's origin",
                InsertionError::TooSmall => "too close to the plane's origin",
                InsertionError::NAN => "not a number",
            };
            Error::InvalidArgument(format!(
                "point {i} ({}, {}, {}) projects to ({}, {}), which is {why} for the triangulation",
                point.x, point.y, point.z, uv.x, uv.y
            ))
        })?;
        let vertex = handle.index();
        if vertex == vertex_points.len() {
            vertex_points.push(i);
        }
        point_vertices.push(vertex as u32);
    }
    Ok(Projected {
        triangulation,
        vertex_points,
        point_vertices,
    })
}

/// Triangulates `points` by the Delaunay criterion of their projections onto
/// `plane` (no point inside any triangle's circumcircle).
///
/// The mesh's vertices are the distinct input points in input order; of
/// points with the same projection (exactly, in `f64`) the first is kept and
/// the later ones are merged into it and counted in the report. Every face
/// is a triangle, counter-clockwise seen from the plane's normal, so faces
/// are front-facing along it. Where four or more points are cocircular the
/// choice among the equally Delaunay diagonals is spade's.
///
/// # Errors
/// - [`Error::InvalidArgument`] naming the first point with a NaN or
///   infinite coordinate (or one beyond the triangulation's range).
/// - [`Error::DegenerateInput`] for fewer than 3 distinct projections or when
///   they are all collinear.
/// - [`Error::ResultTooLarge`] for more than [`MAX_ELEMENTS`]` / 6` points
///   (up to two triangles per point must fit the cap), before anything is
///   allocated.
pub fn delaunay(points: &[DVec3], plane: &Plane) -> Result<(Mesh, DelaunayReport)> {
    // n points make at most 2n - 5 triangles: 6n face corners at most.
    if points.len() as u64 > MAX_ELEMENTS / 6 {
        return Err(Error::ResultTooLarge(format!(
            "a triangulation of {} points may have up to {} face corners; the limit is {MAX_ELEMENTS}, so at most {} points",
            points.len(),
            6 * points.len() as u128,
            MAX_ELEMENTS / 6
        )));
    }
    let projected = project_and_triangulate(points, plane)?;
    let triangulation = &projected.triangulation;
    let distinct = triangulation.num_vertices();
    if distinct < 3 {
        return Err(Error::DegenerateInput(format!(
            "a triangulation needs at least 3 distinct points; {} points were given, {distinct} distinct on the plane",
            points.len()
        )));
    }
    if triangulation.all_vertices_on_line() {
        return Err(Error::DegenerateInput(format!(
            "all {distinct} distinct points are collinear on the plane; there is nothing to triangulate"
        )));
    }
    let mut positions = try_vec(distinct, "the mesh's vertices")?;
    positions.extend(projected.vertex_points.iter().map(|&i| points[i]));
    let face_count = triangulation.num_inner_faces();
    let mut face_indices = try_vec(face_count * 3, "the mesh's faces")?;
    for face in triangulation.inner_faces() {
        // spade lists a face's vertices counter-clockwise in plane coordinates.
        face_indices.extend(face.vertices().map(|v| v.fix().index() as u32));
    }
    let mut face_sizes = try_vec(face_count, "the mesh's faces")?;
    face_sizes.resize(face_count, 3);
    let mesh = Mesh::from_valid_parts(positions, face_sizes, face_indices);
    let report = DelaunayReport {
        merged_duplicates: points.len() - distinct,
        point_vertices: projected.point_vertices,
    };
    Ok((mesh, report))
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    /// A small deterministic generator, so failures reproduce.
    pub(crate) struct Lcg(pub u64);
    impl Lcg {
        pub(crate) fn next(&mut self) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    fn random_points(seed: u64, n: usize) -> Vec<DVec2> {
        let mut rng = Lcg(seed);
        (0..n)
            .map(|_| DVec2::new(rng.next() * 10.0 - 5.0, rng.next() * 6.0 - 1.0))
            .collect()
    }

    fn circumcircle(a: DVec2, b: DVec2, c: DVec2) -> (DVec2, f64) {
        let d = 2.0 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
        let (a2, b2, c2) = (a.length_squared(), b.length_squared(), c.length_squared());
        let center = DVec2::new(
            (a2 * (b.y - c.y) + b2 * (c.y - a.y) + c2 * (a.y - b.y)) / d,
            (a2 * (c.x - b.x) + b2 * (a.x - c.x) + c2 * (b.x - a.x)) / d,
        );
        (center, (a - center).length())
    }

    #[test]
    fn random_point_sets_have_empty_circumcircles() {
        for seed in 1..6 {
            let flat = random_points(seed, 200);
            let points: Vec<DVec3> = flat.iter().map(|p| p.extend(seed as f64)).collect();
            let (mesh, report) = delaunay(&points, &Plane::xy()).unwrap();
            assert_eq!(report.merged_duplicates, 0);
            assert_eq!(mesh.vertex_count(), 200);
            assert!(mesh.face_count() > 200);
            for face in mesh.faces() {
                let [a, b, c] = [0, 1, 2].map(|k| flat[face[k] as usize]);
                assert!((b - a).perp_dot(c - a) > 0.0, "face not counter-clockwise");
                let (center, radius) = circumcircle(a, b, c);
                for (i, p) in flat.iter().enumerate() {
                    if face.contains(&(i as u32)) {
                        continue;
                    }
                    assert!(
                        (*p - center).length() > radius * (1.0 - 1e-9),
                        "point {i} inside the circumcircle of {face:?}"
                    );
                }
            }
            // Euler: a triangulation of n points with h on the hull has 2n - 2 - h triangles.
            let topology = crate::mesh::topology::Topology::new(&mesh);
            let hull = topology.naked_edges().len();
            assert_eq!(mesh.face_count(), 2 * 200 - 2 - hull);
        }
    }

    #[test]
    fn a_tilted_plane_gives_the_triangles_of_its_flat_copy() {
        let flat = random_points(42, 100);
        let flat_points: Vec<DVec3> = flat.iter().map(|p| p.extend(0.0)).collect();
        let (flat_mesh, _) = delaunay(&flat_points, &Plane::xy()).unwrap();

        let origin = DVec3::new(100.0, -20.0, 3.0);
        let x = DVec3::new(1.0, 2.0, 2.0) / 3.0;
        let y = DVec3::new(-2.0, -1.0, 2.0) / 3.0;
        let normal = x.cross(y);
        let mut rng = Lcg(7);
        let tilted: Vec<DVec3> = flat
            .iter()
            // Heights off the plane do not change the projection.
            .map(|p| origin + x * p.x + y * p.y + normal * (rng.next() * 4.0 - 2.0))
            .collect();
        // Unnormalised, skewed axes describe the same plane.
        let plane = Plane::new(origin, x * 5.0, y * 0.5 + x * 0.25).unwrap();
        let (tilted_mesh, _) = delaunay(&tilted, &plane).unwrap();
        assert_eq!(tilted_mesh.positions(), &tilted[..]);

        let canonical = |mesh: &Mesh| {
            let mut faces: Vec<[u32; 3]> = mesh
                .faces()
                .map(|f| {
                    let k = (0..3).min_by_key(|&k| f[k]).unwrap();
                    [f[k], f[(k + 1) % 3], f[(k + 2) % 3]]
                })
                .collect();
            faces.sort();
            faces
        };
        assert_eq!(canonical(&flat_mesh), canonical(&tilted_mesh));
        // Front-facing along the plane's normal.
        for f in 0..tilted_mesh.face_count() {
            let p: Vec<DVec3> = tilted_mesh.face_positions(f).collect();
            let projected: Vec<DVec3> = p
                .iter()
                .map(|q| *q - normal * normal.dot(*q - origin))
                .collect();
            let n = (projected[1] - projected[0]).cross(projected[2] - projected[0]);
            assert!(n.dot(normal) > 0.0);
        }
    }

    #[test]
    fn duplicates_are_merged_into_the_first_and_reported() {
        let points = [
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(1.0, 0.0, 5.0), // same projection as point 1
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.0, 0.0, 0.0),
        ];
        let (mesh, report) = delaunay(&points, &Plane::xy()).unwrap();
        assert_eq!(report.merged_duplicates, 2);
        assert_eq!(report.point_vertices, vec![0, 1, 2, 1, 3, 0]);
        assert_eq!(mesh.vertex_count(), 4);
        assert_eq!(mesh.positions()[1], DVec3::new(1.0, 0.0, 0.0));
        assert_eq!(mesh.face_count(), 2);
    }

    #[test]
    fn collinear_and_too_few_points_are_refused() {
        let line: Vec<DVec3> = (0..5)
            .map(|i| DVec3::new(i as f64, 2.0 * i as f64, 0.0))
            .collect();
        let error = delaunay(&line, &Plane::xy()).unwrap_err();
        assert!(
            matches!(&error, Error::DegenerateInput(m) if m.contains("collinear")),
            "{error}"
        );
        // Collinear only once projected: a vertical triangle seen from above.
        let upright = [DVec3::ZERO, DVec3::X, DVec3::new(0.5, 0.0, 1.0)];
        assert!(matches!(
            delaunay(&upright, &Plane::xy()),
            Err(Error::DegenerateInput(_))
        ));
        let two = [DVec3::ZERO, DVec3::X, DVec3::X];
        let error = delaunay(&two, &Plane::xy()).unwrap_err();
        assert!(
            matches!(&error, Error::DegenerateInput(m) if m.contains("2 distinct")),
            "{error}"
        );
        assert!(matches!(
            delaunay(&[], &Plane::xy()),
            Err(Error::DegenerateInput(_))
        ));
    }

    #[test]
    fn non_finite_points_are_named() {
        let points = [
            DVec3::ZERO,
            DVec3::X,
            DVec3::new(0.0, f64::NAN, 0.0),
            DVec3::Y,
        ];
        let error = delaunay(&points, &Plane::xy()).unwrap_err();
        assert!(
            matches!(&error, Error::InvalidArgument(m) if m.contains("point 2")),
            "{error}"
        );
        let far = [DVec3::ZERO, DVec3::X, DVec3::new(1e300, 1.0, 0.0)];
        let error = delaunay(&far, &Plane::xy()).unwrap_err();
        assert!(
            matches!(&error, Error::InvalidArgument(m) if m.contains("point 2")),
            "{error}"
        );
    }
}
