//! The making tools together: Voronoi cells on a plane become n-gon faces,
//! each gets a pyramid, and (welded) they form the Voronoi skin's one piece.

use weft::make::plane::Plane;
use weft::make::stellate::{stellate, Heights};
use weft::make::voronoi::{cells_to_mesh, voronoi};
use weft::mend::weld::{join, weld};
use weft::subdivide::{catmull_clark, NakedEdges};
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

    // The chain as a designer builds it, only Weft calls: one pyramid per
    // cell, the list joined, welded, then Catmull-Clark with the outline fixed.
    let pyramids: Vec<Mesh> = cells
        .iter()
        .map(|cell| {
            stellate(
                &cells_to_mesh(std::slice::from_ref(cell)).unwrap(),
                Heights::One(-0.3),
            )
            .unwrap()
        })
        .collect();
    let joined = join(&pyramids.iter().collect::<Vec<_>>()).unwrap();
    assert_eq!(joined.vertex_count(), skin.vertex_count());
    assert_eq!(joined.face_count(), skin.face_count());
    assert_eq!(
        Topology::new(&joined).info(&joined).component_count,
        points.len()
    );
    let (welded, report) = weld(&joined, 1e-9).unwrap();
    assert_eq!(report.removed_face_count, 0);
    // The same surface as welding the pyramids stellated all at once.
    let (welded_at_once, _) = weld(&skin, 1e-9).unwrap();
    assert_eq!(welded.vertex_count(), welded_at_once.vertex_count());
    assert_eq!(welded.face_count(), welded_at_once.face_count());
    let smooth = catmull_clark(&welded, 2, NakedEdges::Fixed).unwrap();
    for mesh in [&welded, &smooth] {
        let topology = Topology::new(mesh);
        let info = topology.info(mesh);
        assert_eq!(info.component_count, 1);
        assert_eq!(info.non_manifold_edge_count, 0);
        assert_eq!(info.non_manifold_vertex_count, 0);
        assert!(info.is_oriented && info.is_orientable);
        for e in topology.naked_edges() {
            let [a, b] = topology.edges()[e as usize];
            for v in [a, b] {
                assert!(on_boundary(mesh.positions()[v as usize], boundary));
            }
        }
        assert!(info.naked_edge_count >= boundary.len());
    }
    // Fixed keeps the outline: the subdivided naked edges are the welded ones split in four.
    assert_eq!(
        Topology::new(&smooth).info(&smooth).naked_edge_count,
        4 * Topology::new(&welded).info(&welded).naked_edge_count
    );
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
