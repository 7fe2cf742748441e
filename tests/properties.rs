//! Property tests on random meshes: the invariants that must hold whatever
//! the input, checked on hundreds of generated cases.

use proptest::prelude::*;
use weft::{shapes, DVec3, Mesh, Topology};

/// A random closed, oriented manifold of known genus: a torus or a sphere-like
/// box of random resolution, jittered, with random quads split into triangles
/// and random pairs of neighbouring quads merged into hexagons.
fn closed_mesh() -> impl Strategy<Value = (Mesh, i64)> {
    (3usize..9, 3usize..7, any::<u64>(), prop::bool::ANY).prop_map(|(u, v, seed, torus)| {
        let (base, euler) = if torus {
            (shapes::torus(u, v), 0)
        } else {
            (box_mesh(v), 2)
        };
        (remix(&base, seed), euler)
    })
}

/// A box of `n × n` quads on each side, its six grids sharing vertices by position.
fn box_mesh(n: usize) -> Mesh {
    // A quad-sphere: the cube's faces subdivided linearly, shared vertices by position.
    let mut positions: Vec<DVec3> = Vec::new();
    let mut faces = Vec::new();
    let mut index_of = std::collections::HashMap::new();
    let mut id = |p: DVec3, positions: &mut Vec<DVec3>| {
        let key = (p * 1e6).round().to_array().map(|c| c as i64);
        *index_of.entry(key).or_insert_with(|| {
            positions.push(p);
            positions.len() as u32 - 1
        })
    };
    let axes = [
        (DVec3::X, DVec3::Y, DVec3::Z),
        (DVec3::Y, DVec3::Z, DVec3::X),
        (DVec3::Z, DVec3::X, DVec3::Y),
    ];
    for (a, b, normal) in axes {
        for side in [-1.0, 1.0] {
            let (a, b) = if side > 0.0 { (a, b) } else { (b, a) };
            let counts = (n, n);
            for i in 0..counts.0 {
                for j in 0..counts.1 {
                    let corner = |di: usize, dj: usize| {
                        let s = 2.0 * (i + di) as f64 / counts.0 as f64 - 1.0;
                        let t = 2.0 * (j + dj) as f64 / counts.1 as f64 - 1.0;
                        normal * side + a * s + b * t
                    };
                    let quad = [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)];
                    faces.push(quad.map(|p| id(p, &mut positions)).to_vec());
                }
            }
        }
    }
    Mesh::from_polygons(positions, faces).unwrap()
}

/// Jitters the positions and changes some faces' shapes without changing the surface's topology.
fn remix(mesh: &Mesh, seed: u64) -> Mesh {
    let mut state = seed | 1;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    let positions: Vec<DVec3> = mesh
        .positions()
        .iter()
        .map(|&p| p + DVec3::new(jitter(next()), jitter(next()), jitter(next())))
        .collect();
    let mut faces: Vec<Vec<u32>> = Vec::new();
    for face in mesh.faces() {
        if face.len() == 4 && next() % 3 == 0 {
            faces.push(vec![face[0], face[1], face[2]]);
            faces.push(vec![face[0], face[2], face[3]]);
        } else {
            faces.push(face.to_vec());
        }
    }
    Mesh::from_polygons(positions, faces).unwrap()
}

fn jitter(bits: u64) -> f64 {
    ((bits % 1000) as f64 / 1000.0 - 0.5) * 0.01
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn topology_of_closed_meshes_is_consistent((mesh, euler) in closed_mesh()) {
        let topology = Topology::new(&mesh);
        let info = topology.info(&mesh);
        prop_assert!(info.is_closed && info.is_orientable && info.is_oriented);
        prop_assert_eq!(info.component_count, 1);
        prop_assert_eq!(info.non_manifold_vertex_count, 0);
        prop_assert_eq!(
            info.vertex_count as i64 - info.edge_count as i64 + info.face_count as i64,
            euler
        );
        // Every corner's edge joins that corner's vertex and the next one.
        let corners = topology.corner_vertices();
        for (c, &e) in topology.corner_edges().iter().enumerate() {
            let [a, b] = topology.edges()[e as usize];
            let (u, v) = (corners[c], corners[topology.corner_next()[c] as usize]);
            prop_assert_eq!((a, b), (u.min(v), u.max(v)));
        }
        let uses: usize = (0..topology.edge_count()).map(|e| topology.edge_face_count(e)).sum();
        prop_assert_eq!(uses, mesh.index_count());
    }

    #[test]
    fn reversing_random_faces_keeps_orientability((mesh, _) in closed_mesh(), pick in any::<u64>()) {
        let faces: Vec<Vec<u32>> = mesh
            .faces()
            .enumerate()
            .map(|(f, face)| {
                let mut face = face.to_vec();
                if (pick >> (f % 64)) & 1 == 1 {
                    face.reverse();
                }
                face
            })
            .collect();
        let flipped = Mesh::from_polygons(mesh.positions().to_vec(), faces).unwrap();
        let topology = Topology::new(&flipped);
        let orientation = topology.orientation();
        prop_assert!(orientation.component_orientable.iter().all(|&o| o));
        // Applying the flips found makes every manifold edge consistent.
        let unified: Vec<Vec<u32>> = flipped
            .faces()
            .zip(&orientation.face_flip)
            .map(|(face, &flip)| {
                let mut face = face.to_vec();
                if flip {
                    face.reverse();
                }
                face
            })
            .collect();
        let unified = Mesh::from_polygons(flipped.positions().to_vec(), unified).unwrap();
        prop_assert!(Topology::new(&unified).info(&unified).is_oriented);
    }

    #[test]
    fn flat_buffers_round_trip((mesh, _) in closed_mesh()) {
        let flat: Vec<f64> = mesh.positions().iter().flat_map(|p| p.to_array()).collect();
        let again = Mesh::from_flat(&flat, mesh.face_sizes(), mesh.face_indices()).unwrap();
        prop_assert_eq!(again, mesh);
    }
}

mod operations {
    use super::*;
    use weft::cull::cull_adjacent;
    use weft::orient::{flip, signed_volume, unify_orientation};
    use weft::subdivide::{catmull_clark, loop_subdivision, NakedEdges};
    use weft::triangulate::triangulate;
    use weft::weld::{join, weld};

    fn euler(mesh: &Mesh) -> i64 {
        let info = Topology::new(mesh).info(mesh);
        info.vertex_count as i64 - info.edge_count as i64 + info.face_count as i64
    }

    /// Every face gets its own copies of its vertices: the mesh falls apart into loose polygons.
    fn unweld(mesh: &Mesh) -> Mesh {
        let mut positions = Vec::new();
        let mut faces = Vec::new();
        for face in mesh.faces() {
            let start = positions.len() as u32;
            positions.extend(face.iter().map(|&v| mesh.positions()[v as usize]));
            faces.push((start..start + face.len() as u32).collect::<Vec<_>>());
        }
        Mesh::from_polygons(positions, faces).unwrap()
    }

    /// A staircase of unit boxes: column (i, j) is `heights[i][j]` boxes tall,
    /// heights never growing away from the origin, so the solid's surface is a
    /// manifold sphere. Returns the loose boxes and the number of exposed faces.
    fn staircase(seed: u64, n: usize) -> (Vec<Mesh>, usize) {
        let mut state = seed | 1;
        let mut next = move |bound: u64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state % bound
        };
        let mut heights = vec![vec![0usize; n]; n];
        for i in 0..n {
            for j in 0..n {
                let cap = match (i, j) {
                    (0, 0) => 4,
                    (0, _) => heights[0][j - 1],
                    (_, 0) => heights[i - 1][0],
                    _ => heights[i - 1][j].min(heights[i][j - 1]),
                };
                heights[i][j] = if (i, j) == (0, 0) {
                    1 + next(4) as usize
                } else {
                    next(cap as u64 + 1) as usize
                };
            }
        }
        let filled = |i: i64, j: i64, k: i64| {
            i >= 0
                && j >= 0
                && k >= 0
                && (i as usize) < n
                && (j as usize) < n
                && (k as usize) < heights[i as usize][j as usize]
        };
        let mut boxes = Vec::new();
        let mut exposed = 0;
        for i in 0..n as i64 {
            for j in 0..n as i64 {
                for k in 0..heights[i as usize][j as usize] as i64 {
                    let offset = DVec3::new(i as f64, j as f64, k as f64);
                    let cube = shapes::cube();
                    let moved = cube.positions().iter().map(|&p| p + offset).collect();
                    boxes.push(cube.with_positions(moved).unwrap());
                    for (di, dj, dk) in [
                        (1, 0, 0),
                        (-1, 0, 0),
                        (0, 1, 0),
                        (0, -1, 0),
                        (0, 0, 1),
                        (0, 0, -1),
                    ] {
                        if !filled(i + di, j + dj, k + dk) {
                            exposed += 1;
                        }
                    }
                }
            }
        }
        (boxes, exposed)
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 32, failure_persistence: None, ..ProptestConfig::default() })]

        #[test]
        fn subdivision_makes_the_predicted_counts_and_keeps_euler((mesh, chi) in closed_mesh(), levels in 1u32..3) {
            let topology = Topology::new(&mesh);
            let smooth = catmull_clark(&mesh, levels, NakedEdges::Smooth).unwrap();
            let first = catmull_clark(&mesh, 1, NakedEdges::Smooth).unwrap();
            prop_assert_eq!(first.vertex_count(), mesh.vertex_count() + topology.edge_count() + mesh.face_count());
            prop_assert_eq!(first.face_count(), mesh.index_count());
            prop_assert!(smooth.is_quad_mesh());
            prop_assert_eq!(euler(&smooth), chi);

            let triangles = triangulate(&mesh).unwrap().mesh;
            let t = Topology::new(&triangles);
            let looped = loop_subdivision(&triangles, 1, NakedEdges::Smooth).unwrap();
            prop_assert_eq!(looped.vertex_count(), triangles.vertex_count() + t.edge_count());
            prop_assert_eq!(looped.face_count(), 4 * triangles.face_count());
            prop_assert!(looped.is_triangle_mesh());
            prop_assert_eq!(euler(&looped), chi);
        }

        #[test]
        fn weld_restores_loose_faces_and_is_idempotent((mesh, _) in closed_mesh()) {
            let loose = unweld(&mesh);
            let (welded, report) = weld(&loose, 1e-6).unwrap();
            prop_assert!(welded.vertex_count() <= loose.vertex_count());
            prop_assert!(welded.face_count() <= loose.face_count());
            prop_assert_eq!(welded.vertex_count(), mesh.vertex_count());
            prop_assert_eq!(welded.face_count(), mesh.face_count());
            prop_assert_eq!(report.removed_face_count, 0);
            prop_assert_eq!(Topology::new(&welded).info(&welded), Topology::new(&mesh).info(&mesh));
            let (again, second) = weld(&welded, 1e-6).unwrap();
            prop_assert_eq!(&again, &welded);
            prop_assert_eq!(second.merged_vertex_count, 0);
        }

        #[test]
        fn culled_box_staircases_are_closed_manifolds(seed in any::<u64>(), n in 1usize..4) {
            let (boxes, exposed) = staircase(seed, n);
            let refs: Vec<&Mesh> = boxes.iter().collect();
            let (welded, _) = weld(&join(&refs).unwrap(), 1e-9).unwrap();
            let (culled, removed) = cull_adjacent(&welded);
            prop_assert_eq!(culled.face_count(), exposed);
            prop_assert_eq!(removed, 6 * boxes.len() - exposed);
            let (skin, _) = weld(&culled, 1e-9).unwrap();
            let info = Topology::new(&skin).info(&skin);
            prop_assert!(info.is_closed && info.is_oriented, "{:?}", info);
            prop_assert_eq!(info.non_manifold_edge_count + info.non_manifold_vertex_count, 0);
            prop_assert_eq!(info.component_count, 1);
            prop_assert_eq!(euler(&skin), 2);
            prop_assert!(signed_volume(&skin) > 0.0);
        }

        #[test]
        fn flip_twice_is_the_identity((mesh, _) in closed_mesh()) {
            let once = flip(&mesh);
            prop_assert_ne!(&once, &mesh);
            prop_assert_eq!(flip(&once), mesh);
        }

        #[test]
        fn unify_makes_every_manifold_edge_consistent_and_faces_out((mesh, _) in closed_mesh(), pick in any::<u64>()) {
            let faces: Vec<Vec<u32>> = mesh
                .faces()
                .enumerate()
                .map(|(f, face)| {
                    let mut face = face.to_vec();
                    if (pick >> (f % 64)) & 1 == 1 {
                        face.reverse();
                    }
                    face
                })
                .collect();
            let scrambled = Mesh::from_polygons(mesh.positions().to_vec(), faces).unwrap();
            let (unified, flipped) = unify_orientation(&scrambled);
            prop_assert!(flipped <= scrambled.face_count());
            prop_assert!(Topology::new(&unified).info(&unified).is_oriented);
            prop_assert!(signed_volume(&unified) > 0.0);
        }

        #[test]
        fn triangulation_keeps_the_area_of_planar_convex_faces(angles in prop::collection::vec(0.0f64..std::f64::consts::TAU, 3..12), radius in 0.1f64..100.0) {
            let mut angles = angles;
            angles.sort_by(f64::total_cmp);
            angles.dedup_by(|a, b| (*a - *b).abs() < 1e-3);
            prop_assume!(angles.len() >= 3);
            let positions: Vec<DVec3> = angles.iter().map(|a| DVec3::new(a.cos(), a.sin(), 0.0) * radius).collect();
            let polygon: Vec<u32> = (0..positions.len() as u32).collect();
            let area = |mesh: &Mesh| -> f64 {
                mesh.faces()
                    .map(|f| {
                        let p: Vec<DVec3> = f.iter().map(|&v| mesh.positions()[v as usize]).collect();
                        (1..p.len() - 1).map(|i| (p[i] - p[0]).cross(p[i + 1] - p[0]).z / 2.0).sum::<f64>()
                    })
                    .sum()
            };
            let mesh = Mesh::from_polygons(positions, [polygon]).unwrap();
            let triangles = triangulate(&mesh).unwrap().mesh;
            prop_assert!(triangles.is_triangle_mesh());
            prop_assert_eq!(triangles.face_count(), mesh.vertex_count() - 2);
            prop_assert!((area(&triangles) - area(&mesh)).abs() <= 1e-9 * area(&mesh));
            // No triangle is flipped: each has positive area on its own.
            for f in 0..triangles.face_count() {
                let p: Vec<DVec3> = triangles.face_positions(f).collect();
                prop_assert!((p[1] - p[0]).cross(p[2] - p[0]).z > 0.0);
            }
        }
    }
}
