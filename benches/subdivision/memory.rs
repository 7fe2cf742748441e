//! What is measured in child processes of the benchmark: the peak memory
//! of one one-shot subdivision, and the first call in a fresh process (what
//! every command-line run and the first solve on the canvas pay).

use std::hint::black_box;
use std::process::Command;
use std::time::Instant;

use weft::subdivide::{subdivide, NakedEdges};

use crate::{case, osd_options, pool, threads, weft_one_shot, CASE_NAMES};

/// What a child process measures: `peak|cold case level who`.
const CHILD_VAR: &str = "WEFT_BENCH_CHILD";
/// Fresh processes per cold-call case; the median is reported.
pub const COLD_PROCESSES: usize = 5;
/// The cases whose first call is measured.
pub const COLD_CASES: [&str; 2] = ["cc-100k-L3", "loop-100k-L3"];

/// In a child, the measurement its environment asks for, as one line.
pub fn child() -> Option<String> {
    let spec = std::env::var(CHILD_VAR).ok()?;
    let mut words = spec.split_whitespace();
    let (kind, name, levels, who) = (
        words.next()?,
        words.next()?,
        words.next()?.parse::<u32>().ok()?,
        words.next().unwrap_or("weft"),
    );
    // Built alone: memory freed by other cases would be reused unseen.
    let name = CASE_NAMES.into_iter().find(|&n| n == name)?;
    let case = case(name);
    Some(match kind {
        "cold" => {
            // The library's thread pool starts in this call, as in a new
            // process of a host.
            let start = Instant::now();
            black_box(weft_one_shot(&case, levels));
            format!("{}", start.elapsed().as_secs_f64())
        }
        _ => {
            let all = pool(threads());
            // Starts the pool's threads on a small mesh, so that no memory the
            // measured call could reuse is left free on the heap.
            let warm_up = weft::mesh::shapes::icosahedron();
            all.install(|| drop(subdivide(&warm_up, case.scheme, 1, NakedEdges::Smooth)));
            std::fs::write("/proc/self/clear_refs", "5").expect("reset the peak resident size");
            let before = status_kib("VmRSS:") * 1024;
            let output = match who {
                "weft" => all.install(|| weft_one_shot(&case, levels).output_bytes()),
                _ => {
                    let refiner = weft_reference::OsdRefiner::new(
                        &case.cage,
                        &osd_options(case.scheme),
                        levels,
                    )
                    .unwrap();
                    black_box(refiner.interpolate(&case.cage.positions, 3));
                    0
                }
            };
            let peak = status_kib("VmHWM:") * 1024;
            format!("{} {}", peak.saturating_sub(before), output)
        }
    })
}

fn status_kib(field: &str) -> usize {
    let status = std::fs::read_to_string("/proc/self/status").expect("/proc/self/status");
    status
        .lines()
        .find_map(|l| l.strip_prefix(field))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        .expect("a VmRSS/VmHWM line")
}

fn run_child(spec: &str) -> Option<Vec<f64>> {
    let exe = std::env::current_exe().ok()?;
    let out = Command::new(exe).env(CHILD_VAR, spec).output().ok()?;
    let text = String::from_utf8_lossy(&out.stdout);
    let line = text.lines().last()?;
    line.split_whitespace()
        .map(|w| w.parse::<f64>().ok())
        .collect()
}

/// The first-call times of [`COLD_CASES`] that the filter selects: the
/// median over [`COLD_PROCESSES`] fresh processes, and every sample.
pub fn cold_calls(filter: Option<&str>) -> Vec<(String, f64, Vec<f64>)> {
    let mut results = Vec::new();
    for label in COLD_CASES {
        if filter.is_some_and(|f| !label.contains(f)) {
            continue;
        }
        let (name, level) = label.rsplit_once("-L").expect("a case label");
        let mut samples: Vec<f64> = (0..COLD_PROCESSES)
            .filter_map(|_| run_child(&format!("cold {name} {level}"))?.first().copied())
            .collect();
        if samples.is_empty() {
            continue;
        }
        samples.sort_by(f64::total_cmp);
        results.push((label.to_owned(), samples[samples.len() / 2], samples));
    }
    results
}

/// Prints the peak memory table of every one-shot case the filter selects.
pub fn peak_memory(filter: Option<&str>) {
    println!("\n## Peak memory of one-shot subdivision (MB above the input)\n");
    println!("| case | output | Weft peak | Weft peak/output | OSD peak | OSD peak/output |");
    println!("|---|---:|---:|---:|---:|---:|");
    for name in CASE_NAMES {
        for levels in 1..=3 {
            let label = format!("{name}-L{levels}");
            if filter.is_some_and(|f| !label.contains(f)) {
                continue;
            }
            let weft = run_child(&format!("peak {name} {levels} weft"));
            let osd = run_child(&format!("peak {name} {levels} osd"));
            let (Some(&[weft_peak, output]), Some(&[osd_peak, _])) =
                (weft.as_deref(), osd.as_deref())
            else {
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
