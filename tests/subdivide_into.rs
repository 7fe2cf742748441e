//! Subdivision into a caller's buffers equals the subdivision that makes a
//! new mesh, bit for bit, and refuses short buffers before writing.

use weft::mesh::shapes;
use weft::subdivide::{refined_counts, subdivide, subdivide_into, NakedEdges, Scheme};
use weft::{DVec3, Error, Mesh};

const MODES: [NakedEdges; 4] = [
    NakedEdges::Fixed,
    NakedEdges::Smooth,
    NakedEdges::CornerFixed,
    NakedEdges::None,
];

/// A value no subdivision writes, to see what was left alone.
const UNTOUCHED: f64 = -1234.5;

/// `cage` with `count` more vertices that no face uses, after its own:
/// too many for the points of the level before the last to be kept in the
/// last level's index buffer.
fn with_unused_vertices(cage: &Mesh, count: usize) -> Mesh {
    let mut positions = cage.positions().to_vec();
    positions.extend((0..count).map(|i| DVec3::new(i as f64, 0.5, -2.0)));
    Mesh::from_polygons(positions, cage.faces()).unwrap()
}

fn cages(scheme: Scheme) -> Vec<Mesh> {
    let mut cages = some_cages(scheme);
    cages.push(with_unused_vertices(&cages[0], 2000));
    cages
}

fn some_cages(scheme: Scheme) -> Vec<Mesh> {
    match scheme {
        Scheme::CatmullClark => vec![
            shapes::cube(),
            shapes::torus(12, 9),
            shapes::mixed_polygons(),
            shapes::quad_grid_with_hole(),
            shapes::fin(),
            shapes::bow_tie(),
        ],
        Scheme::Loop => vec![
            shapes::icosahedron(),
            shapes::triangle_torus(10, 8),
            shapes::triangle_grid_with_hole(),
            shapes::triangle_grid(5, 4),
        ],
    }
}

fn bits(points: &[DVec3]) -> Vec<[u64; 3]> {
    points
        .iter()
        .map(|p| p.to_array().map(f64::to_bits))
        .collect()
}

/// Subdivides into buffers `spare` longer than needed; checks the result
/// and that the spare values are untouched.
fn check_into(cage: &Mesh, scheme: Scheme, levels: u32, mode: NakedEdges, spare: usize) {
    let expected = subdivide(cage, scheme, levels, mode).unwrap();
    let (n, k) = (expected.vertex_count(), expected.index_count());
    let mut positions = vec![DVec3::splat(UNTOUCHED); n + spare];
    let mut indices = vec![u32::MAX; k + spare];
    let counts = subdivide_into(cage, scheme, levels, mode, &mut positions, &mut indices).unwrap();
    let what = format!("{scheme:?} level {levels} {mode:?}, {n} vertices");
    assert_eq!(
        (counts.vertex_count, counts.face_count, counts.index_count),
        (n, expected.face_count(), k),
        "{what}"
    );
    assert_eq!(bits(&positions[..n]), bits(expected.positions()), "{what}");
    assert_eq!(&indices[..k], expected.face_indices(), "{what}");
    assert!(
        positions[n..].iter().all(|&p| p == DVec3::splat(UNTOUCHED)),
        "{what}"
    );
    assert!(indices[k..].iter().all(|&i| i == u32::MAX), "{what}");
}

#[test]
fn equals_the_new_mesh_bit_for_bit() {
    for scheme in [Scheme::CatmullClark, Scheme::Loop] {
        for cage in cages(scheme) {
            for mode in MODES {
                for levels in 0..=3 {
                    check_into(&cage, scheme, levels, mode, 0);
                    check_into(&cage, scheme, levels, mode, 5);
                }
            }
        }
    }
}

#[test]
fn equals_the_new_mesh_near_the_ends_of_the_double_range() {
    // Coordinates this large are refined at an exactly scaled size.
    for (scheme, cage) in [
        (Scheme::CatmullClark, shapes::torus(6, 5)),
        (Scheme::Loop, shapes::icosahedron()),
    ] {
        let huge: Vec<DVec3> = cage.positions().iter().map(|&p| p * 1e307).collect();
        let cage = cage.with_positions(huge).unwrap();
        for levels in 1..=2 {
            check_into(&cage, scheme, levels, NakedEdges::Smooth, 2);
        }
    }
}

#[test]
fn short_buffers_are_refused_before_anything_is_written() {
    let cage = shapes::torus(8, 6);
    for levels in [0, 1, 2, 3] {
        let counts = refined_counts(&cage, Scheme::CatmullClark, levels).unwrap();
        for (short_positions, short_indices) in [(1, 0), (0, 1), (1, 1)] {
            let mut positions =
                vec![DVec3::splat(UNTOUCHED); counts.vertex_count - short_positions];
            let mut indices = vec![u32::MAX; counts.index_count - short_indices];
            let error = subdivide_into(
                &cage,
                Scheme::CatmullClark,
                levels,
                NakedEdges::Smooth,
                &mut positions,
                &mut indices,
            )
            .unwrap_err();
            let Error::BufferTooSmall(message) = &error else {
                panic!("{error}");
            };
            let named = if short_positions == 1 {
                "positions"
            } else {
                "face_indices"
            };
            assert!(message.starts_with(named), "{message}");
            assert!(positions.iter().all(|&p| p == DVec3::splat(UNTOUCHED)));
            assert!(indices.iter().all(|&i| i == u32::MAX));
        }
    }
}

#[test]
fn loop_refuses_a_face_that_is_not_a_triangle() {
    let cage = shapes::cube();
    let (mut positions, mut indices) = (vec![DVec3::ZERO; 1000], vec![0; 4000]);
    let error = subdivide_into(
        &cage,
        Scheme::Loop,
        1,
        NakedEdges::Smooth,
        &mut positions,
        &mut indices,
    )
    .unwrap_err();
    assert!(
        matches!(error, Error::NotTriangles { face: 0, size: 4 }),
        "{error}"
    );
}
