//! Values typed with a unit: `103mph`, `28°`, `29.92 inHg`, `70F`. One
//! table of units per quantity, each unit with the spellings it may be
//! typed in and its exact definition; a bare number is SI. `--set`, preset
//! strings and `fly --batch` cells all read through [`read_typed`].

use super::{
    DEGREE, FAHRENHEIT, FOOT, INCH, INCH_OF_MERCURY, KILOGRAMS_PER_POUND, METRES_PER_FOOT, MPH,
    OUNCE, Quantity, RPM, Unit, ZERO_CELSIUS_IN_KELVIN,
};

/// A unit a value may be typed in, under each of its spellings.
#[derive(Clone, Copy, Debug)]
pub struct TypedUnit {
    /// How it may follow the number, the first as it is listed.
    pub spellings: &'static [&'static str],
    pub unit: Unit,
}

const fn typed(spellings: &'static [&'static str], unit: Unit) -> TypedUnit {
    TypedUnit { spellings, unit }
}

/// Lengths, for distances and sizes alike (SI first, in each table).
const LENGTH: &[TypedUnit] = &[
    typed(&["m"], Unit::linear("m", 1.0)),
    typed(&["cm"], Unit::ratio("cm", 1.0, 100.0)),
    typed(&["mm"], Unit::ratio("mm", 1.0, 1000.0)),
    typed(&["km"], Unit::linear("km", 1000.0)),
    typed(&["ft"], FOOT),
    typed(&["in"], INCH),
];
const SPEED: &[TypedUnit] = &[
    typed(&["m/s"], Unit::linear("m/s", 1.0)),
    // 1000 m / 3600 s = 5/18 m/s.
    typed(&["km/h"], Unit::ratio("km/h", 5.0, 18.0)),
    typed(&["mph"], MPH),
    typed(&["ft/s"], Unit::linear("ft/s", METRES_PER_FOOT)),
];
const SPIN: &[TypedUnit] = &[
    typed(&["rad/s"], Unit::linear("rad/s", 1.0)),
    typed(&["rpm"], RPM),
];
const ANGLE: &[TypedUnit] = &[
    typed(&["rad"], Unit::linear("rad", 1.0)),
    typed(&["deg", "°"], DEGREE),
];
const TEMPERATURE: &[TypedUnit] = &[
    typed(&["C", "°C"], Unit::linear("°C", 1.0)),
    typed(&["F", "°F"], FAHRENHEIT),
    typed(&["K"], Unit::affine("K", 1.0, 1.0, ZERO_CELSIUS_IN_KELVIN)),
];
const PRESSURE: &[TypedUnit] = &[
    typed(&["hPa", "mbar"], Unit::linear("hPa", 1.0)),
    typed(&["Pa"], Unit::ratio("Pa", 1.0, 100.0)),
    typed(&["kPa"], Unit::linear("kPa", 10.0)),
    typed(&["inHg"], INCH_OF_MERCURY),
];
const MASS: &[TypedUnit] = &[
    typed(&["kg"], Unit::linear("kg", 1.0)),
    typed(&["g"], Unit::ratio("g", 1.0, 1000.0)),
    typed(&["oz"], OUNCE),
    typed(&["lb"], Unit::linear("lb", KILOGRAMS_PER_POUND)),
];
const ACCELERATION: &[TypedUnit] = &[
    typed(&["m/s²", "m/s^2", "m/s2"], Unit::linear("m/s²", 1.0)),
    typed(
        &["ft/s²", "ft/s^2", "ft/s2"],
        Unit::linear("ft/s²", METRES_PER_FOOT),
    ),
];

impl Quantity {
    /// The units a value of this quantity may be typed in, SI first.
    pub fn typed_units(self) -> &'static [TypedUnit] {
        match self {
            Quantity::Distance | Quantity::Size => LENGTH,
            Quantity::Speed => SPEED,
            Quantity::Spin => SPIN,
            Quantity::Angle => ANGLE,
            Quantity::Temperature => TEMPERATURE,
            Quantity::Pressure => PRESSURE,
            Quantity::Mass => MASS,
            Quantity::Acceleration => ACCELERATION,
            Quantity::Unchanged => &[],
        }
    }

    /// The units an out-of-range bare number was likely meant in, as typed
    /// (`deg`, `mph`): the imperial unit first, then a common metric one.
    fn likely_units(self) -> &'static [&'static str] {
        match self {
            Quantity::Distance => &["ft"],
            Quantity::Size => &["in", "mm"],
            Quantity::Speed => &["mph", "km/h"],
            Quantity::Spin => &["rpm"],
            Quantity::Angle => &["deg"],
            Quantity::Temperature => &["F", "K"],
            Quantity::Pressure => &["inHg", "kPa"],
            Quantity::Mass => &["oz", "g"],
            Quantity::Acceleration => &["ft/s2"],
            Quantity::Unchanged => &[],
        }
    }
}

/// A value as typed: the number, the unit it came in (`None`: bare, so
/// SI) and the value in SI.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reading {
    pub number: f64,
    pub unit: Option<Unit>,
    pub si: f64,
}

/// Why typed text is no value of a quantity.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum TypedError {
    /// No number where the text starts.
    NotANumber,
    /// A unit of another quantity (`28deg` for a speed).
    OtherQuantity { unit: String, quantity: Quantity },
    /// No unit of any quantity.
    UnknownUnit { unit: String },
}

/// Reads `text`, a number and optionally a unit of `quantity` after it (a
/// space between them allowed), in SI. `own_symbol` is the SI unit's label
/// of the value typed (`s`, `%`, `kg/m³`), accepted as it is for the
/// quantities that have no table of units.
pub fn read_typed(
    text: &str,
    quantity: Quantity,
    own_symbol: &'static str,
) -> Result<Reading, TypedError> {
    let text = text.trim();
    let (number, suffix) = split_number(text).ok_or(TypedError::NotANumber)?;
    if suffix.is_empty() {
        return Ok(Reading {
            number,
            unit: None,
            si: number,
        });
    }
    let unit = find(quantity.typed_units(), suffix).or_else(|| {
        let own = !own_symbol.is_empty() && (suffix == own_symbol || suffix == ascii(own_symbol));
        own.then(|| Unit::linear(own_symbol, 1.0))
    });
    if let Some(unit) = unit {
        return Ok(Reading {
            number,
            unit: Some(unit),
            si: unit.read(number),
        });
    }
    let unit = suffix.to_owned();
    match Quantity::ALL
        .into_iter()
        .find(|q| find(q.typed_units(), suffix).is_some())
    {
        Some(quantity) => Err(TypedError::OtherQuantity { unit, quantity }),
        None => Err(TypedError::UnknownUnit { unit }),
    }
}

/// The units `quantity` is typed in, as listed in errors: "m/s, km/h, mph,
/// ft/s"; `own_symbol` alone for a quantity without a table, "" if none.
pub fn accepted(quantity: Quantity, own_symbol: &str) -> String {
    let units = quantity.typed_units();
    if units.is_empty() {
        return own_symbol.to_owned();
    }
    let spellings: Vec<&str> = units.iter().flat_map(|u| u.spellings).copied().collect();
    spellings.join(", ")
}

/// The likely units (as typed) in which `number`, out of range as SI, is
/// accepted: `103` for a speed in (0, 100] m/s gives `mph` (46.0 m/s) and
/// `km/h` (28.6 m/s).
pub fn suggested_units(
    quantity: Quantity,
    number: f64,
    accepts: impl Fn(f64) -> bool,
) -> Vec<&'static str> {
    quantity
        .likely_units()
        .iter()
        .copied()
        .filter(|spelling| {
            find(quantity.typed_units(), spelling).is_some_and(|unit| accepts(unit.read(number)))
        })
        .collect()
}

fn find(units: &[TypedUnit], suffix: &str) -> Option<Unit> {
    units
        .iter()
        .find(|u| u.spellings.contains(&suffix))
        .map(|u| u.unit)
}

/// A unit's label without superscripts: `kg/m3`, `m2/s`.
fn ascii(symbol: &str) -> String {
    symbol.replace('²', "2").replace('³', "3")
}

/// The number `text` starts with, and the rest (trimmed): the whole text if
/// Rust reads it as a number (`inf`, `NaN`, `1e5` too), else the longest
/// leading decimal number (`-1.5e3` of `-1.5e3ft`).
fn split_number(text: &str) -> Option<(f64, &str)> {
    if let Ok(number) = text.parse() {
        return Some((number, ""));
    }
    let bytes = text.as_bytes();
    let digits = |from: usize| {
        bytes[from..]
            .iter()
            .take_while(|b| b.is_ascii_digit())
            .count()
    };
    let mut end = usize::from(matches!(bytes.first(), Some(b'+' | b'-')));
    let whole = digits(end);
    end += whole;
    let mut fraction = 0;
    if bytes.get(end) == Some(&b'.') {
        fraction = digits(end + 1);
        end += 1 + fraction;
    }
    if whole + fraction == 0 {
        return None;
    }
    if matches!(bytes.get(end), Some(b'e' | b'E')) {
        let sign = usize::from(matches!(bytes.get(end + 1), Some(b'+' | b'-')));
        let exponent = digits(end + 1 + sign);
        if exponent > 0 {
            end += 1 + sign + exponent;
        }
    }
    let number = text[..end].parse().ok()?;
    Some((number, text[end..].trim_start()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn si(text: &str, quantity: Quantity) -> f64 {
        read_typed(text, quantity, quantity.si_symbol())
            .unwrap_or_else(|e| panic!("{text}: {e:?}"))
            .si
    }

    #[test]
    fn every_suffix_reads_by_its_exact_definition() {
        use Quantity::*;
        // Each to the last bit: the product (or quotient) the definition names.
        let cases: &[(&str, Quantity, f64)] = &[
            ("103mph", Speed, 103.0 * 0.44704),
            ("103 mph", Speed, 103.0 * 0.44704),
            ("46.04512m/s", Speed, 46.04512),
            ("160km/h", Speed, 160.0 * 5.0 / 18.0),
            ("100ft/s", Speed, 100.0 * 0.3048),
            ("28deg", Angle, 28f64.to_radians()),
            ("28°", Angle, 28f64.to_radians()),
            ("0.5rad", Angle, 0.5),
            (
                "2500rpm",
                Spin,
                2500.0 * (2.0 * std::f64::consts::PI / 60.0),
            ),
            ("261.8rad/s", Spin, 261.8),
            ("400ft", Distance, 400.0 * 0.3048),
            ("1580m", Distance, 1580.0),
            ("1.58km", Distance, 1.58 * 1000.0),
            ("35in", Size, 35.0 * 0.0254),
            ("3.66cm", Size, 3.66 / 100.0),
            ("26.5mm", Size, 26.5 / 1000.0),
            ("5.1oz", Mass, 5.1 * 0.028_349_523_125),
            ("145g", Mass, 145.0 / 1000.0),
            ("2lb", Mass, 2.0 * 0.453_592_37),
            ("0.145kg", Mass, 0.145),
            ("70F", Temperature, 190.0 / 9.0),
            ("70°F", Temperature, 190.0 / 9.0),
            ("21C", Temperature, 21.0),
            ("21°C", Temperature, 21.0),
            ("294.15K", Temperature, 294.15 - 273.15),
            ("29.92inHg", Pressure, 29.92 * 33.863_886_666_7),
            ("1013.25hPa", Pressure, 1013.25),
            ("1013.25mbar", Pressure, 1013.25),
            ("101325Pa", Pressure, 101_325.0 / 100.0),
            ("101.325kPa", Pressure, 101.325 * 10.0),
            ("9.81m/s²", Acceleration, 9.81),
            ("9.81m/s^2", Acceleration, 9.81),
            ("32.174ft/s2", Acceleration, 32.174 * 0.3048),
        ];
        for &(text, quantity, expected) in cases {
            assert_eq!(si(text, quantity), expected, "{text}");
        }
        // The numbers people quote.
        assert_eq!(si("103mph", Speed), 46.045_12);
        assert!((si("70F", Temperature) - 21.111_111_111_111).abs() < 1e-12);
        // 29.92 × 33.8638866667 = 1013.207489067664 hPa, by hand.
        assert!((si("29.92inHg", Pressure) - 1_013.207_489_067_664).abs() < 1e-9);
        assert!((si("5.1oz", Mass) - 0.144_582_567_937_5).abs() < 1e-15);
        assert!((si("-40F", Temperature) + 40.0).abs() < 1e-12);
    }

    #[test]
    fn a_bare_number_is_si_and_every_spelling_is_listed() {
        assert_eq!(
            read_typed(" 44.5 ", Quantity::Speed, "m/s"),
            Ok(Reading {
                number: 44.5,
                unit: None,
                si: 44.5
            })
        );
        // As Rust reads numbers: the range check refuses what is not finite.
        assert!(si("inf", Quantity::Speed).is_infinite());
        assert_eq!(si("1e1", Quantity::Speed), 10.0);
        assert_eq!(si("-1.5e1ft", Quantity::Distance), -15.0 * 0.3048);
        assert_eq!(si(".5 rad", Quantity::Angle), 0.5);
        assert_eq!(accepted(Quantity::Speed, "m/s"), "m/s, km/h, mph, ft/s");
        assert_eq!(accepted(Quantity::Angle, "rad"), "rad, deg, °");
        assert_eq!(accepted(Quantity::Unchanged, "s"), "s");
    }

    #[test]
    fn a_key_without_a_table_takes_its_own_symbol() {
        let read = |text| read_typed(text, Quantity::Unchanged, "kg/m³").map(|r| r.si);
        assert_eq!(read("1.2kg/m³"), Ok(1.2));
        assert_eq!(read("1.2 kg/m3"), Ok(1.2));
        assert_eq!(
            read("1.2mph"),
            Err(TypedError::OtherQuantity {
                unit: "mph".into(),
                quantity: Quantity::Speed
            })
        );
        assert_eq!(
            read_typed("5%", Quantity::Unchanged, "").map(|r| r.si),
            Err(TypedError::UnknownUnit { unit: "%".into() })
        );
    }

    #[test]
    fn wrong_units_and_non_numbers_are_told_apart() {
        assert_eq!(
            read_typed("28deg", Quantity::Speed, "m/s"),
            Err(TypedError::OtherQuantity {
                unit: "deg".into(),
                quantity: Quantity::Angle
            })
        );
        assert_eq!(
            read_typed("28 furlongs", Quantity::Speed, "m/s"),
            Err(TypedError::UnknownUnit {
                unit: "furlongs".into()
            })
        );
        for text in ["fast", "", "mph", "-", ".", "e5", "--5"] {
            assert_eq!(
                read_typed(text, Quantity::Speed, "m/s"),
                Err(TypedError::NotANumber),
                "{text:?}"
            );
        }
        // Case matters: MPH is no unit, and Mm is no millimetre.
        assert!(read_typed("5MPH", Quantity::Speed, "m/s").is_err());
    }

    #[test]
    fn likely_units_are_those_that_bring_the_number_in_range() {
        let speed = |v: f64| v > 0.0 && v <= 100.0;
        assert_eq!(
            suggested_units(Quantity::Speed, 103.0, speed),
            ["mph", "km/h"]
        );
        assert_eq!(suggested_units(Quantity::Speed, 300.0, speed), ["km/h"]);
        let angle = |v: f64| v.abs() < std::f64::consts::FRAC_PI_2;
        assert_eq!(suggested_units(Quantity::Angle, 28.0, angle), ["deg"]);
        assert!(suggested_units(Quantity::Angle, 95.0, angle).is_empty());
        let celsius = |v: f64| (-50.0..=60.0).contains(&v);
        assert_eq!(suggested_units(Quantity::Temperature, 70.0, celsius), ["F"]);
    }
}
