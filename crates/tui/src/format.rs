//! Numbers as the explorer writes them: the inputs pane shows a value this
//! way, in the units chosen (`u`), and an edit starts from the same text and
//! is read back in the same unit. Values stay SI inside; only text passes
//! through here.

use crate::shown::READOUT_DECIMALS;
use model::keys::{InputError, Key, number_text};
use units::{Quantity, UnitSystem};

/// The key's nudge step in the unit shown: its own in SI, else rounded to
/// 1, 2 or 5 in the shown unit (1 mph, 100 rpm, 0.5°), as
/// `sensitivity::nudge_in` nudges.
pub fn shown_step(key: &Key, system: UnitSystem) -> f64 {
    let unit = key.unit_in(system);
    if unit.is_identity() {
        key.step
    } else {
        unit.nice_step(key.step)
    }
}

/// An SI value of `key` rounded to its step in the unit shown (0.5 mm or
/// 0.02 in for the undercut): what a click on the surface sets, so that
/// the inputs pane shows it whole.
pub fn on_step(key: &Key, si: f64, system: UnitSystem) -> f64 {
    let (unit, step) = (key.unit_in(system), shown_step(key, system));
    unit.read((unit.show(si) / step).round() * step)
}

/// An SI value of `key` as shown in `system`: in SI (and in a unit that
/// does not convert) to a thousandth of the step, as it always was; in a
/// converted unit to the step's own last digit (29.92 inHg for a 0.02 inHg
/// step, 94 mph for 1 mph), since the SI value rarely lands on a round
/// number there and more digits would only show the conversion. A nudge
/// still changes the last digit shown.
///
/// A value that is whole at up to three more digits (90.5 or 94.23 mph,
/// as typed) keeps them: the rounding hides only the conversion's digits.
///
/// Where the readout shows the same quantity, the value not typed is
/// shown as the readout shows it, so that one number reads the same in
/// every pane: an angle or a size (ψ, E, the radii) to the readout's
/// digits (0.4887 rad, 9.13°, 1.043 in), or finer where the step is; the
/// air's ρ to a thousandth and ν as 1.776e-5.
pub fn shown_value(key: &Key, si: f64, system: UnitSystem) -> String {
    let unit = key.unit_in(system);
    let (value, step) = (unit.show(si), shown_step(key, system));
    // The value as typed, if it was typed to at most 3 digits past the step.
    let typed = || {
        (0..=3)
            .map(|finer| number(value, step, finer))
            .find(|text| is_exact(text, value))
    };
    match (key.name, key.quantity()) {
        // The air as the readout's air line shows it (ρ 1.007 kg/m³, ν
        // 1.776e-5 m²/s), or as typed where that was finer.
        (AIR_DENSITY, _) => typed().unwrap_or_else(|| trim(format!("{value:.3}"))),
        (VISCOSITY, _) => scientific(value),
        // A batted ball's exit speed and spin as the readout's launch line
        // shows them (44.30 m/s, 191.8 rad/s; 99.09 mph, 1832 rpm), or as
        // typed: the swing's launch otherwise keeps digits nowhere shown.
        (LAUNCH_SPEED, _) => typed().unwrap_or_else(|| readout_digits(value, unit, 2)),
        (LAUNCH_SPIN, _) => typed().unwrap_or_else(|| readout_digits(value, unit, 1)),
        // An angle or a size as the readout shows it (0.4887 rad, 9.13°,
        // 1.043 in), or finer where the step is.
        (_, Quantity::Angle | Quantity::Size) => typed().unwrap_or_else(|| {
            let step_decimals = (-step.log10()).ceil().max(0.0) as usize;
            let decimals = unit.decimals(READOUT_DECIMALS).max(step_decimals);
            trim(format!("{value:.decimals$}"))
        }),
        _ if unit.is_identity() => number(value, step, 3),
        _ => typed().unwrap_or_else(|| number(value, step, 0)),
    }
}

/// ν as the readout shows it, 1.776e-5, or as typed (1.5e-5).
fn scientific(value: f64) -> String {
    (0..=5)
        .map(|digits| format!("{value:.digits$e}"))
        // Relative: every ν is far below the 1e-9 that `is_exact` allows.
        .find(|text| {
            text.parse::<f64>()
                .is_ok_and(|shown| (shown - value).abs() <= 1e-9 * value.abs())
        })
        .unwrap_or_else(|| format!("{value:.3e}"))
}

/// `value` (in `unit`) to the readout's digits for `si_decimals` in SI.
fn readout_digits(value: f64, unit: units::Unit, si_decimals: usize) -> String {
    let decimals = unit.decimals(si_decimals);
    let text = format!("{value:.decimals$}");
    if text == format!("-{:.decimals$}", 0.0) {
        text[1..].to_owned()
    } else {
        text
    }
}

const LAUNCH_SPEED: &str = "launch.speed";
const LAUNCH_SPIN: &str = "launch.spin";
const AIR_DENSITY: &str = "environment.air_density";
const VISCOSITY: &str = "environment.kinematic_viscosity";

/// Whether `text` reads back as `value` (to a part in 10⁹): the digits a
/// user typed, not a conversion's or a derivation's.
fn is_exact(text: &str, value: f64) -> bool {
    text.parse::<f64>()
        .is_ok_and(|shown| (shown - value).abs() <= 1e-9 * value.abs().max(1.0))
}

/// A value and its unit as the inputs pane's columns show them: degrees
/// on their number ("9.13°", as every other pane writes an angle), other
/// units in the unit column ("1.043", "in").
pub fn value_and_unit(key: &Key, si: f64, system: UnitSystem) -> (String, &'static str) {
    let (value, symbol) = (shown_value(key, si, system), key.unit_in(system).symbol);
    if symbol == "°" {
        (format!("{value}°"), "")
    } else {
        (value, symbol)
    }
}

/// An SI value of `key` in `system`, to a thousandth of the shown step: for
/// a refused value, which is named as typed rather than rounded.
fn precise_value(key: &Key, si: f64, system: UnitSystem) -> String {
    number(key.unit_in(system).show(si), shown_step(key, system), 3)
}

/// `value` to `finer` more decimals than `step` has, trailing zeros
/// trimmed.
fn number(value: f64, step: f64, finer: i32) -> String {
    let decimals = ((-step.log10()).ceil() as i32 + finer).clamp(0, 12) as usize;
    trim(format!("{value:.decimals$}"))
}

/// A number's text without trailing zeros (nor a lone point, nor "-0").
fn trim(text: String) -> String {
    let text = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    };
    if text == "-0" { "0".to_owned() } else { text }
}

/// A typed value of `key` back in SI: a bare number in the unit shown, or
/// a number with a unit (`103mph`, `28°`) as `--set` takes it; or why not.
pub fn read_value(key: &Key, text: &str, system: UnitSystem) -> Result<f64, InputError> {
    let unit = key.unit_in(system);
    match text.trim().parse::<f64>() {
        Ok(shown) => Ok(unit.read(shown)),
        Err(_) => key.read_with_unit(text, unit),
    }
}

/// A key's accepted range in the unit shown, with the unit: "(0, 100] m/s",
/// "(0, 223.693] mph", "[-90, 90] °".
pub fn shown_bounds(key: &Key, system: UnitSystem) -> String {
    let (range, symbol) = (shown_range(key, system), key.unit_in(system).symbol);
    if symbol.is_empty() {
        range
    } else {
        format!("{range} {symbol}")
    }
}

/// A key's accepted range in the unit shown, without the unit: "(0, 100]",
/// "(-90, 90)", "[-π/2, π/2]".
pub fn shown_range(key: &Key, system: UnitSystem) -> String {
    let unit = key.unit_in(system);
    // Each end accepted when typed back (in SI the table's own text).
    key.bounds.shown_in(unit)
}

/// Why a value was refused, in the units shown: a range error on a key
/// names the value and its accepted range in the key's shown unit
/// ("pitch.speed = 300 mph: must be a finite number in (0, 223.693] mph");
/// a miss, in the undercut's. Other relations between inputs keep the
/// library's SI text.
pub fn error_text(error: &InputError, system: UnitSystem) -> String {
    if system == UnitSystem::Si {
        return error.to_string();
    }
    match error {
        InputError::OutOfRange { key, value, .. } => {
            let Ok(key) = model::scene::Scene::key(key) else {
                return error.to_string();
            };
            let unit = key.unit_in(system);
            if unit.is_identity() {
                return error.to_string();
            }
            format!(
                "{} = {} {}: must be a finite number in {}",
                key.name,
                precise_value(key, *value, system),
                unit.symbol,
                shown_bounds(key, system)
            )
        }
        InputError::Miss { value, limit } => {
            let unit = Quantity::Size.in_system(system);
            format!(
                "bat.undercut = {} {}: the bat misses the ball; |E| must be below r_b + r_B = {} {}",
                number_text((unit.show(*value) * 1e4).round() / 1e4),
                unit.symbol,
                number_text((unit.show(*limit) * 1e4).round() / 1e4),
                unit.symbol
            )
        }
        _ => error.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use model::scene::Scene;

    #[test]
    fn imperial_values_steps_and_errors_are_in_the_shown_unit() {
        let imperial = UnitSystem::Imperial;
        let speed = Scene::key("pitch.speed").unwrap();
        // 42 m/s is 93.951 mph; the step is 1 mph, so whole mph are shown.
        assert_eq!(shown_step(speed, imperial), 1.0);
        assert_eq!(shown_value(speed, 42.0, imperial), "94");
        assert_eq!(shown_value(speed, 42.0 + 0.44704, imperial), "95");
        // Typed values keep their digits (issue 36): 90.5 mph is shown and
        // edited as 90.5, 94.23 as 94.23; a nudge keeps the half.
        for typed in ["90.5", "94.23", "94", "101.125"] {
            let si = read_value(speed, typed, imperial).unwrap();
            assert_eq!(shown_value(speed, si, imperial), typed);
        }
        let nudged = read_value(speed, "90.5", imperial).unwrap() + 0.44704;
        assert_eq!(shown_value(speed, nudged, imperial), "91.5");
        // Four more digits are the conversion's: rounded to the step.
        let si = read_value(speed, "94.2345", imperial).unwrap();
        assert_eq!(shown_value(speed, si, imperial), "94");
        assert!((read_value(speed, "100", imperial).unwrap() - 44.704).abs() < 1e-12);
        let mut scene = Scene::default();
        scene.pitch.speed = read_value(speed, "300", imperial).unwrap();
        let error = scene.validate().unwrap_err();
        assert_eq!(
            error_text(&error, imperial),
            "pitch.speed = 300 mph: must be a finite number in (0, 223.693] mph"
        );
        // An angle's bound, π/2, is 90°.
        let angle = Scene::key("launch.angle").unwrap();
        let mut scene = Scene::default();
        (angle.set)(&mut scene, read_value(angle, "95", imperial).unwrap());
        let error = scene.validate().unwrap_err();
        assert_eq!(
            error_text(&error, imperial),
            "launch.angle = 95 °: must be a finite number in [-90, 90] °"
        );
        // SI keeps the library's text.
        assert_eq!(error_text(&error, UnitSystem::Si), error.to_string());
    }
    #[test]
    fn imperial_values_show_the_steps_digits_and_a_nudge_shows() {
        let imperial = UnitSystem::Imperial;
        let shown = |name: &str, si: f64| shown_value(Scene::key(name).unwrap(), si, imperial);
        // 1013.25 hPa is 29.921 inHg; the step is 0.02 inHg.
        assert_eq!(shown("environment.pressure", 1013.25), "29.92");
        // 0.0265 m is 1.0433 in, step 0.02 in; 0.0231 m is 0.9094 in:
        // to the thousandth, as the readout shows an undercut (1.043 in).
        assert_eq!(shown("bat.undercut", 0.0265), "1.043");
        assert_eq!(shown("ball.gyration_radius", 0.0231), "0.909");
        // Table II's ψ, 0.1594 rad, is 9.133°: 9.13° as the readout has it,
        // the degree sign on the number as everywhere else.
        assert_eq!(shown("bat.swing_angle", 0.1594), "9.13");
        let psi = Scene::key("bat.swing_angle").unwrap();
        assert_eq!(
            value_and_unit(psi, 0.1594, imperial),
            ("9.13°".to_owned(), "")
        );
        // The air as the readout shows it: ρ 1.007, ν 1.776e-5 (Coors'),
        // or as typed (1.23, 1.5e-5).
        for system in [imperial, UnitSystem::Si] {
            let air = |name: &str, si: f64| shown_value(Scene::key(name).unwrap(), si, system);
            assert_eq!(air("environment.air_density", 1.007_330_4), "1.007");
            assert_eq!(air("environment.air_density", 1.23), "1.23");
            assert_eq!(air("environment.air_density", 1.2345), "1.2345");
            assert_eq!(
                air("environment.kinematic_viscosity", 1.776_290_3e-5),
                "1.776e-5"
            );
            assert_eq!(air("environment.kinematic_viscosity", 1.5e-5), "1.5e-5");
        }
        let speed = Scene::key("pitch.speed").unwrap();
        assert_eq!(
            value_and_unit(speed, 42.0, imperial),
            ("94".to_owned(), "mph")
        );
        // A batted ball's launch, not typed, as the readout's launch line
        // has it; typed, as typed (issue 36).
        for (system, speed, spin) in [
            (UnitSystem::Si, "44.30", "191.8"),
            (imperial, "99.09", "1832"),
        ] {
            let launch = |name: &str, si: f64| shown_value(Scene::key(name).unwrap(), si, system);
            assert_eq!(launch("launch.speed", 44.299_13), speed);
            assert_eq!(launch("launch.spin", 191.834_6), spin);
        }
        let exit = Scene::key("launch.speed").unwrap();
        for typed in ["44.2991", "44.3", "45"] {
            let si = read_value(exit, typed, UnitSystem::Si).unwrap();
            assert_eq!(shown_value(exit, si, UnitSystem::Si), typed);
        }
        // SI as it always was: a thousandth of the step.
        assert_eq!(
            shown_value(Scene::key("bat.undercut").unwrap(), 0.0265, UnitSystem::Si),
            "0.0265"
        );
        // An angle in SI as the readout shows it: 28° is 0.4887 rad, and
        // the optimum's ψ 0.1744 rad; a typed 0.48869 keeps its digits.
        let si_angle =
            |name: &str, rad: f64| shown_value(Scene::key(name).unwrap(), rad, UnitSystem::Si);
        assert_eq!(si_angle("launch.angle", 28f64.to_radians()), "0.4887");
        assert_eq!(si_angle("bat.swing_angle", 0.174_372_1), "0.1744");
        assert_eq!(si_angle("launch.angle", 0.48869), "0.48869");
        let scene = Scene::default();
        for key in model::keys::all_keys() {
            let step = shown_step(key, imperial);
            let unit = key.unit_in(imperial);
            let si = (key.get)(&scene);
            let nudged = unit.read(unit.show(si) + step);
            assert_ne!(
                shown_value(key, si, imperial),
                shown_value(key, nudged, imperial),
                "{} by {step}",
                key.name
            );
            let text = shown_value(key, si, imperial);
            let decimals = text.split_once('.').map_or(0, |(_, d)| d.len());
            // The step's digits, or (an angle, a size) the readout's.
            if !unit.is_identity() {
                let step_decimals = (-step.log10()).ceil().max(0.0) as usize;
                let most = step_decimals.max(unit.decimals(READOUT_DECIMALS));
                assert!(decimals <= most, "{}: {text}", key.name);
            }
        }
    }
}

/// A difference with its sign and `decimals` decimals, "+0.00" rather than
/// "-0.00" for one that rounds to nothing (a class reads "-0.00" as a
/// loss).
pub fn signed(value: f64, decimals: usize) -> String {
    let text = format!("{value:+.decimals$}");
    if text.starts_with('-') && text[1..].chars().all(|c| c == '0' || c == '.') {
        format!("+{}", &text[1..])
    } else {
        text
    }
}

#[cfg(test)]
mod signed_tests {
    use super::signed;

    #[test]
    fn a_difference_that_rounds_to_nothing_is_positive_zero() {
        assert_eq!(signed(-0.001, 2), "+0.00");
        assert_eq!(signed(-0.0, 4), "+0.0000");
        assert_eq!(signed(-0.006, 2), "-0.01");
        assert_eq!(signed(0.004, 2), "+0.00");
        assert_eq!(signed(-95.0, 0), "-95");
    }
}
