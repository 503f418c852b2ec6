//! One Dormand–Prince step's arithmetic, written once for a state of one
//! flight (`SVector<f64, N>`, numbers `f64`) and for the states of four
//! flights in lock-step (`lanes::Lanes<N>`, numbers `f64x4`): the stages,
//! the error estimate and its norm, and the dense output's fifth
//! coefficient. The single integrator and the lock-step one differ only in
//! what they do with the result.

use std::ops::{Add, Mul, Sub};

use super::super::real::Real;
use super::State;
use super::tableau::*;

/// A state the stages can combine: sums, differences and multiples by a
/// number (one per lane), and its components.
pub trait Vector<R: Real>:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<R, Output = Self>
{
    /// The number of components.
    const DIM: usize;
    fn component(&self, i: usize) -> R;
}

impl<const N: usize> Vector<f64> for State<N> {
    const DIM: usize = N;
    #[inline(always)]
    fn component(&self, i: usize) -> f64 {
        self[i]
    }
}

/// Stages 2 to 7 of a step of size `h` from (t, y) with slope `k1`, and
/// its 5th-order end y1 (k7 is the slope there).
pub struct Stages<V> {
    /// k2 … k7.
    pub k: [V; 6],
    pub y1: V,
}

/// The six evaluations of a step. Each stage's input adds its newest
/// slope last, times its weight already multiplied by h: the evaluations
/// form one dependent chain, and this way each waits on a single
/// multiply-add after the one before, the older slopes' sum being ready.
#[inline(always)]
pub fn stages<R: Real, V: Vector<R>>(
    f: &mut impl FnMut(R, &V) -> V,
    t: R,
    y: &V,
    k1: &V,
    h: R,
) -> Stages<V> {
    let mut out = Stages { k: [*y; 6], y1: *y };
    stages_into(
        &mut out,
        &mut |t, y, slope: &mut V| *slope = f(t, y),
        t,
        y,
        k1,
        h,
    );
    out
}

/// [`stages`], written into `out`, each slope by `f` into its place: the
/// lock-step loop keeps its stages in place, as four lanes' are 900 bytes,
/// and a slope returned by value was moved into them with a call to
/// `memcpy` (a 3-D state's 192 bytes are past what the compiler copies
/// inline): six calls a step, 5 % of a surface's time and more of a 3-D
/// batch's.
#[inline(always)]
pub fn stages_into<R: Real, V: Vector<R>>(
    out: &mut Stages<V>,
    f: &mut impl FnMut(R, &V, &mut V),
    t: R,
    y: &V,
    k1: &V,
    h: R,
) {
    let c = R::splat;
    let [k2, k3, k4, k5, k6, k7] = &mut out.k;
    f(t + c(C2) * h, &(*y + *k1 * (c(A21) * h)), k2);
    let k2 = *k2;
    f(
        t + c(C3) * h,
        &((*y + *k1 * (c(A31) * h)) + k2 * (c(A32) * h)),
        k3,
    );
    let k3 = *k3;
    f(
        t + c(C4) * h,
        &((*y + (*k1 * c(A41) + k2 * c(A42)) * h) + k3 * (c(A43) * h)),
        k4,
    );
    let k4 = *k4;
    f(
        t + c(C5) * h,
        &((*y + (*k1 * c(A51) + k2 * c(A52) + k3 * c(A53)) * h) + k4 * (c(A54) * h)),
        k5,
    );
    let k5 = *k5;
    f(
        t + h,
        &((*y + (*k1 * c(A61) + k2 * c(A62) + k3 * c(A63) + k4 * c(A64)) * h) + k5 * (c(A65) * h)),
        k6,
    );
    let k6 = *k6;
    out.y1 =
        (*y + (*k1 * c(A71) + k3 * c(A73) + k4 * c(A74) + k5 * c(A75)) * h) + k6 * (c(A76) * h);
    f(t + h, &out.y1, k7);
}

/// 1/(absolute + relative·max(|y0|, |y1|)) per component: the error's
/// scale. Computed from y1 alone (not the error), so that it overlaps the
/// last stage's evaluation instead of following it.
#[inline(always)]
pub fn inverse_scales<R: Real, V: Vector<R>, const D: usize>(
    y0: &V,
    y1: &V,
    relative: R,
    absolute: R,
) -> [R; D] {
    let mut scales = [R::splat(1.0); D];
    for (i, scale) in scales.iter_mut().enumerate() {
        let size = y0.component(i).abs().max(y1.component(i).abs());
        *scale = R::splat(1.0) / (absolute + relative * size);
    }
    scales
}

/// The square of Hairer's root-mean-square error norm of the step: the
/// difference between the 5th- and 4th-order results, scaled. Squared, as
/// the controller takes its power (no square root on the step's chain).
#[inline(always)]
pub fn error_squared<R: Real, V: Vector<R>, const D: usize>(
    k1: &V,
    stages: &Stages<V>,
    h: R,
    inverse_scales: &[R; D],
) -> R {
    let c = R::splat;
    let [_, k3, k4, k5, k6, k7] = &stages.k;
    let err =
        (*k1 * c(E1) + *k3 * c(E3) + *k4 * c(E4) + *k5 * c(E5) + *k6 * c(E6) + *k7 * c(E7)) * h;
    let mut sum = R::splat(0.0);
    for (i, inverse) in inverse_scales.iter().enumerate() {
        let r = err.component(i) * *inverse;
        sum = sum + r * r;
    }
    sum * R::splat(1.0 / D as f64)
}

/// The fifth coefficient of the step's continuous extension (Hairer's
/// dopri5.f): needed only where an observer reads inside the step.
#[inline(always)]
pub fn dense_c5<R: Real, V: Vector<R>>(k1: &V, stages: &Stages<V>, h: R) -> V {
    let c = R::splat;
    let [_, k3, k4, k5, k6, k7] = &stages.k;
    (*k1 * c(D1) + *k3 * c(D3) + *k4 * c(D4) + *k5 * c(D5) + *k6 * c(D6) + *k7 * c(D7)) * h
}
