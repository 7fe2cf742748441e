//! The cages and options beyond Weaverbird's against OpenSubdiv 3.5: hole
//! faces, boundary interpolation "none", Catmull-Clark's smooth-triangle
//! weights and the bilinear scheme, at levels 1-3, with every naked-edge
//! mode, creases and both creasing methods; positions within 1e-9 of the
//! bounding-box diagonal and the same faces, limit positions and normals,
//! and face-varying values where they apply.
//!
//! OpenSubdiv refines a hole like any face and tags its children; its users
//! leave them out of what they draw, and so does the reference here.

mod support;

use support::{
    assert_drivers_agree, assert_rows_close, bumped, face_map, face_varying_both,
    opensubdiv_limit_at_vertices, osd_options, to_ref, tolerance, vertex_map,
};
use weft::mesh::shapes;
use weft::subdivide::{
    subdivide, subdivide_with, Crease, Creasing, NakedEdges, Refiner, Scheme, Subdivider,
    SubdivisionOptions, TriangleRule,
};
use weft::toolbar::split::split_polygons;
use weft::{DVec3, Mesh};
use weft_reference::{opensubdiv_refine, BoundaryInterpolation, OsdOptions, OsdRefiner};

const MODES: [NakedEdges; 4] = [
    NakedEdges::Fixed,
    NakedEdges::Smooth,
    NakedEdges::CornerFixed,
    NakedEdges::None,
];

fn flat_points(points: &[DVec3]) -> Vec<f64> {
    points.iter().flat_map(|p| p.to_array()).collect()
}

/// A cage, the holes to cut in it and creases to put on it.
struct Case {
    name: &'static str,
    scheme: Scheme,
    cage: Mesh,
    holes: Vec<u32>,
    creases: Vec<Crease>,
}

/// The bumped 4 × 4 quad grid: faces 5 and 6 are inside, 0 at a corner
/// and 13 on the far side; the crease runs along the edges of face 5.
fn quad_cases() -> Vec<Case> {
    let grid = bumped(shapes::quad_grid(4, 4));
    let crease_by_hole = vec![([6, 7], 10.0), ([7, 12], 2.5), ([12, 11], 1.0)];
    let boundary_crease = vec![([0, 1], 10.0), ([1, 2], 10.0), ([2, 3], 0.5)];
    vec![
        Case {
            name: "quad grid, holes inside and at a corner, a crease beside them",
            scheme: Scheme::CatmullClark,
            cage: grid.clone(),
            holes: vec![5, 6, 0],
            creases: crease_by_hole,
        },
        Case {
            name: "quad grid, a hole on the boundary, the boundary creased",
            scheme: Scheme::CatmullClark,
            cage: grid,
            holes: vec![13],
            creases: boundary_crease,
        },
        Case {
            name: "closed cube, one face a hole",
            scheme: Scheme::CatmullClark,
            cage: shapes::cube(),
            holes: vec![2],
            creases: vec![([0, 1], 1.5)],
        },
        Case {
            name: "mixed polygons, the hexagon and a triangle holes",
            scheme: Scheme::CatmullClark,
            cage: shapes::mixed_polygons(),
            holes: vec![0, 5],
            creases: vec![([6, 7], 10.0), ([7, 8], 2.0)],
        },
        Case {
            name: "triangle grid, holes inside and on the boundary",
            scheme: Scheme::Loop,
            cage: bumped(shapes::triangle_grid(4, 3)),
            holes: vec![9, 10, 1],
            creases: vec![([6, 7], 10.0), ([7, 8], 1.5)],
        },
        Case {
            name: "icosahedron, a hole beside a crease",
            scheme: Scheme::Loop,
            cage: shapes::icosahedron(),
            holes: vec![0],
            creases: vec![(edge_of(&shapes::icosahedron(), 0), 2.0)],
        },
    ]
}

/// Whether every edge has one or two faces running it in opposite
/// directions and every vertex one fan: where normals have a meaning.
fn manifold(mesh: &Mesh) -> bool {
    let info = weft::Topology::try_new(mesh).unwrap().info(mesh);
    info.non_manifold_edge_count == 0 && info.non_manifold_vertex_count == 0 && info.is_oriented
}

fn edge_of(mesh: &Mesh, face: usize) -> [u32; 2] {
    [mesh.face(face)[0], mesh.face(face)[1]]
}

/// The options of a case in one naked-edge mode and creasing method, with
/// or without its holes.
fn case_options(
    case: &Case,
    naked_edges: NakedEdges,
    creasing: Creasing,
    holes: bool,
) -> SubdivisionOptions {
    SubdivisionOptions {
        naked_edges,
        creasing,
        creases: case.creases.clone(),
        holes: if holes {
            case.holes.clone()
        } else {
            Vec::new()
        },
        ..SubdivisionOptions::default()
    }
}

/// Positions, faces, limit and (smooth and linear) face-varying values of
/// one subdivision against OpenSubdiv's.
fn assert_equals_opensubdiv(
    cage: &Mesh,
    scheme: Scheme,
    options: &SubdivisionOptions,
    levels: u32,
    what: &str,
) {
    let reference_cage = to_ref(cage);
    let osd = osd_options(scheme, options, &reference_cage);
    let subdivider = Subdivider::new(cage, scheme, levels, options).unwrap();
    let ours = subdivider.mesh().unwrap();
    let theirs = opensubdiv_refine(&reference_cage, &osd, levels).unwrap();
    let map = vertex_map(&ours, &theirs, what);
    let tol = tolerance(&ours);
    assert_rows_close(
        &flat_points(ours.positions()),
        &theirs.positions,
        3,
        &map,
        tol,
        what,
    );
    let faces = face_map(&ours, &theirs, &map);
    assert_eq!(faces.len(), theirs.face_count(), "{what}: faces");

    // The one-shot drivers and the counts say the same.
    assert_drivers_agree(cage, (scheme, levels, options), &subdivider, &ours, what);
    let parents = subdivider.parent_faces();
    assert!(
        parents.iter().all(|p| !options.holes.contains(p)),
        "{what}: a hole's child"
    );

    // The limit at every vertex. Normals are compared where the tangents
    // span a plane: at a valence-2 vertex between two symmetric faces they
    // are parallel, Weft's normal is zero and OpenSubdiv's rounding noise.
    let their_limit = opensubdiv_limit_at_vertices(&reference_cage, &osd, levels);
    let our_limit = subdivider.limit().unwrap();
    assert_rows_close(
        &flat_points(&our_limit.positions),
        &their_limit.positions,
        3,
        &map,
        tol,
        &format!("{what} limit"),
    );
    if manifold(cage) {
        let spanning: Vec<usize> = map
            .iter()
            .map(|&r| {
                let row = |t: &[f64]| DVec3::from_slice(&t[3 * r..3 * r + 3]);
                let (du, dv) = (row(&their_limit.du), row(&their_limit.dv));
                if du.cross(dv).length() > 1e-9 * du.length() * dv.length() {
                    r
                } else {
                    usize::MAX
                }
            })
            .collect();
        assert_rows_close(
            &flat_points(&our_limit.normals),
            &their_limit.normals,
            3,
            &spanning,
            1e-9,
            &format!("{what} normals"),
        );
    }

    // Face-varying values: a value per vertex, smooth and linear.
    for (linear, ours_values, their_values, their_indices) in
        face_varying_both(cage, &osd, levels, &subdivider)
    {
        assert_eq!(
            ours_values.len(),
            2 * their_indices.len(),
            "{what}: face-varying corners"
        );
        let mut their_offsets = vec![0usize];
        for &n in &theirs.face_sizes {
            their_offsets.push(their_offsets.last().unwrap() + n as usize);
        }
        for (f, &(g, r)) in faces.iter().enumerate() {
            let n = ours.face(f).len();
            for k in 0..n {
                let ours_corner = ours.face_offsets()[f] as usize + k;
                let value = their_indices[their_offsets[g] + (k + r) % n] as usize;
                for axis in 0..2 {
                    let (a, b) = (
                        ours_values[2 * ours_corner + axis],
                        their_values[2 * value + axis],
                    );
                    assert!(
                        (a - b).abs() <= tol,
                        "{what} {linear:?}: face {f} corner {k}: {a} vs OpenSubdiv {b}"
                    );
                }
            }
        }
    }
}

#[test]
fn holes_equal_opensubdiv_in_every_mode() {
    for case in quad_cases() {
        for naked_edges in MODES {
            for creasing in [Creasing::Uniform, Creasing::Chaikin] {
                let options = case_options(&case, naked_edges, creasing, true);
                for levels in 1..=3 {
                    let what = format!(
                        "{:?} {} {naked_edges:?} {creasing:?} level {levels}",
                        case.scheme, case.name
                    );
                    assert_equals_opensubdiv(&case.cage, case.scheme, &options, levels, &what);
                }
            }
        }
    }
}

#[test]
fn boundary_none_with_creases_equals_opensubdiv() {
    for case in quad_cases() {
        for creasing in [Creasing::Uniform, Creasing::Chaikin] {
            let options = case_options(&case, NakedEdges::None, creasing, false);
            for levels in 1..=3 {
                let what = format!(
                    "{:?} {} none {creasing:?} level {levels}",
                    case.scheme, case.name
                );
                assert_equals_opensubdiv(&case.cage, case.scheme, &options, levels, &what);
            }
        }
    }
}

#[test]
fn boundary_none_leaves_holes_and_keeps_every_point() {
    let grid = shapes::quad_grid(3, 3);
    let none = subdivide(&grid, Scheme::CatmullClark, 2, NakedEdges::None).unwrap();
    let smooth = subdivide(&grid, Scheme::CatmullClark, 2, NakedEdges::Smooth).unwrap();
    // Only the middle face touches no boundary vertex: its 16 children stay.
    assert_eq!(none.face_count(), 16);
    assert_eq!(none.positions(), smooth.positions());
    let middle: Vec<u32> = smooth.face_indices()[4 * 16 * 4..5 * 16 * 4].to_vec();
    assert_eq!(none.face_indices(), &middle[..]);
    // The refiner and the one-shot agree.
    let refiner = Refiner::new(&grid, Scheme::CatmullClark, 2, NakedEdges::None).unwrap();
    assert_eq!(refiner.mesh().unwrap(), none);
    // And OpenSubdiv agrees on every named open shape.
    for (name, cage) in [
        ("quad grid", bumped(shapes::quad_grid(4, 3))),
        ("quad grid with a hole", shapes::quad_grid_with_hole()),
        ("fin", shapes::fin()),
        ("bow-tie", shapes::bow_tie()),
        ("Möbius strip", shapes::mobius_strip(8)),
    ] {
        for scheme in [Scheme::CatmullClark, Scheme::Loop] {
            if scheme == Scheme::Loop && !cage.is_triangle_mesh() {
                continue;
            }
            for levels in 1..=3 {
                let what = format!("{scheme:?} {name} none level {levels}");
                let options = SubdivisionOptions::new(NakedEdges::None);
                assert_equals_opensubdiv(&cage, scheme, &options, levels, &what);
            }
        }
    }
}

/// Cages whose triangles sit among quads and n-gons, for the smooth-triangle
/// weights: the mixed prism, a quad grid with a fan of triangles inside and
/// triangles on its boundary, and an all-triangle icosahedron.
fn triangle_cases() -> Vec<(&'static str, Mesh, Vec<Crease>)> {
    let grid = bumped(shapes::quad_grid(3, 3));
    let mut faces: Vec<Vec<u32>> = grid.faces().map(|f| f.to_vec()).collect();
    // The middle quad 5-6-10-9 and the corner quad 0-1-5-4 become triangles.
    faces[4] = vec![5, 6, 10];
    faces.push(vec![5, 10, 9]);
    faces[0] = vec![0, 1, 5];
    faces.push(vec![0, 5, 4]);
    let mixed_grid = Mesh::from_polygons(grid.positions().to_vec(), faces).unwrap();
    vec![
        (
            "mixed polygons",
            shapes::mixed_polygons(),
            vec![([2, 9], 1.5), ([9, 8], 10.0)],
        ),
        (
            "quad grid with triangles",
            mixed_grid,
            vec![([5, 10], 0.5), ([6, 10], 2.0)],
        ),
        ("icosahedron", shapes::icosahedron(), Vec::new()),
    ]
}

#[test]
fn smooth_triangles_equal_opensubdiv() {
    for (name, cage, creases) in triangle_cases() {
        for naked_edges in MODES {
            for creasing in [Creasing::Uniform, Creasing::Chaikin] {
                for creased in [false, true] {
                    let options = SubdivisionOptions {
                        naked_edges,
                        creasing,
                        creases: if creased { creases.clone() } else { Vec::new() },
                        triangles: TriangleRule::Smooth,
                        ..SubdivisionOptions::default()
                    };
                    for levels in 1..=3 {
                        let what = format!("{name} smooth triangles {naked_edges:?} {creasing:?} creased {creased} level {levels}");
                        assert_equals_opensubdiv(
                            &cage,
                            Scheme::CatmullClark,
                            &options,
                            levels,
                            &what,
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn smooth_triangles_move_only_what_touches_a_triangle() {
    let cage = shapes::mixed_polygons();
    let catmark = SubdivisionOptions::new(NakedEdges::Smooth);
    let smooth = SubdivisionOptions {
        triangles: TriangleRule::Smooth,
        ..catmark.clone()
    };
    let a = subdivide_with(&cage, Scheme::CatmullClark, 1, &catmark).unwrap();
    let b = subdivide_with(&cage, Scheme::CatmullClark, 1, &smooth).unwrap();
    let moved: Vec<usize> = (0..a.vertex_count())
        .filter(|&v| a.positions()[v] != b.positions()[v])
        .collect();
    // Level 1 moves only edge points of edges beside the two triangles
    // (faces 5 and 6 share the vertices 2, 3, 8 and 9).
    assert!(!moved.is_empty());
    let topology = weft::Topology::try_new(&cage).unwrap();
    for &v in &moved {
        let e = v - cage.vertex_count();
        let [x, y] = topology.edges()[e];
        assert!(
            [2, 3, 8, 9].contains(&x) && [2, 3, 8, 9].contains(&y),
            "vertex {v} (edge {x}-{y}) moved"
        );
    }
    // Loop ignores the rule.
    let ico = shapes::icosahedron();
    assert_eq!(
        subdivide_with(&ico, Scheme::Loop, 2, &smooth).unwrap(),
        subdivide_with(&ico, Scheme::Loop, 2, &catmark).unwrap()
    );
}

#[test]
fn split_polygons_is_opensubdivs_bilinear_scheme() {
    let cases = [
        ("cube", shapes::cube()),
        ("mixed polygons", shapes::mixed_polygons()),
        ("open quad grid", bumped(shapes::quad_grid(3, 2))),
        ("open triangle grid", bumped(shapes::triangle_grid(3, 2))),
        ("fin", shapes::fin()),
        ("bow-tie", shapes::bow_tie()),
        ("Möbius strip", shapes::mobius_strip(8)),
    ];
    for (name, cage) in cases {
        let reference_cage = to_ref(&cage);
        for boundary in [BoundaryInterpolation::EdgeOnly, BoundaryInterpolation::None] {
            let osd = OsdOptions::new(weft_reference::Scheme::Bilinear, boundary);
            for levels in 1..=3 {
                let what = format!("bilinear {boundary:?} level {levels} of the {name}");
                let ours = split_polygons(&cage, levels).unwrap();
                let theirs = opensubdiv_refine(&reference_cage, &osd, levels).unwrap();
                let map = vertex_map(&ours, &theirs, &what);
                assert_rows_close(
                    &flat_points(ours.positions()),
                    &theirs.positions,
                    3,
                    &map,
                    tolerance(&ours),
                    &what,
                );
                assert_eq!(
                    face_map(&ours, &theirs, &map).len(),
                    theirs.face_count(),
                    "{what}: faces"
                );
            }
        }
    }
}

/// The rows of `width` numbers in `values`, for comparing point sets whose
/// points may coincide (so that no one-to-one match by position exists).
fn rows(values: &[f64], width: usize) -> Vec<Vec<f64>> {
    values.chunks_exact(width).map(|r| r.to_vec()).collect()
}

/// Every row of ours matched to its own row of theirs within `tol` (rows
/// may repeat, so the match is by multiset, not by position).
fn assert_rows_equal(ours: &[Vec<f64>], theirs: &[Vec<f64>], tol: f64, what: &str) {
    assert_eq!(ours.len(), theirs.len(), "{what}: counts");
    let mut taken = vec![false; theirs.len()];
    for (k, a) in ours.iter().enumerate() {
        let close = |b: &Vec<f64>| a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol);
        let found = (0..theirs.len()).find(|&r| !taken[r] && close(&theirs[r]));
        let Some(r) = found else {
            panic!("{what}: row {k} {a:?} has no OpenSubdiv row within {tol:e}");
        };
        taken[r] = true;
    }
}

/// The faces as their corners' positions, three numbers a corner.
fn face_points(positions: &[f64], sizes: &[u32], indices: &[u32]) -> Vec<Vec<f64>> {
    let mut faces = Vec::new();
    let mut start = 0;
    for &n in sizes {
        let corners = &indices[start..start + n as usize];
        faces.push(
            corners
                .iter()
                .flat_map(|&v| positions[3 * v as usize..3 * v as usize + 3].to_vec())
                .collect(),
        );
        start += n as usize;
    }
    faces
}

/// Every face of ours matched to its own face of theirs with the same
/// corners (in any order) within `tol`.
fn assert_same_faces(ours: &[Vec<f64>], theirs: &[Vec<f64>], tol: f64, what: &str) {
    assert_eq!(ours.len(), theirs.len(), "{what}: face counts");
    let corners = |f: &Vec<f64>| f.chunks_exact(3).map(|c| c.to_vec()).collect::<Vec<_>>();
    let same = |a: &Vec<f64>, b: &Vec<f64>| {
        let (a, b) = (corners(a), corners(b));
        a.len() == b.len()
            && a.iter().all(|p| {
                b.iter()
                    .any(|q| p.iter().zip(q).all(|(x, y)| (x - y).abs() <= tol))
            })
    };
    let mut taken = vec![false; theirs.len()];
    for (k, a) in ours.iter().enumerate() {
        let Some(r) = (0..theirs.len()).find(|&r| !taken[r] && same(a, &theirs[r])) else {
            panic!("{what}: face {k} {a:?} has no OpenSubdiv face with the same corners");
        };
        taken[r] = true;
    }
}

#[test]
fn coincident_loop_triangles_equal_opensubdiv() {
    let p = |x: f64, y: f64, z: f64| DVec3::new(x, y, z);
    let flat = [p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0)];
    let mut doubled_faces: Vec<Vec<u32>> =
        shapes::icosahedron().faces().map(|f| f.to_vec()).collect();
    let twin = doubled_faces[3].iter().rev().copied().collect();
    doubled_faces.push(twin);
    let ico = shapes::icosahedron();
    let cases = [
        (
            "pillow",
            Mesh::from_polygons(flat.to_vec(), [[0u32, 1, 2], [1, 0, 2]]).unwrap(),
        ),
        (
            "the same triangle twice",
            Mesh::from_polygons(flat.to_vec(), [[0u32, 1, 2], [0, 1, 2]]).unwrap(),
        ),
        (
            "three triangles on one vertex set",
            Mesh::from_polygons(flat.to_vec(), [[2u32, 0, 1], [2, 1, 0], [0, 2, 1]]).unwrap(),
        ),
        (
            "icosahedron with a face doubled",
            Mesh::from_polygons(ico.positions().to_vec(), doubled_faces).unwrap(),
        ),
    ];
    for (name, cage) in &cases {
        let reference_cage = to_ref(cage);
        for naked_edges in MODES {
            for creasing in [Creasing::Uniform, Creasing::Chaikin] {
                let options = SubdivisionOptions {
                    naked_edges,
                    creasing,
                    creases: vec![(edge_of(cage, 0), 1.5)],
                    ..SubdivisionOptions::default()
                };
                let osd = osd_options(Scheme::Loop, &options, &reference_cage);
                for levels in 1..=3 {
                    let what = format!("{name} {naked_edges:?} {creasing:?} level {levels}");
                    let ours = subdivide_with(cage, Scheme::Loop, levels, &options).unwrap();
                    let theirs = opensubdiv_refine(&reference_cage, &osd, levels).unwrap();
                    let tol = tolerance(&ours);
                    let our_positions = flat_points(ours.positions());
                    assert_rows_equal(
                        &rows(&our_positions, 3),
                        &rows(&theirs.positions, 3),
                        tol,
                        &what,
                    );
                    assert_same_faces(
                        &face_points(&our_positions, ours.face_sizes(), ours.face_indices()),
                        &face_points(&theirs.positions, &theirs.face_sizes, &theirs.face_indices),
                        tol,
                        &format!("{what} faces"),
                    );
                    let plain = subdivide(cage, Scheme::Loop, levels, naked_edges).unwrap();
                    let counts =
                        weft::subdivide::refined_counts(cage, Scheme::Loop, levels).unwrap();
                    assert_eq!(counts.vertex_count, plain.vertex_count(), "{what}: counts");
                    if naked_edges != NakedEdges::None {
                        assert_eq!(
                            plain.vertex_count(),
                            theirs.vertex_count(),
                            "{what}: the plain path"
                        );
                    }
                    if !manifold(cage) {
                        // The limit at non-manifold vertices is OpenSubdiv's own
                        // convention, compared in creases.rs where it applies.
                        continue;
                    }
                    let full = OsdOptions {
                        full_topology: true,
                        ..osd.clone()
                    };
                    let limit = OsdRefiner::new(&reference_cage, &full, levels)
                        .unwrap()
                        .limit(&reference_cage.positions)
                        .unwrap();
                    let ours_limit = Subdivider::new(cage, Scheme::Loop, levels, &options)
                        .unwrap()
                        .limit()
                        .unwrap();
                    assert_rows_equal(
                        &rows(&flat_points(&ours_limit.positions), 3),
                        &rows(&limit.positions, 3),
                        tol,
                        &format!("{what} limit"),
                    );
                }
            }
        }
    }
}
