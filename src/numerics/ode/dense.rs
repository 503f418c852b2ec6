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
    pub(super) inverse_h: f64,
    pub(super) coefficients: [State<N>; 4],
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
