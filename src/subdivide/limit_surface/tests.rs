use super::*;
use crate::mesh::shapes;
use crate::subdivide::{Creasing, NakedEdges, Subdivider, TriangleRule};

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

/// A torus of `n` × `n` quads with every fourth quad split into two
/// triangles: extraordinary vertices in a repeating pattern.
fn split_torus(n: usize) -> Mesh {
    let torus = shapes::torus(n, n);
    let mut faces: Vec<Vec<u32>> = Vec::new();
    for f in 0..torus.face_count() {
        let q = torus.face(f);
        match f % 4 {
            0 => faces.extend([vec![q[0], q[1], q[2]], vec![q[0], q[2], q[3]]]),
            _ => faces.push(q.to_vec()),
        }
    }
    Mesh::from_polygons(torus.positions().to_vec(), faces).unwrap()
}

/// Faces whose graphs meet the same small mesh share its expansion, and
/// every sample is the same bits as with each face expanding its own.
#[test]
fn faces_share_the_expansions_of_alike_neighbourhoods() {
    let cage = split_torus(12);
    let mut options = SubdivisionOptions::new(NakedEdges::Smooth);
    // A semi-sharp crease and a corner, whose sharpness is in the nodes' identity.
    let q = cage.face(5);
    options.creases.push(([q[0], q[1]], 1.5));
    options.corners.push((cage.face(40)[2], 2.0));
    for scheme in [Scheme::CatmullClark, Scheme::Loop] {
        let cage = match scheme {
            Scheme::CatmullClark => cage.clone(),
            Scheme::Loop => crate::mesh::triangulate::triangulate(&cage).unwrap().mesh,
        };
        let shared = LimitSurface::new(&cage, scheme, &options).unwrap();
        let subdivider = Subdivider::new(&cage, scheme, 0, &options).unwrap();
        let level = &subdivider.levels[0];
        let expansions = local::Expansions::default();
        let mut node_count = 0;
        for f in 0..cage.face_count() {
            let graph = local::face_graph(scheme, level, f, &options, &expansions).unwrap();
            node_count += graph.nodes.len();
        }
        assert!(
            expansions.len() * 4 < node_count,
            "{scheme:?}: {} expansions for {node_count} nodes",
            expansions.len()
        );
        let mut alone = shared.clone();
        alone.faces = (0..cage.face_count())
            .map(|f| {
                let own = local::Expansions::default();
                local::face_graph(scheme, level, f, &options, &own).unwrap()
            })
            .collect();
        let (mut faces, mut uvs) = (Vec::new(), Vec::new());
        for f in 0..cage.face_count() as u32 {
            for (u, v) in [
                (0.0, 0.0),
                (0.1, 0.3),
                (0.25, 0.25),
                (0.5, 0.0),
                (1e-9, 0.4),
            ] {
                faces.push(f);
                uvs.extend([u, v]);
            }
        }
        assert!(
            sample_bits(&shared, &faces, &uvs) == sample_bits(&alone, &faces, &uvs),
            "{scheme:?}"
        );
    }
}

/// Samples evaluated together, where a face's samples reuse the points of
/// its root's children, are the same bits as each evaluated alone: face by
/// face, faces interleaved, and the children in any order.
#[test]
fn samples_together_equal_samples_alone() {
    // Faces whose root is refined (beside the split quads) and faces whose
    // root is a patch (all of the plain torus's).
    let cages = [split_torus(6), shapes::torus(5, 6)];
    for (cage, scheme) in cages
        .iter()
        .flat_map(|cage| [Scheme::CatmullClark, Scheme::Loop].map(|scheme| (cage, scheme)))
    {
        let cage = match scheme {
            Scheme::CatmullClark => cage.clone(),
            Scheme::Loop => crate::mesh::triangulate::triangulate(cage).unwrap().mesh,
        };
        let options = SubdivisionOptions::new(NakedEdges::Smooth);
        let surface = LimitSurface::new(&cage, scheme, &options).unwrap();
        let parameters = [(0.1, 0.2), (0.4, 0.05), (0.05, 0.4), (0.2, 0.1), (0.3, 0.3)];
        let (mut faces, mut uvs) = (Vec::new(), Vec::new());
        // Face by face, then two faces interleaved.
        for f in 0..cage.face_count() as u32 {
            for (u, v) in parameters {
                faces.push(f);
                uvs.extend([u, v]);
            }
        }
        for f in 0..cage.face_count() as u32 - 1 {
            for (i, (u, v)) in parameters.into_iter().enumerate() {
                faces.push(f + (i % 2) as u32);
                uvs.extend([u, v]);
            }
        }
        let together = sample_bits(&surface, &faces, &uvs);
        for i in 0..faces.len() {
            let alone = sample_bits(&surface, &faces[i..=i], &uvs[2 * i..2 * i + 2]);
            let what = format!("{scheme:?}: sample {i}, face {}", faces[i]);
            for (values, alone) in together.iter().zip(&alone) {
                assert_eq!(values[i], alone[0], "{what}");
            }
        }
    }
}

/// The bits of the positions, first and second derivatives at the samples.
fn sample_bits(surface: &LimitSurface, faces: &[u32], uvs: &[f64]) -> [Vec<[u64; 3]>; 3] {
    let n = faces.len();
    let (mut p, mut du, mut dv) = (
        vec![DVec3::ZERO; n],
        vec![DVec3::ZERO; n],
        vec![DVec3::ZERO; n],
    );
    surface
        .evaluate(faces, uvs, &mut p, Some(&mut du), Some(&mut dv))
        .unwrap();
    [p, du, dv].map(|values| {
        values
            .iter()
            .map(|q| q.to_array().map(f64::to_bits))
            .collect()
    })
}

/// Cages with every kind of rule: semi-sharp creases averaged along their
/// chain (Chaikin), corners, naked edges, triangles among quads with the
/// smooth-triangle weights, non-manifold edges and a vertex of 40 faces.
fn ruled_cages() -> Vec<(Mesh, Scheme, SubdivisionOptions)> {
    // Semi-sharp and sharp creases around the first face, a corner at a
    // vertex of the second.
    let creased = |cage: &Mesh| {
        let mut options = SubdivisionOptions::new(NakedEdges::Smooth);
        let face = cage.face(0);
        let (a, b, c, last) = (face[0], face[1], face[2], face[face.len() - 1]);
        options.creases = vec![([a, b], 1.5), ([b, c], 2.25), ([last, a], 10.0)];
        options.corners = vec![(cage.face(1)[2], 0.75)];
        options.creasing = Creasing::Chaikin;
        options
    };
    let mut smooth_triangles = SubdivisionOptions::new(NakedEdges::CornerFixed);
    smooth_triangles.triangles = TriangleRule::Smooth;
    let fan = shapes::fan(40);
    let fixed = SubdivisionOptions::new(NakedEdges::Fixed);
    vec![
        (
            shapes::cube(),
            Scheme::CatmullClark,
            creased(&shapes::cube()),
        ),
        (
            shapes::icosahedron(),
            Scheme::Loop,
            creased(&shapes::icosahedron()),
        ),
        (
            shapes::mixed_polygons(),
            Scheme::CatmullClark,
            smooth_triangles,
        ),
        (shapes::quad_grid(3, 2), Scheme::CatmullClark, fixed.clone()),
        (shapes::fin(), Scheme::CatmullClark, fixed.clone()),
        (fan.clone(), Scheme::CatmullClark, fixed.clone()),
        (
            fan,
            Scheme::Loop,
            SubdivisionOptions::new(NakedEdges::Smooth),
        ),
        (shapes::triangle_grid(3, 2), Scheme::Loop, fixed),
    ]
}

/// Asserts that the weight of `point` in row `r` has the bits of `value`
/// (0 where the row leaves the point out), and that no weight is stored as 0.
#[track_caller]
fn assert_weight(
    sparse: &local::Sparse,
    r: usize,
    point: usize,
    value: f64,
    what: impl Fn() -> String,
) {
    let range = sparse.offsets[r] as usize..sparse.offsets[r + 1] as usize;
    assert!(
        sparse.weights[range.clone()].iter().all(|&w| w != 0.0),
        "{}",
        what()
    );
    let at = sparse.sources[range.clone()]
        .iter()
        .position(|&s| s as usize == point);
    let w = at.map_or(0.0, |k| sparse.weights[range.start + k]);
    assert_eq!(w.to_bits(), (value + 0.0).to_bits(), "{}", what());
}

/// For each of `n` points, the points all at zero but that one at x = 1.
fn unit_points(n: usize) -> impl Iterator<Item = (usize, Vec<DVec3>)> {
    (0..n).map(move |k| {
        let mut unit = vec![DVec3::ZERO; n];
        unit[k] = DVec3::X;
        (k, unit)
    })
}

/// A level's stencils as weights of the parent's points are, bit for bit,
/// what refining each parent point alone at 1 gives.
#[test]
fn stencil_weights_are_the_refinement_of_unit_points() {
    for (cage, scheme, options) in ruled_cages() {
        let one = Subdivider::new(&cage, scheme, 1, &options).unwrap();
        let weights = local::Sparse::of_stencils(&one.stencils[0]);
        assert_eq!(weights.rows(), one.vertex_count());
        let mut refined = vec![DVec3::ZERO; one.vertex_count()];
        for (k, unit) in unit_points(cage.vertex_count()) {
            one.evaluate(&unit, &mut refined).unwrap();
            for (r, p) in refined.iter().enumerate() {
                let what = || format!("{scheme:?} row {r} point {k}");
                assert_weight(&weights, r, k, p.x, what);
            }
        }
    }
}

/// The limit masks at cage vertices as weights are, bit for bit, the limit
/// of each cage point alone at 1.
#[test]
fn limit_weights_are_the_limit_of_unit_points() {
    // On the torus of 2 × 3 quads each vertex meets its neighbours along
    // one direction twice, so their terms are summed in order.
    let smooth = SubdivisionOptions::new(NakedEdges::Smooth);
    let mut cases = ruled_cages();
    cases.push((shapes::torus(5, 4), Scheme::CatmullClark, smooth.clone()));
    cases.push((shapes::torus(2, 3), Scheme::CatmullClark, smooth));
    for (cage, scheme, options) in cases {
        let size = match scheme {
            Scheme::CatmullClark => 4,
            Scheme::Loop => 3,
        };
        if cage.face_sizes().iter().any(|&s| s != size) {
            continue;
        }
        let zero = Subdivider::new(&cage, scheme, 0, &options).unwrap();
        let n = cage.vertex_count();
        let weights = zero.cage_limit_weights(0..n).unwrap();
        let rows: Vec<local::Sparse> = weights
            .iter()
            .map(|masks| local::Sparse::from_rows(masks.iter().map(Vec::as_slice)))
            .collect();
        for (k, unit) in unit_points(n) {
            let limit = zero.limit_of(&unit).unwrap();
            for (v, masks) in rows.iter().enumerate() {
                let values = [limit.positions[v], limit.du[v], limit.dv[v]];
                for (row, value) in values.iter().enumerate() {
                    let what = || format!("{scheme:?} vertex {v} mask {row} point {k}");
                    assert_weight(masks, row, k, value.x, what);
                }
            }
        }
    }
}

/// A vertex of more faces than the limit surface takes is refused before
/// any refinement, naming it; one of the most is not.
#[test]
fn a_vertex_of_too_many_faces_is_refused() {
    let options = SubdivisionOptions::new(NakedEdges::Fixed);
    let too_many = MAX_LIMIT_VALENCE as u32 + 1;
    let err = LimitSurface::new(&shapes::fan(too_many), Scheme::Loop, &options).unwrap_err();
    assert!(matches!(err, Error::ResultTooLarge(_)), "{err}");
    let text = err.to_string();
    assert!(text.contains("cage vertex 0 has 1025 faces"), "{text}");
    assert!(LimitSurface::new(&shapes::fan(64), Scheme::Loop, &options).is_ok());
}
