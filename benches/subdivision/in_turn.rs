//! The target cases timed in turn: each round calls OpenSubdiv, Weft on one
//! thread and on all threads, and writes the huge-page floor, once each, so
//! that a slow spell of a shared machine, which criterion's case-after-case
//! medians can put on one side only, falls on all of them. Each round
//! starts one call later than the round before: on a guest where memory
//! handed back is slow to fault in again, the call after OpenSubdiv's
//! (which frees a gigabyte) pays for it, and this way each call follows it
//! in as many rounds. Each ratio is the median of the rounds' own ratios.

use std::time::Instant;

/// Rounds timed, after one of warm-up: each call first in two.
pub const ROUNDS: usize = 8;

/// What a round calls, in this order: OpenSubdiv, Weft on one thread,
/// Weft on all threads, the huge-page floor.
pub const OSD: usize = 0;
pub const WEFT_ONE: usize = 1;
pub const WEFT_ALL: usize = 2;
pub const FLOOR_HUGE: usize = 3;

/// The rounds of one case: seconds per call, in the order of [`OSD`] to [`FLOOR_HUGE`].
pub struct InTurn {
    pub case: String,
    pub rounds: Vec<[f64; 4]>,
}

impl InTurn {
    /// Times `calls` (in the order of [`OSD`] to [`FLOOR_HUGE`]) round after round.
    pub fn run(case: String, calls: [&dyn Fn(); 4]) -> InTurn {
        for call in calls {
            call();
        }
        let rounds = (0..ROUNDS)
            .map(|round| {
                let mut seconds = [0.0; 4];
                for k in 0..4 {
                    let i = (round + k) % 4;
                    let start = Instant::now();
                    calls[i]();
                    seconds[i] = start.elapsed().as_secs_f64();
                }
                seconds
            })
            .collect();
        InTurn { case, rounds }
    }

    fn median_of(&self, of: impl Fn(&[f64; 4]) -> f64) -> f64 {
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
}

/// The table of the rounds' medians and ratios.
pub fn print(rows: &[InTurn], threads: usize) {
    if rows.is_empty() {
        return;
    }
    println!(
        "\n## In turn: the target cases, {ROUNDS} rounds of OSD, Weft 1t, Weft {threads}t and the \
         huge-page floor (median ms; ratios: median of the rounds' ratios)\n"
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
}
