//! How many threads share the work: rayon's own count (one per CPU the
//! process may use, a container's quota included), or `RAYON_NUM_THREADS`'s
//! (and rayon's older `RAYON_RS_NUM_CPUS`'s), which is refused when it is
//! not a whole number from 0 to [`MAX_THREADS`]: rayon would start as many
//! threads as it says (100000 took longer than 30 s to start) or, given a
//! word, quietly take its own count.

use super::UsageError;

/// The most threads a user may ask for: more than any machine this runs
/// on has CPUs for, few enough to start in a few milliseconds.
pub const MAX_THREADS: usize = 256;

/// The variables rayon reads its count from, in its order.
const VARIABLES: [&str; 2] = ["RAYON_NUM_THREADS", "RAYON_RS_NUM_CPUS"];

/// Refuses a thread count rayon should not be left to read.
pub fn check_thread_count() -> Result<(), UsageError> {
    for variable in VARIABLES {
        if let Some(value) = std::env::var_os(variable) {
            let text = value.to_string_lossy();
            if !text.parse().is_ok_and(|n: usize| n <= MAX_THREADS) {
                return Err(UsageError::BadThreadCount {
                    variable,
                    value: text.chars().take(40).collect(),
                });
            }
        }
    }
    Ok(())
}
