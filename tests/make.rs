//! The making tools together: Voronoi cells on a plane become n-gon faces,
//! each gets a pyramid, and (welded) they form the Voronoi skin's one piece.

use weft::plane::Plane;
use weft::stellate::{stellate, Heights};
use weft::voronoi::{cells_to_mesh, voronoi};
use weft::{DVec3, Mesh, Topology};

fn random_points(seed: u64, n: usize, accept: impl Fn(DVec3) -> bool) -> Vec<DVec3> {
    let mut state = seed;
    let mut next = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut points = Vec::new();
    while points.len() < n {
        let p = DVec3::new(next() * 10.0, next() * 10.0, 0.0);
        if accept(p) {
            points.push(p);
        }
    }
    points
}

/// Merges vertices closer than `tolerance` (a quadratic stand-in for the
/// library's weld, enough for a few hundred vertices).
fn weld_for_test(mesh: &Mesh, tolerance: f64) -> Mesh {
    let mut representative: Vec<u32> = Vec::new();
    let mut positions: Vec<DVec3> = Vec::new();
    for &p in mesh.positions() {
        match positions
            .iter()
            .position(|q| (*q - p).length() <= tolerance)
        {
            Some(k) => representative.push(k as u32),
            None => {
                representative.push(positions.len() as u32);
                positions.push(p);
            }
        }
    }
    let faces: Vec<Vec<u32>> = mesh
        .faces()
        .map(|f| f.iter().map(|&v| representative[v as usize]).collect())
        .collect();
    Mesh::from_polygons(positions, faces).expect("welded skin is valid")
}

fn on_boundary(p: DVec3, boundary: &[DVec3]) -> bool {
    (0..boundary.len()).any(|i| {
        let (a, b) = (boundary[i], boundary[(i + 1) % boundary.len()]);
        let t = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
        (a + (b - a) * t - p).length() < 1e-9
    })
}

fn check_skin(points: &[DVec3], boundary: &[DVec3]) {
    let cells = voronoi(points, &Plane::xy(), Some(boundary), None).unwrap();
    let faces = cells_to_mesh(&cells).unwrap();
    assert_eq!(faces.face_count(), points.len());
    let corner_count: usize = cells.iter().map(Vec::len).sum();
    let skin = stellate(&faces, Heights::One(-0.3)).unwrap();
    assert_eq!(skin.vertex_count(), corner_count + points.len());
    assert_eq!(skin.face_count(), corner_count);
    // Unwelded: one open pyramid per cell, its rim the cell.
    let info = Topology::new(&skin).info(&skin);
    assert_eq!(info.component_count, points.len());
    assert_eq!(info.naked_edge_count, corner_count);
    assert!(info.is_oriented);
    // Pyramids point down, below the plane's front side.
    assert!(skin.positions()[corner_count..]
        .iter()
        .all(|p| (p.z + 0.3).abs() < 1e-12));

    let welded = weld_for_test(&skin, 1e-9);
    let topology = Topology::new(&welded);
    let info = topology.info(&welded);
    assert_eq!(info.component_count, 1);
    assert_eq!(info.non_manifold_edge_count, 0);
    assert_eq!(info.non_manifold_vertex_count, 0);
    assert!(info.is_oriented && info.is_orientable);
    for e in topology.naked_edges() {
        let [a, b] = topology.edges()[e as usize];
        for v in [a, b] {
            assert!(on_boundary(welded.positions()[v as usize], boundary));
        }
    }
    assert!(info.naked_edge_count >= boundary.len());
}

#[test]
fn a_voronoi_skin_in_a_square_is_one_oriented_manifold_piece() {
    let square = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(10.0, 0.0, 0.0),
        DVec3::new(10.0, 10.0, 0.0),
        DVec3::new(0.0, 10.0, 0.0),
    ];
    check_skin(&random_points(17, 40, |_| true), &square);
}

#[test]
fn a_voronoi_skin_in_an_l_shape_is_one_oriented_manifold_piece() {
    let l_shape = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(10.0, 0.0, 0.0),
        DVec3::new(10.0, 4.0, 0.0),
        DVec3::new(4.0, 4.0, 0.0),
        DVec3::new(4.0, 10.0, 0.0),
        DVec3::new(0.0, 10.0, 0.0),
    ];
    check_skin(&random_points(23, 40, |p| p.x < 4.0 || p.y < 4.0), &l_shape);
}
