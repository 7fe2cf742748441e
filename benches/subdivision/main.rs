//! Weft's subdivision beside OpenSubdiv (Far) and OpenMesh, on the same
//! in-memory meshes in one run, with the memory floor of every output.
//!
//! `cargo bench --bench subdivision` runs every case, then prints Markdown
//! tables of the medians and ratios (read back from criterion's estimates),
//! the target cases and their re-evaluation timed in turn (in_turn.rs),
//! the targets with their
//! measured ratios, the first call in fresh processes
//! beside the steady state, and the peak memory of each one-shot case
//! (children of this binary, `VmHWM` after `clear_refs`). A criterion filter
//! after `--` runs a subset, e.g. `cargo bench --bench subdivision --
//! cc-100k-L3` (the stencil tables are built only without a filter or with
//! one naming `stencil`).
//!
//! Cases: Catmull-Clark of a 10k- and a 100k-quad torus, Loop of a 20k- and
//! a 100k-triangle torus, levels 1-3, smooth naked edges (the tori have none).
//!
//! - `weft-1t`, `weft-2t`: `weft_catmull_clark` / `weft_loop` through the C
//!   ABI (abi.rs), the library allocating the output and the handle freed,
//!   in a rayon pool of one thread and of all threads.
//! - `osd`: OpenSubdiv as its users run it: `TopologyRefinerFactory::Create`,
//!   `RefineUniform` with default `UniformOptions` and
//!   `PrimvarRefiner::Interpolate` level by level, timed together; the bridge
//!   is compiled `-O3 -march=native -DNDEBUG`.
//! - `om`: OpenMesh's uniform `CatmullClarkT` / `LoopT`, loading included.
//! - `floor-4k`, `floor-huge`, `floor-warm`: one thread writing the output's
//!   positions and face indices into fresh 4 KiB pages, fresh memory advised
//!   for huge pages, and memory in use (floors.rs).
//! - re-evaluation at level 3 of the 100k cases: `refiner-build`,
//!   `refiner-evaluate` (into a buffer of the caller) beside OpenSubdiv's
//!   stencils: `stencil-update` (`StencilTableReal<double>::UpdateValues`,
//!   one thread), `stencil-update-Nt` (the same table, each of all threads
//!   updating a contiguous range), `stencil-omp-1t` and `stencil-omp-Nt`
//!   (`Far::StencilTable` in single precision evaluated by
//!   `Osd::OmpEvaluator` on one and on all threads), and the warm floor of
//!   the evaluated positions.

mod abi;
mod floors;
mod in_turn;
mod memory;
mod report;

use std::cell::RefCell;
use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion, SamplingMode};
use rayon::ThreadPool;
use weft::mesh::shapes;
use weft::subdivide::{NakedEdges, Refiner, Scheme};
use weft::{DVec3, Mesh};
use weft_reference::{
    openmesh_catmull_clark, openmesh_loop, BoundaryInterpolation, OsdOptions, OsdParallelStencils,
    OsdRefiner, OsdStencils, RefMesh, Scheme as OsdScheme,
};

const GROUP: &str = "subdivision";
const LEVELS: [u32; 3] = [1, 2, 3];
/// The cases whose re-evaluation is compared (OpenSubdiv's stencil tables
/// take seconds and gigabytes to build, once per run).
const REEVALUATED: [&str; 2] = ["cc-100k", "loop-100k"];
/// The cases' names, in the tables' order.
const CASE_NAMES: [&str; 4] = ["cc-10k", "cc-100k", "loop-20k", "loop-100k"];

struct Case {
    name: &'static str,
    scheme: Scheme,
    mesh: Mesh,
    handle: abi::Handle,
    cage: RefMesh,
}

/// The case `name` of [`CASE_NAMES`], built alone.
fn case(name: &'static str) -> Case {
    let (scheme, mesh) = match name {
        "cc-10k" => (Scheme::CatmullClark, shapes::torus(100, 100)),
        "cc-100k" => (Scheme::CatmullClark, shapes::torus(250, 400)),
        "loop-20k" => (Scheme::Loop, shapes::triangle_torus(100, 100)),
        "loop-100k" => (Scheme::Loop, shapes::triangle_torus(200, 250)),
        _ => panic!("no case {name}"),
    };
    Case {
        name,
        scheme,
        cage: RefMesh {
            positions: mesh.positions().iter().flat_map(|p| p.to_array()).collect(),
            face_sizes: mesh.face_sizes().to_vec(),
            face_indices: mesh.face_indices().to_vec(),
        },
        handle: abi::Handle::new(&mesh),
        mesh,
    }
}

fn osd_options(scheme: Scheme) -> OsdOptions {
    let scheme = match scheme {
        Scheme::CatmullClark => OsdScheme::CatmullClark,
        Scheme::Loop => OsdScheme::Loop,
    };
    OsdOptions::new(scheme, BoundaryInterpolation::EdgeOnly)
}

fn weft_one_shot(case: &Case, levels: u32) -> abi::Handle {
    abi::subdivide(&case.handle, case.scheme == Scheme::Loop, levels)
}

fn osd_one_shot(case: &Case, levels: u32) -> Vec<f64> {
    let refiner = OsdRefiner::new(&case.cage, &osd_options(case.scheme), levels).expect("osd");
    refiner.interpolate(&case.cage.positions, 3)
}

fn om_one_shot(case: &Case, levels: u32) -> RefMesh {
    match case.scheme {
        Scheme::CatmullClark => openmesh_catmull_clark(&case.cage, levels),
        Scheme::Loop => openmesh_loop(&case.cage, levels),
    }
    .expect("openmesh subdivides")
}

fn pool(threads: usize) -> ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
}

fn threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// A benchmark's setup, made the first time the benchmark runs and kept
/// from sample to sample: criterion calls a benchmark's closure once per
/// sample, so memory allocated inside it would be fresh (its pages faulted
/// in again) in the first call of every sample. Made lazily, setups run
/// only when the filter selects the benchmark.
struct Kept<T, F: FnOnce() -> T> {
    value: Option<T>,
    make: Option<F>,
}

impl<T, F: FnOnce() -> T> Kept<T, F> {
    fn new(make: F) -> Self {
        Kept {
            value: None,
            make: Some(make),
        }
    }

    fn get(&mut self) -> &mut T {
        let make = &mut self.make;
        self.value
            .get_or_insert_with(|| (make.take().expect("made once"))())
    }
}

type Group<'a> = criterion::BenchmarkGroup<'a, criterion::measurement::WallTime>;

fn run_benchmarks(
    c: &mut Criterion,
    cases: &[Case],
    all: &ThreadPool,
    one: &ThreadPool,
    stencils: bool,
) {
    let mut group = c.benchmark_group(GROUP);
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(2))
        .sampling_mode(SamplingMode::Flat);
    let threads = all.current_num_threads();
    for case in cases {
        for levels in LEVELS {
            let id = |what: &str| BenchmarkId::new(format!("{}-L{levels}", case.name), what);
            group.bench_function(id("weft-1t"), |b| {
                b.iter(|| one.install(|| black_box(weft_one_shot(case, levels))))
            });
            group.bench_function(id(&format!("weft-{threads}t")), |b| {
                b.iter(|| all.install(|| black_box(weft_one_shot(case, levels))))
            });
            // A host's own buffers, kept from call to call (and from
            // sample to sample: see `Kept`).
            let is_loop = case.scheme == Scheme::Loop;
            let mut buffers = Kept::new(|| abi::Buffers::new(&case.handle, is_loop, levels));
            let mut into = |b: &mut criterion::Bencher<'_>, pool: &ThreadPool| {
                let buffers = buffers.get();
                b.iter(|| {
                    pool.install(|| abi::subdivide_into(&case.handle, is_loop, levels, buffers))
                })
            };
            group.bench_function(id("into-1t"), |b| into(b, one));
            group.bench_function(id(&format!("into-{threads}t")), |b| into(b, all));
            group.bench_function(id("osd"), |b| {
                b.iter(|| black_box(osd_one_shot(case, levels)))
            });
            group.bench_function(id("om"), |b| {
                b.iter(|| black_box(om_one_shot(case, levels)))
            });
            let bytes = weft_one_shot(case, levels).output_bytes();
            group.bench_function(id("floor-4k"), |b| b.iter(|| floors::fresh(bytes, false)));
            group.bench_function(id("floor-huge"), |b| b.iter(|| floors::fresh(bytes, true)));
            let mut buffer = Kept::new(|| floors::written(bytes));
            group.bench_function(id("floor-warm"), |b| {
                let buffer = buffer.get();
                b.iter(|| floors::warm(buffer))
            });
        }
        if REEVALUATED.contains(&case.name) {
            reevaluation(&mut group, case, all, threads, stencils);
        }
    }
    group.finish();
}

fn reevaluation(
    group: &mut Group<'_>,
    case: &Case,
    all: &ThreadPool,
    threads: usize,
    stencils: bool,
) {
    let levels = 3;
    let id = |what: &str| BenchmarkId::new(format!("{}-L{levels}", case.name), what);
    let build = |case: &Case| {
        Refiner::new(&case.mesh, case.scheme, levels, NakedEdges::Smooth).expect("refiner")
    };
    group.bench_function(id(&format!("refiner-build-{threads}t")), |b| {
        b.iter(|| all.install(|| black_box(build(case))))
    });
    // Moved cage positions, as a slider would give; setups run only when
    // the filter selects the benchmark.
    let moved: Vec<DVec3> = case.mesh.positions().iter().map(|p| *p * 1.01).collect();
    // The refiner and its output buffer, kept from sample to sample.
    let mut refined = Kept::new(|| {
        let refiner = build(case);
        let out = vec![DVec3::ZERO; refiner.vertex_count()];
        (refiner, out)
    });
    let mut evaluate = |b: &mut criterion::Bencher<'_>, pool: &ThreadPool| {
        let (refiner, out) = refined.get();
        b.iter(|| pool.install(|| refiner.evaluate(&moved, out).unwrap()))
    };
    group.bench_function(id("refiner-evaluate-1t"), |b| evaluate(b, &pool(1)));
    group.bench_function(id(&format!("refiner-evaluate-{threads}t")), |b| {
        evaluate(b, all)
    });
    let mut buffer = Kept::new(|| floors::written(24 * build(case).vertex_count()));
    group.bench_function(id("evaluate-floor-warm"), |b| {
        let buffer = buffer.get();
        b.iter(|| floors::warm(buffer))
    });
    if !stencils {
        return;
    }

    let options = osd_options(case.scheme);
    let start = Instant::now();
    let table = OsdStencils::new(&case.cage, &options, levels).unwrap();
    report::record_once(
        &format!("{}-L{levels}", case.name),
        "stencil-build",
        start.elapsed(),
    );
    let moved: Vec<f64> = case.cage.positions.iter().map(|x| x * 1.01).collect();
    let mut out = vec![0.0; 3 * table.vertex_count()];
    group.bench_function(id("stencil-update"), |b| {
        b.iter(|| table.update(&moved, &mut out))
    });
    group.bench_function(id(&format!("stencil-update-{threads}t")), |b| {
        b.iter(|| table.update_on_threads(&moved, &mut out, threads as u32))
    });
    drop((table, out));

    let parallel = OsdParallelStencils::new(&case.cage, &options, levels).unwrap();
    let moved: Vec<f32> = moved.iter().map(|&x| x as f32).collect();
    let mut out = vec![0.0f32; 3 * parallel.vertex_count()];
    // One OpenMP thread beside all: Osd's kernel keeps every thread's sum
    // in one small array, so two threads share its cache line.
    let mut omp_thread_counts = vec![1, threads];
    omp_thread_counts.dedup();
    for omp_threads in omp_thread_counts {
        group.bench_function(id(&format!("stencil-omp-{omp_threads}t")), |b| {
            b.iter(|| parallel.update(&moved, &mut out, omp_threads as u32))
        });
    }
}

/// The target cases (level 3 of the 100k tori) timed in turn, those the
/// filter selects (see [`in_turn`]).
fn target_cases_in_turn(
    cases: &[Case],
    all: &ThreadPool,
    one: &ThreadPool,
    filter: Option<&str>,
) -> Vec<in_turn::InTurn> {
    let levels = 3;
    cases
        .iter()
        .filter(|case| REEVALUATED.contains(&case.name))
        .map(|case| (case, format!("{}-L{levels}", case.name)))
        .filter(|(_, name)| filter.is_none_or(|f| name.contains(f) || f.contains(name.as_str())))
        .map(|(case, name)| {
            let bytes = weft_one_shot(case, levels).output_bytes();
            in_turn::InTurn::run(
                name,
                [
                    &|| drop(black_box(osd_one_shot(case, levels))),
                    &|| one.install(|| drop(black_box(weft_one_shot(case, levels)))),
                    &|| all.install(|| drop(black_box(weft_one_shot(case, levels)))),
                    &|| floors::fresh(bytes, true),
                ],
            )
        })
        .collect()
}

/// The re-evaluation of the target cases timed in turn (see
/// [`in_turn`]), those the filter selects: Weft's refiner and the stencil
/// table made again, as `reevaluation` makes them.
fn reevaluation_in_turn(
    cases: &[Case],
    all: &ThreadPool,
    threads: usize,
    filter: Option<&str>,
) -> Vec<in_turn::InTurn<3>> {
    let levels = 3;
    cases
        .iter()
        .filter(|case| REEVALUATED.contains(&case.name))
        .map(|case| (case, format!("{}-L{levels}", case.name)))
        // A filter naming a case selects it; one naming none ("stencil") both.
        .filter(|(_, name)| {
            filter.is_none_or(|f| {
                f.contains(name.as_str()) || !REEVALUATED.iter().any(|case| f.contains(case))
            })
        })
        .map(|(case, name)| {
            let refiner = all
                .install(|| Refiner::new(&case.mesh, case.scheme, levels, NakedEdges::Smooth))
                .expect("refiner");
            let moved: Vec<DVec3> = case.mesh.positions().iter().map(|p| *p * 1.01).collect();
            let out = RefCell::new(vec![DVec3::ZERO; refiner.vertex_count()]);
            let floor = RefCell::new(floors::written(24 * refiner.vertex_count()));
            let table = OsdStencils::new(&case.cage, &osd_options(case.scheme), levels).unwrap();
            let moved_flat: Vec<f64> = case.cage.positions.iter().map(|x| x * 1.01).collect();
            let stencil_out = RefCell::new(vec![0.0; 3 * table.vertex_count()]);
            in_turn::InTurn::run(
                name,
                [
                    &|| {
                        let mut out = out.borrow_mut();
                        let out: &mut [DVec3] = &mut out;
                        all.install(|| refiner.evaluate(&moved, out).unwrap())
                    },
                    &|| floors::warm(&mut floor.borrow_mut()),
                    &|| {
                        let mut stencil_out = stencil_out.borrow_mut();
                        table.update_on_threads(&moved_flat, &mut stencil_out, threads as u32)
                    },
                ],
            )
        })
        .collect()
}

fn main() {
    if let Some(result) = memory::child() {
        println!("{result}");
        return;
    }
    let threads = threads();
    let (all, one) = (pool(threads), pool(1));
    let cases: Vec<Case> = CASE_NAMES.into_iter().map(case).collect();
    // `cargo bench` passes `--bench`; anything else not an option is a filter.
    let filter = std::env::args().skip(1).find(|a| !a.starts_with('-'));
    let stencils = filter.as_deref().is_none_or(|f| f.contains("stencil"));
    let mut criterion = Criterion::default().configure_from_args();
    run_benchmarks(&mut criterion, &cases, &all, &one, stencils);
    criterion.final_summary();
    if std::env::args().any(|a| a == "--list" || a == "--test") {
        return;
    }
    let in_turn = target_cases_in_turn(&cases, &all, &one, filter.as_deref());
    let reevaluated = match stencils {
        true => reevaluation_in_turn(&cases, &all, threads, filter.as_deref()),
        false => Vec::new(),
    };
    drop(cases);
    report::one_shot(threads);
    report::into_buffers(threads);
    report::reevaluation(threads);
    let cold = memory::cold_calls(filter.as_deref());
    report::cold(&cold, threads);
    in_turn::print(&in_turn, threads);
    in_turn::print_reevaluation(&reevaluated, threads);
    report::targets(threads, &cold, &in_turn, &reevaluated);
    memory::peak_memory(filter.as_deref());
}
