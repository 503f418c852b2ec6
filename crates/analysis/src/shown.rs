//! Numbers as the frontends print them, in the units `--units` asks for.
//! The conversions themselves are [`units`]'; here is only how a
//! converted value is written. In SI every helper writes exactly what the
//! commands wrote before `--units` existed.

use crate::landing;
use model::flight::FlightSummary;
use model::keys::{Bounds, Key};
use units::{Quantity, Unit, UnitSystem};

/// The unit system text is printed in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Shown(pub UnitSystem);

impl Shown {
    pub fn is_si(self) -> bool {
        self.0 == UnitSystem::Si
    }

    pub fn unit(self, quantity: Quantity) -> Unit {
        quantity.in_system(self.0)
    }

    /// `si` in this system's unit; exactly `si` in SI.
    pub fn convert(self, quantity: Quantity, si: f64) -> f64 {
        let unit = self.unit(quantity);
        if unit.is_identity() {
            si
        } else {
            unit.show(si)
        }
    }

    /// "44.299 m/s", "99.094 mph", "26.38°": `si_decimals` in SI, about as
    /// fine in the other system ([`Unit::decimals`]).
    pub fn value(self, quantity: Quantity, si: f64, si_decimals: usize) -> String {
        let unit = self.unit(quantity);
        self.value_to(quantity, si, unit.decimals(si_decimals))
    }

    /// As [`Shown::value`], with `decimals` in whichever system.
    pub fn value_to(self, quantity: Quantity, si: f64, decimals: usize) -> String {
        let unit = self.unit(quantity);
        let value = self.convert(quantity, si);
        format!("{value:.decimals$}{}", spaced(unit.symbol))
    }

    /// An angle with its degrees: "0.4604 rad (26.4°)" in SI; in degrees
    /// alone otherwise, to the parenthesis' decimals ("26.4°").
    pub fn angle_and_degrees(self, rad: f64, si_decimals: usize, degrees: usize) -> String {
        if self.is_si() {
            format!("{rad:.si_decimals$} rad ({:.degrees$}°)", rad.to_degrees())
        } else {
            self.value_to(Quantity::Angle, rad, degrees)
        }
    }

    /// A direction in words: "0.3000 rad (17.2° toward right field)", "12.0°
    /// toward left field", "toward centre field".
    pub fn direction(self, rad: f64) -> String {
        let side = if rad > 0.0 {
            "right field"
        } else {
            "left field"
        };
        if rad == 0.0 {
            "toward centre field".to_owned()
        } else if self.is_si() {
            format!(
                "{rad:.4} rad ({:.1}° toward {side})",
                rad.abs().to_degrees()
            )
        } else {
            format!("{:.1}° toward {side}", rad.abs().to_degrees())
        }
    }

    /// A batted spin in words, backspin positive: "191.83 rad/s of
    /// backspin", or in whole rpm as Statcast gives it ("1832 rpm of backspin").
    pub fn spin(self, spin: f64) -> String {
        let decimals = if self.is_si() { 2 } else { 0 };
        let size = self.value_to(Quantity::Spin, spin.abs(), decimals);
        if spin < 0.0 {
            format!("{size} of topspin")
        } else {
            format!("{size} of backspin")
        }
    }

    /// A sidespin in words: "100.00 rad/s of sidespin toward right field"
    /// (positive curves the ball toward right field).
    pub fn sidespin(self, sidespin: f64) -> String {
        let decimals = if self.is_si() { 2 } else { 0 };
        let size = self.value_to(Quantity::Spin, sidespin.abs(), decimals);
        let side = if sidespin < 0.0 {
            "left field"
        } else {
            "right field"
        };
        format!("{size} of sidespin toward {side}")
    }

    /// A launch: "44.299 m/s, 191.83 rad/s of backspin, 0.4604 rad (26.4°)",
    /// or as Statcast gives it, "99.1 mph, 1832 rpm of backspin, 26.4°".
    pub fn launch(self, speed: f64, spin: f64, angle: f64) -> String {
        let decimals = if self.is_si() { 3 } else { 1 };
        format!(
            "{}, {}, {}",
            self.value_to(Quantity::Speed, speed, decimals),
            self.spin(spin),
            self.angle_and_degrees(angle, 4, 1)
        )
    }

    /// A column heading with its unit: "x (m)" or "x (ft)"; `si_symbol` is
    /// the SI label as the heading had it.
    pub fn head(self, name: &str, quantity: Quantity, si_symbol: &'static str) -> String {
        let symbol = quantity.unit(self.0, si_symbol).symbol;
        if symbol.is_empty() {
            name.to_owned()
        } else {
            format!("{name} ({symbol})")
        }
    }

    /// A CSV column name: as it is in SI (scripts read those), with the unit
    /// after it otherwise (`x_ft`), so that no script takes feet for metres.
    pub fn csv_key(self, key: &str, quantity: Quantity) -> String {
        let unit = self.unit(quantity);
        if self.is_si() || unit.is_identity() {
            key.to_owned()
        } else {
            format!("{key}_{}", unit.ascii_symbol())
        }
    }

    /// A key's accepted range with its unit: "(0, 100] m/s" in SI (as
    /// [`Bounds`] writes it), "(0, 223.693] mph" otherwise.
    pub fn bounds(self, key: &Key) -> String {
        let unit = key.unit_in(self.0);
        if self.is_si() || unit.is_identity() {
            return format!("{}{}", key.bounds, spaced(key.unit));
        }
        format!("{}{}", self.interval(key.bounds, unit), spaced(unit.symbol))
    }

    /// An interval's ends in `unit`, without the unit, each printed so
    /// that it is accepted when typed back ([`Bounds::shown_in`]).
    pub fn interval(self, bounds: Bounds, unit: Unit) -> String {
        bounds.shown_in(unit)
    }

    /// Why a flight has no range, as [`landing::not_landed`] says it, with
    /// the height in this system's distance.
    pub fn not_landed(self, summary: &FlightSummary, height: f64) -> String {
        if self.is_si() {
            return landing::not_landed(summary, height);
        }
        let up = self.value_to(Quantity::Distance, height, 1);
        landing::not_landed_at(summary, &up)
    }
}

/// " m/s" after a number, "°" straight after it, nothing for no unit.
fn spaced(symbol: &str) -> String {
    match symbol {
        "" => String::new(),
        "°" => "°".to_owned(),
        symbol => format!(" {symbol}"),
    }
}

// A converted value, short: at most three decimals, no trailing zeros
// (223.694, 90, -58); the figures write theirs so too.
pub use crate::figures::short;

#[cfg(test)]
mod tests {
    use super::*;
    use model::scene::Scene;

    const SI: Shown = Shown(UnitSystem::Si);
    const IMPERIAL: Shown = Shown(UnitSystem::Imperial);

    #[test]
    fn si_text_is_what_the_commands_always_wrote() {
        assert_eq!(
            SI.launch(44.299_2, 191.83, 0.460_4),
            "44.299 m/s, 191.83 rad/s of backspin, 0.4604 rad (26.4°)"
        );
        assert_eq!(SI.spin(-12.0), "12.00 rad/s of topspin");
        let speed = Scene::key("pitch.speed").unwrap();
        assert_eq!(SI.bounds(speed), "(0, 100] m/s");
        assert_eq!(SI.csv_key("x", Quantity::Distance), "x");
    }

    #[test]
    fn imperial_text_converts_and_names_its_units() {
        // The fly-ball preset's launch: 103 mph, 28°, 2500 rpm.
        assert_eq!(
            IMPERIAL.launch(46.045_12, 261.799_387_8, 0.488_692_190_6),
            "103.0 mph, 2500 rpm of backspin, 28.0°"
        );
        assert_eq!(IMPERIAL.value(Quantity::Distance, 121.92, 1), "400.0 ft");
        let speed = Scene::key("pitch.speed").unwrap();
        assert_eq!(IMPERIAL.bounds(speed), "(0, 223.693] mph");
        let angle = Scene::key("launch.angle").unwrap();
        assert_eq!(IMPERIAL.bounds(angle), "[-90, 90]°");
        assert_eq!(IMPERIAL.csv_key("x", Quantity::Distance), "x_ft");
        assert_eq!(IMPERIAL.csv_key("time", Quantity::Unchanged), "time");
        assert_eq!(IMPERIAL.head("E", Quantity::Size, "m"), "E (in)".to_owned());
    }
}
