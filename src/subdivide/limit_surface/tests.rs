use super::*;
use crate::mesh::shapes;
use crate::subdivide::{NakedEdges, Subdivider};

fn limit_at_corners(cage: &Mesh, scheme: Scheme, options: &SubdivisionOptions) -> f64 {
    let surface = LimitSurface::new(cage, scheme, options).unwrap();
    let limit = Subdivider::new(cage, scheme, 1, options)
        .unwrap()
        .limit()
        .unwrap();
    let mut worst: f64 = 0.0;
    for f in 0..cage.face_count() {
        let corners = cage.face(f);
        for (k, &v) in corners.iter().enumerate() {
            let uv = match (scheme, corners.len(), k) {
                (Scheme::Loop, _, 0) | (_, 4, 0) => [0.0, 0.0],
                (Scheme::Loop, _, 1) | (_, 4, 1) => [1.0, 0.0],
                (Scheme::Loop, _, _) => [0.0, 1.0],
                (_, 4, 2) => [1.0, 1.0],
                (_, 4, _) => [0.0, 1.0],
                (_, n, k) => [(k % tile_width(n)) as f64, (k / tile_width(n)) as f64],
            };
            let mut p = [DVec3::ZERO];
            surface
                .evaluate(&[f as u32], &uv, &mut p, None, None)
                .unwrap();
            worst = worst.max((p[0] - limit.positions[v as usize]).length());
        }
    }
    worst
}

#[test]
fn corners_of_a_cube_are_the_limit_points() {
    let cube = shapes::cube();
    let options = SubdivisionOptions::new(NakedEdges::Smooth);
    assert!(limit_at_corners(&cube, Scheme::CatmullClark, &options) < 1e-14);
}

#[test]
fn graphs_stay_small_around_extraordinary_vertices() {
    let cube = shapes::cube();
    let options = SubdivisionOptions::new(NakedEdges::Smooth);
    let surface = LimitSurface::new(&cube, Scheme::CatmullClark, &options).unwrap();
    for graph in &surface.faces {
        assert!(graph.nodes.len() < 40, "{} nodes", graph.nodes.len());
    }
}

#[test]
fn corners_of_mixed_polygons_are_the_limit_points() {
    let cage = shapes::mixed_polygons();
    let options = SubdivisionOptions::new(NakedEdges::Smooth);
    let surface = LimitSurface::new(&cage, Scheme::CatmullClark, &options).unwrap();
    let limit = Subdivider::new(&cage, Scheme::CatmullClark, 1, &options)
        .unwrap()
        .limit()
        .unwrap();
    for f in 0..cage.face_count() {
        let corners = cage.face(f);
        let n = corners.len();
        for (k, &v) in corners.iter().enumerate() {
            let uv = if n == 4 {
                [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]][k]
            } else {
                [(k % tile_width(n)) as f64, (k / tile_width(n)) as f64]
            };
            let mut p = [DVec3::ZERO];
            surface
                .evaluate(&[f as u32], &uv, &mut p, None, None)
                .unwrap();
            let d = (p[0] - limit.positions[v as usize]).length();
            if d > 1e-12 {
                println!(
                    "face {f} ({n} corners) corner {k} vertex {v}: {d:e} nodes {}",
                    surface.faces[f].nodes.len()
                );
            }
        }
    }
}

#[test]
fn derivatives_match_finite_differences_on_sub_faces() {
    let cage = shapes::mixed_polygons();
    let options = SubdivisionOptions::new(NakedEdges::Smooth);
    let surface = LimitSurface::new(&cage, Scheme::CatmullClark, &options).unwrap();
    for f in 0..cage.face_count() {
        let n = cage.face(f).len();
        let w = if n == 4 { 1 } else { tile_width(n) };
        for tile in 0..(if n == 4 { 1 } else { n }) {
            let (x, y) = ((tile % w) as f64, (tile / w) as f64);
            let size = if n == 4 { 1.0 } else { 0.5 };
            for &(a, b) in &[(0.3, 0.3), (0.7, 0.2), (0.5, 0.9)] {
                let (u, v) = (x + size * a, y + size * b);
                let h = 1e-6;
                let at = |u: f64, v: f64| {
                    let mut p = [DVec3::ZERO];
                    let (mut du, mut dv) = ([DVec3::ZERO], [DVec3::ZERO]);
                    surface
                        .evaluate(&[f as u32], &[u, v], &mut p, Some(&mut du), Some(&mut dv))
                        .unwrap();
                    (p[0], du[0], dv[0])
                };
                let (_, du, dv) = at(u, v);
                let fu = (at(u + h, v).0 - at(u - h, v).0) / (2.0 * h);
                let fv = (at(u, v + h).0 - at(u, v - h).0) / (2.0 * h);
                assert!(
                    (fu - du).length() < 1e-6 * du.length().max(1.0),
                    "face {f} ({n}) tile {tile} {u} {v}: {fu:?} {du:?}"
                );
                assert!(
                    (fv - dv).length() < 1e-6 * dv.length().max(1.0),
                    "face {f} ({n}) tile {tile} {u} {v}: {fv:?} {dv:?}"
                );
            }
        }
    }
}
