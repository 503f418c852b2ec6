//! Dormand–Prince 5(4) with step-size control and dense output, after Hairer,
//! Nørsett & Wanner's DOPRI5.
//!
//! Written by hand rather than taken from a crate because the flight needs
//! three things together that the Rust ODE crates do not offer in one place:
//! stack-only state (`SVector`, no allocation per step), an observer that
//! sees each step's continuous extension (to locate the landing and apex by
//! root finding, and to sample a drawn trajectory), and a way to cut a step
//! short at a corner of the right-hand side (the drag curve's kinks) so that
//! no step integrates across one.

use nalgebra::SVector;

mod controller;
mod dense;
mod fixed;
pub mod lanes;
pub mod stages;
mod tableau;

use controller::{LOG2_ERROR_FLOOR, accepted_growth, initial_step, log2_error, rejected_growth};
pub use dense::{BuildDense, DenseStep, Step};
pub use fixed::integrate_fixed;
use stages::{dense_c5, error_squared, inverse_scales, stages};

pub type State<const N: usize> = SVector<f64, N>;

/// Local error tolerance: each component must satisfy
/// |err| ≤ absolute + relative·|y|, in Hairer's root-mean-square norm.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Tolerance {
    pub relative: f64,
    pub absolute: f64,
}

impl Tolerance {
    /// The same number for both.
    pub const fn uniform(tol: f64) -> Self {
        Tolerance {
            relative: tol,
            absolute: tol,
        }
    }
}

/// Work done by one integration, and the first step it found.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct Stats {
    /// Right-hand-side evaluations.
    pub evaluations: u32,
    pub accepted: u32,
    pub rejected: u32,
    /// The step the controller chose after the first accepted one (0 if
    /// none was): what it found a step near the start may be, so a good
    /// first step to try for a neighbouring problem
    /// ([`Settings::initial_step`]).
    pub first_step: f64,
}

/// Why an integration ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// The observer asked to stop (an event was found).
    Stopped,
    /// `t_end` was reached.
    ReachedEnd,
    /// `max_steps` steps were tried.
    StepLimit,
    /// The step size fell below what the time's precision can resolve.
    StepTooSmall,
}

/// What the observer wants after seeing an accepted step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Control {
    Continue,
    Stop,
    /// End this step early at the given time (inside the step, read off the
    /// continuous extension) and go on from there with a fresh derivative:
    /// the right-hand side has changed there (the flight has crossed one of
    /// the drag curve's kinks and switched to the formula on its other side).
    /// The observer should have shown itself the step truncated at that time
    /// ([`Step::truncated`]).
    RestartAt(f64),
    /// Go on, ending the next step no later than the given time: the
    /// observer expects an event (a kink, the landing) a little before it,
    /// so that the step that meets the event wastes little beyond it.
    EndNextBy(f64),
}

/// The default bound on steps: no flight needs more than a few thousand, and
/// a bound means no input can hang a caller.
pub const MAX_STEPS: u32 = 100_000;

/// How to integrate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub tolerance: Tolerance,
    /// Upper bound on tried steps, so that no input can hang a caller.
    pub max_steps: u32,
    /// First step to try; `None` picks one (Hairer's `hinit`, two
    /// evaluations). A neighbouring problem's [`Stats::first_step`] saves
    /// them, and usually a rejection too.
    pub initial_step: Option<f64>,
    pub max_step: f64,
}

impl Settings {
    pub fn new(tolerance: Tolerance) -> Self {
        Settings {
            tolerance,
            max_steps: MAX_STEPS,
            initial_step: None,
            max_step: f64::INFINITY,
        }
    }
}

/// Whether a step of size `h` at time `t` is too small to resolve.
#[inline(always)]
pub(crate) fn too_small(h: f64, t: f64) -> bool {
    h <= 16.0 * f64::EPSILON * t.abs().max(1.0)
}

/// Integrates y' = f(t, y) from (t0, y0) toward `t_end`, showing each
/// accepted step to `observe`. Never allocates.
pub fn integrate<const N: usize, F, O>(
    mut f: F,
    t0: f64,
    y0: State<N>,
    t_end: f64,
    settings: &Settings,
    mut observe: O,
) -> (Outcome, Stats)
where
    F: FnMut(f64, &State<N>) -> State<N>,
    O: FnMut(&Step<N>) -> Control,
{
    let tol = settings.tolerance;
    let mut stats = Stats::default();
    let mut t = t0;
    let mut y = y0;
    let mut k1 = f(t, &y);
    stats.evaluations += 1;
    let mut h = match settings.initial_step {
        Some(h) if h > 0.0 => h,
        _ => initial_step(&mut f, t, &y, &k1, settings, &mut stats),
    };
    // log₂ of the last accepted step's error (floored at 1e-4), for the PI
    // controller.
    let mut previous_log2_error = LOG2_ERROR_FLOOR;
    let mut last_rejected = false;

    loop {
        if stats.accepted + stats.rejected >= settings.max_steps {
            return (Outcome::StepLimit, stats);
        }
        if t >= t_end {
            return (Outcome::ReachedEnd, stats);
        }
        h = h.min(settings.max_step).min(t_end - t);
        if too_small(h, t) {
            return (Outcome::StepTooSmall, stats);
        }

        let s = stages(&mut f, t, &y, &k1, h);
        stats.evaluations += 6;
        let inverse = inverse_scales::<f64, _, N>(&y, &s.y1, tol.relative, tol.absolute);
        let error_squared = error_squared(&k1, &s, h, &inverse);

        if error_squared <= 1.0 {
            let log2_error = log2_error(error_squared);
            let mut h_next = h * accepted_growth(log2_error, previous_log2_error);
            if last_rejected {
                h_next = h_next.min(h);
            }
            if stats.accepted == 0 {
                stats.first_step = h_next;
            }
            stats.accepted += 1;
            previous_log2_error = log2_error.max(LOG2_ERROR_FLOOR);
            last_rejected = false;
            let k7 = s.k[5];
            let build = || DenseStep::new(t, h, (y, s.y1), (&k1, &k7), dense_c5(&k1, &s, h));
            let t1 = t + h;
            let step = Step::new((t, t1), (y, s.y1), &build);
            let control = observe(&step);
            if matches!(control, Control::Stop) {
                return (Outcome::Stopped, stats);
            }
            // Where to go on from: inside the step after a switch (one
            // evaluation, where a redone step would cost six), else its end.
            let restart = step
                .restart_time(control)
                .map(|t_restart| (t_restart, step.at(t_restart)));
            h = h_next;
            if let Some((t_restart, y_restart)) = restart {
                t = t_restart;
                y = y_restart;
                k1 = f(t, &y);
                stats.evaluations += 1;
            } else {
                t = t1;
                y = s.y1;
                k1 = k7;
                if let Control::EndNextBy(t_end_next) = control
                    && t_end_next > t
                {
                    h = h.min(t_end_next - t);
                }
            }
        } else {
            // Reject: shrink, never below a fifth.
            stats.rejected += 1;
            h *= rejected_growth(log2_error(error_squared));
            last_rejected = true;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn harmonic_oscillator_to_tolerance() {
        let f = |_t: f64, y: &State<2>| State::<2>::new(y[1], -y[0]);
        let mut end = State::<2>::zeros();
        let settings = Settings::new(Tolerance::uniform(1e-10));
        let (outcome, stats) = integrate(f, 0.0, State::<2>::new(1.0, 0.0), 10.0, &settings, |s| {
            end = s.y1;
            Control::Continue
        });
        assert_eq!(outcome, Outcome::ReachedEnd);
        assert!((end[0] - 10f64.cos()).abs() < 1e-8, "{end}");
        assert!(stats.accepted < 400);
    }

    #[test]
    fn dense_output_is_fourth_order_accurate() {
        let f = |_t: f64, y: &State<1>| State::<1>::new(y[0]);
        let settings = Settings::new(Tolerance::uniform(1e-12));
        let mut worst: f64 = 0.0;
        integrate(f, 0.0, State::<1>::new(1.0), 2.0, &settings, |s| {
            let mid = 0.5 * (s.t0 + s.t1);
            worst = worst.max((s.at(mid)[0] - mid.exp()).abs());
            Control::Continue
        });
        assert!(worst < 1e-9, "{worst}");
    }

    #[test]
    fn fixed_step_rk4_is_fourth_order() {
        let f = |_t: f64, y: &State<2>| State::<2>::new(y[1], -y[0]);
        let error = |h: f64| {
            let mut end = State::<2>::zeros();
            integrate_fixed(f, 0.0, State::<2>::new(1.0, 0.0), 10.0, h, 100_000, |s| {
                end = s.y1;
                Control::Continue
            });
            (end[0] - 10f64.cos()).abs()
        };
        let ratio = error(0.02) / error(0.01);
        assert!((ratio - 16.0).abs() < 1.0, "{ratio}");
    }

    #[test]
    fn a_step_builds_its_extension_once_and_a_cut_step_borrows_it() {
        let builds = std::cell::Cell::new(0);
        let (y0, y1) = (State::<2>::new(1.0, 0.0), State::<2>::new(0.995, -0.0998));
        let (k0, k1) = (State::<2>::new(0.0, -1.0), State::<2>::new(-0.0998, -0.995));
        let build = || {
            builds.set(builds.get() + 1);
            DenseStep::new(0.0, 0.1, (y0, y1), (&k0, &k1), State::zeros())
        };
        let step = Step::new((0.0, 0.1), (y0, y1), &build);
        // Its ends need no extension.
        assert_eq!((step.y0, step.y1, builds.get()), (y0, y1, 0));
        let middle = step.at(0.05);
        let cut = step.truncated(0.05);
        assert_eq!((cut.t0, cut.t1, cut.y0, cut.y1), (0.0, 0.05, y0, middle));
        // The cut step reads the same polynomial, to the bit.
        assert_eq!(cut.at(0.02), step.at(0.02));
        assert_eq!(cut.slope_at(0.03), step.slope_at(0.03));
        assert_eq!(builds.get(), 1);
        // A cubic Hermite through the ends with their slopes.
        assert!((step.slope_at(0.0) - k0).norm() < 1e-14);
        assert!((step.slope_at(0.1) - k1).norm() < 1e-12);
    }

    #[test]
    fn slope_is_the_derivative_of_the_extension() {
        let f = |_t: f64, y: &State<2>| State::<2>::new(y[1], -y[0]);
        let settings = Settings::new(Tolerance::uniform(1e-6));
        integrate(f, 0.0, State::<2>::new(1.0, 0.0), 3.0, &settings, |s| {
            for t in [s.t0, 0.3 * s.t0 + 0.7 * s.t1, s.t1] {
                let d = 1e-6 * (s.t1 - s.t0);
                let (lo, hi) = ((t - d).max(s.t0), (t + d).min(s.t1));
                let numeric = (s.at(hi) - s.at(lo)) / (hi - lo);
                assert!((s.slope_at(t) - numeric).norm() < 1e-5, "{t}");
            }
            // At the end, the extension's slope is the right-hand side.
            assert!((s.slope_at(s.t1) - f(s.t1, &s.y1)).norm() < 1e-12);
            Control::Continue
        });
    }
}
