//! Four numbers in one AVX register, for the lock-step loop's AVX2 clone.
//! Every operation is an exactly rounded one (no fused multiply-add), the
//! same as [`super::Lane`]'s SSE2 pairs, so that both give the same bits.
//!
//! Its operations are AVX instructions, written with `core::arch`: a value
//! may only be operated on where the CPU has AVX2. The type is private to
//! the crate, and used by one function, `integrate_lanes_avx2`
//! ([`super::super::ode::lanes`]), entered only once AVX2 is detected and
//! compiled with `#[target_feature(enable = "avx2")]`; everything here is
//! `#[inline(always)]` into it. A closure or function left out of line
//! would call each instruction as a function (6× slower, measured): `objdump
//! -d target/*/release/homerun | grep -c 'call.*core_arch::x86::avx'` must
//! print 0.

use std::arch::x86_64::*;
use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

use super::{EXPONENT_SHIFT, LANES, LaneReal, ONE_BITS, Real, SIGNIFICAND_BITS, TWO_52};

/// Four f64 in one AVX register (see the module).
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct Avx2Lane(__m256d);

/// Binary operators, one instruction each.
macro_rules! operator {
    ($trait:ident, $method:ident, $instruction:ident) => {
        impl $trait for Avx2Lane {
            type Output = Self;
            #[inline(always)]
            fn $method(self, other: Self) -> Self {
                // SAFETY: only run where AVX2 is (see the type).
                Avx2Lane(unsafe { $instruction(self.0, other.0) })
            }
        }
    };
}
operator!(Add, add, _mm256_add_pd);
operator!(Sub, sub, _mm256_sub_pd);
operator!(Mul, mul, _mm256_mul_pd);
operator!(Div, div, _mm256_div_pd);
operator!(BitAnd, bitand, _mm256_and_pd);
operator!(BitOr, bitor, _mm256_or_pd);

impl Neg for Avx2Lane {
    type Output = Self;
    /// The sign bit flipped, as `wide`'s.
    #[inline(always)]
    fn neg(self) -> Self {
        // SAFETY: only run where AVX2 is (see the type).
        Avx2Lane(unsafe { _mm256_xor_pd(self.0, _mm256_set1_pd(-0.0)) })
    }
}

impl Not for Avx2Lane {
    type Output = Self;
    #[inline(always)]
    fn not(self) -> Self {
        // SAFETY: only run where AVX2 is (see the type).
        Avx2Lane(unsafe { _mm256_xor_pd(self.0, _mm256_castsi256_pd(_mm256_set1_epi64x(-1))) })
    }
}

impl Avx2Lane {
    #[inline(always)]
    fn compare<const PREDICATE: i32>(self, other: Self) -> Self {
        // SAFETY: only run where AVX2 is (see the type).
        Avx2Lane(unsafe { _mm256_cmp_pd::<PREDICATE>(self.0, other.0) })
    }
    #[inline(always)]
    fn bits(self) -> __m256i {
        // SAFETY: only run where AVX2 is (see the type).
        unsafe { _mm256_castpd_si256(self.0) }
    }
    #[inline(always)]
    fn from_bits(bits: __m256i) -> Self {
        // SAFETY: only run where AVX2 is (see the type).
        Avx2Lane(unsafe { _mm256_castsi256_pd(bits) })
    }
    #[inline(always)]
    fn bits_splat(bits: u64) -> __m256i {
        // SAFETY: only run where AVX2 is (see the type).
        unsafe { _mm256_set1_epi64x(bits as i64) }
    }
}

impl Real for Avx2Lane {
    type Mask = Self;

    #[inline(always)]
    fn splat(x: f64) -> Self {
        // SAFETY: only run where AVX2 is (see the type).
        Avx2Lane(unsafe { _mm256_set1_pd(x) })
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        // SAFETY: only run where AVX2 is (see the type).
        Avx2Lane(unsafe { _mm256_sqrt_pd(self.0) })
    }
    /// The sign bit cleared, as `wide`'s.
    #[inline(always)]
    fn abs(self) -> Self {
        self & Self::from_bits(Self::bits_splat(!(1 << 63)))
    }
    /// As SSE2's `maxpd` (`wide`'s `fast_max`): `other` where either is
    /// NaN.
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        // SAFETY: only run where AVX2 is (see the type).
        Avx2Lane(unsafe { _mm256_max_pd(self.0, other.0) })
    }
    #[inline(always)]
    fn min(self, other: Self) -> Self {
        // SAFETY: only run where AVX2 is (see the type).
        Avx2Lane(unsafe { _mm256_min_pd(self.0, other.0) })
    }
    #[inline(always)]
    fn exp(self) -> Self {
        super::exp_lanes(self)
    }
    #[inline(always)]
    fn lt(self, other: Self) -> Self {
        self.compare::<_CMP_LT_OQ>(other)
    }
    #[inline(always)]
    fn le(self, other: Self) -> Self {
        self.compare::<_CMP_LE_OQ>(other)
    }
    #[inline(always)]
    fn eq(self, other: Self) -> Self {
        self.compare::<_CMP_EQ_OQ>(other)
    }
    #[inline(always)]
    fn select(mask: Self, if_true: Self, if_false: Self) -> Self {
        // SAFETY: only run where AVX2 is (see the type).
        Avx2Lane(unsafe { _mm256_blendv_pd(if_false.0, if_true.0, mask.0) })
    }
    #[inline(always)]
    fn any(mask: Self) -> bool {
        Self::bitmask(mask) != 0
    }
    #[inline(always)]
    fn exponent_and_significand(self) -> (Self, Self) {
        let bits = self.bits();
        let two_52 = Self::splat(TWO_52);
        // SAFETY: only run where AVX2 is (see the type).
        let (exponent, significand) = unsafe {
            (
                _mm256_or_si256(
                    _mm256_srli_epi64::<{ EXPONENT_SHIFT as i32 }>(bits),
                    two_52.bits(),
                ),
                _mm256_or_si256(
                    _mm256_and_si256(bits, Self::bits_splat(SIGNIFICAND_BITS)),
                    Self::bits_splat(ONE_BITS),
                ),
            )
        };
        let biased = Self::from_bits(exponent) - two_52;
        (biased - Self::splat(1023.0), Self::from_bits(significand))
    }
    #[inline(always)]
    fn power_of_two(n: Self) -> Self {
        let biased = (n + Self::splat(TWO_52 + 1023.0)).bits();
        // SAFETY: only run where AVX2 is (see the type).
        Self::from_bits(unsafe { _mm256_slli_epi64::<{ EXPONENT_SHIFT as i32 }>(biased) })
    }
}

impl LaneReal for Avx2Lane {
    /// Through memory: no instruction at all.
    #[inline(always)]
    fn from_array(lanes: [f64; LANES]) -> Self {
        // SAFETY: __m256d is four f64, any bits.
        Avx2Lane(unsafe { std::mem::transmute::<[f64; LANES], __m256d>(lanes) })
    }
    #[inline(always)]
    fn to_array(self) -> [f64; LANES] {
        // SAFETY: as above.
        unsafe { std::mem::transmute::<__m256d, [f64; LANES]>(self.0) }
    }
    #[inline(always)]
    fn get(&self, j: usize) -> f64 {
        // SAFETY: the type is one __m256d, laid out as four f64.
        let lanes = unsafe { &*(self as *const Self).cast::<[f64; LANES]>() };
        lanes[j]
    }
    #[inline(always)]
    fn set(&mut self, j: usize, x: f64) {
        // SAFETY: the type is one __m256d, laid out as four f64.
        let lanes = unsafe { &mut *(self as *mut Self).cast::<[f64; LANES]>() };
        lanes[j] = x;
    }
    #[inline(always)]
    fn mask_of(holds: [bool; LANES]) -> Self {
        Self::from_array(holds.map(super::mask_bits))
    }
    #[inline(always)]
    fn set_mask(mask: &mut Self, j: usize, holds: bool) {
        mask.set(j, super::mask_bits(holds));
    }
    #[inline(always)]
    fn bitmask(mask: Self) -> u32 {
        // SAFETY: only run where AVX2 is (see the type).
        unsafe { _mm256_movemask_pd(mask.0) as u32 }
    }
}
