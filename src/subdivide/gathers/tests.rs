use super::*;
use crate::mesh::shapes;
use crate::subdivide::point_rules::child_faces;
use crate::subdivide::rules::{cage_tags, child_tags};
use crate::subdivide::scheme::NakedEdges;
use crate::subdivide::{catmull_clark, loop_subdivision};
use glam::DVec3;

/// Reading a level's gathers from its parent gives what building the
/// level and reading it gives: every face, edge, rule and ring, on
/// closed, open, mixed and non-manifold shapes, in every naked-edge mode.
#[test]
fn refined_gathers_equal_the_built_level() {
    let shapes = [
        shapes::cube(),
        shapes::quad_grid(3, 2),
        shapes::quad_grid_with_hole(),
        shapes::mixed_polygons(),
        shapes::fin(),
        shapes::bow_tie(),
        shapes::mobius_strip(6),
        shapes::tetrahedron(),
        // Two triangles on the same three vertices, closed; and the same
        // quad twice, every edge run the same way by both.
        crate::Mesh::from_polygons(
            vec![DVec3::ZERO, DVec3::X, DVec3::Y],
            [[0u32, 1, 2], [1, 0, 2]],
        )
        .unwrap(),
        crate::Mesh::from_polygons(
            vec![DVec3::ZERO, DVec3::X, DVec3::ONE, DVec3::Y],
            [[0u32, 1, 2, 3], [0, 1, 2, 3]],
        )
        .unwrap(),
    ];
    for (s, mesh) in shapes.iter().enumerate() {
        for naked in [
            NakedEdges::Fixed,
            NakedEdges::Smooth,
            NakedEdges::CornerFixed,
        ] {
            let levels = TwoLevels::of(mesh, Scheme::CatmullClark, naked);
            let TwoLevels {
                connectivity,
                child,
                child_connectivity,
                ..
            } = &levels;
            let refined = RefinedGathers {
                parent: levels.parent(),
            };
            let built = levels.child();
            let what = format!("shape {s} {naked:?}");
            let grandchild =
                child_faces(Scheme::CatmullClark, child, child_connectivity, false).unwrap();
            assert_eq!(
                catmull_clark::grandchild_faces(&refined, None)
                    .unwrap()
                    .indices,
                grandchild.indices,
                "{what}: grandchild faces"
            );
            assert_eq!(refined.vertex_count(), built.vertex_count(), "{what}");
            assert_eq!(refined.edge_count(), built.edge_count(), "{what}");
            assert_eq!(refined.face_count(), built.face_count(), "{what}");
            for f in 0..built.face_count() {
                assert!(refined.face(f).eq(built.face(f)), "{what}: face {f}");
                let edges: Vec<u32> = (4 * f..4 * f + 4)
                    .map(|c| child_connectivity.corner_edges[c])
                    .collect();
                assert_eq!(refined.quad_edges(f).to_vec(), edges, "{what}: face {f}");
            }
            if refined.parent.faces.size == 4 {
                for q in 0..built.face_count() / 4 {
                    let one_by_one: [[u32; 4]; 4] =
                        std::array::from_fn(|j| refined.quad_edges(4 * q + j));
                    assert_eq!(
                        refined.quad_edges_of_quad(q),
                        one_by_one,
                        "{what}: quad {q}"
                    );
                    let one_by_one: [[u32; 4]; 4] =
                        std::array::from_fn(|j| refined.quad(4 * q + j));
                    assert_eq!(refined.quads_of_quad(q), one_by_one, "{what}: quad {q}");
                }
            }
            assert_same_gathers(&refined, &built, &what);
            // The points made around the parent's faces, edges and vertices
            // are the points made kind by kind from the built level.
            assert_same_points(
                |points, out| catmull_clark::apply(&refined, points, out),
                |points, out| catmull_clark::apply(&built, points, out),
                built.vertex_count(),
                built.vertex_count() + built.edge_count() + built.face_count(),
                &what,
            );
            assert_walked_wings(
                &connectivity.vertex_edge_offsets,
                |v| refined.slot_wings(v),
                |s| refined.edge(s),
                &what,
            );
        }
    }
}

/// The wings walked around each parent vertex (`walked`) are its slots'
/// wings, edge by edge (`edge`), wherever the walk gives them; and it
/// gives them around some vertex.
fn assert_walked_wings(
    vertex_edge_offsets: &[u32],
    walked: impl Fn(usize) -> Option<[[u32; 2]; MAX_WALKED_EDGES]>,
    edge: impl Fn(usize) -> [u32; 4],
    what: &str,
) {
    let mut walked_any = false;
    for v in 0..vertex_edge_offsets.len() - 1 {
        let slots = vertex_edge_offsets[v]..vertex_edge_offsets[v + 1];
        if let Some(wings) = walked(v) {
            walked_any = true;
            for (i, s) in slots.enumerate() {
                let [_, _, w0, w1] = edge(s as usize);
                assert_eq!(wings[i], [w0, w1], "{what}: vertex {v}, slot {s}");
            }
        }
    }
    assert!(walked_any, "{what}: no vertex walked");
}

/// A cage's level and the level `scheme` makes of it, built.
struct TwoLevels<'a> {
    scheme: Scheme,
    faces: Faces<'a>,
    connectivity: Connectivity,
    tags: Tags,
    child: Faces<'static>,
    child_connectivity: Connectivity,
    child_tags: Tags,
}

impl<'a> TwoLevels<'a> {
    fn of(mesh: &'a crate::Mesh, scheme: Scheme, naked: NakedEdges) -> TwoLevels<'a> {
        let faces = Faces::of_mesh(mesh);
        let connectivity = Connectivity::new(&faces).unwrap();
        let tags = cage_tags(&faces, &connectivity, naked).unwrap();
        let child = child_faces(scheme, &faces, &connectivity, true).unwrap();
        let child_connectivity = connectivity.refine(scheme, &faces, true).unwrap();
        let child_tags = child_tags(scheme, &tags, &faces, &child_connectivity).unwrap();
        TwoLevels {
            scheme,
            faces,
            connectivity,
            tags,
            child,
            child_connectivity,
            child_tags,
        }
    }

    fn parent(&self) -> LevelGathers<'_> {
        LevelGathers {
            scheme: self.scheme,
            faces: &self.faces,
            connectivity: &self.connectivity,
            tags: &self.tags,
            groups: None,
        }
    }

    fn child(&self) -> LevelGathers<'_> {
        LevelGathers {
            scheme: self.scheme,
            faces: &self.child,
            connectivity: &self.child_connectivity,
            tags: &self.child_tags,
            groups: None,
        }
    }
}

/// Every edge, and every vertex's rule, crease neighbours or ring, of two
/// readings of one level are the same.
fn assert_same_gathers(refined: &impl Gathers, built: &impl Gathers, what: &str) {
    for e in 0..built.edge_count() {
        assert_eq!(refined.edge(e), built.edge(e), "{what}: edge {e}");
    }
    for v in 0..built.vertex_count() {
        let rule = built.rule(v);
        assert_eq!(refined.rule(v), rule, "{what}: vertex {v}");
        match rule {
            VertexRule::Crease => assert_eq!(
                refined.crease_neighbours(v),
                built.crease_neighbours(v),
                "{what}: vertex {v}"
            ),
            VertexRule::Smooth => {
                let (mut a, mut b) = (Vec::new(), Vec::new());
                let n = refined.around(v, |u, f| a.push((u, f)));
                assert_eq!(n, built.around(v, |u, f| b.push((u, f))));
                assert_eq!(a, b, "{what}: vertex {v}");
            }
            VertexRule::Corner => {}
        }
    }
}

/// Loop's gathers read from the parent level give what building the level
/// and reading it gives, as for Catmull-Clark above: on closed, open and
/// non-manifold triangle meshes, with two triangles on the same three
/// vertices (each keeps its own inside edges), in every naked-edge mode;
/// and the triangles two levels down are the built level's children.
#[test]
fn loop_refined_gathers_equal_the_built_level() {
    let triangulated =
        |mesh: &crate::Mesh| crate::mesh::triangulate::triangulate(mesh).unwrap().mesh;
    let shapes = [
        shapes::tetrahedron(),
        shapes::icosahedron(),
        shapes::triangle_grid(3, 2),
        shapes::triangle_grid_with_hole(),
        shapes::triangle_torus(5, 4),
        triangulated(&shapes::fin()),
        triangulated(&shapes::bow_tie()),
        triangulated(&shapes::mobius_strip(6)),
        crate::Mesh::from_polygons(
            vec![DVec3::ZERO, DVec3::X, DVec3::Y],
            [[0u32, 1, 2], [1, 0, 2]],
        )
        .unwrap(),
    ];
    for (s, mesh) in shapes.iter().enumerate() {
        assert!(mesh.first_non_triangle().is_none(), "shape {s}");
        for naked in [
            NakedEdges::Fixed,
            NakedEdges::Smooth,
            NakedEdges::CornerFixed,
        ] {
            let levels = TwoLevels::of(mesh, Scheme::Loop, naked);
            let TwoLevels {
                child,
                child_connectivity,
                ..
            } = &levels;
            let refined = LoopRefinedGathers::new(levels.parent()).unwrap();
            let built = levels.child();
            let what = format!("shape {s} {naked:?}");
            let grandchild = child_faces(Scheme::Loop, child, child_connectivity, false).unwrap();
            let refined_faces = loop_subdivision::grandchild_faces(&refined, None).unwrap();
            assert_eq!(
                refined_faces.indices, grandchild.indices,
                "{what}: grandchild faces"
            );
            assert_eq!(
                refined_faces.vertex_count, grandchild.vertex_count,
                "{what}"
            );
            assert_eq!(refined.vertex_count(), built.vertex_count(), "{what}");
            assert_eq!(refined.edge_count(), built.edge_count(), "{what}");
            assert_eq!(refined.face_count(), built.face_count(), "{what}");
            for f in 0..child.face_count() {
                assert!(refined.face(f).eq(built.face(f)), "{what}: face {f}");
                let (_, edges) = refined.children(f / 4)[f % 4];
                assert_eq!(
                    edges.to_vec(),
                    child_connectivity.corner_edges[3 * f..3 * f + 3].to_vec(),
                    "{what}: face {f}"
                );
            }
            assert_same_gathers(&refined, &built, &what);
            assert_walked_wings(
                &levels.connectivity.vertex_edge_offsets,
                |v| refined.slot_wings(v),
                |s| refined.edge(s),
                &what,
            );
            assert_same_points(
                |points, out| loop_subdivision::apply(&refined, points, out),
                |points, out| loop_subdivision::apply(&built, points, out),
                built.vertex_count(),
                built.vertex_count() + built.edge_count(),
                &what,
            );
        }
    }
}

/// The points two readings of one level make of the same positions are
/// the same bits: `refined` makes them around the parent's elements,
/// `built` kind by kind (`count` of them from `vertex_count` positions).
fn assert_same_points(
    refined: impl Fn(&[DVec3], &mut [DVec3]),
    built: impl Fn(&[DVec3], &mut [DVec3]),
    vertex_count: usize,
    count: usize,
    what: &str,
) {
    let points: Vec<DVec3> = (0..vertex_count)
        .map(|i| {
            let t = i as f64;
            DVec3::new((t * 0.7).sin(), (t * 1.3).cos() * 3.1, t.sqrt() - 0.4)
        })
        .collect();
    let mut around_parent = vec![DVec3::NAN; count];
    refined(&points, &mut around_parent);
    let mut kind_by_kind = vec![DVec3::NAN; count];
    built(&points, &mut kind_by_kind);
    for (i, (a, b)) in around_parent.iter().zip(&kind_by_kind).enumerate() {
        let bits = |p: &DVec3| p.to_array().map(f64::to_bits);
        assert_eq!(bits(a), bits(b), "{what}: point {i}");
    }
}
