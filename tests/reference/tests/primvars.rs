//! Carried data, face-varying UVs, creases, the limit surface and stencils
//! through the bridge.

mod common;

use common::*;
use weft_reference::*;

fn catmark() -> OsdOptions {
    OsdOptions::new(Scheme::CatmullClark, BoundaryInterpolation::EdgeOnly)
}

fn loop_options() -> OsdOptions {
    OsdOptions::new(Scheme::Loop, BoundaryInterpolation::EdgeOnly)
}

/// A cube with every vertex moved a little, so no symmetry hides mistakes.
fn skewed_cube() -> RefMesh {
    let mut mesh = cube();
    for (i, x) in mesh.positions.iter_mut().enumerate() {
        *x += 0.1 * ((i * 7 % 5) as f64 - 2.0) / 2.0;
    }
    mesh
}

#[test]
fn vertex_data_follows_positions_and_keeps_affine_functions() {
    let cage = skewed_cube();
    // Columns: x, y, z, 1, 2x - y + 3z.
    let data: Vec<f64> = (0..cage.vertex_count())
        .flat_map(|v| {
            let [x, y, z] = cage.position(v);
            [x, y, z, 1.0, 2.0 * x - y + 3.0 * z]
        })
        .collect();
    let refined = opensubdiv_refine(&cage, &catmark(), 2).unwrap();
    let out =
        opensubdiv_refine_vertex_data(&cage, &catmark(), 2, (&data, 5), Primvar::Vertex).unwrap();
    assert_eq!(out.len(), refined.vertex_count() * 5);
    for v in 0..refined.vertex_count() {
        let [x, y, z] = refined.position(v);
        let row = &out[5 * v..5 * v + 5];
        assert_eq!(&row[..3], &[x, y, z]);
        assert!((row[3] - 1.0).abs() < 1e-14);
        assert!((row[4] - (2.0 * x - y + 3.0 * z)).abs() < 1e-13);
    }
}

#[test]
fn varying_data_is_linear() {
    let cage = skewed_cube();
    let out =
        opensubdiv_refine_vertex_data(&cage, &catmark(), 1, (&cage.positions, 3), Primvar::Varying)
            .unwrap();
    // Vertex children keep their values; face points are corner averages.
    assert_eq!(&out[..24], &cage.positions[..]);
    let corners = [0usize, 2, 3, 1];
    for k in 0..3 {
        let average = corners
            .iter()
            .map(|&v| cage.positions[3 * v + k])
            .sum::<f64>()
            / 4.0;
        assert!((out[3 * 8 + k] - average).abs() < 1e-15);
    }
}

#[test]
fn face_varying_without_seams_equals_vertex_interpolation() {
    let cage = cube();
    // One UV per vertex, shared by all its corners: no face-varying boundary
    // on a closed mesh, so with FVarLinear::None the UVs are smooth exactly
    // like vertex data.
    let uvs: Vec<f64> = (0..8)
        .flat_map(|v| [v as f64 * 0.1, (v * v) as f64 * 0.03])
        .collect();
    let mut options = catmark();
    options.fvar_linear = FVarLinear::None;
    let (values, indices) =
        opensubdiv_refine_face_varying(&cage, &options, 2, &uvs, &cage.face_indices).unwrap();
    let refined = opensubdiv_refine(&cage, &options, 2).unwrap();
    let smooth =
        opensubdiv_refine_vertex_data(&cage, &options, 2, (&uvs, 2), Primvar::Vertex).unwrap();
    assert_eq!(indices.len(), refined.face_indices.len());
    for (c, &v) in refined.face_indices.iter().enumerate() {
        let value = indices[c] as usize;
        for k in 0..2 {
            assert!((values[2 * value + k] - smooth[2 * v as usize + k]).abs() < 1e-14);
        }
    }
}

#[test]
fn face_varying_with_seams_and_linear_all_is_bilinear() {
    let cage = cube();
    // Every face its own unit square: 24 values, seams everywhere.
    let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let uvs: Vec<f64> = (0..6)
        .flat_map(|_| square.iter().flatten().copied())
        .collect();
    let uv_indices: Vec<u32> = (0..24).collect();
    let options = catmark(); // fvar_linear: All
    let (values, indices) =
        opensubdiv_refine_face_varying(&cage, &options, 1, &uvs, &uv_indices).unwrap();
    // 6 faces × 9 values (4 corners, 4 edge midpoints, 1 centre).
    assert_eq!(values.len() / 2, 54);
    let uv = |c: usize| {
        [
            values[2 * indices[c] as usize],
            values[2 * indices[c] as usize + 1],
        ]
    };
    // The first child of face 0 runs corner 0, edge 0-1, centre, edge 3-0.
    assert_eq!(uv(0), [0.0, 0.0]);
    assert_eq!(uv(1), [0.5, 0.0]);
    assert_eq!(uv(2), [0.5, 0.5]);
    assert_eq!(uv(3), [0.0, 0.5]);
    // With FVarLinear::None the seams still hold but corners are smoothed
    // along them, so the corner value moves off (0, 0).
    let mut smooth = options.clone();
    smooth.fvar_linear = FVarLinear::None;
    let (values, indices) =
        opensubdiv_refine_face_varying(&cage, &smooth, 1, &uvs, &uv_indices).unwrap();
    let corner = [
        values[2 * indices[0] as usize],
        values[2 * indices[0] as usize + 1],
    ];
    assert!(corner[0] > 0.01 && corner[1] > 0.01, "{corner:?}");
}

#[test]
fn infinite_and_semi_sharp_creases() {
    // Edge 0-1 of the unit cube: smooth edge point (.5, 1/8, 1/8), midpoint
    // (.5, 0, 0). OpenSubdiv blends the two rules by a sharpness below 1.
    let edge_point = |sharpness: f32| {
        let mut options = catmark();
        options.crease_edges = vec![[0, 1]];
        options.crease_sharpness = vec![sharpness];
        let out = opensubdiv_refine(&cube(), &options, 1).unwrap();
        let (v, d) = nearest(&out, [0.5, 0.0, 0.0]);
        let (_, d_half) = nearest(&out, [0.5, 0.0625, 0.0625]);
        (out.position(v), d, d_half)
    };
    let (_, d, _) = edge_point(f32::INFINITY);
    assert!(d < 1e-15);
    let (_, d, _) = edge_point(1.0);
    assert!(d < 1e-15);
    let (_, _, d_half) = edge_point(0.5);
    assert!(d_half < 1e-15);
    let (p, _, _) = edge_point(0.0);
    assert!(distance(p, [0.5, 0.125, 0.125]) < 1e-15);
}

#[test]
fn corner_sharpness_anchors_a_vertex() {
    let mut options = catmark();
    options.corner_vertices = vec![0];
    options.corner_sharpness = vec![SHARPNESS_INFINITE];
    let out = opensubdiv_refine(&cube(), &options, 3).unwrap();
    assert_eq!(out.position(0), [0.0, 0.0, 0.0]);
    let free = opensubdiv_refine(&cube(), &catmark(), 3).unwrap();
    assert!(distance(free.position(0), [0.0; 3]) > 0.1);
}

#[test]
fn chaikin_differs_from_uniform_on_uneven_creases() {
    let mut uniform = catmark();
    uniform.crease_edges = vec![[0, 1], [1, 5]];
    uniform.crease_sharpness = vec![1.5, 3.0];
    let mut chaikin = uniform.clone();
    chaikin.creasing = CreasingMethod::Chaikin;
    let a = opensubdiv_refine(&cube(), &uniform, 3).unwrap();
    let b = opensubdiv_refine(&cube(), &chaikin, 3).unwrap();
    assert_eq!(a.face_indices, b.face_indices);
    let largest = a
        .positions
        .iter()
        .zip(&b.positions)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    assert!(largest > 1e-4, "Chaikin and Uniform agree to {largest}");
}

#[test]
fn limit_of_a_vertex_does_not_change_with_level() {
    // Vertex children keep their indices, and a vertex's limit point is the
    // limit of its children, so the first 8 limit points agree across levels.
    let cage = skewed_cube();
    let one = opensubdiv_limit(&cage, &catmark(), 1).unwrap();
    let three = opensubdiv_limit(&cage, &catmark(), 3).unwrap();
    for k in 0..24 {
        assert!((one.positions[k] - three.positions[k]).abs() < 1e-12);
        assert!((one.normals[k] - three.normals[k]).abs() < 1e-12);
    }
    // The limit point differs from the refined point.
    let refined = opensubdiv_refine(&cage, &catmark(), 1).unwrap();
    assert!(
        distance(
            refined.position(0),
            [one.positions[0], one.positions[1], one.positions[2]]
        ) > 1e-3
    );
}

#[test]
fn limit_normals_of_symmetric_shapes_are_radial() {
    for (cage, options, center) in [
        (cube(), catmark(), [0.5; 3]),
        (icosahedron(), loop_options(), [0.0; 3]),
    ] {
        let limit = opensubdiv_limit(&cage, &options, 1).unwrap();
        for v in 0..limit.positions.len() / 3 {
            let p = [0, 1, 2].map(|k| limit.positions[3 * v + k] - center[k]);
            let length = distance(p, [0.0; 3]);
            let n = &limit.normals[3 * v..3 * v + 3];
            let dot = (p[0] * n[0] + p[1] * n[1] + p[2] * n[2]) / length;
            // du × dv points outward for outward-facing (counter-clockwise) faces.
            assert!((dot - 1.0).abs() < 1e-12, "vertex {v}: {dot}");
        }
    }
}

#[test]
fn limit_of_the_icosahedron_is_round() {
    let limit = opensubdiv_limit(&icosahedron(), &loop_options(), 1).unwrap();
    let radius = |v: usize| distance([0, 1, 2].map(|k| limit.positions[3 * v + k]), [0.0; 3]);
    for v in 1..12 {
        assert!((radius(v) - radius(0)).abs() < 1e-12);
    }
}

#[test]
fn stencils_reproduce_refinement() {
    let grid = bumpy_quad_grid(3, 2);
    let mut creased = catmark();
    creased.crease_edges = vec![[0, 1], [1, 3]];
    creased.crease_sharpness = vec![SHARPNESS_INFINITE, 1.5];
    for (cage, options, levels) in [
        (cube(), catmark(), 1),
        (cube(), creased, 3),
        (
            grid.clone(),
            OsdOptions::fixed(Scheme::CatmullClark, &grid),
            2,
        ),
        (icosahedron(), loop_options(), 2),
    ] {
        let stencils = OsdStencils::new(&cage, &options, levels).unwrap();
        let moved = skew(&cage);
        let mut out = vec![f64::NAN; stencils.vertex_count() * 3];
        stencils.update(&moved.positions, &mut out);
        let expected = opensubdiv_refine(&moved, &options, levels).unwrap();
        assert_eq!(stencils.faces.face_sizes, expected.face_sizes);
        assert_eq!(stencils.faces.face_indices, expected.face_indices);
        assert_eq!(out.len(), expected.positions.len());
        for (a, b) in out.iter().zip(&expected.positions) {
            assert!((a - b).abs() < 1e-12, "{a} vs {b}");
        }
    }
}

#[test]
fn stencils_on_threads_write_what_one_thread_writes() {
    // 98 stencils at level 2: 200 threads leave some ranges empty.
    let cage = cube();
    let stencils = OsdStencils::new(&cage, &catmark(), 2).unwrap();
    let moved = skew(&cage);
    let mut one = vec![f64::NAN; stencils.vertex_count() * 3];
    stencils.update(&moved.positions, &mut one);
    for threads in [0, 1, 2, 3, 7, 200] {
        let mut spread = vec![f64::NAN; one.len()];
        stencils.update_on_threads(&moved.positions, &mut spread, threads);
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&spread), bits(&one), "{threads} threads");
    }
}

#[test]
fn openmp_stencils_agree_with_double_precision_on_any_thread_count() {
    let cage = cube();
    let stencils = OsdStencils::new(&cage, &catmark(), 2).unwrap();
    let parallel = OsdParallelStencils::new(&cage, &catmark(), 2).unwrap();
    assert_eq!(parallel.vertex_count(), stencils.vertex_count());
    let moved = skew(&cage);
    let mut exact = vec![0.0; stencils.vertex_count() * 3];
    stencils.update(&moved.positions, &mut exact);
    let single: Vec<f32> = moved.positions.iter().map(|&x| x as f32).collect();
    for threads in [0, 1, 2] {
        let mut out = vec![f32::NAN; exact.len()];
        parallel.update(&single, &mut out, threads);
        for (a, b) in out.iter().zip(&exact) {
            assert!(
                (f64::from(*a) - b).abs() < 1e-5,
                "{a} vs {b}, {threads} threads"
            );
        }
    }
}

fn skew(mesh: &RefMesh) -> RefMesh {
    let mut moved = mesh.clone();
    for (i, x) in moved.positions.iter_mut().enumerate() {
        *x = *x * 1.5 + ((i * 13 % 7) as f64) * 0.01;
    }
    moved
}

#[test]
fn stencils_refuse_level_zero() {
    assert!(OsdStencils::new(&cube(), &catmark(), 0).is_err());
}

#[test]
fn refiner_serves_several_primvars() {
    let cage = skewed_cube();
    let refiner = OsdRefiner::new(&cage, &catmark(), 2).unwrap();
    assert_eq!(refiner.vertex_count(), 98);
    assert_eq!(refiner.face_count(), 96);
    let positions = refiner.interpolate(&cage.positions, 3);
    assert_eq!(
        positions,
        opensubdiv_refine(&cage, &catmark(), 2).unwrap().positions
    );
    let ones = refiner.interpolate(&[1.0; 8], 1);
    assert!(ones.iter().all(|x| (x - 1.0).abs() < 1e-15));
}

#[test]
fn non_manifold_input_goes_through_every_call() {
    for (cage, options) in [(fin(), catmark()), (bow_tie(), loop_options())] {
        let refined = opensubdiv_refine(&cage, &options, 2).unwrap();
        let n = refined.vertex_count();
        let limit = opensubdiv_limit(&cage, &options, 2).unwrap();
        assert_eq!(limit.positions.len(), 3 * n);
        assert!(limit.positions.iter().all(|x| x.is_finite()));
        let stencils = OsdStencils::new(&cage, &options, 2).unwrap();
        let mut out = vec![0.0; 3 * n];
        stencils.update(&cage.positions, &mut out);
        for (a, b) in out.iter().zip(&refined.positions) {
            assert!((a - b).abs() < 1e-12);
        }
        let corners = cage.face_indices.len();
        let uvs: Vec<f64> = (0..2 * corners).map(|i| i as f64 * 0.1).collect();
        let uv_indices: Vec<u32> = (0..corners as u32).collect();
        let (values, indices) =
            opensubdiv_refine_face_varying(&cage, &options, 2, &uvs, &uv_indices).unwrap();
        assert_eq!(indices.len(), refined.face_indices.len());
        assert!(indices.iter().all(|&i| (i as usize) < values.len() / 2));
    }
}

#[test]
fn face_varying_input_is_checked() {
    let cage = cube();
    let err =
        opensubdiv_refine_face_varying(&cage, &catmark(), 1, &[0.0; 4], &[0; 23]).unwrap_err();
    assert!(
        err.0.contains("23 face-varying indices for 24 corners"),
        "{err}"
    );
    let mut indices = vec![0u32; 24];
    indices[5] = 2;
    let err =
        opensubdiv_refine_face_varying(&cage, &catmark(), 1, &[0.0; 4], &indices).unwrap_err();
    assert!(err.0.contains("corner 5 has face-varying value 2"), "{err}");
}

#[test]
#[should_panic(expected = "8 vertices of width 3 need 24 numbers")]
fn short_data_panics_before_reaching_cpp() {
    let refiner = OsdRefiner::new(&cube(), &catmark(), 1).unwrap();
    refiner.interpolate(&[0.0; 23], 3);
}

#[test]
#[should_panic(expected = "out must hold xyz for 26 vertices")]
fn short_stencil_output_panics_before_reaching_cpp() {
    let stencils = OsdStencils::new(&cube(), &catmark(), 1).unwrap();
    let mut out = vec![0.0; 77];
    stencils.update(&cube().positions, &mut out);
}
