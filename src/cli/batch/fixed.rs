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

/// 2^52, where a double's units are its last bit.
const TWO_52: f64 = (1u64 << 52) as f64;

/// Appends `value` with `decimals` decimals, as `format!("{value:.decimals$}")`.
pub(super) fn write(out: &mut Vec<u8>, value: f64, decimals: usize) {
    dispatch(out, value, decimals, None);
}

/// [`write`], then the byte `then` (a row's comma): one append for both.
pub(super) fn write_then(out: &mut Vec<u8>, value: f64, decimals: usize, then: u8) {
    dispatch(out, value, decimals, Some(then));
}

/// [`write_then`] if `then` is given, else [`write`].
pub(super) fn write_maybe_then(out: &mut Vec<u8>, value: f64, decimals: usize, then: Option<u8>) {
    match then {
        Some(then) => write_then(out, value, decimals, then),
        None => write(out, value, decimals),
    }
}

#[inline(always)]
fn dispatch(out: &mut Vec<u8>, value: f64, decimals: usize, then: Option<u8>) {
    // Each count of decimals compiled apart: its power of ten and digit
    // loop are constants.
    match decimals {
        0 => write_with::<0>(out, value, then),
        1 => write_with::<1>(out, value, then),
        2 => write_with::<2>(out, value, then),
        3 => write_with::<3>(out, value, then),
        4 => write_with::<4>(out, value, then),
        5 => write_with::<5>(out, value, then),
        6 => write_with::<6>(out, value, then),
        7 => write_with::<7>(out, value, then),
        8 => write_with::<8>(out, value, then),
        9 => write_with::<9>(out, value, then),
        _ => by_format(out, value, decimals, then),
    }
}

/// [`write`] with `D` decimals (at most 9), then `then` if given: inlined
/// where `D` is known (a column's decimals in SI), with no call but the
/// rare fallback's.
#[inline(always)]
pub(super) fn write_with<const D: usize>(out: &mut Vec<u8>, value: f64, then: Option<u8>) {
    match text::<D>(value) {
        Some(text) => append(out, text, then),
        None => by_format(out, value, D, then),
    }
}

/// `text`, then `then`, appended at once.
#[inline(always)]
fn append(out: &mut Vec<u8>, Text { mut room, mut len }: Text, then: Option<u8>) {
    if let Some(then) = then {
        room[len] = then;
        len += 1;
    }
    // The whole room copied (a fixed size: a few moves, no call), then cut
    // to the text: cheaper than a copy of its length.
    let at = out.len();
    out.extend_from_slice(&room);
    out.truncate(at + len);
}

/// The standard library's text, out of the common path.
#[cold]
#[inline(never)]
fn by_format(out: &mut Vec<u8>, value: f64, decimals: usize, then: Option<u8>) {
    let _ = write!(out, "{value:.decimals$}");
    out.extend(then);
}

/// Bytes a number's text may take here, and the byte after it: a sign, 16
/// digits before the point (the scaled value stays below 2^50 < 10^16), the
/// point and 9 decimals.
const ROOM: usize = 32;

/// A number's text at the start of a fixed room.
struct Text {
    room: [u8; ROOM],
    len: usize,
}

/// Powers of ten as integers, for splitting the scaled value at its point
/// and counting its digits.
const POWERS: [u64; 17] = {
    let mut powers = [1u64; 17];
    let mut i = 1;
    while i < powers.len() {
        powers[i] = powers[i - 1] * 10;
        i += 1;
    }
    powers
};

/// "00", "01", … "99": two digits a lookup.
const DIGIT_PAIRS: [u8; 200] = {
    let mut pairs = [0u8; 200];
    let mut i = 0;
    while i < 100 {
        pairs[2 * i] = b'0' + (i / 10) as u8;
        pairs[2 * i + 1] = b'0' + (i % 10) as u8;
        i += 1;
    }
    pairs
};

/// `value` with `D` decimals, if the scaled value's rounding is clear (see
/// the module's note); `None` for the standard library to write.
#[inline(always)]
fn text<const D: usize>(value: f64) -> Option<Text> {
    let scaled = value.abs() * SCALE[D];
    // Below 2^52, adding 2^52 leaves no bits for a fraction: the sum is the
    // scaled value rounded to an integer (to even at a half, which the
    // test below rules out), and its last bits are that integer.
    let shifted = scaled + TWO_52;
    let whole = shifted - TWO_52;
    // The product's error is at most half an ulp of `scaled`; a value
    // farther than that from a half rounds the same either way.
    let clear = (scaled - whole).abs() < 0.5 - scaled * f64::EPSILON;
    if !(scaled < LARGEST_SCALED && clear) {
        return None;
    }
    let whole = shifted.to_bits() - TWO_52.to_bits();
    let (integer, mut fraction) = (whole / POWERS[D], whole % POWERS[D]);
    let mut room = [0u8; ROOM];
    // `format!` keeps the sign of a negative value that rounds to zero,
    // and of −0.0.
    let sign = usize::from(value.is_sign_negative());
    room[0] = b'-';
    let point = put_integer(&mut room, sign, integer);
    let len = if D == 0 { point } else { point + 1 + D };
    let mut at = len;
    for _ in 0..D / 2 {
        at -= 2;
        let pair = 2 * (fraction % 100) as usize;
        fraction /= 100;
        room[at..at + 2].copy_from_slice(&DIGIT_PAIRS[pair..pair + 2]);
    }
    if D % 2 == 1 {
        room[point + 1] = b'0' + fraction as u8;
    }
    if D > 0 {
        room[point] = b'.';
    }
    Some(Text { room, len })
}

/// Writes `integer`'s digits into `room` from `from`; where they end.
#[inline(always)]
fn put_integer(room: &mut [u8; ROOM], from: usize, mut integer: u64) -> usize {
    let mut digits = 1;
    while digits < POWERS.len() && integer >= POWERS[digits] {
        digits += 1;
    }
    let end = from + digits;
    let mut at = end;
    while integer >= 10 {
        at -= 2;
        let pair = 2 * (integer % 100) as usize;
        integer /= 100;
        room[at..at + 2].copy_from_slice(&DIGIT_PAIRS[pair..pair + 2]);
    }
    if at > from {
        room[from] = b'0' + integer as u8;
    }
    end
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
    fn every_count_of_digits_prints_as_format_prints_it() {
        // Each length of the integer part (1 to 16 digits, the last below
        // 2^50 scaled), at and next to the powers of ten where it grows,
        // and values that round up into one more digit (9.9995 → 10.000).
        for decimals in 0..=10 {
            for digits in 0..17 {
                let power = 10f64.powi(digits);
                for value in [
                    power,
                    power - 1.0,
                    power * 1.234_567_89,
                    power - 0.5 / SCALE[decimals.min(9)],
                    power - 0.4 / SCALE[decimals.min(9)],
                    power - 0.6 / SCALE[decimals.min(9)],
                ] {
                    agrees(value, decimals);
                    agrees(-value, decimals);
                }
            }
        }
    }

    #[test]
    fn what_follows_a_number_is_appended_whole() {
        let mut out = b"x,".to_vec();
        write_then(&mut out, 127.42651, 3, b',');
        write_then(&mut out, -0.0, 6, b',');
        write_then(&mut out, 1e300, 2, b',');
        write_then(&mut out, 2.5, 12, b';');
        // The longest text written here: a sign, 16 digits and 9 decimals.
        write_then(&mut out, -(LARGEST_SCALED - 1.0) / 1e9, 9, b'z');
        write(&mut out, f64::NAN, 4);
        let expected = format!(
            "x,127.427,-0.000000,{:.2},2.500000000000;{:.9}zNaN",
            1e300,
            -(LARGEST_SCALED - 1.0) / 1e9
        );
        assert_eq!(String::from_utf8(out).unwrap(), expected);
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
