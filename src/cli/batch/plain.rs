//! A cell's plain decimal number (`43.1950`, `-0.298784`), read as
//! `str::parse::<f64>` reads it at a fraction of its cost: up to 15
//! digits make an integer below 2^53, and one division by an exact power
//! of ten rounds it correctly (Clinger's fast path), which is the answer
//! `parse` gives. Anything else (an exponent, a unit, more digits) is
//! left to the full readers.

/// Powers of ten exact as doubles, for up to 15 decimals.
const POWERS: [f64; 16] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
];

/// Digits that keep the integer below 2^53.
const MAX_DIGITS: usize = 15;

/// `text` as `text.parse::<f64>()` reads it, if it is a sign, digits, and
/// optionally a point and more digits (15 digits at most); else `None`.
pub(super) fn plain_decimal(text: &str) -> Option<f64> {
    let bytes = text.as_bytes();
    let (negative, rest) = match bytes.first()? {
        b'-' => (true, &bytes[1..]),
        b'+' => (false, &bytes[1..]),
        _ => (false, bytes),
    };
    // 15 digits and a point at most: the integer cannot overflow below.
    if rest.len() > MAX_DIGITS + 1 {
        return None;
    }
    let mut integer = 0u64;
    let mut digits = |part: &[u8]| {
        for &byte in part {
            let digit = byte.wrapping_sub(b'0');
            if digit >= 10 {
                return false;
            }
            integer = integer * 10 + u64::from(digit);
        }
        true
    };
    // Digits, or digits, a point and digits.
    let decimals = match rest.iter().position(|&b| b == b'.') {
        None if !rest.is_empty() && digits(rest) => 0,
        Some(point) if point > 0 && point + 1 < rest.len() => {
            let (whole, fraction) = (&rest[..point], &rest[point + 1..]);
            if !(digits(whole) && digits(fraction)) {
                return None;
            }
            fraction.len()
        }
        _ => return None,
    };
    if rest.len() - usize::from(decimals > 0) > MAX_DIGITS {
        return None;
    }
    let magnitude = integer as f64 / POWERS[decimals];
    Some(if negative { -magnitude } else { magnitude })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn agrees(text: &str) {
        if let Some(value) = plain_decimal(text) {
            let parsed: f64 = text.parse().unwrap_or(f64::NAN);
            assert_eq!(value.to_bits(), parsed.to_bits(), "{text}");
        }
    }

    #[test]
    fn plain_decimals_read_as_parse_reads_them() {
        for text in [
            "0",
            "-0",
            "+0",
            "-0.0",
            "43.1950",
            "-0.298784",
            "000012.5000",
            "7",
        ] {
            assert!(plain_decimal(text).is_some(), "{text}");
            agrees(text);
        }
        // 15 digits are read; 16, exponents, units, stray points are not.
        assert!(plain_decimal("123456789.012345").is_some());
        assert!(plain_decimal("999999999999999").is_some());
        for text in [
            "",
            "-",
            "+",
            ".",
            "5.",
            ".5",
            "-.5",
            "1.2.3",
            "1e5",
            "1E-3",
            "103mph",
            " 1",
            "1 ",
            "1234567890.123456",
            "9999999999999999",
            "nan",
            "inf",
            "0x10",
            "1,5",
            "--1",
            "1..2",
            "12.",
            "1 2",
            "1\u{e9}",
            "\u{e9}1",
            "1:5",
            "1/5",
            "0.000000000000000",
            "123456789012345.6",
        ] {
            assert_eq!(plain_decimal(text), None, "{text}");
        }
        // Random decimals of every length and place of the point.
        let mut next = crate::numerics::xorshift::bits(0x2545_f491_4f6c_dd1d);
        for _ in 0..300_000 {
            let bits = next();
            let digits = 1 + (bits % 15) as usize;
            let number = next() % 10u64.pow(digits as u32);
            let mut text = format!("{number:0digits$}");
            let point = (bits >> 8) as usize % (digits + 1);
            if point > 0 && point < digits {
                text.insert(digits - point, '.');
            }
            if bits & (1 << 40) != 0 {
                text.insert(0, '-');
            }
            assert!(plain_decimal(&text).is_some(), "{text}");
            agrees(&text);
        }
    }
}
