//! Arithmetic written once for one number (`f64`) or four at a time
//! (`wide::f64x4`, one flight per lane): the flight's forces and the
//! integrator's step control are generic over [`Real`], so that the single
//! flight and the flights in lock-step evaluate the very same formulas.
//!
//! Also the step-size controller's cheap powers ([`log2_rough`],
//! [`exp2_rough`]) and an exponential for the lanes ([`exp_lanes`]), all
//! from the same few bit-level pieces each type supplies.

use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

use wide::{f64x4, f64x8};

/// The lanes of the flights in lock-step: eight flights a vector (on
/// SSE2, four pairs; eight independent chains keep the cores' pipelines
/// fuller than four).
pub type Lane = f64x4;
/// How many flights a [`Lane`] carries.
pub const LANES: usize = 4;

/// A floating-point number, or four of them in lock-step.
pub trait Real:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// Per-lane truth: `bool` for one number, an all-ones/all-zeros lane
    /// mask for four.
    type Mask: Copy
        + BitAnd<Output = Self::Mask>
        + BitOr<Output = Self::Mask>
        + Not<Output = Self::Mask>;

    fn splat(x: f64) -> Self;
    fn sqrt(self) -> Self;
    fn abs(self) -> Self;
    fn max(self, other: Self) -> Self;
    fn min(self, other: Self) -> Self;
    /// e^self. For one number, libm's (the single flight's results stay as
    /// they were); for four, [`exp_lanes`].
    fn exp(self) -> Self;
    fn lt(self, other: Self) -> Self::Mask;
    fn le(self, other: Self) -> Self::Mask;
    fn eq(self, other: Self) -> Self::Mask;
    /// `if_true` where `mask` holds, else `if_false`.
    fn select(mask: Self::Mask, if_true: Self, if_false: Self) -> Self;
    /// Whether `mask` holds in any lane.
    fn any(mask: Self::Mask) -> bool;

    /// The unbiased binary exponent field of a positive finite number, as a
    /// number (−1023 for zero), and its significand in [1, 2).
    fn exponent_and_significand(self) -> (Self, Self);
    /// 2^n for an integral n in [−1022, 1023] given as a number.
    fn power_of_two(n: Self) -> Self;
}

/// 1.5·2^52: adding and subtracting it rounds a number below 2^51 in size
/// to the nearest integer (in the default rounding mode), in any lane,
/// without a rounding instruction (SSE2 has none).
const ROUNDER: f64 = 6_755_399_441_055_744.0;

/// x rounded to the nearest integer, for |x| < 2^51.
#[inline(always)]
fn round<R: Real>(x: R) -> R {
    (x + R::splat(ROUNDER)) - R::splat(ROUNDER)
}

/// log₂ x within 2e-5 (absolute) for positive normal x; about −1023 at 0.
/// On the significand 1 + u: u + u(1 − u)·r(u), r a cubic fitted to
/// log₂(1 + u), exact at u = 0 and 1, so that the whole is continuous
/// across powers of two (a jump there would make two nearly equal errors
/// give different steps).
#[inline(always)]
pub fn log2_rough<R: Real>(x: R) -> R {
    const R_FIT: [f64; 4] = [
        0.441_835_872_118_750_2,
        -0.266_536_280_312_731_47,
        0.147_018_770_468_407_86,
        -0.044_243_741_326_192_59,
    ];
    let (exponent, significand) = x.exponent_and_significand();
    let u = significand - R::splat(1.0);
    exponent + (u + u * (R::splat(1.0) - u) * polynomial(u, &R_FIT))
}

/// 2^y within 4e-6 (relative) for y in [−1022, 1023]: 2^n from the
/// exponent bits (n = ⌊y⌋, or y at an integer) times 2^f, f = y − n in
/// [0, 1], as 1 + f + f(1 − f)·s(f), s a quadratic fitted to 2^f: exact at
/// f = 0 and 1, so continuous wherever n steps.
#[inline(always)]
pub fn exp2_rough<R: Real>(y: R) -> R {
    const S_FIT: [f64; 3] = [
        -0.306_967_033_042_016_83,
        -0.065_597_245_340_515_06,
        -0.013_542_427_793_843_438,
    ];
    let n = round(y - R::splat(0.5));
    let f = y - n;
    let one = R::splat(1.0);
    R::power_of_two(n) * (one + f + f * (one - f) * polynomial(f, &S_FIT))
}

/// e^x to a few ulp for x in [−700, 700] (clamped there: e^−700 is below
/// every use, and no lane overflows), written with lane operations only: for the lanes, where
/// libm's exp would be four calls in turn. Cody & Waite's reduction
/// x = n·ln 2 + r, |r| ≤ ½ln 2, then e^r by its Taylor series to r¹³/13!
/// (the next term is under 1e-17 of it).
#[inline(always)]
pub fn exp_lanes<R: Real>(x: R) -> R {
    const LN2_HIGH: f64 = 0.693_145_751_953_125;
    const LN2_LOW: f64 = 1.428_606_820_309_417_2e-6;
    let x = x.max(R::splat(-700.0)).min(R::splat(700.0));
    let n = round(x * R::splat(std::f64::consts::LOG2_E));
    let r = (x - n * R::splat(LN2_HIGH)) - n * R::splat(LN2_LOW);
    R::power_of_two(n) * estrin(r, &INVERSE_FACTORIALS)
}

/// 1/k! for k = 0 … 13.
const INVERSE_FACTORIALS: [f64; 14] = {
    let mut c = [1.0; 14];
    let mut k = 1;
    while k < 14 {
        c[k] = c[k - 1] / k as f64;
        k += 1;
    }
    c
};

/// c₀ + c₁u + … by Estrin's scheme: pairs c₂ₖ + c₂ₖ₊₁u, then pairs of
/// those with u², and so on: the same products as Horner's rule, in a
/// chain about log₂ K long instead of K (the lanes' exponential waits on
/// it at every evaluation).
#[inline(always)]
fn estrin<R: Real, const K: usize>(u: R, c: &[f64; K]) -> R {
    let mut terms: [R; K] = std::array::from_fn(|i| R::splat(c[i]));
    let (mut len, mut power) = (K, u);
    while len > 1 {
        let half = len.div_ceil(2);
        for k in 0..half {
            terms[k] = if 2 * k + 1 < len {
                terms[2 * k] + terms[2 * k + 1] * power
            } else {
                terms[2 * k]
            };
        }
        len = half;
        power = power * power;
    }
    terms[0]
}

/// c₀ + c₁u + … by Horner's rule.
#[inline(always)]
fn polynomial<R: Real, const K: usize>(u: R, c: &[f64; K]) -> R {
    let mut sum = R::splat(c[K - 1]);
    for &coefficient in c[..K - 1].iter().rev() {
        sum = sum * u + R::splat(coefficient);
    }
    sum
}

const EXPONENT_SHIFT: u32 = 52;
const SIGNIFICAND_BITS: u64 = (1 << EXPONENT_SHIFT) - 1;
const ONE_BITS: u64 = 0x3ff0_0000_0000_0000;
/// 2^52: its bits' low part holds an integer added to it.
const TWO_52: f64 = 4_503_599_627_370_496.0;

impl Real for f64 {
    type Mask = bool;

    #[inline(always)]
    fn splat(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        f64::abs(self)
    }
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        f64::max(self, other)
    }
    #[inline(always)]
    fn min(self, other: Self) -> Self {
        f64::min(self, other)
    }
    #[inline(always)]
    fn exp(self) -> Self {
        f64::exp(self)
    }
    #[inline(always)]
    fn lt(self, other: Self) -> bool {
        self < other
    }
    #[inline(always)]
    fn le(self, other: Self) -> bool {
        self <= other
    }
    #[inline(always)]
    fn eq(self, other: Self) -> bool {
        self == other
    }
    #[inline(always)]
    fn select(mask: bool, if_true: Self, if_false: Self) -> Self {
        if mask { if_true } else { if_false }
    }
    #[inline(always)]
    fn any(mask: bool) -> bool {
        mask
    }
    #[inline(always)]
    fn exponent_and_significand(self) -> (Self, Self) {
        let bits = self.to_bits();
        let biased = f64::from_bits((bits >> EXPONENT_SHIFT) | TWO_52.to_bits()) - TWO_52;
        let significand = f64::from_bits((bits & SIGNIFICAND_BITS) | ONE_BITS);
        (biased - 1023.0, significand)
    }
    #[inline(always)]
    fn power_of_two(n: Self) -> Self {
        f64::from_bits((n + (TWO_52 + 1023.0)).to_bits() << EXPONENT_SHIFT)
    }
}

/// [`Real`] for a vector of lanes (`$bits` its bits' type).
macro_rules! lanes_real {
    ($lane:ty, $bits:ty) => {
        impl Real for $lane {
            type Mask = $lane;

            #[inline(always)]
            fn splat(x: f64) -> Self {
                <$lane>::splat(x)
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                <$lane>::sqrt(self)
            }
            #[inline(always)]
            fn abs(self) -> Self {
                <$lane>::abs(self)
            }
            #[inline(always)]
            fn max(self, other: Self) -> Self {
                <$lane>::fast_max(self, other)
            }
            #[inline(always)]
            fn min(self, other: Self) -> Self {
                <$lane>::fast_min(self, other)
            }
            #[inline(always)]
            fn exp(self) -> Self {
                exp_lanes(self)
            }
            #[inline(always)]
            fn lt(self, other: Self) -> Self {
                self.simd_lt(other)
            }
            #[inline(always)]
            fn le(self, other: Self) -> Self {
                self.simd_le(other)
            }
            #[inline(always)]
            fn eq(self, other: Self) -> Self {
                self.simd_eq(other)
            }
            #[inline(always)]
            fn select(mask: Self, if_true: Self, if_false: Self) -> Self {
                mask.select(if_true, if_false)
            }
            #[inline(always)]
            fn any(mask: Self) -> bool {
                mask.any()
            }
            #[inline(always)]
            fn exponent_and_significand(self) -> (Self, Self) {
                let bits = self.to_bits();
                let two_52 = <$lane>::splat(TWO_52);
                let biased =
                    <$lane>::from_bits((bits >> EXPONENT_SHIFT) | two_52.to_bits()) - two_52;
                let significand = <$lane>::from_bits(
                    (bits & <$bits>::splat(SIGNIFICAND_BITS)) | <$bits>::splat(ONE_BITS),
                );
                (biased - <$lane>::splat(1023.0), significand)
            }
            #[inline(always)]
            fn power_of_two(n: Self) -> Self {
                <$lane>::from_bits(
                    (n + <$lane>::splat(TWO_52 + 1023.0)).to_bits() << EXPONENT_SHIFT,
                )
            }
        }
    };
}

lanes_real!(f64x4, wide::u64x4);
lanes_real!(f64x8, wide::u64x8);

/// What the flights in lock-step need of their numbers beyond [`Real`]:
/// [`LANES`] of them, one flight's each, read and written one at a time.
///
/// [`Lane`] (`wide`'s, whose instructions are chosen when the crate is
/// compiled: two SSE2 pairs for baseline x86-64) has it.
pub trait LaneReal: Real + std::fmt::Debug {
    fn from_array(lanes: [f64; LANES]) -> Self;
    fn to_array(self) -> [f64; LANES];
    /// Lane `j`, read in place (one load; a whole vector copied out to be
    /// indexed took four instructions).
    fn get(&self, j: usize) -> f64;
    /// Sets lane `j` to `x`, in place (a whole vector written back would
    /// wait for the one lane's store to land).
    fn set(&mut self, j: usize, x: f64);
    /// The mask that holds in the lanes where `holds` is true.
    fn mask_of(holds: [bool; LANES]) -> Self::Mask;
    /// Sets lane `j` of `mask` to `holds`, in place.
    fn set_mask(mask: &mut Self::Mask, j: usize, holds: bool);
    /// Bit j set where lane j of `mask` holds.
    fn bitmask(mask: Self::Mask) -> u32;
}

/// All ones where `holds`: a lane mask's truth.
#[inline(always)]
fn mask_bits(holds: bool) -> f64 {
    f64::from_bits(if holds { u64::MAX } else { 0 })
}

impl LaneReal for f64x4 {
    #[inline(always)]
    fn from_array(lanes: [f64; LANES]) -> Self {
        f64x4::new(lanes)
    }
    #[inline(always)]
    fn to_array(self) -> [f64; LANES] {
        f64x4::to_array(self)
    }
    #[inline(always)]
    fn get(&self, j: usize) -> f64 {
        self.as_array()[j]
    }
    #[inline(always)]
    fn set(&mut self, j: usize, x: f64) {
        self.as_mut_array()[j] = x;
    }
    #[inline(always)]
    fn mask_of(holds: [bool; LANES]) -> Self {
        f64x4::new(holds.map(mask_bits))
    }
    #[inline(always)]
    fn set_mask(mask: &mut Self, j: usize, holds: bool) {
        mask.set(j, mask_bits(holds));
    }
    #[inline(always)]
    fn bitmask(mask: Self) -> u32 {
        mask.to_bitmask()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rough_powers_are_within_their_stated_errors() {
        let mut worst_log: f64 = 0.0;
        let mut worst_exp: f64 = 0.0;
        for k in 0..20_000 {
            // 1e-30 … 1e30, and the integers (powers of two) exactly.
            let x = 10f64.powf(-30.0 + 60.0 * k as f64 / 20_000.0);
            worst_log = worst_log.max((log2_rough(x) - x.log2()).abs());
            let y = -60.0 + 120.0 * k as f64 / 20_000.0;
            worst_exp = worst_exp.max((exp2_rough(y) / y.exp2() - 1.0).abs());
        }
        assert!(worst_log < 2e-5, "{worst_log:e}");
        assert!(worst_exp < 4e-6, "{worst_exp:e}");
        assert!(log2_rough(0.0) <= -1022.0);
        assert_eq!(exp2_rough(0.0), exp2_rough(-0.0));
        assert_eq!(f64::power_of_two(-3.0), 0.125);
        // Continuous where the exponent steps.
        for k in [-20, -1, 0, 3] {
            let two = 2f64.powi(k);
            let (below, above) = (two * (1.0 - f64::EPSILON), two);
            assert!((log2_rough(above) - log2_rough(below)).abs() < 1e-14);
            let y = k as f64;
            let (a, b) = (exp2_rough(y - 1e-15), exp2_rough(y + 1e-15));
            assert!((a / b - 1.0).abs() < 1e-13, "{k}: {a} {b}");
        }
    }

    #[test]
    fn the_lanes_exp_is_libms_to_a_few_ulp_and_lanes_agree_with_one() {
        let mut worst: f64 = 0.0;
        for k in 0..40_001 {
            let x = -40.0 + 50.0 * k as f64 / 40_000.0;
            worst = worst.max((exp_lanes(x) / x.exp() - 1.0).abs());
        }
        assert!(
            worst < 4.0 * f64::EPSILON,
            "{:.2} ulp",
            worst / f64::EPSILON
        );
        assert_eq!(exp_lanes(-800.0), exp_lanes(-700.0));
        let x = [-3.7, 0.0, 1.25, -19.0];
        let four = exp_lanes(f64x4::new(x)).to_array();
        let two = exp2_rough(f64x4::new(x)).to_array();
        let split = f64x4::new([1e-9, 3.0, 0.75, 1e20]).exponent_and_significand();
        for i in 0..4 {
            assert_eq!(four[i], exp_lanes(x[i]));
            assert_eq!(two[i], exp2_rough(x[i]));
        }
        assert_eq!(split.0.to_array()[1], 1.0);
        assert_eq!(split.1.to_array()[2], 1.5);
    }
}
