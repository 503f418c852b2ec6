//! Step-size control: the error norm, the first step, and the PI controller's
//! constants (Hairer's defaults, with Gustafsson's PI stabilisation).

use super::{Settings, State, Stats, Tolerance};

// Step-size control (Hairer's defaults, with Gustafsson's PI stabilisation).
pub(super) const SAFETY: f64 = 0.9;
pub(super) const MIN_FACTOR: f64 = 0.2;
pub(super) const MAX_FACTOR: f64 = 10.0;
pub(super) const BETA: f64 = 0.04;

#[inline]
pub(super) fn error_norm<const N: usize>(
    err: &State<N>,
    y0: &State<N>,
    y1: &State<N>,
    tol: Tolerance,
) -> f64 {
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
