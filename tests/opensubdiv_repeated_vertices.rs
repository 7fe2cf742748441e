//! Faces that name a vertex more than once (`0 1 1 2`, `0 1 2 1 3`),
//! accepted when the mesh is built with
//! `MeshOptions::allow_repeated_vertices`, against OpenSubdiv 3.5, which
//! subdivides them as non-manifold topology: the same refined faces and
//! points, limit points and face-varying values (smooth and linear), at
//! levels 1-3 in every naked-edge mode, with creases, for Catmull-Clark
//! and Loop.
//!
//! Refined points of such faces coincide (the point of a degenerate edge
//! sits on its vertex), so points are compared as a multiset and faces as
//! cycles of points, not vertex by vertex.

mod support;

use support::{
    assert_drivers_agree, bumped, face_varying_both, opensubdiv_limit_at_vertices, osd_options,
    to_ref, tolerance,
};
use weft::mesh::shapes;
use weft::subdivide::{
    Crease, Creasing, NakedEdges, Refiner, Scheme, Subdivider, SubdivisionOptions,
};
use weft::{DVec3, Mesh, MeshError, MeshOptions};
use weft_reference::opensubdiv_refine;

const ALLOW: MeshOptions = MeshOptions {
    allow_repeated_vertices: true,
};

/// `mesh` with some of its faces replaced.
fn with_faces(mesh: &Mesh, replace: &[(usize, &[u32])], add: &[&[u32]]) -> Mesh {
    let mut faces: Vec<Vec<u32>> = mesh.faces().map(|f| f.to_vec()).collect();
    for &(f, face) in replace {
        faces[f] = face.to_vec();
    }
    faces.extend(add.iter().map(|f| f.to_vec()));
    Mesh::from_polygons_with(mesh.positions().to_vec(), faces, ALLOW).unwrap()
}

/// The cages: each repeats a vertex in another way.
fn cases() -> Vec<(&'static str, Scheme, Mesh, Vec<Crease>)> {
    // The 3 × 3 grid's vertices are 4y + x; face 4 is the middle 5-6-10-9.
    let grid = bumped(shapes::quad_grid(3, 3));
    let triangles = bumped(shapes::triangle_grid(3, 3));
    let t = |f: usize| triangles.face(f).to_vec();
    let (t4, t5) = (t(4), t(5));
    vec![
        (
            "a degenerate edge inside (5 6 6 10 9)",
            Scheme::CatmullClark,
            with_faces(&grid, &[(4, &[5, 6, 6, 10, 9])], &[]),
            vec![([9, 10], 2.0)],
        ),
        (
            "a degenerate edge on the boundary (0 1 1 5 4)",
            Scheme::CatmullClark,
            with_faces(&grid, &[(0, &[0, 1, 1, 5, 4])], &[]),
            Vec::new(),
        ),
        (
            "a face meeting a vertex twice (5 6 10 6 9)",
            Scheme::CatmullClark,
            with_faces(&grid, &[(4, &[5, 6, 10, 6, 9])], &[]),
            vec![([5, 6], 1.5)],
        ),
        (
            "one pair three times in a face (1 2 5 4 1 4)",
            Scheme::CatmullClark,
            with_faces(&grid, &[(0, &[1, 2, 5, 4, 1, 4])], &[]),
            Vec::new(),
        ),
        (
            "a vertex twice without a repeated pair (5 6 10 5 9 8)",
            Scheme::CatmullClark,
            with_faces(&grid, &[(4, &[5, 6, 10, 5, 9, 8])], &[]),
            Vec::new(),
        ),
        (
            "an extra face on one vertex three times (6 6 6)",
            Scheme::CatmullClark,
            with_faces(&grid, &[], &[&[6, 6, 6]]),
            Vec::new(),
        ),
        (
            "a triangle with a degenerate edge",
            Scheme::Loop,
            with_faces(&triangles, &[(4, &[t4[0], t4[1], t4[1]])], &[]),
            vec![([t5[0], t5[1]], 2.0)],
        ),
        (
            "a triangle meeting a pair twice",
            Scheme::Loop,
            with_faces(&triangles, &[(5, &[t5[0], t5[1], t5[0]])], &[]),
            Vec::new(),
        ),
    ]
}

/// Each point's cluster: the first reference point within `tol` of it
/// (the refined points of such faces coincide exactly, others lie far
/// apart). Panics when a point has no reference point near it.
fn clusters(points: &[DVec3], reference: &[DVec3], tol: f64, what: &str) -> Vec<usize> {
    let mut by_x: Vec<usize> = (0..reference.len()).collect();
    by_x.sort_by(|&a, &b| reference[a].x.total_cmp(&reference[b].x));
    points
        .iter()
        .enumerate()
        .map(|(v, p)| {
            let start = by_x.partition_point(|&r| reference[r].x < p.x - tol);
            by_x[start..]
                .iter()
                .take_while(|&&r| reference[r].x <= p.x + tol)
                .copied()
                .filter(|&r| (reference[r] - *p).length() <= tol)
                .min()
                .unwrap_or_else(|| {
                    panic!("{what}: point {v} at {p} has no reference point near it")
                })
        })
        .collect()
}

/// Asserts that `ours` and `theirs` hold the same points (as a multiset,
/// within `tol`) and the same faces (as cycles of those points), and
/// returns how many points coincide with another.
fn assert_same_points_and_faces(
    ours: (&[DVec3], &[&[u32]]),
    theirs: (&[DVec3], &[&[u32]]),
    tol: f64,
    what: &str,
) -> usize {
    assert_eq!(ours.0.len(), theirs.0.len(), "{what}: vertex counts");
    assert!(!theirs.0.is_empty(), "{what}: no points");
    assert_eq!(ours.1.len(), theirs.1.len(), "{what}: face counts");
    let our_clusters = clusters(ours.0, theirs.0, tol, what);
    let their_clusters = clusters(theirs.0, theirs.0, tol, what);
    let counted = |c: &[usize]| {
        let mut c = c.to_vec();
        c.sort_unstable();
        c
    };
    assert_eq!(
        counted(&our_clusters),
        counted(&their_clusters),
        "{what}: points"
    );
    // A face as the cycle of its points' clusters, turned to start at its least.
    let cycles = |faces: &[&[u32]], cluster: &[usize]| {
        let mut cycles: Vec<Vec<usize>> = faces
            .iter()
            .map(|face| {
                let ids: Vec<usize> = face.iter().map(|&v| cluster[v as usize]).collect();
                (0..ids.len())
                    .map(|r| {
                        ids[r..]
                            .iter()
                            .chain(&ids[..r])
                            .copied()
                            .collect::<Vec<usize>>()
                    })
                    .min()
                    .unwrap()
            })
            .collect();
        cycles.sort_unstable();
        cycles
    };
    assert_eq!(
        cycles(ours.1, &our_clusters),
        cycles(theirs.1, &their_clusters),
        "{what}: faces"
    );
    let mut distinct = counted(&their_clusters);
    distinct.dedup();
    theirs.0.len() - distinct.len()
}

fn points(flat: &[f64]) -> Vec<DVec3> {
    flat.chunks_exact(3).map(DVec3::from_slice).collect()
}

/// Returns how many refined points coincide with another.
fn assert_equals_opensubdiv(
    cage: &Mesh,
    scheme: Scheme,
    options: &SubdivisionOptions,
    levels: u32,
    what: &str,
) -> usize {
    let reference_cage = to_ref(cage);
    let osd = osd_options(scheme, options, &reference_cage);
    let subdivider = Subdivider::new(cage, scheme, levels, options).unwrap();
    let ours = subdivider.mesh().unwrap();
    let theirs = opensubdiv_refine(&reference_cage, &osd, levels).unwrap();
    let tol = tolerance(&ours);
    let our_faces: Vec<&[u32]> = ours.faces().collect();
    let their_faces: Vec<&[u32]> = theirs.faces().collect();
    let their_points = points(&theirs.positions);
    let coincident = assert_same_points_and_faces(
        (ours.positions(), &our_faces),
        (&their_points, &their_faces),
        tol,
        what,
    );

    // Every driver says the same.
    assert_drivers_agree(cage, (scheme, levels, options), &subdivider, &ours, what);
    if options.creases.is_empty() {
        // The refiner's stencils sum a repeated vertex's weights first, so
        // its points may differ from the one-shot's in the last bits.
        let refined = Refiner::new(cage, scheme, levels, options.naked_edges)
            .unwrap()
            .mesh()
            .unwrap();
        assert_eq!(
            refined.face_indices(),
            ours.face_indices(),
            "{what}: refiner faces"
        );
        for (v, (p, q)) in refined.positions().iter().zip(ours.positions()).enumerate() {
            assert!(
                (*p - *q).length() <= tol,
                "{what}: refiner vertex {v}: {p} vs {q}"
            );
        }
    }

    // The limit at every vertex.
    let their_limit = opensubdiv_limit_at_vertices(&reference_cage, &osd, levels);
    let our_limit = subdivider.limit().unwrap();
    assert_same_points_and_faces(
        (&our_limit.positions, &our_faces),
        (&points(&their_limit.positions), &their_faces),
        tol,
        &format!("{what} limit"),
    );

    // Face-varying values, one per vertex, smooth and linear: per refined
    // face, the cycle of its corners' values. (Boundary "none" can leave no
    // face at all.)
    let refined_values = match ours.face_count() {
        0 => Vec::new(),
        _ => face_varying_both(cage, &osd, levels, &subdivider),
    };
    for (linear, ours_values, their_values, their_indices) in refined_values {
        let as_points = |flat: &[f64]| -> Vec<DVec3> {
            flat.chunks_exact(2)
                .map(|uv| DVec3::new(uv[0], uv[1], 0.0))
                .collect()
        };
        // Ours are per corner; theirs are indexed by corner.
        let corner_faces = |sizes: &[u32]| -> Vec<Vec<u32>> {
            let mut next = 0u32;
            sizes
                .iter()
                .map(|&n| {
                    next += n;
                    (next - n..next).collect()
                })
                .collect()
        };
        let our_corners = corner_faces(ours.face_sizes());
        let their_corners = corner_faces(&theirs.face_sizes);
        let their_corner_values: Vec<f64> = their_indices
            .iter()
            .flat_map(|&i| {
                [
                    their_values[2 * i as usize],
                    their_values[2 * i as usize + 1],
                ]
            })
            .collect();
        let ours_refs: Vec<&[u32]> = our_corners.iter().map(Vec::as_slice).collect();
        let theirs_refs: Vec<&[u32]> = their_corners.iter().map(Vec::as_slice).collect();
        assert_same_points_and_faces(
            (&as_points(&ours_values), &ours_refs),
            (&as_points(&their_corner_values), &theirs_refs),
            tol,
            &format!("{what} face-varying {linear:?}"),
        );
    }
    coincident
}

#[test]
fn faces_repeating_a_vertex_equal_opensubdiv() {
    for (name, scheme, cage, creases) in cases() {
        let mut coincident = 0;
        for naked_edges in [
            NakedEdges::Fixed,
            NakedEdges::Smooth,
            NakedEdges::CornerFixed,
            NakedEdges::None,
        ] {
            for creasing in [Creasing::Uniform, Creasing::Chaikin] {
                let options = SubdivisionOptions {
                    naked_edges,
                    creasing,
                    creases: creases.clone(),
                    ..SubdivisionOptions::default()
                };
                for levels in 1..=3 {
                    let what =
                        format!("{scheme:?} {name} {naked_edges:?} {creasing:?} level {levels}");
                    coincident += assert_equals_opensubdiv(&cage, scheme, &options, levels, &what);
                }
            }
        }
        // The point of a degenerate edge stays on its vertex.
        if name.contains("degenerate") || name.contains("6 6 6") {
            assert!(coincident > 0, "{name}: no coincident points");
        }
    }
}

#[test]
fn repeated_vertices_are_refused_unless_allowed() {
    let grid = shapes::quad_grid(3, 3);
    let mut faces: Vec<Vec<u32>> = grid.faces().map(|f| f.to_vec()).collect();
    faces[4] = vec![5, 6, 6, 10, 9];
    let refused = Mesh::from_polygons(grid.positions().to_vec(), faces.clone()).unwrap_err();
    assert_eq!(
        refused,
        MeshError::RepeatedIndex {
            face: 4,
            index: 6,
            first: 1,
            second: 2
        }
    );
    let allowed = Mesh::from_polygons_with(grid.positions().to_vec(), faces, ALLOW).unwrap();
    assert_eq!(allowed.face(4), &[5, 6, 6, 10, 9]);
    // The other checks still hold.
    let short = Mesh::from_polygons_with(grid.positions().to_vec(), [[0u32, 0].as_slice()], ALLOW);
    assert!(matches!(
        short,
        Err(MeshError::FaceTooSmall { face: 0, size: 2 })
    ));
    let out =
        Mesh::from_polygons_with(grid.positions().to_vec(), [[0u32, 0, 99].as_slice()], ALLOW);
    assert!(matches!(
        out,
        Err(MeshError::IndexOutOfRange {
            face: 0,
            corner: 2,
            ..
        })
    ));
}
