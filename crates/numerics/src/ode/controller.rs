//! Step-size control: the PI controller (Hairer's defaults, with
//! Gustafsson's PI stabilisation) and the first step.
//!
//! The controller's powers are taken with [`log2_rough`] and [`exp2_rough`]
//! (a few multiplications) instead of libm's ln and exp (or pow), which sat
//! on every step's dependent chain: the step's error decides the next
//! step's size, whose stages cannot start before it. The factor is only
//! ever a guess, scaled by SAFETY and clamped to [MIN_FACTOR, MAX_FACTOR],
//! so its ~1e-5 relative error (tested against `powf`) changes no decision
//! that matters: a step accepted or rejected at an error within 2e-5 of the
//! tolerance is as good either way.

use super::super::real::{Real, exp2_rough, log2_rough};
use super::{Settings, State, Stats};

pub(super) const SAFETY: f64 = 0.9;
/// The least and most a step may shrink or grow by.
pub(super) const MIN_FACTOR: f64 = 0.2;
pub(super) const MAX_FACTOR: f64 = 10.0;
/// Gustafsson's β: the weight of the previous step's error.
pub(super) const BETA: f64 = 0.04;
/// The error's exponent: 1/5 for a 5th-order pair, less 0.75β.
const ALPHA: f64 = 0.2 - 0.75 * BETA;
/// The previous error is floored at 1e-4 (log₂ 1e-4), as in dopri5.f.
pub(super) const LOG2_ERROR_FLOOR: f64 = -13.287_712_379_549_449;

/// log₂ of the error norm from its square.
#[inline(always)]
pub(super) fn log2_error<R: Real>(error_squared: R) -> R {
    R::splat(0.5) * log2_rough(error_squared)
}

/// The next step over this one after an accepted step with error norm
/// 2^`log2_error`, the previous accepted one's having been
/// 2^`previous_log2_error`: SAFETY·err^(−α)·prev^β, within [MIN_FACTOR,
/// MAX_FACTOR] (an error of 0 grows the step the most).
#[inline(always)]
pub(super) fn accepted_growth<R: Real>(log2_error: R, previous_log2_error: R) -> R {
    // Clamped before the power, far outside the factor's own clamp, so that
    // the power's argument stays where exp2_rough is exact.
    let power = (R::splat(BETA) * previous_log2_error - R::splat(ALPHA) * log2_error)
        .max(R::splat(-60.0))
        .min(R::splat(60.0));
    (R::splat(SAFETY) * exp2_rough(power))
        .max(R::splat(MIN_FACTOR))
        .min(R::splat(MAX_FACTOR))
}

/// The retry's step over the rejected one: SAFETY·err^(−α), never below
/// MIN_FACTOR (also for an infinite or NaN error, whose rough logarithm is
/// finite and large).
#[inline(always)]
pub(super) fn rejected_growth<R: Real>(log2_error: R) -> R {
    let power = (-R::splat(ALPHA) * log2_error).max(R::splat(-60.0));
    (R::splat(SAFETY) * exp2_rough(power))
        .max(R::splat(MIN_FACTOR))
        .min(R::splat(1.0))
}

/// Hairer's initial step guess: the step whose first-order local error
/// estimate would be 1 % of the tolerance.
pub(super) fn initial_step<const N: usize, F>(
    f: &mut F,
    t0: f64,
    y0: &State<N>,
    f0: &State<N>,
    settings: &Settings,
    stats: &mut Stats,
) -> f64
where
    F: FnMut(f64, &State<N>) -> State<N>,
{
    let tol = settings.tolerance;
    let scale = y0.map(|y| tol.absolute + tol.relative * y.abs());
    let rms = |v: &State<N>| (v.component_div(&scale).norm_squared() / N as f64).sqrt();
    let dnf = rms(f0);
    let dny = rms(y0);
    let mut h = if dnf <= 1e-5 || dny <= 1e-5 {
        1e-6
    } else {
        0.01 * dny / dnf
    };
    h = h.min(settings.max_step);
    let f1 = f(t0 + h, &(y0 + f0 * h));
    stats.evaluations += 1;
    let der2 = rms(&(f1 - f0)) / h;
    let der12 = der2.abs().max(dnf);
    let h1 = if der12 <= 1e-15 {
        (h * 1e-3).max(1e-6)
    } else {
        (0.01 / der12).powf(1.0 / 5.0)
    };
    (100.0 * h).min(h1).min(settings.max_step)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The factors as libm's powers give them (the controller as it was).
    fn exact(error: f64, previous: f64, accepted: bool) -> f64 {
        if accepted {
            (SAFETY * error.powf(-ALPHA) * previous.max(1e-4).powf(BETA))
                .clamp(MIN_FACTOR, MAX_FACTOR)
        } else {
            (SAFETY * error.powf(-ALPHA)).clamp(MIN_FACTOR, 1.0)
        }
    }

    #[test]
    fn the_rough_factors_are_libms_within_a_part_in_1e5() {
        let mut worst: f64 = 0.0;
        for i in 0..=400 {
            let error = 10f64.powf(-12.0 + 14.0 * i as f64 / 400.0);
            for previous in [1e-9, 1e-4, 3e-3, 0.2, 0.9, 1.0] {
                let log2 = log2_error(error * error);
                let rough = if error <= 1.0 {
                    let floor = log2_error(previous * previous).max(LOG2_ERROR_FLOOR);
                    accepted_growth(log2, floor)
                } else {
                    rejected_growth(log2)
                };
                let exact = exact(error, previous, error <= 1.0);
                worst = worst.max((rough / exact - 1.0).abs());
            }
        }
        assert!(worst < 1e-5, "{worst:e}");
        // No error grows the step the most; no finite error shrinks it
        // less than a NaN or an infinite one does.
        assert_eq!(
            accepted_growth(log2_error(0.0), LOG2_ERROR_FLOOR),
            MAX_FACTOR
        );
        for bad in [f64::NAN, f64::INFINITY, 1e300] {
            assert_eq!(rejected_growth(log2_error(bad)), MIN_FACTOR, "{bad}");
        }
        assert!((LOG2_ERROR_FLOOR - 1e-4f64.log2()).abs() < 1e-12);
    }
}
