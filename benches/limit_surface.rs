//! The limit surface evaluated anywhere: 1,000,000 samples on cages of
//! about 10,000 faces, Weft's `LimitSurface::evaluate` (positions and both
//! derivatives, on one thread and on all) beside OpenSubdiv's Bfr on the
//! same samples (`Bfr::RefinerSurfaceFactory`, one `Surface<double>` per
//! face kept for that face's samples, `Evaluate` with derivatives; one
//! thread, as Bfr evaluates). Building each evaluator is timed apart.
//!
//! Run with `cargo bench --bench limit_surface`.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use weft::mesh::shapes;
use weft::subdivide::{subdivide, LimitSurface, NakedEdges, Scheme, SubdivisionOptions};
use weft::{DVec3, Mesh};
use weft_reference::{BoundaryInterpolation, OsdOptions, OsdRefiner, RefMesh, Scheme as OsdScheme};

const SAMPLES: usize = 1_000_000;

/// The cages: a regular torus of 10,000 quads, and a cube refined 5 times
/// (6,144 quads, 8 extraordinary vertices).
fn cages() -> Vec<(&'static str, Mesh)> {
    vec![
        ("torus-10k", shapes::torus(100, 100)),
        (
            "cube-6k",
            subdivide(&shapes::cube(), Scheme::CatmullClark, 5, NakedEdges::Smooth).unwrap(),
        ),
    ]
}

/// `SAMPLES` samples spread over the faces in face order, at scattered
/// parameters of each.
fn samples(face_count: usize) -> (Vec<u32>, Vec<f64>) {
    let mut faces = Vec::with_capacity(SAMPLES);
    let mut uvs = Vec::with_capacity(2 * SAMPLES);
    for k in 0..SAMPLES {
        faces.push((k * face_count / SAMPLES) as u32);
        uvs.push(((k * 7919) % 1000) as f64 / 999.0);
        uvs.push(((k * 104_729) % 1000) as f64 / 999.0);
    }
    (faces, uvs)
}

fn limit_surface(c: &mut Criterion) {
    let mut group = c.benchmark_group("limit-surface");
    group.sample_size(10);
    let options = SubdivisionOptions::new(NakedEdges::Smooth);
    for (name, cage) in cages() {
        let (faces, uvs) = samples(cage.face_count());
        let surface = LimitSurface::new(&cage, Scheme::CatmullClark, &options).unwrap();
        let (mut p, mut du, mut dv) = (
            vec![DVec3::ZERO; SAMPLES],
            vec![DVec3::ZERO; SAMPLES],
            vec![DVec3::ZERO; SAMPLES],
        );
        group.bench_function(format!("{name}/weft-build"), |b| {
            b.iter(|| LimitSurface::new(black_box(&cage), Scheme::CatmullClark, &options).unwrap())
        });
        for threads in [1, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            group.bench_function(format!("{name}/weft-{threads}t"), |b| {
                b.iter(|| {
                    pool.install(|| {
                        surface
                            .evaluate(
                                black_box(&faces),
                                &uvs,
                                &mut p,
                                Some(&mut du),
                                Some(&mut dv),
                            )
                            .unwrap()
                    })
                })
            });
        }

        let reference = RefMesh {
            positions: cage.positions().iter().flat_map(|q| q.to_array()).collect(),
            face_sizes: cage.face_sizes().to_vec(),
            face_indices: cage.face_indices().to_vec(),
        };
        let osd = OsdOptions::new(OsdScheme::CatmullClark, BoundaryInterpolation::EdgeOnly);
        let refiner = OsdRefiner::new(&reference, &osd, 0).unwrap();
        // Bfr's default approximation of irregular faces (smooth 2, sharp 6).
        group.bench_function(format!("{name}/bfr-1t"), |b| {
            b.iter(|| {
                refiner
                    .bfr_evaluate(&reference.positions, (2, 6), black_box(&faces), &uvs)
                    .unwrap()
            })
        });
        // The same points, to the rounding of the patches where both are exact.
        let [theirs, _, _] = refiner
            .bfr_evaluate(&reference.positions, (2, 6), &faces, &uvs)
            .unwrap();
        let worst = p
            .iter()
            .zip(theirs.chunks_exact(3))
            .map(|(a, b)| (*a - DVec3::from_slice(b)).length())
            .fold(0.0, f64::max);
        eprintln!("{name}: largest distance between Weft and Bfr over the samples {worst:.2e}");
    }
    group.finish();
}

criterion_group!(benches, limit_surface);
criterion_main!(benches);
