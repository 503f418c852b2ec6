//! One text per quantity, wherever the explorer shows it (the readout, the
//! Table II line, the heatmap's axes, the impact, the field's title): each
//! quantity in one unit, the paper's in SI (the undercut E in m as Table
//! II gives it, every angle in rad) and baseball's otherwise (in, °), so
//! that no pane shows a quantity in a unit another pane does not.

use crate::format::signed;
use units::{Quantity, UnitSystem};

/// The decimals in SI the readout gives an angle (0.1744 rad) and the
/// undercut (0.0273 m); in the other units about as fine (9.99°, 1.074 in).
pub const READOUT_DECIMALS: usize = 4;

/// `si` of `quantity` in the unit of `units`, with its symbol: `si_decimals`
/// in SI and about as fine in the other system ([`units::Unit::decimals`]);
/// `sign` for a difference ("+0.0008 m", never "-0.0000"). Degrees sit on
/// their number ("9.13°"), other symbols a space away.
pub fn quantity_text(
    units: UnitSystem,
    quantity: Quantity,
    si: f64,
    si_decimals: usize,
    sign: bool,
) -> String {
    let unit = quantity.in_system(units);
    let decimals = unit.decimals(si_decimals);
    let value = if sign {
        signed(unit.show_difference(si), decimals)
    } else {
        let text = format!("{:.decimals$}", unit.show(si));
        // "-0.0000" reads as a loss: a zero has no sign.
        if text
            .trim_start_matches('-')
            .chars()
            .all(|c| c == '0' || c == '.')
        {
            text.trim_start_matches('-').to_owned()
        } else {
            text
        }
    };
    let gap = if unit.symbol == "°" { "" } else { " " };
    format!("{value}{gap}{}", unit.symbol)
}

/// A distance in the units shown: (value, unit).
pub fn distance(units: UnitSystem, metres: f64) -> (f64, &'static str) {
    let unit = Quantity::Distance.in_system(units);
    (unit.show(metres), unit.symbol)
}

/// A range as every pane shows it, at one rounding (the readout's, to
/// which the Δ column's gains add up): "134.70 m".
pub fn range_text(units: UnitSystem, metres: f64) -> String {
    let (value, unit) = distance(units, metres);
    format!("{value:.2} {unit}")
}

/// An angle: "0.1744 rad" or "9.99°" (ψ, θ, ζ, the launch, the landing,
/// the slip's direction).
pub fn angle_text(units: UnitSystem, rad: f64, si_decimals: usize, sign: bool) -> String {
    quantity_text(units, Quantity::Angle, rad, si_decimals, sign)
}

/// The undercut E: "0.0273 m" (Table II's unit and digits) or "1.074 in".
pub fn undercut_text(units: UnitSystem, metres: f64, sign: bool) -> String {
    quantity_text(units, Quantity::Size, metres, READOUT_DECIMALS, sign)
}

/// The undercut's axis: a tick's text and the axis' title, "E (m)" with
/// 0.01 m ticks to two decimals, or "E (in)" to one.
pub fn undercut_tick(units: UnitSystem, metres: f64) -> String {
    let unit = Quantity::Size.in_system(units);
    let decimals = if units == UnitSystem::Si { 2 } else { 1 };
    let text = format!("{:.decimals$}", unit.show(metres));
    // "0.00" says nothing "0" does not.
    if text
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        "0".to_owned()
    } else {
        text
    }
}

/// The undercut axis' title: "E (m)" or "E (in)".
pub fn undercut_axis(units: UnitSystem) -> String {
    format!("E ({})", Quantity::Size.in_system(units).symbol)
}

/// The swing angle axis' tick: "0.8" (rad) or "46" (°), bare as the
/// undercut's are, the unit said once beside the axis' name
/// ([`swing_angle_unit`]).
pub fn swing_angle_tick(units: UnitSystem, rad: f64) -> String {
    match units {
        UnitSystem::Si => format!("{rad:.1}"),
        UnitSystem::Imperial => format!("{:.0}", rad.to_degrees()),
    }
}

/// The swing angle axis' unit, under its name as "E (m)" has it: "(rad)"
/// or "(°)".
pub fn swing_angle_unit(units: UnitSystem) -> String {
    format!("({})", Quantity::Angle.in_system(units).symbol)
}

/// A direction from the centre-field line in words: "0.12 rad toward right
/// field", "7° toward left field", or "centre field" within half a degree.
pub fn direction_text(units: UnitSystem, rad: f64) -> String {
    if rad.to_degrees().abs() < 0.5 {
        return "centre field".to_owned();
    }
    let side = if rad > 0.0 { "right" } else { "left" };
    format!(
        "{} toward {side} field",
        angle_text(units, rad.abs(), 2, false)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    const SI: UnitSystem = UnitSystem::Si;
    const IMPERIAL: UnitSystem = UnitSystem::Imperial;

    #[test]
    fn the_undercut_is_in_metres_as_table_ii_gives_it_or_in_inches() {
        assert_eq!(undercut_text(SI, 0.0265, false), "0.0265 m");
        assert_eq!(undercut_text(SI, 0.027_27, false), "0.0273 m");
        assert_eq!(undercut_text(SI, -0.000_77, true), "-0.0008 m");
        assert_eq!(undercut_text(SI, -0.000_01, true), "+0.0000 m");
        assert_eq!(undercut_text(IMPERIAL, 0.027_27, false), "1.074 in");
        assert_eq!(undercut_axis(SI), "E (m)");
        assert_eq!(undercut_axis(IMPERIAL), "E (in)");
        assert_eq!(undercut_tick(SI, 0.05), "0.05");
        assert_eq!(undercut_tick(SI, 0.0), "0");
        assert_eq!(undercut_tick(IMPERIAL, 0.05), "2.0");
    }

    #[test]
    fn every_angle_is_in_radians_or_in_degrees_never_both() {
        assert_eq!(angle_text(SI, 0.4604, 4, false), "0.4604 rad");
        assert_eq!(angle_text(IMPERIAL, 0.4604, 4, false), "26.38°");
        assert_eq!(angle_text(SI, -0.015, 4, true), "-0.0150 rad");
        assert_eq!(angle_text(IMPERIAL, -0.015, 4, true), "-0.86°");
        // A landing to a tenth of a degree: 3 decimals of a radian.
        assert_eq!(angle_text(IMPERIAL, 0.8308, 3, false), "47.6°");
        assert_eq!(angle_text(SI, 0.8308, 3, false), "0.831 rad");
        assert_eq!(direction_text(SI, 0.12), "0.12 rad toward right field");
        assert_eq!(direction_text(IMPERIAL, -0.12), "7° toward left field");
        assert_eq!(direction_text(SI, 0.005), "centre field");
        assert_eq!(swing_angle_tick(SI, 0.8), "0.8");
        assert_eq!(swing_angle_tick(IMPERIAL, 0.8), "46");
        assert_eq!(swing_angle_unit(SI), "(rad)");
        assert_eq!(swing_angle_unit(IMPERIAL), "(°)");
    }
}
