//! An accepted step as its observer sees it ([`Step`]), and its continuous
//! extension ([`DenseStep`]), built only when the observer reads inside the
//! step: most steps are judged by their ends alone (no event between
//! them), and the extension's coefficients are six combinations of the
//! stages that those steps need not pay for.

use std::cell::OnceCell;

use super::State;

/// One accepted step's continuous extension (4th order, Shampine's): the
/// polynomial alone, its step's ends being the [`Step`]'s.
#[derive(Clone, Copy, Debug)]
pub struct DenseStep<const N: usize> {
    t0: f64,
    y0: State<N>,
    /// 1/h, h being the step size the extension was built on (t1 − t0
    /// unless its step was cut short): `at` and `slope_at` multiply by it,
    /// as the event roots call them in a dependent chain where a division
    /// would be the slowest link.
    inverse_h: f64,
    coefficients: [State<N>; 4],
}

impl<const N: usize> DenseStep<N> {
    /// The step from (t0, y0) over `h` to y1, with slopes `k_start` and
    /// `k_end` at its ends: a cubic Hermite extension, raised to Shampine's
    /// quartic by `c5` (zero for the plain cubic).
    #[inline(always)]
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
            y0,
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
        // Read in place (a map copied each coefficient's state out first).
        let [diff, c3, c4, c5]: [f64; 4] = std::array::from_fn(|k| self.coefficients[k][i]);
        let q = c3 + (c4 + c5 * s1) * s;
        let dq = c4 + c5 * (s1 - s);
        let p = diff + q * s1;
        let dp = dq * s1 - q;
        (self.y0[i] + p * s, (p + dp * s) * self.inverse_h)
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
    /// Where the extension comes from.
    source: Source<'a, N>,
    /// The extension [`Source::Build`] made, once asked for.
    built: OnceCell<DenseStep<N>>,
}

/// Makes a step's extension from the integrator's stages.
pub type BuildDense<'a, const N: usize> = dyn Fn() -> DenseStep<N> + 'a;

/// Where a [`Step`]'s extension comes from.
#[derive(Clone, Copy)]
enum Source<'a, const N: usize> {
    /// Built from the integrator's stages on first use.
    Build(&'a BuildDense<'a, N>),
    /// Another's: the step this one was cut from, or one given.
    Borrowed(&'a DenseStep<N>),
}

impl<'a, const N: usize> Step<'a, N> {
    /// The step from `t0` to `t1`, whose extension `build` makes.
    #[inline(always)]
    pub fn new(
        (t0, t1): (f64, f64),
        (y0, y1): (State<N>, State<N>),
        build: &'a BuildDense<'a, N>,
    ) -> Self {
        Step {
            t0,
            t1,
            y0,
            y1,
            source: Source::Build(build),
            built: OnceCell::new(),
        }
    }

    /// The step from `t0` to `t1` whose extension is `dense`.
    pub fn of_dense(
        (t0, t1): (f64, f64),
        (y0, y1): (State<N>, State<N>),
        dense: &'a DenseStep<N>,
    ) -> Self {
        Step {
            t0,
            t1,
            y0,
            y1,
            source: Source::Borrowed(dense),
            built: OnceCell::new(),
        }
    }

    /// The continuous extension, built now if not yet.
    #[inline]
    pub fn dense(&self) -> &DenseStep<N> {
        match self.source {
            Source::Borrowed(dense) => dense,
            Source::Build(build) => self.built.get_or_init(build),
        }
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

    /// The same step, ending at `t` (t0 < t ≤ t1) instead: its extension
    /// is this step's, borrowed, not copied.
    #[inline]
    pub fn truncated(&self, t: f64) -> Step<'_, N> {
        let dense = self.dense();
        Step::of_dense((self.t0, t), (self.y0, dense.at(t)), dense)
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
