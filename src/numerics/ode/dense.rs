//! An accepted step as its observer sees it ([`Step`]), and its continuous
//! extension ([`DenseStep`]), built only when the observer reads inside the
//! step: most steps are judged by their ends alone (no event between
//! them), and the extension's coefficients are six combinations of the
//! stages that those steps need not pay for.

use std::cell::OnceCell;

use super::State;

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
    /// The step from (t0, y0) over `h` to y1, with slopes `k_start` and
    /// `k_end` at its ends: a cubic Hermite extension, raised to Shampine's
    /// quartic by `c5` (zero for the plain cubic).
    #[inline]
    pub(super) fn new(
        t0: f64,
        h: f64,
        (y0, y1): (State<N>, State<N>),
        (k_start, k_end): (&State<N>, &State<N>),
        c5: State<N>,
    ) -> Self {
        let diff = y1 - y0;
        let c3 = k_start * h - diff;
        let c4 = diff - k_end * h - c3;
        DenseStep {
            t0,
            t1: t0 + h,
            y0,
            y1,
            inverse_h: 1.0 / h,
            coefficients: [diff, c3, c4, c5],
        }
    }

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

    /// Component `i` of the solution at `t` and its slope there: as
    /// [`DenseStep::at`] and [`DenseStep::slope_at`], for one component
    /// (what an event's root finding reads).
    #[inline]
    pub fn component_at(&self, t: f64, i: usize) -> (f64, f64) {
        let s = (t - self.t0) * self.inverse_h;
        let s1 = 1.0 - s;
        let [diff, c3, c4, c5] = self.coefficients.map(|c| c[i]);
        let q = c3 + (c4 + c5 * s1) * s;
        let dq = c4 + c5 * (s1 - s);
        let p = diff + q * s1;
        let dp = dq * s1 - q;
        (self.y0[i] + p * s, (p + dp * s) * self.inverse_h)
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

/// An accepted step as the observer sees it: its ends at once, its
/// continuous extension ([`Step::dense`], and [`Step::at`] and
/// [`Step::slope_at`] on it) built on first use.
pub struct Step<'a, const N: usize> {
    pub t0: f64,
    pub t1: f64,
    pub y0: State<N>,
    pub y1: State<N>,
    dense: OnceCell<DenseStep<N>>,
    /// Builds the extension from the integrator's stages (`None` when it
    /// is built already).
    build: Option<&'a dyn Fn() -> DenseStep<N>>,
}

impl<'a, const N: usize> Step<'a, N> {
    /// The step from `t0` to `t1`, whose extension `build` makes.
    #[inline(always)]
    pub fn new(
        (t0, t1): (f64, f64),
        (y0, y1): (State<N>, State<N>),
        build: &'a dyn Fn() -> DenseStep<N>,
    ) -> Self {
        Step {
            t0,
            t1,
            y0,
            y1,
            dense: OnceCell::new(),
            build: Some(build),
        }
    }

    /// The step whose extension is `dense`.
    pub fn of_dense(dense: DenseStep<N>) -> Step<'static, N> {
        Step {
            t0: dense.t0,
            t1: dense.t1,
            y0: dense.y0,
            y1: dense.y1,
            dense: OnceCell::from(dense),
            build: None,
        }
    }

    /// The continuous extension, built now if not yet.
    #[inline]
    pub fn dense(&self) -> &DenseStep<N> {
        self.dense.get_or_init(|| match self.build {
            Some(build) => build(),
            None => unreachable!("a step without its builder is built"),
        })
    }

    /// The solution at `t` in [t0, t1].
    #[inline]
    pub fn at(&self, t: f64) -> State<N> {
        self.dense().at(t)
    }

    /// The extension's slope at `t` in [t0, t1].
    #[inline]
    pub fn slope_at(&self, t: f64) -> State<N> {
        self.dense().slope_at(t)
    }

    /// The same step, ending at `t` (t0 < t ≤ t1) instead.
    pub fn truncated(&self, t: f64) -> Step<'static, N> {
        Step::of_dense(self.dense().truncated(t))
    }

    /// Where to go on from, if the observer's `control` asks for a restart
    /// inside this step: there the right-hand side changed, so the next step
    /// starts from the extension with a fresh derivative.
    #[inline]
    pub fn restart_time(&self, control: super::Control) -> Option<f64> {
        match control {
            super::Control::RestartAt(t) if t < self.t1 => Some(t.max(self.t0)),
            _ => None,
        }
    }
}
