//! Units for display: SI (the paper's) or the baseball units analysts use
//! (mph, ft, rpm, °F). Values are SI everywhere inside; only text shown to
//! a person, and text typed by one, passes through here.
//!
//! Written by hand: the unit crates (uom, dimensioned) type every quantity
//! at compile time, which the key table — one `f64` per input — cannot use,
//! and we need only a dozen affine conversions and their labels.

use std::f64::consts::PI;
use std::fmt;
use std::str::FromStr;

mod input;

pub use input::{Reading, TypedError, TypedUnit, accepted, read_typed, suggested_units};

/// Which units text is shown and typed in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum UnitSystem {
    /// The paper's units: m, m/s, rad, rad/s, kg, °C, hPa.
    #[default]
    Si,
    /// Baseball's: ft (distances), in (sizes), mph, degrees, rpm, oz, °F, inHg.
    Imperial,
}

impl UnitSystem {
    pub const ALL: [UnitSystem; 2] = [UnitSystem::Si, UnitSystem::Imperial];

    pub fn name(self) -> &'static str {
        match self {
            UnitSystem::Si => "si",
            UnitSystem::Imperial => "imperial",
        }
    }

    /// The other system: what a toggle switches to.
    pub fn toggled(self) -> UnitSystem {
        match self {
            UnitSystem::Si => UnitSystem::Imperial,
            UnitSystem::Imperial => UnitSystem::Si,
        }
    }
}

impl fmt::Display for UnitSystem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A unit system's name that is not one.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown units {0:?}: expected si or imperial")]
pub struct UnknownUnits(pub String);

impl FromStr for UnitSystem {
    type Err = UnknownUnits;

    fn from_str(text: &str) -> Result<UnitSystem, UnknownUnits> {
        match text.trim().to_ascii_lowercase().as_str() {
            "si" | "metric" => Ok(UnitSystem::Si),
            "imperial" | "us" => Ok(UnitSystem::Imperial),
            _ => Err(UnknownUnits(text.to_owned())),
        }
    }
}

/// What a number measures, which decides its imperial unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Quantity {
    /// Field distances and heights: ranges, apexes, fences, elevation (ft).
    Distance,
    /// Sizes of the ball and bat, and the undercut (in): feet would show
    /// a 1.44 in ball radius as 0.12 ft.
    Size,
    /// Speeds (mph).
    Speed,
    /// Spin rates (rpm).
    Spin,
    /// Angles (degrees).
    Angle,
    /// Temperatures (°F).
    Temperature,
    /// Barometric pressure (inHg, as US weather reports give it).
    Pressure,
    /// Masses (oz, as bats are sold).
    Mass,
    /// Accelerations (ft/s²).
    Acceleration,
    /// Shown in SI in both systems (ρ, ν, μ, times, humidity, counts).
    Unchanged,
}

/// Metres per foot (exact, international foot).
pub const METRES_PER_FOOT: f64 = 0.3048;
/// Metres per inch (exact).
pub const METRES_PER_INCH: f64 = 0.0254;
/// Metres per second per mile per hour (exact: 1609.344 m / 3600 s).
pub const METRES_PER_SECOND_PER_MPH: f64 = 0.44704;
/// Kilograms per avoirdupois ounce (exact).
pub const KILOGRAMS_PER_OUNCE: f64 = 0.028_349_523_125;
/// Hectopascals per inch of mercury, the factor US weather services use
/// (3386.38866667 Pa). The conventional inch (13.5951 g/cm³ of mercury
/// under standard gravity) is 3386.38864 Pa: 8 parts in 10⁹ apart, far
/// below a barometer's last digit.
pub const HECTOPASCALS_PER_INCH_OF_MERCURY: f64 = 33.863_886_666_7;
/// Kilograms per avoirdupois pound (exact).
pub const KILOGRAMS_PER_POUND: f64 = 0.453_592_37;
/// Radians per second per revolution per minute: 2π/60.
pub const RADIANS_PER_SECOND_PER_RPM: f64 = 2.0 * PI / 60.0;
/// Radians per degree, π/180 as `f64::to_radians` multiplies by it.
pub const RADIANS_PER_DEGREE: f64 = PI / 180.0;
/// The kelvin scale's zero in °C (exact).
pub const ZERO_CELSIUS_IN_KELVIN: f64 = 273.15;

/// One displayed unit: shown = si · scale + offset.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Unit {
    pub symbol: &'static str,
    scale: f64,
    offset: f64,
    /// SI per shown unit as the exact definition's ratio, numerator over
    /// denominator (0.44704 / 1 m/s per mph, 5 / 9 °C per °F, 5 / 18 m/s
    /// per km/h): a typed value is multiplied by the one and divided by the
    /// other, so that 100 mph is 44.704 m/s to the last bit and 70 °F is
    /// 190/9 °C, as in a preset written by hand or a batch's column.
    si_per_shown: (f64, f64),
}

impl Unit {
    /// A unit `si_per_shown` SI units large (0.3048 for the foot).
    const fn linear(symbol: &'static str, si_per_shown: f64) -> Unit {
        Unit::ratio(symbol, si_per_shown, 1.0)
    }

    /// A unit `numerator / denominator` SI units large (1 / 100 for cm).
    const fn ratio(symbol: &'static str, numerator: f64, denominator: f64) -> Unit {
        Unit {
            symbol,
            scale: denominator / numerator,
            offset: 0.0,
            si_per_shown: (numerator, denominator),
        }
    }

    /// °F (or kelvin, `Unit::affine("K", 1.0, 1.0, 273.15)`): shown =
    /// si · denominator / numerator + offset.
    const fn affine(symbol: &'static str, numerator: f64, denominator: f64, offset: f64) -> Unit {
        Unit {
            offset,
            ..Unit::ratio(symbol, numerator, denominator)
        }
    }

    /// The SI value as shown in this unit.
    pub fn show(self, si: f64) -> f64 {
        si * self.scale + self.offset
    }

    /// A value typed in this unit, back in SI.
    pub fn read(self, shown: f64) -> f64 {
        let (numerator, denominator) = self.si_per_shown;
        (shown - self.offset) * numerator / denominator
    }

    /// A difference of SI values (a nudge, a Δ) in this unit: no offset.
    pub fn show_difference(self, si: f64) -> f64 {
        si * self.scale
    }

    /// A nudge step in this unit near `si_step`, rounded to 1, 2 or 5 times
    /// a power of ten, so that nudging 0.5 m/s in mph steps by 1 mph, not
    /// by 1.118 (returned in this unit).
    pub fn nice_step(self, si_step: f64) -> f64 {
        let shown = self.show_difference(si_step).abs();
        if self.is_identity() || !shown.is_finite() || shown == 0.0 {
            return shown;
        }
        let decade = 10f64.powf(shown.log10().floor());
        let mantissa = shown / decade;
        // Geometric midpoints between 1, 2, 5 and 10.
        let nice = if mantissa < 2f64.sqrt() {
            1.0
        } else if mantissa < 10f64.sqrt() {
            2.0
        } else if mantissa < 50f64.sqrt() {
            5.0
        } else {
            10.0
        };
        nice * decade
    }

    /// Whether this unit is the SI one (nothing to convert).
    pub fn is_identity(self) -> bool {
        self.scale == 1.0 && self.offset == 0.0
    }

    /// The decimals that show a value in this unit about as finely as
    /// `si_decimals` show it in SI: the last digit's step is at most
    /// 10^0.25 ≈ 1.8 times the SI one's (134.699 m → 441.926 ft, 0.0265 m
    /// → 1.043 in, 0.1594 rad → 9.13°), never a coarser digit.
    pub fn decimals(self, si_decimals: usize) -> usize {
        if self.is_identity() {
            return si_decimals;
        }
        let finer = si_decimals as f64 - self.scale.abs().log10() - 0.25;
        finer.ceil().max(0.0) as usize
    }

    /// The symbol in plain ASCII, for CSV headers (`x_ft`, `angle_deg`).
    pub fn ascii_symbol(self) -> &'static str {
        match self.symbol {
            "°" => "deg",
            "°F" => "degF",
            "°C" => "degC",
            "ft/s²" => "ft_per_s2",
            "m/s²" => "m_per_s2",
            "m/s" => "m_per_s",
            "rad/s" => "rad_per_s",
            other => other,
        }
    }
}

/// The units of baseball, shown by `--units imperial` and typed anywhere.
pub(crate) const FOOT: Unit = Unit::linear("ft", METRES_PER_FOOT);
pub(crate) const INCH: Unit = Unit::linear("in", METRES_PER_INCH);
pub(crate) const MPH: Unit = Unit::linear("mph", METRES_PER_SECOND_PER_MPH);
pub(crate) const RPM: Unit = Unit::linear("rpm", RADIANS_PER_SECOND_PER_RPM);
pub(crate) const DEGREE: Unit = Unit::linear("°", RADIANS_PER_DEGREE);
pub(crate) const FAHRENHEIT: Unit = Unit::affine("°F", 5.0, 9.0, 32.0);
pub(crate) const INCH_OF_MERCURY: Unit = Unit::linear("inHg", HECTOPASCALS_PER_INCH_OF_MERCURY);
pub(crate) const OUNCE: Unit = Unit::linear("oz", KILOGRAMS_PER_OUNCE);

impl Quantity {
    /// Every quantity.
    pub const ALL: [Quantity; 10] = [
        Quantity::Distance,
        Quantity::Size,
        Quantity::Speed,
        Quantity::Spin,
        Quantity::Angle,
        Quantity::Temperature,
        Quantity::Pressure,
        Quantity::Mass,
        Quantity::Acceleration,
        Quantity::Unchanged,
    ];

    /// What it measures, in words: "a speed", "an angle".
    pub fn noun(self) -> &'static str {
        match self {
            Quantity::Distance | Quantity::Size => "a length",
            Quantity::Speed => "a speed",
            Quantity::Spin => "a spin rate",
            Quantity::Angle => "an angle",
            Quantity::Temperature => "a temperature",
            Quantity::Pressure => "a pressure",
            Quantity::Mass => "a mass",
            Quantity::Acceleration => "an acceleration",
            Quantity::Unchanged => "a plain number",
        }
    }

    /// The unit to show this quantity in. `si_symbol` is the SI unit's
    /// label, used as is in the SI system (the key table's `unit`).
    pub fn unit(self, system: UnitSystem, si_symbol: &'static str) -> Unit {
        if system == UnitSystem::Si {
            return Unit::linear(si_symbol, 1.0);
        }
        match self {
            Quantity::Distance => FOOT,
            Quantity::Size => INCH,
            Quantity::Speed => MPH,
            Quantity::Spin => RPM,
            Quantity::Angle => DEGREE,
            Quantity::Temperature => FAHRENHEIT,
            Quantity::Pressure => INCH_OF_MERCURY,
            Quantity::Mass => OUNCE,
            Quantity::Acceleration => Unit::linear("ft/s²", METRES_PER_FOOT),
            Quantity::Unchanged => Unit::linear(si_symbol, 1.0),
        }
    }

    /// The SI unit's label for quantities that have one fixed label.
    pub fn si_symbol(self) -> &'static str {
        match self {
            Quantity::Distance | Quantity::Size => "m",
            Quantity::Speed => "m/s",
            Quantity::Spin => "rad/s",
            Quantity::Angle => "rad",
            Quantity::Temperature => "°C",
            Quantity::Pressure => "hPa",
            Quantity::Mass => "kg",
            Quantity::Acceleration => "m/s²",
            Quantity::Unchanged => "",
        }
    }

    /// The unit to show this quantity in, with its own SI label.
    pub fn in_system(self, system: UnitSystem) -> Unit {
        self.unit(system, self.si_symbol())
    }
}

/// A number as a person reads it: to six significant digits, trailing zeros trimmed (134.112,
/// 0.0254); in scientific notation beyond 10⁹ or below 10⁻⁶.
pub fn significant(value: f64) -> String {
    let magnitude = value.abs();
    if magnitude == 0.0 {
        return "0".to_owned();
    }
    if !value.is_finite() {
        // inf, -inf, NaN as Rust writes them: the exponent form below
        // would make "infe".
        return value.to_string();
    }
    if !(1e-6..1e9).contains(&magnitude) {
        // 1.42278e301, 1e-300: the mantissa to six digits, trimmed.
        let text = format!("{value:.5e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, ""));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        return format!("{mantissa}e{exponent}");
    }
    let decimals = (5 - magnitude.log10().floor() as i32).max(0) as usize;
    let text = format!("{value:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    }
}

/// `value` to `digits` significant digits, and to no more than
/// `most_decimals` decimals (a tiny value is zeros there, not a long run of
/// them); a zero, inf or NaN as Rust writes it ("0", "-0", "inf"). For
/// tick labels and notes: the pictures' and the explorer's figures'.
pub fn sig(value: f64, digits: i32, most_decimals: i32) -> String {
    if value == 0.0 || !value.is_finite() {
        return format!("{value}");
    }
    let decimals =
        (digits - 1 - value.abs().log10().floor() as i32).clamp(0, most_decimals) as usize;
    format!("{value:.decimals$}")
}

/// `value` to `decimals` decimals, with no sign on a zero: "-0.00" reads
/// as a loss, or as a number below zero on an axis.
pub fn fixed(value: f64, decimals: usize) -> String {
    let text = format!("{value:.decimals$}");
    let digits = text.trim_start_matches('-');
    if digits.chars().all(|c| c == '0' || c == '.') {
        digits.to_owned()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fixed_zero_has_no_sign() {
        assert_eq!(fixed(-0.0001, 2), "0.00");
        assert_eq!(fixed(-0.006, 2), "-0.01");
        assert_eq!(fixed(26.375, 1), "26.4");
    }

    #[test]
    fn typed_values_convert_by_the_exact_definitions() {
        let read =
            |quantity: Quantity, shown: f64| quantity.unit(UnitSystem::Imperial, "").read(shown);
        // Each to the last bit: what a preset or a batch column gives.
        assert_eq!(read(Quantity::Speed, 100.0), 44.704);
        assert_eq!(read(Quantity::Speed, 103.0), 103.0 * 0.44704);
        assert_eq!(read(Quantity::Distance, 400.0), 121.92);
        assert_eq!(read(Quantity::Size, 1.0), 0.0254);
        assert_eq!(read(Quantity::Angle, 30.0), 30f64.to_radians());
        assert_eq!(read(Quantity::Temperature, 212.0), 100.0);
        assert_eq!(read(Quantity::Spin, 2500.0), 2500.0 * (2.0 * PI / 60.0));
    }

    #[test]
    fn baseball_numbers_convert_as_quoted() {
        let imperial = UnitSystem::Imperial;
        // 400 ft to centre field is the paper's 121.9 m.
        let ft = Quantity::Distance.in_system(imperial);
        assert!((ft.read(400.0) - 121.92).abs() < 1e-9);
        // 103 mph, 28°, 2500 rpm: the fly-ball preset's launch.
        assert!((Quantity::Speed.in_system(imperial).read(103.0) - 46.04512).abs() < 1e-9);
        assert!((Quantity::Angle.in_system(imperial).read(28.0) - 0.488_692_190_6).abs() < 1e-9);
        assert!((Quantity::Spin.in_system(imperial).read(2500.0) - 261.799_387_8).abs() < 1e-6);
        // A 32 oz bat is 0.907 kg; 29.92 inHg is the standard 1013.2 hPa.
        assert!((Quantity::Mass.in_system(imperial).read(32.0) - 0.907_184_74).abs() < 1e-9);
        let inhg = Quantity::Pressure.in_system(imperial);
        assert!((inhg.show(1013.25) - 29.921).abs() < 1e-3);
    }

    #[test]
    fn significant_digits_are_six_and_trimmed() {
        assert_eq!(significant(190.0 / 9.0), "21.1111");
        assert_eq!(
            significant(29.92 * HECTOPASCALS_PER_INCH_OF_MERCURY),
            "1013.21"
        );
        assert_eq!(significant(1580.0), "1580");
        assert_eq!(significant(300.0 * 0.44704), "134.112");
        assert_eq!(significant(0.0254), "0.0254");
        assert_eq!(significant(-0.0), "0");
        assert_eq!(significant(1e-300), "1e-300");
        assert_eq!(significant(-1.422_784_810_126_582_3e301), "-1.42278e301");
        // Issue 38: inf was "infe" ("launch.speed = inf mph (infe m/s)").
        assert_eq!(significant(f64::INFINITY), "inf");
        assert_eq!(significant(f64::NEG_INFINITY), "-inf");
        assert_eq!(significant(f64::NAN), "NaN");
    }

    #[test]
    fn sig_keeps_its_digits_up_to_the_decimals_allowed() {
        assert_eq!(sig(134.699, 4, 8), "134.7");
        assert_eq!(sig(0.026_54, 3, 6), "0.0265");
        assert_eq!(sig(-2.5e-3, 2, 8), "-0.0025");
        assert_eq!(sig(12_345.6, 3, 8), "12346");
        // Below the decimals allowed, zeros.
        assert_eq!(sig(1.234e-7, 3, 8), "0.00000012");
        assert_eq!(sig(1.234e-7, 3, 6), "0.000000");
        assert_eq!(sig(0.0, 3, 6), "0");
        assert_eq!(sig(-0.0, 3, 6), "-0");
        assert_eq!(sig(f64::INFINITY, 3, 6), "inf");
        assert_eq!(sig(f64::NAN, 3, 6), "NaN");
    }

    #[test]
    fn temperature_is_affine_and_differences_are_not() {
        let fahrenheit = Quantity::Temperature.in_system(UnitSystem::Imperial);
        assert_eq!(fahrenheit.show(0.0), 32.0);
        assert_eq!(fahrenheit.show(100.0), 212.0);
        assert!((fahrenheit.read(-40.0) + 40.0).abs() < 1e-12);
        // A 1 °C step is a 1.8 °F step, not 33.8.
        assert_eq!(fahrenheit.show_difference(1.0), 1.8);
    }

    #[test]
    fn show_and_read_are_inverse_and_si_is_identity() {
        for quantity in Quantity::ALL {
            for system in UnitSystem::ALL {
                let unit = quantity.in_system(system);
                for si in [-31.7, 0.0, 1e-3, 42.0, 1013.25] {
                    let back = unit.read(unit.show(si));
                    assert!(
                        (back - si).abs() <= 1e-12 * si.abs().max(1.0),
                        "{quantity:?}"
                    );
                }
            }
            assert!(quantity.in_system(UnitSystem::Si).is_identity());
        }
        assert!(
            !Quantity::Speed
                .in_system(UnitSystem::Imperial)
                .is_identity()
        );
    }

    #[test]
    fn nudges_are_round_numbers_in_the_shown_unit() {
        let imperial = UnitSystem::Imperial;
        // 0.5 m/s is 1.118 mph: nudge by 1 mph; 10 rad/s is 95.5 rpm: 100.
        assert_eq!(Quantity::Speed.in_system(imperial).nice_step(0.5), 1.0);
        assert_eq!(Quantity::Spin.in_system(imperial).nice_step(10.0), 100.0);
        // 0.01 rad is 0.573°: 0.5°. 1 °C is 1.8 °F: 2 °F.
        assert_eq!(Quantity::Angle.in_system(imperial).nice_step(0.01), 0.5);
        assert_eq!(
            Quantity::Temperature.in_system(imperial).nice_step(1.0),
            2.0
        );
        // SI keeps the key's own step.
        assert_eq!(
            Quantity::Speed.in_system(UnitSystem::Si).nice_step(0.5),
            0.5
        );
    }

    #[test]
    fn imperial_decimals_are_about_as_fine_as_the_si_ones() {
        let imperial = |q: Quantity| q.in_system(UnitSystem::Imperial);
        // 0.001 m is 0.0033 ft: 3 decimals; 0.1 m is 0.33 ft: 1.
        assert_eq!(imperial(Quantity::Distance).decimals(3), 3);
        assert_eq!(imperial(Quantity::Distance).decimals(1), 1);
        // 0.0001 m is 0.0039 in: 3 decimals.
        assert_eq!(imperial(Quantity::Size).decimals(4), 3);
        // 0.01 rad/s is 0.095 rpm: 1 decimal; 0.0001 rad is 0.0057°: 2.
        assert_eq!(imperial(Quantity::Spin).decimals(2), 1);
        assert_eq!(imperial(Quantity::Angle).decimals(4), 2);
        assert_eq!(imperial(Quantity::Speed).decimals(3), 3);
        // Never below zero, and SI keeps its own.
        assert_eq!(imperial(Quantity::Spin).decimals(0), 0);
        assert_eq!(Quantity::Size.in_system(UnitSystem::Si).decimals(5), 5);
    }

    #[test]
    fn csv_symbols_are_ascii() {
        for quantity in [
            Quantity::Angle,
            Quantity::Temperature,
            Quantity::Acceleration,
            Quantity::Speed,
            Quantity::Spin,
        ] {
            for system in UnitSystem::ALL {
                let symbol = quantity.in_system(system).ascii_symbol();
                assert!(symbol.is_ascii() && !symbol.contains('/'), "{symbol}");
            }
        }
        assert_eq!(
            Quantity::Angle
                .in_system(UnitSystem::Imperial)
                .ascii_symbol(),
            "deg"
        );
        assert_eq!(
            Quantity::Distance
                .in_system(UnitSystem::Imperial)
                .ascii_symbol(),
            "ft"
        );
    }

    #[test]
    fn names_parse_and_unknown_ones_say_what_is_accepted() {
        assert_eq!("imperial".parse(), Ok(UnitSystem::Imperial));
        assert_eq!(" SI ".parse(), Ok(UnitSystem::Si));
        let error = "furlongs".parse::<UnitSystem>().unwrap_err();
        assert_eq!(
            error.to_string(),
            "unknown units \"furlongs\": expected si or imperial"
        );
        assert_eq!(UnitSystem::Si.toggled(), UnitSystem::Imperial);
    }
}
