//! Repeatable numbers for tests that draw many cases.

/// Words from `seed` (xorshift; the seed must not be 0).
pub(crate) fn words(mut state: u64) -> impl FnMut() -> u64 {
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    }
}

/// Numbers in [0, 1) from `seed`, the top 53 bits of [`words`].
pub(crate) fn units(seed: u64) -> impl FnMut() -> f64 {
    let mut next = words(seed);
    move || (next() >> 11) as f64 / (1u64 << 53) as f64
}
