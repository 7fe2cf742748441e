//! The limit surface anywhere ([`LimitSurface`]) against the limit at the
//! vertices (`Subdivider::limit`, what `weft_subdivide_limit` returns) and
//! against OpenSubdiv's Bfr (`Bfr::RefinerSurfaceFactory`,
//! `Surface<double>::Evaluate`).
//!
//! - At every corner of every face, in both schemes, every naked-edge mode,
//!   with and without creases: the position equals the limit position and
//!   the normalised `du × dv` equals the limit normal, to 1e-12 of the
//!   cage's size.
//! - On regular faces (closed, open, across infinitely sharp creases)
//!   positions and derivatives equal Bfr's to 1e-12 relative.
//! - Around extraordinary vertices Bfr approximates; raising its
//!   approximation level brings it to Weft's values, below 1e-6.

mod support;

use support::{bumped, osd_options, to_ref};
use weft::mesh::shapes;
use weft::subdivide::{Creasing, LimitSurface, NakedEdges, Scheme, Subdivider, SubdivisionOptions};
use weft::{DVec3, Mesh};
use weft_reference::OsdRefiner;

const MODES: [NakedEdges; 4] = [
    NakedEdges::Fixed,
    NakedEdges::Smooth,
    NakedEdges::CornerFixed,
    NakedEdges::None,
];

fn size(mesh: &Mesh) -> f64 {
    let (mut lo, mut hi) = (DVec3::splat(f64::MAX), DVec3::splat(f64::MIN));
    for &p in mesh.positions() {
        lo = lo.min(p);
        hi = hi.max(p);
    }
    (hi - lo).length()
}

/// The `(u, v)` of corner `k` of a face of `n` corners.
fn corner_uv(scheme: Scheme, n: usize, k: usize) -> [f64; 2] {
    match (scheme, n) {
        (Scheme::Loop, _) => [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]][k],
        (_, 4) => [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]][k],
        (_, n) => {
            let w = if n < 5 { 2 } else { 3 };
            [(k % w) as f64, (k / w) as f64]
        }
    }
}

/// Evaluates `surface` at every sample; positions, du, dv.
fn evaluate(surface: &LimitSurface, faces: &[u32], uvs: &[f64]) -> [Vec<DVec3>; 3] {
    let n = faces.len();
    let mut out = [
        vec![DVec3::ZERO; n],
        vec![DVec3::ZERO; n],
        vec![DVec3::ZERO; n],
    ];
    let [p, du, dv] = &mut out;
    surface.evaluate(faces, uvs, p, Some(du), Some(dv)).unwrap();
    out
}

/// Largest position and normal deviations from the limit at the corners.
fn corner_deviation(cage: &Mesh, scheme: Scheme, options: &SubdivisionOptions) -> (f64, f64) {
    let surface = LimitSurface::new(cage, scheme, options).unwrap();
    // Deep enough that semi-sharp creases have decayed; where the normal
    // still changes from level to level (a corner, where the surface has
    // no tangent plane) it is not compared.
    let limit_at = |levels| {
        Subdivider::new(cage, scheme, levels, options)
            .unwrap()
            .limit()
            .unwrap()
    };
    let (limit, before) = (limit_at(4), limit_at(3));
    let holes = weft::subdivide::parent_faces_with(cage, scheme, 0, options).unwrap();
    let (mut faces, mut uvs, mut vertices) = (Vec::new(), Vec::new(), Vec::new());
    for &f in &holes {
        let corners = cage.face(f as usize);
        for (k, &v) in corners.iter().enumerate() {
            faces.push(f);
            uvs.extend(corner_uv(scheme, corners.len(), k));
            vertices.push(v as usize);
        }
    }
    let [p, du, dv] = evaluate(&surface, &faces, &uvs);
    let normals: Vec<DVec3> = du
        .iter()
        .zip(&dv)
        .map(|(a, b)| a.cross(*b).normalize_or_zero())
        .collect();
    // Where the faces at a vertex disagree on the normal, the surface has a
    // kink there (a corner, a bow-tie, a fin) and no tangent plane: the
    // vertex limit's normal is one face's, and is not compared.
    let one_plane = |v: usize| {
        let around: Vec<DVec3> = (0..vertices.len())
            .filter(|&i| vertices[i] == v)
            .map(|i| normals[i])
            .collect();
        around.iter().all(|n| (*n - around[0]).length() < 1e-9)
    };
    let (mut position, mut normal) = (0.0f64, 0.0f64);
    for (i, &v) in vertices.iter().enumerate() {
        // Catmull-Clark's vertex limit keeps a point of two faces where the
        // level has it: no reference there.
        if (limit.positions[v] - before.positions[v]).length() > 1e-9 * size(cage) {
            continue;
        }
        position = position.max((p[i] - limit.positions[v]).length());
        // At a corner the vertex limit's tangents are its first edges at
        // the last level, which turn from level to level towards the
        // surface's: no reference there either.
        let settled = (limit.normals[v] - before.normals[v]).length() < 1e-12;
        if settled && one_plane(v) {
            normal = normal.max((normals[i] - limit.normals[v]).length());
        }
    }
    (position / size(cage), normal)
}

fn open_quads() -> Mesh {
    bumped(shapes::quad_grid(4, 3))
}

fn open_triangles() -> Mesh {
    bumped(shapes::triangle_grid(4, 3))
}

/// A semi-sharp crease across the middle of the 4 × 3 grid, a sharper one
/// along it, and a semi-sharp corner.
fn creased(cage: &Mesh, mode: NakedEdges, creasing: Creasing) -> SubdivisionOptions {
    let mut options = SubdivisionOptions::new(mode);
    options.creasing = creasing;
    // Vertex (i, j) of the grid is j * 5 + i.
    options.creases = vec![([6, 7], 1.5), ([7, 8], 2.3), ([8, 9], 10.0), ([2, 7], 0.6)];
    options.corners = vec![(12, 1.7)];
    let _ = cage;
    options
}

#[test]
fn corners_are_the_limit_at_the_vertices() {
    let closed_cc = [
        ("cube", shapes::cube()),
        ("tetrahedron", shapes::tetrahedron()),
        ("torus", shapes::torus(6, 4)),
        ("mixed polygons", shapes::mixed_polygons()),
    ];
    let open_cc = [
        ("grid", open_quads()),
        ("grid with hole", bumped(shapes::quad_grid_with_hole())),
        ("l-shaped hexagon", shapes::l_shaped_hexagon(0.0)),
        ("fin", shapes::fin()),
        ("bow tie", shapes::bow_tie()),
    ];
    let closed_loop = [
        ("icosahedron", shapes::icosahedron()),
        ("tetrahedron", shapes::tetrahedron()),
        ("triangle torus", shapes::triangle_torus(6, 4)),
    ];
    let open_loop = [
        ("triangle grid", open_triangles()),
        (
            "triangle grid with hole",
            bumped(shapes::triangle_grid_with_hole()),
        ),
        ("fin", shapes::fin()),
        ("bow tie", shapes::bow_tie()),
    ];
    let mut worst = (0.0f64, 0.0f64);
    for (scheme, shapes) in [
        (
            Scheme::CatmullClark,
            closed_cc.iter().chain(&open_cc).collect::<Vec<_>>(),
        ),
        (Scheme::Loop, closed_loop.iter().chain(&open_loop).collect()),
    ] {
        for (name, cage) in shapes {
            for mode in MODES {
                let options = SubdivisionOptions::new(mode);
                let (p, n) = corner_deviation(cage, scheme, &options);
                assert!(
                    p < 1e-12 && n < 1e-12,
                    "{scheme:?} {name} {mode:?}: {p:e} {n:e}"
                );
                worst = (worst.0.max(p), worst.1.max(n));
            }
        }
        let grid = match scheme {
            Scheme::CatmullClark => open_quads(),
            Scheme::Loop => open_triangles(),
        };
        for mode in MODES {
            for creasing in [Creasing::Uniform, Creasing::Chaikin] {
                let options = creased(&grid, mode, creasing);
                let (p, n) = corner_deviation(&grid, scheme, &options);
                assert!(
                    p < 1e-12 && n < 1e-12,
                    "{scheme:?} creased {mode:?} {creasing:?}: {p:e} {n:e}"
                );
                worst = (worst.0.max(p), worst.1.max(n));
            }
        }
    }
    println!(
        "largest deviation at corners: position {:e}, normal {:e}",
        worst.0, worst.1
    );
}

/// A deterministic spread of `(u, v)` in a face's domain, corners and
/// edges included.
fn samples(scheme: Scheme, n: usize) -> Vec<[f64; 2]> {
    let mut out = Vec::new();
    let steps = [0.0, 0.125, 0.3, 0.5, 0.71, 0.9, 1.0];
    for &a in &steps {
        for &b in &steps {
            match (scheme, n) {
                (Scheme::Loop, _) if a + b <= 1.0 => out.push([a, b]),
                (Scheme::Loop, _) => {}
                (_, 4) => out.push([a, b]),
                (_, n) => {
                    let w = if n < 5 { 2 } else { 3 };
                    for i in 0..n {
                        out.push([(i % w) as f64 + 0.5 * a, (i / w) as f64 + 0.5 * b]);
                    }
                }
            }
        }
    }
    out
}

/// Every sample of every face in `faces`, as evaluation arguments.
fn spread(cage: &Mesh, scheme: Scheme, faces: &[u32]) -> (Vec<u32>, Vec<f64>) {
    let (mut fs, mut uvs) = (Vec::new(), Vec::new());
    for &f in faces {
        for uv in samples(scheme, cage.face(f as usize).len()) {
            fs.push(f);
            uvs.extend(uv);
        }
    }
    (fs, uvs)
}

/// Largest deviation of Weft's positions, du and dv from Bfr's at the
/// approximation level, relative to the cage's size.
fn bfr_deviation(
    cage: &Mesh,
    scheme: Scheme,
    options: &SubdivisionOptions,
    faces: &[u32],
    uvs: &[f64],
    level: i32,
) -> [f64; 3] {
    let surface = LimitSurface::new(cage, scheme, options).unwrap();
    let ours = evaluate(&surface, faces, uvs);
    let reference = to_ref(cage);
    let osd = OsdRefiner::new(&reference, &osd_options(scheme, options, &reference), 0).unwrap();
    let theirs = osd
        .bfr_evaluate(&reference.positions, (level, level), faces, uvs)
        .unwrap();
    let scale = size(cage);
    let mut worst = [0.0f64; 3];
    for (which, (ours, theirs)) in ours.iter().zip(&theirs).enumerate() {
        for (i, p) in ours.iter().enumerate() {
            let q = DVec3::from_slice(&theirs[3 * i..3 * i + 3]);
            worst[which] = worst[which].max((*p - q).length() / scale);
        }
    }
    worst
}

#[test]
fn regular_faces_equal_bfr() {
    let torus = shapes::torus(8, 6);
    let all = |m: &Mesh| (0..m.face_count() as u32).collect::<Vec<_>>();
    let mut cases: Vec<(&str, Mesh, Scheme, SubdivisionOptions, Vec<u32>)> = Vec::new();
    cases.push((
        "torus",
        torus.clone(),
        Scheme::CatmullClark,
        SubdivisionOptions::new(NakedEdges::Smooth),
        all(&torus),
    ));
    // Infinitely sharp creases around the torus: boundary patches each side.
    let mut sharp = SubdivisionOptions::new(NakedEdges::Smooth);
    sharp.creases = (0..8u32)
        .map(|i| ([i * 6, ((i + 1) % 8) * 6], 10.0))
        .collect();
    cases.push((
        "creased torus",
        torus.clone(),
        Scheme::CatmullClark,
        sharp.clone(),
        all(&torus),
    ));
    let triangles = shapes::triangle_torus(8, 6);
    cases.push((
        "triangle torus",
        triangles.clone(),
        Scheme::Loop,
        SubdivisionOptions::new(NakedEdges::Smooth),
        all(&triangles),
    ));
    cases.push((
        "creased triangle torus",
        triangles.clone(),
        Scheme::Loop,
        sharp,
        all(&triangles),
    ));
    // Open grids: the faces whose corners are all regular (not the grid's
    // corner faces, whose corners have one face).
    let grid = bumped(shapes::quad_grid(5, 4));
    let inner: Vec<u32> = (0..20u32)
        .filter(|&f| ![0, 4, 15, 19].contains(&f))
        .collect();
    for mode in [NakedEdges::Smooth, NakedEdges::CornerFixed] {
        cases.push((
            "grid",
            grid.clone(),
            Scheme::CatmullClark,
            SubdivisionOptions::new(mode),
            inner.clone(),
        ));
    }
    // Corner Fixed makes the grid's corners regular corner patches.
    cases.push((
        "grid corners",
        grid.clone(),
        Scheme::CatmullClark,
        SubdivisionOptions::new(NakedEdges::CornerFixed),
        all(&grid),
    ));
    let tri_grid = bumped(shapes::triangle_grid(5, 4));
    let regular: Vec<u32> = (0..tri_grid.face_count() as u32)
        .filter(|&f| {
            tri_grid.face(f as usize).iter().all(|&v| {
                let (i, j) = (v % 6, v / 6);
                // Boundary vertices of valence 4 and interior of valence 6.
                !matches!((i, j), (0, 0) | (5, 4) | (0, 4) | (5, 0))
            })
        })
        .collect();
    cases.push((
        "triangle grid",
        tri_grid.clone(),
        Scheme::Loop,
        SubdivisionOptions::new(NakedEdges::Smooth),
        regular,
    ));
    let mut worst = [0.0f64; 3];
    for (name, cage, scheme, options, faces) in &cases {
        let (fs, uvs) = spread(cage, *scheme, faces);
        let d = bfr_deviation(cage, *scheme, options, &fs, &uvs, 0);
        println!("{name}: position {:e}, du {:e}, dv {:e}", d[0], d[1], d[2]);
        assert!(d.iter().all(|&d| d < 1e-12), "{name}: {d:?}");
        for k in 0..3 {
            worst[k] = worst[k].max(d[k]);
        }
    }
    println!("largest deviation from Bfr on regular faces: {worst:?}");
}

#[test]
fn bfr_converges_to_weft_around_extraordinary_vertices() {
    let cases = [
        (
            "cube",
            shapes::cube(),
            Scheme::CatmullClark,
            SubdivisionOptions::new(NakedEdges::Smooth),
        ),
        (
            "tetrahedron",
            shapes::tetrahedron(),
            Scheme::CatmullClark,
            SubdivisionOptions::new(NakedEdges::Smooth),
        ),
        (
            "icosahedron",
            shapes::icosahedron(),
            Scheme::Loop,
            SubdivisionOptions::new(NakedEdges::Smooth),
        ),
        (
            "creased grid",
            open_quads(),
            Scheme::CatmullClark,
            creased(&open_quads(), NakedEdges::Smooth, Creasing::Chaikin),
        ),
    ];
    for (name, cage, scheme, options) in cases {
        let faces: Vec<u32> = (0..cage.face_count() as u32).collect();
        let (mut fs, mut uvs) = (Vec::new(), Vec::new());
        // Samples near corners and inside, not at the corners themselves
        // (where the derivatives are the limit tangents, not Bfr's).
        let steps = [0.011, 0.07, 0.3, 0.5, 0.8, 0.97];
        for &f in &faces {
            let n = cage.face(f as usize).len();
            for &a in &steps {
                for &b in &steps {
                    match (scheme, n) {
                        (Scheme::Loop, _) if a + b > 1.0 => {}
                        (Scheme::Loop, _) | (_, 4) => {
                            fs.push(f);
                            uvs.extend([a, b]);
                        }
                        (_, n) => {
                            let w = if n < 5 { 2 } else { 3 };
                            for i in 0..n {
                                fs.push(f);
                                uvs.extend([(i % w) as f64 + 0.5 * a, (i / w) as f64 + 0.5 * b]);
                            }
                        }
                    }
                }
            }
        }
        let mut errors = Vec::new();
        for level in [0, 2, 4, 6, 8, 10] {
            let d = bfr_deviation(&cage, scheme, &options, &fs, &uvs, level);
            errors.push(d[0]);
        }
        println!("{name}: position error of Bfr at approximation levels 0, 2, .., 10: {errors:?}");
        assert!(*errors.last().unwrap() < 1e-6, "{name}: {errors:?}");
        for pair in errors.windows(2) {
            assert!(pair[1] <= pair[0] * 1.01 + 1e-15, "{name}: {errors:?}");
        }
    }
}

#[test]
fn samples_outside_a_face_or_on_a_hole_are_refused_and_nothing_is_written() {
    let mut p = [DVec3::splat(-7.0); 2];
    let expect = |surface: &LimitSurface, faces: &[u32], uvs: &[f64], needle: &str| {
        let mut p = [DVec3::splat(-7.0); 2];
        let error = surface
            .evaluate(faces, uvs, &mut p[..faces.len()], None, None)
            .unwrap_err();
        assert!(error.to_string().contains(needle), "{error}");
        assert!(p.iter().all(|&q| q == DVec3::splat(-7.0)));
    };
    let icosahedron = LimitSurface::new(
        &shapes::icosahedron(),
        Scheme::Loop,
        &SubdivisionOptions::new(NakedEdges::Smooth),
    )
    .unwrap();
    expect(
        &icosahedron,
        &[0, 3],
        &[0.2, 0.2, 0.7, 0.4],
        "sample 1: (u, v) = (0.7, 0.4) is outside the domain of face 3 (a triangle",
    );
    expect(
        &icosahedron,
        &[0, 30],
        &[0.2, 0.2, 0.1, 0.1],
        "sample 1: face 30 is out of range (the cage has 20 faces)",
    );
    expect(
        &icosahedron,
        &[1, 2],
        &[-0.0, f64::NAN, 0.1, 0.1],
        "sample 0 on face 1: (u, v) = (-0, NaN) is not finite",
    );
    // A pentagon's tiles leave gaps: u = 0.75 lies in none.
    let mixed = shapes::mixed_polygons();
    let pentagon = (0..mixed.face_count())
        .find(|&f| mixed.face(f).len() == 5)
        .unwrap() as u32;
    let surface = LimitSurface::new(
        &mixed,
        Scheme::CatmullClark,
        &SubdivisionOptions::new(NakedEdges::Smooth),
    )
    .unwrap();
    expect(&surface, &[pentagon], &[0.75, 0.25], "outside the domain");
    expect(&surface, &[pentagon], &[0.25, 1.75], "outside the domain");
    surface
        .evaluate(&[pentagon], &[2.5, 0.5], &mut p[..1], None, None)
        .unwrap();
    // Holes are not part of the surface.
    let mut options = SubdivisionOptions::new(NakedEdges::Smooth);
    options.holes = vec![5];
    let grid = open_quads();
    let holed = LimitSurface::new(&grid, Scheme::CatmullClark, &options).unwrap();
    expect(
        &holed,
        &[4, 5],
        &[0.5, 0.5, 0.5, 0.5],
        "sample 1: face 5 is a hole",
    );
    holed
        .evaluate(&[4, 6], &[0.5, 0.5, 0.5, 0.5], &mut p, None, None)
        .unwrap();
}

#[test]
fn extraordinary_corners_approached_from_inside_converge() {
    // Along the diagonal towards a cube corner (valence 3), positions tend
    // to the corner's limit and the normals to its normal.
    let cube = shapes::cube();
    let options = SubdivisionOptions::new(NakedEdges::Smooth);
    let surface = LimitSurface::new(&cube, Scheme::CatmullClark, &options).unwrap();
    let n = 40;
    let faces = vec![0u32; n + 1];
    let mut uvs = vec![0.0; 2 * (n + 1)];
    for k in 0..n {
        let t = 0.5f64.powi(k as i32 + 1) * 0.7;
        uvs[2 * k] = t;
        uvs[2 * k + 1] = 0.6 * t;
    }
    let [p, du, dv] = evaluate(&surface, &faces, &uvs);
    let corner = p[n];
    let normal = du[n].cross(dv[n]).normalize();
    let turn = |k: usize| (du[k].cross(dv[k]).normalize() - normal).length();
    for k in 1..n {
        assert!((p[k] - corner).length() <= (p[k - 1] - corner).length() + 1e-15);
        assert!(
            turn(k) <= turn(k - 1) + 1e-12,
            "{k}: {} after {}",
            turn(k),
            turn(k - 1)
        );
    }
    assert!((p[n - 1] - corner).length() < 1e-9);
    assert!(turn(n - 1) < 1e-6, "{}", turn(n - 1));
}

/// Queries around a cage: points of its surface pushed off along the normal
/// both ways, and points scattered over its box and beyond.
fn queries(surface: &LimitSurface, cage: &Mesh, scheme: Scheme) -> Vec<DVec3> {
    let faces: Vec<u32> = (0..cage.face_count() as u32).collect();
    let (fs, uvs) = spread(cage, scheme, &faces);
    let [p, du, dv] = evaluate(surface, &fs, &uvs);
    let scale = size(cage);
    let mut out = Vec::new();
    for i in (0..p.len()).step_by(17) {
        let n = du[i].cross(dv[i]).normalize_or_zero();
        let offset = [0.0, 0.05, -0.03, 0.2, -0.15][i % 5] * scale;
        out.push(p[i] + n * offset);
    }
    let (mut lo, mut hi) = (DVec3::splat(f64::MAX), DVec3::splat(f64::MIN));
    for &q in cage.positions() {
        (lo, hi) = (lo.min(q), hi.max(q));
    }
    let mut state = 12345u64;
    let mut next = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..30 {
        let t = DVec3::new(next(), next(), next()) * 1.6 - 0.3;
        out.push(lo + (hi - lo) * t);
    }
    out
}

#[test]
fn closest_points_lie_on_the_surface_and_nothing_sampled_is_nearer() {
    let cases = [
        (
            "cube",
            shapes::cube(),
            Scheme::CatmullClark,
            SubdivisionOptions::new(NakedEdges::Smooth),
        ),
        (
            "mixed polygons",
            shapes::mixed_polygons(),
            Scheme::CatmullClark,
            SubdivisionOptions::new(NakedEdges::Smooth),
        ),
        (
            "open grid",
            open_quads(),
            Scheme::CatmullClark,
            SubdivisionOptions::new(NakedEdges::CornerFixed),
        ),
        (
            "creased grid",
            open_quads(),
            Scheme::CatmullClark,
            creased(&open_quads(), NakedEdges::Fixed, Creasing::Chaikin),
        ),
        (
            "icosahedron",
            shapes::icosahedron(),
            Scheme::Loop,
            SubdivisionOptions::new(NakedEdges::Smooth),
        ),
        (
            "open triangles",
            open_triangles(),
            Scheme::Loop,
            SubdivisionOptions::new(NakedEdges::Smooth),
        ),
    ];
    for (name, cage, scheme, options) in cases {
        let surface = LimitSurface::new(&cage, scheme, &options).unwrap();
        let points = queries(&surface, &cage, scheme);
        let n = points.len();
        let (mut faces, mut uvs, mut found) = (vec![0; n], vec![0.0; 2 * n], vec![DVec3::ZERO; n]);
        surface
            .closest_points(&points, &mut faces, &mut uvs, &mut found)
            .unwrap();
        // On the surface: the evaluation at the returned face and (u, v).
        let [again, _, _] = evaluate(&surface, &faces, &uvs);
        assert_eq!(again, found, "{name}");
        // Nothing of a dense sampling of the surface is nearer.
        let all: Vec<u32> = (0..cage.face_count() as u32).collect();
        let (mut fs, mut dense) = (Vec::new(), Vec::new());
        let steps = 16;
        for &f in &all {
            let k = cage.face(f as usize).len();
            for i in 0..=steps {
                for j in 0..=steps {
                    let (a, b) = (i as f64 / steps as f64, j as f64 / steps as f64);
                    match (scheme, k) {
                        (Scheme::Loop, _) if a + b > 1.0 => {}
                        (Scheme::Loop, _) | (_, 4) => {
                            fs.push(f);
                            dense.extend([a, b]);
                        }
                        (_, k) => {
                            let w = if k < 5 { 2 } else { 3 };
                            for t in 0..k {
                                fs.push(f);
                                dense.extend([(t % w) as f64 + 0.5 * a, (t / w) as f64 + 0.5 * b]);
                            }
                        }
                    }
                }
            }
        }
        let [samples, _, _] = evaluate(&surface, &fs, &dense);
        let tolerance = 1e-9 * size(&cage);
        let mut worst: f64 = 0.0;
        for (k, (q, p)) in points.iter().zip(&found).enumerate() {
            let d = (*q - *p).length();
            let (i, nearest) = samples
                .iter()
                .map(|s| (*s - *q).length())
                .enumerate()
                .fold((0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
            assert!(
                d <= nearest + tolerance,
                "{name}: {q:?} found at {d} on face {} at {:?}, a sample at {nearest} on face {} at {:?}",
                faces[k],
                &uvs[2 * k..2 * k + 2],
                fs[i],
                &dense[2 * i..2 * i + 2]
            );
            worst = worst.max(d - nearest);
        }
        println!("{name}: {n} queries, found distance minus nearest sample at most {worst:e}");
    }
}

#[test]
fn far_query_points_project_onto_the_surface() {
    // Points far outside the cage, up to where squared distances would
    // overflow: on the surface all the same.
    let cage = shapes::cube();
    let surface = LimitSurface::new(
        &cage,
        Scheme::CatmullClark,
        &SubdivisionOptions::new(NakedEdges::Smooth),
    )
    .unwrap();
    let far = [
        DVec3::new(1e6, 0.5, 0.5),
        DVec3::new(-1e300, 2.0, -3.0),
        DVec3::new(1e300, 1e300, 1e300),
    ];
    let (mut faces, mut uvs, mut positions) = (vec![0u32; 3], vec![0.0; 6], vec![DVec3::ZERO; 3]);
    let started = std::time::Instant::now();
    surface
        .closest_points(&far, &mut faces, &mut uvs, &mut positions)
        .unwrap();
    assert!(
        started.elapsed().as_secs_f64() < 5.0,
        "took {:?}",
        started.elapsed()
    );
    for (k, p) in positions.iter().enumerate() {
        assert!(p.is_finite(), "point {k}: {p}");
        let [at, _, _] = evaluate(&surface, &faces[k..k + 1], &uvs[2 * k..2 * k + 2]);
        assert!((at[0] - *p).length() < 1e-12, "point {k} is its evaluation");
    }
    // The point far along +x lands on the cube's +x side.
    assert!(positions[0].x > 0.7, "{}", positions[0]);
}

#[test]
fn closest_points_of_huge_and_tiny_cages_are_the_unit_cage_scaled() {
    // Squared distances of a cage near 1e154 overflow and of one near 1e-154
    // underflow: the search measures in units of the cage's size, so a cage
    // scaled by a power of two gives the same faces and parameters, and the
    // points scaled exactly.
    for (scheme, cage, options) in [
        (
            Scheme::CatmullClark,
            bumped(shapes::torus(6, 5)),
            NakedEdges::Smooth,
        ),
        (Scheme::Loop, shapes::icosahedron(), NakedEdges::Fixed),
        (Scheme::CatmullClark, open_quads(), NakedEdges::CornerFixed),
    ] {
        let options = SubdivisionOptions::new(options);
        let surface = LimitSurface::new(&cage, scheme, &options).unwrap();
        let queries = queries(&surface, &cage, scheme);
        let n = queries.len();
        let closest = |surface: &LimitSurface, points: &[DVec3]| {
            let (mut faces, mut uvs, mut positions) =
                (vec![0u32; n], vec![0.0; 2 * n], vec![DVec3::ZERO; n]);
            surface
                .closest_points(points, &mut faces, &mut uvs, &mut positions)
                .unwrap();
            (faces, uvs, positions)
        };
        let (faces, uvs, positions) = closest(&surface, &queries);
        for scale in [2f64.powi(512), 2f64.powi(-512)] {
            let moved: Vec<DVec3> = cage.positions().iter().map(|&p| p * scale).collect();
            let scaled_cage = cage.with_positions(moved).unwrap();
            let scaled_surface = LimitSurface::new(&scaled_cage, scheme, &options).unwrap();
            let scaled_queries: Vec<DVec3> = queries.iter().map(|&q| q * scale).collect();
            let (scaled_faces, scaled_uvs, scaled_positions) =
                closest(&scaled_surface, &scaled_queries);
            assert_eq!(scaled_faces, faces, "{scheme:?} scaled by {scale:e}");
            assert_eq!(scaled_uvs, uvs, "{scheme:?} scaled by {scale:e}");
            for (k, (&p, &s)) in positions.iter().zip(&scaled_positions).enumerate() {
                assert!(
                    s.is_finite(),
                    "{scheme:?} scaled by {scale:e}: query {k} at {s}"
                );
                assert_eq!(p * scale, s, "{scheme:?} scaled by {scale:e}: query {k}");
            }
        }
    }
}
