//! Every numeric input has one entry in [`KEYS`] (or, for the inputs beyond
//! the paper, [`EXTENDED_KEYS`]): its dotted key (the same in TOML presets,
//! `--set`, sweeps and the explorer), its symbol in the paper, its unit, its
//! accepted range and a nudge step for the explorer. Validation, parsing and
//! the generic get/set all go through those tables, so a new input is added
//! in exactly one place. [`InputBatch`] sets the keys of one source of
//! inputs, refusing contradictory ones.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_3, PI};

use units::{self, Quantity, Unit, UnitSystem};

use super::aero::UnknownModel;
use super::pitch;
use super::scene::{Scene, UnknownHand};

mod batch;
mod table;
mod typed;

pub use batch::InputBatch;
pub use table::{
    AIR_KEYS, ATMOSPHERE_KEYS, CALIBRATION_KEYS, DRAG_KEY, EXTENDED_KEYS, HAND_KEY, KEYS,
    LAUNCH_KEYS, LIFT_KEY, SWING_3D_KEYS, TEXT_KEYS, TRACKING_KEYS, all_keys, swing_keys,
};
pub use typed::{Typed, out_of_range_shown, read_in_system, read_typed};

/// A closed or half-open interval of accepted values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    pub min: f64,
    pub max: f64,
    /// Whether `min` itself is excluded (speeds, masses, radii must be > 0).
    pub min_exclusive: bool,
    /// Whether `max` itself is excluded (a launch angle stays below π/2).
    pub max_exclusive: bool,
}

impl Bounds {
    const fn closed(min: f64, max: f64) -> Self {
        Bounds {
            min,
            max,
            min_exclusive: false,
            max_exclusive: false,
        }
    }
    const fn positive(max: f64) -> Self {
        Bounds {
            min: 0.0,
            max,
            min_exclusive: true,
            max_exclusive: false,
        }
    }
    /// `value` of key `key` (in `unit`) if it is inside, else the error
    /// that names the key, the value and the range.
    pub fn check(
        self,
        key: &'static str,
        value: f64,
        unit: &'static str,
    ) -> Result<(), InputError> {
        if self.contains(value) {
            Ok(())
        } else {
            Err(InputError::OutOfRange {
                key,
                value,
                bounds: self,
                unit,
                typed: None,
            })
        }
    }

    pub fn contains(&self, value: f64) -> bool {
        let above = if self.min_exclusive {
            value > self.min
        } else {
            value >= self.min
        };
        let below = if self.max_exclusive {
            value < self.max
        } else {
            value <= self.max
        };
        value.is_finite() && above && below
    }
}

impl std::fmt::Display for Bounds {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let open = if self.min_exclusive { '(' } else { '[' };
        let close = if self.max_exclusive { ')' } else { ']' };
        write!(
            f,
            "{open}{}, {}{close}",
            bound_text(self.min),
            bound_text(self.max)
        )
    }
}

/// A bound as a person reads it: ±π/2 rather than ±1.5707963267948966.
fn bound_text(value: f64) -> String {
    match value {
        FRAC_PI_2 => "π/2".to_owned(),
        FRAC_PI_3 => "π/3".to_owned(),
        PI => "π".to_owned(),
        _ if value == -FRAC_PI_2 => "-π/2".to_owned(),
        _ if value == -FRAC_PI_3 => "-π/3".to_owned(),
        _ if value == -PI => "-π".to_owned(),
        _ => value.to_string(),
    }
}

/// One numeric input: how it is named, bounded, nudged, read and written.
#[derive(Clone, Copy)]
pub struct Key {
    /// Dotted key, as in TOML and `--set`.
    pub name: &'static str,
    /// The paper's symbol.
    pub symbol: &'static str,
    pub unit: &'static str,
    pub description: &'static str,
    pub bounds: Bounds,
    /// Why the bounds are where they are, in a sentence or two.
    pub bounds_reason: &'static str,
    /// A nudge that suits the quantity (the explorer's arrow keys).
    pub step: f64,
    pub get: fn(&Scene) -> f64,
    pub set: fn(&mut Scene, f64),
}

impl Key {
    /// What the key measures, which decides its unit outside SI. From the
    /// SI unit, except that lengths split into sizes (of the ball and the
    /// bat, and the undercut: inches) and distances (feet).
    pub fn quantity(&self) -> Quantity {
        match self.unit {
            "m" if self.name == "bat.undercut" || self.name.ends_with("radius") => Quantity::Size,
            "m" => Quantity::Distance,
            "m/s" => Quantity::Speed,
            "rad/s" => Quantity::Spin,
            "rad" => Quantity::Angle,
            "°C" => Quantity::Temperature,
            "hPa" => Quantity::Pressure,
            "kg" => Quantity::Mass,
            "m/s²" => Quantity::Acceleration,
            _ => Quantity::Unchanged,
        }
    }

    /// The unit this key is shown and typed in under `system`.
    pub fn unit_in(&self, system: UnitSystem) -> Unit {
        self.quantity().unit(system, self.unit)
    }
}

impl std::fmt::Debug for Key {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name)
    }
}

/// Why a set of inputs was refused. Each message names the key, the value and
/// what would have been accepted.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum InputError {
    #[error(
        "{key} = {}: must be a finite number in {bounds}{}{}",
        .typed.as_ref().map_or_else(|| number_text(*.value), |t| t.text.clone()),
        unit_suffix(.unit),
        .typed.as_ref().map_or("", |t| t.suggestion.as_str())
    )]
    OutOfRange {
        key: &'static str,
        /// In SI.
        value: f64,
        bounds: Bounds,
        unit: &'static str,
        /// The text typed, when the value was typed as text.
        typed: Option<Box<Typed>>,
    },
    #[error("{key} = {text}: {why}; {key} takes {accepted}")]
    WrongUnit {
        key: &'static str,
        text: String,
        /// What is wrong with the unit typed.
        why: String,
        /// The units the key takes.
        accepted: String,
    },
    #[error(
        "bat.undercut = {}: the bat misses the ball; |E| must be below r_b + r_B = {} m",
        number_text(*.value),
        units::significant(*.limit)
    )]
    Miss { value: f64, limit: f64 },
    #[error(
        "pitch.speed = {}: Eq. (3)'s fit gives {}, more than the speed itself; at this gravity it needs a pitch speed of at least {minimum:.2} m/s",
        number_text(*.speed),
        vertical_text(*.vertical)
    )]
    PitchOutsideFit {
        speed: f64,
        vertical: f64,
        minimum: f64,
    },
    #[error("unknown key `{key}`; {}", unknown_key_hint(.key, .known))]
    UnknownKey { key: String, known: String },
    #[error("{key} = {text:?}: not a number")]
    NotANumber { key: String, text: String },
    #[error(
        "{key} = {} {unit}, taken from the swing ({swing}): must be in {bounds} {unit}, as if given; give {key}, or change the swing",
        units::significant(*.value)
    )]
    SwingLaunch {
        key: &'static str,
        value: f64,
        bounds: Bounds,
        unit: &'static str,
        /// The swing's inputs that made it: "pitch.speed = 42, …".
        swing: String,
    },
    #[error(transparent)]
    UnknownModel(#[from] UnknownModel),
    #[error(transparent)]
    UnknownHand(#[from] UnknownHand),
    #[error(
        "{given} and {weather} set together: the weather keys ({}) derive ρ and ν; give either ρ and ν or the weather",
        ATMOSPHERE_KEYS.join(", ")
    )]
    AirGivenTwice {
        /// The ρ or ν key given.
        given: &'static str,
        /// The weather key given.
        weather: &'static str,
    },
    #[error(
        "ball.mass = {} kg: with ball.radius = {} m the ball is {density:.3} kg/m³ on average; the model ignores buoyancy and needs at least {MIN_BALL_DENSITY} kg/m³ (a ping-pong ball is ~80), so ball.mass ≥ {minimum:.4} kg",
        number_text(*.mass),
        number_text(*.radius)
    )]
    BallTooLight {
        mass: f64,
        radius: f64,
        density: f64,
        minimum: f64,
    },
    #[error(
        "{key} = {} m: must be in [{min:.4}, {max:.4}] m, from {} to {} of {radius_key} = {} m",
        number_text(*.value),
        GYRATION_CORE,
        .shape,
        number_text(*.radius)
    )]
    GyrationRadius {
        key: &'static str,
        value: f64,
        radius_key: &'static str,
        radius: f64,
        min: f64,
        max: f64,
        /// The largest ratio, in words.
        shape: &'static str,
    },
}

impl Scene {
    /// Looks up a numeric key.
    pub fn key(name: &str) -> Result<&'static Key, InputError> {
        // By hash: a batch looks up a column's key on every row, and a
        // search through the 70-odd names cost more than the rest of
        // setting it.
        static BY_NAME: std::sync::OnceLock<std::collections::HashMap<&'static str, &'static Key>> =
            std::sync::OnceLock::new();
        let by_name = BY_NAME.get_or_init(|| all_keys().map(|k| (k.name, k)).collect());
        by_name
            .get(name)
            .copied()
            .ok_or_else(|| InputError::UnknownKey {
                key: name.to_owned(),
                known: known_keys(),
            })
    }

    pub fn get(&self, name: &str) -> Result<f64, InputError> {
        Ok((Self::key(name)?.get)(self))
    }

    /// Sets a numeric key, without validating the whole scene (call
    /// [`Scene::validate`] once all changes are made).
    pub fn set(&mut self, name: &str, value: f64) -> Result<(), InputError> {
        (Self::key(name)?.set)(self, value);
        Ok(())
    }

    /// Sets any key from text, as `--set KEY=VALUE` does: a number in SI,
    /// or with a unit of the key's quantity ([`Key::read`]), in range.
    pub fn set_text(&mut self, name: &str, text: &str) -> Result<(), InputError> {
        self.set_text_in(name, text, UnitSystem::Si)
    }

    /// [`Scene::set_text`] typed under `system`: a bare number is in the
    /// unit the key is shown in there ([`Key::read_in`]).
    pub fn set_text_in(
        &mut self,
        name: &str,
        text: &str,
        system: UnitSystem,
    ) -> Result<(), InputError> {
        if name == DRAG_KEY {
            self.choose_drag(text.parse()?);
            return Ok(());
        }
        if name == LIFT_KEY {
            self.choose_lift(text.parse()?);
            return Ok(());
        }
        if name == HAND_KEY {
            self.bat.hand = text.parse()?;
            return Ok(());
        }
        let key = Self::key(name)?;
        let value = key.read_in(text, system)?;
        (key.set)(self, value);
        Ok(())
    }

    /// Checks every input before any computation. The first problem found is
    /// returned; ranges first, then the relations between inputs.
    pub fn validate(&self) -> Result<(), InputError> {
        // Derived, ρ and ν are checked after the weather they come from, so
        // that a bad temperature is named rather than the density it gave.
        let derived = self.environment.atmosphere().is_some();
        // Only the launch values given are inputs: one taken from the swing
        // is an output of the (validated) swing, checked through it.
        let ordered = checking_order(derived)
            .iter()
            .map(|&key| (key, (key.get)(self)))
            .chain(self.given_launch());
        for (key, value) in ordered {
            key.bounds.check(key.name, value, key.unit)?;
        }
        let density =
            self.ball.mass / (4.0 / 3.0 * std::f64::consts::PI * self.ball.radius.powi(3));
        if density < MIN_BALL_DENSITY {
            return Err(InputError::BallTooLight {
                mass: self.ball.mass,
                radius: self.ball.radius,
                density,
                minimum: self.ball.mass * MIN_BALL_DENSITY / density,
            });
        }
        check_gyration(
            "ball.gyration_radius",
            self.ball.gyration_radius,
            ("ball.radius", self.ball.radius),
            (SHELL_GYRATION, "√(2/3) (a thin shell)"),
        )?;
        check_gyration(
            "bat.gyration_radius",
            self.bat.gyration_radius,
            ("bat.radius", self.bat.radius),
            (1.0, "1 (a thin tube)"),
        )?;
        let limit = self.reach();
        if self.bat.undercut.abs() >= limit {
            return Err(InputError::Miss {
                value: self.bat.undercut,
                limit,
            });
        }
        let vertical = pitch::vertical_velocity(self.pitch.speed, self.environment.gravity);
        if vertical.abs() >= self.pitch.speed {
            return Err(InputError::PitchOutsideFit {
                speed: self.pitch.speed,
                vertical,
                minimum: pitch::minimum_speed(self.environment.gravity),
            });
        }
        self.check_swing_launch()
    }

    /// [`Scene::validate`] for a scene validated whole whose launch values
    /// alone have changed since (a batch row's direction solved, its spin
    /// estimated): nothing else it checks depends on them, so this finds
    /// what `validate` would, at a fraction of its cost.
    pub fn validate_changed_launch(&self) -> Result<(), InputError> {
        // A batch row's common case, checked at once: every value given in
        // its bounds, and none left to the swing.
        let values = self.launch.values();
        let in_bounds = LAUNCH_KEYS
            .iter()
            .zip(values)
            .all(|(key, value)| value.is_none_or(|v| key.bounds.contains(v)));
        if in_bounds && self.launch.is_complete() {
            return Ok(());
        }
        for (key, value) in self.given_launch() {
            key.bounds.check(key.name, value, key.unit)?;
        }
        self.check_swing_launch()
    }

    /// The launch keys given, with their values.
    fn given_launch(&self) -> impl Iterator<Item = (&'static Key, f64)> {
        LAUNCH_KEYS
            .iter()
            .zip(self.launch.values())
            .filter_map(|(key, value)| value.map(|v| (key, v)))
    }
}

/// Every key but the launch's, in the order [`Scene::validate`] checks
/// them: with the air `derived` from the weather, ρ and ν after the rest.
/// Worked out once (a batch validates every row; comparing names each time
/// cost more than the checks).
fn checking_order(derived: bool) -> &'static [&'static Key] {
    static ORDERS: std::sync::OnceLock<[Vec<&'static Key>; 2]> = std::sync::OnceLock::new();
    let orders = ORDERS.get_or_init(|| {
        let inputs = || swing_keys().chain(CALIBRATION_KEYS).chain(TRACKING_KEYS);
        let later = |key: &&Key| AIR_KEYS.contains(&key.name);
        let given: Vec<_> = inputs().collect();
        let derived = inputs()
            .filter(|k| !later(k))
            .chain(inputs().filter(later))
            .collect();
        [given, derived]
    });
    &orders[usize::from(derived)]
}

/// The lightest ball the model is fair to (kg/m³, mean density): buoyancy,
/// which it ignores, is then at most ρ/50 of the weight (2.5 % at sea
/// level). A ping-pong ball is ~80 kg/m³, a baseball ~700.
pub const MIN_BALL_DENSITY: f64 = 50.0;
/// The smallest radius of gyration accepted, as a fraction of the radius:
/// a body with nearly all its mass at the centre.
const GYRATION_CORE: f64 = 0.2;
/// A thin spherical shell's k/r = √(2/3): no sphere spreads its mass further.
const SHELL_GYRATION: f64 = 0.816_496_580_927_726;

/// A radius of gyration between `GYRATION_CORE` and `max_ratio` times its
/// body's radius.
fn check_gyration(
    key: &'static str,
    value: f64,
    (radius_key, radius): (&'static str, f64),
    (max_ratio, shape): (f64, &'static str),
) -> Result<(), InputError> {
    let (min, max) = (GYRATION_CORE * radius, max_ratio * radius);
    if (min..=max).contains(&value) {
        Ok(())
    } else {
        Err(InputError::GyrationRadius {
            key,
            value,
            radius_key,
            radius,
            min,
            max,
            shape,
        })
    }
}

/// What to say of an unknown key: the known key closest to it (by
/// Jaro–Winkler, above 0.85), or where to find them all, not all of them.
fn unknown_key_hint(key: &str, known: &str) -> String {
    let names = || known.split(", ").filter(|name| !name.is_empty());
    let closest = names()
        .map(|name| (strsim::jaro_winkler(key, name), name))
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .filter(|(score, _)| *score > 0.85);
    if let Some((_, name)) = closest {
        return format!("did you mean `{name}`? (`homerun keys` lists every key)");
    }
    let mut groups: Vec<&str> = Vec::new();
    for name in names() {
        let group = name.split_once('.').map_or(name, |(group, _)| group);
        if !groups.contains(&group) {
            groups.push(group);
        }
    }
    let groups: Vec<String> = groups.iter().map(|g| format!("{g}.*")).collect();
    format!("`homerun keys` lists every key ({})", groups.join(", "))
}

/// A number as typed when that is short (0.09, 1000, NaN, 1518.1420786309536),
/// in scientific notation when Rust's plain form would run to hundreds of
/// digits (1e-200): either way the shortest digits that read back as it.
pub fn number_text(value: f64) -> String {
    let plain = value.to_string();
    if plain.len() <= 20 {
        plain
    } else {
        format!("{value:e}")
    }
}

/// Eq. (3)'s vertical velocity in an error: "a vertical velocity of
/// -6.51 m/s", or of 1e301 m/s for a pitch of 1e-300 m/s; infinite below
/// that (5e-324 m/s).
fn vertical_text(vertical: f64) -> String {
    if vertical.is_finite() {
        format!(
            "a vertical velocity of {} m/s",
            units::significant(vertical)
        )
    } else {
        "an infinite vertical velocity".to_owned()
    }
}

fn unit_suffix(unit: &str) -> String {
    if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    }
}

fn known_keys() -> String {
    let mut names: Vec<&str> = all_keys().map(|k| k.name).collect();
    names.extend(TEXT_KEYS);
    names.join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_key_reads_back_what_it_wrote() {
        for key in KEYS {
            let mut scene = Scene::default();
            let value = (key.get)(&scene) + key.step;
            (key.set)(&mut scene, value);
            assert_eq!((key.get)(&scene), value, "{}", key.name);
        }
    }

    #[test]
    fn defaults_are_valid_and_bad_values_name_their_key() {
        Scene::default().validate().unwrap();
        let mut scene = Scene::default();
        scene.bat.speed = f64::NAN;
        let message = scene.validate().unwrap_err().to_string();
        assert!(message.starts_with("bat.speed = NaN"), "{message}");
        let mut scene = Scene::default();
        scene.bat.undercut = 0.0716;
        assert!(matches!(scene.validate(), Err(InputError::Miss { .. })));
    }

    #[test]
    fn a_changed_launch_is_judged_as_the_whole_check_judges_it() {
        // From valid scenes, swing and batted ball, at sea level and with
        // the air derived from weather (the whole check's other order),
        // each launch value set good, out of range, NaN or left to the
        // swing: both checks give the same answer, error for error.
        let mut weather = Scene::default();
        weather.set("environment.temperature", 35.0).unwrap();
        let mut batted = Scene::default();
        batted.launch.speed = Some(45.0);
        batted.launch.angle = Some(0.5);
        // Every value given (a batch row's usual launch): the quick check.
        let mut complete = batted;
        complete.launch.spin = Some(200.0);
        complete.launch.direction = Some(-0.2);
        complete.launch.sidespin = Some(30.0);
        let values = [
            None,
            Some(0.3),
            Some(-2.0),
            Some(500.0),
            Some(1e5),
            Some(f64::NAN),
        ];
        let mut compared = 0;
        let mut refused = 0;
        for base in [Scene::default(), weather, batted, complete] {
            base.validate().unwrap();
            for slot in 0..5 {
                for value in values {
                    let mut scene = base;
                    match slot {
                        0 => scene.launch.speed = value,
                        1 => scene.launch.angle = value,
                        2 => scene.launch.spin = value,
                        3 => scene.launch.direction = value,
                        _ => scene.launch.sidespin = value,
                    }
                    let whole = scene.validate().map_err(|e| e.to_string());
                    let launch = scene.validate_changed_launch().map_err(|e| e.to_string());
                    assert_eq!(launch, whole, "slot {slot} = {value:?}");
                    refused += usize::from(whole.is_err());
                    compared += 1;
                }
            }
        }
        assert_eq!(compared, 120);
        // Out of range, NaN, and a swing's own launch a given value
        // leaves outside its bounds: both kinds of refusal are compared.
        assert!(refused >= 30, "{refused}");
    }

    #[test]
    fn tiny_values_are_refused_in_short_form() {
        let mut scene = Scene::default();
        scene.ball.mass = 5e-324;
        let message = scene.validate().unwrap_err().to_string();
        assert_eq!(
            message,
            "ball.mass = 5e-324: must be a finite number in [0.001, 10] kg"
        );
    }

    #[test]
    fn a_ball_lighter_than_the_model_allows_is_refused_with_its_minimum() {
        // A baseball-sized ball of 1 g is 4.9 kg/m³: a balloon.
        let mut scene = Scene::default();
        scene.ball.mass = 0.001;
        let Err(InputError::BallTooLight { minimum, .. }) = scene.validate() else {
            panic!("accepted a balloon");
        };
        // The minimum itself is accepted: 50 kg/m³ × (4/3)π(0.0366 m)³.
        let expected = MIN_BALL_DENSITY * 4.0 / 3.0 * std::f64::consts::PI * 0.0366f64.powi(3);
        assert!(
            (minimum - expected).abs() < 1e-12,
            "{minimum} vs {expected}"
        );
        scene.ball.mass = minimum * (1.0 + 1e-12);
        scene.validate().unwrap();
    }

    #[test]
    fn radii_of_gyration_stay_within_their_bodies() {
        // A thin shell's k = √(2/3)·r is the largest a sphere can have.
        let mut scene = Scene::default();
        scene.ball.gyration_radius = 0.817 * scene.ball.radius;
        assert!(matches!(
            scene.validate(),
            Err(InputError::GyrationRadius {
                key: "ball.gyration_radius",
                ..
            })
        ));
        scene.ball.gyration_radius = 0.816 * scene.ball.radius;
        scene.validate().unwrap();
        // A bat's k about its own axis is at most its radius (a thin tube).
        let mut scene = Scene::default();
        scene.bat.gyration_radius = 1.01 * scene.bat.radius;
        let message = scene.validate().unwrap_err().to_string();
        assert!(message.starts_with("bat.gyration_radius = "), "{message}");
        scene.bat.gyration_radius = 0.19 * scene.bat.radius;
        assert!(scene.validate().is_err());
    }
}

#[cfg(test)]
mod quantity_tests {
    use super::*;

    fn quantity(name: &str) -> Quantity {
        all_keys()
            .find(|k| k.name == name)
            .unwrap_or_else(|| panic!("no key {name}"))
            .quantity()
    }

    #[test]
    fn lengths_split_into_sizes_and_distances() {
        for size in [
            "bat.undercut",
            "bat.radius",
            "bat.gyration_radius",
            "ball.radius",
        ] {
            assert_eq!(quantity(size), Quantity::Size, "{size}");
        }
        for distance in ["environment.contact_height", "environment.elevation"] {
            assert_eq!(quantity(distance), Quantity::Distance, "{distance}");
        }
        assert_eq!(quantity("bat.swing_angle"), Quantity::Angle);
        assert_eq!(quantity("pitch.spin"), Quantity::Spin);
        assert_eq!(quantity("environment.air_density"), Quantity::Unchanged);
        // Every key with a unit of length, speed or angle has an imperial one.
        for key in all_keys() {
            let imperial = key.unit_in(UnitSystem::Imperial);
            if ["m", "m/s", "rad", "rad/s", "kg", "°C", "hPa"].contains(&key.unit) {
                assert!(!imperial.is_identity(), "{}", key.name);
            }
        }
    }
}
