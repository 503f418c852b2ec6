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

/// Work done by one integration.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Stats {
    /// Right-hand-side evaluations.
    pub evaluations: u32,
    pub accepted: u32,
    pub rejected: u32,
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
    /// ([`DenseStep::truncated`]).
    RestartAt(f64),
    /// Go on, ending the next step no later than the given time: the
    /// observer expects an event (a kink, the landing) a little before it,
    /// so that the step that meets the event wastes little beyond it.
    EndNextBy(f64),
}

/// One accepted step and its continuous extension (4th order, Shampine's).
#[derive(Clone, Copy, Debug)]
pub struct DenseStep<const N: usize> {
    pub t0: f64,
    pub t1: f64,
    pub y0: State<N>,
    pub y1: State<N>,
    /// 1/h, h being the step size the extension was built on (t1 − t0
    /// unless truncated): `at` and `slope_at` multiply by it, as the event
    /// roots call them in a dependent chain where a division would be the
    /// slowest link.
    inverse_h: f64,
    coefficients: [State<N>; 4],
}

impl<const N: usize> DenseStep<N> {
    /// The solution at `t` in [t0, t1].
    #[inline]
    pub fn at(&self, t: f64) -> State<N> {
        let s = (t - self.t0) * self.inverse_h;
        let s1 = 1.0 - s;
        let [diff, c3, c4, c5] = &self.coefficients;
        self.y0 + (diff + (c3 + (c4 + c5 * s1) * s) * s1) * s
    }

    /// The derivative of the continuous extension, dy/dt at `t` in
    /// [t0, t1] (at t1 it equals the right-hand side there, k7).
    #[inline]
    pub fn slope_at(&self, t: f64) -> State<N> {
        let s = (t - self.t0) * self.inverse_h;
        let s1 = 1.0 - s;
        let [diff, c3, c4, c5] = &self.coefficients;
        // y = y0 + P·s, P = diff + Q·s1, Q = c3 + (c4 + c5·s1)·s.
        let q = c3 + (c4 + c5 * s1) * s;
        let dq = c4 + c5 * (s1 - s);
        let p = diff + q * s1;
        let dp = dq * s1 - q;
        (p + dp * s) * self.inverse_h
    }

    /// The same step, ending at `t` (t0 < t ≤ t1) instead.
    pub fn truncated(&self, t: f64) -> DenseStep<N> {
        DenseStep {
            t1: t,
            y1: self.at(t),
            ..*self
        }
    }
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
    /// First step to try; `None` picks one (Hairer's `hinit`, two evaluations).
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

// Butcher tableau of Dormand & Prince (1980).
const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;
// Difference between the 5th- and 4th-order weights.
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
// Dense output weights (Hairer's dopri5.f).
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

// Step-size control (Hairer's defaults, with Gustafsson's PI stabilisation).
const SAFETY: f64 = 0.9;
const MIN_FACTOR: f64 = 0.2;
const MAX_FACTOR: f64 = 10.0;
const BETA: f64 = 0.04;

#[inline]
fn error_norm<const N: usize>(err: &State<N>, y0: &State<N>, y1: &State<N>, tol: Tolerance) -> f64 {
    let mut sum = 0.0;
    for i in 0..N {
        let scale = tol.absolute + tol.relative * y0[i].abs().max(y1[i].abs());
        let r = err[i] / scale;
        sum += r * r;
    }
    (sum / N as f64).sqrt()
}

/// Hairer's initial step guess: the step whose first-order local error
/// estimate would be 1 % of the tolerance.
fn initial_step<const N: usize, F>(
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
    O: FnMut(&DenseStep<N>) -> Control,
{
    let tol = settings.tolerance;
    let mut stats = Stats::default();
    let mut t = t0;
    let mut y = y0;
    let mut k1 = f(t, &y);
    stats.evaluations += 1;
    let mut h = match settings.initial_step {
        Some(h) => h,
        None => initial_step(&mut f, t, &y, &k1, settings, &mut stats),
    };
    // ln of the last accepted step's error (floored at 1e-4), for the PI
    // controller; logarithms make its two powers one exp (pow costs 2×).
    let mut previous_ln_error: f64 = 1e-4f64.ln();
    let mut last_rejected = false;

    loop {
        if stats.accepted + stats.rejected >= settings.max_steps {
            return (Outcome::StepLimit, stats);
        }
        if t >= t_end {
            return (Outcome::ReachedEnd, stats);
        }
        h = h.min(settings.max_step).min(t_end - t);
        if h <= 16.0 * f64::EPSILON * t.abs().max(1.0) {
            return (Outcome::StepTooSmall, stats);
        }

        let k2 = f(t + C2 * h, &(y + k1 * (A21 * h)));
        let k3 = f(t + C3 * h, &(y + (k1 * A31 + k2 * A32) * h));
        let k4 = f(t + C4 * h, &(y + (k1 * A41 + k2 * A42 + k3 * A43) * h));
        let k5 = f(
            t + C5 * h,
            &(y + (k1 * A51 + k2 * A52 + k3 * A53 + k4 * A54) * h),
        );
        let k6 = f(
            t + h,
            &(y + (k1 * A61 + k2 * A62 + k3 * A63 + k4 * A64 + k5 * A65) * h),
        );
        let y1 = y + (k1 * A71 + k3 * A73 + k4 * A74 + k5 * A75 + k6 * A76) * h;
        let k7 = f(t + h, &y1);
        stats.evaluations += 6;

        let err_vec = (k1 * E1 + k3 * E3 + k4 * E4 + k5 * E5 + k6 * E6 + k7 * E7) * h;
        let err = error_norm(&err_vec, &y, &y1, tol);

        if err <= 1.0 {
            // Accept.
            // err^(0.2 − 0.75β) / previous^β / SAFETY, with err = 0 → 0.
            let ln_error = err.ln();
            let fac = ((0.2 - BETA * 0.75) * ln_error - BETA * previous_ln_error).exp() / SAFETY;
            let fac = fac.clamp(1.0 / MAX_FACTOR, 1.0 / MIN_FACTOR);
            let mut h_next = h / fac;
            if last_rejected {
                h_next = h_next.min(h);
            }
            let diff = y1 - y;
            let c3 = k1 * h - diff;
            let c4 = diff - k7 * h - c3;
            let c5 = (k1 * D1 + k3 * D3 + k4 * D4 + k5 * D5 + k6 * D6 + k7 * D7) * h;
            let step = DenseStep {
                t0: t,
                t1: t + h,
                y0: y,
                y1,
                inverse_h: 1.0 / h,
                coefficients: [diff, c3, c4, c5],
            };
            stats.accepted += 1;
            previous_ln_error = ln_error.max(1e-4f64.ln());
            last_rejected = false;
            h = h_next;
            match observe(&step) {
                Control::Stop => return (Outcome::Stopped, stats),
                Control::RestartAt(t_restart) if t_restart < step.t1 => {
                    // One evaluation, where a redone step would cost six.
                    t = t_restart.max(step.t0);
                    y = step.at(t);
                    k1 = f(t, &y);
                    stats.evaluations += 1;
                }
                control => {
                    t = step.t1;
                    y = y1;
                    k1 = k7;
                    if let Control::EndNextBy(t_end_next) = control
                        && t_end_next > t
                    {
                        h = h.min(t_end_next - t);
                    }
                }
            }
        } else {
            // Reject: shrink, never below a fifth.
            stats.rejected += 1;
            let shrink = if err.is_finite() {
                (err.powf(0.2 - BETA * 0.75) / SAFETY).min(1.0 / MIN_FACTOR)
            } else {
                1.0 / MIN_FACTOR
            };
            h /= shrink;
            last_rejected = true;
        }
    }
}

/// The classical fixed-step Runge–Kutta method (4th order, four
/// evaluations a step), with a cubic Hermite continuous extension: the
/// benchmark's comparison for [`integrate`], with the same observer protocol.
/// The last step is shortened to end on `t_end`.
pub fn integrate_fixed<const N: usize, F, O>(
    mut f: F,
    t0: f64,
    y0: State<N>,
    t_end: f64,
    step: f64,
    max_steps: u32,
    mut observe: O,
) -> (Outcome, Stats)
where
    F: FnMut(f64, &State<N>) -> State<N>,
    O: FnMut(&DenseStep<N>) -> Control,
{
    let mut stats = Stats::default();
    let (mut t, mut y) = (t0, y0);
    let mut k1 = f(t, &y);
    stats.evaluations += 1;
    loop {
        if stats.accepted >= max_steps {
            return (Outcome::StepLimit, stats);
        }
        let h = step.min(t_end - t);
        if h <= 16.0 * f64::EPSILON * t.abs().max(1.0) {
            return (Outcome::ReachedEnd, stats);
        }
        let k2 = f(t + 0.5 * h, &(y + k1 * (0.5 * h)));
        let k3 = f(t + 0.5 * h, &(y + k2 * (0.5 * h)));
        let k4 = f(t + h, &(y + k3 * h));
        let y1 = y + (k1 + (k2 + k3) * 2.0 + k4) * (h / 6.0);
        // The next step's first stage, and the Hermite extension's end slope.
        let k_end = f(t + h, &y1);
        stats.evaluations += 4;
        stats.accepted += 1;
        let diff = y1 - y;
        let c3 = k1 * h - diff;
        let c4 = diff - k_end * h - c3;
        let dense = DenseStep {
            t0: t,
            t1: t + h,
            y0: y,
            y1,
            inverse_h: 1.0 / h,
            coefficients: [diff, c3, c4, State::<N>::zeros()],
        };
        match observe(&dense) {
            Control::Stop => return (Outcome::Stopped, stats),
            Control::RestartAt(t_restart) if t_restart < dense.t1 => {
                t = t_restart.max(dense.t0);
                y = dense.at(t);
                k1 = f(t, &y);
                stats.evaluations += 1;
            }
            _ => {
                t = dense.t1;
                y = y1;
                k1 = k_end;
            }
        }
    }
}

/// A root of `g` in [a, b], where g(a) and g(b) differ in sign, to within
/// `tolerance` in t, `g` returning its value and its derivative: Newton's
/// method from the secant through the ends, falling back to bisection when a
/// Newton step would leave the bracket. On a step's continuous extension
/// (a polynomial, its derivative exact) it converges in about four
/// iterations where regula falsi (Illinois) took about seven (a fastball's five
/// events: 20 against 36); the iterations form a dependent chain, so their
/// number is the cost.
pub fn find_root_newton(
    mut g: impl FnMut(f64) -> (f64, f64),
    mut a: f64,
    mut b: f64,
    tolerance: f64,
) -> f64 {
    let (ga, _) = g(a);
    let (gb, _) = g(b);
    if ga == 0.0 {
        return a;
    }
    if gb == 0.0 {
        return b;
    }
    let b_positive = gb > 0.0;
    let mut t = (a * gb - b * ga) / (gb - ga);
    for _ in 0..100 {
        let (gt, slope) = g(t);
        if gt == 0.0 {
            return t;
        }
        // Keep the root bracketed: b on g(b)'s side, a on the other.
        if (gt > 0.0) == b_positive {
            b = t;
        } else {
            a = t;
        }
        let newton = t - gt / slope;
        let (low, high) = if a < b { (a, b) } else { (b, a) };
        let inside = newton >= low && newton <= high;
        // Converged (the test is on the Newton step, as the new point may
        // be the bracket's end itself).
        if inside && (newton - t).abs() < tolerance {
            return newton;
        }
        let next = if inside { newton } else { 0.5 * (a + b) };
        if (b - a).abs() < tolerance {
            return next;
        }
        t = next;
    }
    t
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
    fn newton_finds_roots_and_stays_in_the_bracket() {
        let r = find_root_newton(|x| (x * x - 2.0, 2.0 * x), 0.0, 2.0, 1e-14);
        assert!((r - 2f64.sqrt()).abs() < 1e-12);
        // A zero slope at the secant's guess: bisection, not a jump to ±∞.
        let r = find_root_newton(|x| (x * x * x, 3.0 * x * x), -1.0, 1.0, 1e-14);
        assert!(r.abs() < 1e-4, "{r}");
        let r = find_root_newton(|x| (x.cos(), -x.sin()), 0.0, 3.0, 1e-14);
        assert!((r - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
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
