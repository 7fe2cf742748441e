//! A mesh from a grid of points: the Mesh UV / Mesh Surface step, where the
//! host samples its NURBS surface on U × V points and Weft connects them.

use glam::DVec3;

use crate::buffers::try_vec;
use crate::error::{Error, Result, MAX_ELEMENTS};
use crate::make::plane::check_points;
use crate::mesh::Mesh;

/// The checks of [`mesh_from_grid`] on the counts alone (the C ABI makes
/// them before it views the caller's buffer of points).
pub(crate) fn check_grid_counts(
    point_count: usize,
    u_count: usize,
    v_count: usize,
    closed_u: bool,
    closed_v: bool,
) -> Result<()> {
    if u_count < 2 || v_count < 2 {
        return Err(Error::InvalidArgument(format!(
            "a grid needs at least 2 points in each direction; u_count is {u_count} and v_count is {v_count}"
        )));
    }
    let expected = u_count.checked_mul(v_count);
    if expected != Some(point_count) {
        return Err(Error::InvalidArgument(format!(
            "{point_count} points were given but a grid of u_count × v_count = {u_count} × {v_count} needs {}",
            expected.map_or("more than memory can hold".to_string(), |n| n.to_string())
        )));
    }
    for (closed, name, count) in [(closed_u, "u", u_count), (closed_v, "v", v_count)] {
        if closed && count < 3 {
            return Err(Error::InvalidArgument(format!(
                "a grid closed in {name} needs at least 3 points in {name}; {name}_count is {count}"
            )));
        }
    }
    Ok(())
}

/// Connects a `u_count × v_count` grid of points into quads, or triangles.
///
/// Point `(u, v)` is `points[v * u_count + u]`: u runs fastest, one row of
/// constant v after another. The quad at `(u, v)` is
/// `(u, v), (u+1, v), (u+1, v+1), (u, v+1)`, so its front side is the side
/// `∂/∂u × ∂/∂v` points to. Faces come row by row, u fastest.
///
/// A direction that is `closed` wraps around: the last point of each row
/// connects to the first, which is not repeated (pass `u_count` distinct
/// points; the seam is welded by index). The vertices are the points, in
/// order.
///
/// With `triangulate`, each quad is split along its shorter diagonal (the
/// `(u, v)`–`(u+1, v+1)` one on a tie) into two triangles, the one holding
/// the quad's first corner first.
///
/// # Errors
/// [`Error::InvalidArgument`] when `points.len() != u_count * v_count`
/// (naming both), when a count is below 2, when a closed direction has
/// fewer than 3 points, or naming a point with a non-finite coordinate;
/// [`Error::ResultTooLarge`] past [`MAX_ELEMENTS`].
pub fn mesh_from_grid(
    points: &[DVec3],
    u_count: usize,
    v_count: usize,
    closed_u: bool,
    closed_v: bool,
    triangulate: bool,
) -> Result<Mesh> {
    check_grid_counts(points.len(), u_count, v_count, closed_u, closed_v)?;
    check_points(points, "point")?;
    let quads_u = if closed_u { u_count } else { u_count - 1 };
    let quads_v = if closed_v { v_count } else { v_count - 1 };
    let quad_count = quads_u as u64 * quads_v as u64;
    let index_count = quad_count * if triangulate { 6 } else { 4 };
    if points.len() as u64 > MAX_ELEMENTS || index_count > MAX_ELEMENTS {
        return Err(Error::ResultTooLarge(format!(
            "a grid of {u_count} × {v_count} points would have {index_count} face corners, over the limit of {MAX_ELEMENTS}"
        )));
    }
    let face_count = quad_count as usize * if triangulate { 2 } else { 1 };
    let mut face_sizes = try_vec(face_count, "the grid's faces")?;
    let mut face_indices = try_vec(index_count as usize, "the grid's faces")?;
    let index = |u: usize, v: usize| ((v % v_count) * u_count + u % u_count) as u32;
    for v in 0..quads_v {
        for u in 0..quads_u {
            let quad = [
                index(u, v),
                index(u + 1, v),
                index(u + 1, v + 1),
                index(u, v + 1),
            ];
            if triangulate {
                let [a, b, c, d] = quad.map(|i| points[i as usize]);
                let triangles = if (c - a).length_squared() <= (d - b).length_squared() {
                    [[quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]]
                } else {
                    [[quad[0], quad[1], quad[3]], [quad[1], quad[2], quad[3]]]
                };
                for triangle in triangles {
                    face_sizes.push(3);
                    face_indices.extend_from_slice(&triangle);
                }
            } else {
                face_sizes.push(4);
                face_indices.extend_from_slice(&quad);
            }
        }
    }
    Ok(Mesh::from_valid_parts(
        points.to_vec(),
        face_sizes,
        face_indices,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::topology::Topology;

    fn flat_grid(u_count: usize, v_count: usize) -> Vec<DVec3> {
        (0..v_count)
            .flat_map(|v| (0..u_count).map(move |u| DVec3::new(u as f64, v as f64, 0.0)))
            .collect()
    }

    fn normal(mesh: &Mesh, f: usize) -> DVec3 {
        let p: Vec<DVec3> = mesh.face_positions(f).collect();
        (0..p.len()).map(|k| p[k].cross(p[(k + 1) % p.len()])).sum()
    }

    #[test]
    fn an_open_grid_gives_quads_facing_u_cross_v() {
        let mesh = mesh_from_grid(&flat_grid(4, 3), 4, 3, false, false, false).unwrap();
        assert_eq!(mesh.vertex_count(), 12);
        assert_eq!(mesh.face_count(), 6);
        assert_eq!(mesh.face(0), &[0, 1, 5, 4]);
        assert_eq!(mesh.face(5), &[6, 7, 11, 10]);
        for f in 0..6 {
            assert!(normal(&mesh, f).z > 0.0);
        }
        let info = Topology::new(&mesh).info(&mesh);
        assert_eq!(info.naked_edge_count, 10);
        assert!(info.is_oriented);
    }

    #[test]
    fn triangles_split_along_the_shorter_diagonal() {
        // Squash one quad so the diagonal from (1,0) to (0,1) is the shorter.
        let mut points = flat_grid(2, 2);
        points[3] = DVec3::new(3.0, 3.0, 0.0);
        let mesh = mesh_from_grid(&points, 2, 2, false, false, true).unwrap();
        assert_eq!(mesh.face_indices(), &[0, 1, 2, 1, 3, 2]);
        let square = mesh_from_grid(&flat_grid(2, 2), 2, 2, false, false, true).unwrap();
        assert_eq!(square.face_indices(), &[0, 1, 3, 0, 3, 2]);
        for f in 0..2 {
            assert!(normal(&mesh, f).z > 0.0 && normal(&square, f).z > 0.0);
        }
    }

    fn torus_points(u_count: usize, v_count: usize) -> Vec<DVec3> {
        let mut points = Vec::new();
        for v in 0..v_count {
            let b = std::f64::consts::TAU * v as f64 / v_count as f64;
            for u in 0..u_count {
                let a = std::f64::consts::TAU * u as f64 / u_count as f64;
                let r = 3.0 + b.cos();
                points.push(DVec3::new(r * a.cos(), r * a.sin(), b.sin()));
            }
        }
        points
    }

    #[test]
    fn closed_directions_weld_the_seam_by_index() {
        let points = torus_points(8, 5);
        for triangulate in [false, true] {
            let mesh = mesh_from_grid(&points, 8, 5, true, true, triangulate).unwrap();
            assert_eq!(mesh.vertex_count(), 40);
            assert_eq!(mesh.face_count(), if triangulate { 80 } else { 40 });
            let info = Topology::new(&mesh).info(&mesh);
            assert!(info.is_closed && info.is_oriented);
            assert_eq!(info.vertex_count + info.face_count - info.edge_count, 0);
        }
        // A cylinder: closed in u only.
        let mesh = mesh_from_grid(&points[..16], 8, 2, true, false, false).unwrap();
        assert_eq!(mesh.face_count(), 8);
        assert_eq!(mesh.face(7), &[7, 0, 8, 15]);
        let info = Topology::new(&mesh).info(&mesh);
        assert_eq!(info.naked_edge_count, 16);
    }

    #[test]
    fn wrong_counts_are_named() {
        let points = flat_grid(4, 3);
        let e = mesh_from_grid(&points[..11], 4, 3, false, false, false).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("11 points") && m.contains("4 × 3")),
            "{e}"
        );
        let e = mesh_from_grid(&points[..4], 4, 1, false, false, false).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("v_count is 1")),
            "{e}"
        );
        let e = mesh_from_grid(&points[..8], 2, 4, true, false, false).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("closed in u")),
            "{e}"
        );
        let e = mesh_from_grid(&points, usize::MAX, 2, false, false, false).unwrap_err();
        assert!(matches!(e, Error::InvalidArgument(_)));
        let mut bad = points.clone();
        bad[7].y = f64::NAN;
        let e = mesh_from_grid(&bad, 4, 3, false, false, false).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidArgument(m) if m.contains("point 7")),
            "{e}"
        );
    }
}
