//! A number's shortest text, exactly as `{x}` (`Display`) writes it, at a
//! third of the cost: the digits from `zmij` (Schubfach), written in
//! `Display`'s plain decimal notation. A 64×64 surface's CSV is 12 288
//! such numbers; through `Display` they took a fifth of the command.
//!
//! Both choose the shortest digits that read back as the number and, of
//! those, the nearest; they differ only where two are equally near: `zmij`
//! (like `ryu`) rounds such a tie to even, `Display` up
//! (1658206780088562.25 is …562.2 against …562.3). A tie needs the number's
//! exact decimal value to have at most 18 significant digits, which
//! [`may_tie`] rules out for nearly every number a computation gives; the
//! rest go through `Display` itself.

use std::fmt::Write as _;

/// Appends `x` as `write!(text, "{x}")` would.
pub fn push(text: &mut String, x: f64) {
    if !x.is_finite() || may_tie(x) {
        let _ = write!(text, "{x}");
        return;
    }
    let mut buffer = zmij::Buffer::new();
    let digits = buffer.format_finite(x);
    // zmij writes plain decimals for a first digit from 10⁻⁵ to 10¹⁵:
    // well inside, no exponent to look for (a search of the text, a
    // quarter of a number's cost).
    if (1e-4..1e15).contains(&x.abs()) {
        text.push_str(digits.strip_suffix(".0").unwrap_or(digits));
        return;
    }
    match digits.split_once('e') {
        // "123.0" or "0.00123": Display's own layout, but for the ".0".
        None => text.push_str(digits.strip_suffix(".0").unwrap_or(digits)),
        Some((significand, exponent)) => scientific(text, significand, exponent),
    }
}

/// `x` as `x.to_string()` gives it.
pub fn text(x: f64) -> String {
    let mut text = String::with_capacity(24);
    push(&mut text, x);
    text
}

/// Whether `x`'s exact decimal value could lie midway between two shortest
/// candidates. x = m·2^q with m odd: for q < 0 its exact decimal has the
/// significant digits of m·5^(−q), so a tie (at most 17 digits and a
/// final 5) needs m·5^(−q) < 10^18 (m·4^(−q) ≥ 2^60 rules it out at
/// once, for nearly every number); a
/// whole number below 2^53 is its own shortest text (any shorter one is
/// at least 1 away, outside its half-ulp ≤ 0.5), so it cannot tie.
fn may_tie(x: f64) -> bool {
    let bits = x.to_bits() & !(1 << 63);
    let (biased, fraction) = ((bits >> 52) as i32, bits & ((1 << 52) - 1));
    let (m, q) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1 << 52), biased - 1075)
    };
    if m == 0 {
        return true;
    }
    let (m, q) = (m >> m.trailing_zeros(), q + m.trailing_zeros() as i32);
    if q >= 0 {
        return x.abs() >= 9_007_199_254_740_992.0;
    }
    let bits_of_m = 64 - m.leading_zeros() as i32;
    if bits_of_m - 1 + 2 * -q >= 60 {
        return false;
    }
    // Here −q < 30: m·5^(−q) < 2^53·5^30 fits a u128.
    u128::from(m) * 5u128.pow(-q as u32) < 10u128.pow(18)
}

/// "1.25e-7" as Display writes it: "0.000000125" (no exponent, ever).
fn scientific(text: &mut String, significand: &str, exponent: &str) {
    let (sign, significand) = match significand.strip_prefix('-') {
        Some(rest) => ("-", rest),
        None => ("", significand),
    };
    let (first, rest) = significand.split_once('.').unwrap_or((significand, ""));
    let rest = rest.trim_end_matches('0');
    let exponent: i32 = exponent.parse().expect("zmij writes an integer exponent");
    // The value is 0.DIGITS × 10^point, DIGITS = first + rest.
    let point = exponent + first.len() as i32;
    let count = (first.len() + rest.len()) as i32;
    text.push_str(sign);
    if point <= 0 {
        text.push_str("0.");
        text.extend(std::iter::repeat_n('0', (-point) as usize));
        text.push_str(first);
        text.push_str(rest);
    } else if point < count {
        let (left, right) = rest.split_at((point - first.len() as i32) as usize);
        text.push_str(first);
        text.push_str(left);
        text.push('.');
        text.push_str(right);
    } else {
        text.push_str(first);
        text.push_str(rest);
        text.extend(std::iter::repeat_n('0', (point - count) as usize));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn display(x: f64) -> String {
        format!("{x}")
    }

    /// Every kind of number prints as Display prints it: random bit
    /// patterns (every exponent, subnormals), random values over 40 decades,
    /// short decimals and quarter-steps (where ties live), and the edges.
    #[test]
    fn writes_what_display_writes() {
        let mut state = 0x9E37_79B9_7F4A_7C15_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut mismatches = Vec::new();
        let mut fallbacks = 0;
        for n in 0..400_000 {
            let r = next();
            let x = match n % 4 {
                0 => f64::from_bits(r),
                1 => (r >> 11) as f64 / (1u64 << 53) as f64 * 10f64.powi((r % 40) as i32 - 20),
                2 => (r % 100_000_000_000_000_000) as f64 / 10f64.powi((r >> 58) as i32),
                _ => (r >> 20) as f64 * 0.25 + [0.0, 0.125, 0.0625][(r % 3) as usize],
            };
            let x = if n % 8 == 5 { -x } else { x };
            if n % 4 == 1 && x.abs() < 1e12 {
                fallbacks += usize::from(may_tie(x));
            }
            if text(x) != display(x) {
                mismatches.push((x, text(x), display(x)));
            }
        }
        let edges = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.1,
            1e-7,
            1.25e-7,
            1e15,
            1e16,
            // Where the plain decimals' shortcut ends.
            1e-4,
            9.999_999_999_999_999e-5,
            -1.000_000_000_000_001e-4,
            999_999_999_999_999.9,
            -999_999_999_999_999.9,
            1.000_000_000_000_000_2e15,
            1.5e300,
            f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            9_007_199_254_740_993.0,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for x in edges {
            if text(x) != display(x) {
                mismatches.push((x, text(x), display(x)));
            }
        }
        assert!(
            mismatches.is_empty(),
            "{:?}",
            &mismatches[..mismatches.len().min(5)]
        );
        // Numbers as a computation gives them (below 10^12) take Display's
        // path only if their last bits are zeros (a short exact decimal):
        // 22 of 100 000 here.
        assert!(fallbacks < 100, "{fallbacks}");
    }

    /// Exact ties go to Display, whose digits differ from zmij's there.
    #[test]
    fn ties_round_as_display_rounds() {
        // Exactly …562.25 and …417.125, midway between two 17-digit texts.
        let (tie, other_tie) = (
            1_658_206_780_088_562.0 + 0.25,
            201_409_170_638_417.0 + 0.125,
        );
        for x in [tie, other_tie, 0.5, 2.5] {
            assert!(may_tie(x), "{x}");
            assert_eq!(text(x), display(x));
        }
        assert_eq!(text(tie), "1658206780088562.3");
        let mut buffer = zmij::Buffer::new();
        assert_eq!(buffer.format_finite(tie), "1658206780088562.2");
    }

    /// What a surface's CSV holds: the fast path, in plain notation.
    #[test]
    fn surface_numbers() {
        for (x, shown) in [
            (0.05 / 63.0, "0.0007936507936507937"),
            (-0.6, "-0.6"),
            (3.5311946820637163, "3.5311946820637163"),
            (0.0000123456789, "0.0000123456789"),
            (123456789012345680.0, "123456789012345680"),
        ] {
            assert_eq!(text(x), shown);
        }
        assert!(!may_tie(0.05 / 63.0) && !may_tie(-0.6));
    }
}
