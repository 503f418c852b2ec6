//! rayon's worker threads, counted without std's cgroup reads.

/// Makes the calling thread one of a pool of a thread for each CPU this
/// process may run on (its affinity mask: one system call), so that its
/// parallel iterators run there, unless `RAYON_NUM_THREADS` sets the count
/// (rayon's own pool then serves, as it reads it). Once per process.
///
/// Against rayon's global pool, started when first used:
/// - its count, `std::thread::available_parallelism`, also reads the
///   cgroup's CPU quota (seven system calls more: ~50 µs of a 3 ms surface
///   on this project's machine). A quota below the mask (a container given
///   part of its CPUs' time) is not seen here: the threads share the time
///   it allows, the results the same (no result depends on the number of
///   threads);
/// - the calling thread works too: one thread fewer to start, none to wake
///   when the work is done;
/// - the other threads are not waited for (`build_global` waits until each
///   has started, ~0.1 ms here): they join the work as they come up.
///
/// The pool is kept for the process's life (rayon's global one is too).
pub fn start_pool() {
    static POOL: std::sync::OnceLock<Option<rayon::ThreadPool>> = std::sync::OnceLock::new();
    POOL.get_or_init(|| {
        if std::env::var_os("RAYON_NUM_THREADS").is_some() {
            return None;
        }
        // An error (no thread could start, or this one is in a pool
        // already) leaves the work to the pool it would have gone to.
        rayon::ThreadPoolBuilder::new()
            .num_threads(cpus_allowed()?)
            .use_current_thread()
            .build()
            .ok()
    });
}

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
