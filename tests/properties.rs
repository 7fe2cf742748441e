//! Property tests on random meshes: the invariants that must hold whatever
//! the input, checked on hundreds of generated cases.
//!
//! The generators are deterministic functions of the values proptest draws
//! (a seed drives the jitter and the face changes), so a failing case shrinks
//! and can be kept: a case worth keeping becomes a named test below, with
//! its mesh in a file next to this one.

use std::collections::{HashMap, HashSet};

use proptest::prelude::*;
use proptest::test_runner::{RngAlgorithm, TestRng};
use weft::mesh::shapes;
use weft::{DVec3, Mesh, Topology};

/// A random closed, oriented manifold of known Euler characteristic: a torus
/// or a sphere-like box of random resolution, jittered, with random quads
/// split into triangles.
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

/// A [`closed_mesh`] with random pairs of neighbouring faces merged into one
/// polygon: triangles, quads, pentagons (a triangle and a quad) and hexagons
/// (two quads) mixed. The surface and its Euler characteristic stay.
fn polygon_mesh() -> impl Strategy<Value = (Mesh, i64)> {
    (closed_mesh(), any::<u64>())
        .prop_map(|((mesh, euler), seed)| (merge_pairs(&mesh, seed), euler))
}

/// An open mesh to weld: a [`polygon_mesh`] with random faces removed, random
/// faces given their own copies of their vertices, every coordinate moved by
/// a random amount up to a random `spread` (0: the copies are exact
/// duplicates), and a random tolerance from 0 to beyond the shortest edges.
fn open_mesh() -> impl Strategy<Value = (Mesh, f64)> {
    (
        polygon_mesh(),
        any::<u64>(),
        prop_oneof![Just(0.0), 0.0f64..0.05, 0.0f64..0.3],
        prop_oneof![Just(0.0), 0.0f64..0.02, 0.0f64..0.4],
    )
        .prop_map(|((mesh, _), seed, spread, tolerance)| {
            let mut next = seeded_words(seed);
            let mut positions = mesh.positions().to_vec();
            let mut faces = Vec::new();
            for face in mesh.faces() {
                match next() % 4 {
                    0 => continue,
                    1 => {
                        let start = positions.len() as u32;
                        let copies: Vec<DVec3> =
                            face.iter().map(|&v| positions[v as usize]).collect();
                        positions.extend(copies);
                        faces.push((start..start + face.len() as u32).collect::<Vec<_>>());
                    }
                    _ => faces.push(face.to_vec()),
                }
            }
            if faces.is_empty() {
                faces.push(mesh.face(0).to_vec());
            }
            for p in &mut positions {
                let unit = DVec3::new(unit(next()), unit(next()), unit(next())) - 0.5;
                *p += unit * 2.0 * spread;
            }
            (Mesh::from_polygons(positions, faces).unwrap(), tolerance)
        })
}

/// Words from proptest's own seeded generator: the generators' only source
/// of randomness besides proptest's values.
fn seeded_words(seed: u64) -> impl FnMut() -> u64 {
    let bytes = [seed.to_le_bytes(), (!seed).to_le_bytes()].concat();
    let mut rng = TestRng::from_seed(RngAlgorithm::XorShift, &bytes);
    move || rng.next_u64()
}

/// A number in [0, 1) from random bits.
fn unit(bits: u64) -> f64 {
    (bits >> 11) as f64 / (1u64 << 53) as f64
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

/// Jitters the positions and splits some quads into triangles, without
/// changing the surface's topology.
fn remix(mesh: &Mesh, seed: u64) -> Mesh {
    let mut next = seeded_words(seed);
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

/// Merges random pairs of faces across a shared edge into one polygon (the
/// edge goes; V − E + F stays). A face merges at most once, and only when
/// the two faces share nothing but that edge and every other face meets the
/// new polygon at most in one of its edges: so the result stays a manifold,
/// and no diagonal a triangulation draws inside the polygon is an edge
/// anywhere else.
fn merge_pairs(mesh: &Mesh, seed: u64) -> Mesh {
    let mut next = seeded_words(seed);
    let faces: Vec<&[u32]> = mesh.faces().collect();
    let mut face_of: HashMap<(u32, u32), usize> = HashMap::new();
    for (f, face) in faces.iter().enumerate() {
        for i in 0..face.len() {
            face_of.insert((face[i], face[(i + 1) % face.len()]), f);
        }
    }
    let mut out: Vec<Option<Vec<u32>>> = faces.iter().map(|f| Some(f.to_vec())).collect();
    let mut taken = vec![false; faces.len()];
    for f in 0..faces.len() {
        if taken[f] || next() % 2 == 0 {
            continue;
        }
        let (face, n) = (faces[f], faces[f].len());
        let start = next() as usize % n;
        for i in (0..n).map(|k| (start + k) % n) {
            let (a, b) = (face[i], face[(i + 1) % n]);
            let Some(&g) = face_of.get(&(b, a)) else {
                continue;
            };
            let shared = face.iter().filter(|v| faces[g].contains(v)).count();
            if taken[g] || shared != 2 {
                continue;
            }
            // f runs a → b, g runs b → a: f from b round to a, then g between a and b.
            let (other, m) = (faces[g], faces[g].len());
            let j = other.iter().position(|&v| v == b).unwrap();
            let mut polygon: Vec<u32> = (1..=n).map(|s| face[(i + s) % n]).collect();
            polygon.extend((2..m).map(|s| other[(j + s) % m]));
            let apart = |x: u32, y: u32| {
                let p = polygon.iter().position(|&v| v == x).unwrap();
                polygon[(p + 1) % polygon.len()] != y
                    && polygon[(p + polygon.len() - 1) % polygon.len()] != y
            };
            let clashes = out
                .iter()
                .enumerate()
                .flat_map(|(h, o)| o.as_ref().map(|o| (h, o)))
                .any(|(h, o)| {
                    let common: Vec<u32> =
                        o.iter().copied().filter(|v| polygon.contains(v)).collect();
                    h != f
                        && h != g
                        && (common.len() > 2 || (common.len() == 2 && apart(common[0], common[1])))
                });
            if clashes {
                continue;
            }
            taken[f] = true;
            taken[g] = true;
            out[f] = Some(polygon);
            out[g] = None;
            break;
        }
    }
    Mesh::from_polygons(mesh.positions().to_vec(), out.into_iter().flatten()).unwrap()
}

/// The mesh's edges, each as its two vertices in increasing order.
fn edges(mesh: &Mesh) -> HashSet<(u32, u32)> {
    mesh.faces()
        .flat_map(|face| {
            (0..face.len()).map(move |i| {
                let (a, b) = (face[i], face[(i + 1) % face.len()]);
                (a.min(b), a.max(b))
            })
        })
        .collect()
}

fn jitter(bits: u64) -> f64 {
    ((bits % 1000) as f64 / 1000.0 - 0.5) * 0.01
}

/// `mesh` with face f reversed where bit `f % 64` of `pick` is set.
fn reverse_picked_faces(mesh: &Mesh, pick: u64) -> Mesh {
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
    Mesh::from_polygons(mesh.positions().to_vec(), faces).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn topology_of_closed_meshes_is_consistent((mesh, euler) in polygon_mesh()) {
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
    fn reversing_random_faces_keeps_orientability((mesh, _) in polygon_mesh(), pick in any::<u64>()) {
        let flipped = reverse_picked_faces(&mesh, pick);
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

/// Reads the OBJ subset the test meshes are written in: `v x y z` and `f a b c ...` (1-based).
fn read_obj(text: &str) -> Mesh {
    let mut positions = Vec::new();
    let mut faces = Vec::new();
    for line in text.lines() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                let c: Vec<f64> = words.map(|w| w.parse().unwrap()).collect();
                positions.push(DVec3::new(c[0], c[1], c[2]));
            }
            Some("f") => faces.push(
                words
                    .map(|w| w.parse::<u32>().unwrap() - 1)
                    .collect::<Vec<_>>(),
            ),
            _ => {}
        }
    }
    Mesh::from_polygons(positions, faces).unwrap()
}

/// A case the closed-mesh generator once made when it gridded the box's
/// sides with different counts: their seams do not meet. Topology must count
/// it as the open surface it is, with every corner's edge right, and the
/// seams' T-nodes, once repaired, close it.
#[test]
fn a_box_whose_sides_do_not_meet_is_open_along_its_seams() {
    let mesh = read_obj(include_str!("properties-mismatched-box.obj"));
    assert_eq!((mesh.vertex_count(), mesh.face_count()), (119, 137));
    let topology = Topology::new(&mesh);
    let info = topology.info(&mesh);
    let mut uses: HashMap<(u32, u32), usize> = HashMap::new();
    for face in mesh.faces() {
        for i in 0..face.len() {
            let (a, b) = (face[i], face[(i + 1) % face.len()]);
            *uses.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    let naked: Vec<(u32, u32)> = uses
        .iter()
        .filter(|(_, &n)| n == 1)
        .map(|(&e, _)| e)
        .collect();
    assert_eq!(info.edge_count, uses.len());
    assert_eq!(info.edge_count, 272);
    assert_eq!(info.naked_edge_count, naked.len());
    assert_eq!(info.naked_edge_count, 54);
    assert!(uses.values().all(|&n| n <= 2));
    assert_eq!(info.non_manifold_edge_count, 0);
    // A seam vertex with 2k naked edges has k fans of faces: more than one is non-manifold.
    let mut naked_at = vec![0usize; mesh.vertex_count()];
    for &(a, b) in &naked {
        naked_at[a as usize] += 1;
        naked_at[b as usize] += 1;
    }
    let fans = naked_at.iter().filter(|&&n| n > 2).count();
    assert_eq!(info.non_manifold_vertex_count, fans);
    assert!(!info.is_closed && info.is_orientable && info.is_oriented);
    assert_eq!(info.component_count, 1);
    let corners = topology.corner_vertices();
    for (c, &e) in topology.corner_edges().iter().enumerate() {
        let [a, b] = topology.edges()[e as usize];
        let (u, v) = (corners[c], corners[topology.corner_next()[c] as usize]);
        assert_eq!((a, b), (u.min(v), u.max(v)));
    }
    let edge_uses: usize = (0..topology.edge_count())
        .map(|e| topology.edge_face_count(e))
        .sum();
    assert_eq!(edge_uses, mesh.index_count());
    // The vertices of the finer grids lie on the coarser grids' naked edges.
    let (repaired, inserted) = weft::mend::t_nodes::repair_t_nodes(&mesh, 0.02).unwrap();
    assert!(inserted > 0);
    let fixed = Topology::new(&repaired).info(&repaired);
    assert!(fixed.is_closed && fixed.is_oriented, "{fixed:?}");
    assert_eq!(
        fixed.vertex_count as i64 - fixed.edge_count as i64 + fixed.face_count as i64,
        2
    );
}

/// The polygon generator makes what its tests rely on: closed manifolds of
/// the promised Euler characteristic, with triangles, quads, pentagons and
/// hexagons among their faces.
#[test]
fn the_polygon_generator_mixes_triangles_quads_and_n_gons() {
    let mut sizes = HashSet::new();
    for seed in 0..8 {
        for (base, euler) in [(shapes::torus(6, 5), 0), (box_mesh(4), 2)] {
            let mesh = merge_pairs(&remix(&base, seed), seed + 100);
            let info = Topology::new(&mesh).info(&mesh);
            assert!(info.is_closed && info.is_oriented && info.non_manifold_vertex_count == 0);
            assert_eq!(
                info.vertex_count as i64 - info.edge_count as i64 + info.face_count as i64,
                euler
            );
            sizes.extend(mesh.face_sizes().iter().copied());
        }
    }
    assert_eq!(sizes, HashSet::from([3, 4, 5, 6]));
}

mod operations {
    use super::*;
    use weft::mend::cull::cull_adjacent;
    use weft::mend::orient::{flip, signed_volume, unify_orientation};
    use weft::mend::weld::{join, weld, weld_owned, WeldReport};
    use weft::mesh::triangulate::triangulate;
    use weft::subdivide::{
        catmull_clark, loop_subdivision, refined_counts, subdivide, NakedEdges, Refiner, Scheme,
    };

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

    /// Whether the polygon, projected onto the plane across its Newell
    /// vector, is simple: no two edges without a common corner cross, touch
    /// or overlap there.
    fn projects_simple(points: &[DVec3]) -> bool {
        let normal: DVec3 = (0..points.len())
            .map(|i| points[i].cross(points[(i + 1) % points.len()]))
            .sum::<DVec3>()
            .normalize();
        let u = normal.any_orthonormal_vector();
        let w = normal.cross(u);
        let q: Vec<(f64, f64)> = points.iter().map(|p| (p.dot(u), p.dot(w))).collect();
        let turn = |a: (f64, f64), b: (f64, f64), c: (f64, f64)| {
            (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
        };
        let k = q.len();
        (0..k).all(|i| {
            (i + 2..k).filter(|&j| (j + 1) % k != i).all(|j| {
                let (a, b, c, d) = (q[i], q[(i + 1) % k], q[j], q[(j + 1) % k]);
                turn(c, d, a) * turn(c, d, b) > 0.0 || turn(a, b, c) * turn(a, b, d) > 0.0
            })
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 32, failure_persistence: None, ..ProptestConfig::default() })]

        #[test]
        fn subdivision_makes_the_predicted_counts_and_keeps_euler((mesh, chi) in polygon_mesh()) {
            // Catmull-Clark: V' = V + E + F, E' = 2E + Σ sizes, F' = Σ sizes, all quads.
            let (v, e, f, s) = (mesh.vertex_count(), edges(&mesh).len(), mesh.face_count(), mesh.index_count());
            let mut predicted = Vec::new();
            let (mut v_l, mut e_l, mut f_l, mut s_l) = (v, e, f, s);
            for _ in 0..2 {
                (v_l, e_l, f_l, s_l) = (v_l + e_l + f_l, 2 * e_l + s_l, s_l, 4 * s_l);
                predicted.push((v_l, e_l, f_l, s_l));
            }
            prop_assert_eq!(predicted[1].2, 4 * s);
            for (level, &(v_l, e_l, f_l, s_l)) in (1u32..).zip(&predicted) {
                let counts = refined_counts(&mesh, Scheme::CatmullClark, level).unwrap();
                prop_assert_eq!((counts.vertex_count, counts.face_count, counts.index_count), (v_l, f_l, s_l), "level {}", level);
                let out = catmull_clark(&mesh, level, NakedEdges::Smooth).unwrap();
                prop_assert_eq!((out.vertex_count(), out.face_count(), out.index_count()), (v_l, f_l, s_l), "level {}", level);
                prop_assert_eq!(edges(&out).len(), e_l, "level {}", level);
                prop_assert!(out.is_quad_mesh());
                prop_assert_eq!(v_l as i64 - e_l as i64 + f_l as i64, chi);
                prop_assert_eq!(euler(&out), chi);
                prop_assert!(Topology::new(&out).info(&out).is_closed);
            }

            // Loop: V' = V + E, E' = 2E + 3F, F' = 4F, all triangles.
            let triangles = triangulate(&mesh).unwrap().mesh;
            let (v, e, f) = (triangles.vertex_count(), edges(&triangles).len(), triangles.face_count());
            prop_assert_eq!(v as i64 - e as i64 + f as i64, chi);
            let mut predicted = Vec::new();
            let (mut v_l, mut e_l, mut f_l) = (v, e, f);
            for _ in 0..2 {
                (v_l, e_l, f_l) = (v_l + e_l, 2 * e_l + 3 * f_l, 4 * f_l);
                predicted.push((v_l, e_l, f_l));
            }
            prop_assert_eq!(predicted[1].2, 16 * f);
            for (level, &(v_l, e_l, f_l)) in (1u32..).zip(&predicted) {
                let counts = refined_counts(&triangles, Scheme::Loop, level).unwrap();
                prop_assert_eq!((counts.vertex_count, counts.face_count, counts.index_count), (v_l, f_l, 3 * f_l), "level {}", level);
                let looped = loop_subdivision(&triangles, level, NakedEdges::Smooth).unwrap();
                prop_assert_eq!((looped.vertex_count(), looped.face_count(), looped.index_count()), (v_l, f_l, 3 * f_l), "level {}", level);
                prop_assert_eq!(edges(&looped).len(), e_l, "level {}", level);
                prop_assert!(looped.is_triangle_mesh());
                prop_assert_eq!(v_l as i64 - e_l as i64 + f_l as i64, chi);
                prop_assert_eq!(euler(&looped), chi);
                prop_assert!(Topology::new(&looped).info(&looped).is_closed);
            }
        }

        /// One-shot subdivision reads its gathers from the levels (the last
        /// Catmull-Clark level from the one before it); the refiner stores
        /// them as plans. Both must give the same bits, on open meshes
        /// welded at random tolerances (naked edges, and non-manifold edges
        /// and vertices where pieces meet), in every naked-edge mode.
        #[test]
        fn one_shot_subdivision_equals_the_refiner_bit_for_bit((mesh, tolerance) in open_mesh()) {
            let (mesh, _) = weld(&mesh, tolerance).unwrap();
            let triangles = triangulate(&mesh).unwrap().mesh;
            for (scheme, cage) in [(Scheme::CatmullClark, &mesh), (Scheme::Loop, &triangles)] {
                for naked in [NakedEdges::Fixed, NakedEdges::Smooth, NakedEdges::CornerFixed] {
                    for levels in 1..=3 {
                        let one_shot = subdivide(cage, scheme, levels, naked).unwrap();
                        let refined = Refiner::new(cage, scheme, levels, naked).unwrap().mesh().unwrap();
                        prop_assert_eq!(one_shot.face_indices(), refined.face_indices(), "{:?} {:?} L{}", scheme, naked, levels);
                        let same_bits = one_shot.positions().iter().zip(refined.positions()).all(|(a, b)| {
                            a.to_array().map(f64::to_bits) == b.to_array().map(f64::to_bits)
                        });
                        prop_assert!(same_bits, "{:?} {:?} L{}", scheme, naked, levels);
                    }
                }
            }
        }

        #[test]
        fn weld_restores_loose_faces_and_is_idempotent((mesh, _) in polygon_mesh()) {
            let loose = unweld(&mesh);
            let (welded, report) = weld(&loose, 1e-6).unwrap();
            prop_assert_eq!(weld_owned(loose.clone(), 1e-6).unwrap(), (welded.clone(), report));
            prop_assert!(welded.vertex_count() <= loose.vertex_count());
            prop_assert!(welded.face_count() <= loose.face_count());
            prop_assert_eq!(welded.vertex_count(), mesh.vertex_count());
            prop_assert_eq!(welded.face_sizes(), mesh.face_sizes());
            // The same faces through the same points (the vertices renumbered in order of first use).
            for f in 0..mesh.face_count() {
                prop_assert!(welded.face_positions(f).eq(mesh.face_positions(f)), "face {}", f);
            }
            prop_assert_eq!(report.merged_vertex_count, loose.vertex_count() - mesh.vertex_count());
            prop_assert_eq!(report.removed_face_count, 0);
            prop_assert_eq!(Topology::new(&welded).info(&welded), Topology::new(&mesh).info(&mesh));
            let (again, second) = weld(&welded, 1e-6).unwrap();
            prop_assert_eq!(&again, &welded);
            prop_assert_eq!(second.merged_vertex_count, 0);
        }

        #[test]
        fn weld_of_open_meshes_never_adds_anything_and_is_idempotent((mesh, tolerance) in open_mesh()) {
            let positions = mesh.positions();
            // The clusters by brute force: every pair within the tolerance, joined transitively.
            let n = positions.len();
            let mut root: Vec<usize> = (0..n).collect();
            fn find(root: &mut [usize], mut v: usize) -> usize {
                while root[v] != v {
                    root[v] = root[root[v]];
                    v = root[v];
                }
                v
            }
            for a in 0..n {
                for b in a + 1..n {
                    let d = (positions[a] - positions[b]).length();
                    // A pair at the tolerance itself is left to rounding: not drawn.
                    prop_assume!((d - tolerance).abs() > 1e-12 * tolerance.max(1e-300) || d == 0.0);
                    if d <= tolerance {
                        let (ra, rb) = (find(&mut root, a), find(&mut root, b));
                        root[ra.max(rb)] = ra.min(rb);
                    }
                }
            }
            // The expected result: each cluster at its first vertex, repeats
            // dropped from faces, faces of fewer than 3 vertices removed,
            // unused clusters left out, everything else in order.
            let cluster: Vec<usize> = (0..n).map(|v| find(&mut root, v)).collect();
            let mut faces: Vec<Vec<usize>> = Vec::new();
            for face in mesh.faces() {
                let mut kept: Vec<usize> = Vec::new();
                for &v in face {
                    if !kept.contains(&cluster[v as usize]) {
                        kept.push(cluster[v as usize]);
                    }
                }
                if kept.len() >= 3 {
                    faces.push(kept);
                }
            }
            let mut used: Vec<usize> = faces.iter().flatten().copied().collect();
            used.sort_unstable();
            used.dedup();
            let index: HashMap<usize, u32> = used.iter().enumerate().map(|(i, &c)| (c, i as u32)).collect();
            let expected = Mesh::from_polygons(
                used.iter().map(|&c| positions[c]).collect(),
                faces.iter().map(|f| f.iter().map(|c| index[c]).collect::<Vec<_>>()),
            )
            .unwrap();

            let (welded, report) = weld(&mesh, tolerance).unwrap();
            prop_assert!(welded.vertex_count() <= mesh.vertex_count());
            prop_assert!(welded.face_count() <= mesh.face_count());
            prop_assert!(welded.index_count() <= mesh.index_count());
            prop_assert_eq!(&welded, &expected);
            prop_assert_eq!(weld_owned(mesh.clone(), tolerance).unwrap(), (welded.clone(), report));
            let clusters = cluster.iter().enumerate().filter(|&(v, &c)| v == c).count();
            prop_assert_eq!(report.merged_vertex_count, n - clusters);
            prop_assert_eq!(report.unused_vertex_count, clusters - welded.vertex_count());
            prop_assert_eq!(report.removed_face_count, mesh.face_count() - welded.face_count());
            let (again, second) = weld(&welded, tolerance).unwrap();
            prop_assert_eq!(&again, &welded);
            prop_assert_eq!(second, WeldReport::default());
        }

        #[test]
        fn triangulation_keeps_each_polygons_boundary_winding_and_vector_area((mesh, chi) in polygon_mesh()) {
            let result = triangulate(&mesh).unwrap();
            let triangles = &result.mesh;
            prop_assert!(triangles.is_triangle_mesh());
            prop_assert_eq!(triangles.positions(), mesh.positions());
            let expected: usize = mesh.face_sizes().iter().map(|&n| n as usize - 2).sum();
            prop_assert_eq!(triangles.face_count(), expected);
            prop_assert_eq!(result.parent_faces.len(), expected);
            let mut first = 0;
            for (f, face) in mesh.faces().enumerate() {
                let count = face.len() - 2;
                let children = first..first + count;
                first += count;
                prop_assert!(result.parent_faces[children.clone()].iter().all(|&p| p as usize == f));
                // Each triangle runs through three of the polygon's corners in
                // the polygon's order, and the triangles' edges that are the
                // polygon's edges are each of them once, the same way round.
                let place = |v: u32| face.iter().position(|&w| w == v);
                let mut boundary = HashSet::new();
                let newell = |p: &[DVec3]| -> DVec3 { (0..p.len()).map(|i| p[i].cross(p[(i + 1) % p.len()])).sum() };
                let polygon: Vec<DVec3> = mesh.face_positions(f).collect();
                let mut vector_area = DVec3::ZERO;
                for t in children {
                    let tri = triangles.face(t);
                    let at: Vec<usize> = tri.iter().map(|&v| place(v).unwrap()).collect();
                    let turns = (0..3).filter(|&i| at[(i + 1) % 3] < at[i]).count();
                    prop_assert_eq!(turns, 1, "face {} triangle {:?}", f, tri);
                    for i in 0..3 {
                        if (at[i] + 1) % face.len() == at[(i + 1) % 3] {
                            prop_assert!(boundary.insert(at[i]));
                        }
                    }
                    let p: Vec<DVec3> = triangles.face_positions(t).collect();
                    let area = newell(&p);
                    // An n-gon is cut in its best-fit plane: where it is a
                    // simple polygon there, every ear turns the polygon's way
                    // (a quad's shorter diagonal promises nothing of the kind
                    // on a twisted quad).
                    if face.len() > 4 && projects_simple(&polygon) {
                        prop_assert!(area.dot(newell(&polygon)) > 0.0, "face {} {:?}: triangle {:?} is flipped", f, polygon, tri);
                    }
                    vector_area += area;
                }
                prop_assert_eq!(boundary.len(), face.len());
                prop_assert!((vector_area - newell(&polygon)).length() <= 1e-12 * newell(&polygon).length());
            }
            let info = Topology::new(triangles).info(triangles);
            prop_assert!(info.is_closed && info.is_oriented && info.non_manifold_vertex_count == 0, "{:?}", info);
            prop_assert_eq!(euler(triangles), chi);
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
        fn flip_twice_is_the_identity((mesh, _) in polygon_mesh()) {
            let once = flip(&mesh);
            prop_assert_ne!(&once, &mesh);
            prop_assert_eq!(flip(&once), mesh);
        }

        #[test]
        fn unify_makes_every_manifold_edge_consistent_and_faces_out((mesh, _) in polygon_mesh(), pick in any::<u64>()) {
            let scrambled = reverse_picked_faces(&mesh, pick);
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
