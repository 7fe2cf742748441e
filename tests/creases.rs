//! Creases, corners, carried data, face-varying UVs and the limit surface
//! against OpenSubdiv 3.5, for both schemes, at levels 1-3, on closed and
//! open shapes, with infinite, integer and fractional sharpness and both
//! creasing methods. Everything must agree within 1e-9 of the bounding-box
//! diagonal.
//!
//! Weft and OpenSubdiv make the same faces in the same order (the children
//! of face f contiguous, child i at corner i), so vertices are matched
//! through the faces: corner k of refined face f is the same vertex in both.

mod support;

use support::{assert_rows_close, bumped, face_map, osd_options, to_ref, tolerance, vertex_map};
use weft::mesh::shapes;
use weft::subdivide::FaceVaryingLinear;
use weft::subdivide::{
    subdivide, subdivide_with, Crease, Creasing, NakedEdges, Scheme, Subdivider, SubdivisionOptions,
};
use weft::{DVec3, Mesh};
use weft_reference::{
    opensubdiv_refine, opensubdiv_refine_face_varying, FVarLinear, OsdOptions, OsdRefiner, RefMesh,
};

fn shapes_for(scheme: Scheme) -> Vec<(&'static str, Mesh, bool)> {
    match scheme {
        Scheme::CatmullClark => vec![
            ("cube", shapes::cube(), true),
            ("torus", shapes::torus(6, 4), true),
            ("quad grid", bumped(shapes::quad_grid(3, 3)), false),
        ],
        Scheme::Loop => vec![
            ("icosahedron", shapes::icosahedron(), true),
            ("triangle torus", shapes::triangle_torus(6, 4), true),
            ("triangle grid", bumped(shapes::triangle_grid(3, 3)), false),
        ],
    }
}

/// The edges of the cage's first faces, creased with `sharpness` in turn,
/// and two corners.
fn creased(mesh: &Mesh, sharpness: &[f64], corners: &[f64]) -> (Vec<Crease>, Vec<(u32, f64)>) {
    let mut edges = Vec::new();
    for f in 0..mesh.face_count().min(3) {
        let face = mesh.face(f);
        for i in 0..face.len() {
            let edge = [face[i], face[(i + 1) % face.len()]];
            let key = [edge[0].min(edge[1]), edge[0].max(edge[1])];
            if !edges
                .iter()
                .any(|&(e, _): &([u32; 2], f64)| [e[0].min(e[1]), e[0].max(e[1])] == key)
            {
                edges.push((edge, sharpness[edges.len() % sharpness.len()]));
            }
        }
    }
    let last = mesh.vertex_count() as u32 - 1;
    let corner_list = corners
        .iter()
        .enumerate()
        .map(|(i, &s)| (if i == 0 { last } else { last - 2 }, s))
        .collect();
    (edges, corner_list)
}

const SHARPNESS_SETS: [(&str, &[f64], &[f64]); 4] = [
    ("infinite", &[f64::INFINITY], &[f64::INFINITY]),
    ("integer", &[1.0, 2.0, 3.0], &[1.0, 2.0]),
    ("fractional", &[0.5, 2.5, 1.25, 0.75], &[0.5, 1.5]),
    ("mixed", &[f64::INFINITY, 2.5, 0.5, 1.0, 0.0], &[2.5]),
];

/// The naked-edge modes worth comparing: on a closed shape they all agree.
fn naked_edge_modes(closed: bool) -> &'static [NakedEdges] {
    if closed {
        &[NakedEdges::Smooth]
    } else {
        &[
            NakedEdges::Smooth,
            NakedEdges::CornerFixed,
            NakedEdges::Fixed,
        ]
    }
}
/// Both creasing rules with each naked-edge mode of `modes`, each with
/// these creases and corners.
fn option_sets(
    creases: &[Crease],
    corners: &[(u32, f64)],
    modes: &[NakedEdges],
) -> Vec<SubdivisionOptions> {
    [Creasing::Uniform, Creasing::Chaikin]
        .into_iter()
        .flat_map(|creasing| {
            modes.iter().map(move |&naked_edges| SubdivisionOptions {
                naked_edges,
                creases: creases.to_vec(),
                corners: corners.to_vec(),
                creasing,
                ..SubdivisionOptions::default()
            })
        })
        .collect()
}

/// One comparison with OpenSubdiv: a shape creased by one sharpness set,
/// under one scheme, creasing rule and naked-edge mode.
struct CreasedCase {
    scheme: Scheme,
    /// The scheme, shape, set, rule and mode, for messages.
    label: String,
    cage: Mesh,
    reference_cage: RefMesh,
    options: SubdivisionOptions,
    osd: OsdOptions,
}

/// Every scheme's shapes with every sharpness set, creasing rule and
/// naked-edge mode worth comparing.
fn creased_cases() -> Vec<CreasedCase> {
    let mut cases = Vec::new();
    for scheme in [Scheme::CatmullClark, Scheme::Loop] {
        for (name, cage, closed) in shapes_for(scheme) {
            let reference_cage = to_ref(&cage);
            for &(set, sharpness, corner_sharpness) in &SHARPNESS_SETS {
                let (creases, corners) = creased(&cage, sharpness, corner_sharpness);
                for options in option_sets(&creases, &corners, naked_edge_modes(closed)) {
                    let (creasing, naked_edges) = (options.creasing, options.naked_edges);
                    cases.push(CreasedCase {
                        scheme,
                        label: format!("{scheme:?} {name} {set} {creasing:?} {naked_edges:?}"),
                        cage: cage.clone(),
                        reference_cage: reference_cage.clone(),
                        osd: osd_options(scheme, &options, &reference_cage),
                        options,
                    });
                }
            }
        }
    }
    cases
}

#[test]
fn creases_and_corners_equal_opensubdiv() {
    for case in creased_cases() {
        for levels in 1..=3 {
            let what = format!("{} level {levels}", case.label);
            let ours = subdivide_with(&case.cage, case.scheme, levels, &case.options).unwrap();
            let theirs = opensubdiv_refine(&case.reference_cage, &case.osd, levels).unwrap();
            let map = vertex_map(&ours, &theirs, &what);
            let flat: Vec<f64> = ours.positions().iter().flat_map(|p| p.to_array()).collect();
            assert_rows_close(&flat, &theirs.positions, 3, &map, tolerance(&ours), &what);
        }
    }
}

#[test]
fn without_creases_equals_the_plain_schemes() {
    for scheme in [Scheme::CatmullClark, Scheme::Loop] {
        for (name, cage, _) in shapes_for(scheme) {
            for mode in [
                NakedEdges::Fixed,
                NakedEdges::Smooth,
                NakedEdges::CornerFixed,
            ] {
                let plain = subdivide(&cage, scheme, 2, mode).unwrap();
                let ours =
                    subdivide_with(&cage, scheme, 2, &SubdivisionOptions::new(mode)).unwrap();
                assert_eq!(ours.face_indices(), plain.face_indices(), "{name}");
                for (a, b) in ours.positions().iter().zip(plain.positions()) {
                    assert!(
                        (*a - *b).length() < 1e-12,
                        "{scheme:?} {name} {mode:?}: {a} vs {b}"
                    );
                }
            }
        }
    }
}

#[test]
fn carried_vertex_data_equals_opensubdiv() {
    for scheme in [Scheme::CatmullClark, Scheme::Loop] {
        for (name, cage, closed) in shapes_for(scheme) {
            let modes = naked_edge_modes(closed);
            let (creases, corners) = creased(&cage, &[2.5, 0.5, f64::INFINITY], &[1.5]);
            let reference_cage = to_ref(&cage);
            // Five columns: a colour and two weights, not linear in position.
            let width = 5;
            let data: Vec<f64> = (0..cage.vertex_count())
                .flat_map(|v| {
                    let x = v as f64;
                    [x.sin(), (0.3 * x).cos(), 0.1 * x, x * x * 0.01, 1.0]
                })
                .collect();
            for options in option_sets(&creases, &corners, modes) {
                let (creasing, naked_edges) = (options.creasing, options.naked_edges);
                let osd = osd_options(scheme, &options, &reference_cage);
                for levels in 1..=3 {
                    let what = format!(
                        "{scheme:?} {name} {creasing:?} {naked_edges:?} vertex data level {levels}"
                    );
                    let subdivider = Subdivider::new(&cage, scheme, levels, &options).unwrap();
                    let ours = subdivider.vertex_data(&data, width).unwrap();
                    let refiner = OsdRefiner::new(&reference_cage, &osd, levels).unwrap();
                    let theirs = refiner.interpolate(&data, width);
                    let mut faces = refiner.faces();
                    faces.positions = refiner.interpolate(&reference_cage.positions, 3);
                    let map = vertex_map(&subdivider.mesh().unwrap(), &faces, &what);
                    assert_rows_close(&ours, &theirs, width, &map, 1e-12, &what);
                    // The constant column stays 1.
                    assert!(ours
                        .chunks_exact(width)
                        .all(|row| (row[4] - 1.0).abs() < 1e-12));
                }
            }
        }
    }
}

#[test]
fn an_unknown_crease_edge_is_named() {
    let cube = shapes::cube();
    let options = SubdivisionOptions {
        creases: vec![([0, 1], 1.0), ([0, 7], 2.0)],
        ..SubdivisionOptions::default()
    };
    let err = subdivide_with(&cube, Scheme::CatmullClark, 1, &options).unwrap_err();
    assert!(
        err.to_string().contains("crease 1 joins vertices 0 and 7"),
        "{err}"
    );
    let options = SubdivisionOptions {
        corners: vec![(3, f64::NAN)],
        ..SubdivisionOptions::default()
    };
    let err = subdivide_with(&cube, Scheme::CatmullClark, 1, &options).unwrap_err();
    assert!(err.to_string().contains("corner 0 (vertex 3)"), "{err}");
    let options = SubdivisionOptions {
        creases: vec![([0, 1], -1.0)],
        ..SubdivisionOptions::default()
    };
    assert!(subdivide_with(&cube, Scheme::CatmullClark, 1, &options).is_err());
}

#[test]
fn an_infinite_corner_stays_and_a_hard_crease_stays_on_its_polyline() {
    let cube = shapes::cube();
    let options = SubdivisionOptions {
        corners: vec![(0, f64::INFINITY)],
        ..SubdivisionOptions::default()
    };
    let out = subdivide_with(&cube, Scheme::CatmullClark, 3, &options).unwrap();
    assert_eq!(out.positions()[0], cube.positions()[0]);
}

#[test]
fn limit_positions_and_normals_equal_opensubdiv() {
    for case in creased_cases() {
        for levels in 0..=3 {
            let what = format!("{} limit at level {levels}", case.label);
            let subdivider =
                Subdivider::new(&case.cage, case.scheme, levels, &case.options).unwrap();
            let ours = subdivider.limit().unwrap();
            let full = OsdOptions {
                full_topology: true,
                ..case.osd.clone()
            };
            let refiner = OsdRefiner::new(&case.reference_cage, &full, levels).unwrap();
            let theirs = refiner.limit(&case.reference_cage.positions).unwrap();
            let mut faces = refiner.faces();
            faces.positions = refiner.interpolate(&case.reference_cage.positions, 3);
            let refined = subdivider.mesh().unwrap();
            let map = vertex_map(&refined, &faces, &what);
            let flat = |v: &[DVec3]| v.iter().flat_map(|p| p.to_array()).collect::<Vec<f64>>();
            assert_rows_close(
                &flat(&ours.positions),
                &theirs.positions,
                3,
                &map,
                tolerance(&refined),
                &what,
            );
            assert_rows_close(
                &flat(&ours.normals),
                &theirs.normals,
                3,
                &map,
                1e-9,
                &format!("{what} normals"),
            );
        }
    }
}

/// UVs with seams: per-face islands on the cube, a wrapped cylindrical map
/// on closed shapes (seams where it wraps), two islands on grids.
fn uv_layout(name: &str, mesh: &Mesh) -> (Vec<f64>, Vec<u32>) {
    let mut keys: std::collections::HashMap<(u32, u64, u64), u32> = Default::default();
    let mut values = Vec::new();
    let mut indices = Vec::new();
    for (f, face) in mesh.faces().enumerate() {
        let raw: Vec<[f64; 2]> = face
            .iter()
            .map(|&v| {
                let p = mesh.positions()[v as usize];
                if name.contains("grid") {
                    [p.x, p.y]
                } else if name == "cube" {
                    [
                        p.x + 0.5 * p.z + 0.3 * f as f64,
                        p.y - 0.25 * p.z + 0.1 * f as f64,
                    ]
                } else {
                    let u = p.y.atan2(p.x) / std::f64::consts::TAU + 0.5;
                    let r = (p.x * p.x + p.y * p.y).sqrt();
                    let w = p.z.atan2(r - 1.0) / std::f64::consts::TAU + 0.5;
                    [u, w]
                }
            })
            .collect();
        let mut uv = raw.clone();
        for axis in 0..2 {
            let max = raw.iter().map(|t| t[axis]).fold(f64::MIN, f64::max);
            for t in uv.iter_mut() {
                if max - t[axis] > 0.5 {
                    t[axis] += 1.0;
                }
            }
        }
        let centroid_x = raw.iter().map(|t| t[0]).sum::<f64>() / raw.len() as f64;
        if name.starts_with("dart") {
            // One value per vertex, except at vertex 1 (on the border) left
            // of x = 1: a seam from the border that ends inside (a dart).
            for (k, &v) in face.iter().enumerate() {
                let p = mesh.positions()[v as usize];
                let split = v == 1 && centroid_x < 1.0;
                let key = (v, split as u64, 0);
                let index = *keys.entry(key).or_insert_with(|| {
                    values.extend_from_slice(&[p.x + if split { 0.3 } else { 0.0 }, p.y]);
                    (values.len() / 2 - 1) as u32
                });
                let _ = k;
                indices.push(index);
            }
            continue;
        }
        for (k, &v) in face.iter().enumerate() {
            let mut t = uv[k];
            let island = if name == "cube" {
                f as u64
            } else if name.contains("grid") && centroid_x > 1.5 {
                t[0] += 0.25;
                1
            } else {
                0
            };
            let key = (v, t[0].to_bits() ^ island, t[1].to_bits());
            let index = *keys.entry(key).or_insert_with(|| {
                values.extend_from_slice(&t);
                (values.len() / 2 - 1) as u32
            });
            indices.push(index);
        }
    }
    (values, indices)
}

#[test]
fn face_varying_uvs_equal_opensubdiv() {
    let modes = [
        (FaceVaryingLinear::All, FVarLinear::All),
        (FaceVaryingLinear::Boundaries, FVarLinear::Boundaries),
        (FaceVaryingLinear::CornersOnly, FVarLinear::CornersOnly),
        (FaceVaryingLinear::Smooth, FVarLinear::None),
        (FaceVaryingLinear::CornersPlus1, FVarLinear::CornersPlus1),
        (FaceVaryingLinear::CornersPlus2, FVarLinear::CornersPlus2),
    ];
    let mut failures = Vec::new();
    for scheme in [Scheme::CatmullClark, Scheme::Loop] {
        let mut cases = shapes_for(scheme);
        let (_, grid, _) = cases[2].clone();
        cases.push(("dart grid", grid, false));
        for (name, cage, closed) in cases {
            let (uvs, uv_indices) = uv_layout(name, &cage);
            let reference_cage = to_ref(&cage);
            let naked_modes: &[NakedEdges] = if closed {
                &[NakedEdges::Smooth]
            } else {
                &[NakedEdges::Smooth, NakedEdges::CornerFixed]
            };
            let crease_sets = std::iter::once(("uncreased", &[][..], &[][..]))
                .chain(SHARPNESS_SETS.iter().copied());
            for (k, (set, sharpness, corner_sharpness)) in crease_sets.enumerate() {
                let (creases, corners) = if sharpness.is_empty() {
                    (Vec::new(), Vec::new())
                } else {
                    creased(&cage, sharpness, corner_sharpness)
                };
                for &naked_edges in naked_modes {
                    let options = SubdivisionOptions {
                        naked_edges,
                        creases: creases.clone(),
                        corners: corners.clone(),
                        creasing: if k % 2 == 0 {
                            Creasing::Uniform
                        } else {
                            Creasing::Chaikin
                        },
                        ..SubdivisionOptions::default()
                    };
                    for (ours_linear, their_linear) in modes {
                        let mut osd = osd_options(scheme, &options, &reference_cage);
                        osd.fvar_linear = their_linear;
                        for levels in 1..=3 {
                            let what = format!("{scheme:?} {name} {set} {naked_edges:?} {ours_linear:?} level {levels}");
                            let subdivider =
                                Subdivider::new(&cage, scheme, levels, &options).unwrap();
                            let ours = subdivider
                                .face_varying(&uvs, 2, &uv_indices, ours_linear)
                                .unwrap();
                            let (values, indices) = opensubdiv_refine_face_varying(
                                &reference_cage,
                                &osd,
                                levels,
                                &uvs,
                                &uv_indices,
                            )
                            .unwrap();
                            let theirs_mesh =
                                opensubdiv_refine(&reference_cage, &osd, levels).unwrap();
                            let refined = subdivider.mesh().unwrap();
                            let map = vertex_map(&refined, &theirs_mesh, &what);
                            let faces = face_map(&refined, &theirs_mesh, &map);
                            let their_offsets: Vec<usize> = std::iter::once(0)
                                .chain(theirs_mesh.face_sizes.iter().scan(0usize, |s, &n| {
                                    *s += n as usize;
                                    Some(*s)
                                }))
                                .collect();
                            let mut worst = 0.0f64;
                            for (f, &(g, r)) in faces.iter().enumerate() {
                                let n = refined.face(f).len();
                                for k in 0..n {
                                    let ours_corner = refined.face_offsets()[f] as usize + k;
                                    let their_corner = their_offsets[g] + (k + r) % n;
                                    let value = indices[their_corner] as usize;
                                    for axis in 0..2 {
                                        let d = (ours[2 * ours_corner + axis]
                                            - values[2 * value + axis])
                                            .abs();
                                        worst = worst.max(d);
                                        if d > 1e-9
                                            && std::env::var("FV_DEBUG").is_ok()
                                            && levels == 1
                                        {
                                            eprintln!("{what}: face {f} corner {k} vertex {} ours {} theirs {}", refined.face(f)[k], ours[2 * ours_corner + axis], values[2 * value + axis]);
                                        }
                                    }
                                }
                            }
                            if worst > 1e-9 {
                                failures.push(format!("{what}: off by {worst:e}"));
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn every_named_shape_with_creases_equals_opensubdiv_and_never_panics() {
    let all = [
        ("tetrahedron", shapes::tetrahedron()),
        ("quad grid with a hole", shapes::quad_grid_with_hole()),
        ("mixed polygons", shapes::mixed_polygons()),
        ("fin", shapes::fin()),
        ("bow-tie", shapes::bow_tie()),
        ("Möbius strip", shapes::mobius_strip(8)),
    ];
    for (name, cage) in all {
        let schemes: &[Scheme] = if cage.is_triangle_mesh() {
            &[Scheme::CatmullClark, Scheme::Loop]
        } else {
            &[Scheme::CatmullClark]
        };
        let (creases, corners) = creased(&cage, &[2.5, f64::INFINITY, 0.5], &[1.5]);
        for &scheme in schemes {
            for naked_edges in [
                NakedEdges::Fixed,
                NakedEdges::Smooth,
                NakedEdges::CornerFixed,
            ] {
                let options = SubdivisionOptions {
                    naked_edges,
                    creases: creases.clone(),
                    corners: corners.clone(),
                    creasing: Creasing::Chaikin,
                    ..SubdivisionOptions::default()
                };
                let reference_cage = to_ref(&cage);
                let osd = osd_options(scheme, &options, &reference_cage);
                for levels in 1..=2 {
                    let what = format!("{scheme:?} {name} {naked_edges:?} level {levels}");
                    let subdivider = Subdivider::new(&cage, scheme, levels, &options).unwrap();
                    let ours = subdivider.mesh().unwrap();
                    let theirs = opensubdiv_refine(&reference_cage, &osd, levels).unwrap();
                    let map = vertex_map(&ours, &theirs, &what);
                    let flat: Vec<f64> =
                        ours.positions().iter().flat_map(|p| p.to_array()).collect();
                    assert_rows_close(&flat, &theirs.positions, 3, &map, tolerance(&ours), &what);
                    // The limit and face-varying values are defined everywhere.
                    let limit = subdivider.limit().unwrap();
                    assert!(limit.positions.iter().all(|p| p.is_finite()), "{what}");
                    assert!(limit.normals.iter().all(|n| n.is_finite()), "{what}");
                    let uvs: Vec<f64> = cage.positions().iter().flat_map(|p| [p.x, p.y]).collect();
                    let values = subdivider
                        .face_varying(&uvs, 2, cage.face_indices(), FaceVaryingLinear::Smooth)
                        .unwrap();
                    assert_eq!(values.len(), 2 * ours.index_count(), "{what}");
                }
            }
        }
    }
}

#[test]
fn unwelded_seams_and_folds_become_creases() {
    // Two unit quads side by side, their shared edge unwelded (vertices 1, 4
    // and 2, 5 coincide), folded by 90 degrees along it.
    let positions = vec![
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(0.0, 1.0, 0.0),
        // -0.0 is the same number as 0.0, so it welds.
        DVec3::new(1.0, -0.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(1.0, 1.0, 1.0),
        DVec3::new(1.0, 0.0, 1.0),
    ];
    let mesh = Mesh::from_polygons(positions, vec![vec![0, 1, 2, 3], vec![4, 7, 6, 5]]).unwrap();
    let weft::subdivide::CreasedMesh {
        mesh: welded,
        creases,
        vertex_map,
    } = weft::subdivide::creases_from_mesh(&mesh, 180.0).unwrap();
    assert_eq!(welded.vertex_count(), 6);
    assert_eq!(vertex_map, [0, 1, 2, 3, 1, 2, 4, 5]);
    assert_eq!(creases.len(), 1);
    let [a, b] = creases[0].0;
    let ends = [
        welded.positions()[a as usize],
        welded.positions()[b as usize],
    ];
    assert!(ends.contains(&DVec3::new(1.0, 0.0, 0.0)) && ends.contains(&DVec3::new(1.0, 1.0, 0.0)));
    assert!(creases[0].1.is_infinite() || creases[0].1 >= 10.0);
    // A cube: every edge folds by 90 degrees, sharper than 60, none by more than 120.
    let folds = weft::subdivide::creases_from_mesh(&shapes::cube(), 60.0)
        .unwrap()
        .creases;
    assert_eq!(folds.len(), 12);
    let none = weft::subdivide::creases_from_mesh(&shapes::cube(), 120.0)
        .unwrap()
        .creases;
    assert!(none.is_empty());
    assert!(weft::subdivide::creases_from_mesh(&shapes::cube(), f64::NAN).is_err());
    // The creases subdivide: the fold stays a straight line.
    let options = SubdivisionOptions {
        naked_edges: NakedEdges::Smooth,
        creases,
        ..SubdivisionOptions::default()
    };
    let out = subdivide_with(&welded, Scheme::CatmullClark, 2, &options).unwrap();
    let on_fold = out
        .positions()
        .iter()
        .filter(|p| (p.x - 1.0).abs() < 1e-12 && p.z.abs() < 1e-12)
        .count();
    assert_eq!(on_fold, 5);
}
