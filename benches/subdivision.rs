//! Weft's subdivision beside OpenSubdiv (Far) and OpenMesh, on the same
//! in-memory meshes in one run.
//!
//! `cargo bench --bench subdivision` runs every case, then prints a Markdown
//! table of the medians and ratios (read back from criterion's estimates) and
//! the peak memory of each one-shot case, measured in a child process of this
//! binary (`VmHWM` after `clear_refs`). A criterion filter after `--` runs a
//! subset, e.g. `cargo bench --bench subdivision -- cc-100k-L3` (the stencil
//! table is built only without a filter or with one naming `stencil`).
//!
//! Cases: Catmull-Clark of a 10k- and a 100k-quad torus, Loop of a 20k- and
//! a 100k-triangle torus, levels 1-3, all with smooth naked edges (the tori
//! have none).
//!
//! - one-shot: `weft` with a rayon pool of one thread and of all threads;
//!   `osd` = `OsdRefiner::new` (Far `TopologyRefinerFactory` + `RefineUniform`)
//!   plus `interpolate` (`PrimvarRefiner::Interpolate` level by level), also
//!   timed apart at level 3 (`osd-refine`, `osd-interpolate`); `om` = OpenMesh's
//!   uniform `CatmullClarkT` / `LoopT` including loading its mesh.
//! - re-evaluation at level 3 of the 100k cases: `refiner-build`,
//!   `refiner-evaluate` (into a buffer of the caller) beside `stencil-update`
//!   (`StencilTable::UpdateValues`); the stencil table's build (seconds and
//!   gigabytes) is timed once, outside criterion.

use std::hint::black_box;
use std::path::PathBuf;
use std::process::Command;
use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion, SamplingMode};
use rayon::ThreadPool;
use weft::mesh::shapes;
use weft::subdivide::{subdivide, NakedEdges, Refiner, Scheme};
use weft::{DVec3, Mesh};
use weft_reference::{
    openmesh_catmull_clark, openmesh_loop, BoundaryInterpolation, OsdOptions, OsdRefiner,
    OsdStencils, RefMesh, Scheme as OsdScheme,
};

const GROUP: &str = "subdivision";
const LEVELS: [u32; 3] = [1, 2, 3];
/// The case whose stencils and refiner are compared (the 10 s, 4 GB build of
/// OpenSubdiv's stencil table is done once per run).
const REEVALUATED: [&str; 2] = ["cc-100k", "loop-100k"];

struct Case {
    name: &'static str,
    scheme: Scheme,
    mesh: Mesh,
    cage: RefMesh,
}

/// The cases' names, in the tables' order.
const CASE_NAMES: [&str; 4] = ["cc-10k", "cc-100k", "loop-20k", "loop-100k"];

fn cases() -> Vec<Case> {
    CASE_NAMES.into_iter().map(case).collect()
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
        cage: ref_mesh(&mesh),
        mesh,
    }
}

fn ref_mesh(mesh: &Mesh) -> RefMesh {
    RefMesh {
        positions: mesh.positions().iter().flat_map(|p| p.to_array()).collect(),
        face_sizes: mesh.face_sizes().to_vec(),
        face_indices: mesh.face_indices().to_vec(),
    }
}

fn osd_options(scheme: Scheme) -> OsdOptions {
    let scheme = match scheme {
        Scheme::CatmullClark => OsdScheme::CatmullClark,
        Scheme::Loop => OsdScheme::Loop,
    };
    OsdOptions::new(scheme, BoundaryInterpolation::EdgeOnly)
}

fn weft_one_shot(case: &Case, levels: u32) -> Mesh {
    subdivide(&case.mesh, case.scheme, levels, NakedEdges::Smooth).expect("weft subdivides")
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

/// Bytes of a mesh's buffers: positions, face sizes, indices and offsets.
fn mesh_bytes(mesh: &Mesh) -> usize {
    24 * mesh.vertex_count() + 4 * (2 * mesh.face_count() + 1) + 4 * mesh.index_count()
}

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
            group.bench_function(id("osd"), |b| {
                b.iter(|| black_box(osd_one_shot(case, levels)))
            });
            group.bench_function(id("om"), |b| {
                b.iter(|| black_box(om_one_shot(case, levels)))
            });
            if levels == 3 {
                let options = osd_options(case.scheme);
                group.bench_function(id("osd-refine"), |b| {
                    b.iter(|| black_box(OsdRefiner::new(&case.cage, &options, levels).unwrap()))
                });
                group.bench_function(id("osd-interpolate"), |b| {
                    let refiner = OsdRefiner::new(&case.cage, &options, levels).unwrap();
                    b.iter(|| black_box(refiner.interpolate(&case.cage.positions, 3)))
                });
            }
        }
        if REEVALUATED.contains(&case.name) {
            reevaluation(&mut group, case, all, threads, stencils);
        }
    }
    group.finish();
}

fn reevaluation(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
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
    let evaluate = |b: &mut criterion::Bencher<'_>, pool: &ThreadPool| {
        let refiner = build(case);
        let mut out = vec![DVec3::ZERO; refiner.vertex_count()];
        b.iter(|| pool.install(|| refiner.evaluate(&moved, &mut out).unwrap()))
    };
    group.bench_function(id("refiner-evaluate-1t"), |b| evaluate(b, &pool(1)));
    group.bench_function(id(&format!("refiner-evaluate-{threads}t")), |b| {
        evaluate(b, all)
    });
    if !stencils {
        return;
    }

    let start = Instant::now();
    let stencils = OsdStencils::new(&case.cage, &osd_options(case.scheme), levels).unwrap();
    let built = start.elapsed();
    println!(
        "{GROUP}/{}-L{levels}/stencil-build: {:.2} s (timed once)",
        case.name,
        built.as_secs_f64()
    );
    record_once(&format!("{}-L{levels}", case.name), "stencil-build", built);
    let moved: Vec<f64> = case.cage.positions.iter().map(|x| x * 1.01).collect();
    let mut out = vec![0.0; 3 * stencils.vertex_count()];
    group.bench_function(id("stencil-update"), |b| {
        b.iter(|| stencils.update(&moved, &mut out))
    });
}

/// Timings measured once, outside criterion, kept for the summary.
fn record_once(case: &str, what: &str, time: Duration) {
    let path = estimates_dir().join(case).join(what);
    std::fs::create_dir_all(&path).expect("criterion's directory");
    std::fs::write(path.join("once.txt"), format!("{}", time.as_secs_f64()))
        .expect("write a timing");
}

fn estimates_dir() -> PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target"));
    target.join("criterion").join(GROUP)
}

/// The median (seconds) of the latest run of `case/what`, if it ran.
fn median(case: &str, what: &str) -> Option<f64> {
    let dir = estimates_dir().join(case).join(what);
    if let Ok(once) = std::fs::read_to_string(dir.join("once.txt")) {
        return once.trim().parse().ok();
    }
    let json = std::fs::read_to_string(dir.join("new").join("estimates.json")).ok()?;
    let at = json.find("\"median\"")?;
    let rest = &json[at..];
    let value = &rest[rest.find("\"point_estimate\":")? + "\"point_estimate\":".len()..];
    let end = value.find([',', '}'])?;
    value[..end].trim().parse::<f64>().ok().map(|ns| ns * 1e-9)
}

fn summary(cases: &[Case], threads: usize) {
    let all = format!("weft-{threads}t");
    let ms = |t: Option<f64>| t.map_or("–".to_owned(), |t| format!("{:.1}", t * 1e3));
    let ratio = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) => format!("{:.1}×", a / b),
        _ => "–".to_owned(),
    };
    println!("\n## One-shot (median ms; ratio = other / Weft)\n");
    println!(
        "| case | Weft 1t | Weft {threads}t | OSD | OSD refine | OSD interp. | OpenMesh \
         | OSD/Weft 1t | OSD/Weft {threads}t | OM/Weft {threads}t |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for case in cases {
        for levels in LEVELS {
            let name = format!("{}-L{levels}", case.name);
            let get = |what: &str| median(&name, what);
            let (w1, wn, osd, om) = (get("weft-1t"), get(&all), get("osd"), get("om"));
            if w1.is_none() && wn.is_none() && osd.is_none() && om.is_none() {
                continue;
            }
            println!(
                "| {name} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
                ms(w1),
                ms(wn),
                ms(osd),
                ms(get("osd-refine")),
                ms(get("osd-interpolate")),
                ms(om),
                ratio(osd, w1),
                ratio(osd, wn),
                ratio(om, wn),
            );
        }
    }
    println!("\n## Re-evaluation at level 3 (median ms)\n");
    println!(
        "| case | refiner build {threads}t | Weft one-shot {threads}t | build/one-shot \
         | evaluate 1t | evaluate {threads}t | stencil update | stencil build (once) \
         | update/evaluate {threads}t |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    for name in REEVALUATED {
        let name = format!("{name}-L3");
        let get = |what: &str| median(&name, what);
        let build = get(&format!("refiner-build-{threads}t"));
        let evaluate = get(&format!("refiner-evaluate-{threads}t"));
        let update = get("stencil-update");
        if build.is_none() && update.is_none() {
            continue;
        }
        println!(
            "| {name} | {} | {} | {} | {} | {} | {} | {} | {} |",
            ms(build),
            ms(get(&all)),
            ratio(build, get(&all)),
            ms(get("refiner-evaluate-1t")),
            ms(evaluate),
            ms(update),
            get("stencil-build").map_or("–".to_owned(), |t| format!("{t:.2} s")),
            ratio(update, evaluate),
        );
    }
}

/// What a child process measures: `case level who`.
const PEAK_VAR: &str = "WEFT_BENCH_PEAK";

/// In a child: builds the case, resets the peak resident size, runs one
/// one-shot subdivision, prints `peak_bytes output_bytes`.
fn peak_child(spec: &str) {
    let mut words = spec.split_whitespace();
    let (name, levels, who) = (
        words.next().unwrap(),
        words.next().unwrap().parse::<u32>().unwrap(),
        words.next().unwrap(),
    );
    // Built alone: memory freed by other cases would be reused unseen.
    let name = CASE_NAMES
        .into_iter()
        .find(|&n| n == name)
        .expect("a case name");
    let case = case(name);
    let all = pool(std::thread::available_parallelism().map_or(1, |n| n.get()));
    // Starts the pool's threads on a small mesh, so that no memory the
    // measured call could reuse is left free on the heap.
    let warm_up = weft::mesh::shapes::icosahedron();
    all.install(|| drop(subdivide(&warm_up, case.scheme, 1, NakedEdges::Smooth)));
    std::fs::write("/proc/self/clear_refs", "5").expect("reset the peak resident size");
    let before = status_kib("VmRSS:") * 1024;
    let output = match who {
        "weft" => all.install(|| mesh_bytes(&black_box(weft_one_shot(&case, levels)))),
        _ => {
            // OpenSubdiv's positions, and its last level's faces as a mesh.
            let refiner = OsdRefiner::new(&case.cage, &osd_options(case.scheme), levels).unwrap();
            black_box(refiner.interpolate(&case.cage.positions, 3));
            // Compared with Weft's output of the same mesh.
            0
        }
    };
    let peak = status_kib("VmHWM:") * 1024;
    println!("{} {}", peak.saturating_sub(before), output);
}

fn status_kib(field: &str) -> usize {
    let status = std::fs::read_to_string("/proc/self/status").expect("/proc/self/status");
    status
        .lines()
        .find_map(|l| l.strip_prefix(field))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        .expect("a VmRSS/VmHWM line")
}

fn peak_memory(filter: Option<&str>) {
    println!("\n## Peak memory of one-shot subdivision (MB above the input)\n");
    println!("| case | output | Weft peak | Weft peak/output | OSD peak | OSD peak/output |");
    println!("|---|---:|---:|---:|---:|---:|");
    let exe = std::env::current_exe().expect("this benchmark's path");
    let measure = |spec: &str| -> Option<(f64, f64)> {
        let out = Command::new(&exe).env(PEAK_VAR, spec).output().ok()?;
        let text = String::from_utf8_lossy(&out.stdout);
        let mut numbers = text.split_whitespace().map(|w| w.parse::<f64>().ok());
        Some((numbers.next()??, numbers.next()??))
    };
    for name in CASE_NAMES {
        for levels in 1..=3 {
            let label = format!("{name}-L{levels}");
            if filter.is_some_and(|f| !label.contains(f)) {
                continue;
            }
            let weft = measure(&format!("{name} {levels} weft"));
            let osd = measure(&format!("{name} {levels} osd"));
            let (Some((weft_peak, output)), Some((osd_peak, _))) = (weft, osd) else {
                println!("| {label} | – | – | – | – | – |");
                continue;
            };
            println!(
                "| {label} | {} | {} | {:.2}× | {} | {:.2}× |",
                mb(output),
                mb(weft_peak),
                weft_peak / output,
                mb(osd_peak),
                osd_peak / output
            );
        }
    }
}

/// Megabytes, with a decimal below 10.
fn mb(bytes: f64) -> String {
    match bytes / 1e6 {
        m if m < 10.0 => format!("{m:.1}"),
        m => format!("{m:.0}"),
    }
}

fn main() {
    if let Ok(spec) = std::env::var(PEAK_VAR) {
        peak_child(&spec);
        return;
    }
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let (all, one) = (pool(threads), pool(1));
    let cases = cases();
    // `cargo bench` passes `--bench`; anything else not an option is a filter.
    let filter = std::env::args().skip(1).find(|a| !a.starts_with('-'));
    // The stencil table takes seconds and gigabytes: built only when its
    // update is measured.
    let stencils = filter.as_deref().is_none_or(|f| f.contains("stencil"));
    let mut criterion = Criterion::default().configure_from_args();
    run_benchmarks(&mut criterion, &cases, &all, &one, stencils);
    criterion.final_summary();
    if std::env::args().any(|a| a == "--list" || a == "--test") {
        return;
    }
    summary(&cases, threads);
    peak_memory(filter.as_deref());
}
