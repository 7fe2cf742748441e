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
