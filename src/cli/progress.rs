//! A progress line on stderr for work that may take more than a second
//! (sweeps, surfaces, figures, Table II, the benchmark): shown only when
//! stderr is a terminal, from the first second on, rewritten in place (`\r`)
//! ten times a second, and erased when the work ends, so that the output and
//! any error line that follows stay clean. Nothing is written when stderr is
//! a file or a pipe.

use std::io::{IsTerminal as _, Write};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::time::{Duration, Instant};

/// How long work runs before its progress is shown.
const DELAY: Duration = Duration::from_secs(1);
/// How often the line is rewritten.
const EVERY: Duration = Duration::from_millis(100);

/// What a piece of work has done so far: `tick` once per step.
pub struct Progress {
    done: AtomicUsize,
}

impl Progress {
    /// One more step done (a point of a sweep, a cell of a surface).
    pub fn tick(&self) {
        self.done.fetch_add(1, Ordering::Relaxed);
    }

    fn done(&self) -> usize {
        self.done.load(Ordering::Relaxed)
    }
}

/// A total of steps not known in advance (a stream's rows): the line counts
/// them without a total.
pub const UNCOUNTED: usize = usize::MAX;

/// What the line says about the work: "sweep" and, if the steps are
/// counted, how many there are and what they are ("points").
#[derive(Clone, Copy)]
pub struct Work<'a> {
    pub what: &'a str,
    /// The steps and their name; `None`: only the time is shown.
    pub steps: Option<(usize, &'a str)>,
}

impl Work<'_> {
    /// "homerun: sweep 3 of 11 points, 2.1 s"
    fn line(&self, done: usize, elapsed: Duration) -> String {
        let seconds = elapsed.as_secs_f64();
        match self.steps {
            Some((UNCOUNTED, unit)) => {
                format!("homerun: {} {done} {unit}, {seconds:.1} s", self.what)
            }
            Some((total, unit)) => {
                format!(
                    "homerun: {} {done} of {total} {unit}, {seconds:.1} s",
                    self.what
                )
            }
            None => format!("homerun: {}, {seconds:.1} s", self.what),
        }
    }
}

/// Runs `work` on this thread, showing its progress on stderr if stderr is
/// a terminal.
pub fn run<T>(work: Work, job: impl FnOnce(&Progress) -> T) -> T {
    let mut stderr = std::io::stderr();
    let sink: Option<&mut (dyn Write + Send)> = if stderr.is_terminal() {
        Some(&mut stderr)
    } else {
        None
    };
    run_to(work, sink, DELAY, job)
}

/// As [`run`], writing to `sink` (if any) once `delay` has passed.
fn run_to<T>(
    work: Work,
    sink: Option<&mut (dyn Write + Send)>,
    delay: Duration,
    job: impl FnOnce(&Progress) -> T,
) -> T {
    let progress = Progress {
        done: AtomicUsize::new(0),
    };
    let Some(sink) = sink else {
        return job(&progress);
    };
    let (finished, wait) = mpsc::channel::<()>();
    std::thread::scope(|scope| {
        let progress = &progress;
        scope.spawn(move || {
            let start = Instant::now();
            if wait.recv_timeout(delay) != Err(RecvTimeoutError::Timeout) {
                return;
            }
            loop {
                // A failed write (stderr closed) only loses the line.
                let line = work.line(progress.done(), start.elapsed());
                let _ = write!(sink, "\r{line}\x1b[K");
                let _ = sink.flush();
                if wait.recv_timeout(EVERY) != Err(RecvTimeoutError::Timeout) {
                    break;
                }
            }
            let _ = write!(sink, "\r\x1b[K");
            let _ = sink.flush();
        });
        let result = job(progress);
        drop(finished);
        result
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_line_counts_steps_and_is_erased_at_the_end() {
        let mut sink = Vec::new();
        let work = Work {
            what: "sweep",
            steps: Some((3, "points")),
        };
        let result = run_to(work, Some(&mut sink), Duration::ZERO, |p| {
            for _ in 0..3 {
                std::thread::sleep(Duration::from_millis(120));
                p.tick();
            }
            std::thread::sleep(Duration::from_millis(120));
            42
        });
        assert_eq!(result, 42);
        let text = String::from_utf8(sink).unwrap();
        assert!(
            text.starts_with("\rhomerun: sweep 0 of 3 points, 0.0 s\x1b[K"),
            "{text:?}"
        );
        assert!(text.contains("homerun: sweep 3 of 3 points, "), "{text:?}");
        assert!(text.ends_with("\x1b[K\r\x1b[K"), "{text:?}");
        assert!(!text.contains('\n'), "{text:?}");
    }

    #[test]
    fn quick_work_and_a_pipe_show_nothing() {
        let mut sink = Vec::new();
        let work = Work {
            what: "table2",
            steps: None,
        };
        assert_eq!(run_to(work, Some(&mut sink), DELAY, |_| 7), 7);
        assert!(sink.is_empty());
        assert_eq!(run_to(work, None, Duration::ZERO, |p| p.done()), 0);
        assert_eq!(
            work.line(0, Duration::from_millis(2345)),
            "homerun: table2, 2.3 s"
        );
    }
}
