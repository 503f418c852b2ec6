//! rayon's worker threads, counted without std's cgroup reads.

/// Starts rayon's global pool with a thread for each CPU this process may
/// run on (its affinity mask: one system call), the calling thread one of
/// them (one thread fewer to start, none to wake when the work is done:
/// `surface --grid 2x2` 0.88 → 0.79 ms of wall, 0.18 ms less CPU), unless
/// `RAYON_NUM_THREADS`
/// sets the count (rayon reads it) or the pool runs already. Left to
/// itself, rayon counts them with `std::thread::available_parallelism`,
/// which also reads the cgroup's CPU quota (seven system calls more: ~50 µs
/// of a 3 ms surface on this project's machine). A quota below the mask (a
/// container given part of its CPUs' time) is then not seen: the threads
/// share the time it allows, the results the same (no result depends on
/// the number of threads).
///
/// `build_global` waits until the new thread has started (~0.1 ms). A pool
/// that did not wait (`build`, kept for the process) started faster but
/// flew slower: on this machine a new thread starts on its parent's CPU,
/// and runs only when the parent sleeps or the scheduler moves it (~2 ms,
/// measured: 200 of 200 starts); waiting, the parent is woken onto the
/// idle CPU. `surface --grid 64x64` took 3.6–4.0 ms (p10, median) that way
/// against 3.3–3.4 ms.
pub fn start_pool() {
    static STARTED: std::sync::Once = std::sync::Once::new();
    STARTED.call_once(|| {
        if std::env::var_os("RAYON_NUM_THREADS").is_some() {
            return;
        }
        if let Some(count) = cpus_allowed() {
            one_heap();
            // An error only says the pool runs already.
            let _ = rayon::ThreadPoolBuilder::new()
                .num_threads(count)
                .use_current_thread()
                .build_global();
        }
    });
}

/// New threads' memory from the one heap: glibc gives each new thread a
/// heap of its own (a 64 MB reservation, its first pages touched) on its
/// first allocation, which the pool's start waits on (`surface --grid 2x2`
/// 0.77 → 0.73 ms of wall). The pool's few allocations a chunk hardly
/// contend for it.
#[cfg(all(target_os = "linux", target_env = "gnu"))]
fn one_heap() {
    // SAFETY: glibc's documented tunable; mallopt takes the heap's lock, so
    // other threads may allocate meanwhile (those with a heap keep it).
    unsafe { libc::mallopt(libc::M_ARENA_MAX, 1) };
}

#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
fn one_heap() {}

/// The CPUs in this process's affinity mask (`None` where it cannot be
/// read: more than `cpu_set_t` holds, or not Linux).
#[cfg(target_os = "linux")]
fn cpus_allowed() -> Option<usize> {
    // SAFETY: an all-zero cpu_set_t is an empty set.
    let mut set: libc::cpu_set_t = unsafe { std::mem::zeroed() };
    let size = std::mem::size_of::<libc::cpu_set_t>();
    // SAFETY: `set` is a cpu_set_t of `size` bytes, written by the call.
    if unsafe { libc::sched_getaffinity(0, size, &mut set) } != 0 {
        return None;
    }
    // SAFETY: `set` is an initialised cpu_set_t.
    let count = unsafe { libc::CPU_COUNT(&set) };
    usize::try_from(count).ok().filter(|&n| n > 0)
}

#[cfg(not(target_os = "linux"))]
fn cpus_allowed() -> Option<usize> {
    None
}

#[cfg(test)]
mod tests {
    #[test]
    #[cfg(target_os = "linux")]
    fn the_cpus_allowed_are_std_s_count_without_a_quota() {
        // std's count is the mask's, or fewer under a cgroup quota.
        let std_count = std::thread::available_parallelism().map_or(1, |n| n.get());
        let allowed = super::cpus_allowed().expect("an affinity mask");
        assert!(allowed >= std_count, "{allowed} against {std_count}");
    }
}
