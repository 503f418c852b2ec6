//! The key table: every numeric input's name, symbol, unit, bounds and the
//! reason for them (`homerun keys` prints it), nudge step and accessors.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_3, PI};

use super::{Bounds, Key};
use crate::atmosphere::Atmosphere;
use crate::scene::SceneKind;

/// A key: its name, symbol, unit, description, bounds and their reason,
/// nudge step, then how it is read and written (see `access!`).
macro_rules! key {
    ($name:literal, $symbol:literal, $unit:literal, $desc:literal, $bounds:expr, $why:literal, $step:expr, $($access:tt)+) => {
        Key {
            name: $name,
            symbol: $symbol,
            unit: $unit,
            description: $desc,
            bounds: $bounds,
            bounds_reason: $why,
            step: $step,
            get: access!(get $($access)+),
            set: access!(set $($access)+),
        }
    };
}

/// A key's reader (`get`) or writer (`set`): given as `get: …, set: …`, or
/// a field of the scene (`pitch.speed`), of the weather or of the launch.
macro_rules! access {
    (get get: $get:expr, set: $set:expr) => {
        $get
    };
    (set get: $get:expr, set: $set:expr) => {
        $set
    };
    // A key of the weather, `atmosphere(field)`: reads the atmosphere in
    // force (the standard one while ρ and ν are given), and writing it
    // derives ρ and ν.
    (get atmosphere($field:ident)) => {
        |s| s.environment.atmosphere().unwrap_or(Atmosphere::STANDARD).$field
    };
    (set atmosphere($field:ident)) => {
        |s, v| {
            let mut atmosphere = s.environment.atmosphere().unwrap_or(Atmosphere::STANDARD);
            atmosphere.$field = v;
            s.environment.set_atmosphere(atmosphere)
        }
    };
    // A key of the launch, `launch(field)`: reads the launch in force (the
    // swing's impact's, on a swing scene), and writing it makes the scene a
    // batted ball.
    (get launch($field:ident)) => {
        |s| s.batted_ball().$field
    };
    (set launch($field:ident)) => {
        |s, v| {
            s.launch.$field = Some(v);
            s.set_kind(SceneKind::BattedBall);
        }
    };
    (get $($field:ident).+) => {
        |s| s.$($field).+
    };
    (set $($field:ident).+) => {
        |s, v| s.$($field).+ = v
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
        "Above 0, a pitch that reaches the plate; up to 100 m/s, where Eq. (19) still keeps e* in (0, 1) for any approach (it does below ~240 m/s) and the air is still incompressible (Mach 0.3).",
        0.5,
        pitch.speed
    ),
    key!(
        "pitch.spin",
        "ω_b0",
        "rad/s",
        "pitch spin (topspin positive, fastball backspin negative)",
        Bounds::closed(-1000.0, 1000.0),
        "±1000 rad/s (9550 rpm), four times any pitch's (a fastball's ~2300 rpm is 240 rad/s); beyond it the spin parameter leaves the lift data behind.",
        10.0,
        pitch.spin
    ),
    key!(
        "bat.speed",
        "V̂_B0",
        "m/s",
        "bat speed at the contact point",
        Bounds::positive(100.0),
        "Above 0, a bat that meets the ball; up to 100 m/s, as the pitch: Eq. (19)'s e* stays in (0, 1) and the air incompressible.",
        0.5,
        bat.speed
    ),
    key!(
        "bat.spin",
        "ω_B0",
        "rad/s",
        "bat roll about its axis (positive adds backspin, Fig. 9)",
        Bounds::closed(-200.0, 200.0),
        "±200 rad/s of roll, far past what a swing rolls a bat (a few tens of rad/s), to explore Fig. 9's trend.",
        5.0,
        bat.spin
    ),
    key!(
        "bat.undercut",
        "E",
        "m",
        "undercut: ball centre above bat axis (square to a tilted bat)",
        Bounds::closed(-0.4, 0.4),
        "±0.4 m, twice the largest r_b + r_B the radii allow; validation refuses a miss, |E| ≥ r_b + r_B, for the radii given.",
        0.0005,
        bat.undercut
    ),
    key!(
        "bat.swing_angle",
        "ψ",
        "rad",
        "swing angle above horizontal",
        Bounds::closed(-FRAC_PI_2, FRAC_PI_2),
        "From straight down to straight up.",
        0.01,
        bat.swing_angle
    ),
    key!(
        "bat.friction",
        "μ",
        "",
        "bat–ball coefficient of friction",
        Bounds::closed(0.0, 2.0),
        "0 (frictionless) to 2, past any leather on wood or aluminium (the paper measures 0.50 and 0.35, §III).",
        0.01,
        bat.friction
    ),
    key!(
        "bat.effective_mass",
        "M_B",
        "kg",
        "bat mass equivalent at the centre of percussion",
        Bounds::closed(0.05, 10.0),
        "From well below any bat (a 0.9 kg bat weighs ~0.6–0.8 kg at its sweet spot) to a sledgehammer; away from 0, where Eq. (12)'s inverse inertia overflows.",
        0.05,
        bat.effective_mass
    ),
    key!(
        "bat.radius",
        "r_B",
        "m",
        "bat barrel radius",
        Bounds::closed(0.01, 0.2),
        "A broomstick (1 cm) to a log; away from 0, where the bat's moment of inertia underflows.",
        0.001,
        bat.radius
    ),
    key!(
        "bat.gyration_radius",
        "k_B2",
        "m",
        "bat radius of gyration about its axis",
        Bounds::closed(0.001, 0.2),
        "Also tied to r_B when the scene is checked: between 0.2·r_B (all mass at the core) and r_B (a thin tube), as for any body of revolution of that radius.",
        0.001,
        bat.gyration_radius
    ),
    key!(
        "ball.mass",
        "M_b",
        "kg",
        "ball mass",
        Bounds::closed(0.001, 10.0),
        "Also tied to r_b when the scene is checked: the model ignores buoyancy and the air a ball drags along, fair only for a ball far denser than air.",
        0.005,
        ball.mass
    ),
    key!(
        "ball.radius",
        "r_b",
        "m",
        "ball radius",
        Bounds::closed(0.01, 0.2),
        "A marble (1 cm) to a volleyball-and-more (20 cm); away from 0, where the ball's moment of inertia underflows.",
        0.001,
        ball.radius
    ),
    key!(
        "ball.gyration_radius",
        "k_b",
        "m",
        "ball radius of gyration",
        Bounds::closed(0.001, 0.2),
        "Also tied to r_b when the scene is checked: between 0.2·r_b (a heavy core) and √(2/3)·r_b (a thin shell, the most a sphere's mass can spread).",
        0.001,
        ball.gyration_radius
    ),
    key!(
        "environment.wind",
        "V_w",
        "m/s",
        "horizontal wind toward environment.wind_direction (direction 0: positive is a tailwind)",
        Bounds::closed(-50.0, 50.0),
        "±50 m/s (112 mph) is a hurricane's wind: no game is played in it.",
        1.0,
        environment.wind
    ),
    key!(
        "environment.wind_direction",
        "φ_w",
        "rad",
        "where the wind blows toward: 0 centre field, positive toward right field",
        Bounds::closed(-PI, PI),
        "A full turn: the wind may blow toward any point of the compass.",
        0.1,
        environment.wind_direction
    ),
    key!(
        "environment.wind_height",
        "h_w",
        "m",
        "height above which the wind blows (0: everywhere), as in Nathan's calculator",
        Bounds::closed(0.0, 100.0),
        "From the ground to 100 m, above any batted ball's apex (~50 m): a layer any higher is the same as no wind.",
        1.0,
        environment.wind_height
    ),
    key!(
        "environment.air_density",
        "ρ",
        "kg/m³",
        "air density",
        Bounds::closed(0.0, 5.0),
        "Given, ρ and ν replace any atmosphere's (see `environment.temperature`).",
        0.01,
        get: |s| s.environment.air_density,
        set: |s, v| s.environment.set_air_density(v)
    ),
    key!(
        "environment.kinematic_viscosity",
        "ν",
        "m²/s",
        "kinematic viscosity of air",
        Bounds::positive(1e-3),
        "Above 0, or Re is infinite; up to 1e-3 m²/s, 70 times air's, where Re falls far below any drag data.",
        1e-7,
        get: |s| s.environment.kinematic_viscosity,
        set: |s, v| s.environment.set_kinematic_viscosity(v)
    ),
    key!(
        "environment.gravity",
        "g",
        "m/s²",
        "gravitational acceleration",
        Bounds::positive(30.0),
        "Above 0, or no ball lands; up to 30 m/s², three times Earth's (Jupiter's is ~25).",
        0.1,
        environment.gravity
    ),
    key!(
        "environment.contact_height",
        "y(0)",
        "m",
        "height of the ball at contact",
        Bounds::closed(0.0, 10.0),
        "From the ground to 10 m, higher than any batter reaches.",
        0.1,
        environment.contact_height
    ),
];

/// The inputs beyond the paper: from Alan Nathan's trajectory calculator,
/// the spin's decay and the weather; and the swing in three dimensions, the
/// bat's tilt and direction (with `bat.hand`, [`SWING_3D_KEYS`];
/// docs/swing-3d.md). Kept apart from [`KEYS`] while the
/// explorer's rows, a saved preset's lines and `homerun keys` are built from
/// that table alone; `Scene::key`, `Scene::set` and `Scene::validate` take
/// both (see [`all_keys`]).
///
/// Setting any weather key derives ρ and ν from the four (the others at
/// their standard values, [`Atmosphere::STANDARD`]); giving ρ or ν
/// afterwards replaces the derived value. One source of inputs may not give
/// both: see [`super::InputBatch`].
pub const EXTENDED_KEYS: &[Key] = &[
    key!(
        "model.spin_decay",
        "τ",
        "s",
        "spin decay time, ω(t) = ω₀·e^(−t/τ); 0 = no decay (the paper's constant spin)",
        Bounds::closed(0.0, 1000.0),
        "§II.D: ~30–50 s for a baseball, ~16 s measured on golf balls. Up to 1000 s, where a 6 s flight loses 0.6 % of its spin.",
        1.0,
        spin_decay
    ),
    key!(
        "environment.temperature",
        "T",
        "°C",
        "air temperature (setting it derives ρ and ν)",
        Bounds::closed(-50.0, 60.0),
        "From colder than any game (−50 °C) to above the hottest air recorded (56.7 °C); Sutherland's law and the vapour-pressure fit hold there.",
        1.0,
        atmosphere(temperature)
    ),
    key!(
        "environment.elevation",
        "h",
        "m",
        "field elevation above sea level (setting it derives ρ and ν)",
        Bounds::closed(-500.0, 5000.0),
        "From the Dead Sea shore (−430 m) to above the highest cities (El Alto, 4150 m); the e^(−βh) pressure law stays within a few per cent of the standard atmosphere's there.",
        10.0,
        atmosphere(elevation)
    ),
    key!(
        "environment.pressure",
        "p",
        "hPa",
        "barometric pressure corrected to sea level (setting it derives ρ and ν)",
        Bounds::closed(870.0, 1085.0),
        "Sea-level-corrected, as weather reports give it: from the lowest ever recorded (870 hPa, typhoon Tip) to the highest (1084.8 hPa, Siberia).",
        1.0,
        atmosphere(pressure)
    ),
    key!(
        "environment.humidity",
        "RH",
        "%",
        "relative humidity (setting it derives ρ and ν)",
        Bounds::closed(0.0, 100.0),
        "A relative humidity, by definition.",
        5.0,
        atmosphere(humidity)
    ),
    key!(
        "bat.tilt",
        "τ_B",
        "rad",
        "swing plane's tilt: barrel below the hands at the arc's bottom (0: the paper's level bat)",
        Bounds::closed(-FRAC_PI_3, FRAC_PI_3),
        "Measured barrels sit 25–35° below the hands in big-league swings and −29.6 ± 8.7° in elite softball (docs/swing-3d.md), and low and high pitches take them further; toward ±90° the bat stands upright, where \"above the axis\" (E) loses its meaning.",
        0.02,
        bat.tilt
    ),
    key!(
        "bat.direction",
        "φ_B",
        "rad",
        "bat velocity's horizontal direction: 0 centre field, positive toward right field",
        Bounds::closed(-FRAC_PI_3, FRAC_PI_3),
        "Beyond the foul lines (±45°) with room for a pulled or late swing; a bat moving more sideways meets the pitch nearly edge-on.",
        0.02,
        bat.direction
    ),
    key!(
        "bat.tangential_restitution",
        "e_T",
        "",
        "tangential restitution: a gripping contact's slip springs back e_T-fold (0: the paper's rolling)",
        Bounds::closed(0.0, 1.0),
        "0 is rigid rolling; 1 gives the slip back whole, no tangential loss. Measured ball–bat contacts spin the ball up to 40 % more than rolling does (Kensrud, Nathan & Smith, arXiv:1610.03464); friction caps the spring-back either way.",
        0.02,
        bat.tangential_restitution
    ),
];

/// The launch of a batted-ball scene (see [`crate::launch`](mod@crate::launch)).
/// Setting one makes the scene a batted ball; each one not set is read
/// from the scene's own swing (the impact's launch), and reading one on a
/// swing scene gives the impact's. Kept apart from [`KEYS`], which are the
/// swing scene's rows in the explorer.
pub const LAUNCH_KEYS: &[Key] = &[
    key!(
        "launch.speed",
        "V̂_bf",
        "m/s",
        "launch speed of a batted ball (no pitch, no impact)",
        Bounds::positive(100.0),
        "Above 0: a ball at rest does not fly. Up to 100 m/s, about Mach 0.3, where air stops behaving as incompressible (no drag model here knows compressibility) and nearly twice the fastest batted ball measured (122 mph, 54.6 m/s).",
        0.5,
        launch(speed)
    ),
    key!(
        "launch.angle",
        "ζ",
        "rad",
        "launch angle above the horizontal",
        Bounds::closed(-FRAC_PI_2, FRAC_PI_2),
        "Straight up or down at most: Statcast records ±90° (a ball popped straight up, one driven into the plate), and past it the ball leaves backwards.",
        0.01,
        launch(angle)
    ),
    key!(
        "launch.spin",
        "ω_bf",
        "rad/s",
        "launch spin, backspin positive",
        Bounds::closed(-1000.0, 1000.0),
        "As the pitch's spin: the impact's spins reach ~1000 rad/s at the cusps of Fig. 5, and at 1000 rad/s (9550 rpm) the spin parameter passes 1 at 37 m/s, beyond the data both lift fits rest on.",
        10.0,
        launch(spin)
    ),
    key!(
        "launch.direction",
        "φ",
        "rad",
        "launch direction: 0 centre field, positive toward right field (fair within ±π/4)",
        Bounds::closed(-PI, PI),
        "Any way round: fair territory is ±π/4, and a ball fouled back over the catcher (|φ| > π/2, as Trackman measures some) still flies; ±π is straight back.",
        0.01,
        launch(direction)
    ),
    key!(
        "launch.sidespin",
        "ω_s",
        "rad/s",
        "sidespin, positive curving the ball toward right field",
        Bounds::closed(-1000.0, 1000.0),
        "As the backspin: the two together make the spin vector, and ~3000 rpm is as much as batted balls are estimated to carry.",
        10.0,
        launch(sidespin)
    ),
];

/// Factors on the drag and lift coefficients, for fitting a model to
/// measured flights (`homerun calibrate`); 1 is the model as published.
/// Kept apart from [`EXTENDED_KEYS`] so that the explorer's rows stay as
/// they are; `homerun keys`, `--set`, presets and batch columns take them.
pub const CALIBRATION_KEYS: &[Key] = &[
    key!(
        "model.drag_scale",
        "k_D",
        "",
        "factor on C_D (1: the model as published; homerun calibrate fits it)",
        Bounds::closed(0.3, 3.0),
        "From a third to three times the model's: a season's ball differs from another's by a few per cent in drag (the 2019 \"juiced\" ball was put at 3–5 % less), a wrong model by tens of per cent; outside these a fit is telling of bad data, not of a ball. Above 0, since no drag is another model (a vacuum), not a scale of this one.",
        0.01,
        drag_scale
    ),
    key!(
        "model.lift_scale",
        "k_L",
        "",
        "factor on C_L (1: the model as published; homerun calibrate fits it where apex or hang time is measured)",
        Bounds::closed(0.0, 3.0),
        "As the drag's, from 0: lift can be switched off (model.lift = none says so more plainly).",
        0.01,
        lift_scale
    ),
];

/// What bat tracking's solve finds beyond the paper's swing: the bat's lead
/// over its path (docs/swing-3d.md, *The bat's lead over its path*). Kept
/// apart from [`EXTENDED_KEYS`] so that the explorer's rows stay as they
/// are; `homerun keys`, `--set`, presets (where not 0) and batch columns
/// take it.
pub const TRACKING_KEYS: &[Key] = &[key!(
    "bat.lead",
    "λ_B",
    "rad",
    "bat's lead over its path: barrel turned ahead of square to the velocity, in the swing plane (0: the paper's square bat)",
    Bounds::closed(-crate::impact::MOST_LEAD, crate::impact::MOST_LEAD),
    "sin λ is the share of the contact point's speed along the bat (the hands' drive along it); at ±45° the bat slides along itself as fast as it sweeps across, beyond it faster, a bat dragged along its length rather than swung (docs/swing-3d.md).",
    0.01,
    bat.lead
)];

/// Every numeric input: [`KEYS`], then [`EXTENDED_KEYS`], then
/// [`LAUNCH_KEYS`], then [`CALIBRATION_KEYS`] and [`TRACKING_KEYS`] (last,
/// so that the explorer's indices into the others stay).
pub fn all_keys() -> impl Iterator<Item = &'static Key> {
    swing_keys()
        .chain(LAUNCH_KEYS)
        .chain(CALIBRATION_KEYS)
        .chain(TRACKING_KEYS)
}

/// The numeric inputs of a swing scene: all but the launch, which a swing
/// computes (setting a launch key makes a batted ball).
pub fn swing_keys() -> impl Iterator<Item = &'static Key> {
    KEYS.iter().chain(EXTENDED_KEYS)
}

/// The given air: ρ and ν.
pub const AIR_KEYS: [&str; 2] = ["environment.air_density", "environment.kinematic_viscosity"];

/// The weather keys, which derive ρ and ν.
pub const ATMOSPHERE_KEYS: [&str; 4] = [
    "environment.temperature",
    "environment.elevation",
    "environment.pressure",
    "environment.humidity",
];

/// The non-numeric inputs: the drag and lift models, the batter's hand.
pub use crate::aero::{DRAG_KEY, LIFT_KEY};
pub use crate::scene::HAND_KEY;

/// Every key that takes a name rather than a number.
pub const TEXT_KEYS: [&str; 3] = [DRAG_KEY, LIFT_KEY, HAND_KEY];

/// The keys that take the swing out of the paper's plane: with the first
/// two at 0 the swing is the paper's, whatever the hand.
pub const SWING_3D_KEYS: [&str; 3] = ["bat.tilt", "bat.direction", HAND_KEY];
