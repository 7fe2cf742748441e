//! Mending on meshes of a million elements: weld and the topology it feeds,
//! with OpenSubdiv building its topology of the same mesh beside Weft's
//! (`Far::TopologyRefinerFactory::Create`, no refinement).
//!
//! The group `files` reads and writes an OBJ file of a million quads in
//! memory (the parallel reader and writer, no disk).
//!
//! Run with `cargo bench --bench mending`.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use weft::mend::weld::{weld, DEFAULT_WELD_TOLERANCE};
use weft::mesh::shapes;
use weft::{DVec3, Mesh, Topology};
use weft_reference::{BoundaryInterpolation, OsdOptions, OsdRefiner, RefMesh, Scheme as OsdScheme};

/// A 500 × 500 quad grid whose every face has its own four vertices, each
/// moved by up to 0.0004 on every axis: 1,000,000 vertices that weld back to
/// 251,001, the way separately meshed panels arrive from the host.
fn loose_grid() -> Mesh {
    grid_soup(|k| {
        let jitter = ((k * 7919) % 9) as f64 * 0.5e-4;
        DVec3::new(jitter, -jitter, jitter)
    })
}

/// The same grid's faces each with four vertices of their own, exact
/// copies of the grid's: a soup as STL files hold them, each position
/// written as often as faces meet at it, the copies near in order.
fn copied_grid() -> Mesh {
    grid_soup(|_| DVec3::ZERO)
}

/// A 500 × 500 quad grid's faces each with four vertices of their own, the
/// k-th corner's moved by `nudge(k)`.
fn grid_soup(nudge: impl Fn(usize) -> DVec3) -> Mesh {
    let grid = shapes::quad_grid(500, 500);
    let mut positions = Vec::with_capacity(grid.index_count());
    for (k, &v) in grid.face_indices().iter().enumerate() {
        positions.push(grid.positions()[v as usize] + nudge(k));
    }
    let indices: Vec<u32> = (0..grid.index_count() as u32).collect();
    Mesh::new(positions, grid.face_sizes().to_vec(), indices).unwrap()
}

fn mending(c: &mut Criterion) {
    let mut group = c.benchmark_group("mending");
    group.sample_size(10);

    let loose = loose_grid();
    assert_eq!(loose.vertex_count(), 1_000_000);
    let (welded, _) = weld(&loose, DEFAULT_WELD_TOLERANCE).unwrap();
    assert_eq!(welded.vertex_count(), 501 * 501);
    group.bench_function("weld 1M vertices", |b| {
        b.iter(|| weld(black_box(&loose), DEFAULT_WELD_TOLERANCE).unwrap())
    });
    let copied = copied_grid();
    let (welded, _) = weld(&copied, DEFAULT_WELD_TOLERANCE).unwrap();
    assert_eq!(welded.vertex_count(), 501 * 501);
    group.bench_function("weld 1M exact copies", |b| {
        b.iter(|| weld(black_box(&copied), DEFAULT_WELD_TOLERANCE).unwrap())
    });

    let grid = shapes::quad_grid(1000, 1000);
    group.bench_function("topology of 1M quads", |b| {
        b.iter(|| Topology::new(black_box(&grid)))
    });
    let cage = RefMesh {
        positions: grid.positions().iter().flat_map(|p| p.to_array()).collect(),
        face_sizes: grid.face_sizes().to_vec(),
        face_indices: grid.face_indices().to_vec(),
    };
    let options = OsdOptions::new(OsdScheme::CatmullClark, BoundaryInterpolation::EdgeOnly);
    group.bench_function("OpenSubdiv topology of 1M quads", |b| {
        b.iter(|| OsdRefiner::new(black_box(&cage), &options, 0).expect("osd"))
    });
    group.finish();
}

fn files(c: &mut Criterion) {
    let mut group = c.benchmark_group("files");
    group.sample_size(10);
    let grid = shapes::quad_grid(1000, 1000);
    let mut text = Vec::new();
    weft::io::obj::write(&mut text, &grid).unwrap();
    assert_eq!(weft::io::obj::parse(&text).unwrap(), grid);
    group.bench_function("read OBJ of 1M quads", |b| {
        b.iter(|| weft::io::obj::parse(black_box(&text)).unwrap())
    });
    group.bench_function("write OBJ of 1M quads", |b| {
        b.iter(|| {
            let mut out = Vec::with_capacity(text.len());
            weft::io::obj::write(&mut out, black_box(&grid)).unwrap();
            out
        })
    });
    group.finish();
}

criterion_group!(benches, mending, files);
criterion_main!(benches);
