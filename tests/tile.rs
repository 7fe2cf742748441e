//! Tile (Weaverbird's wbTile): each fill strategy's counts and pattern, and
//! what every one keeps: the outline, the winding, the welded seams.

use weft::mesh::shapes;
use weft::toolbar::tile::{tile, TileFaces, TileFill};
use weft::{DVec3, Mesh, Topology};

const FILLS: [TileFill; 8] = [
    TileFill::Skip,
    TileFill::Best,
    TileFill::TriangleFan,
    TileFill::TriangleHand,
    TileFill::TriangleKnit,
    TileFill::TriangleZigzag,
    TileFill::QuadStitch,
    TileFill::QuadFan,
];

fn area(mesh: &Mesh) -> f64 {
    (0..mesh.face_count())
        .map(|f| {
            let p: Vec<DVec3> = mesh.face_positions(f).collect();
            let n: DVec3 = (0..p.len()).map(|i| p[i].cross(p[(i + 1) % p.len()])).sum();
            n.length() / 2.0
        })
        .sum()
}

/// A regular hexagon in z = 0, counter-clockwise.
fn hexagon() -> Mesh {
    let p: Vec<DVec3> = (0..6)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / 6.0;
            DVec3::new(a.cos(), a.sin(), 0.0)
        })
        .collect();
    Mesh::from_polygons(p, [[0u32, 1, 2, 3, 4, 5]]).unwrap()
}

fn faces(mesh: &Mesh) -> Vec<Vec<u32>> {
    mesh.faces().map(<[u32]>::to_vec).collect()
}

#[test]
fn each_fill_of_a_hexagon_has_its_pattern() {
    let h = hexagon();
    let fill = |f| faces(&tile(&h, f, TileFaces::All).unwrap());
    assert_eq!(fill(TileFill::Skip), [vec![0, 1, 2, 3, 4, 5]]);
    assert_eq!(
        fill(TileFill::TriangleHand),
        [vec![0, 1, 2], vec![0, 2, 3], vec![0, 3, 4], vec![0, 4, 5]]
    );
    assert_eq!(
        fill(TileFill::TriangleZigzag),
        [vec![0, 1, 5], vec![1, 2, 5], vec![2, 4, 5], vec![2, 3, 4]]
    );
    assert_eq!(
        fill(TileFill::TriangleKnit),
        [vec![0, 1, 5], vec![1, 2, 5], vec![2, 3, 5], vec![3, 4, 5]]
    );
    assert_eq!(
        fill(TileFill::QuadStitch),
        [vec![0, 1, 2, 5], vec![2, 3, 4, 5]]
    );
    assert_eq!(
        fill(TileFill::QuadFan),
        [vec![6, 0, 1, 2], vec![6, 2, 3, 4], vec![6, 4, 5, 0]]
    );
    let fan = tile(&h, TileFill::TriangleFan, TileFaces::All).unwrap();
    assert_eq!(fan.face_count(), 6);
    assert!(
        fan.positions()[6].length() < 1e-15,
        "the centre is the centroid"
    );
    assert_eq!(fan.face(5), [6, 5, 0]);
}

#[test]
fn every_fill_keeps_a_closed_solid_closed_oriented_and_its_area() {
    let solid = shapes::mixed_polygons(); // faces of 6, 6, 5, 5, 4, 3, 3, 4, 4 corners
    let before = area(&solid);
    // (vertices, faces) per fill of all faces.
    let expected = [
        (13, 9),
        (13, 4 + 4 + 3 + 3 + 2 + 1 + 1 + 2 + 2),
        (13 + 9, 40),
        (13, 22),
        (13, 22),
        (13, 22),
        (13, 2 + 2 + 2 + 2 + 1 + 1 + 1 + 1 + 1),
        (13 + 9, 3 + 3 + 3 + 3 + 2 + 2 + 2 + 2 + 2),
    ];
    for (fill, (vertices, faces)) in FILLS.into_iter().zip(expected) {
        let out = tile(&solid, fill, TileFaces::All).unwrap();
        let info = Topology::new(&out).info(&out);
        assert_eq!(
            (info.vertex_count, info.face_count),
            (vertices, faces),
            "{fill:?}"
        );
        assert!(info.is_closed && info.is_oriented, "{fill:?}: {info:?}");
        assert_eq!(
            info.vertex_count + info.face_count,
            info.edge_count + 2,
            "{fill:?}"
        );
        assert!((area(&out) - before).abs() < 1e-12, "{fill:?}");
        assert_eq!(&out.positions()[..13], solid.positions(), "{fill:?}");
    }
}

#[test]
fn only_the_chosen_faces_change() {
    let solid = shapes::mixed_polygons();
    let count = |faces| {
        tile(&solid, TileFill::TriangleHand, faces)
            .unwrap()
            .face_count()
    };
    assert_eq!(count(TileFaces::All), 22);
    assert_eq!(count(TileFaces::QuadsAndMore), 22); // triangles are already one triangle
    assert_eq!(count(TileFaces::PentagonsAndMore), 9 - 4 + 4 + 4 + 3 + 3);
    assert_eq!(count(TileFaces::Quads), 9 + 3);
    let fan = tile(&solid, TileFill::TriangleFan, TileFaces::Triangles).unwrap();
    assert_eq!((fan.vertex_count(), fan.face_count()), (15, 9 + 2 * 2));
    // The untouched faces come through as they were, in place.
    assert_eq!(fan.face(0), solid.face(0));
    assert_eq!(fan.face(4), solid.face(4));
}

#[test]
fn seams_between_filled_faces_stay_welded() {
    let grid = shapes::quad_grid(3, 3);
    let before = Topology::new(&grid).info(&grid);
    for fill in FILLS {
        let out = tile(&grid, fill, TileFaces::All).unwrap();
        let info = Topology::new(&out).info(&out);
        assert_eq!(info.naked_edge_count, before.naked_edge_count, "{fill:?}");
        assert_eq!(info.component_count, 1, "{fill:?}");
        assert!(info.is_oriented, "{fill:?}");
    }
}

#[test]
fn best_cuts_a_concave_face_inside_it() {
    // An L-shaped hexagon: a fan from v0 would leave the face.
    let p = [
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [0.0, 2.0],
    ]
    .map(|[x, y]| DVec3::new(x, y, 0.0));
    let l = Mesh::from_polygons(p.to_vec(), [[0u32, 1, 2, 3, 4, 5]]).unwrap();
    let best = tile(&l, TileFill::Best, TileFaces::All).unwrap();
    assert_eq!(best.face_count(), 4);
    assert!((area(&best) - 3.0).abs() < 1e-12);
    for f in 0..4 {
        let q: Vec<DVec3> = best.face_positions(f).collect();
        assert!(
            (q[1] - q[0]).cross(q[2] - q[0]).z > 0.0,
            "triangle {f} is wound as the face"
        );
    }
}
