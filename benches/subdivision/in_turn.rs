//! The target cases timed in turn: each round calls OpenSubdiv, Weft on one
//! thread and on all threads, and writes the huge-page floor, once each, so
//! that a slow spell of a shared machine, which criterion's case-after-case
//! medians can put on one side only, falls on all of them. On a guest where
//! memory handed back is slow to fault in again, the call right after
//! OpenSubdiv's (which frees a gigabyte) pays for it, so the rounds' orders
//! are chosen so that, over the whole sequence of calls, each call follows
//! each other one equally often ([`ORDERS`]). Each ratio is the median of
//! the rounds' own ratios.

use std::time::Instant;

/// The orders of the rounds, repeated [`REPEATS`] times after a warm-up in
/// [`WARM_UP`]'s order. Each call follows each other one twice in the calls
/// of these six rounds, the first call of the first round counted after the
/// last of the sixth (which the warm-up, ending with the same call, makes
/// true of the first repeat as well).
const ORDERS: [[usize; 4]; 6] = [
    [OSD, WEFT_ONE, WEFT_ALL, FLOOR_HUGE],
    [OSD, WEFT_ONE, WEFT_ALL, FLOOR_HUGE],
    [OSD, WEFT_ALL, WEFT_ONE, FLOOR_HUGE],
    [WEFT_ONE, OSD, FLOOR_HUGE, WEFT_ALL],
    [OSD, WEFT_ALL, WEFT_ONE, FLOOR_HUGE],
    [WEFT_ONE, OSD, FLOOR_HUGE, WEFT_ALL],
];

/// The warm-up's order: it ends with the last round's last call.
const WARM_UP: [usize; 4] = [OSD, WEFT_ONE, FLOOR_HUGE, WEFT_ALL];

/// How many times the rounds of [`ORDERS`] are timed.
const REPEATS: usize = 2;

/// Rounds timed: each call once in each.
pub const ROUNDS: usize = ORDERS.len() * REPEATS;

/// The calls, by index: OpenSubdiv, Weft on one thread, Weft on all
/// threads, the huge-page floor.
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
        assert!(follows_evenly(), "the rounds' orders are not balanced");
        for i in WARM_UP {
            calls[i]();
        }
        let rounds = ORDERS
            .iter()
            .cycle()
            .take(ROUNDS)
            .map(|order| {
                let mut seconds = [0.0; 4];
                for &i in order {
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

/// Whether, in the calls of [`ORDERS`] taken as a cycle and after the
/// warm-up, each call follows each other one equally often, and every
/// round calls each once.
fn follows_evenly() -> bool {
    let calls: Vec<usize> = ORDERS.iter().flatten().copied().collect();
    let mut follows = [[0usize; 4]; 4];
    for (k, &call) in calls.iter().enumerate() {
        let before = calls[(k + calls.len() - 1) % calls.len()];
        follows[before][call] += 1;
    }
    let each = calls.len() / 12;
    let rounds_whole = ORDERS.iter().all(|order| {
        let mut seen = [false; 4];
        order.iter().for_each(|&i| seen[i] = true);
        seen.iter().all(|&s| s)
    });
    let balanced = (0..4).all(|a| (0..4).all(|b| a == b || follows[a][b] == each));
    rounds_whole && balanced && WARM_UP.last() == calls.last()
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
