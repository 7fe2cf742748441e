//! Subdivision's counts, order, naked-edge modes, refiner and triangulation.

use weft::mesh::shapes;
use weft::mesh::triangulate::{as_triangles, triangulate};
use weft::subdivide::{
    catmull_clark, loop_subdivision, parent_faces, refined_counts, subdivide, NakedEdges, Refiner,
    Scheme,
};
use weft::{DVec3, Error, Mesh, Topology};

const MODES: [NakedEdges; 3] = [
    NakedEdges::Fixed,
    NakedEdges::Smooth,
    NakedEdges::CornerFixed,
];

fn euler(mesh: &Mesh) -> i64 {
    let edges = Topology::new(mesh).edge_count() as i64;
    mesh.vertex_count() as i64 - edges + mesh.face_count() as i64
}

#[test]
fn catmull_clark_counts_are_exact() {
    for cage in [
        shapes::cube(),
        shapes::mixed_polygons(),
        shapes::quad_grid_with_hole(),
        shapes::fin(),
    ] {
        let mut level = cage.clone();
        for levels in 1..=3 {
            let edges = Topology::new(&level).edge_count();
            let out = catmull_clark(&cage, levels, NakedEdges::Smooth).unwrap();
            assert_eq!(
                out.vertex_count(),
                level.vertex_count() + edges + level.face_count()
            );
            assert_eq!(out.face_count(), level.index_count());
            assert!(out.is_quad_mesh());
            let counts = refined_counts(&cage, Scheme::CatmullClark, levels).unwrap();
            assert_eq!(
                (counts.vertex_count, counts.face_count, counts.index_count),
                (out.vertex_count(), out.face_count(), out.index_count())
            );
            level = out;
        }
    }
}

#[test]
fn loop_counts_are_exact() {
    for cage in [
        shapes::icosahedron(),
        shapes::triangle_grid(3, 2),
        shapes::bow_tie(),
    ] {
        let edges = Topology::new(&cage).edge_count();
        let out = loop_subdivision(&cage, 1, NakedEdges::Smooth).unwrap();
        assert_eq!(out.vertex_count(), cage.vertex_count() + edges);
        assert_eq!(out.face_count(), 4 * cage.face_count());
        assert!(out.is_triangle_mesh());
        let three = loop_subdivision(&cage, 3, NakedEdges::Fixed).unwrap();
        assert_eq!(three.face_count(), 64 * cage.face_count());
        assert!(three.is_triangle_mesh());
    }
    // pmp's golden number: an icosahedron has 80 faces after one step.
    assert_eq!(
        loop_subdivision(&shapes::icosahedron(), 1, NakedEdges::Smooth)
            .unwrap()
            .face_count(),
        80
    );
}

#[test]
fn euler_characteristic_is_kept_on_closed_manifolds() {
    for (scheme, cage) in [
        (Scheme::CatmullClark, shapes::cube()),
        (Scheme::CatmullClark, shapes::torus(6, 4)),
        (Scheme::CatmullClark, shapes::mixed_polygons()),
        (Scheme::Loop, shapes::icosahedron()),
        (Scheme::Loop, shapes::triangle_torus(5, 3)),
    ] {
        let chi = euler(&cage);
        for levels in 1..=3 {
            let out = subdivide(&cage, scheme, levels, NakedEdges::Smooth).unwrap();
            assert_eq!(euler(&out), chi, "{scheme:?} level {levels}");
        }
    }
}

#[test]
fn output_order_is_as_documented() {
    let cage = shapes::mixed_polygons();
    let topology = Topology::new(&cage);
    let (v, e) = (cage.vertex_count() as u32, topology.edge_count() as u32);
    let out = catmull_clark(&cage, 1, NakedEdges::Smooth).unwrap();
    // Edge points in sorted-edge order: the point of edge [a, b] is V + e.
    let mut child = 0;
    for (f, face) in cage.faces().enumerate() {
        for (i, &corner) in face.iter().enumerate() {
            let next = face[(i + 1) % face.len()];
            let previous = face[(i + face.len() - 1) % face.len()];
            let edge = |a, b| v + topology.find_edge(a, b).unwrap() as u32;
            assert_eq!(
                out.face(child),
                &[
                    corner,
                    edge(corner, next),
                    v + e + f as u32,
                    edge(previous, corner)
                ]
            );
            child += 1;
        }
    }
    // Face points are centroids, after the edge points.
    let centroid = cage.face_positions(0).sum::<DVec3>() / 6.0;
    assert!((out.positions()[(v + e) as usize] - centroid).length() < 1e-15);

    let tri = shapes::tetrahedron();
    let topology = Topology::new(&tri);
    let out = loop_subdivision(&tri, 1, NakedEdges::Smooth).unwrap();
    for (f, face) in tri.faces().enumerate() {
        let edge = |i: usize| 4 + topology.find_edge(face[i], face[(i + 1) % 3]).unwrap() as u32;
        assert_eq!(out.face(4 * f), &[face[0], edge(0), edge(2)]);
        assert_eq!(out.face(4 * f + 1), &[face[1], edge(1), edge(0)]);
        assert_eq!(out.face(4 * f + 3), &[edge(0), edge(1), edge(2)]);
    }
}

#[test]
fn parent_faces_follow_the_children() {
    let cage = shapes::mixed_polygons();
    let parents = parent_faces(&cage, Scheme::CatmullClark, 2).unwrap();
    let out = catmull_clark(&cage, 2, NakedEdges::Fixed).unwrap();
    assert_eq!(parents.len(), out.face_count());
    // The first face (a hexagon) makes 6 quads, then 24 at level 2.
    assert!(parents[..24].iter().all(|&p| p == 0));
    assert_eq!(parents[24], 1);
    // Every level-2 face lies inside (or on) its cage face's bounding box.
    for (f, &p) in parents.iter().enumerate() {
        let (lo, hi) = cage
            .face_positions(p as usize)
            .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(l, h), q| {
                (l.min(q), h.max(q))
            });
        let centre = out.face_positions(f).sum::<DVec3>() / 4.0;
        assert!(centre.cmpge(lo - 0.3).all() && centre.cmple(hi + 0.3).all());
    }
    let parents = parent_faces(&shapes::icosahedron(), Scheme::Loop, 2).unwrap();
    assert_eq!(parents.len(), 320);
    assert_eq!((parents[15], parents[16]), (0, 1));
}

/// Whether `p` lies on one of `cage`'s naked edges.
fn on_naked_polyline(p: DVec3, cage: &Mesh) -> bool {
    let topology = Topology::new(cage);
    topology.naked_edges().iter().any(|&e| {
        let [a, b] = topology.edges()[e as usize];
        let (a, b) = (cage.positions()[a as usize], cage.positions()[b as usize]);
        let t = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
        (a + (b - a) * t).distance(p) < 1e-12
    })
}

/// A 3 × 3 grid bent out of its plane, so that smoothing moves its border.
fn bent_grid() -> Mesh {
    let grid = shapes::quad_grid(3, 3);
    let positions = grid
        .positions()
        .iter()
        .map(|p| DVec3::new(p.x, p.y, 0.2 * (p.x - 1.3).powi(2) + 0.1 * p.x * p.y))
        .collect();
    grid.with_positions(positions).unwrap()
}

#[test]
fn fixed_keeps_the_boundary_polyline() {
    let bent = bent_grid();
    for (scheme, cage) in [
        (Scheme::CatmullClark, bent.clone()),
        (Scheme::Loop, triangulate(&bent).unwrap().mesh),
    ] {
        let boundary = Topology::new(&cage).boundary_vertices();
        for levels in 1..=3 {
            let out = subdivide(&cage, scheme, levels, NakedEdges::Fixed).unwrap();
            for (v, &on) in boundary.iter().enumerate() {
                if on {
                    assert_eq!(out.positions()[v], cage.positions()[v], "vertex {v} moved");
                }
            }
            let out_boundary = Topology::new(&out).boundary_vertices();
            for (v, &on) in out_boundary.iter().enumerate() {
                if on {
                    assert!(
                        on_naked_polyline(out.positions()[v], &cage),
                        "{scheme:?} level {levels}: boundary vertex {v} left the polyline"
                    );
                }
            }
        }
    }
}

#[test]
fn corner_fixed_keeps_one_face_corners_and_smooth_moves_them() {
    let grid = bent_grid();
    let corners = [0usize, 3, 12, 15]; // one face each
    for (scheme, cage) in [
        (Scheme::CatmullClark, grid.clone()),
        (Scheme::Loop, triangulate(&grid).unwrap().mesh),
    ] {
        let fixed = subdivide(&cage, scheme, 2, NakedEdges::CornerFixed).unwrap();
        let smooth = subdivide(&cage, scheme, 2, NakedEdges::Smooth).unwrap();
        for v in corners {
            let faces = Topology::new(&cage).vertex_corners(v).len();
            if faces == 1 {
                assert_eq!(fixed.positions()[v], cage.positions()[v]);
                assert_ne!(smooth.positions()[v], cage.positions()[v]);
            }
        }
        // The boundary vertex in the middle of a side moves in both modes.
        let side = 1;
        assert_ne!(fixed.positions()[side], cage.positions()[side]);
    }
    // Smooth: a one-face corner moves by the B-spline rule 3/4 v + 1/8 (a + b).
    let smooth = catmull_clark(&shapes::quad_grid(3, 3), 1, NakedEdges::Smooth).unwrap();
    let expected = DVec3::new(1.0, 1.0, 0.0) * 0.125;
    assert!((smooth.positions()[0] - expected).length() < 1e-15);
}

#[test]
fn holes_come_out_rounded_or_keep_their_polyline() {
    let cage = shapes::quad_grid_with_hole();
    // The hole is the square [1,3]²; its corner (1,1) is vertex 6.
    let hole_corner = 6;
    let smooth = catmull_clark(&cage, 3, NakedEdges::Smooth).unwrap();
    let fixed = catmull_clark(&cage, 3, NakedEdges::Fixed).unwrap();
    assert_eq!(fixed.positions()[hole_corner], DVec3::new(1.0, 1.0, 0.0));
    let rounded = smooth.positions()[hole_corner];
    assert!(rounded.x > 1.05 && rounded.y > 1.05, "{rounded}");
    // Every smooth hole-boundary vertex lies off the square's corners: rounded.
    let on_hole = |p: DVec3| (p.x - 2.0).abs().max((p.y - 2.0).abs());
    let boundary = Topology::new(&smooth).boundary_vertices();
    let hole_points: Vec<DVec3> = boundary
        .iter()
        .enumerate()
        .filter(|&(v, &b)| b && on_hole(smooth.positions()[v]) < 1.5)
        .map(|(v, _)| smooth.positions()[v])
        .collect();
    assert!(!hole_points.is_empty());
    // Inside the square, and away from its corners: the corners are cut round.
    let corners =
        [(1.0, 1.0), (3.0, 1.0), (3.0, 3.0), (1.0, 3.0)].map(|(x, y)| DVec3::new(x, y, 0.0));
    for p in &hole_points {
        assert!(on_hole(*p) <= 1.0 + 1e-12, "{p}");
        assert!(
            corners.iter().all(|c| c.distance(*p) > 0.1),
            "{p} is at a sharp corner"
        );
    }
    let fixed_boundary = Topology::new(&fixed).boundary_vertices();
    for (v, &b) in fixed_boundary.iter().enumerate() {
        let p = fixed.positions()[v];
        if b && on_hole(p) < 1.5 {
            assert!(
                (on_hole(p) - 1.0).abs() < 1e-12,
                "vertex {v} at {p} left the hole's polyline"
            );
        }
    }
}

#[test]
fn loop_refuses_quads_naming_the_face() {
    let err = loop_subdivision(&shapes::mixed_polygons(), 1, NakedEdges::Smooth).unwrap_err();
    assert_eq!(err, Error::NotTriangles { face: 0, size: 6 });
    assert!(err.to_string().contains("triangulate"));
    let triangles = triangulate(&shapes::mixed_polygons()).unwrap();
    assert!(loop_subdivision(&triangles.mesh, 2, NakedEdges::Smooth).is_ok());
}

#[test]
fn too_many_levels_is_an_error_not_an_abort() {
    let start = std::time::Instant::now();
    let err = catmull_clark(&shapes::cube(), 16, NakedEdges::Smooth).unwrap_err();
    assert!(matches!(err, Error::ResultTooLarge(_)));
    // The sentence says how many levels were asked for, which one passes
    // the cap, and how many would fit.
    let message = err.to_string();
    assert!(
        message.contains("16 levels of subdivision: level 14 would make 1610612736 faces"),
        "{message}"
    );
    assert!(message.contains("use at most 13 levels"), "{message}");
    // Level 13 is indeed within the cap (counted, not built).
    let counts = refined_counts(&shapes::cube(), Scheme::CatmullClark, 13).unwrap();
    assert_eq!(counts.face_count, 6 * 4usize.pow(13));
    let err = loop_subdivision(&shapes::icosahedron(), u32::MAX, NakedEdges::Smooth).unwrap_err();
    assert!(matches!(err, Error::ResultTooLarge(_)));
    assert!(
        err.to_string()
            .contains("4294967295 levels of subdivision: level 13 would make 1342177280 faces"),
        "{err}"
    );
    assert!(start.elapsed().as_secs() < 2);
}

#[test]
fn non_manifold_input_keeps_every_face() {
    for cage in [shapes::fin(), shapes::bow_tie(), shapes::mobius_strip(8)] {
        for mode in MODES {
            let out = catmull_clark(&cage, 2, mode).unwrap();
            assert_eq!(out.face_count(), 4 * cage.index_count());
            assert!(out.positions().iter().all(|p| p.is_finite()));
        }
    }
}

/// `cage` with `count` more vertices that no face uses, after its own.
fn with_unused_vertices(cage: &Mesh, count: usize) -> Mesh {
    let mut positions = cage.positions().to_vec();
    positions.extend((0..count).map(|i| DVec3::new(i as f64, 0.5, -2.0)));
    Mesh::from_polygons(positions, cage.faces()).unwrap()
}

/// `cage` with its vertices and faces numbered in a scrambled order (and
/// each face's corners turned), so that no neighbourhood is numbered near
/// its neighbours.
fn scrambled(cage: &Mesh, seed: u64) -> Mesh {
    let mut state = seed;
    let mut next = move |n: usize| {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 33) % n as u64) as usize
    };
    let mut order: Vec<usize> = (0..cage.vertex_count()).collect();
    for i in (1..order.len()).rev() {
        order.swap(i, next(i + 1));
    }
    // Vertex `order[k]` becomes vertex k.
    let mut renumbered = vec![0u32; order.len()];
    for (k, &v) in order.iter().enumerate() {
        renumbered[v] = k as u32;
    }
    let positions = order.iter().map(|&v| cage.positions()[v]).collect();
    let mut faces: Vec<Vec<u32>> = cage
        .faces()
        .map(|face| face.iter().map(|&v| renumbered[v as usize]).collect())
        .collect();
    for i in (1..faces.len()).rev() {
        let j = next(i + 1);
        faces.swap(i, j);
        let turn = next(faces[i].len());
        faces[i].rotate_left(turn);
    }
    Mesh::from_polygons(positions, faces).unwrap()
}

#[test]
fn refiner_evaluate_equals_one_shot_on_large_levels() {
    // 18,432 quads: level 1 has 73,728 faces, enough for a refiner made
    // on two threads to make level 3 in three bands (16,384 parent faces a
    // thread); the seam's groups read the last band's face points, and in
    // the scrambled copy most groups read far away.
    // The triangle torus: every vertex has six neighbours, whose rings the
    // refiner sums unrolled.
    let torus = shapes::torus(144, 128);
    let triangles = shapes::triangle_torus(48, 32);
    let cages = [
        (Scheme::CatmullClark, torus.clone()),
        (Scheme::CatmullClark, scrambled(&torus, 7)),
        (Scheme::Loop, triangles.clone()),
        (Scheme::Loop, scrambled(&triangles, 7)),
    ];
    let two_threads = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    for (scheme, cage) in cages {
        let refiner = two_threads
            .install(|| Refiner::new(&cage, scheme, 3, NakedEdges::Smooth))
            .unwrap();
        let moved: Vec<DVec3> = cage
            .positions()
            .iter()
            .map(|p| *p * 1.5 + DVec3::new(p.y * p.z, 0.25, -p.x))
            .collect();
        let mut out = vec![DVec3::ZERO; refiner.vertex_count()];
        refiner.evaluate(&moved, &mut out).unwrap();
        let moved_cage = cage.with_positions(moved).unwrap();
        let expected = subdivide(&moved_cage, scheme, 3, NakedEdges::Smooth).unwrap();
        assert_eq!(out, expected.positions());
        assert_eq!(refiner.face_indices(), expected.face_indices());
    }
}

#[test]
fn refiner_evaluate_equals_one_shot() {
    let cage = shapes::mixed_polygons();
    let triangles = triangulate(&cage).unwrap().mesh;
    // One-shot keeps the points of the level before the last in the last
    // level's index buffer where they fit; with many unused vertices they
    // do not, and go to a buffer of their own.
    for (scheme, cage) in [
        (Scheme::CatmullClark, cage.clone()),
        (Scheme::Loop, triangles.clone()),
        (Scheme::CatmullClark, with_unused_vertices(&cage, 2000)),
        (Scheme::Loop, with_unused_vertices(&triangles, 2000)),
    ] {
        for mode in MODES {
            for levels in 0..=3 {
                let refiner = Refiner::new(&cage, scheme, levels, mode).unwrap();
                let one_shot = subdivide(&cage, scheme, levels, mode).unwrap();
                assert_eq!(refiner.mesh().unwrap(), one_shot);
                // New positions: the same faces, the positions of a one-shot run.
                let moved: Vec<DVec3> = cage
                    .positions()
                    .iter()
                    .map(|p| *p * 2.0 + DVec3::new(0.0, p.x * p.x, 1.0))
                    .collect();
                let mut out = vec![DVec3::ZERO; refiner.vertex_count()];
                refiner.evaluate(&moved, &mut out).unwrap();
                let expected =
                    subdivide(&cage.with_positions(moved).unwrap(), scheme, levels, mode).unwrap();
                assert_eq!(out, expected.positions());
                assert_eq!(refiner.face_indices(), expected.face_indices());
            }
        }
    }
    let refiner =
        Refiner::new(&shapes::cube(), Scheme::CatmullClark, 2, NakedEdges::Fixed).unwrap();
    let mut out = vec![DVec3::ZERO; refiner.vertex_count()];
    assert!(matches!(
        refiner.evaluate(&[DVec3::ZERO; 3], &mut out),
        Err(Error::InvalidArgument(_))
    ));
}

#[test]
fn triangulate_keeps_area_and_maps_parents() {
    let cage = shapes::quad_grid_with_hole();
    let t = triangulate(&cage).unwrap();
    assert_eq!(t.mesh.face_count(), 2 * cage.face_count());
    assert_eq!(t.parent_faces.len(), t.mesh.face_count());
    assert_eq!(&t.parent_faces[..4], &[0, 0, 1, 1]);
    let area = |m: &Mesh| -> f64 {
        m.faces()
            .map(|f| {
                let p: Vec<DVec3> = f.iter().map(|&v| m.positions()[v as usize]).collect();
                (1..p.len() - 1)
                    .map(|i| (p[i] - p[0]).cross(p[i + 1] - p[0]))
                    .sum::<DVec3>()
                    .length()
                    / 2.0
            })
            .sum()
    };
    assert!((area(&t.mesh) - 12.0).abs() < 1e-12);
    // A concave L-shaped hexagon: 4 triangles, area 3.
    let l_shape = shapes::l_shaped_hexagon(0.5);
    let t = triangulate(&l_shape).unwrap();
    assert_eq!(t.mesh.face_count(), 4);
    assert!((area(&t.mesh) - 3.0).abs() < 1e-12);
    // Triangles come through unchanged.
    let tri = shapes::icosahedron();
    assert_eq!(triangulate(&tri).unwrap().mesh, tri);
}

#[test]
fn as_triangles_copies_a_triangle_mesh_and_triangulates_any_other() {
    let icosahedron = shapes::icosahedron();
    let (copy, split) = as_triangles(&icosahedron).unwrap();
    assert_eq!(split, 0);
    assert_eq!(copy.mesh, icosahedron);
    assert_eq!(
        copy.parent_faces,
        (0..icosahedron.face_count() as u32).collect::<Vec<_>>()
    );

    let mixed = shapes::mixed_polygons();
    let (triangles, split) = as_triangles(&mixed).unwrap();
    let not_triangles = mixed.face_sizes().iter().filter(|&&s| s != 3).count();
    assert!(not_triangles > 0);
    assert_eq!(split, not_triangles);
    assert_eq!(triangles, triangulate(&mixed).unwrap());
    assert!(triangles.mesh.is_triangle_mesh());
}
