//! The limit surface as bicubic patches (`limit_patches`) and their STEP
//! file: exact where the surface is a B-spline (checked against the
//! uniform bicubic B-spline of a regular torus cage, written out by hand),
//! watertight, approximations that improve with isolation, and a STEP file
//! whose surfaces read back to the same control points.

use std::collections::HashMap;

use weft::io::step;
use weft::mesh::shapes;
use weft::subdivide::{
    limit_patches, BezierPatch, Creasing, NakedEdges, Scheme, Subdivider, SubdivisionOptions,
};
use weft::{DVec3, Error, Mesh, Topology};

fn smooth() -> SubdivisionOptions {
    SubdivisionOptions::new(NakedEdges::Smooth)
}

/// The uniform cubic B-spline basis at `t`.
fn b_spline(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [
        s * s * s / 6.0,
        (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0,
        (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0,
        t * t * t / 6.0,
    ]
}

/// Where (s, t) of child k of a quad lies in the quad's (u, v): child k sits
/// at corner k, its u towards corner k + 1, its v towards corner k - 1.
fn in_parent(k: usize, (s, t): (f64, f64)) -> (f64, f64) {
    let q = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
    let (here, next, previous) = (q[k], q[(k + 1) % 4], q[(k + 3) % 4]);
    (
        here.0 + s * (next.0 - here.0) / 2.0 + t * (previous.0 - here.0) / 2.0,
        here.1 + s * (next.1 - here.1) / 2.0 + t * (previous.1 - here.1) / 2.0,
    )
}

#[test]
fn patches_of_a_regular_torus_are_its_b_spline_surface() {
    let (nu, nv) = (6, 8);
    let cage = shapes::torus(nu, nv);
    let point = |i: usize, j: usize| cage.positions()[(i % nu) * nv + j % nv];
    for isolation in [1, 2] {
        let patches = limit_patches(&cage, &smooth(), isolation).unwrap();
        assert_eq!(patches.patches.len(), nu * nv * 4usize.pow(isolation));
        assert_eq!(patches.exact_count, patches.patches.len());
        let per_face = 4usize.pow(isolation);
        for (k, patch) in patches.patches.iter().enumerate() {
            let face = k / per_face;
            assert_eq!(patch.cage_face as usize, face);
            let (i, j) = (face / nv, face % nv);
            // The digits of k within its cage face: the path of children.
            let path: Vec<usize> = (0..isolation)
                .rev()
                .map(|level| (k % per_face) / 4usize.pow(level) % 4)
                .collect();
            for a in 0..=4 {
                for b in 0..=4 {
                    let local = (a as f64 / 4.0, b as f64 / 4.0);
                    let (u, v) = path.iter().rev().fold(local, |p, &c| in_parent(c, p));
                    let (bu, bv) = (b_spline(u), b_spline(v));
                    let mut exact = DVec3::ZERO;
                    for (x, wu) in bu.iter().enumerate() {
                        for (y, wv) in bv.iter().enumerate() {
                            exact += wu * wv * point(i + nu - 1 + x, j + nv - 1 + y);
                        }
                    }
                    let ours = patch.point(local.0, local.1);
                    assert!(
                        (ours - exact).length() < 1e-13,
                        "isolation {isolation} patch {k} at {local:?}: {ours} vs {exact}"
                    );
                }
            }
        }
    }
}

/// The patches of the faces of `mesh` refined `isolation` levels, checked
/// watertight: at every refined edge the two patches' boundary curves are
/// the same control points, bit for bit, run in opposite directions.
fn assert_watertight(cage: &Mesh, options: &SubdivisionOptions, isolation: u32) -> usize {
    let patches = limit_patches(cage, options, isolation).unwrap();
    let refined = Subdivider::new(cage, Scheme::CatmullClark, isolation, options)
        .unwrap()
        .mesh()
        .unwrap();
    assert_eq!(patches.patches.len(), refined.face_count());
    let mut curves: HashMap<[u32; 2], [DVec3; 4]> = HashMap::new();
    let mut shared = 0;
    for (f, face) in refined.faces().enumerate() {
        for k in 0..4 {
            let (a, b) = (face[k], face[(k + 1) % 4]);
            let curve = patches.patches[f].edge(k);
            if let Some(theirs) = curves.get(&[b, a]) {
                let mut reversed = *theirs;
                reversed.reverse();
                assert_eq!(curve, reversed, "face {f} edge {k}");
                shared += 1;
            }
            curves.insert([a, b], curve);
        }
    }
    shared
}

#[test]
fn patches_are_watertight_across_every_edge() {
    // A closed torus: every edge shared.
    let torus = shapes::torus(5, 7);
    assert_eq!(assert_watertight(&torus, &smooth(), 1), 2 * 5 * 7 * 4);
    // An open grid with a hard crease and a hole, and mixed polygons.
    let grid = shapes::quad_grid(4, 4);
    let creased = SubdivisionOptions {
        creases: vec![([5, 6], f64::INFINITY), ([6, 7], 2.0)],
        holes: vec![15],
        ..smooth()
    };
    assert!(assert_watertight(&grid, &creased, 2) > 0);
    assert!(assert_watertight(&shapes::mixed_polygons(), &smooth(), 2) > 0);
}

#[test]
fn the_approximation_near_extraordinary_vertices_improves_with_isolation() {
    let cube = shapes::cube();
    let mut previous = f64::INFINITY;
    for isolation in 1..=4 {
        let patches = limit_patches(&cube, &smooth(), isolation).unwrap();
        // Three faces touch each of the 8 corners of valence 3; the rest are exact.
        assert_eq!(
            patches.patches.len() - patches.exact_count,
            24,
            "isolation {isolation}"
        );
        assert!(
            patches.max_error < 0.6 * previous,
            "isolation {isolation}: {}",
            patches.max_error
        );
        assert!(patches.max_error > 1e-6);
        previous = patches.max_error;
    }
}

/// `mesh` with every vertex moved by up to a tenth, by a fixed pattern, so
/// that no two faces are alike.
fn bumped(mesh: &Mesh) -> Mesh {
    let moved = mesh
        .positions()
        .iter()
        .enumerate()
        .map(|(i, &p)| {
            let t = i as f64;
            p + 0.1 * DVec3::new((1.3 * t).sin(), (2.1 * t).cos(), (0.7 * t).sin())
        })
        .collect();
    mesh.with_positions(moved).unwrap()
}

/// Cages whose patches are checked against the limit three levels down:
/// smooth, creased (infinite, semi-sharp and decaying), with corners and a
/// hole, with two faces at a vertex, and at every vertex valence.
fn checked_cages() -> Vec<(&'static str, Mesh, SubdivisionOptions, u32)> {
    let creased = SubdivisionOptions {
        creases: vec![([5, 6], f64::INFINITY), ([6, 7], 2.0), ([13, 14], 0.5)],
        corners: vec![(0, f64::INFINITY), (9, 1.5)],
        holes: vec![15],
        creasing: Creasing::Chaikin,
        ..SubdivisionOptions::new(NakedEdges::Fixed)
    };
    let torus_crease = SubdivisionOptions {
        creases: vec![([0, 1], 1.5), ([1, 2], 1.5)],
        ..smooth()
    };
    vec![
        ("mixed polygons", shapes::mixed_polygons(), smooth(), 2),
        ("bumped cube", bumped(&shapes::cube()), smooth(), 2),
        ("creased grid", bumped(&shapes::quad_grid(4, 4)), creased, 1),
        (
            "creased grid, level 2",
            bumped(&shapes::quad_grid(3, 3)),
            torus_crease.clone(),
            2,
        ),
        (
            "torus with a semi-sharp crease",
            bumped(&shapes::torus(5, 6)),
            torus_crease,
            1,
        ),
    ]
}

/// The limit points three levels below `isolation`, and the distance from
/// a point to the nearest of them.
fn fine_limit(cage: &Mesh, options: &SubdivisionOptions, isolation: u32) -> Vec<DVec3> {
    let fine = Subdivider::new(cage, Scheme::CatmullClark, isolation + 3, options).unwrap();
    fine.limit().unwrap().positions
}

fn nearest(limit: &[DVec3], p: DVec3) -> f64 {
    limit
        .iter()
        .map(|q| (*q - p).length())
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn patch_corners_are_limit_points_and_errors_are_measured_against_the_limit() {
    for (name, cage, options, isolation) in checked_cages() {
        let patches = limit_patches(&cage, &options, isolation).unwrap();
        let limit = fine_limit(&cage, &options, isolation);
        let size = patches.size;
        for (k, patch) in patches.patches.iter().enumerate() {
            for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
                assert!(
                    nearest(&limit, patch.point(u, v)) < 1e-13 * size,
                    "{name}: patch {k} corner ({u}, {v})"
                );
            }
            // Its error is within the distance of its ⅛ grid from the limit:
            // a patch taken as exact (error 0) lies on the limit.
            let mut worst: f64 = 0.0;
            for a in 0..=8 {
                for b in 0..=8 {
                    let p = patch.point(a as f64 / 8.0, b as f64 / 8.0);
                    worst = worst.max(nearest(&limit, p));
                }
            }
            assert!(
                worst <= patch.error + 1e-13 * size,
                "{name}: patch {k}: {worst} vs {}",
                patch.error
            );
        }
    }
}

#[test]
fn edges_away_from_extraordinary_vertices_are_exact_on_every_patch() {
    // On a closed smooth cage, every vertex of valence 4 is regular: an edge
    // between two of them is on the limit even where the face beside it
    // touches a vertex of another valence and is fitted.
    for (cage, isolation) in [(bumped(&shapes::cube()), 2), (shapes::mixed_polygons(), 2)] {
        let patches = limit_patches(&cage, &smooth(), isolation).unwrap();
        let limit = fine_limit(&cage, &smooth(), isolation);
        let refined = Subdivider::new(&cage, Scheme::CatmullClark, isolation, &smooth())
            .unwrap()
            .mesh()
            .unwrap();
        let valences = Topology::new(&refined).vertex_valences();
        let regular = |v: u32| valences[v as usize] == 4;
        let (mut exact_edges, mut fitted_faces_with_them) = (0, 0);
        for (f, face) in refined.faces().enumerate() {
            let patch = &patches.patches[f];
            let mut any = false;
            for k in 0..4 {
                if !(regular(face[k]) && regular(face[(k + 1) % 4])) {
                    continue;
                }
                let [a, b, c, d] = patch.edge(k);
                for t in 0..=8 {
                    let w = bernstein_weights(t as f64 / 8.0);
                    let p = w[0] * a + w[1] * b + w[2] * c + w[3] * d;
                    assert!(
                        nearest(&limit, p) < 1e-13 * patches.size,
                        "face {f} edge {k} at {t}/8"
                    );
                }
                exact_edges += 1;
                any = true;
            }
            if any && patch.error > 1e-9 {
                fitted_faces_with_them += 1;
            }
        }
        assert!(exact_edges > 0 && fitted_faces_with_them > 0);
    }
}

fn bernstein_weights(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t]
}

#[test]
fn cages_near_the_ends_of_the_double_range_give_the_same_patches_scaled() {
    let cube = shapes::cube();
    let plain = limit_patches(&cube, &smooth(), 2).unwrap();
    for scale in [1e300, 1e-300, 2f64.powi(1000)] {
        let scaled = cube
            .with_positions(cube.positions().iter().map(|&p| p * scale).collect())
            .unwrap();
        let patches = limit_patches(&scaled, &smooth(), 2).unwrap();
        assert_eq!(patches.exact_count, plain.exact_count, "{scale:e}");
        assert!(
            (patches.max_error / scale - plain.max_error).abs() < 1e-10 * plain.max_error,
            "{scale:e}"
        );
        for (a, b) in patches.patches.iter().zip(&plain.patches) {
            for (ra, rb) in a.control.iter().zip(&b.control) {
                for (pa, pb) in ra.iter().zip(rb) {
                    assert!(
                        pa.is_finite() && (*pa / scale - *pb).length() < 1e-13,
                        "{scale:e}: {pa} vs {pb}"
                    );
                }
            }
        }
    }
}

#[test]
fn holes_leave_no_patch_and_bad_isolation_is_refused() {
    let grid = shapes::quad_grid(3, 3);
    let holed = SubdivisionOptions {
        holes: vec![4],
        ..smooth()
    };
    let patches = limit_patches(&grid, &holed, 1).unwrap();
    assert_eq!(patches.patches.len(), 8 * 4);
    assert!(patches.patches.iter().all(|p| p.cage_face != 4));
    for isolation in [0, 9] {
        let error = limit_patches(&grid, &smooth(), isolation).unwrap_err();
        assert!(
            matches!(&error, Error::InvalidArgument(m) if m.contains("isolation")),
            "{error}"
        );
    }
}

/// The control points of every `B_SPLINE_SURFACE_WITH_KNOTS` of a STEP
/// file, read by a small reader of the entities the writer uses.
fn surfaces_of(text: &str) -> Vec<[[DVec3; 4]; 4]> {
    let mut points: HashMap<usize, DVec3> = HashMap::new();
    let mut surfaces = Vec::new();
    for line in text.lines().filter(|l| l.starts_with('#')) {
        let (id, entity) = line.split_once('=').unwrap();
        let id: usize = id[1..].parse().unwrap();
        if let Some(rest) = entity.strip_prefix("CARTESIAN_POINT('',(") {
            let xyz: Vec<f64> = rest
                .trim_end_matches("));")
                .split(',')
                .map(|x| x.parse().unwrap())
                .collect();
            points.insert(id, DVec3::new(xyz[0], xyz[1], xyz[2]));
        } else if let Some(rest) = entity.strip_prefix("B_SPLINE_SURFACE_WITH_KNOTS('',3,3,(") {
            let grid = &rest[..rest.find(")),").unwrap() + 1];
            let rows: Vec<Vec<usize>> = grid
                .split("),(")
                .map(|row| {
                    row.trim_matches(|c| c == '(' || c == ')')
                        .split(',')
                        .map(|r| r.trim_start_matches('#').parse().unwrap())
                        .collect()
                })
                .collect();
            assert!(rest.contains("(4,4),(4,4),(0.,1.),(0.,1.)"), "{line}");
            surfaces.push(std::array::from_fn(|i| {
                std::array::from_fn(|j| points[&rows[i][j]])
            }));
        }
    }
    surfaces
}

#[test]
fn the_step_file_holds_the_patches_bit_for_bit() {
    let cage = shapes::torus(4, 6);
    let patches = limit_patches(&cage, &smooth(), 1).unwrap();
    let controls: Vec<step::Bicubic> = patches.patches.iter().map(|p| p.control).collect();
    let mut out = Vec::new();
    step::write(&mut out, "torus.step", &controls).unwrap();
    let text = String::from_utf8(out).unwrap();
    let read = surfaces_of(&text);
    assert_eq!(read, controls);
    // A closed shell: every edge written once and used by two faces.
    let faces = controls.len();
    assert_eq!(text.matches("ADVANCED_FACE(").count(), faces);
    assert_eq!(text.matches("EDGE_CURVE(").count(), 2 * faces);
    assert_eq!(text.matches("ORIENTED_EDGE(").count(), 4 * faces);
    assert_eq!(text.matches("VERTEX_POINT(").count(), faces);
    // And the surface read back is the patch.
    let patch = BezierPatch {
        control: read[5],
        ..patches.patches[5]
    };
    assert_eq!(patch.point(0.3, 0.7), patches.patches[5].point(0.3, 0.7));
    let topology = Topology::new(&cage);
    assert!(topology.info(&cage).is_closed);
}
