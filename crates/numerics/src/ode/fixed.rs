//! Fixed-step RK4: the benchmark's comparison for the adaptive integrator.

use super::{Control, DenseStep, Outcome, State, Stats, Step, too_small};

/// The classical fixed-step Runge–Kutta method (4th order, four
/// evaluations a step), with a cubic Hermite continuous extension: the
/// benchmark's comparison for [`integrate`](super::integrate), with the same observer protocol.
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
    O: FnMut(&Step<N>) -> Control,
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
        if too_small(h, t) {
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
        let extension = DenseStep::new(t, h, (y, y1), (&k1, &k_end), State::<N>::zeros());
        let dense = Step::of_dense((t, t + h), (y, y1), &extension);
        let control = observe(&dense);
        if matches!(control, Control::Stop) {
            return (Outcome::Stopped, stats);
        }
        if let Some(t_restart) = dense.restart_time(control) {
            t = t_restart;
            y = dense.at(t);
            k1 = f(t, &y);
            stats.evaluations += 1;
        } else {
            t = dense.t1;
            y = y1;
            k1 = k_end;
        }
    }
}
