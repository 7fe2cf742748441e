//! The tables printed after a run: medians read back from criterion's
//! estimates, ratios, and the targets with what was measured.

use std::path::PathBuf;
use std::time::Duration;

use crate::in_turn::{
    ratio_in, InTurn, EVALUATE, FLOOR_HUGE, OSD, STENCILS, WARM_FLOOR, WEFT_ALL, WEFT_ONE,
};
use crate::{CASE_NAMES, GROUP, LEVELS, REEVALUATED};

/// Timings measured once, outside criterion, kept for the summary.
pub fn record_once(case: &str, what: &str, time: Duration) {
    println!(
        "{GROUP}/{case}/{what}: {:.2} s (timed once)",
        time.as_secs_f64()
    );
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

fn ms(t: Option<f64>) -> String {
    t.map_or("–".to_owned(), |t| format!("{:.1}", t * 1e3))
}

fn ratio(a: Option<f64>, b: Option<f64>) -> String {
    a.zip(b)
        .map_or("–".to_owned(), |(a, b)| format!("{:.2}×", a / b))
}

/// One-shot subdivision beside OpenSubdiv, OpenMesh and the floors.
pub fn one_shot(threads: usize) {
    let all = format!("weft-{threads}t");
    println!("\n## One-shot through the C ABI (median ms; ratio = other / Weft)\n");
    println!(
        "| case | Weft 1t | Weft {threads}t | OSD | OpenMesh | OSD/Weft 1t | OSD/Weft {threads}t \
         | OM/Weft {threads}t | floor 4 KiB | floor huge | floor warm | Weft {threads}t/floor huge |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for name in CASE_NAMES {
        for levels in LEVELS {
            let label = format!("{name}-L{levels}");
            let get = |what: &str| median(&label, what);
            let (w1, wn, osd, om) = (get("weft-1t"), get(&all), get("osd"), get("om"));
            if w1.is_none() && wn.is_none() && osd.is_none() && om.is_none() {
                continue;
            }
            let huge = get("floor-huge");
            println!(
                "| {label} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
                ms(w1),
                ms(wn),
                ms(osd),
                ms(om),
                ratio(osd, w1),
                ratio(osd, wn),
                ratio(om, wn),
                ms(get("floor-4k")),
                ms(huge),
                ms(get("floor-warm")),
                ratio(wn, huge),
            );
        }
    }
}

/// One-shot subdivision into a host's own buffers (`weft_subdivide_into`),
/// beside the calls that allocate and the warm floor.
pub fn into_buffers(threads: usize) {
    let all = format!("weft-{threads}t");
    let into_all = format!("into-{threads}t");
    println!("\n## One-shot into the host's buffers (`weft_subdivide_into`, median ms)\n");
    println!(
        "| case | into 1t | into {threads}t | Weft {threads}t (allocating) | OSD | OSD/into 1t \
         | OSD/into {threads}t | floor warm | into {threads}t/floor warm |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    for name in CASE_NAMES {
        for levels in LEVELS {
            let label = format!("{name}-L{levels}");
            let get = |what: &str| median(&label, what);
            let (i1, i_all) = (get("into-1t"), get(&into_all));
            if i1.is_none() && i_all.is_none() {
                continue;
            }
            let (osd, warm) = (get("osd"), get("floor-warm"));
            println!(
                "| {label} | {} | {} | {} | {} | {} | {} | {} | {} |",
                ms(i1),
                ms(i_all),
                ms(get(&all)),
                ms(osd),
                ratio(osd, i1),
                ratio(osd, i_all),
                ms(warm),
                ratio(i_all, warm),
            );
        }
    }
}

/// OpenSubdiv's stencils on `threads` threads, the faster of its two ways
/// there: `UpdateValues` over contiguous ranges, and `Osd::OmpEvaluator`.
fn osd_stencils_on_threads(case: &str, threads: usize) -> Option<f64> {
    let get = |what: &str| median(case, what);
    let (spread, omp) = (
        get(&format!("stencil-update-{threads}t")),
        get(&format!("stencil-omp-{threads}t")),
    );
    match (spread, omp) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// Re-evaluation at level 3 beside OpenSubdiv's stencils.
pub fn reevaluation(threads: usize) {
    println!("\n## Re-evaluation at level 3 (median ms)\n");
    println!(
        "| case | refiner build {threads}t | one-shot {threads}t | evaluate 1t | evaluate {threads}t \
         | warm floor | evaluate {threads}t/floor | OSD UpdateValues 1t | OSD UpdateValues {threads}t \
         | OSD OmpEvaluator 1t | OSD OmpEvaluator {threads}t | OSD 1t/evaluate 1t \
         | OSD {threads}t/evaluate {threads}t | stencil build (once) |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for name in REEVALUATED {
        let label = format!("{name}-L3");
        let get = |what: &str| median(&label, what);
        let build = get(&format!("refiner-build-{threads}t"));
        let evaluate = get(&format!("refiner-evaluate-{threads}t"));
        if build.is_none() && evaluate.is_none() {
            continue;
        }
        let floor = get("evaluate-floor-warm");
        let (evaluate_one, update_one) = (get("refiner-evaluate-1t"), get("stencil-update"));
        println!(
            "| {label} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            ms(build),
            ms(get(&format!("weft-{threads}t"))),
            ms(evaluate_one),
            ms(evaluate),
            ms(floor),
            ratio(evaluate, floor),
            ms(update_one),
            ms(get(&format!("stencil-update-{threads}t"))),
            ms(get("stencil-omp-1t")),
            ms(get(&format!("stencil-omp-{threads}t"))),
            ratio(update_one, evaluate_one),
            ratio(osd_stencils_on_threads(&label, threads), evaluate),
            get("stencil-build").map_or("–".to_owned(), |t| format!("{t:.2} s")),
        );
    }
    println!(
        "\nOSD {threads}t is the faster of OpenSubdiv's two ways on {threads} threads: \
         `UpdateValues` with each thread on a contiguous range of the stencils, \
         and `Osd::OmpEvaluator`."
    );
}

/// The first call in fresh processes beside the steady state.
pub fn cold(cold: &[(String, f64, Vec<f64>)], threads: usize) {
    println!("\n## First call in a fresh process ({threads} threads)\n");
    println!("| case | cold median | cold samples | steady median | cold/steady |");
    println!("|---|---:|---|---:|---:|");
    for (label, median_cold, samples) in cold {
        let steady = median(label, &format!("weft-{threads}t"));
        let samples: Vec<String> = samples.iter().map(|s| format!("{:.0}", s * 1e3)).collect();
        println!(
            "| {label} | {} | {} | {} | {} |",
            ms(Some(*median_cold)),
            samples.join(", "),
            ms(steady),
            ratio(Some(*median_cold), steady)
        );
    }
}

/// One target: what it compares, the measured ratio, and whether it holds.
/// A target's row: measured from criterion's medians and, where the case
/// was timed in turn, from the rounds' ratios; met when both meet it.
fn target(what: &str, measured: Option<f64>, in_turn: Option<f64>, bound: f64, at_least: bool) {
    let meets = |m: f64| (m >= bound) == at_least;
    let shown = |m: Option<f64>| m.map_or("–".to_owned(), |m| format!("{m:.2}×"));
    let met = match (measured, in_turn) {
        (None, None) => "not run",
        (Some(a), Some(b)) if meets(a) && meets(b) => "yes",
        (Some(a), Some(b)) if meets(a) || meets(b) => "in one reading of two",
        (Some(m), None) | (None, Some(m)) if meets(m) => "yes",
        _ => "no",
    };
    let sign = if at_least { "≥" } else { "≤" };
    println!(
        "| {what} | {sign} {bound}× | {} | {} | {met} |",
        shown(measured),
        shown(in_turn)
    );
}

/// The hard targets of the speed work, read from this run.
pub fn targets(
    threads: usize,
    cold: &[(String, f64, Vec<f64>)],
    in_turn: &[InTurn],
    reevaluated: &[InTurn<3>],
) {
    let all = format!("weft-{threads}t");
    let get = |case: &str, what: &str| median(case, what);
    let over = |a: Option<f64>, b: Option<f64>| a.zip(b).map(|(a, b)| a / b);
    let (osd, one, both, floor) = (OSD, WEFT_ONE, WEFT_ALL, FLOOR_HUGE);
    let turn = |case: &str, a: usize, b: usize| ratio_in(in_turn, case, a, b);
    let again = |case: &str, a: usize, b: usize| ratio_in(reevaluated, case, a, b);
    println!("\n## Targets (this run)\n");
    println!("| target | bound | measured (criterion medians) | measured (in turn) | met |");
    println!("|---|---|---:|---:|---|");
    let (cc, lp) = ("cc-100k-L3", "loop-100k-L3");
    target(
        &format!("CC L3 100k: OSD / Weft {threads}t"),
        over(get(cc, "osd"), get(cc, &all)),
        turn(cc, osd, both),
        8.0,
        true,
    );
    target(
        "CC L3 100k: OSD / Weft 1t",
        over(get(cc, "osd"), get(cc, "weft-1t")),
        turn(cc, osd, one),
        4.0,
        true,
    );
    target(
        &format!("Loop L3 100k: OSD / Weft {threads}t"),
        over(get(lp, "osd"), get(lp, &all)),
        turn(lp, osd, both),
        6.0,
        true,
    );
    for case in [cc, lp] {
        target(
            &format!("{case}: Weft {threads}t / huge-page fresh floor (1t)"),
            over(get(case, &all), get(case, "floor-huge")),
            turn(case, both, floor),
            1.5,
            false,
        );
        let evaluate = get(case, &format!("refiner-evaluate-{threads}t"));
        target(
            &format!("{case}: evaluate {threads}t / warm floor"),
            over(evaluate, get(case, "evaluate-floor-warm")),
            again(case, EVALUATE, WARM_FLOOR),
            2.0,
            false,
        );
        target(
            &format!("{case}: OSD stencils {threads}t / evaluate {threads}t"),
            over(osd_stencils_on_threads(case, threads), evaluate),
            again(case, STENCILS, EVALUATE),
            3.0,
            true,
        );
        let cold_median = cold.iter().find(|c| c.0 == case).map(|c| c.1);
        target(
            &format!("{case}: cold first call / steady"),
            over(cold_median, get(case, &all)),
            None,
            1.5,
            false,
        );
    }
}
