//! Numbers to a fixed count of decimals, written into a byte buffer, exactly
//! as `format!("{:.N}")` writes them, several times faster.
//!
//! Why our own: `ryu` and the standard library's shortest forms answer
//! another question (the shortest text that reads back), and the standard
//! library's exact fixed form costs a multi-precision fallback on some
//! values; a batch prints a dozen fixed-decimal numbers a row. The value
//! scaled by 10^N is rounded in floating point, which is the exact answer
//! whenever the scaled value is not within its own rounding error of a
//! half; those few, and anything huge or not finite, go to the standard
//! library. So the text is `format!`'s, byte for byte (tested below).

use std::io::Write;

/// Powers of ten that are exact doubles, for the decimals a batch prints.
const SCALE: [f64; 10] = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9];

/// Scaled values below this (2^50) keep a fraction with room to spare: the
/// product's rounding error (under 2^-3 here) stays far from the half.
const LARGEST_SCALED: f64 = (1u64 << 50) as f64;

/// Appends `value` with `decimals` decimals, as `format!("{value:.decimals$}")`.
pub(super) fn write(out: &mut Vec<u8>, value: f64, decimals: usize) {
    if let Some(&scale) = SCALE.get(decimals) {
        let scaled = value.abs() * scale;
        let whole = round(scaled);
        // The product's error is at most half an ulp of `scaled`; a value
        // farther than that from a half rounds the same either way.
        let clear = (scaled - whole).abs() < 0.5 - scaled * f64::EPSILON;
        if scaled < LARGEST_SCALED && clear {
            write_scaled(out, value.is_sign_negative(), whole as u64, decimals);
            return;
        }
    }
    let _ = write!(out, "{value:.decimals$}");
}

/// `x.round()` (half away from zero; ±0 alike), without its library call
/// (the baseline x86-64 has no rounding instruction): below 2^52 from the
/// truncation, the fraction left being exact.
#[inline]
pub(super) fn round(x: f64) -> f64 {
    if x.abs() < (1u64 << 52) as f64 {
        let truncated = x as i64 as f64;
        let fraction = x - truncated;
        if fraction >= 0.5 {
            truncated + 1.0
        } else if fraction <= -0.5 {
            truncated - 1.0
        } else {
            truncated
        }
    } else {
        x.round()
    }
}

/// `digits` / 10^decimals, signed as `negative` says (`format!` keeps the
/// sign of a negative value that rounds to zero, and of −0.0).
fn write_scaled(out: &mut Vec<u8>, negative: bool, digits: u64, decimals: usize) {
    if negative {
        out.push(b'-');
    }
    let mut text = itoa::Buffer::new();
    let text = text.format(digits).as_bytes();
    if decimals == 0 {
        out.extend_from_slice(text);
        return;
    }
    if text.len() > decimals {
        let (whole, fraction) = text.split_at(text.len() - decimals);
        out.extend_from_slice(whole);
        out.push(b'.');
        out.extend_from_slice(fraction);
    } else {
        // 5 at 3 decimals is 0.005.
        out.extend_from_slice(b"0.");
        out.extend(std::iter::repeat_n(b'0', decimals - text.len()));
        out.extend_from_slice(text);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fixed(value: f64, decimals: usize) -> String {
        let mut out = Vec::new();
        write(&mut out, value, decimals);
        String::from_utf8(out).unwrap()
    }

    fn agrees(value: f64, decimals: usize) {
        assert_eq!(
            fixed(value, decimals),
            format!("{value:.decimals$}"),
            "{value:e} to {decimals}"
        );
    }

    use crate::numerics::xorshift::bits as xorshift;

    #[test]
    fn round_is_the_library_s() {
        let mut next = xorshift(0x9e37_79b9_7f4a_7c15);
        let halves = [
            0.5,
            -0.5,
            1.5,
            -2.5,
            4503599627370495.5,
            -4503599627370495.5,
        ];
        let edges = [
            0.0,
            -0.0,
            0.49999999999999994,
            -0.49999999999999994,
            4503599627370496.0,
        ];
        let specials = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e300, -1e300];
        let random = std::iter::repeat_with(|| {
            let state = next();
            let unit = (state >> 11) as f64 / (1u64 << 53) as f64;
            (unit - 0.5) * 10f64.powi((state % 20) as i32 - 3)
        });
        let values = halves.into_iter().chain(edges).chain(specials);
        for x in values.chain(random.take(100_000)) {
            let (ours, library) = (round(x), x.round());
            assert!(
                ours == library || ours.is_nan() && library.is_nan(),
                "{x:e}"
            );
        }
    }

    #[test]
    fn edges_print_as_format_prints_them() {
        let edges = [
            0.0,
            -0.0,
            -0.0004,
            0.0005,
            0.0015,
            0.0025,
            -0.0005,
            1.0005,
            2.5,
            0.5,
            1.5,
            -2.5,
            127.4265,
            1e-320,
            -1e-320,
            0.999_999_5,
            9.999_5,
            99.9995,
            1e14,
            1e15 + 0.5,
            4.5e15,
            1e300,
            -1e300,
            f64::MAX,
            f64::MIN_POSITIVE,
            f64::NAN,
            -f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for value in edges {
            for decimals in 0..12 {
                agrees(value, decimals);
            }
        }
    }

    #[test]
    fn random_values_and_exact_halves_print_as_format_prints_them() {
        let mut next = xorshift(0x2545_f491_4f6c_dd1d);
        for _ in 0..200_000 {
            let bits = next();
            let decimals = (bits % 10) as usize;
            // Values of every size a batch prints, and raw bit patterns.
            let unit = (bits >> 11) as f64 / (1u64 << 53) as f64;
            let size = 10f64.powi((bits % 19) as i32 - 6);
            agrees((unit - 0.3) * size, decimals);
            agrees(f64::from_bits(next()), decimals);
            // Exact binary halves at the last printed digit (ties).
            let tie = ((next() % 100_000) as f64 + 0.5) / SCALE[decimals.min(3)];
            agrees(tie, decimals.min(3));
            agrees(-tie, decimals.min(3));
        }
    }
}
