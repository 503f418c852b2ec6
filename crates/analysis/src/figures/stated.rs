//! The paper's stated numbers beside ours, and a figure's notes, in the
//! units shown: under baseball units a range gained in ft, an undercut in
//! in, a speed in mph, a spin in rpm and an angle in °, so that a figure's
//! notes agree with its axes (issue 36). Words in double quotes are the
//! paper's own and stay as it printed them.

use super::Comparison;
use units::{Quantity, Unit, UnitSystem};

/// A rate the paper states per unit of speed ("range gained per 1 m/s").
const PER_SPEED: &str = "per 1 m/s";

/// `c` in the units shown: its numbers, its unit and the numbers its words
/// quote. The paper's number is rounded to the digits it gave, two at
/// least (5 m per 1 m/s is 7.3 ft per 1 mph, 44.34 m/s 99.19 mph); ours
/// is left whole.
pub fn comparison(c: &Comparison, shown: UnitSystem) -> Comparison {
    if shown == UnitSystem::Si {
        return c.clone();
    }
    let (quantity, si_scale) = match c.unit {
        "m/s" => (Quantity::Speed, 1.0),
        "rad" => (Quantity::Angle, 1.0),
        "rad/s" => (Quantity::Spin, 1.0),
        "mm" => (Quantity::Size, 1e-3),
        "m" if names_the_undercut(&c.what) => (Quantity::Size, 1.0),
        "m" => (Quantity::Distance, 1.0),
        _ => (Quantity::Unchanged, 1.0),
    };
    let mut what = c.what.clone();
    // Per 1 m/s is per 2.237 mph: the rate per 1 mph instead.
    let per = if what.contains(PER_SPEED) {
        what = what.replace(PER_SPEED, "per 1 mph");
        Quantity::Speed.in_system(shown).show(1.0)
    } else {
        1.0
    };
    let unit = quantity.in_system(shown);
    if unit.is_identity() {
        return Comparison {
            what: words(&what, shown),
            ..c.clone()
        };
    }
    let show = |si: f64| unit.show(si * si_scale) / per;
    Comparison {
        what: words(&what, shown),
        unit: unit.symbol,
        paper: significant(show(c.paper), stated_digits(c.paper).max(2)),
        ours: show(c.ours),
    }
}

/// `number` with `unit` as every pane writes it: a degree on its number
/// ("25.7°"), another unit a space away, none where there is none (C_D).
pub fn with_unit(number: &str, unit: &str) -> String {
    match unit {
        "" => number.to_owned(),
        "°" => format!("{number}°"),
        _ => format!("{number} {unit}"),
    }
}

/// Whether a stated length is the undercut E (in inches), not a range (ft).
fn names_the_undercut(what: &str) -> bool {
    what.contains("undercut")
        || what
            .split(|c: char| !(c.is_alphanumeric() || c == '_'))
            .any(|word| word == "E")
}

/// How many significant digits the paper gave `value` (5 → 1, 0.064 → 2,
/// 44.34 → 4).
fn stated_digits(value: f64) -> i32 {
    let text = format!("{:.6}", value.abs());
    let text = text.trim_end_matches('0').trim_end_matches('.');
    text.chars()
        .filter(char::is_ascii_digit)
        .skip_while(|&c| c == '0')
        .count()
        .max(1) as i32
}

/// `value` rounded to `digits` significant digits.
fn significant(value: f64, digits: i32) -> f64 {
    if value == 0.0 || !value.is_finite() {
        return value;
    }
    let scale = 10f64.powi(digits - 1 - value.abs().log10().floor() as i32);
    (value * scale).round() / scale
}

/// The SI units a note's numbers are written with, longest first (" m/s"
/// before " m"), and what each measures.
const UNITS: [(&str, Quantity, f64); 5] = [
    (" m/s", Quantity::Speed, 1.0),
    (" rad/s", Quantity::Spin, 1.0),
    (" rad", Quantity::Angle, 1.0),
    (" mm", Quantity::Size, 1e-3),
    (" m", Quantity::Distance, 1.0),
];

/// A note's words in the units shown: each number written with an SI unit
/// ("42 m/s", "E = 0.0265 m", "from 35 to 45 m/s") converted to about its
/// digits; a length under a metre is an undercut or a size (in), longer a
/// distance (ft). Words in double quotes (the paper's) stay as they are.
pub fn words(text: &str, shown: UnitSystem) -> String {
    if shown == UnitSystem::Si {
        return text.to_owned();
    }
    text.split('"')
        .enumerate()
        .map(|(k, part)| {
            if k % 2 == 1 {
                part.to_owned()
            } else {
                unquoted(part, shown)
            }
        })
        .collect::<Vec<_>>()
        .join("\"")
}

/// A number in `text` at bytes `start..end`, and the SI unit after it.
struct Number {
    start: usize,
    end: usize,
    unit: Option<(&'static str, Quantity, f64)>,
}

/// The numbers in `text`: a sign (−, +, -) and digits with a point.
fn numbers(text: &str) -> Vec<Number> {
    let mut found = Vec::new();
    let mut chars = text.char_indices().peekable();
    let mut before: Option<char> = None;
    while let Some((at, c)) = chars.next() {
        let signed =
            matches!(c, '−' | '+' | '-') && chars.peek().is_some_and(|(_, n)| n.is_ascii_digit());
        let starts = (c.is_ascii_digit() || signed)
            && before.is_none_or(|b| !(b.is_alphanumeric() || b == '.' || b == '_'));
        before = Some(c);
        if !starts {
            continue;
        }
        let mut end = at + c.len_utf8();
        while let Some(&(k, n)) = chars.peek() {
            if !(n.is_ascii_digit() || n == '.') {
                break;
            }
            end = k + n.len_utf8();
            before = Some(n);
            chars.next();
        }
        let rest = &text[end..];
        let unit = UNITS.into_iter().find(|(symbol, _, _)| {
            rest.starts_with(symbol)
                && rest[symbol.len()..]
                    .chars()
                    .next()
                    .is_none_or(|n| !n.is_alphanumeric())
        });
        found.push(Number {
            start: at,
            end,
            unit,
        });
    }
    found
}

fn unquoted(text: &str, shown: UnitSystem) -> String {
    let numbers = numbers(text);
    let mut out = String::with_capacity(text.len());
    let mut from = 0;
    for (k, number) in numbers.iter().enumerate() {
        // "from 35 to 45 m/s": the 35 takes the 45's unit.
        let next = numbers.get(k + 1);
        let ranged = next.filter(|n| &text[number.end..n.start] == " to ");
        let (unit, with_symbol) = match (number.unit, ranged.and_then(|n| n.unit)) {
            (Some(unit), _) => (unit, true),
            (None, Some(unit)) => (unit, false),
            (None, None) => continue,
        };
        out.push_str(&text[from..number.start]);
        out.push_str(&converted(
            &text[number.start..number.end],
            unit,
            with_symbol,
            shown,
        ));
        from = if with_symbol {
            number.end + unit.0.len()
        } else {
            number.end
        };
    }
    out.push_str(&text[from..]);
    out
}

/// One number written with an SI unit, in the units shown.
fn converted(
    number: &str,
    (_, quantity, si_scale): (&'static str, Quantity, f64),
    with_symbol: bool,
    shown: UnitSystem,
) -> String {
    let minus = number.starts_with('−');
    let plus = number.starts_with('+');
    let digits = number.trim_start_matches(['−', '+']);
    let Ok(value) = digits.parse::<f64>() else {
        return number.to_owned();
    };
    let si = if minus { -value } else { value } * si_scale;
    let quantity = match quantity {
        Quantity::Distance if si.abs() < 1.0 => Quantity::Size,
        q => q,
    };
    let unit: Unit = quantity.in_system(shown);
    let decimals = digits.split_once('.').map_or(0, |(_, d)| d.len());
    let scale_digits = (si_scale.log10().round() as i32).unsigned_abs() as usize;
    let decimals = unit.decimals(decimals + scale_digits);
    let shown_value = unit.show(si);
    let text = format!("{:.decimals$}", shown_value.abs());
    let sign = match (shown_value < 0.0, minus, plus) {
        (true, true, _) => "−",
        (true, false, _) => "-",
        (false, _, true) => "+",
        _ => "",
    };
    if !with_symbol {
        return format!("{sign}{text}");
    }
    let gap = if unit.symbol == "°" { "" } else { " " };
    format!("{sign}{text}{gap}{}", unit.symbol)
}

#[cfg(test)]
mod tests {
    use super::*;

    const IMPERIAL: UnitSystem = UnitSystem::Imperial;

    fn stated(what: &str, unit: &'static str, paper: f64, ours: f64) -> Comparison {
        Comparison {
            what: what.to_owned(),
            unit,
            paper,
            ours,
        }
    }

    #[test]
    fn a_rate_per_metre_per_second_is_feet_per_mph() {
        let c = stated(
            "range gained per 1 m/s of bat speed near 30 m/s",
            "m",
            5.0,
            4.01,
        );
        let shown = comparison(&c, IMPERIAL);
        assert_eq!(
            shown.what,
            "range gained per 1 mph of bat speed near 67 mph"
        );
        assert_eq!(shown.unit, "ft");
        assert_eq!(shown.paper, 7.3);
        assert!((shown.ours - 4.01 / 0.3048 * 0.44704).abs() < 1e-9);
        // SI as the paper has it.
        assert_eq!(comparison(&c, UnitSystem::Si), c);
    }

    #[test]
    fn stated_lengths_are_undercuts_in_inches_or_ranges_in_feet() {
        let level = stated(
            "bat speed where a level swing (ψ_opt = 0) becomes optimal",
            "m/s",
            42.0,
            40.2,
        );
        let level = comparison(&level, IMPERIAL);
        assert_eq!((level.unit, level.paper), ("mph", 94.0));
        let halts = stated(
            "μ = 0.35: slip halts during impact below E",
            "m",
            0.064,
            0.06,
        );
        assert_eq!(comparison(&halts, IMPERIAL).unit, "in");
        let ab = stated("undercut from A to B", "mm", 6.5, 6.0);
        let ab = comparison(&ab, IMPERIAL);
        assert_eq!((ab.unit, ab.paper), ("in", 0.26));
        let less = stated("range of A less range of B", "m", 7.3, 7.0);
        assert_eq!(comparison(&less, IMPERIAL).unit, "ft");
        let zeta = stated("ζ at E = 0.040 m, μ = 0.35–0.5", "rad", 0.731, 0.73);
        let zeta = comparison(&zeta, IMPERIAL);
        assert_eq!(zeta.what, "ζ at E = 1.57 in, μ = 0.35–0.5");
        assert_eq!((zeta.unit, zeta.paper), ("°", 41.9));
        // A difference the paper gives in degrees stays so.
        let degrees = stated("their difference", "°", 8.6, 8.0);
        assert_eq!(comparison(&degrees, IMPERIAL), degrees);
        assert_eq!(with_unit("25.7", "°"), "25.7°");
        assert_eq!(with_unit("99.2", "mph"), "99.2 mph");
        assert_eq!(with_unit("0.15", ""), "0.15");
    }

    #[test]
    fn a_notes_numbers_are_converted_and_the_papers_quotes_kept() {
        assert_eq!(
            words(
                "paper: ψ_opt falls to 0 at 42 m/s and below it after (\"increasing the bat speed by only 1 m/s increases the optimal range by nearly 5 m\")",
                IMPERIAL
            ),
            "paper: ψ_opt falls to 0 at 94 mph and below it after (\"increasing the bat speed by only 1 m/s increases the optimal range by nearly 5 m\")"
        );
        assert_eq!(
            words(
                "range gained from −200 to 200 rad/s (\"about 8 m\")",
                IMPERIAL
            ),
            "range gained from −1910 to 1910 rpm (\"about 8 m\")"
        );
        assert_eq!(words("from 35 to 45 m/s", IMPERIAL), "from 78 to 101 mph");
        assert_eq!(
            words("A: E = 0.0265 m, range 134.70 m in 5.55 s", IMPERIAL),
            "A: E = 1.043 in, range 441.93 ft in 5.55 s"
        );
        assert_eq!(
            words("E_opt 0.02650 m at −10 m/s, 0.02700 m at +10 m/s", IMPERIAL),
            "E_opt 1.0433 in at −22 mph, 1.0630 in at +22 mph"
        );
        // Neither a radius nor a unit inside a word; Re and μ have none.
        for text in [
            "the bat's radius",
            "Re = 165 000, μ = 0.35",
            "ν 1.5e-5 m²/s",
            "5 min",
        ] {
            assert_eq!(words(text, IMPERIAL), text);
        }
        assert_eq!(words("42 m/s", UnitSystem::Si), "42 m/s");
    }
}
