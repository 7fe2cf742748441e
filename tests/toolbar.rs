//! The rest of Weaverbird's toolbar on named shapes: counts, and the
//! property that defines each operation.

use weft::mesh::shapes;
use weft::toolbar::extract::{
    dual, edge_segments, mesh_edges, mesh_from_lines, reroute_faces, DualMode,
};
use weft::toolbar::smooth::{
    blur, laplacian, laplacian_hc, laplacian_hc_with, HcOptions, NakedEdges, SmoothDirection,
};
use weft::toolbar::split::{
    constant_quads_split, inner_polygons, midedge, sierpinski_triangles, split_polygons,
    split_triangles,
};
use weft::toolbar::transform::{
    bevel_edges, bevel_vertices, offset, picture_frame, sierpinski_carpet, thicken, window,
    InsetMode, OffsetType,
};
use weft::{DVec3, Error, Mesh, Topology};

fn info(mesh: &Mesh) -> weft::MeshInfo {
    Topology::new(mesh).info(mesh)
}

fn newell(mesh: &Mesh, f: usize) -> DVec3 {
    let p: Vec<DVec3> = mesh.face_positions(f).collect();
    (0..p.len()).map(|i| p[i].cross(p[(i + 1) % p.len()])).sum()
}

fn area(mesh: &Mesh) -> f64 {
    (0..mesh.face_count())
        .map(|f| newell(mesh, f).length() / 2.0)
        .sum()
}

/// Volume enclosed by a closed, outward mesh (fan triangles against the origin).
fn volume(mesh: &Mesh) -> f64 {
    mesh.faces()
        .map(|face| {
            let p = mesh.positions();
            let a = p[face[0] as usize];
            (1..face.len() - 1)
                .map(|i| a.dot(p[face[i] as usize].cross(p[face[i + 1] as usize])) / 6.0)
                .sum::<f64>()
        })
        .sum()
}

fn on_unit_cube(p: DVec3) -> bool {
    let inside = p.min_element() >= -1e-12 && p.max_element() <= 1.0 + 1e-12;
    let on_face = p
        .to_array()
        .iter()
        .any(|&x| x.abs() < 1e-12 || (x - 1.0).abs() < 1e-12);
    inside && on_face
}

fn single(points: &[[f64; 3]]) -> Mesh {
    let p = points.iter().map(|&a| DVec3::from_array(a)).collect();
    Mesh::from_polygons(p, [(0..points.len() as u32).collect::<Vec<_>>()]).unwrap()
}

fn sizes_of(mesh: &Mesh, size: u32) -> usize {
    mesh.face_sizes().iter().filter(|&&s| s == size).count()
}

#[test]
fn split_polygons_of_a_cube_keeps_the_surface() {
    let cube = shapes::cube();
    let split = split_polygons(&cube, 1).unwrap();
    assert_eq!((split.vertex_count(), split.face_count()), (26, 24));
    assert!(split.is_quad_mesh());
    assert_eq!(&split.positions()[..8], cube.positions());
    assert!(split.positions().iter().all(|&p| on_unit_cube(p)));
    assert!((area(&split) - 6.0).abs() < 1e-12);
    let i = info(&split);
    assert!(i.is_closed && i.is_oriented);
    let twice = split_polygons(&cube, 2).unwrap();
    assert_eq!((twice.vertex_count(), twice.face_count()), (98, 96));
    assert_eq!(split_polygons(&cube, 0).unwrap(), cube);
}

#[test]
fn split_triangles_of_a_tetrahedron_keeps_its_area() {
    let tetra = shapes::tetrahedron();
    let split = split_triangles(&tetra, 1).unwrap();
    assert_eq!((split.vertex_count(), split.face_count()), (10, 16));
    assert!((area(&split) - area(&tetra)).abs() < 1e-12);
    assert!(info(&split).is_closed && info(&split).is_oriented);
    assert_eq!(split_triangles(&tetra, 2).unwrap().face_count(), 64);
    let err = split_triangles(&shapes::cube(), 1).unwrap_err();
    assert_eq!(err, Error::NotTriangles { face: 0, size: 4 });
}

#[test]
fn too_many_levels_fail_before_building() {
    let err = split_polygons(&shapes::cube(), 20).unwrap_err();
    assert!(matches!(err, Error::ResultTooLarge(_)), "{err}");
    let err = split_polygons(&shapes::cube(), 21).unwrap_err();
    assert!(matches!(err, Error::InvalidArgument(_)));
}

#[test]
fn constant_quads_split_keeps_each_kind_of_face() {
    // A quad and a triangle sharing an edge.
    let p = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [2.0, 0.5, 0.0],
    ]
    .map(DVec3::from_array)
    .to_vec();
    let mesh = Mesh::from_polygons(p, [vec![0, 1, 2, 3], vec![1, 4, 2]]).unwrap();
    let split = constant_quads_split(&mesh, 1).unwrap();
    assert_eq!((sizes_of(&split, 4), sizes_of(&split, 3)), (4, 4));
    // 5 vertices + 6 edge midpoints + 1 quad centre.
    assert_eq!(split.vertex_count(), 12);
    assert!((area(&split) - area(&mesh)).abs() < 1e-12);
    assert_eq!(
        info(&split).naked_edge_count,
        2 * info(&mesh).naked_edge_count
    );
    let cube = constant_quads_split(&shapes::cube(), 2).unwrap();
    assert!(cube.is_quad_mesh() && cube.face_count() == 96);
}

#[test]
fn midedge_of_a_cube_is_a_cuboctahedron() {
    let m = midedge(&shapes::cube(), 1).unwrap();
    assert_eq!(m.vertex_count(), 12);
    assert_eq!((sizes_of(&m, 4), sizes_of(&m, 3)), (6, 8));
    assert!(info(&m).is_closed && info(&m).is_oriented);
    // Boundary: the outline of a square stays, its corners kept.
    let square = shapes::quad_grid(1, 1);
    let m = midedge(&square, 1).unwrap();
    assert_eq!((m.vertex_count(), m.face_count()), (8, 5));
    assert!((area(&m) - 1.0).abs() < 1e-12);
    assert!(info(&m).is_oriented);
}

#[test]
fn inner_polygons_add_a_face_and_a_quad_per_edge() {
    let m = inner_polygons(&shapes::cube(), 1, 0.5).unwrap();
    assert_eq!((m.vertex_count(), m.face_count()), (32, 30));
    assert!(info(&m).is_closed && info(&m).is_oriented);
    assert!((area(&m) - 6.0).abs() < 1e-12);
    assert!(inner_polygons(&shapes::cube(), 1, 1.0).is_err());
}

#[test]
fn sierpinski_triangles_triple_faces_and_naked_edges() {
    let triangle = single(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
    let mut naked = 3;
    for level in 1..=3 {
        let s = sierpinski_triangles(&triangle, level).unwrap();
        naked *= 3;
        assert_eq!(s.face_count(), 3usize.pow(level));
        assert_eq!(info(&s).naked_edge_count, naked);
    }
    // A closed solid gets one hole per face.
    let s = sierpinski_triangles(&shapes::icosahedron(), 1).unwrap();
    assert_eq!(s.face_count(), 60);
    assert_eq!(info(&s).naked_edge_count, 60);
}

fn bumpy_grid() -> Mesh {
    let mut grid = shapes::quad_grid(4, 4);
    for (i, p) in grid.positions_mut().iter_mut().enumerate() {
        p.z = ((i * 7919) % 13) as f64 * 0.05;
    }
    grid
}

#[test]
fn laplacian_naked_edge_modes() {
    let grid = bumpy_grid();
    let boundary = Topology::new(&grid).boundary_vertices();
    let fixed = laplacian(&grid, 5, 0.5, NakedEdges::Fixed).unwrap();
    for (v, &on_boundary) in boundary.iter().enumerate() {
        if on_boundary {
            assert_eq!(fixed.positions()[v], grid.positions()[v]);
        }
    }
    assert_ne!(fixed.positions()[6], grid.positions()[6]);
    // Smooth: a vertex on the side x = 0 only listens to that side.
    let smooth = laplacian(&grid, 1, 0.5, NakedEdges::Smooth).unwrap();
    assert_eq!(smooth.positions()[5].x, 0.0);
    assert_eq!(
        smooth.positions()[5].z,
        0.5 * grid.positions()[5].z + 0.25 * (grid.positions()[0].z + grid.positions()[10].z)
    );
    assert_ne!(smooth.positions()[0], grid.positions()[0]);
    let corner = laplacian(&grid, 5, 0.5, NakedEdges::CornerFixed).unwrap();
    assert_eq!(corner.positions()[0], grid.positions()[0]);
    assert_ne!(corner.positions()[5], grid.positions()[5]);
    assert!(laplacian(&grid, 1, 1.5, NakedEdges::Fixed).is_err());
}

fn jittered_sphere() -> Mesh {
    let mut sphere = split_triangles(&shapes::icosahedron(), 2).unwrap();
    for (i, p) in sphere.positions_mut().iter_mut().enumerate() {
        let jitter = 1.0 + (((i * 2654435761) % 1000) as f64 / 1000.0 - 0.5) * 0.2;
        *p = p.normalize() * jitter;
    }
    sphere
}

#[test]
fn hc_keeps_volume_better_than_laplacian() {
    let sphere = jittered_sphere();
    let v0 = volume(&sphere);
    let plain = laplacian(&sphere, 10, 1.0, NakedEdges::Fixed).unwrap();
    let hc = laplacian_hc(&sphere, 10, 0.0, 0.6, NakedEdges::Fixed).unwrap();
    let (lost_plain, lost_hc) = ((v0 - volume(&plain)).abs(), (v0 - volume(&hc)).abs());
    assert!(
        lost_hc < lost_plain / 3.0,
        "HC lost {lost_hc}, Laplacian {lost_plain}"
    );
    // And it does smooth: the spread of the radii shrinks.
    let spread = |m: &Mesh| {
        let r: Vec<f64> = m.positions().iter().map(|p| p.length()).collect();
        r.iter().cloned().fold(f64::MIN, f64::max) - r.iter().cloned().fold(f64::MAX, f64::min)
    };
    assert!(spread(&hc) < spread(&sphere) / 2.0);
}

#[test]
fn blur_averages_values_and_checks_their_count() {
    let grid = shapes::quad_grid(2, 2);
    let constant = vec![0.25; 9 * 3];
    let out = blur(&grid, &constant, 3, 4, 1.0, NakedEdges::Smooth).unwrap();
    assert!(out.iter().all(|&x| (x - 0.25).abs() < 1e-15));
    // A spike at the middle vertex spreads to its four neighbours.
    let mut spike = vec![0.0; 9];
    spike[4] = 1.0;
    let out = blur(&grid, &spike, 1, 1, 1.0, NakedEdges::Fixed).unwrap();
    assert_eq!(out[4], 0.0);
    assert_eq!(out[0], 0.0); // boundary fixed
    let out = blur(&grid, &spike, 1, 1, 0.5, NakedEdges::Smooth).unwrap();
    assert_eq!(out[4], 0.5);
    let err = blur(&grid, &[0.0; 5], 1, 1, 1.0, NakedEdges::Fixed).unwrap_err();
    let text = err.to_string();
    assert!(
        text.contains("5 values") && text.contains("need 9"),
        "{text}"
    );
}

#[test]
fn planes_intersection_offset_moves_each_face_plane_by_d() {
    let cube = shapes::cube();
    let d = 0.25;
    let out = offset(&cube, d, OffsetType::PlanesIntersection).unwrap();
    for f in 0..cube.face_count() {
        let n = newell(&cube, f).normalize();
        let plane = n.dot(cube.positions()[cube.face(f)[0] as usize]) + d;
        for &v in cube.face(f) {
            assert!((n.dot(out.positions()[v as usize]) - plane).abs() < 1e-12);
        }
    }
    // A cube corner's three faces meet symmetrically: hypotenuse agrees.
    let hyp = offset(&cube, d, OffsetType::HypotenuseAverage).unwrap();
    for (a, b) in hyp.positions().iter().zip(out.positions()) {
        assert!((*a - *b).length() < 1e-12);
    }
    let diag = offset(&cube, d, OffsetType::Diagonal).unwrap();
    for (a, b) in diag.positions().iter().zip(cube.positions()) {
        assert!(((*a - *b).length() - d).abs() < 1e-12);
    }
    // Flat vertices move straight by d.
    let flat = offset(&shapes::quad_grid(2, 2), d, OffsetType::PlanesIntersection).unwrap();
    assert!(flat.positions().iter().all(|p| (p.z - d).abs() < 1e-12));
}

#[test]
fn thicken_of_an_open_grid_is_a_closed_solid() {
    let grid = shapes::quad_grid(3, 2);
    for d in [0.5, -0.5] {
        let solid = thicken(&grid, d, OffsetType::PlanesIntersection).unwrap();
        assert_eq!(solid.vertex_count(), 24);
        assert_eq!(solid.face_count(), 12 + 10);
        let i = info(&solid);
        assert!(i.is_closed && i.is_oriented && i.component_count == 1);
        assert!(volume(&solid) > 0.0, "outward for d = {d}");
        assert!((volume(&solid) - 3.0).abs() < 1e-12);
    }
}

/// The unit normal of each face around each vertex, once per corner, as
/// the offset module reads them (Newell's normal of each face).
fn normals_around(mesh: &Mesh) -> Vec<Vec<DVec3>> {
    let mut around = vec![Vec::new(); mesh.vertex_count()];
    for (f, face) in mesh.faces().enumerate() {
        let n = newell(mesh, f).normalize();
        for &v in face {
            around[v as usize].push(n);
        }
    }
    around
}

/// Checks that `moved` is `mesh` offset by `d` as `kind` defines it, vertex
/// by vertex: n_v the normalised sum of the unit normals of v's faces,
/// Diagonal moves by d·n_v; Hypotenuse Average along n_v by the mean over
/// v's faces of d / cos θ_f (cosines below 0.1 taken as 0.1); Planes
/// Intersection onto the plane of each of v's faces moved by d along its
/// normal (with two faces, onto their moved line).
fn assert_offset_by(mesh: &Mesh, moved: &[DVec3], d: f64, kind: OffsetType) {
    for (v, normals) in normals_around(mesh).iter().enumerate() {
        let p = mesh.positions()[v];
        let step = moved[v] - p;
        let n_v = normals.iter().sum::<DVec3>().normalize();
        let what = format!("{kind:?} vertex {v}: moved by {step}");
        match kind {
            OffsetType::Diagonal => assert!((step - d * n_v).length() < 1e-12, "{what}"),
            OffsetType::HypotenuseAverage => {
                let mean = normals
                    .iter()
                    .map(|n| d / n_v.dot(*n).max(0.1))
                    .sum::<f64>()
                    / normals.len() as f64;
                assert!((step - mean * n_v).length() < 1e-12, "{what}");
            }
            OffsetType::PlanesIntersection => {
                for n in normals {
                    assert!((n.dot(step) - d).abs() < 1e-12, "{what}: {n}");
                }
            }
        }
    }
}

/// A prism on an equilateral triangle, outward: at each corner the base
/// meets the two walls at right angles, the walls meet each other at 60°.
fn triangular_prism() -> Mesh {
    let corner = |k: usize, z: f64| {
        let a = std::f64::consts::TAU * k as f64 / 3.0;
        DVec3::new(a.cos(), a.sin(), z)
    };
    let positions = (0..6).map(|i| corner(i % 3, (i / 3) as f64)).collect();
    let faces: [&[u32]; 5] = [
        &[0, 2, 1],
        &[3, 4, 5],
        &[0, 1, 4, 3],
        &[1, 2, 5, 4],
        &[2, 0, 3, 5],
    ];
    let prism = Mesh::from_polygons(positions, faces).unwrap();
    assert!(volume(&prism) > 0.0);
    prism
}

#[test]
fn offset_types_differ_where_faces_meet_at_unequal_angles() {
    let prism = triangular_prism();
    let d = 0.2;
    let kinds = [
        OffsetType::Diagonal,
        OffsetType::HypotenuseAverage,
        OffsetType::PlanesIntersection,
    ];
    let moved: Vec<Mesh> = kinds
        .iter()
        .map(|&kind| offset(&prism, d, kind).unwrap())
        .collect();
    for (out, &kind) in moved.iter().zip(&kinds) {
        assert_eq!(out.face_indices(), prism.face_indices());
        assert_offset_by(&prism, out.positions(), d, kind);
    }
    // At corner 0 the unit normals are -z and two horizontal ones 120°
    // apart, so n_v = (u - z)/√2, u halfway between the walls' normals:
    // cos θ is 1/√2 to the base and 1/(2√2) to each wall.
    let u = DVec3::X;
    let n_v = (u - DVec3::Z) / 2f64.sqrt();
    let p = prism.positions()[0];
    let hypotenuse = n_v * d * (2f64.sqrt() + 2.0 * 2.0 * 2f64.sqrt()) / 3.0;
    let planes = u * 2.0 * d - DVec3::Z * d;
    assert!((moved[1].positions()[0] - p - hypotenuse).length() < 1e-12);
    assert!((moved[2].positions()[0] - p - planes).length() < 1e-12);
    assert!((moved[0].positions()[0] - p - n_v * d).length() < 1e-12);
    // Here, unlike at a cube's corner, the hypotenuse average misses the
    // offset planes: farther than d from the base, nearer to the walls.
    let hyp = moved[1].positions()[0] - p;
    assert!((hypotenuse - planes).length() > 0.7 * d);
    assert!(-hyp.z > 1.1 * d);
    assert!(hyp.dot(u) / 2.0 < 0.9 * d);
    // The diagonal moves less than d from every face's plane.
    let diagonal = moved[0].positions()[0] - p;
    for n in &normals_around(&prism)[0] {
        assert!(n.dot(diagonal) < 0.75 * d, "{n}");
    }
}

/// `mesh` without its face `f`.
fn without_face(mesh: &Mesh, f: usize) -> Mesh {
    let faces: Vec<&[u32]> = (0..mesh.face_count())
        .filter(|&g| g != f)
        .map(|g| mesh.face(g))
        .collect();
    Mesh::from_polygons(mesh.positions().to_vec(), faces).unwrap()
}

#[test]
fn thicken_with_each_offset_type_is_a_closed_solid_offset_by_d() {
    // The unit cube and the prism without their tops: 4 and 3 naked edges.
    let open_box = without_face(&shapes::cube(), 1);
    let open_prism = without_face(&triangular_prism(), 1);
    for (name, open, naked) in [("box", &open_box, 4), ("prism", &open_prism, 3)] {
        assert_eq!(info(open).naked_edge_count, naked);
        let (v, f) = (open.vertex_count(), open.face_count());
        for kind in [
            OffsetType::Diagonal,
            OffsetType::HypotenuseAverage,
            OffsetType::PlanesIntersection,
        ] {
            for d in [0.2, -0.2] {
                let what = format!("{name} {kind:?} d = {d}");
                let solid = thicken(open, d, kind).unwrap();
                // The surface, its offset, and a quad along each naked edge.
                assert_eq!(solid.vertex_count(), 2 * v, "{what}");
                assert_eq!(solid.face_count(), 2 * f + naked, "{what}");
                assert_eq!(
                    solid.index_count(),
                    2 * open.index_count() + 4 * naked,
                    "{what}"
                );
                let i = info(&solid);
                assert!(
                    i.is_closed && i.is_oriented && i.component_count == 1,
                    "{what}: {i:?}"
                );
                assert_eq!(i.non_manifold_vertex_count, 0, "{what}");
                assert!(volume(&solid) > 0.0, "{what}: faces outward");
                assert_eq!(&solid.positions()[..v], open.positions(), "{what}");
                let layer = &solid.positions()[v..];
                assert_eq!(layer, offset(open, d, kind).unwrap().positions(), "{what}");
                assert_offset_by(open, layer, d, kind);
            }
        }
    }
    let open = open_box;
    // Planes intersection keeps every wall d thick, the rim included: the
    // solid is the box grown (or shrunk) by d on every side but the top.
    for d in [0.2, -0.2] {
        let solid = thicken(&open, d, OffsetType::PlanesIntersection).unwrap();
        let side = 1.0 + 2.0 * d;
        let expected = (side * side * (1.0 + d) - 1.0).abs();
        assert!((volume(&solid) - expected).abs() < 1e-12, "d = {d}");
    }
}

#[test]
fn window_and_picture_frame_counts() {
    let cube = shapes::cube();
    let w = window(&cube, &[0.2], InsetMode::EdgeFraction).unwrap();
    assert_eq!((w.vertex_count(), w.face_count()), (32, 30));
    assert!(info(&w).is_closed && info(&w).is_oriented);
    assert!((area(&w) - 6.0).abs() < 1e-12);
    let frame = picture_frame(&cube, &[0.1; 6], InsetMode::Parallelogram).unwrap();
    assert_eq!(frame.face_count(), 24);
    assert_eq!(info(&frame).naked_edge_count, 24);
    // The parallelogram rule frames a unit square with constant width.
    let square = shapes::quad_grid(1, 1);
    let w = window(&square, &[0.1], InsetMode::Parallelogram).unwrap();
    for p in &w.positions()[4..] {
        for x in [p.x, p.y] {
            assert!((x - 0.1).abs() < 1e-12 || (x - 0.9).abs() < 1e-12);
        }
    }
    let err = window(&cube, &[0.1, 0.2], InsetMode::EdgeFraction).unwrap_err();
    let text = err.to_string();
    assert!(
        text.contains("2 distances") && text.contains("6 faces"),
        "{text}"
    );
    assert!(window(&cube, &[0.5], InsetMode::EdgeFraction).is_err());
}

#[test]
fn sierpinski_carpet_of_a_quad() {
    let quad = shapes::quad_grid(1, 1);
    let c = sierpinski_carpet(&quad, 1).unwrap();
    assert_eq!((c.vertex_count(), c.face_count()), (16, 8));
    assert!((area(&c) - 8.0 / 9.0).abs() < 1e-12);
    assert_eq!(info(&c).naked_edge_count, 16);
    let c2 = sierpinski_carpet(&shapes::quad_grid(2, 1), 2).unwrap();
    assert_eq!(c2.face_count(), 128);
    assert_eq!(info(&c2).component_count, 1);
    assert!(sierpinski_carpet(&shapes::tetrahedron(), 1).is_err());
}

#[test]
fn bevels_of_a_cube() {
    let cube = shapes::cube();
    let t = bevel_vertices(&cube, 0.25).unwrap();
    assert_eq!(t.vertex_count(), 24);
    assert_eq!((sizes_of(&t, 8), sizes_of(&t, 3)), (6, 8));
    assert!(info(&t).is_closed && info(&t).is_oriented);
    assert!(t.positions().iter().all(|&p| on_unit_cube(p)));
    let e = bevel_edges(&cube, 0.25).unwrap();
    assert_eq!((e.vertex_count(), e.face_count()), (24, 26));
    assert_eq!((sizes_of(&e, 4), sizes_of(&e, 3)), (18, 8));
    assert!(info(&e).is_closed && info(&e).is_oriented);
    assert!(bevel_vertices(&cube, 0.5).is_err());
}

#[test]
fn dual_of_a_cube_is_an_octahedron() {
    let d = dual(&shapes::cube(), DualMode::VertexAverage).unwrap();
    assert_eq!((d.vertex_count(), d.face_count()), (6, 8));
    assert!(d.is_triangle_mesh());
    assert!(info(&d).is_closed && info(&d).is_oriented);
    assert!(volume(&d) > 0.0);
    let ico = shapes::icosahedron();
    let dodeca = dual(&ico, DualMode::VertexAverage).unwrap();
    assert_eq!((dodeca.vertex_count(), dodeca.face_count()), (20, 12));
    let back = dual(&dodeca, DualMode::KeepSize).unwrap();
    assert_eq!((back.vertex_count(), back.face_count()), (12, 20));
    let ((lo, hi), (blo, bhi)) = (dodeca.bounding_box().unwrap(), back.bounding_box().unwrap());
    assert!(((lo + hi) - (blo + bhi)).length() < 1e-12);
    assert!(((hi - lo).length() - (bhi - blo).length()).abs() < 1e-12);
    // Only interior vertices of a grid get faces.
    let g = dual(&shapes::quad_grid(3, 3), DualMode::VertexAverage).unwrap();
    assert_eq!((g.vertex_count(), g.face_count()), (9, 4));
}

#[test]
fn edges_and_reroute() {
    let cube = shapes::cube();
    let edges = mesh_edges(&cube);
    assert_eq!(edges.len(), 12);
    let segments = edge_segments(&cube);
    assert!(segments.iter().all(|s| (s[0] - s[1]).length() == 1.0));
    let r = reroute_faces(&cube, 1);
    for f in 0..6 {
        let (a, b) = (cube.face(f), r.face(f));
        assert_eq!(b, &[a[1], a[2], a[3], a[0]]);
    }
    assert_eq!(reroute_faces(&r, -1), cube);
    assert_eq!(reroute_faces(&cube, 4), cube);
}

fn grid_lines(jitter: f64) -> Vec<[DVec3; 2]> {
    let mut segments = Vec::new();
    let p = |x: f64, y: f64, k: usize| DVec3::new(x + jitter * (k % 3) as f64, y, 0.0);
    for i in 0..3 {
        for j in 0..2 {
            let (i, j) = (i as f64, j as f64);
            segments.push([p(i, j, segments.len()), p(i, j + 1.0, segments.len() + 1)]);
            segments.push([p(j, i, segments.len()), p(j + 1.0, i, segments.len() + 1)]);
        }
    }
    segments
}

#[test]
fn mesh_from_lines_of_a_grid() {
    let m = mesh_from_lines(&grid_lines(0.0), 0.0, 4).unwrap();
    assert_eq!((m.vertex_count(), m.face_count()), (9, 4));
    assert!(m.is_quad_mesh());
    assert!(info(&m).is_oriented);
    assert!((0..4).all(|f| newell(&m, f).z > 0.0));
    // Welded within the tolerance.
    let m = mesh_from_lines(&grid_lines(1e-4), 1e-3, 4).unwrap();
    assert_eq!((m.vertex_count(), m.face_count()), (9, 4));
    // Faces above the maximum valence are left out.
    assert_eq!(
        mesh_from_lines(&grid_lines(0.0), 0.0, 3)
            .unwrap()
            .face_count(),
        0
    );
    // A dangling segment is ignored.
    let mut lines = grid_lines(0.0);
    lines.push([DVec3::new(1.0, 1.0, 0.0), DVec3::new(1.5, 1.4, 0.0)]);
    assert_eq!(mesh_from_lines(&lines, 0.0, 4).unwrap().face_count(), 4);
    let bad = [[DVec3::ZERO, DVec3::new(f64::NAN, 0.0, 0.0)]];
    let err = mesh_from_lines(&bad, 0.0, 4).unwrap_err();
    assert!(err.to_string().contains("segment 0"));
}

/// Every operation on every named shape, non-manifold and non-orientable
/// ones included: a valid mesh or a named error, never a panic.
#[test]
fn every_operation_survives_every_named_shape() {
    let named = [
        shapes::cube(),
        shapes::tetrahedron(),
        shapes::icosahedron(),
        shapes::torus(6, 4),
        shapes::triangle_torus(5, 4),
        shapes::quad_grid(3, 2),
        shapes::triangle_grid(2, 2),
        shapes::quad_grid_with_hole(),
        shapes::triangle_grid_with_hole(),
        shapes::mixed_polygons(),
        shapes::fin(),
        shapes::bow_tie(),
        shapes::mobius_strip(8),
        Mesh::empty(),
    ];
    let valid = |m: Mesh| {
        let (p, s, i) = m.into_parts();
        Mesh::new(p, s, i).expect("a valid result");
    };
    for mesh in &named {
        for level in 0..3 {
            valid(split_polygons(mesh, level).unwrap());
            valid(constant_quads_split(mesh, level).unwrap());
            valid(midedge(mesh, level).unwrap());
            valid(inner_polygons(mesh, level, 0.3).unwrap());
            valid(sierpinski_triangles(mesh, level).unwrap());
            if mesh.is_triangle_mesh() {
                valid(split_triangles(mesh, level).unwrap());
            }
            if mesh.is_quad_mesh() {
                valid(sierpinski_carpet(mesh, level).unwrap());
            }
        }
        for naked in [
            NakedEdges::Fixed,
            NakedEdges::Smooth,
            NakedEdges::CornerFixed,
        ] {
            valid(laplacian(mesh, 3, 0.5, naked).unwrap());
            valid(laplacian_hc(mesh, 3, 0.1, 0.6, naked).unwrap());
        }
        for kind in [
            OffsetType::Diagonal,
            OffsetType::HypotenuseAverage,
            OffsetType::PlanesIntersection,
        ] {
            valid(offset(mesh, 0.1, kind).unwrap());
            valid(thicken(mesh, -0.1, kind).unwrap());
        }
        for mode in [InsetMode::EdgeFraction, InsetMode::Parallelogram] {
            valid(window(mesh, &[0.1], mode).unwrap());
            valid(picture_frame(mesh, &[0.1], mode).unwrap());
        }
        valid(bevel_edges(mesh, 0.2).unwrap());
        valid(bevel_vertices(mesh, 0.2).unwrap());
        valid(dual(mesh, DualMode::KeepSize).unwrap());
        valid(reroute_faces(mesh, 2));
        let lines = edge_segments(mesh);
        valid(mesh_from_lines(&lines, 1e-9, 8).unwrap());
    }
}

#[test]
fn hc_activation_keeps_inactive_vertices_and_checks_its_length() {
    let sphere = jittered_sphere();
    let n = sphere.vertex_count();
    let mut weights = vec![1.0; n];
    for w in weights.iter_mut().step_by(3) {
        *w = 0.0;
    }
    let options = HcOptions {
        alpha: 0.0,
        beta: 0.6,
        naked: NakedEdges::Fixed,
        direction: SmoothDirection::Free,
        activation: Some(&weights),
    };
    let out = laplacian_hc_with(&sphere, 5, &options).unwrap();
    for v in 0..n {
        let moved = out.positions()[v] != sphere.positions()[v];
        assert_eq!(moved, v % 3 != 0, "vertex {v}");
    }
    // All ones is the plain algorithm, bit for bit.
    let ones = vec![1.0; n];
    let all = laplacian_hc_with(
        &sphere,
        5,
        &HcOptions {
            activation: Some(&ones),
            ..options
        },
    )
    .unwrap();
    let plain = laplacian_hc(&sphere, 5, 0.0, 0.6, NakedEdges::Fixed).unwrap();
    assert_eq!(all.positions(), plain.positions());
    let short = vec![1.0; n - 1];
    let message = laplacian_hc_with(
        &sphere,
        1,
        &HcOptions {
            activation: Some(&short),
            ..options
        },
    )
    .unwrap_err()
    .to_string();
    assert!(
        message.contains(&format!("{} values", n - 1))
            && message.contains(&format!("{n} vertices")),
        "{message}"
    );
    let mut bad = ones.clone();
    bad[7] = 1.5;
    let message = laplacian_hc_with(
        &sphere,
        1,
        &HcOptions {
            activation: Some(&bad),
            ..options
        },
    )
    .unwrap_err()
    .to_string();
    assert!(message.contains("vertex 7 is 1.5"), "{message}");
}

#[test]
fn hc_direction_keeps_vertices_on_their_normal_line_or_tangent_plane() {
    let sphere = jittered_sphere();
    let normals = weft::mesh::analysis::vertex_normals(&sphere);
    let run = |direction| {
        let options = HcOptions {
            alpha: 0.0,
            beta: 0.6,
            naked: NakedEdges::Fixed,
            direction,
            activation: None,
        };
        laplacian_hc_with(&sphere, 5, &options).unwrap()
    };
    let along = run(SmoothDirection::AlongNormal);
    let tangential = run(SmoothDirection::Tangential);
    let (mut moved_along, mut moved_tangent) = (0.0f64, 0.0f64);
    for (v, &n) in normals.iter().enumerate() {
        let o = sphere.positions()[v];
        let a = along.positions()[v] - o;
        assert!(
            a.cross(n).length() < 1e-12,
            "vertex {v} left its normal line"
        );
        let t = tangential.positions()[v] - o;
        assert!(t.dot(n).abs() < 1e-12, "vertex {v} left its tangent plane");
        moved_along = moved_along.max(a.length());
        moved_tangent = moved_tangent.max(t.length());
    }
    assert!(moved_along > 1e-3 && moved_tangent > 1e-3);
    // Along the normals the bumps flatten: the spread of the radii shrinks.
    let spread = |m: &Mesh| {
        let r: Vec<f64> = m.positions().iter().map(|p| p.length()).collect();
        r.iter().cloned().fold(f64::MIN, f64::max) - r.iter().cloned().fold(f64::MAX, f64::min)
    };
    assert!(spread(&along) < spread(&sphere) / 2.0);
}
