//! Reproducible pseudo-random numbers for tests (Marsaglia's xorshift),
//! with no dependency: the same stream on every machine.

/// 64-bit words from `seed` (not 0).
pub fn bits(mut state: u64) -> impl FnMut() -> u64 {
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    }
}

/// Numbers in [0, 1), 53 bits each, from `seed` (not 0).
pub fn uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut next = bits(seed);
    move || (next() >> 11) as f64 / (1u64 << 53) as f64
}
