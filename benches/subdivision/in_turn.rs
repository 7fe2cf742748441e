//! The target cases timed in turn: each round calls OpenSubdiv, Weft on one
//! thread and on all threads, and writes the huge-page floor, once each, so
//! that a slow spell of a shared machine, which criterion's case-after-case
//! medians can put on one side only, falls on all of them. Each timed call
//! comes right after an untimed call of its own, as each of criterion's
//! does: on a guest where memory handed back is slow to fault in again,
//! the call right after OpenSubdiv's (which frees a gigabyte) takes up to
//! several times as long, whichever call it is, and timing that would
//! measure the neighbour. Each ratio is the median of the rounds' own
//! ratios. The re-evaluation of the same cases is timed the same way:
//! Weft's refiner, the warm floor of its output and OpenSubdiv's stencils,
//! all on every thread but the floor.

use std::time::Instant;

/// Rounds timed; the untimed call before each timed one is its warm-up.
pub const ROUNDS: usize = 8;

/// The calls, by index: OpenSubdiv, Weft on one thread, Weft on all
/// threads, the huge-page floor.
pub const OSD: usize = 0;
pub const WEFT_ONE: usize = 1;
pub const WEFT_ALL: usize = 2;
pub const FLOOR_HUGE: usize = 3;

/// The re-evaluation's calls, by index: Weft's refiner evaluating on all
/// threads, the warm floor of its positions, OpenSubdiv's stencil table
/// updated on all threads.
pub const EVALUATE: usize = 0;
pub const WARM_FLOOR: usize = 1;
pub const STENCILS: usize = 2;

/// The rounds of one case: seconds per call, in the order of the calls'
/// indices ([`OSD`] to [`FLOOR_HUGE`], or [`EVALUATE`] to [`STENCILS`]).
pub struct InTurn<const N: usize = 4> {
    pub case: String,
    pub rounds: Vec<[f64; N]>,
}

impl<const N: usize> InTurn<N> {
    /// Times `calls` round after round, each right after an untimed call
    /// of itself.
    pub fn run(case: String, calls: [&dyn Fn(); N]) -> InTurn<N> {
        let rounds = (0..ROUNDS)
            .map(|_| {
                calls.map(|call| {
                    call();
                    let start = Instant::now();
                    call();
                    start.elapsed().as_secs_f64()
                })
            })
            .collect();
        InTurn { case, rounds }
    }

    fn median_of(&self, of: impl Fn(&[f64; N]) -> f64) -> f64 {
        let mut values: Vec<f64> = self.rounds.iter().map(of).collect();
        values.sort_by(f64::total_cmp);
        let middle = values.len() / 2;
        match values.len() % 2 {
            0 => (values[middle - 1] + values[middle]) / 2.0,
            _ => values[middle],
        }
    }

    /// The median time of call `i`.
    pub fn median(&self, i: usize) -> f64 {
        self.median_of(|round| round[i])
    }

    /// The median over the rounds of call `a`'s time over call `b`'s.
    pub fn ratio(&self, a: usize, b: usize) -> f64 {
        self.median_of(|round| round[a] / round[b])
    }

    /// Every round's times (ms), under a line naming the `calls`.
    fn print_rounds(&self, calls: &str) {
        println!("\n{}, every round (ms): {calls}\n", self.case);
        for round in &self.rounds {
            println!("- {}", round.map(|s| format!("{:.1}", s * 1e3)).join(", "));
        }
    }
}

/// The ratio of calls `a` and `b` in the rounds of `case` (see
/// [`InTurn::ratio`]), when `rows` holds that case.
pub fn ratio_in<const N: usize>(rows: &[InTurn<N>], case: &str, a: usize, b: usize) -> Option<f64> {
    rows.iter()
        .find(|row| row.case == case)
        .map(|row| row.ratio(a, b))
}

/// The table of the rounds' medians and ratios.
pub fn print(rows: &[InTurn], threads: usize) {
    if rows.is_empty() {
        return;
    }
    println!(
        "\n## In turn: the target cases, {ROUNDS} rounds of OSD, Weft 1t, Weft {threads}t and the \
         huge-page floor, each timed after an untimed call of its own (median ms; ratios: median \
         of the rounds' ratios)\n"
    );
    println!(
        "| case | OSD | Weft 1t | Weft {threads}t | floor huge | OSD/Weft 1t | OSD/Weft {threads}t \
         | Weft {threads}t/floor huge |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|");
    for row in rows {
        let ms = |i: usize| format!("{:.1}", row.median(i) * 1e3);
        println!(
            "| {} | {} | {} | {} | {} | {:.2}× | {:.2}× | {:.2}× |",
            row.case,
            ms(OSD),
            ms(WEFT_ONE),
            ms(WEFT_ALL),
            ms(FLOOR_HUGE),
            row.ratio(OSD, WEFT_ONE),
            row.ratio(OSD, WEFT_ALL),
            row.ratio(WEFT_ALL, FLOOR_HUGE)
        );
    }
    for row in rows {
        row.print_rounds(&format!("OSD, Weft 1t, Weft {threads}t, floor huge"));
    }
}

/// The table of the re-evaluation's rounds: medians and ratios.
pub fn print_reevaluation(rows: &[InTurn<3>], threads: usize) {
    if rows.is_empty() {
        return;
    }
    println!(
        "\n## In turn: re-evaluation at level 3, {ROUNDS} rounds of Weft's evaluate {threads}t, \
         the warm floor and OSD's stencils {threads}t, each timed after an untimed call of its \
         own (median ms; ratios: median of the rounds' ratios)\n"
    );
    println!(
        "| case | evaluate {threads}t | warm floor | OSD stencils {threads}t | evaluate/warm floor \
         | OSD stencils/evaluate |"
    );
    println!("|---|---:|---:|---:|---:|---:|");
    for row in rows {
        let ms = |i: usize| format!("{:.1}", row.median(i) * 1e3);
        println!(
            "| {} | {} | {} | {} | {:.2}× | {:.2}× |",
            row.case,
            ms(EVALUATE),
            ms(WARM_FLOOR),
            ms(STENCILS),
            row.ratio(EVALUATE, WARM_FLOOR),
            row.ratio(STENCILS, EVALUATE)
        );
    }
    for row in rows {
        row.print_rounds(&format!(
            "evaluate {threads}t, warm floor, OSD stencils {threads}t"
        ));
    }
}
