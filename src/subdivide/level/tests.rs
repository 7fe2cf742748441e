use super::*;

#[test]
fn connectivity_of_two_triangles() {
    let faces = Faces {
        vertex_count: 4,
        size: 0,
        offsets: vec![0, 3, 6].into(),
        indices: vec![0, 1, 2, 0, 2, 3].into(),
    };
    let c = Connectivity::new(&faces).unwrap();
    assert_eq!(c.edges, vec![[0, 1], [0, 2], [0, 3], [1, 2], [2, 3]]);
    let diagonal = c.edges.iter().position(|&e| e == [0, 2]).unwrap();
    assert_eq!(c.edge_corners(diagonal), &[2, 3]);
    assert_eq!(c.vertex_corners(0), &[0, 3]);
    assert_eq!(c.corner_edges, vec![0, 3, 1, 1, 4, 2]);
    assert_eq!(c.vertex_edges(2), &[1, 3, 4]);
}

/// On faces of one size, corners find their face and neighbours by
/// arithmetic exactly as through the offsets.
#[test]
fn uniform_faces_match_their_offsets() {
    use crate::mesh::shapes;
    for mesh in [
        shapes::cube(),
        shapes::icosahedron(),
        shapes::quad_grid(3, 2),
    ] {
        let uniform = Faces::of_mesh(&mesh);
        assert_ne!(uniform.size, 0);
        let general = Faces {
            size: 0,
            ..uniform.clone()
        };
        let (a, b) = (
            Connectivity::new(&uniform).unwrap(),
            Connectivity::new(&general).unwrap(),
        );
        assert!(a.corner_faces.is_empty());
        assert_same(&a, &b, "uniform");
        for c in 0..uniform.corner_count() {
            let f = b.face_of(c);
            assert_eq!(uniform.next(c, f), general.next(c, f), "next of {c}");
            assert_eq!(uniform.prev(c, f), general.prev(c, f), "prev of {c}");
            assert_eq!(uniform.face(f), general.face(f));
        }
        assert_eq!(uniform.face_count(), general.face_count());
    }
    assert_eq!(Faces::of_mesh(&shapes::mixed_polygons()).size, 0);
}

/// A cage's faces read its mesh's indices, and its offsets when its faces
/// differ in size, in place: one-shot subdivision holds no copy of them
/// beside the output (at level 1 a copy of the indices would be an eighth
/// of the output).
#[test]
fn cage_faces_read_the_mesh_in_place() {
    use crate::mesh::shapes;
    use std::borrow::Cow;
    for mesh in [shapes::triangle_torus(8, 10), shapes::mixed_polygons()] {
        let faces = Faces::of_mesh(&mesh);
        let Cow::Borrowed(indices) = faces.indices else {
            panic!("the cage's indices were copied");
        };
        assert_eq!(indices.as_ptr(), mesh.face_indices().as_ptr());
        if faces.size == 0 {
            let Cow::Borrowed(offsets) = faces.offsets else {
                panic!("the cage's offsets were copied");
            };
            assert_eq!(offsets.as_ptr(), mesh.face_offsets().as_ptr());
        }
        let owned = faces.clone().into_owned();
        assert!(matches!(owned.indices, Cow::Owned(_)));
        assert_eq!(owned.indices, faces.indices);
        assert_eq!(owned.offsets, faces.offsets);
    }
}

fn assert_same(derived: &Connectivity, bucketed: &Connectivity, what: &str) {
    assert_eq!(derived.edges, bucketed.edges, "{what}: edges");
    let arrays = |c: &Connectivity| {
        let corner_faces = (0..c.corner_edges.len())
            .map(|k| c.face_of(k) as u32)
            .collect();
        [
            ("corner faces", corner_faces),
            ("corner edges", c.corner_edges.clone()),
            ("edge offsets", c.edge_offsets.clone()),
            ("edge corners", c.edge_corners.clone()),
            ("vertex offsets", c.vertex_offsets.clone()),
            ("vertex corners", c.vertex_corners.clone()),
            ("vertex edge offsets", c.vertex_edge_offsets.clone()),
            ("vertex edges", c.vertex_edges.clone()),
        ]
    };
    for ((name, ours), (_, theirs)) in arrays(derived).into_iter().zip(arrays(bucketed)) {
        assert_eq!(ours, theirs, "{what}: {name}");
    }
}

/// The arithmetic child connectivity equals bucketing the child faces,
/// on closed, open, mixed and non-manifold shapes, over three levels.
#[test]
fn refined_connectivity_equals_bucketing() {
    use crate::mesh::shapes;
    let pillow = crate::Mesh::from_polygons(
        vec![crate::DVec3::ZERO, crate::DVec3::X, crate::DVec3::Y],
        [[0u32, 1, 2], [1, 0, 2]],
    )
    .unwrap();
    // A vertex of 40 edges and an edge of 40 faces: their lists are
    // searched by halves, not scanned.
    let (fan, book) = (shapes::fan(40), shapes::book(40));
    let polygons = [
        ("fan", fan.clone()),
        ("book", book.clone()),
        ("cube", shapes::cube()),
        ("grid", shapes::quad_grid(3, 2)),
        ("grid with hole", shapes::quad_grid_with_hole()),
        ("mixed", shapes::mixed_polygons()),
        ("fin", shapes::fin()),
        ("bow tie", shapes::bow_tie()),
        ("mobius", shapes::mobius_strip(6)),
    ];
    let triangles = [
        ("fan", fan),
        ("book", book),
        ("tetrahedron", shapes::tetrahedron()),
        ("icosahedron", shapes::icosahedron()),
        ("triangle grid", shapes::triangle_grid(3, 2)),
        ("triangle grid with hole", shapes::triangle_grid_with_hole()),
        ("pillow", pillow),
    ];
    let cases = polygons
        .into_iter()
        .map(|(n, m)| (n, m, Scheme::CatmullClark))
        .chain(
            triangles
                .clone()
                .into_iter()
                .map(|(n, m)| (n, m, Scheme::Loop)),
        )
        .chain(
            triangles
                .into_iter()
                .map(|(n, m)| (n, m, Scheme::CatmullClark)),
        );
    for (name, mesh, scheme) in cases {
        if scheme == Scheme::Loop && mesh.first_non_triangle().is_some() {
            continue;
        }
        // Bucketing merges the pillow's inside edges, which belong one to
        // each triangle (see the test below).
        if scheme == Scheme::Loop && name == "pillow" {
            continue;
        }
        let mut faces = Faces::of_mesh(&mesh);
        let mut connectivity = Connectivity::new(&faces).unwrap();
        for level in 1..=3 {
            let child = super::super::point_rules::child_faces(scheme, &faces, &connectivity, true)
                .unwrap();
            let derived = connectivity.refine(scheme, &faces, true).unwrap();
            // Bucketed through the offsets, not the faces' uniform size.
            let offsets_only = Faces {
                size: 0,
                ..child.clone()
            };
            assert_same(
                &derived,
                &Connectivity::new(&offsets_only).unwrap(),
                &format!("{name} {scheme:?} level {level}"),
            );
            (faces, connectivity) = (child, derived);
        }
    }
}

/// Two triangles on the same three vertices: at every level each triangle
/// keeps its own three inside edges (2E + 3F child edges), as OpenSubdiv's
/// refinement does, though bucketing the child faces would merge them.
#[test]
fn loop_keeps_the_inside_edges_of_coincident_triangles_apart() {
    let pillow = crate::Mesh::from_polygons(
        vec![crate::DVec3::ZERO, crate::DVec3::X, crate::DVec3::Y],
        [[0u32, 1, 2], [1, 0, 2]],
    )
    .unwrap();
    let mut faces = Faces::of_mesh(&pillow);
    let mut connectivity = Connectivity::new(&faces).unwrap();
    for level in 1..=3 {
        let child =
            super::super::point_rules::child_faces(Scheme::Loop, &faces, &connectivity, true)
                .unwrap();
        let derived = connectivity.refine(Scheme::Loop, &faces, true).unwrap();
        assert_eq!(
            derived.edge_count(),
            2 * connectivity.edge_count() + 3 * faces.face_count(),
            "level {level}"
        );
        assert!(
            derived.edge_count() > Connectivity::new(&child).unwrap().edge_count(),
            "level {level}: bucketing merges some"
        );
        // Every child edge has the corners of two faces: a closed surface.
        for e in 0..derived.edge_count() {
            assert_eq!(derived.edge_corners(e).len(), 2, "level {level} edge {e}");
        }
        (faces, connectivity) = (child, derived);
    }
}

/// The searches by halves of long lists find what a scan finds, first and
/// last, in ascending lists with repeats (a degenerate edge is listed twice
/// at its vertex) and for values the list does not hold.
#[test]
fn positions_in_long_lists_equal_a_scan() {
    use super::{last_position, position};
    let mut words = crate::test_random::words(7);
    for len in 1..=80 {
        for _ in 0..20 {
            let mut list: Vec<u32> = (0..len).map(|_| (words() % 60) as u32).collect();
            list.sort_unstable();
            for x in 0..62 {
                let first = list.iter().position(|&y| y == x).unwrap_or(0) as u32;
                let last = list.iter().rposition(|&y| y == x).unwrap_or(0) as u32;
                assert_eq!(position(&list, x), first, "{list:?} {x}");
                assert_eq!(last_position(&list, x), last, "{list:?} {x}");
            }
        }
    }
}
