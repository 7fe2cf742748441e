//! The mending chain on named shapes: join and weld, cull adjacent faces,
//! orientation, planarity, T-nodes and the naked boundary.

use weft::mend::cull::cull_adjacent;
use weft::mend::matching::{match_lines_to_edges, match_points_to_vertices};
use weft::mend::orient::{is_orientable, signed_volume, unify_orientation};
use weft::mend::t_nodes::{find_t_nodes, repair_t_nodes};
use weft::mend::weld::{join, weld, DEFAULT_WELD_TOLERANCE};
use weft::mesh::analysis::{
    is_planar, naked_boundaries, planarity, planarity_deviations, plane_deviation, Planarity,
};
use weft::mesh::shapes;
use weft::subdivide::{catmull_clark, NakedEdges};
use weft::{DVec3, Mesh, MeshInfo, Topology};

fn info(mesh: &Mesh) -> MeshInfo {
    Topology::new(mesh).info(mesh)
}

fn translated(mesh: &Mesh, by: DVec3) -> Mesh {
    mesh.with_positions(mesh.positions().iter().map(|&p| p + by).collect())
        .unwrap()
}

/// A grid of `nx` × `ny` quads facing +z, spanning `width` × `height` from
/// `origin`, with heights from `z(x, y)`.
fn grid(
    nx: usize,
    ny: usize,
    origin: [f64; 2],
    size: [f64; 2],
    z: impl Fn(f64, f64) -> f64,
) -> Mesh {
    let mut positions = Vec::new();
    for j in 0..=ny {
        for i in 0..=nx {
            let x = origin[0] + size[0] * i as f64 / nx as f64;
            let y = origin[1] + size[1] * j as f64 / ny as f64;
            positions.push(DVec3::new(x, y, z(x, y)));
        }
    }
    let id = |i: usize, j: usize| (j * (nx + 1) + i) as u32;
    let faces: Vec<[u32; 4]> = (0..ny)
        .flat_map(|j| {
            (0..nx).map(move |i| [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)])
        })
        .collect();
    Mesh::from_polygons(positions, faces).unwrap()
}

fn join_weld_cull(boxes: &[Mesh]) -> (Mesh, usize) {
    let refs: Vec<&Mesh> = boxes.iter().collect();
    let joined = join(&refs).unwrap();
    assert_eq!(joined.face_count(), 6 * boxes.len());
    let (welded, report) = weld(&joined, DEFAULT_WELD_TOLERANCE).unwrap();
    assert_eq!(report.removed_face_count, 0);
    cull_adjacent(&welded)
}

#[test]
fn two_boxes_sharing_a_face_cull_to_one_closed_box() {
    let boxes = [shapes::cube(), translated(&shapes::cube(), DVec3::X)];
    let (culled, removed) = join_weld_cull(&boxes);
    assert_eq!(removed, 2);
    assert_eq!(culled.face_count(), 10);
    assert_eq!(culled.vertex_count(), 12);
    let info = info(&culled);
    assert!(info.is_closed && info.is_oriented);
    assert_eq!(info.component_count, 1);
    assert!((signed_volume(&culled) - 2.0).abs() < 1e-12);
}

#[test]
fn aggregation_of_27_cubes_culls_to_its_skin() {
    let mut boxes = Vec::new();
    for i in 0..3 {
        for j in 0..3 {
            for k in 0..3 {
                let at = DVec3::new(i as f64, j as f64, k as f64);
                boxes.push(translated(&shapes::cube(), at));
            }
        }
    }
    let (culled, removed) = join_weld_cull(&boxes);
    // 3 directions × 2 inner walls × 3 × 3 cubes, each wall twice.
    assert_eq!(removed, 108);
    assert_eq!(culled.face_count(), 54);
    let info = info(&culled);
    assert!(info.is_closed && info.is_oriented);
    assert_eq!(info.component_count, 1);
    assert_eq!(info.non_manifold_vertex_count, 0);
    assert!((signed_volume(&culled) - 27.0).abs() < 1e-9);
}

#[test]
fn cube_with_three_faces_flipped_comes_back_facing_out() {
    let cube = shapes::cube();
    let faces: Vec<Vec<u32>> = cube
        .faces()
        .enumerate()
        .map(|(f, face)| {
            let mut face = face.to_vec();
            if f % 2 == 0 {
                face.reverse();
            }
            face
        })
        .collect();
    let scrambled = Mesh::from_polygons(cube.positions().to_vec(), faces).unwrap();
    assert!(!info(&scrambled).is_oriented);
    assert!(is_orientable(&scrambled));
    let (fixed, flipped) = unify_orientation(&scrambled);
    assert_eq!(flipped, 3);
    assert!(info(&fixed).is_oriented);
    assert!((signed_volume(&fixed) - 1.0).abs() < 1e-12);
    // Reversed again, each face starts at its old first corner: the cube itself.
    for f in 0..6 {
        let mut expected = cube.face(f).to_vec();
        let rotate = expected
            .iter()
            .position(|&v| v == fixed.face(f)[0])
            .unwrap();
        expected.rotate_left(rotate);
        assert_eq!(fixed.face(f), expected.as_slice());
    }
}

#[test]
fn mobius_strip_is_not_orientable_and_has_one_boundary_loop() {
    let strip = shapes::mobius_strip(8);
    assert!(!is_orientable(&strip));
    let loops = naked_boundaries(&strip);
    assert_eq!(loops.len(), 1);
    assert!(loops[0].closed);
    assert_eq!(loops[0].vertices.len(), 16);
    // Unifying cannot make it consistent, and must not turn it "outward".
    let (unified, _) = unify_orientation(&strip);
    assert!(!info(&unified).is_oriented);
}

#[test]
fn translational_surface_grid_is_planar() {
    // z = f(x) + g(y): z00 + z11 = z10 + z01 on every cell, so each quad is planar.
    let mesh = grid(6, 5, [-1.0, 0.5], [3.0, 2.0], |x, y| x.sin() + 0.3 * y * y);
    let deviations = planarity_deviations(&mesh);
    assert!(deviations.iter().all(|&d| d < 1e-12), "{deviations:?}");
    assert!(is_planar(&mesh, 1e-9).unwrap());
}

#[test]
fn hyperbolic_paraboloid_grid_is_not_planar() {
    // z = xy over [-1.5, 1.5]² in unit cells. The middle cell has corners
    // (∓½, ∓½, ¼) and (±½, ∓½, -¼): their covariance is diag(1, 1, ¼), so
    // the best-fit plane is z = 0 and every corner lies exactly ¼ from it.
    let mesh = grid(3, 3, [-1.5, -1.5], [3.0, 3.0], |x, y| x * y);
    let deviations = planarity_deviations(&mesh);
    assert!((deviations[4] - 0.25).abs() < 1e-12, "{deviations:?}");
    assert!(deviations.iter().all(|&d| d > 0.1 && d <= 0.25 + 1e-12));
    assert!(!is_planar(&mesh, 0.01).unwrap());
    assert!(is_planar(&mesh, 0.3).unwrap());
}

#[test]
fn planarity_on_all_threads_is_each_face_measured_alone() {
    // 120 × 100 cells of a warped surface (several runs of faces per
    // thread), with a row of cells cut into triangles and one pentagon.
    let warped = grid(120, 100, [-2.0, -1.0], [4.0, 3.0], |x, y| {
        0.3 * x * y + 0.1 * (3.0 * x).sin()
    });
    let (positions, mut sizes, mut indices) = warped.into_parts();
    let (quads_in_a_row, split) = (120, 40);
    let row = &indices[4 * split * quads_in_a_row..4 * (split + 1) * quads_in_a_row].to_vec();
    let mut tail: Vec<u32> = row
        .chunks(4)
        .flat_map(|q| [q[0], q[1], q[2], q[0], q[2], q[3]])
        .collect();
    tail.extend_from_slice(&[0, 1, 2, 123, 121]);
    indices.splice(
        4 * split * quads_in_a_row..4 * (split + 1) * quads_in_a_row,
        [],
    );
    sizes.truncate(sizes.len() - quads_in_a_row);
    sizes.extend(std::iter::repeat_n(3, 2 * quads_in_a_row));
    sizes.push(5);
    indices.extend(tail);
    let mesh = Mesh::new(positions, sizes, indices).unwrap();
    let alone: Vec<f64> = (0..mesh.face_count())
        .map(|f| match mesh.face(f).len() {
            3 => 0.0,
            _ => plane_deviation(&mesh.face_positions(f).collect::<Vec<_>>()),
        })
        .collect();
    assert_eq!(planarity_deviations(&mesh), alone);
    let largest = alone.iter().copied().fold(0.0, f64::max);
    assert!(
        largest > 1e-5 && alone[mesh.face_count() - 2] == 0.0,
        "{largest}"
    );
    for tolerance in [0.0, largest / 2.0, largest] {
        let beyond = alone.iter().filter(|&&d| d > tolerance).count();
        assert_eq!(
            planarity(&mesh, tolerance).unwrap(),
            Planarity {
                largest_deviation: largest,
                faces_beyond: beyond
            }
        );
        assert_eq!(is_planar(&mesh, tolerance).unwrap(), beyond == 0);
    }
    assert!(planarity(&mesh, -1.0).is_err() && planarity(&mesh, f64::NAN).is_err());
    let empty = Mesh::new(Vec::new(), Vec::new(), Vec::new()).unwrap();
    assert_eq!(planarity(&empty, 0.0).unwrap().faces_beyond, 0);
}

#[test]
fn hyperbolic_paraboloid_unit_quad_deviation_matches_the_formula() {
    // Corners of z = xy on the unit square: (0,0,0), (1,0,0), (1,1,1), (0,1,0).
    // Centroid (½, ½, ¼); centred corners (-½,-½,-¼), (½,-½,-¼), (½,½,¾),
    // (-½,½,-¼). Their scatter matrix is [[1, 0, ½], [0, 1, ½], [½, ½, ¾]].
    // By the x ↔ y symmetry the normal is (1, 1, b); besides (1, -1, 0)
    // (eigenvalue 1) the eigenvalues solve 4λ² - 7λ + 1 = 0, the smallest
    // λ = (7 - √33)/8, with b = 2(λ - 1) = -(1 + √33)/4, so
    // |n|² = 2 + b² = (66 + 2√33)/16. The corner (0,0,0) is furthest:
    // |(-½,-½,-¼)·n| / |n| = ((15 - √33)/16) / (√(66 + 2√33)/4)
    // = (15 - √33) / (4√(66 + 2√33)) ≈ 0.262855.
    // (The vertical fit z = ½x + ½y - ¼ leaves residuals of exactly ±¼, a
    // perpendicular distance of ¼/√(1 + ¼ + ¼) ≈ 0.2041, but that plane is
    // not the least-squares plane of the perpendicular distances: its sum of
    // squares is 1/6, more than λ = (7 - √33)/8 ≈ 0.1569.)
    let s = 33f64.sqrt();
    let expected = (15.0 - s) / (4.0 * (66.0 + 2.0 * s).sqrt());
    let corners = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(1.0, 1.0, 1.0),
        DVec3::new(0.0, 1.0, 0.0),
    ];
    assert!((plane_deviation(&corners) - expected).abs() < 1e-12);
    assert!((expected - 0.262855).abs() < 1e-6);
    // Moved far away and turned, the deviation stays.
    let far: Vec<DVec3> = corners
        .iter()
        .map(|p| DVec3::new(p.z, p.x, p.y) + DVec3::new(1e5, -2e5, 3e4))
        .collect();
    assert!((plane_deviation(&far) - expected).abs() < 1e-9);
}

#[test]
fn closed_is_told_per_component() {
    let cube = shapes::cube();
    let grid = shapes::quad_grid(3, 2);
    let fin = shapes::fin();
    // Components are numbered by their first face: the order of the parts.
    for (parts, expected) in [
        (vec![&cube, &grid], vec![true, false]),
        (vec![&grid, &cube], vec![false, true]),
        (vec![&cube, &fin, &cube], vec![true, false, true]),
    ] {
        let mesh = join(&parts).unwrap();
        let topology = Topology::new(&mesh);
        assert_eq!(topology.component_closed(), expected);
        let (faces, count) = topology.face_components();
        assert_eq!(count, expected.len());
        // The cube's faces all lie in one closed component.
        let first_cube = if std::ptr::eq(parts[0], &cube) {
            0
        } else {
            grid.face_count()
        };
        assert!(expected[faces[first_cube] as usize]);
        // The whole mesh is not closed, though one piece is.
        assert!(!topology.info(&mesh).is_closed);
    }
    // A mesh of closed pieces only is closed, piece by piece and as a whole.
    let two_cubes = join(&[&cube, &cube]).unwrap();
    let topology = Topology::new(&two_cubes);
    assert_eq!(topology.component_closed(), vec![true, true]);
    assert!(topology.info(&two_cubes).is_closed);
    // No faces, no components.
    assert!(Topology::new(&Mesh::empty()).component_closed().is_empty());
}

#[test]
fn weld_merges_chains_drops_collapsed_faces_and_is_idempotent() {
    // A strip of triangles whose loose copies are welded back.
    let strip = shapes::triangle_grid(5, 1);
    let copies: Vec<Mesh> = (0..strip.face_count())
        .map(|f| {
            let corners: Vec<DVec3> = strip.face_positions(f).collect();
            Mesh::from_polygons(corners, [[0u32, 1, 2]]).unwrap()
        })
        .collect();
    let refs: Vec<&Mesh> = copies.iter().collect();
    let loose = join(&refs).unwrap();
    assert_eq!(loose.vertex_count(), 30);
    let (welded, report) = weld(&loose, DEFAULT_WELD_TOLERANCE).unwrap();
    assert_eq!(welded.vertex_count(), 12);
    assert_eq!(report.merged_vertex_count, 18);
    assert_eq!(info(&welded).component_count, 1);
    assert_eq!(weld(&welded, DEFAULT_WELD_TOLERANCE).unwrap().0, welded);

    // A chain of points 0.4 apart merges whole under a tolerance of 0.5;
    // the thin triangles across it collapse to two vertices and go.
    let mut positions: Vec<DVec3> = (0..5)
        .map(|i| DVec3::new(0.4 * i as f64, 0.0, 0.0))
        .collect();
    positions.push(DVec3::new(0.0, 3.0, 0.0));
    positions.push(DVec3::new(3.0, 3.0, 0.0));
    let mesh = Mesh::from_polygons(
        positions,
        [
            vec![0, 6, 5],
            vec![1, 2, 5],
            vec![4, 3, 6],
            vec![0, 4, 6, 5],
        ],
    )
    .unwrap();
    let (welded, report) = weld(&mesh, 0.5).unwrap();
    assert_eq!(report.merged_vertex_count, 4);
    assert_eq!(report.removed_face_count, 2);
    assert_eq!(welded.face_count(), 2);
    assert_eq!(welded.face(0), &[0, 2, 1]);
    assert_eq!(welded.face(1), &[0, 2, 1]); // the quad lost its merged corner
    assert_eq!(welded.positions()[0], DVec3::ZERO);
}

/// At tolerance 0 only identical positions merge, and -0 is the same
/// position as +0 even when other vertices sort between them.
#[test]
fn weld_at_tolerance_zero_merges_identical_positions_and_signed_zeros() {
    let positions = vec![
        DVec3::new(-0.0, 1.0, 0.0),
        DVec3::new(-0.0, 2.0, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(1.0, 1.0, 1e-300),
    ];
    let mesh = Mesh::from_polygons(positions, [[0u32, 2, 1], [3, 4, 5]]).unwrap();
    let (welded, report) = weld(&mesh, 0.0).unwrap();
    assert_eq!(report.merged_vertex_count, 2);
    assert_eq!(welded.vertex_count(), 4);
    assert_eq!(welded.face(0), &[0, 2, 1]);
    assert_eq!(welded.face(1), &[0, 2, 3]);
    // The merged vertex keeps its first vertex's position, sign and all.
    assert!(welded.positions()[0].x.is_sign_negative());
}

#[test]
fn t_nodes_between_grids_of_4x4_and_4x7_quads_are_found_and_repaired() {
    let left = grid(4, 4, [0.0, 0.0], [4.0, 4.0], |_, _| 0.0);
    let right = grid(4, 7, [4.0, 0.0], [4.0, 4.0], |_, _| 0.0);
    let (mesh, report) = weld(&join(&[&left, &right]).unwrap(), DEFAULT_WELD_TOLERANCE).unwrap();
    // Only the seam's two ends coincide.
    assert_eq!(report.merged_vertex_count, 2);
    assert_eq!(info(&mesh).component_count, 2);

    let nodes = find_t_nodes(&mesh, DEFAULT_WELD_TOLERANCE).unwrap();
    assert_eq!(nodes.len(), 9);
    let on_left: Vec<f64> = nodes
        .iter()
        .filter(|n| n.face < 16)
        .map(|n| n.parameter)
        .collect();
    let on_right: Vec<f64> = nodes
        .iter()
        .filter(|n| n.face >= 16)
        .map(|n| n.parameter)
        .collect();
    // The right grid's seam vertices at y = 4k/7 fall in the left's edges
    // from (4, j) up to (4, j + 1) at t = 4k/7 - j = (4k mod 7)/7, in the
    // order k = 1, 2, …, 6: 4/7, 1/7, 5/7, 2/7, 6/7, 3/7.
    let expected: Vec<f64> = [4.0, 1.0, 5.0, 2.0, 6.0, 3.0]
        .iter()
        .map(|k| k / 7.0)
        .collect();
    assert_eq!(on_left.len(), 6);
    for (t, e) in on_left.iter().zip(&expected) {
        assert!((t - e).abs() < 1e-12, "{on_left:?}");
    }
    // The left's seam vertices y = 1, 2, 3 fall in the right's edges that
    // run down from y = 8/7, 16/7, 24/7: t = (8/7 - 1)/(4/7) = ¼, then ½, ¾.
    assert_eq!(on_right.len(), 3);
    for (t, e) in on_right.iter().zip([0.25, 0.5, 0.75]) {
        assert!((t - e).abs() < 1e-12, "{on_right:?}");
    }
    for n in &nodes {
        let p = mesh.positions()[n.vertex as usize];
        let [a, b] = n.edge.map(|v| mesh.positions()[v as usize]);
        assert!(p.distance(a.lerp(b, n.parameter)) < 1e-12);
        let face = mesh.face(n.face as usize);
        let runs_edge = (0..face.len()).any(|i| [face[i], face[(i + 1) % face.len()]] == n.edge);
        assert!(runs_edge, "{n:?}");
    }

    let (repaired, inserted) = repair_t_nodes(&mesh, DEFAULT_WELD_TOLERANCE).unwrap();
    assert_eq!(inserted, 9);
    assert_eq!(repaired.face_count(), 16 + 28);
    let repaired_info = info(&repaired);
    assert_eq!(repaired_info.component_count, 1);
    assert!(repaired_info.is_oriented);
    // Only the outer border is naked: 4 + 4 along the bottom and the top,
    // 4 on the left, 7 on the right. Nothing along the seam x = 4.
    assert_eq!(repaired_info.naked_edge_count, 27);
    let loops = naked_boundaries(&repaired);
    assert_eq!(loops.len(), 1);
    let points = loops[0].points(&repaired);
    let on_seam = (0..points.len())
        .filter(|&i| points[i].x == 4.0 && points[(i + 1) % points.len()].x == 4.0)
        .count();
    assert_eq!(on_seam, 0);
    // The seam faces became n-gons: a left column face gains the right's seam vertices.
    assert_eq!(repaired.face_sizes()[3], 5); // (3..4) × (0..1) gains y = 4/7
    assert!(find_t_nodes(&repaired, DEFAULT_WELD_TOLERANCE)
        .unwrap()
        .is_empty());
    // Catmull-Clark now sees one surface: one piece, and no naked edge along the seam.
    let smooth = catmull_clark(&repaired, 2, NakedEdges::Fixed).unwrap();
    let smooth_info = info(&smooth);
    assert_eq!(smooth_info.component_count, 1);
    assert!(smooth_info.is_oriented);
    assert_eq!(smooth_info.naked_edge_count, 27 * 4);
    let seam_naked = naked_boundaries(&smooth)
        .iter()
        .flat_map(|l| {
            let p = l.points(&smooth);
            (0..p.len())
                .filter(|&i| {
                    (p[i].x - 4.0).abs() < 1e-12 && (p[(i + 1) % p.len()].x - 4.0).abs() < 1e-12
                })
                .map(|i| (p[i].y, p[(i + 1) % p.len()].y))
                .collect::<Vec<_>>()
        })
        // The seam runs from y = 0 to 4 inside; only the border's own ends may touch x = 4.
        .filter(|&(a, b)| a.min(b) > 1e-12 && a.max(b) < 4.0 - 1e-12)
        .count();
    assert_eq!(seam_naked, 0);
    // Without the repair the same grids subdivide as two pieces split along the seam.
    let unrepaired = catmull_clark(&mesh, 1, NakedEdges::Fixed).unwrap();
    assert_eq!(info(&unrepaired).component_count, 2);
}

#[test]
fn empty_and_faceless_meshes_pass_through_every_operation() {
    let lone_points = Mesh::new(vec![DVec3::ZERO, DVec3::ZERO], vec![], vec![]).unwrap();
    for mesh in [Mesh::empty(), lone_points] {
        let (welded, report) = weld(&mesh, DEFAULT_WELD_TOLERANCE).unwrap();
        assert_eq!(welded, Mesh::empty());
        assert_eq!(
            report.merged_vertex_count + report.unused_vertex_count,
            mesh.vertex_count()
        );
        assert_eq!(cull_adjacent(&mesh), (mesh.clone(), 0));
        assert_eq!(unify_orientation(&mesh), (mesh.clone(), 0));
        assert!(find_t_nodes(&mesh, 0.0).unwrap().is_empty());
        assert!(naked_boundaries(&mesh).is_empty());
        assert!(planarity_deviations(&mesh).is_empty());
        assert!(is_planar(&mesh, 0.0).unwrap());
        assert!(is_orientable(&mesh));
    }
}

#[test]
fn points_match_their_nearest_vertex_within_the_tolerance() {
    let cube = shapes::cube();
    let corners = cube.positions();
    // Each point a little off a corner, one nearer to corner 6 than to any other.
    let points: Vec<DVec3> = [3usize, 0, 6, 5]
        .iter()
        .map(|&v| corners[v] + DVec3::new(0.01, -0.02, 0.015))
        .collect();
    let found = match_points_to_vertices(&cube, &points, 0.05).unwrap();
    assert_eq!(found, vec![3, 0, 6, 5]);
    // Two vertices within reach: the nearer wins whatever its index.
    let mut close = Mesh::new(
        vec![
            DVec3::ZERO,
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(0.3, 0.0, 0.0),
        ],
        vec![3, 3],
        vec![0, 1, 2, 3, 1, 2],
    )
    .unwrap();
    assert_eq!(
        match_points_to_vertices(&close, &[DVec3::new(0.2, 0.0, 0.0)], 0.5).unwrap(),
        vec![3]
    );
    // Equally near: the lower index.
    close.positions_mut()[3] = DVec3::new(0.4, 0.0, 0.0);
    assert_eq!(
        match_points_to_vertices(&close, &[DVec3::new(0.2, 0.0, 0.0)], 0.5).unwrap(),
        vec![0]
    );
    // Tolerance 0 still finds an exact hit.
    assert_eq!(
        match_points_to_vertices(&cube, &[corners[7]], 0.0).unwrap(),
        vec![7]
    );
}

#[test]
fn a_point_with_no_vertex_in_reach_is_named() {
    let cube = shapes::cube();
    let points = [cube.positions()[1], DVec3::new(0.5, 0.5, 3.0)];
    let error = match_points_to_vertices(&cube, &points, 0.1).unwrap_err();
    let message = error.to_string();
    assert!(
        message.contains("point 1 at (0.5, 0.5, 3) is no vertex of the mesh within 0.1"),
        "{message}"
    );
    for tolerance in [-1.0, f64::NAN, f64::INFINITY] {
        let message = match_points_to_vertices(&cube, &points, tolerance)
            .unwrap_err()
            .to_string();
        assert!(message.contains("tolerance is"), "{message}");
    }
    let message = match_points_to_vertices(&cube, &[DVec3::new(f64::NAN, 0.0, 0.0)], 0.1)
        .unwrap_err()
        .to_string();
    assert!(message.contains("point 0 is (NaN, 0, 0)"), "{message}");
    // A point so far away that its grid cell passes the end of i64 simply
    // finds nothing.
    let far = DVec3::new(1e300, -1e300, 1e300);
    let message = match_points_to_vertices(&cube, &[far], 0.0)
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("point 0 at (1000000000000000") && message.contains("is no vertex"),
        "{message}"
    );
}

#[test]
fn lines_match_edges_in_their_own_direction() {
    let grid = shapes::quad_grid(2, 2);
    let p = grid.positions();
    let topology = Topology::new(&grid);
    let wobble = DVec3::new(0.01, 0.01, 0.0);
    let [a, b] = topology.edges()[3];
    let lines = [
        [p[a as usize] + wobble, p[b as usize] - wobble],
        [p[b as usize], p[a as usize]],
    ];
    let pairs = match_lines_to_edges(&grid, &lines, 0.05).unwrap();
    assert_eq!(pairs, vec![[a, b], [b, a]]);
    for &[u, v] in &pairs {
        assert!(topology.find_edge(u, v).is_some());
    }
}

#[test]
fn with_several_vertices_in_reach_the_pair_that_is_an_edge_wins() {
    // Vertices 0 and 3 sit close together at the line's start, but only 3 is
    // joined to vertex 1 at its end; 0 is nearer to the start.
    let mesh = Mesh::new(
        vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.05, 0.0, 0.0),
            DVec3::new(0.0, -1.0, 0.0),
        ],
        vec![3, 3],
        vec![3, 1, 2, 0, 4, 3],
    )
    .unwrap();
    let line = [[DVec3::new(-0.01, 0.0, 0.0), DVec3::new(1.0, 0.0, 0.0)]];
    assert_eq!(
        match_lines_to_edges(&mesh, &line, 0.1).unwrap(),
        vec![[3, 1]]
    );
    // Both 0-3 and 3-0 are edges; the nearer pair to the line's ends wins.
    let line = [[DVec3::new(0.06, 0.0, 0.0), DVec3::new(-0.01, 0.0, 0.0)]];
    assert_eq!(
        match_lines_to_edges(&mesh, &line, 0.1).unwrap(),
        vec![[3, 0]]
    );
}

#[test]
fn a_line_matching_no_edge_is_named_with_its_reason() {
    let grid = shapes::quad_grid(2, 2);
    let p = grid.positions();
    // Vertices 0 and 4 are corners of one quad but not the ends of an edge.
    let diagonal = [p[0], p[4]];
    let message = match_lines_to_edges(&grid, &[[p[0], p[1]], diagonal], 0.01)
        .unwrap_err()
        .to_string();
    assert!(message.contains("line 1 from"), "{message}");
    assert!(
        message.contains("matches no edge of the mesh within 0.01: its ends are vertices but not the ends of one edge"),
        "{message}"
    );
    let off = [p[0], DVec3::new(9.0, 9.0, 9.0)];
    let message = match_lines_to_edges(&grid, &[off], 0.01)
        .unwrap_err()
        .to_string();
    assert!(message.contains("line 0 from"), "{message}");
    assert!(
        message.contains("its end is no vertex of the mesh"),
        "{message}"
    );
    let message = match_lines_to_edges(&grid, &[[off[1], off[0]]], 0.01)
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("its start is no vertex of the mesh"),
        "{message}"
    );
    assert!(match_lines_to_edges(&grid, &[], -1.0).is_err());
}
