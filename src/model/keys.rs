//! Every numeric input has one entry in [`KEYS`]: its dotted key (the same in
//! TOML presets, `--set`, sweeps and the explorer), its symbol in the paper, its
//! unit, its accepted range and a nudge step for the explorer. Validation,
//! parsing and the generic get/set all go through that table, so a new input
//! is added in exactly one place.

use std::f64::consts::FRAC_PI_2;

use super::aero::UnknownModel;
use super::pitch;
use super::scene::Scene;

/// A closed or half-open interval of accepted values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    pub min: f64,
    pub max: f64,
    /// Whether `min` itself is excluded (speeds, masses, radii must be > 0).
    pub min_exclusive: bool,
}

impl Bounds {
    const fn closed(min: f64, max: f64) -> Self {
        Bounds {
            min,
            max,
            min_exclusive: false,
        }
    }
    const fn positive(max: f64) -> Self {
        Bounds {
            min: 0.0,
            max,
            min_exclusive: true,
        }
    }
    pub fn contains(&self, value: f64) -> bool {
        let above = if self.min_exclusive {
            value > self.min
        } else {
            value >= self.min
        };
        value.is_finite() && above && value <= self.max
    }
}

impl std::fmt::Display for Bounds {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let open = if self.min_exclusive { '(' } else { '[' };
        write!(
            f,
            "{open}{}, {}]",
            bound_text(self.min),
            bound_text(self.max)
        )
    }
}

/// A bound as a person reads it: ±π/2 rather than ±1.5707963267948966.
fn bound_text(value: f64) -> String {
    if value == FRAC_PI_2 {
        "π/2".to_owned()
    } else if value == -FRAC_PI_2 {
        "-π/2".to_owned()
    } else {
        value.to_string()
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
    /// A nudge that suits the quantity (the explorer's arrow keys).
    pub step: f64,
    pub get: fn(&Scene) -> f64,
    pub set: fn(&mut Scene, f64),
}

impl std::fmt::Debug for Key {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name)
    }
}

macro_rules! key {
    ($name:literal, $symbol:literal, $unit:literal, $desc:literal, $bounds:expr, $step:expr, $($field:ident).+) => {
        Key {
            name: $name,
            symbol: $symbol,
            unit: $unit,
            description: $desc,
            bounds: $bounds,
            step: $step,
            get: |s| s.$($field).+,
            set: |s, v| s.$($field).+ = v,
        }
    };
}

/// Every numeric input. Bounds are what the model can meaningfully take:
/// Eq. (19) keeps e* in (0, 1) for approach speeds below about 240 m/s, so
/// speeds stop at 100 m/s each.
pub const KEYS: &[Key] = &[
    key!(
        "pitch.speed",
        "V̂_b0",
        "m/s",
        "pitch speed at the plate",
        Bounds::positive(100.0),
        0.5,
        pitch.speed
    ),
    key!(
        "pitch.spin",
        "ω_b0",
        "rad/s",
        "pitch spin (topspin positive, fastball backspin negative)",
        Bounds::closed(-1000.0, 1000.0),
        10.0,
        pitch.spin
    ),
    key!(
        "bat.speed",
        "V̂_B0",
        "m/s",
        "bat speed at the contact point",
        Bounds::positive(100.0),
        0.5,
        bat.speed
    ),
    key!(
        "bat.spin",
        "ω_B0",
        "rad/s",
        "bat roll about its axis (positive adds backspin, Fig. 9)",
        Bounds::closed(-200.0, 200.0),
        5.0,
        bat.spin
    ),
    key!(
        "bat.undercut",
        "E",
        "m",
        "undercut: ball centre above bat axis",
        Bounds::closed(-0.4, 0.4),
        0.0005,
        bat.undercut
    ),
    key!(
        "bat.swing_angle",
        "ψ",
        "rad",
        "swing angle above horizontal",
        Bounds::closed(-FRAC_PI_2, FRAC_PI_2),
        0.01,
        bat.swing_angle
    ),
    key!(
        "bat.friction",
        "μ",
        "",
        "bat–ball coefficient of friction",
        Bounds::closed(0.0, 2.0),
        0.01,
        bat.friction
    ),
    key!(
        "bat.effective_mass",
        "M_B",
        "kg",
        "bat mass equivalent at the centre of percussion",
        Bounds::positive(10.0),
        0.05,
        bat.effective_mass
    ),
    key!(
        "bat.radius",
        "r_B",
        "m",
        "bat barrel radius",
        Bounds::positive(0.2),
        0.001,
        bat.radius
    ),
    key!(
        "bat.gyration_radius",
        "k_B2",
        "m",
        "bat radius of gyration about its axis",
        Bounds::positive(0.2),
        0.001,
        bat.gyration_radius
    ),
    key!(
        "ball.mass",
        "M_b",
        "kg",
        "ball mass",
        Bounds::positive(10.0),
        0.005,
        ball.mass
    ),
    key!(
        "ball.radius",
        "r_b",
        "m",
        "ball radius",
        Bounds::positive(0.2),
        0.001,
        ball.radius
    ),
    key!(
        "ball.gyration_radius",
        "k_b",
        "m",
        "ball radius of gyration",
        Bounds::positive(0.2),
        0.001,
        ball.gyration_radius
    ),
    key!(
        "environment.wind",
        "V_w",
        "m/s",
        "horizontal wind, positive toward centre field",
        Bounds::closed(-50.0, 50.0),
        1.0,
        environment.wind
    ),
    key!(
        "environment.air_density",
        "ρ",
        "kg/m³",
        "air density",
        Bounds::closed(0.0, 5.0),
        0.01,
        environment.air_density
    ),
    key!(
        "environment.kinematic_viscosity",
        "ν",
        "m²/s",
        "kinematic viscosity of air",
        Bounds::positive(1e-3),
        1e-7,
        environment.kinematic_viscosity
    ),
    key!(
        "environment.gravity",
        "g",
        "m/s²",
        "gravitational acceleration",
        Bounds::positive(30.0),
        0.1,
        environment.gravity
    ),
    key!(
        "environment.contact_height",
        "y(0)",
        "m",
        "height of the ball at contact",
        Bounds::closed(0.0, 10.0),
        0.1,
        environment.contact_height
    ),
];

/// The one non-numeric input.
pub const DRAG_KEY: &str = "model.drag";

/// Why a set of inputs was refused. Each message names the key, the value and
/// what would have been accepted.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum InputError {
    #[error("{key} = {value}: must be a finite number in {bounds}{}", unit_suffix(.unit))]
    OutOfRange {
        key: &'static str,
        value: f64,
        bounds: Bounds,
        unit: &'static str,
    },
    #[error(
        "bat.undercut = {value}: the bat misses the ball; |E| must be below r_b + r_B = {limit} m"
    )]
    Miss { value: f64, limit: f64 },
    #[error(
        "pitch.speed = {speed}: Eq. (3)'s fit gives a vertical velocity of {vertical:.2} m/s, more than the speed itself; at this gravity it needs a pitch speed of at least {minimum:.2} m/s"
    )]
    PitchOutsideFit {
        speed: f64,
        vertical: f64,
        minimum: f64,
    },
    #[error("unknown key `{key}`{}; known keys: {known}", suggestion(.key))]
    UnknownKey { key: String, known: String },
    #[error("{key} = {text:?}: not a number")]
    NotANumber { key: String, text: String },
    #[error(transparent)]
    UnknownModel(#[from] UnknownModel),
}

impl Scene {
    /// Looks up a numeric key.
    pub fn key(name: &str) -> Result<&'static Key, InputError> {
        KEYS.iter()
            .find(|k| k.name == name)
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

    /// Sets any key from text, as `--set KEY=VALUE` does.
    pub fn set_text(&mut self, name: &str, text: &str) -> Result<(), InputError> {
        if name == DRAG_KEY {
            self.drag = text.parse()?;
            return Ok(());
        }
        let key = Self::key(name)?;
        let value: f64 = text.trim().parse().map_err(|_| InputError::NotANumber {
            key: name.to_owned(),
            text: text.to_owned(),
        })?;
        (key.set)(self, value);
        Ok(())
    }

    /// Checks every input before any computation. The first problem found is
    /// returned; ranges first, then the relations between inputs.
    pub fn validate(&self) -> Result<(), InputError> {
        for key in KEYS {
            let value = (key.get)(self);
            if !key.bounds.contains(value) {
                return Err(InputError::OutOfRange {
                    key: key.name,
                    value,
                    bounds: key.bounds,
                    unit: key.unit,
                });
            }
        }
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
        Ok(())
    }
}

/// " (did you mean `bat.speed`?)" for a near miss of a known key.
fn suggestion(key: &str) -> String {
    KEYS.iter()
        .map(|k| k.name)
        .chain([DRAG_KEY])
        .map(|name| (strsim::jaro_winkler(key, name), name))
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .filter(|(score, _)| *score > 0.85)
        .map(|(_, name)| format!(" (did you mean `{name}`?)"))
        .unwrap_or_default()
}

fn unit_suffix(unit: &str) -> String {
    if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    }
}

fn known_keys() -> String {
    let mut names: Vec<&str> = KEYS.iter().map(|k| k.name).collect();
    names.push(DRAG_KEY);
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
}
