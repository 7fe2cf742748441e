//! One test per input that fuzzing found to break an operation, on the small
//! mesh that triggered it, asserting the behaviour now defined for it. The
//! inputs themselves stay in `fuzz/corpus/operations/`.

use weft::{DVec3, Mesh};

fn mesh(positions: &[[f64; 3]], faces: &[&[u32]]) -> Mesh {
    let positions = positions.iter().map(|&p| DVec3::from_array(p)).collect();
    Mesh::from_polygons(positions, faces).unwrap()
}

/// Rebuilds the mesh through the checking constructor: every face has
/// distinct in-range corners and every coordinate is finite.
fn assert_valid(m: &Mesh) {
    let rebuilt = Mesh::new(
        m.positions().to_vec(),
        m.face_sizes().to_vec(),
        m.face_indices().to_vec(),
    );
    assert_eq!(rebuilt.as_ref().err(), None);
}

/// Three faces on four points: edge 0-1 has three faces, edge 3-0 two faces
/// running it the same way. Vertex 1's fan of faces 2 and 1 starts and ends
/// at the non-manifold edge 0-1, whose midpoint its polygon used twice.
#[test]
fn midedge_fan_around_a_non_manifold_edge_uses_its_midpoint_once() {
    let m = mesh(
        &[
            [-15.5, -15.873046875, -15.6201171875],
            [-15.494140625, -15.1171875, -14.861328125],
            [-14.109375, -16.0, -16.0],
            [-13.857421875, -13.60546875, -15.875],
        ],
        &[&[3, 0, 1], &[3, 0, 1, 2], &[1, 0, 2]],
    );
    let once = weft::split::midedge(&m, 1).unwrap();
    assert_valid(&once);
    // 6 edge midpoints and the 4 vertices kept at broken fans; 3 face
    // polygons and 8 vertex polygons.
    assert_eq!(once.vertex_count(), 10);
    assert_eq!(once.face_count(), 11);
    // Midpoint 0 is edge 0-1, 3 is edge 1-2, 7 is vertex 1 kept.
    assert!(once.faces().any(|f| f == [0, 3, 7]));
    let twice = weft::split::midedge(&m, 2).unwrap();
    assert_valid(&twice);
    assert_eq!(twice.face_count(), 32);
}

/// `weft_platonic` with a radius of 1e300: the hull was searched at that
/// scale, where the cross products overflow to infinity, no plane had the
/// points on one side, and an empty corner list was indexed (a panic). The
/// faces are now found on the unit solid and scaled afterwards.
#[test]
fn platonic_solids_at_extreme_radii() {
    use weft::primitives::{platonic, Platonic};
    let expected = [
        (Platonic::Tetrahedron, 4, 4),
        (Platonic::Hexahedron, 8, 6),
        (Platonic::Octahedron, 6, 8),
        (Platonic::Dodecahedron, 20, 12),
        (Platonic::Icosahedron, 12, 20),
    ];
    for radius in [1e300, f64::MAX, 1e-300] {
        for (kind, vertices, faces) in expected {
            let solid = platonic(kind, radius).unwrap();
            assert_valid(&solid);
            assert_eq!(solid.vertex_count(), vertices, "{kind:?} at {radius}");
            assert_eq!(solid.face_count(), faces, "{kind:?} at {radius}");
            assert_eq!(
                solid.face_indices(),
                platonic(kind, 1.0).unwrap().face_indices()
            );
            for p in solid.positions() {
                let relative = (p / radius).length();
                assert!((relative - 1.0).abs() < 1e-12, "{kind:?} at {radius}");
            }
        }
    }
}

/// A triangle fan whose coordinates are near `f64::MAX`: the sums inside
/// smoothing, offset and the dual's rescaling overflow to infinity, which
/// used to come back as a mesh with infinite coordinates.
fn huge_fan() -> Mesh {
    let big = 1.5e308;
    mesh(
        &[
            [0.0, 0.0, 0.0],
            [big, 0.0, 0.0],
            [big, big, 0.0],
            [0.0, big, 0.0],
            [-big, big, 0.0],
        ],
        &[&[0, 1, 2], &[0, 2, 3], &[0, 3, 4]],
    )
}

fn assert_degenerate_naming_a_vertex(result: weft::Result<Mesh>) {
    match result {
        Err(weft::Error::DegenerateInput(message)) => {
            assert!(message.contains("vertex"), "{message}")
        }
        Err(other) => panic!("unexpected error: {other}"),
        Ok(m) => panic!("accepted with positions {:?}", m.positions()),
    }
}

#[test]
fn overflowing_coordinates_are_refused_not_returned() {
    use weft::smooth::{laplacian, laplacian_hc, NakedEdges};
    use weft::transform::{offset, OffsetType};
    let fan = huge_fan();
    assert_degenerate_naming_a_vertex(laplacian(&fan, 1, 1.0, NakedEdges::Smooth));
    assert_degenerate_naming_a_vertex(laplacian_hc(&fan, 1, 0.5, 0.5, NakedEdges::Smooth));
    // A triangle far along its own normal, offset further.
    let far = mesh(
        &[
            [0.0, 0.0, 1.5e308],
            [1.0, 0.0, 1.5e308],
            [0.0, 1.0, 1.5e308],
        ],
        &[&[0, 1, 2]],
    );
    assert_degenerate_naming_a_vertex(offset(&far, 1e308, OffsetType::Diagonal));
    assert_degenerate_naming_a_vertex(weft::transform::thicken(&far, 1e308, OffsetType::Diagonal));
    // The same shape at an ordinary scale smooths and offsets as before.
    let small = fan.with_positions(fan.positions().iter().map(|p| *p * 1e-300).collect());
    let small = small.unwrap();
    assert_valid(&laplacian(&small, 1, 1.0, NakedEdges::Smooth).unwrap());
    assert_valid(&offset(&small, 1.0, OffsetType::Diagonal).unwrap());
}

/// `weft_repair_t_nodes` with tolerance 0 on two triangles whose
/// coordinates are near 1e-300: the mean naked-edge length, the cell size
/// of the edge grid, squared to 0, the cells fell to 2^-40 of the
/// coordinates, and listing the cells each edge crosses ran out of memory.
/// The grid now coarsens until the edges cross a linear number of cells.
#[test]
fn t_nodes_at_tiny_coordinates_stay_linear() {
    let tiny = |p: [f64; 3]| p.map(|c| c * 1e-300);
    let m = mesh(
        &[
            tiny([-10.96484375, -15.9990234375, -14.6123046875]),
            tiny([-15.458984375, -10.623046875, -15.333984375]),
            tiny([5.416015625, 5.416015625, 5.25]),
            tiny([-15.998046875, -15.767578125, -13.4794921875]),
        ],
        &[&[1, 2, 3], &[1, 0, 2]],
    );
    let (repaired, inserted) = weft::t_nodes::repair_t_nodes(&m, 0.0).unwrap();
    assert_eq!(inserted, 0);
    assert_eq!(repaired, m);
    // A vertex in the middle of a naked edge is still found at that scale.
    let seam = mesh(
        &[
            tiny([0.0, 0.0, 0.0]),
            tiny([2.0, 0.0, 0.0]),
            tiny([1.0, 1.0, 0.0]),
            tiny([1.0, 0.0, 0.0]),
            tiny([0.0, -1.0, 0.0]),
            tiny([2.0, -1.0, 0.0]),
        ],
        &[&[0, 1, 2], &[4, 5, 1, 3, 0]],
    );
    let nodes = weft::t_nodes::find_t_nodes(&seam, 1e-310).unwrap();
    assert_eq!(nodes.len(), 1);
    assert_eq!((nodes[0].vertex, nodes[0].edge), (3, [0, 1]));
}

/// Weld compared squared distances: near 1e-300 they underflow to 0 and
/// near 1e300 they overflow to infinity, so two vertices 1.5 tolerances
/// apart were welded at both ends of the range.
#[test]
fn weld_keeps_its_meaning_at_extreme_scales() {
    for scale in [1e-300, 1.0, 1e300] {
        let strip = mesh(
            &[
                [0.0, 0.0, 0.0],
                [1.5 * scale, 0.0, 0.0],
                [0.0, 1.5 * scale, 0.0],
                [1.5 * scale, 1.5 * scale, 0.0],
            ],
            &[&[0, 1, 2], &[2, 1, 3]],
        );
        let (welded, _) = weft::weld::weld(&strip, scale).unwrap();
        assert_eq!(welded, strip, "at scale {scale:e}");
        // 1.6 tolerances: the 1.5 edges weld, every face collapses.
        let (welded, _) = weft::weld::weld(&strip, 1.6 * scale).unwrap();
        assert_eq!(welded.face_count(), 0, "at scale {scale:e}");
    }
}

/// Found by fuzzing, in `src/subdivide/` (being reworked on other branches,
/// so not fixed here): two levels of Catmull-Clark on three faces whose
/// coordinates are near 1.6e307 return a vertex at -inf. The rules sum
/// several positions before dividing (face points: Σ corners / n; the
/// vertex rule: (Q + 2R + (n − 3)S) / n), and the sum passes `f64::MAX`
/// although the average would not. Fix: average relative to one of the
/// points (S + ((Q − S) + 2(R − S)) / n), or check the result's finiteness
/// and return `DegenerateInput` naming the vertex. Meanwhile the C ABI
/// refuses such a result (see `weft_catmull_clark`).
#[test]
#[ignore = "overflow in src/subdivide, reported to its owners"]
fn catmull_clark_near_f64_max_stays_finite() {
    use weft::subdivide::{catmull_clark, NakedEdges};
    let m = mesh(
        &[
            [-15.5, -15.873046875, -15.62109375],
            [-15.369140625, -15.1171875, -14.4892578125],
            [-14.865234375, -14.298828125, -14.109375],
            [-13.857421875, -13.4482421875, -15.5],
            [-11.7490234375, -15.6171875, -15.494140625],
            [15.263671875, -15.1162109375, -14.7470703125],
        ]
        .map(|p| p.map(|c| c * 1e306)),
        &[&[2, 5, 4, 3], &[2, 3, 4], &[2, 1, 0, 3, 4, 5]],
    );
    match catmull_clark(&m, 2, NakedEdges::Fixed) {
        Ok(smooth) => assert_valid(&smooth),
        Err(e) => assert!(matches!(e, weft::Error::DegenerateInput(_)), "{e}"),
    }
}

/// The readers' fuzz target: a text STL with a coordinate of 1.9e89 read
/// fine, but binary STL stores `f32`, so writing it produced an infinite
/// coordinate and the file could not be read back. Binary STL now refuses
/// such a mesh, naming the vertex; text STL keeps every digit.
#[test]
fn binary_stl_refuses_coordinates_beyond_f32() {
    use weft::io::{parse_mesh, stl, Format};
    let m = mesh(
        &[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.9e89, 0.0]],
        &[&[0, 1, 2]],
    );
    let mut binary = Vec::new();
    let error = stl::write(&mut binary, &m, false).unwrap_err();
    assert_eq!(error.kind(), std::io::ErrorKind::InvalidInput);
    assert!(error.to_string().contains("vertex 2"), "{error}");
    let mut text = Vec::new();
    stl::write(&mut text, &m, true).unwrap();
    let again = parse_mesh(Format::Stl, &text).unwrap();
    assert_eq!(again.positions()[2].y, 1.9e89);
}
