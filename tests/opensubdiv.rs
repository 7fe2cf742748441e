//! Weft's subdivision against OpenSubdiv 3.5 (every scheme, every naked-edge
//! mode, levels 1-3, on every named shape) and OpenMesh 9 (closed shapes, and
//! Loop against Smooth on open ones).
//!
//! Positions must agree within 1e-9 of the bounding-box diagonal and the
//! faces must be the same. OpenSubdiv orders vertices differently (vertex
//! children, then face points, then edge points in its own edge order), so
//! vertices are matched by position: each Weft vertex to the one reference
//! vertex within the tolerance, which must be a bijection; faces are then
//! compared as cycles (any starting corner, same winding).
//!
//! OpenMesh's Catmull-Clark moves a boundary vertex with (1,4,1)/6-like
//! weights instead of the cubic B-spline's (1,6,1)/8, so it is no reference
//! on open quad meshes: it is compared on closed shapes only.

use weft::mesh::shapes;
use weft::mesh::triangulate::triangulate;
use weft::subdivide::{subdivide, NakedEdges, Refiner, Scheme};
use weft::Mesh;
use weft_reference::{
    openmesh_catmull_clark, openmesh_loop, opensubdiv_refine, BoundaryInterpolation, OsdOptions,
    RefMesh,
};

const MODES: [NakedEdges; 4] = [
    NakedEdges::Fixed,
    NakedEdges::Smooth,
    NakedEdges::CornerFixed,
    NakedEdges::None,
];

fn to_ref(mesh: &Mesh) -> RefMesh {
    RefMesh {
        positions: mesh.positions().iter().flat_map(|p| p.to_array()).collect(),
        face_sizes: mesh.face_sizes().to_vec(),
        face_indices: mesh.face_indices().to_vec(),
    }
}

fn osd_options(scheme: Scheme, mode: NakedEdges, cage: &RefMesh) -> OsdOptions {
    let scheme = match scheme {
        Scheme::CatmullClark => weft_reference::Scheme::CatmullClark,
        Scheme::Loop => weft_reference::Scheme::Loop,
    };
    match mode {
        NakedEdges::Fixed => OsdOptions::fixed(scheme, cage),
        NakedEdges::Smooth => OsdOptions::new(scheme, BoundaryInterpolation::EdgeOnly),
        NakedEdges::CornerFixed => OsdOptions::new(scheme, BoundaryInterpolation::EdgeAndCorner),
        NakedEdges::None => OsdOptions::new(scheme, BoundaryInterpolation::None),
    }
}

/// Three sheets of two quads meeting along a spine of two edges: the middle
/// spine vertex has more faces than edges and no naked edge, OpenSubdiv's
/// "interior non-manifold crease", which it does not sharpen into a corner.
fn three_sheets() -> Mesh {
    // A bent spine, so that its crease rule moves the middle vertex.
    let spine = [
        weft::DVec3::new(0.0, 0.0, 0.0),
        weft::DVec3::new(1.0, 0.3, 0.2),
        weft::DVec3::new(2.0, 0.0, 0.0),
    ];
    let mut positions = spine.to_vec();
    let mut faces = Vec::new();
    for k in 0..3 {
        let angle = std::f64::consts::TAU * k as f64 / 3.0 + 0.3;
        let offset = weft::DVec3::new(0.1 * k as f64, angle.cos(), angle.sin());
        let base = positions.len() as u32;
        positions.extend(spine.iter().map(|&p| p + offset));
        faces.push(vec![0, 1, base + 1, base]);
        faces.push(vec![1, 2, base + 2, base + 1]);
    }
    Mesh::from_polygons(positions, faces).unwrap()
}

/// Every named shape, and for Loop its triangulation where it has other faces.
fn shapes_for(scheme: Scheme) -> Vec<(&'static str, Mesh)> {
    let all = vec![
        ("cube", shapes::cube()),
        ("tetrahedron", shapes::tetrahedron()),
        ("icosahedron", shapes::icosahedron()),
        ("torus", shapes::torus(6, 4)),
        ("triangle torus", shapes::triangle_torus(6, 4)),
        ("open quad grid", shapes::quad_grid(3, 2)),
        ("open triangle grid", shapes::triangle_grid(3, 2)),
        ("quad grid with a hole", shapes::quad_grid_with_hole()),
        (
            "triangle grid with a hole",
            shapes::triangle_grid_with_hole(),
        ),
        ("mixed polygons", shapes::mixed_polygons()),
        ("non-manifold fin", shapes::fin()),
        ("bow-tie", shapes::bow_tie()),
        ("Möbius strip", shapes::mobius_strip(8)),
        ("three sheets on one spine", three_sheets()),
    ];
    match scheme {
        Scheme::CatmullClark => all,
        Scheme::Loop => all
            .into_iter()
            .map(|(name, mesh)| {
                if mesh.is_triangle_mesh() {
                    (name, mesh)
                } else {
                    (name, triangulate(&mesh).unwrap().mesh)
                }
            })
            .collect(),
    }
}

/// Asserts that `ours` and `reference` are the same mesh up to vertex order.
fn assert_same_mesh(ours: &Mesh, reference: &RefMesh, what: &str) {
    assert_eq!(
        ours.vertex_count(),
        reference.vertex_count(),
        "{what}: vertex counts differ"
    );
    assert_eq!(
        ours.face_count(),
        reference.face_count(),
        "{what}: face counts differ"
    );
    let (lo, hi) = ours.bounding_box().expect("vertices");
    let tolerance = 1e-9 * (hi - lo).length().max(1e-300);

    // Reference vertices sorted by x; each of ours looks in its x window.
    let theirs: Vec<[f64; 3]> = (0..reference.vertex_count())
        .map(|v| reference.position(v))
        .collect();
    let mut by_x: Vec<u32> = (0..theirs.len() as u32).collect();
    by_x.sort_by(|&a, &b| theirs[a as usize][0].total_cmp(&theirs[b as usize][0]));
    let mut map = vec![u32::MAX; ours.vertex_count()];
    let mut taken = vec![false; theirs.len()];
    for (v, p) in ours.positions().iter().enumerate() {
        let start = by_x.partition_point(|&r| theirs[r as usize][0] < p.x - tolerance);
        let mut found = None;
        for &r in &by_x[start..] {
            let q = theirs[r as usize];
            if q[0] > p.x + tolerance {
                break;
            }
            let d = ((q[0] - p.x).powi(2) + (q[1] - p.y).powi(2) + (q[2] - p.z).powi(2)).sqrt();
            if d <= tolerance {
                assert!(
                    found.is_none(),
                    "{what}: vertex {v} at {p} matches two reference vertices"
                );
                found = Some(r);
            }
        }
        let Some(r) = found else {
            let nearest = theirs
                .iter()
                .map(|q| {
                    ((q[0] - p.x).powi(2) + (q[1] - p.y).powi(2) + (q[2] - p.z).powi(2)).sqrt()
                })
                .fold(f64::INFINITY, f64::min);
            panic!("{what}: vertex {v} at {p} has no reference vertex within {tolerance:e} (nearest {nearest:e})");
        };
        assert!(
            !taken[r as usize],
            "{what}: reference vertex {r} matched twice"
        );
        taken[r as usize] = true;
        map[v] = r;
    }

    let canonical = |face: Vec<u32>| {
        let start = (0..face.len()).min_by_key(|&i| face[i]).unwrap();
        let mut rotated = face[start..].to_vec();
        rotated.extend_from_slice(&face[..start]);
        rotated
    };
    let mut our_faces: Vec<Vec<u32>> = ours
        .faces()
        .map(|f| canonical(f.iter().map(|&v| map[v as usize]).collect()))
        .collect();
    let mut their_faces: Vec<Vec<u32>> = reference.faces().map(|f| canonical(f.to_vec())).collect();
    our_faces.sort();
    their_faces.sort();
    assert!(our_faces == their_faces, "{what}: the faces differ");
}

#[test]
fn catmull_clark_equals_opensubdiv() {
    compare_with_opensubdiv(Scheme::CatmullClark);
}

#[test]
fn loop_equals_opensubdiv() {
    compare_with_opensubdiv(Scheme::Loop);
}

fn compare_with_opensubdiv(scheme: Scheme) {
    for (name, cage) in shapes_for(scheme) {
        let reference_cage = to_ref(&cage);
        for mode in MODES {
            let options = osd_options(scheme, mode, &reference_cage);
            for levels in 1..=3 {
                let what = format!("{scheme:?} {mode:?} level {levels} of the {name}");
                let ours = subdivide(&cage, scheme, levels, mode).unwrap();
                let reference = opensubdiv_refine(&reference_cage, &options, levels).unwrap();
                assert_same_mesh(&ours, &reference, &what);
            }
        }
    }
}

/// Level 4, where one-shot subdivision makes levels 2 and 3 around the
/// elements of the level before, and the refiner applies its plans of
/// levels 2, 3 and 4 that way: both against OpenSubdiv, on every shape in
/// every naked-edge mode.
#[test]
fn level_four_equals_opensubdiv_one_shot_and_refined() {
    for scheme in [Scheme::CatmullClark, Scheme::Loop] {
        for (name, cage) in shapes_for(scheme) {
            let reference_cage = to_ref(&cage);
            for mode in MODES {
                let what = format!("{scheme:?} {mode:?} level 4 of the {name}");
                let options = osd_options(scheme, mode, &reference_cage);
                let reference = opensubdiv_refine(&reference_cage, &options, 4).unwrap();
                let ours = subdivide(&cage, scheme, 4, mode).unwrap();
                assert_same_mesh(&ours, &reference, &what);
                let refined = Refiner::new(&cage, scheme, 4, mode)
                    .unwrap()
                    .mesh()
                    .unwrap();
                assert_same_mesh(&refined, &reference, &format!("{what}, refined"));
            }
        }
    }
}

#[test]
fn closed_shapes_equal_openmesh() {
    let closed = [
        ("cube", shapes::cube()),
        ("tetrahedron", shapes::tetrahedron()),
        ("icosahedron", shapes::icosahedron()),
        ("torus", shapes::torus(6, 4)),
        ("mixed polygons", shapes::mixed_polygons()),
    ];
    for (name, cage) in &closed {
        for levels in 1..=3 {
            let ours = subdivide(cage, Scheme::CatmullClark, levels, NakedEdges::Smooth).unwrap();
            let reference = openmesh_catmull_clark(&to_ref(cage), levels).unwrap();
            assert_same_mesh(
                &ours,
                &reference,
                &format!("OpenMesh Catmull-Clark {levels} {name}"),
            );
        }
    }
    let triangles = [
        ("tetrahedron", shapes::tetrahedron()),
        ("icosahedron", shapes::icosahedron()),
        ("triangle torus", shapes::triangle_torus(6, 4)),
    ];
    for (name, cage) in &triangles {
        for levels in 1..=3 {
            let ours = subdivide(cage, Scheme::Loop, levels, NakedEdges::Smooth).unwrap();
            let reference = openmesh_loop(&to_ref(cage), levels).unwrap();
            assert_same_mesh(&ours, &reference, &format!("OpenMesh Loop {levels} {name}"));
        }
    }
}

/// The mesh without the vertices no face uses (OpenMesh drops them; Weft and
/// OpenSubdiv keep them where they are).
fn without_unused_vertices(mesh: &Mesh) -> Mesh {
    let mut new_index = vec![u32::MAX; mesh.vertex_count()];
    let mut positions = Vec::new();
    for &v in mesh.face_indices() {
        if new_index[v as usize] == u32::MAX {
            new_index[v as usize] = positions.len() as u32;
            positions.push(mesh.positions()[v as usize]);
        }
    }
    let indices = mesh
        .face_indices()
        .iter()
        .map(|&v| new_index[v as usize])
        .collect();
    Mesh::new(positions, mesh.face_sizes().to_vec(), indices).unwrap()
}

#[test]
fn open_triangle_meshes_equal_openmesh_loop_in_smooth_mode() {
    let open = [
        ("open triangle grid", shapes::triangle_grid(3, 2)),
        (
            "triangle grid with a hole",
            without_unused_vertices(&shapes::triangle_grid_with_hole()),
        ),
    ];
    for (name, cage) in &open {
        for levels in 1..=3 {
            let ours = subdivide(cage, Scheme::Loop, levels, NakedEdges::Smooth).unwrap();
            let reference = openmesh_loop(&to_ref(cage), levels).unwrap();
            assert_same_mesh(&ours, &reference, &format!("OpenMesh Loop {levels} {name}"));
        }
    }
}
