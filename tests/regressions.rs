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
    let once = weft::toolbar::split::midedge(&m, 1).unwrap();
    assert_valid(&once);
    // 6 edge midpoints and the 4 vertices kept at broken fans; 3 face
    // polygons and 8 vertex polygons.
    assert_eq!(once.vertex_count(), 10);
    assert_eq!(once.face_count(), 11);
    // Midpoint 0 is edge 0-1, 3 is edge 1-2, 7 is vertex 1 kept.
    assert!(once.faces().any(|f| f == [0, 3, 7]));
    let twice = weft::toolbar::split::midedge(&m, 2).unwrap();
    assert_valid(&twice);
    assert_eq!(twice.face_count(), 32);
}

/// `weft_platonic` with a radius of 1e300: the hull was searched at that
/// scale, where the cross products overflow to infinity, no plane had the
/// points on one side, and an empty corner list was indexed (a panic). The
/// faces are now found on the unit solid and scaled afterwards.
#[test]
fn platonic_solids_at_extreme_radii() {
    use weft::make::primitives::{platonic, Platonic};
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
    use weft::toolbar::smooth::{laplacian, laplacian_hc, NakedEdges};
    use weft::toolbar::transform::{offset, OffsetType};
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
    assert_degenerate_naming_a_vertex(weft::toolbar::transform::thicken(
        &far,
        1e308,
        OffsetType::Diagonal,
    ));
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
    let (repaired, inserted) = weft::mend::t_nodes::repair_t_nodes(&m, 0.0).unwrap();
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
    let nodes = weft::mend::t_nodes::find_t_nodes(&seam, 1e-310).unwrap();
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
        let (welded, _) = weft::mend::weld::weld(&strip, scale).unwrap();
        assert_eq!(welded, strip, "at scale {scale:e}");
        // 1.6 tolerances: the 1.5 edges weld, every face collapses.
        let (welded, _) = weft::mend::weld::weld(&strip, 1.6 * scale).unwrap();
        assert_eq!(welded.face_count(), 0, "at scale {scale:e}");
    }
}

/// Found by fuzzing: two levels of Catmull-Clark on three faces whose
/// coordinates are near 1.6e307 returned a vertex at -inf. The rules sum
/// several positions before dividing (face points: Σ corners / n; the
/// vertex rule: (Q + 2R + (n − 3)S) / n), and the sum passed `f64::MAX`
/// although the average would not. Positions past 2^960 are now subdivided
/// at an exactly scaled-down size (a power of two) and scaled back.
#[test]
fn catmull_clark_near_f64_max_stays_finite() {
    use weft::subdivide::{catmull_clark, NakedEdges};
    let m = near_max_cage(|c| c * 1e306);
    let smooth = catmull_clark(&m, 2, NakedEdges::Fixed).unwrap();
    assert_valid(&smooth);
    assert_eq!(smooth.face_count(), 4 * (4 + 3 + 6));
    // Every rule is a convex combination here: the result stays in the cage's box.
    let (low, high) = m.bounding_box().unwrap();
    for p in smooth.positions() {
        assert!(p.cmpge(low).all() && p.cmple(high).all(), "{p}");
    }
}

/// The cage of the test above, its coordinates mapped by `scale`.
fn near_max_cage(scale: impl Fn(f64) -> f64) -> Mesh {
    mesh(
        &[
            [-15.5, -15.873046875, -15.62109375],
            [-15.369140625, -15.1171875, -14.4892578125],
            [-14.865234375, -14.298828125, -14.109375],
            [-13.857421875, -13.4482421875, -15.5],
            [-11.7490234375, -15.6171875, -15.494140625],
            [15.263671875, -15.1162109375, -14.7470703125],
        ]
        .map(|p| p.map(&scale)),
        &[&[2, 5, 4, 3], &[2, 3, 4], &[2, 1, 0, 3, 4, 5]],
    )
}

/// 2^1019: the cage's coordinates (up to 16 = 2^4) times this reach 2^1023,
/// the top binade of `f64`.
const HUGE: f64 = 5.617791046444737e306;

fn scaled_points(points: &[DVec3], factor: f64) -> Vec<DVec3> {
    points.iter().map(|p| *p * factor).collect()
}

/// Subdivision commutes exactly with scaling by a power of two, so the huge
/// cage's result is the ordinary cage's result times 2^1019, bit for bit —
/// for both schemes, the refiner, creases, carried data, face-varying
/// values and the limit.
#[test]
fn subdivision_at_the_top_of_the_f64_range_is_exactly_the_scaled_result() {
    use weft::subdivide::{
        catmull_clark, loop_subdivision, FaceVaryingLinear, NakedEdges, Refiner, Scheme,
        Subdivider, SubdivisionOptions, SHARPNESS_INFINITE,
    };
    assert_eq!(HUGE, 2f64.powi(1019));
    let ordinary = near_max_cage(|c| c);
    let huge = near_max_cage(|c| c * HUGE);
    for mode in [
        NakedEdges::Fixed,
        NakedEdges::Smooth,
        NakedEdges::CornerFixed,
    ] {
        let expected = catmull_clark(&ordinary, 3, mode).unwrap();
        let got = catmull_clark(&huge, 3, mode).unwrap();
        assert_eq!(got.positions(), scaled_points(expected.positions(), HUGE));
        assert_eq!(got.face_indices(), expected.face_indices());
    }
    let triangles = weft::mesh::triangulate::triangulate(&ordinary)
        .unwrap()
        .mesh;
    let huge_triangles = triangles
        .with_positions(scaled_points(triangles.positions(), HUGE))
        .unwrap();
    let expected = loop_subdivision(&triangles, 3, NakedEdges::Smooth).unwrap();
    let got = loop_subdivision(&huge_triangles, 3, NakedEdges::Smooth).unwrap();
    assert_eq!(got.positions(), scaled_points(expected.positions(), HUGE));

    // The refiner, built on the ordinary cage, evaluated at the huge one.
    let refiner = Refiner::new(&ordinary, Scheme::CatmullClark, 2, NakedEdges::Smooth).unwrap();
    let mut at_ordinary = vec![DVec3::ZERO; refiner.vertex_count()];
    refiner
        .evaluate(ordinary.positions(), &mut at_ordinary)
        .unwrap();
    let mut at_huge = vec![DVec3::ZERO; refiner.vertex_count()];
    refiner.evaluate(huge.positions(), &mut at_huge).unwrap();
    assert_eq!(at_huge, scaled_points(&at_ordinary, HUGE));
    assert_eq!(
        Refiner::new(&huge, Scheme::CatmullClark, 2, NakedEdges::Smooth)
            .unwrap()
            .mesh()
            .unwrap()
            .positions(),
        &at_huge[..]
    );

    // Creases, carried data, face-varying values and the limit.
    let mut options = SubdivisionOptions::new(NakedEdges::Smooth);
    options.creases = vec![([2, 3], 1.5), ([3, 4], SHARPNESS_INFINITE)];
    options.corners = vec![(5, 2.0)];
    for scheme in [Scheme::CatmullClark, Scheme::Loop] {
        let (small, big) = match scheme {
            Scheme::CatmullClark => (&ordinary, &huge),
            Scheme::Loop => (&triangles, &huge_triangles),
        };
        let subdivider = Subdivider::new(small, scheme, 2, &options).unwrap();
        let expected = subdivider.mesh().unwrap();
        let mut got = vec![DVec3::ZERO; subdivider.vertex_count()];
        subdivider.evaluate(big.positions(), &mut got).unwrap();
        assert_eq!(got, scaled_points(expected.positions(), HUGE), "{scheme:?}");
        let refiner = Refiner::with_options(small, scheme, 2, &options).unwrap();
        refiner.evaluate(big.positions(), &mut got).unwrap();
        assert_eq!(got, scaled_points(expected.positions(), HUGE), "{scheme:?}");

        let data: Vec<f64> = (0..small.vertex_count() * 2)
            .map(|i| (i as f64 - 5.5) * 1.25)
            .collect();
        let huge_data: Vec<f64> = data.iter().map(|x| x * HUGE).collect();
        let expected = subdivider.vertex_data(&data, 2).unwrap();
        let got = subdivider.vertex_data(&huge_data, 2).unwrap();
        assert_eq!(got, expected.iter().map(|x| x * HUGE).collect::<Vec<_>>());

        // One UV per face corner: every edge a seam.
        let indices: Vec<u32> = (0..small.index_count() as u32).collect();
        let uvs: Vec<f64> = (0..2 * indices.len())
            .map(|i| (i % 7) as f64 * 2.5)
            .collect();
        let huge_uvs: Vec<f64> = uvs.iter().map(|x| x * HUGE).collect();
        let expected = subdivider
            .face_varying(&uvs, 2, &indices, FaceVaryingLinear::Smooth)
            .unwrap();
        let got = subdivider
            .face_varying(&huge_uvs, 2, &indices, FaceVaryingLinear::Smooth)
            .unwrap();
        assert_eq!(got, expected.iter().map(|x| x * HUGE).collect::<Vec<_>>());

        // Some Catmull-Clark limit tangents are differences of points
        // 31 × 2^1019 apart: beyond the largest double, so refused, naming
        // the vertex (Loop's fit) ...
        match subdivider.limit_of(big.positions()) {
            Err(weft::Error::DegenerateInput(m)) if scheme == Scheme::CatmullClark => {
                assert!(m.contains("tangent of refined vertex"), "{m}")
            }
            Ok(huge_limit) if scheme == Scheme::Loop => {
                let expected = subdivider.limit_of(small.positions()).unwrap();
                assert_eq!(huge_limit.dv, scaled_points(&expected.dv, HUGE));
                assert_eq!(huge_limit.normals, expected.normals);
            }
            other => panic!("{scheme:?}: {other:?}"),
        }
        // ... but at 2^1017 they fit, and everything scales exactly.
        let limit = subdivider.limit_of(small.positions()).unwrap();
        let quarter = HUGE / 4.0;
        let big_limit = subdivider
            .limit_of(&scaled_points(small.positions(), quarter))
            .unwrap();
        assert_eq!(
            big_limit.positions,
            scaled_points(&limit.positions, quarter)
        );
        assert_eq!(big_limit.du, scaled_points(&limit.du, quarter));
        assert_eq!(big_limit.dv, scaled_points(&limit.dv, quarter));
        assert_eq!(big_limit.normals, limit.normals);
        // Tangents near 2^524 or 2^-536, whose cross product overflows or
        // underflows, still give the same unit normals.
        for factor in [2f64.powi(520), 2f64.powi(-540)] {
            let far = subdivider
                .limit_of(&scaled_points(small.positions(), factor))
                .unwrap();
            assert_eq!(far.normals, limit.normals, "{scheme:?} at {factor:e}");
        }
        let unit = |n: &&DVec3| (n.length() - 1.0).abs() < 1e-12;
        assert!(limit.normals.iter().filter(unit).count() > limit.normals.len() / 2);
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

/// The operations fuzz target: Loop on three triangles over the same three
/// vertices (each edge with three faces). `weft_subdivision_counts` once
/// announced more vertices than the subdivision made (which merged the
/// inside edges of the triangles' middle children): a host sizing its
/// buffers by it read unwritten values. Every triangle now keeps its own
/// inside edges, as OpenSubdiv does, and the counts, both paths and
/// OpenSubdiv agree: 2E + 3F edges a level.
#[test]
fn loop_counts_of_triangles_on_the_same_vertices_match_the_subdivision() {
    use weft::subdivide::{
        catmull_clark, loop_subdivision, refined_counts, NakedEdges, Scheme, Subdivider,
        SubdivisionOptions,
    };
    let m = mesh(
        &[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        &[&[2, 0, 1], &[2, 1, 0], &[0, 2, 1]],
    );
    // A closed tetrahedron with one face doubled, reversed.
    let doubled = mesh(
        &[
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ],
        &[&[0, 2, 1], &[0, 1, 3], &[0, 3, 2], &[1, 2, 3], &[1, 2, 0]],
    );
    for cage in [&m, &doubled] {
        for levels in 0..=3 {
            let counts = refined_counts(cage, Scheme::Loop, levels).unwrap();
            let plain = loop_subdivision(cage, levels, NakedEdges::Smooth).unwrap();
            assert_eq!(counts.vertex_count, plain.vertex_count(), "level {levels}");
            assert_eq!(counts.face_count, plain.face_count());
            assert_eq!(counts.index_count, plain.index_count());
            let options = SubdivisionOptions::new(NakedEdges::Smooth);
            let creased = Subdivider::new(cage, Scheme::Loop, levels, &options).unwrap();
            assert_eq!(counts.vertex_count, creased.vertex_count());
            let counts = refined_counts(cage, Scheme::CatmullClark, levels).unwrap();
            let plain = catmull_clark(cage, levels, NakedEdges::Smooth).unwrap();
            assert_eq!(counts.vertex_count, plain.vertex_count());
        }
    }
    // Level 1: 3 + 3 vertices and 2·3 + 3·3 edges; level 2: 6 + 15.
    assert_eq!(
        refined_counts(&m, Scheme::Loop, 2).unwrap().vertex_count,
        21
    );
}

/// The readers' fuzz target (`fuzz/corpus/readers/ply-two-vertex-elements`):
/// a binary PLY header declaring `element vertex` twice, the second time
/// with colours, was read as one list of eight vertices with colours for
/// four of them, and writing that file failed. A second element of one
/// name is now refused, naming its line and the first one's.
#[test]
fn ply_with_two_vertex_elements_is_refused() {
    use weft::io::{parse_mesh, parse_mesh_file, Format, Location};
    // The fuzzer's input after its first byte (which picks the format).
    let input = include_bytes!("../fuzz/corpus/readers/ply-two-vertex-elements");
    for error in [
        parse_mesh(Format::Ply, &input[1..]).unwrap_err(),
        parse_mesh_file(Format::Ply, &input[1..]).unwrap_err(),
    ] {
        assert_eq!(error.location(), Some(Location::Line(12)), "{error}");
        assert!(
            error
                .to_string()
                .contains("a second element \"vertex\" (the first is on line 3)"),
            "{error}"
        );
    }
}
