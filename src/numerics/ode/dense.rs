//! An accepted step's continuous extension.

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

    /// Where to go on from, if the observer's `control` asks for a restart
    /// inside this step: there the right-hand side changed, so the next step
    /// starts from the extension with a fresh derivative.
    #[inline]
    pub(super) fn restart_time(&self, control: super::Control) -> Option<f64> {
        match control {
            super::Control::RestartAt(t) if t < self.t1 => Some(t.max(self.t0)),
            _ => None,
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

    /// The same step, ending at `t` (t0 < t ≤ t1) instead.
    pub fn truncated(&self, t: f64) -> DenseStep<N> {
        DenseStep {
            t1: t,
            y1: self.at(t),
            ..*self
        }
    }
}
