//! Evaluation of the limit surface anywhere: 1 M samples on a 10k-quad
//! torus (every face regular) and on a 10k-face cage with extraordinary
//! vertices (the torus with every fourth quad split into two triangles,
//! subdivided by Catmull-Clark), Weft's `LimitSurface::evaluate` (positions
//! and both derivatives, on one thread and on two) beside OpenSubdiv's Bfr
//! (`Surface<double>::Evaluate`, one surface per face kept for that face's
//! samples, as its users evaluate; with Bfr's default approximation of
//! irregular faces; one thread), both into buffers kept from call to call,
//! and the preparation of Weft's surface
//! (`LimitSurface::new`). The largest distance between the two over the
//! samples is printed.
//!
//! `cargo bench --bench limit_surface`.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use weft::mesh::shapes;
use weft::subdivide::{LimitSurface, NakedEdges, Scheme, SubdivisionOptions};
use weft::{DVec3, Mesh};
use weft_reference::{BoundaryInterpolation, OsdOptions, OsdRefiner, RefMesh};

const SAMPLES: usize = 1_000_000;

/// The torus with every fourth quad split into two triangles.
fn irregular_torus() -> Mesh {
    let torus = shapes::torus(100, 100);
    let mut faces: Vec<Vec<u32>> = Vec::new();
    for f in 0..torus.face_count() {
        let q = torus.face(f);
        if f % 4 == 0 {
            faces.push(vec![q[0], q[1], q[2]]);
            faces.push(vec![q[0], q[2], q[3]]);
        } else {
            faces.push(q.to_vec());
        }
    }
    Mesh::from_polygons(torus.positions().to_vec(), faces).unwrap()
}

/// `SAMPLES` parameters spread over the faces, face by face.
fn samples(cage: &Mesh) -> (Vec<u32>, Vec<f64>) {
    let per_face = SAMPLES.div_ceil(cage.face_count());
    let side = (per_face as f64).sqrt().ceil() as usize;
    let (mut faces, mut uvs) = (Vec::new(), Vec::new());
    for f in 0..cage.face_count() {
        let n = cage.face(f).len();
        for k in 0..per_face {
            let (a, b) = ((k % side) as f64 + 0.5, (k / side) as f64 + 0.5);
            let (u, v) = (a / side as f64, b / side as f64);
            faces.push(f as u32);
            if n == 4 {
                uvs.extend([u, v]);
            } else {
                // Sub-face k mod n of the face, in its tile.
                let w = if n < 5 { 2 } else { 3 };
                let tile = k % n;
                uvs.extend([(tile % w) as f64 + 0.5 * u, (tile / w) as f64 + 0.5 * v]);
            }
        }
    }
    faces.truncate(SAMPLES);
    uvs.truncate(2 * SAMPLES);
    (faces, uvs)
}

fn to_ref(mesh: &Mesh) -> RefMesh {
    RefMesh {
        positions: mesh.positions().iter().flat_map(|p| p.to_array()).collect(),
        face_sizes: mesh.face_sizes().to_vec(),
        face_indices: mesh.face_indices().to_vec(),
    }
}

fn limit_surface(c: &mut Criterion) {
    let mut group = c.benchmark_group("limit-surface");
    group.sample_size(10);
    let options = SubdivisionOptions::new(NakedEdges::Smooth);
    for (name, cage) in [
        ("torus-10k", shapes::torus(100, 100)),
        ("irregular-10k", irregular_torus()),
    ] {
        let (faces, uvs) = samples(&cage);
        group.bench_function(format!("{name}/weft-new"), |b| {
            b.iter(|| LimitSurface::new(black_box(&cage), Scheme::CatmullClark, &options).unwrap())
        });
        let surface = LimitSurface::new(&cage, Scheme::CatmullClark, &options).unwrap();
        let mut out = [
            vec![DVec3::ZERO; faces.len()],
            vec![DVec3::ZERO; faces.len()],
            vec![DVec3::ZERO; faces.len()],
        ];
        for threads in [1, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            group.bench_function(format!("{name}/weft-evaluate-1M-{threads}t"), |b| {
                b.iter(|| {
                    let [p, du, dv] = &mut out;
                    pool.install(|| {
                        surface
                            .evaluate(black_box(&faces), &uvs, p, Some(du), Some(dv))
                            .unwrap()
                    });
                })
            });
        }
        let reference = to_ref(&cage);
        let osd = OsdRefiner::new(
            &reference,
            &OsdOptions::new(
                weft_reference::Scheme::CatmullClark,
                BoundaryInterpolation::EdgeOnly,
            ),
            0,
        )
        .unwrap();
        // Bfr writes into buffers kept from call to call, as Weft does.
        let mut theirs = [
            vec![0.0; 3 * faces.len()],
            vec![0.0; 3 * faces.len()],
            vec![0.0; 3 * faces.len()],
        ];
        group.bench_function(format!("{name}/bfr-evaluate-1M-1t"), |b| {
            b.iter(|| {
                let [p, du, dv] = &mut theirs;
                osd.bfr_evaluate_into(
                    &reference.positions,
                    (2, 6),
                    black_box(&faces),
                    &uvs,
                    [p, du, dv],
                )
                .unwrap()
            })
        });
        let [theirs, _, _] = osd
            .bfr_evaluate(&reference.positions, (2, 6), &faces, &uvs)
            .unwrap();
        let worst = out[0]
            .iter()
            .zip(theirs.chunks_exact(3))
            .map(|(a, b)| (*a - DVec3::from_slice(b)).length())
            .fold(0.0, f64::max);
        eprintln!("{name}: largest distance between Weft and Bfr over the samples: {worst:.2e}");
    }
    group.finish();
}

criterion_group!(benches, limit_surface);
criterion_main!(benches);
