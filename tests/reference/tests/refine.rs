//! OpenSubdiv's uniform refinement and OpenMesh's subdividers through the
//! bridge: counts, known positions, boundary rules, agreement of the two.

mod common;

use common::*;
use weft_reference::*;

fn catmark() -> OsdOptions {
    OsdOptions::new(Scheme::CatmullClark, BoundaryInterpolation::EdgeOnly)
}

fn loop_options() -> OsdOptions {
    OsdOptions::new(Scheme::Loop, BoundaryInterpolation::EdgeOnly)
}

#[test]
fn cube_catmull_clark_level_1_counts_and_known_points() {
    let out = opensubdiv_refine(&cube(), &catmark(), 1).unwrap();
    // V + E + F = 8 + 12 + 6 vertices, 6 × 4 quads.
    assert_eq!(out.vertex_count(), 26);
    assert_eq!(out.face_count(), 24);
    assert!(out.face_sizes.iter().all(|&n| n == 4));
    // Corner (0,0,0), valence n = 3. Face points of its three faces:
    // (0,.5,.5), (.5,0,.5), (.5,.5,0), average Q = (1/3,1/3,1/3). Midpoints
    // of its edges: (.5,0,0), (0,.5,0), (0,0,.5), average R = (1/6,1/6,1/6).
    // S = 0, so (Q + 2R + (n-3)S)/n = (1/3 + 1/3)/3 = 2/9 per coordinate.
    // (5/18 would come from averaging edge points instead of midpoints.)
    let (_, d) = nearest(&out, [2.0 / 9.0; 3]);
    assert!(d < 1e-15, "corner point off by {d}");
    // Edge point of edge (0,0,0)-(1,0,0): average of its ends (.5,0,0) and
    // its faces' points (.5,0,.5), (.5,.5,0): (.5, 1/8, 1/8).
    let (_, d) = nearest(&out, [0.5, 0.125, 0.125]);
    assert!(d < 1e-15, "edge point off by {d}");
    // Face point of z = 0.
    let (_, d) = nearest(&out, [0.5, 0.5, 0.0]);
    assert!(d < 1e-15, "face point off by {d}");
    // Vtr's order: the cage's vertices keep their indices, then face points
    // in face order, then edge points; face 0 = [0, 2, 3, 1] has its first
    // child at corner 0, [v0, e(0,2), f0, e(1,0)].
    assert_eq!(out.position(0), [2.0 / 9.0; 3]);
    assert!(distance(out.position(7), [7.0 / 9.0; 3]) < 1e-15);
    assert_eq!(out.position(8), [0.5, 0.5, 0.0]);
    assert_eq!(out.position(14), [0.125, 0.5, 0.125]);
    assert_eq!(out.faces().next().unwrap(), &[0, 14, 8, 17]);
}

#[test]
fn cube_catmull_clark_counts_over_levels() {
    let mut faces = 6;
    for level in 0..=3 {
        let out = opensubdiv_refine(&cube(), &catmark(), level).unwrap();
        assert_eq!(out.face_count(), faces);
        // Closed genus 0: V - E + F = 2 with E = 2F for quads.
        assert_eq!(out.vertex_count(), 2 + faces);
        faces *= 4;
    }
}

#[test]
fn tetrahedron_loop_level_1() {
    let out = opensubdiv_refine(&tetrahedron(), &loop_options(), 1).unwrap();
    assert_eq!(out.vertex_count(), 10);
    assert_eq!(out.face_count(), 16);
    assert!(out.face_sizes.iter().all(|&n| n == 3));
    // A valence-3 vertex with Loop's beta = 3/16: 7/16 v + 3/16 Σ neighbours.
    // For (1,1,1) the neighbours sum to (-1,-1,-1): (7 - 3)/16 = 1/4.
    let (_, d) = nearest(&out, [0.25; 3]);
    assert!(d < 1e-15, "vertex point off by {d}");
}

#[test]
fn openmesh_catmull_clark_equals_opensubdiv_on_closed_cube() {
    for level in 1..=3 {
        let osd = opensubdiv_refine(&cube(), &catmark(), level).unwrap();
        let om = openmesh_catmull_clark(&cube(), level).unwrap();
        assert_same_mesh(&osd, &om, 1e-12);
    }
}

#[test]
fn openmesh_loop_equals_opensubdiv_on_icosahedron() {
    for level in 1..=2 {
        let osd = opensubdiv_refine(&icosahedron(), &loop_options(), level).unwrap();
        let om = openmesh_loop(&icosahedron(), level).unwrap();
        assert_eq!(osd.face_count(), 20 * 4usize.pow(level));
        assert_same_mesh(&osd, &om, 1e-12);
    }
}

#[test]
fn openmesh_loop_refuses_quads() {
    let err = openmesh_loop(&cube(), 1).unwrap_err();
    assert!(err.0.contains("face 0 has 4 corners"), "{err}");
}

#[test]
fn fixed_keeps_every_boundary_vertex() {
    let grid = bumpy_quad_grid(3, 3);
    let boundary = boundary_vertices(&grid);
    assert_eq!(boundary.len(), 12);
    let fixed =
        opensubdiv_refine(&grid, &OsdOptions::fixed(Scheme::CatmullClark, &grid), 2).unwrap();
    let smooth = opensubdiv_refine(&grid, &catmark(), 2).unwrap();
    for &v in &boundary {
        let p = grid.position(v as usize);
        let (_, d) = nearest(&fixed, p);
        assert!(d == 0.0, "Fixed moved boundary vertex {v} by {d}");
        let (_, d) = nearest(&smooth, p);
        assert!(d > 1e-3, "Smooth left boundary vertex {v} in place");
    }
    // The interior vertices move in both.
    let (_, d) = nearest(&fixed, grid.position(5));
    assert!(d > 1e-3);
}

#[test]
fn edge_and_corner_keeps_one_face_corners() {
    let grid = bumpy_quad_grid(3, 2);
    let corners = [0usize, 3, 8, 11];
    let edge_and_corner = opensubdiv_refine(
        &grid,
        &OsdOptions::new(Scheme::CatmullClark, BoundaryInterpolation::EdgeAndCorner),
        2,
    )
    .unwrap();
    let edge_only = opensubdiv_refine(&grid, &catmark(), 2).unwrap();
    for v in corners {
        let p = grid.position(v);
        let (_, d) = nearest(&edge_and_corner, p);
        assert!(d == 0.0, "EdgeAndCorner moved corner {v} by {d}");
        let (_, d) = nearest(&edge_only, p);
        assert!(d > 1e-3, "EdgeOnly left corner {v} in place");
    }
    // A boundary vertex with two faces moves in both.
    let (_, d) = nearest(&edge_and_corner, grid.position(1));
    assert!(d > 1e-3);
}

#[test]
fn loop_edge_and_corner_on_open_triangles() {
    // Two triangles of a bent square: vertices 1 and 3 have one face each.
    let mesh = RefMesh::from_polygons(
        &[
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.2],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.3],
        ],
        &[&[0, 1, 2], &[0, 2, 3]],
    );
    let options = OsdOptions::new(Scheme::Loop, BoundaryInterpolation::EdgeAndCorner);
    let out = opensubdiv_refine(&mesh, &options, 1).unwrap();
    assert_eq!((out.vertex_count(), out.face_count()), (9, 8));
    assert_eq!(nearest(&out, mesh.position(1)).1, 0.0);
    assert_eq!(nearest(&out, mesh.position(3)).1, 0.0);
    // Vertex 0 has two faces: B-spline rule (a + 6v + b)/8 along the boundary.
    let expected = [1.0 / 8.0, 1.0 / 8.0, (0.2 + 0.3) / 8.0];
    assert!(nearest(&out, expected).1 < 1e-15);
}

#[test]
fn non_manifold_fin_refines() {
    let out = opensubdiv_refine(&fin(), &catmark(), 2).unwrap();
    // Level 1: 8 + 10 + 3 vertices, 12 quads; level 2: 21 + 32 + 12, 48 quads.
    assert_eq!(out.vertex_count(), 65);
    assert_eq!(out.face_count(), 48);
    assert!(out.positions.iter().all(|x| x.is_finite()));
    // OpenMesh cannot load it, and says so.
    let err = openmesh_catmull_clark(&fin(), 1).unwrap_err();
    assert!(err.0.contains("face 2"), "{err}");
}

#[test]
fn bow_tie_refines_with_loop() {
    let out = opensubdiv_refine(&bow_tie(), &loop_options(), 1).unwrap();
    assert_eq!((out.vertex_count(), out.face_count()), (11, 8));
    assert!(out.positions.iter().all(|x| x.is_finite()));
}

#[test]
fn mixed_polygons_become_quads() {
    // A pentagon and a triangle sharing an edge.
    let mesh = RefMesh::from_polygons(
        &[
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.5, 1.0, 0.0],
            [0.5, 1.5, 0.2],
            [-0.5, 1.0, 0.0],
            [1.0, -1.0, 0.1],
        ],
        &[&[0, 1, 2, 3, 4], &[0, 5, 1]],
    );
    let out = opensubdiv_refine(&mesh, &catmark(), 1).unwrap();
    // V + E + F = 6 + 7 + 2; 5 + 3 quads.
    assert_eq!((out.vertex_count(), out.face_count()), (15, 8));
    assert!(out.face_sizes.iter().all(|&n| n == 4));
}

#[test]
fn bad_input_is_an_error() {
    let mut mesh = cube();
    mesh.face_indices[3] = 8;
    let err = opensubdiv_refine(&mesh, &catmark(), 1).unwrap_err();
    assert!(err.0.contains("face index 3 is vertex 8"), "{err}");

    let mut options = catmark();
    options.crease_edges.push([0, 9]);
    options.crease_sharpness.push(1.0);
    let err = opensubdiv_refine(&cube(), &options, 1).unwrap_err();
    assert!(err.0.contains("crease edge 0"), "{err}");

    let err = opensubdiv_refine(&cube(), &catmark(), 16).unwrap_err();
    assert!(err.0.contains("at most 15"), "{err}");
}

#[test]
fn opensubdiv_reports_its_own_errors() {
    // The Loop scheme refuses quads inside OpenSubdiv; its message comes back.
    let err = opensubdiv_refine(&cube(), &loop_options(), 1).unwrap_err();
    assert!(
        err.0
            .contains("non-triangular faces not supported by Loop scheme"),
        "{err}"
    );
    // A crease on a vertex pair that is not an edge is skipped with a warning.
    let mut options = catmark();
    options.crease_edges.push([0, 7]);
    options.crease_sharpness.push(2.0);
    let creased = opensubdiv_refine(&cube(), &options, 1).unwrap();
    assert_eq!(creased, opensubdiv_refine(&cube(), &catmark(), 1).unwrap());
}

#[test]
fn openmesh_loop_equals_opensubdiv_edge_only_on_open_triangles() {
    // OpenMesh's Loop uses the (1,6,1)/8 boundary rule and midpoints on
    // boundary edges, which is OpenSubdiv's VTX_BOUNDARY_EDGE_ONLY.
    let quads = bumpy_quad_grid(3, 2);
    let triangles: Vec<Vec<u32>> = quads
        .faces()
        .flat_map(|q| [vec![q[0], q[1], q[2]], vec![q[0], q[2], q[3]]])
        .collect();
    let faces: Vec<&[u32]> = triangles.iter().map(|t| t.as_slice()).collect();
    let points: Vec<[f64; 3]> = (0..quads.vertex_count())
        .map(|v| quads.position(v))
        .collect();
    let mesh = RefMesh::from_polygons(&points, &faces);
    for level in 1..=2 {
        let osd = opensubdiv_refine(&mesh, &loop_options(), level).unwrap();
        let om = openmesh_loop(&mesh, level).unwrap();
        assert_same_mesh(&osd, &om, 1e-12);
    }
}
